"""Equations reduced to the independent speeds and linearisation of constrained systems
(book, ch. 25.3, 25.4): closed loops and rolling, about equilibria and steady motions.

References:
* the reduced rolling disc (M_r u' = f_r on psi', theta', phi') against the multiplier form
  and against sympy.physics.mechanics.KanesMethod at random states (1e-10);
* the four-bar's linearised frequency against the period measured on a small-amplitude
  (1e-5 rad) integration of the multiplier form (scipy DOP853, rtol 1e-12);
* a thin disc (radius r, A = m r^2/4 about a diameter, C = m r^2/2 about its axis) rolling
  upright at speed v = r |Omega|. Small lean theta, heading psi: the yaw equation
  A psi'' - C Omega theta' = 0 (angular momentum about the vertical through G; the contact
  force has no moment about it) and the lean equation about the contact line
  (A + m r^2) theta'' + (C + m r^2) Omega psi' - m g r theta = 0 (spin's gyroscopic moment
  C Omega psi' and the centripetal force m v psi' at height r). Eliminating psi':
  omega_n^2 = (C (C + m r^2) Omega^2 - A m g r) / (A (A + m r^2)), stable iff
  v^2 = r^2 Omega^2 > A m g r^3 / (C (C + m r^2)) = g r / 3 for the thin disc;
* the sleeping top (fixed point O, G at distance l on the axis, A transverse moment about O,
  C axial): A alpha'' + C omega beta' - m g l alpha = 0, A beta'' - C omega alpha' - m g l
  beta = 0, so A s^2 -+ i C omega s - m g l = 0: stable (s purely imaginary) iff
  C^2 omega^2 > 4 A m g l (Maievskii's condition).
"""

import sys
from pathlib import Path

import numpy as np
import pytest
import scipy.integrate
import scipy.optimize
import sympy as sp

import rigidmech as rm
from rigidmech._core.errors import ArgumentError
from rigidmech.vibrations import linearize

sys.path.insert(0, str(Path(__file__).parents[1] / "systems"))
from mechanisms import L0, L1, L2, L3, four_bar  # noqa: E402
from rolling_models import rolling_disc, rolling_disc_kane  # noqa: E402

M_, G_, R_ = 1.3, 9.81, 0.7


@pytest.fixture(scope="module")
def disc():
    s, coords, consts = rolling_disc()
    return s.equations_of_motion(), coords, consts


@pytest.fixture(scope="module")
def bar4():
    s, coords, _, _ = four_bar()
    return s.equations_of_motion(), coords


def closure(q1):
    """q2 (relative to the crank) and q3 of the four-bar for the crank angle q1 (the branch
    with C to the left of B -> D): intersection of two circles."""
    B = np.array([L1 * np.cos(q1), L1 * np.sin(q1)])
    D = np.array([L0, 0.0])
    d = np.linalg.norm(D - B)
    e = (D - B) / d
    x = (L2**2 - L3**2 + d**2) / (2 * d)
    C = B + x * e + np.sqrt(L2**2 - x**2) * np.array([-e[1], e[0]])
    return np.arctan2(C[1] - B[1], C[0] - B[0]) - q1, np.arctan2(C[1], C[0] - L0)


def test_reduced_rolling_disc_matches_the_multiplier_form_and_kanes_method(disc):
    eqs, _, _ = disc
    red = eqs.reduced()
    assert [str(c) for c in red.dependent] == ["x(t)", "y(t)"]
    assert red.mass_matrix.shape == (3, 3) and red.basis.shape == (5, 3)
    kane, q, u, (mk, gk, rk) = rolling_disc_kane()
    vals = {mk: M_, gk: G_, rk: R_}
    MM = sp.lambdify(list(q) + list(u), kane.mass_matrix_full.subs(vals), "numpy")
    FF = sp.lambdify(list(q) + list(u), kane.forcing_full.subs(vals), "numpy")
    reduced = red.rhs(m=M_, g=G_, r=R_)
    full = eqs.rhs(m=M_, g=G_, r=R_)
    rng = np.random.default_rng(5)
    for trial in range(11):
        qv = rng.uniform(-3, 3, 5)
        qv[3] = rng.uniform(0.2, np.pi - 0.2)
        if trial == 10:                                 # upright, heading along x
            qv = np.array([0.0, 0.0, 0.0, np.pi / 2, 0.0])
        w = rng.uniform(-3, 3, 3)                       # psi', theta', phi'
        y = reduced(0.0, np.concatenate([qv, w]))
        qd, acc = y[:5], y[5:]
        np.testing.assert_allclose(qd[2:], w, rtol=0, atol=0)
        np.testing.assert_allclose(qd[:2], [-R_ * np.cos(qv[2]) * w[2],
                                            -R_ * np.sin(qv[2]) * w[2]], rtol=1e-13)
        multipliers = full(0.0, np.concatenate([qv, qd]))[5:]
        np.testing.assert_allclose(acc, multipliers[2:], rtol=1e-10, atol=1e-10)
        theirs = np.linalg.solve(MM(*qv, *qd), FF(*qv, *qd)).ravel()[5:]
        np.testing.assert_allclose(acc, theirs[:3], rtol=1e-10, atol=1e-10)


def test_reduced_four_bar_matches_the_multiplier_form(bar4):
    eqs, (q1, q2, q3) = bar4
    red = eqs.reduced(independent=[q1])
    assert red.independent == (q1,) and red.dependent == (q2, q3)
    T = red.basis
    # the partial velocities span the null space of the constraint Jacobian
    rng = np.random.default_rng(3)
    reduced, full = red.rhs(m=1.0, g=9.81), eqs.rhs(m=1.0, g=9.81)
    for _ in range(5):
        a = rng.uniform(-np.pi, np.pi)
        qv = np.array([a, *closure(a)])
        at = dict(zip((q1, q2, q3), qv, strict=True))
        AT = (eqs.constraints.jacobian * T).xreplace(at)
        assert max(abs(float(x)) for x in AT) < 1e-12
        u = rng.uniform(-2, 2)
        y = reduced(0.0, np.array([*qv, u]))
        acc = full(0.0, np.concatenate([qv, y[:3]]))[3:]
        assert y[3] == pytest.approx(acc[0], rel=1e-10, abs=1e-10)


def test_four_bar_linearised_frequency_matches_a_small_amplitude_simulation(bar4):
    eqs, (q1, _, _) = bar4
    red = eqs.reduced(independent=[q1])
    static = red.rhs(m=1.0, g=9.81)

    def fr(a):
        return static(0.0, np.array([a, *closure(a), 0.0]))[3]

    a0 = scipy.optimize.brentq(fr, -2.0, -1.6, xtol=1e-15)     # the crank hanging down
    b0, c0 = closure(a0)
    lin = linearize(eqs, about={"q1": a0, "q2": b0, "q3": c0}, independent=["q1"],
                    parameters={"m": 1.0, "g": 9.81})
    assert lin.coordinates == (q1,)
    omega = float(sp.sqrt(lin.K[0] / lin.M[0]))
    period = 2 * np.pi / omega
    eps = 1e-5
    y0 = np.array([a0 + eps, *closure(a0 + eps), 0.0, 0.0, 0.0])
    sol = scipy.integrate.solve_ivp(eqs.rhs(m=1.0, g=9.81), (0, 3.2 * period), y0,
                                    method="DOP853", rtol=1e-12, atol=1e-14,
                                    dense_output=True)
    ts = np.linspace(0, 3.2 * period, 4001)
    u = sol.sol(ts)[3]
    turns = [scipy.optimize.brentq(lambda t: sol.sol(t)[3], ts[i], ts[i + 1], xtol=1e-15)
             for i in np.where(np.sign(u[1:]) != np.sign(u[:-1]))[0]]
    measured = 2 * (turns[-1] - turns[0]) / (len(turns) - 1)
    assert len(turns) >= 6
    assert measured == pytest.approx(period, rel=1e-6)


def disc_closed_form(omega_spin, m, g, r):
    A, C = m * r**2 / 4, m * r**2 / 2
    return (C * (C + m * r**2) * omega_spin**2 - A * m * g * r) / (A * (A + m * r**2))


def test_rolling_disc_upright_steady_motion_matrices(disc):
    eqs, (x, y, psi, th, phi), (m, g, r) = disc
    Om = sp.Symbol("Omega")
    lin = linearize(eqs, about={"theta": sp.pi / 2}, velocities={"phi": Om})
    assert lin.coordinates == (psi, th, phi)
    A, C = m * r**2 / 4, m * r**2 / 2
    assert lin.M == sp.diag(A, A + m * r**2, C + m * r**2)
    assert lin.C == sp.Matrix([[0, -C * Om, 0], [(C + m * r**2) * Om, 0, 0], [0, 0, 0]])
    assert lin.K == sp.diag(0, -m * g * r, 0)
    # the rolling speed follows from the constraints: x' = -r Omega
    assert lin.velocities["x"] == -r * Om and lin.velocities["y"] == 0
    # the independent rates alone, as a sequence (psi', theta', phi'): the same system
    again = linearize(eqs, about={"theta": sp.pi / 2}, velocities=[0, 0, Om])
    assert (again.M, again.C, again.K) == (lin.M, lin.C, lin.K)
    with pytest.raises(ArgumentError, match=r"`velocities` must give 5 rates \(or the 3"):
        linearize(eqs, about={"theta": sp.pi / 2}, velocities=[0, Om])


@pytest.mark.parametrize("v", [0.3, 1.2, 1.5, 1.52, 1.54, 2.0, 5.0])
def test_rolling_disc_upright_stable_iff_v2_above_g_r_over_3(disc, v):
    eqs, _, _ = disc
    Om = sp.Symbol("Omega")
    lin = linearize(eqs, about={"theta": sp.pi / 2}, velocities={"phi": Om})
    spin = -v / R_
    ev = lin.eigenvalues(m=M_, g=G_, r=R_, Omega=spin)
    wn2 = disc_closed_form(spin, M_, G_, R_)
    stable = v**2 > G_ * R_ / 3
    assert stable == (wn2 > 0)
    if stable:
        assert np.max(np.abs(ev.real)) < 1e-9
        assert np.max(ev.imag) == pytest.approx(np.sqrt(wn2), rel=1e-10)
    else:
        assert np.max(ev.real) == pytest.approx(np.sqrt(-wn2), rel=1e-10)


def sleeping_top():
    a, b, phi = rm.coordinates("alpha beta phi")
    m, g, ell, A, C = rm.constants("m g l A C", positive=True)
    R0 = rm.Frame("R0")
    R1 = R0.rotated("R1", about=R0.i, angle=a)
    R2 = R1.rotated("R2", about=R1.j, angle=b)
    R3 = R2.rotated("R3", about=R2.k, angle=phi)
    G = R0.origin.moved("G", ell * R3.k)
    top = rm.Body("top", frame=R3, mass=m, centre=G,
                  inertia=rm.InertiaOperator.from_products(A, A, C, frame=R3))
    s = rm.System(galilean=R0)
    s.connect(R0, top, rm.joints.Spherical(at=R0.origin))
    s.act(rm.gravity(-g * R0.k))
    return s.equations_of_motion()


@pytest.mark.parametrize("w", [2.0, 14.0, 14.7, 14.8, 15.5, 50.0])   # critical: 14.77
def test_sleeping_top_maievskii(w):
    eqs = sleeping_top()
    omega = sp.Symbol("omega")
    lin = linearize(eqs, velocities={"phi": omega})
    A, C, m, g, ell = sp.symbols("A C m g l", positive=True)
    assert lin.C == sp.Matrix([[0, C * omega, 0], [-C * omega, 0, 0], [0, 0, 0]])
    assert lin.K == sp.diag(-m * g * ell, -m * g * ell, 0)
    vals = {"A": 0.02, "C": 0.012, "m": 0.5, "g": 9.81, "l": 0.08, "omega": w}
    ev = lin.eigenvalues(**vals)
    disc = vals["C"] ** 2 * w**2 - 4 * vals["A"] * vals["m"] * vals["g"] * vals["l"]
    # roots of A s^2 -+ i C w s - m g l = 0
    if disc > 0:
        assert np.max(np.abs(ev.real)) < 1e-9
        expected = (vals["C"] * w + np.sqrt(disc)) / (2 * vals["A"])
        assert np.max(ev.imag) == pytest.approx(expected, rel=1e-10)
    else:
        assert np.max(ev.real) == pytest.approx(np.sqrt(-disc) / (2 * vals["A"]), rel=1e-8)


def test_linearising_off_the_loop_states_the_residual(bar4):
    eqs, _ = bar4
    with pytest.raises(ArgumentError, match=r"violates the constraints: the residual Φ\(q\*\)"):
        linearize(eqs, about={"q1": -1.8, "q2": 0.0, "q3": 0.0}, independent=["q1"],
                  parameters={"m": 1.0, "g": 9.81})


def test_linearising_a_four_bar_off_equilibrium_states_the_residual(bar4):
    eqs, _ = bar4
    a = -1.0
    with pytest.raises(ArgumentError, match=r"not an equilibrium .* residual f_r\(q\*, u\*\)"):
        linearize(eqs, about={"q1": a, "q2": closure(a)[0], "q3": closure(a)[1]},
                  independent=["q1"], parameters={"m": 1.0, "g": 9.81})


def test_rates_violating_the_rolling_constraints_are_refused(disc):
    eqs, _, _ = disc
    with pytest.raises(ArgumentError, match=r"`velocities` violate the constraints: residual"):
        linearize(eqs, about={"theta": sp.pi / 2}, velocities={"phi": 2, "x": 0.5},
                  parameters={"r": 0.7})


def test_leaning_disc_is_not_a_steady_motion(disc):
    eqs, _, _ = disc
    with pytest.raises(ArgumentError, match=r"not an equilibrium .* residual f_r"):
        linearize(eqs, about={"theta": 1.2})
    with pytest.raises(ArgumentError, match=r"not a steady motion .* residual f_r"):
        linearize(eqs, about={"theta": 1.2}, velocities={"phi": 3.0})


def test_wrong_independent_coordinates_are_refused(disc, bar4):
    eqs, _, _ = disc
    with pytest.raises(ArgumentError, match=r"`independent` must name 3 distinct"):
        eqs.reduced(independent=["psi"])
    with pytest.raises(ArgumentError, match=r"cannot be solved for the rates of \['x', 'psi'\]"):
        eqs.reduced(independent=["y", "theta", "phi"])
    with pytest.raises(ArgumentError, match=r"`independent` names 'z', which is not"):
        eqs.reduced(independent=["z", "theta", "phi"])
    with pytest.raises(ArgumentError, match=r"nothing to reduce"):
        sleeping_top().reduced()
    with pytest.raises(ArgumentError, match=r"`independent` applies to equations with"):
        linearize(sleeping_top(), independent=["alpha"])


def test_gear_pair_turning_freely_is_a_steady_motion_with_the_reduced_inertia():
    """Two gears in mesh (ratio lambda = -z1/z2 = -1/2), no torque: turning at any constant
    rate is a steady motion; the linear system on q1 has the reduced inertia J1 + lambda^2 J2
    (power theorem) and no stiffness."""
    from rigidmech.kinematics import Gear, GearPair

    q1, q2 = rm.coordinates("q1 q2")
    J1, J2 = rm.constants("J1 J2", positive=True)
    R0 = rm.Frame("R0")
    G1 = R0.rotated("G1", about=R0.k, angle=q1)
    G2 = R0.rotated("G2", about=R0.k, angle=q2, origin=R0.point("O2", 60, 0, 0))
    b1 = rm.Body("g1", frame=G1, mass=1,
                 inertia=rm.inertia.disk(1, sp.sqrt(2 * J1), axis=G1.k, centre=G1.origin))
    b2 = rm.Body("g2", frame=G2, mass=1,
                 inertia=rm.inertia.disk(1, sp.sqrt(2 * J2), axis=G2.k, centre=G2.origin))
    s = rm.System(galilean=R0)
    s.connect(R0, b1, rm.joints.Pivot(at=G1.origin, axis=R0.k))
    s.connect(R0, b2, rm.joints.Pivot(at=G2.origin, axis=R0.k))
    pair = GearPair(Gear(20, 2), Gear(40, 2))
    s.connect(b1, b2, rm.actions.GearMesh(pair, b1, b2, carrier=R0, axis=R0.k))
    eqs = s.equations_of_motion()
    w = sp.Symbol("w")
    lin = linearize(eqs, velocities={"q1": w}, independent=[q1])
    lam = pair.ratio
    assert sp.simplify(lin.M[0] - (J1 + lam**2 * J2)) == 0
    assert lin.K == sp.zeros(1, 1) and lin.C == sp.zeros(1, 1)
    assert sp.simplify(lin.velocities["q2"] - lam * w) == 0
    with pytest.raises(ArgumentError, match=r"`velocities` violate the constraints: residual"):
        linearize(eqs, velocities={"q1": 1, "q2": 1}, independent=[q1])


@pytest.mark.parametrize("length", [1.0, 1e-10, 1e6])
def test_rank_decisions_do_not_depend_on_the_unit_of_length(length):
    """A particle on a circle of radius R (x^2 + y^2 = R^2) under gravity, about the bottom,
    x independent: omega^2 = g / R whatever the unit of length (the rank of Phi_q = (0, -2R)
    is decided relative to its size, as assemble does, not against an absolute 1e-9)."""
    from rigidmech.dynamics import Constraints

    x, y = rm.coordinates("x y")
    m, g, R = rm.constants("m g R", positive=True)
    phi = x**2 + y**2 - R**2
    eqs = rm.EquationsOfMotion(
        coordinates=(x, y), mass_matrix=sp.ImmutableMatrix(sp.diag(m, m)),
        forcing=sp.ImmutableMatrix([0, -m * g]),
        constraints=Constraints((x, y), [("rod", phi.diff(rm.t), phi)]))
    lin = linearize(eqs, about={"x": 0, "y": -length}, independent=["x"],
                    parameters={"m": 1.0, "g": 9.81, "R": length})
    M, _, K, _ = lin.numeric()
    np.testing.assert_allclose(K[0, 0] / M[0, 0], 9.81 / length, rtol=1e-12)
