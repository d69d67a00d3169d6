"""Bodies, kinetic and dynamic torsors, kinetic energy (book, ch. 16)."""

import pytest
import sympy as sp

import rigidmech as rm


@pytest.fixture
def disk():
    """A disk of radius a spinning about its axis k1 while its centre moves on a circle of
    radius d about k0 (a seat on a merry-go-round)."""
    q, p = rm.coordinates("q p")
    m, a, d = rm.constants("m a d", positive=True)
    R0 = rm.Frame("R0")
    R1 = R0.rotated("R1", about=R0.k, angle=q)
    G = R0.origin.moved("G", d * R1.i)
    R2 = R1.rotated("R2", about=R1.k, angle=p, origin=G)
    body = rm.Body("disk", frame=R2, mass=m, centre=G,
                   inertia=rm.inertia.disk(m, a, axis=R2.k, centre=G))
    return q, p, m, a, d, R0, R1, R2, G, body


def test_kinetic_energy_closed_form(disk):
    """T = m d^2 q'^2 / 2 + (m a^2 / 2) (q' + p')^2 / 2 (Koenig, ch. 16.3.2)."""
    q, p, m, a, d, R0, *_, body = disk
    qd, pd = q.diff(), p.diff()
    expected = m * d**2 * qd**2 / 2 + m * a**2 / 2 * (qd + pd) ** 2 / 2
    assert sp.simplify(body.kinetic_energy(R0) - expected) == 0


def test_kinetic_torsor_at_centre_and_at_origin(disk):
    """sigma(G) = J_G(omega) = m a^2/2 (q' + p') k; sigma(O) = sigma(G) + OG ^ m v(G)."""
    q, p, m, a, d, R0, R1, R2, G, body = disk
    C = body.kinetic_torsor(R0)
    assert C.resultant.equals(m * d * q.diff() * R1.j)
    assert C.moment.equals(m * a**2 / 2 * (q.diff() + p.diff()) * R0.k)
    C_O = body.kinetic_torsor(R0, at=R0.origin)
    expected = (m * a**2 / 2 * (q.diff() + p.diff()) + m * d**2 * q.diff()) * R0.k
    assert C_O.moment.equals(expected)


def test_dynamic_torsor_is_the_derivative_of_the_kinetic_torsor_at_a_fixed_point(disk):
    """delta(O) = d/dt sigma(O) for O fixed in R0 (ch. 16.2.4); resultant m a(G)."""
    q, p, m, a, d, R0, R1, R2, G, body = disk
    D = body.dynamic_torsor(R0, at=R0.origin)
    sigma_O = body.kinetic_torsor(R0, at=R0.origin).moment
    assert D.moment.equals(sigma_O.dt(R0))
    assert D.resultant.equals(m * G.acceleration(R0))


def test_power_energy_theorem_for_a_free_spinning_body(disk):
    """dT/dt = comoment of the dynamic torsor with the kinematic torsor (ch. 16.3.4)."""
    q, p, m, a, d, R0, R1, R2, G, body = disk
    V = body.kinematic_torsor(relative_to=R0, at=G)
    D = body.dynamic_torsor(R0)
    assert sp.simplify(D.comoment(V) - rm.vectors.time_derivative(body.kinetic_energy(R0))) == 0


def test_negative_mass_is_refused():
    R0 = rm.Frame("R0")
    with pytest.raises(ValueError, match=r"`mass` must be >= 0; got -1"):
        rm.Body("b", frame=R0, mass=-1)


def test_inertia_must_be_an_operator_and_come_with_a_mass():
    R0 = rm.Frame("R0")
    with pytest.raises(TypeError, match="`inertia` must be an InertiaOperator"):
        rm.Body("b", frame=R0, mass=1, inertia=[[1, 0, 0], [0, 1, 0], [0, 0, 1]])
    with pytest.raises(ValueError, match="`inertia` given without `mass`"):
        rm.Body("b", frame=R0, inertia=rm.inertia.sphere(1, 1, frame=R0))


def test_non_symmetric_and_non_positive_inertia_are_refused():
    R0 = rm.Frame("R0")
    with pytest.raises(ValueError, match="must be symmetric"):
        rm.InertiaOperator.from_matrix([[1, 2, 0], [3, 1, 0], [0, 0, 1]], frame=R0)
    with pytest.raises(ValueError, match=r"`A` must be >= 0"):
        rm.InertiaOperator.from_products(-1, 1, 1, frame=R0)


def test_a_vector_where_a_point_is_expected():
    R0 = rm.Frame("R0")
    with pytest.raises(TypeError, match="`centre` must be a Point"):
        rm.Body("b", frame=R0, mass=1, centre=R0.i)


def test_quantities_that_need_a_mass():
    R0 = rm.Frame("R0")
    with pytest.raises(ValueError, match="needs the mass of body b"):
        rm.Body("b", frame=R0).kinetic_energy(R0)


def test_catalogue_operator_is_placed_at_the_mass_centre():
    """rm.inertia.rod(m, L, axis=R1.i) without `centre` is the rod's central operator: the
    body places it at its own mass centre (the TOUR's form)."""
    q = rm.coordinates("q")
    m, L = rm.constants("m L", positive=True)
    R0 = rm.Frame("R0")
    R1 = R0.rotated("R1", about=R0.k, angle=q)
    G = R0.origin.moved("G", L / 2 * R1.i)
    bar = rm.Body("bar", frame=R1, mass=m, centre=G, inertia=rm.inertia.rod(m, L, axis=R1.i))
    assert bar.inertia.at == G
    assert sp.simplify(bar.inertia.C - m * L**2 / 12) == 0
    # T = (m L^2 / 3) q'^2 / 2 about the end
    assert sp.simplify(bar.kinetic_energy(R0) - m * L**2 / 6 * q.diff() ** 2) == 0


def test_operator_given_at_another_point_is_moved_by_huygens():
    """The rod's operator given at its end O (C = m L^2 / 3) is moved to G (m L^2 / 12)."""
    q = rm.coordinates("q")
    m, L = rm.constants("m L", positive=True)
    R0 = rm.Frame("R0")
    R1 = R0.rotated("R1", about=R0.k, angle=q)
    G = R0.origin.moved("G", L / 2 * R1.i)
    J_O = rm.InertiaOperator.from_products(0, m * L**2 / 3, m * L**2 / 3, frame=R1,
                                           at=R0.origin)
    bar = rm.Body("bar", frame=R1, mass=m, centre=G, inertia=J_O)
    assert bar.inertia.at == G
    assert sp.simplify(bar.inertia.C - m * L**2 / 12) == 0


def test_only_central_operators_can_be_placed():
    R0 = rm.Frame("R0")
    J = rm.InertiaOperator.from_products(1, 1, 1, frame=R0)
    with pytest.raises(ValueError, match="only an operator taken at the mass centre"):
        J.placed_at(R0.point("G", 1, 0, 0))
