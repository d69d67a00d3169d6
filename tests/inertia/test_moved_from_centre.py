"""A catalogue operator (central) moved from a centre it was not built at is an error (issue 9:
``disk(...)`` built without ``centre=``, then ``.moved(O, mass, centre=C)``, returned the
unchanged central matrix: the Huygens term was removed and put back)."""

import pytest
import sympy as sp

import rigidmech as rm
from rigidmech.errors import ArgumentError

m, R, a = sp.symbols("m R a", positive=True)


def test_catalogue_operator_moved_with_another_centre_is_refused():
    R0 = rm.Frame("R0")
    C = R0.point("C", a, 0, 0)
    J = rm.inertia.disk(m, R, axis=R0.k)  # at R0.origin, its default centre
    with pytest.raises(ArgumentError,
                       match=r"taken at the mass centre O_R0 .*`centre` is C"):
        J.moved(R0.origin, mass=m, centre=C)


def test_catalogue_operator_placed_then_moved_gives_huygens():
    # the right routes: build at C, or place at C; then Huygens (ch. 15.2.2):
    # J_O = J_C + m [a^2 (I - e_x e_x^T)] for OC = a i: A unchanged, B and C gain m a^2
    R0 = rm.Frame("R0")
    C = R0.point("C", a, 0, 0)
    central = [m * R**2 / 4, m * R**2 / 4, m * R**2 / 2]
    expected = sp.diag(central[0], central[1] + m * a**2, central[2] + m * a**2)
    for J in (rm.inertia.disk(m, R, axis=R0.k, centre=C),
              rm.inertia.disk(m, R, axis=R0.k).placed_at(C)):
        moved = J.moved(R0.origin, mass=m, centre=C)
        assert sp.simplify(moved.matrix - expected) == sp.zeros(3, 3)


def test_catalogue_operator_moved_from_its_own_centre_still_works():
    R0 = rm.Frame("R0")
    J = rm.inertia.disk(m, R, axis=R0.k)
    moved = J.moved(R0.point("P", 0, a, 0), mass=m, centre=R0.origin)
    assert sp.simplify(moved.A - (m * R**2 / 4 + m * a**2)) == 0
