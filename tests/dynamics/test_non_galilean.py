"""A System written in a non-Galilean reference (ch. 19, 24): the equations derived relative
to the moving reference, with the inertial actions of entrainment and Coriolis, equal those
of the Galilean route on three systems (the symbolic difference simplifies to zero), and so do
the connection actions."""

import pytest
import sympy as sp

import rigidmech as rm
from rigidmech._core.errors import ArgumentTypeError, FrameError
from rigidmech.kinetics import InertialActions

t = rm.t


def _zero(expr):
    return sp.simplify(sp.expand(sp.simplify(expr))) == 0


def _same_equations(a, b):
    ea, eb = a.equations_of_motion(), b.equations_of_motion()
    assert ea.coordinates == eb.coordinates
    lhs_a = ea.mass_matrix * sp.Matrix([q.diff(t, 2) for q in ea.coordinates]) - ea.forcing
    lhs_b = eb.mass_matrix * sp.Matrix([q.diff(t, 2) for q in eb.coordinates]) - eb.forcing
    for x, y in zip(lhs_a, lhs_b, strict=True):
        assert _zero(x - y), (x, y)


# -- 1. bead on a rod turning at a prescribed rate, with a spring (ch. 19) -------------------
def _bead(route):
    r = rm.coordinates("r")
    m, w, g, k, l0 = rm.constants("m omega g k l0", positive=True)
    R0 = rm.Frame("R0")
    R1 = R0.rotated("R1", about=R0.k, angle=w * t)
    B = R1.point("B", r, 0, 0)
    bead = rm.Body("bead", frame=R1.translated("Rb", B), mass=m, centre=B)
    spring = rm.Spring(k, l0, a=R0.origin, b=B, on_b=bead)
    if route == "galilean":
        s = rm.System(galilean=R0)
        rod = rm.Body("rod", frame=R1)
        s.connect(R0, rod, rm.joints.Pivot(at=R0.origin, axis=R0.k))
        s.connect(rod, bead, rm.joints.Prismatic(at=B, axis=R1.i))
        parent = rod
    else:
        s = rm.System(galilean=R0, reference=R1)
        s.connect(R1, bead, rm.joints.Prismatic(at=B, axis=R1.i))
        parent = R1
    s.act(rm.gravity(-g * R0.k))
    s.act(spring)
    return s, parent, bead, (r, m, w, g, R1)


def test_bead_on_rotating_rod_same_equations():
    _same_equations(_bead("galilean")[0], _bead("reference")[0])


def test_ch19_bead_on_rotating_rod_action_of_the_rod():
    """Ch. 19: a bead on a horizontal rod turning at the constant rate omega about the
    vertical: the rod's action is N = 2 m omega r' j1 + m g k0 (no friction), the same by both
    routes."""
    actions = []
    for route in ("galilean", "reference"):
        s, parent, bead, (r, m, w, g, R1) = _bead(route)
        A = s.connection_action(parent, bead).resultant
        actions.append(A)
        # the component along the rod is the unknown-free equation of motion: take j1, k1
        assert _zero(A.dot(R1.j) - 2 * m * w * r.diff(t))
        assert _zero(A.dot(R1.k) - m * g)
    assert _zero((actions[0] - actions[1]).dot(R1.i))


def test_bead_equation_closed_form():
    s, _, _, (r, m, w, g, R1) = _bead("reference")
    k, l0 = sp.Symbol("k", positive=True), sp.Symbol("l0", positive=True)
    eqs = s.equations_of_motion()
    # m r'' = m omega^2 r - k (r - l0)   (|r| written as r for r > 0)
    res = (eqs.mass_matrix[0] * r.diff(t, 2) - eqs.forcing[0]).subs(sp.Abs(r), r)
    assert _zero(res - (m * r.diff(t, 2) - m * w**2 * r + k * (r - l0)))


# -- 2. pendulum in a wagon with a prescribed motion (ch. 19) ---------------------------------
def _wagon(route, law=None):
    th = rm.coordinates("theta")
    m, L, g, a, J = rm.constants("m L g a J", positive=True)
    law = a * t**2 / 2 if law is None else law
    R0 = rm.Frame("R0")
    Rw = R0.translated("Rw", R0.point("W", law, 0, 0))
    Rp = Rw.rotated("Rp", about=Rw.k, angle=th)
    G = Rw.origin.moved("G", -L * Rp.j)
    bob = rm.Body("bob", frame=Rp, mass=m, centre=G,
                  inertia=rm.InertiaOperator.from_products(J, J / 2, J, frame=Rp, at=G))
    if route == "galilean":
        s = rm.System(galilean=R0)
        wagon = rm.Body("wagon", frame=Rw)
        s.connect(R0, wagon, rm.joints.Prismatic(at=Rw.origin, axis=R0.i))
        s.connect(wagon, bob, rm.joints.Pivot(at=Rw.origin, axis=Rw.k))
        parent = wagon
    else:
        s = rm.System(galilean=R0, reference=Rw)
        s.connect(Rw, bob, rm.joints.Pivot(at=Rw.origin, axis=Rw.k))
        parent = Rw
    s.act(rm.gravity(-g * R0.j))
    return s, parent, bob, (th, m, L, g, a, Rw)


@pytest.mark.parametrize("law", ["uniform", "any"])
def test_pendulum_in_a_wagon_same_equations_and_action(law):
    b, c = sp.symbols("b c", positive=True)
    x = b * sp.sin(c * t) + t**3 if law == "any" else None
    gal = _wagon("galilean", x)
    ref = _wagon("reference", x)
    _same_equations(gal[0], ref[0])
    Ag = gal[0].connection_action(gal[1], gal[2])
    Ar = ref[0].connection_action(ref[1], ref[2])
    R0 = ref[3][5].root
    assert _zero((Ag.resultant - Ar.resultant).dot(R0.i))
    assert _zero((Ag.resultant - Ar.resultant).dot(R0.j))
    assert _zero((Ag.moment - Ar.moment).dot(R0.k))


# -- 3. spherical (Foucault) pendulum on the turning Earth (ch. 19, 24) -------------------------
def _foucault(route):
    alpha, beta = rm.coordinates("alpha beta")
    m, L, g, lam, W = rm.constants("m L g lambda Omega", positive=True)
    E = rm.kinetics.earth_reference(latitude=lam, rate=W, radius=sp.Symbol("R_T", positive=True))
    R = E.frame
    Ra = R.rotated("Ra", about=R.i, angle=alpha)
    Rb = Ra.rotated("Rb", about=Ra.j, angle=beta)
    P = R.origin.moved("P", -L * Rb.k)
    bob = rm.Body("bob", frame=Rb, mass=m, centre=P)
    if route == "galilean":
        s = rm.System(galilean=E.geocentric)
        ground = rm.Body("ground", frame=R)
        s.connect(E.geocentric, ground, rm.joints.Pivot(at=E.geocentric.origin,
                                                        axis=E.geocentric.k))
        s.connect(ground, bob, rm.joints.Spherical(at=R.origin))
        parent = ground
    else:
        s = rm.System(reference=E)
        parent = R
        s.connect(R, bob, rm.joints.Spherical(at=R.origin))
    # the attraction of the Earth, uniform near O, towards the centre
    s.act(rm.actions.Force(on=bob, vector=-m * g * E.up, at=P))
    return s, parent, bob, E


def test_foucault_pendulum_same_equations():
    _same_equations(_foucault("galilean")[0], _foucault("reference")[0])


# -- the API ---------------------------------------------------------------------------------
def test_reference_views_and_inertial_action():
    s, _, _, E = _foucault("reference")
    assert s.galilean is E.geocentric and s.reference is E.frame
    assert any(isinstance(a, InertialActions) for a in s.actions)
    assert "reference=R_earth" in repr(s)
    g = rm.System(galilean=E.geocentric)
    assert g.reference is g.galilean is E.geocentric


def test_reference_bad_input():
    q = rm.coordinates("q")
    R0 = rm.Frame("R0")
    R1 = R0.rotated("R1", about=R0.k, angle=q)
    with pytest.raises(FrameError, match=r"`reference` frame R1 moves with the parameter "
                                         r"of situation q\(t\)"):
        rm.System(galilean=R0, reference=R1)
    with pytest.raises(ArgumentTypeError, match="`reference` must be a Frame or an "
                                                "EarthReference"):
        rm.System(galilean=R0, reference="R1")
    with pytest.raises(ArgumentTypeError, match="`galilean` must be a Frame .*got None"):
        rm.System(reference=R0.rotated("R2", about=R0.k, angle=t))
    with pytest.raises(FrameError, match="must belong to the same frame tree"):
        Rx = rm.Frame("Rx")
        rm.System(galilean=R0, reference=Rx.rotated("R3", about=Rx.k, angle=t))
    E = rm.kinetics.earth_reference(latitude=0.5)
    with pytest.raises(FrameError, match="must be the geocentric frame"):
        rm.System(galilean=R0, reference=E)
    Rm = R0.rotated("Rm", about=R0.k, angle=t)
    with pytest.raises(FrameError, match="pass a moving frame as `reference=`"):
        rm.System(galilean=Rm)


def test_lagrange_equations_in_the_moving_reference():
    """Lagrange's equations written with T relative to the Earth and the power coefficients
    of the inertial actions (ch. 25) agree with the fundamental principle (both routes)."""
    s = _foucault("reference")[0]
    _same_equations(s, _LagrangeView(rm.lagrange_equations(s)))


class _LagrangeView:
    def __init__(self, eqs):
        self._eqs = eqs

    def equations_of_motion(self):
        return self._eqs


def test_reference_fixed_in_the_galilean_one_adds_nothing():
    R0 = rm.Frame("R0")
    R = R0.rotated("R", about=R0.k, angle=sp.pi / 6).translated("RT", R0.point("A", 1, 2, 0))
    s = rm.System(galilean=R0, reference=R)
    assert s.reference is R and s.galilean is R0 and s.actions == ()


def test_inertial_actions_given_twice_refused():
    s, _, _, E = _foucault("reference")
    with pytest.raises(rm.errors.ConnectionError_,
                       match="already adds its inertial actions .* would count them twice"):
        s.act(InertialActions(reference=E.frame, galilean=E.geocentric))
