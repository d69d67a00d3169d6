"""The double pendulum end to end (book, ch. 25.4.3 and 27.5), checked by independent routes.

Conventions: two uniform rods of mass m and length L, absolute angles q1, q2 measured from
the downward vertical R0.i, gravity g R0.i, pivots at O (fixed) and A (end of bar 1), both
about R0.k.
"""

import numpy as np
import pytest
import sympy as sp
from numpy.testing import assert_allclose
from sympy.physics import mechanics as me

import rigidmech as rm
from rigidmech import ode


def build():
    q1, q2 = rm.coordinates("q1 q2")
    m, L, g = rm.constants("m L g", positive=True)
    R0 = rm.Frame("R0")
    R1 = R0.rotated("R1", about=R0.k, angle=q1)
    R2 = R0.rotated("R2", about=R0.k, angle=q2)
    O = R0.origin
    A = O.moved("A", L * R1.i)
    G1 = O.moved("G1", L / 2 * R1.i)
    G2 = A.moved("G2", L / 2 * R2.i)
    bar1 = rm.Body("bar1", frame=R1, mass=m, centre=G1,
                   inertia=rm.inertia.rod(m, L, axis=R1.i, centre=G1))
    bar2 = rm.Body("bar2", frame=R2, mass=m, centre=G2,
                   inertia=rm.inertia.rod(m, L, axis=R2.i, centre=G2))
    system = rm.System(galilean=R0)
    system.connect(R0, bar1, rm.joints.Pivot(at=O, axis=R0.k))
    system.connect(bar1, bar2, rm.joints.Pivot(at=A, axis=R0.k))
    system.act(rm.gravity(g * R0.i))
    return system, (R0, R1, R2), (O, A, G1, G2), (bar1, bar2), (m, L, g)


@pytest.fixture(scope="module")
def model():
    return build()


def sympy_reference():
    """The same system with sympy.physics.mechanics' LagrangesMethod (independent route)."""
    q1, q2 = me.dynamicsymbols("q1 q2")
    m, L, g = sp.symbols("m L g", positive=True)
    N = me.ReferenceFrame("N")
    A1 = N.orientnew("A1", "Axis", [q1, N.z])
    A2 = N.orientnew("A2", "Axis", [q2, N.z])
    O = me.Point("O")
    O.set_vel(N, 0)
    P = O.locatenew("P", L * A1.x)
    G1 = O.locatenew("G1", L / 2 * A1.x)
    G2 = P.locatenew("G2", L / 2 * A2.x)
    for pt in (G1, G2):
        pt.v2pt_theory(O, N, A1) if pt is G1 else None
    G1.v2pt_theory(O, N, A1)
    P.v2pt_theory(O, N, A1)
    G2.v2pt_theory(P, N, A2)
    Izz = m * L**2 / 12
    b1 = me.RigidBody("b1", G1, A1, m, (me.inertia(A1, 0, Izz, Izz), G1))
    b2 = me.RigidBody("b2", G2, A2, m, (me.inertia(A2, 0, Izz, Izz), G2))
    b1.potential_energy = -m * g * L / 2 * sp.cos(q1)
    b2.potential_energy = -m * g * (L * sp.cos(q1) + L / 2 * sp.cos(q2))
    lag = me.Lagrangian(N, b1, b2)
    lm = me.LagrangesMethod(lag, [q1, q2])
    lm.form_lagranges_equations()
    return lm, (q1, q2), (m, L, g)


def to_our_symbols(expr, qs, ours):
    q_sym, u_sym = ours.q, ours.u
    rule = {}
    for q, qs_, us in zip(qs, q_sym, u_sym, strict=True):
        rule[q.diff()] = us
        rule[q] = qs_
    return expr.xreplace(rule)


def test_equations_of_motion_equal_sympy_lagranges_method(model):
    system, *_ , (m, L, g) = model
    eqs = system.equations_of_motion()
    lm, qs, (ms, Ls, gs) = sympy_reference()
    sub = {ms: m, Ls: L, gs: g}
    M_ref = to_our_symbols(lm.mass_matrix.xreplace(sub), qs, eqs)
    f_ref = to_our_symbols(lm.forcing.xreplace(sub), qs, eqs)
    assert sp.simplify(eqs.mass_matrix - M_ref) == sp.zeros(2, 2)
    assert sp.simplify(eqs.forcing - f_ref) == sp.zeros(2, 1)


def test_lagrange_route_equals_fundamental_principle(model):
    system = model[0]
    fpd = system.equations_of_motion()
    lag = rm.lagrange_equations(system)
    assert sp.simplify(fpd.mass_matrix - lag.mass_matrix) == sp.zeros(2, 2)
    assert sp.simplify(fpd.forcing - lag.forcing) == sp.zeros(2, 1)


def test_textbook_form_of_the_mass_matrix(model):
    """Book ch. 25.4.3 (uniform rods): M = m L^2 [[4/3, cos(q1-q2)/2], [., 1/3]]."""
    system, *_, (m, L, g) = model
    eqs = system.equations_of_motion()
    q1, q2 = eqs.q
    expected = m * L**2 * sp.Matrix([[sp.Rational(4, 3), sp.cos(q1 - q2) / 2],
                                     [sp.cos(q1 - q2) / 2, sp.Rational(1, 3)]])
    assert sp.simplify(eqs.mass_matrix - expected) == sp.zeros(2, 2)


PARAMS = dict(m=1.3, L=0.7, g=9.81)


@pytest.fixture(scope="module")
def motion(model):
    eqs = model[0].equations_of_motion()
    # dense output is opt-in (its memory grows with the steps): the tests below use it
    return eqs.simulate(t=(0.0, 10.0), q0=[2.0, -0.2], u0=[0.3, 0.0], rtol=1e-12,
                        atol=1e-14, n_output=2001, dense_output=True, **PARAMS)


def test_energy_conserved_over_10_s(motion):
    """No friction: T + V constant. DOP853 at rtol 1e-12 leaves a drift far below 1e-9."""
    assert motion.energy_drift() < 1e-9


def _numeric(expr, eqs):
    return sp.lambdify([list(eqs.q), list(eqs.u), *[sp.Symbol(k, positive=True)
                                                    for k in PARAMS]], expr, "numpy")


def test_connection_actions_satisfy_fundamental_principle(model, motion):
    """Resultants of the pivot actions against Newton's law for the carried bodies, with the
    accelerations of the mass centres from finite differences of the integrated positions
    (an independent route: no symbolic acceleration is used), and the moment about each
    pivot axis zero (perfect pivots) when q'' comes from the equations of motion."""
    system, (R0, R1, R2), (O, A, G1, G2), (bar1, bar2), (m, L, g) = model
    eqs = system.equations_of_motion()
    q_sym, u_sym, a_sym, rule = system.symbols()
    sol = motion.result.sol
    ts = np.linspace(1.0, 9.0, 17)
    h = 2e-4
    pos = {}
    for name, G in (("G1", G1), ("G2", G2)):
        xy = [sp.lambdify([list(q_sym), m, L, g],
                          sp.sympify(c).xreplace(rule), "numpy")
              for c in (G - O).components(R0)[:2]]
        pos[name] = lambda tt, xy=xy: np.array(
            [f(sol(tt)[:2], *PARAMS.values()) for f in xy], dtype=float)
    acc = {k: np.array([(p(tt + h) - 2 * p(tt) + p(tt - h)) / h**2 for tt in ts])
           for k, p in pos.items()}
    mass, grav = PARAMS["m"], PARAMS["g"]
    solver = eqs.rhs(**PARAMS)
    for action, carried in (((R0, bar1), ("G1", "G2")), ((bar1, bar2), ("G2",))):
        comps = system.connection_components(*action)  # basis (R0.i, R0.j, R0.k)
        f = sp.lambdify([list(q_sym), list(u_sym), list(a_sym), m, L, g],
                        [comps[c].xreplace(rule) for c in ("X", "Y", "N")], "numpy")
        for k, tt in enumerate(ts):
            y = sol(tt)
            qdd = solver(tt, y)[2:]
            Rx, Ry, N = (float(v) for v in f(y[:2], y[2:], qdd, *PARAMS.values()))
            newton = sum(mass * acc[c][k] for c in carried) - len(carried) * mass * np.array(
                [grav, 0.0])
            # central differences: truncation h^2 |x''''| / 12 (about 2e-3 here for forces
            # of order 200 N) plus rounding 4e-12 / h^2 (1e-4): allow 1e-4 of the force scale
            scale = max(np.abs(newton).max(), mass * grav)
            assert_allclose([Rx, Ry], newton, rtol=0, atol=1e-4 * scale)
            assert abs(N) < 1e-9 * mass * grav * PARAMS["L"]


def test_perfect_pivot_power_is_zero(model):
    """Power of the mutual actions of a perfect pivot in the relative motion (ch. 13.2.4)."""
    system, (R0, R1, R2), (O, A, *_), (bar1, bar2), _ = model
    joint = rm.joints.Pivot(at=A, axis=R0.k)
    T, unknowns = joint.action_torsor("12")
    V21 = bar2.kinematic_torsor(relative_to=R0, at=A) + (
        -bar1.kinematic_torsor(relative_to=R0, at=A))
    assert sp.simplify(rm.power(T, V21)) == 0
    assert len(unknowns) == 5


def test_compiled_rhs_returns_fresh_arrays_in_a_real_integration(model):
    """A solver that keeps references to earlier evaluations (rejected steps) must see the
    same numbers whether or not the right-hand side's results are copied."""
    fun = model[0].equations_of_motion().rhs(**PARAMS)
    y0 = np.array([2.5, -1.0, 0.0, 4.0])
    a = ode.solve(fun, (0.0, 5.0), y0, method="dopri5", rtol=1e-5, atol=1e-8)
    b = ode.solve(lambda t, y: np.array(fun(t, y), copy=True), (0.0, 5.0), y0,
                  method="dopri5", rtol=1e-5, atol=1e-8)
    assert a.nrejected > 0
    r1, r2 = fun(0.0, y0), fun(0.0, y0)
    assert r1 is not r2 and not np.shares_memory(r1, r2)
    assert_allclose(a.y, b.y, rtol=0, atol=0)


def test_batched_rhs_matches_single_states(model):
    fun = model[0].equations_of_motion().rhs(**PARAMS)
    rng = np.random.default_rng(1)
    Y = rng.normal(size=(4, 50))
    batch = fun(0.0, Y)
    single = np.stack([fun(0.0, Y[:, k]) for k in range(50)], axis=1)
    assert_allclose(batch, single, rtol=1e-13, atol=1e-13)


def test_missing_and_unknown_parameters_are_named(model):
    eqs = model[0].equations_of_motion()
    with pytest.raises(ValueError, match=r"missing values for parameters \['g'\]"):
        eqs.rhs(m=1, L=1)
    with pytest.raises(ValueError, match=r"unknown parameters \['mass'\]"):
        eqs.rhs(m=1, L=1, g=1, mass=2)


def test_second_order_methods_need_separable_equations(model):
    eqs = model[0].equations_of_motion()
    with pytest.raises(ValueError, match="depend on q'"):
        eqs.simulate(t=(0, 1), q0=[0.1, 0.0], method="verlet", step=1e-3, **PARAMS)


def test_symplectic_method_on_a_separable_system():
    """Compound pendulum (one rod on a pivot): q'' = -(3g/2L) sin q has no velocity terms,
    so the geometric methods apply; energy stays bounded (Stormer-Verlet, h = 1e-3)."""
    q = rm.coordinates("q")
    m, L, g = rm.constants("m L g", positive=True)
    R0 = rm.Frame("R0")
    R1 = R0.rotated("R1", about=R0.k, angle=q)
    G = R0.origin.moved("G", L / 2 * R1.i)
    bar = rm.Body("bar", frame=R1, mass=m, centre=G,
                  inertia=rm.inertia.rod(m, L, axis=R1.i, centre=G))
    s = rm.System(galilean=R0)
    s.connect(R0, bar, rm.joints.Pivot(at=R0.origin, axis=R0.k))
    s.act(rm.gravity(g * R0.i))
    sim = s.equations_of_motion().simulate(t=(0, 20), q0=[2.5], method="verlet", step=1e-3,
                                           m=1.0, L=1.0, g=9.81)
    # Verlet's energy error is O(h^2) and bounded: about 1e-6 here
    assert sim.energy_drift() < 1e-5
