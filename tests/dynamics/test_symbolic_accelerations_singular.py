"""The symbolic accelerations of equations whose mass matrix is singular at every
configuration are refused with rigidmech's error naming the cause (issue 19, sweep), not
sympy's bare "Matrix det == 0; not invertible."."""

import pytest
import sympy as sp

import rigidmech as rm
from rigidmech.errors import SingularMassMatrixError


def test_a_singular_mass_matrix_is_named():
    x, y = rm.coordinates("x y")
    eqs = rm.EquationsOfMotion(coordinates=(x, y),
                               mass_matrix=sp.ImmutableMatrix([[1, 1], [1, 1]]),
                               forcing=sp.ImmutableMatrix([[-x], [0]]))
    with pytest.raises(SingularMassMatrixError,
                       match=r"`accelerations\(\)`: the mass matrix M is singular at every "
                             r"configuration .*\[x, y\]"):
        eqs.accelerations()


def test_a_coordinate_that_moves_no_mass_is_named():
    x, y = rm.coordinates("x y")
    m = rm.constants("m", positive=True)
    R0 = rm.Frame("R0")
    P = R0.point("P", x, 0, 0)
    Q = R0.point("Q", 0, y, 0)
    s = rm.System(galilean=R0)
    s.add(rm.Body("cart", frame=R0.translated("Rc", P), mass=m, centre=P))
    s.add(rm.Body("ghost", frame=R0.translated("Rg", Q)))          # no mass
    with pytest.raises(SingularMassMatrixError, match=r"row of y is zero"):
        s.equations_of_motion().accelerations()


def test_a_regular_mass_matrix_still_solves():
    x = rm.coordinates("x")
    eqs = rm.EquationsOfMotion(coordinates=(x,), mass_matrix=sp.ImmutableMatrix([[2]]),
                               forcing=sp.ImmutableMatrix([[-4 * x]]))
    assert eqs.accelerations() == sp.ImmutableMatrix([[-2 * x]])
