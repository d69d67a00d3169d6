"""Steady motions with q' ≠ 0 and their stability (book, ch. 20, 25.4): the conical pendulum,
the heavy symmetric top's steady precession, the sleeping top and a disc rolling in a circle,
against closed forms and a simulation."""

import numpy as np
import pytest
import sympy as sp

import rigidmech as rm
from rigidmech import EquationsOfMotion, models
from rigidmech.errors import ArgumentError
from rigidmech.vibrations import SteadyMotion, steady_motions, steady_stability

th, ph, thd, phd = sp.symbols("theta phi theta_dot phi_dot")
m, g, L = sp.symbols("m g L", positive=True)


def _spherical_pendulum():
    # a point mass m at distance L from O, polar angle theta from the downward vertical,
    # azimuth phi: T = m L^2 (theta'^2 + sin^2 theta phi'^2) / 2, V = -m g L cos theta
    return EquationsOfMotion(
        coordinates=(th, ph), q=(th, ph), u=(thd, phd),
        mass_matrix=sp.diag(m * L**2, m * L**2 * sp.sin(th)**2),
        forcing=sp.Matrix([m * L**2 * sp.sin(th) * sp.cos(th) * phd**2 - m * g * L * sp.sin(th),
                           -2 * m * L**2 * sp.sin(th) * sp.cos(th) * thd * phd]))


def test_conical_pendulum_rate_squared_is_g_over_L_cos_theta():
    alpha = sp.Symbol("alpha", positive=True)
    found = steady_motions(_spherical_pendulum(), fixed={th: alpha}, cyclic={ph: None})
    assert len(found) == 2
    for s in found:
        assert sp.simplify(s.rates["phi"]**2 - g / (L * sp.cos(alpha))) == 0
        assert s.rates["theta"] == 0 and s.positions["theta"] == alpha


def test_conical_pendulum_numeric_angle_for_a_given_rate():
    # cos theta = g / (L w^2); theta = 0 (hanging, spinning in place) is outside the box
    found = steady_motions(_spherical_pendulum(), fixed={"theta": None}, cyclic={"phi": 6.0},
                           within=(0.1, 1.5), m=2.0, g=9.81, L=0.5)
    assert len(found) == 1
    assert found[0].positions["theta"] == pytest.approx(np.arccos(9.81 / (0.5 * 36)), abs=1e-12)
    assert steady_stability(_spherical_pendulum(), found[0], m=2.0, g=9.81, L=0.5) == "stable"


def test_heavy_top_steady_precession_obeys_the_closed_form():
    # Lagrange top about its fixed point O, A_O = A + m l^2: steady precession at nutation
    # theta with omega3 = phi' + psi' cos theta needs
    # A_O psi'^2 cos theta - C omega3 psi' + m g l = 0 (two rates: slow and fast)
    top = models.heavy_top()
    eqs = top.system.equations_of_motion()
    p = {"m": 1.0, "g": 9.81, "l": 0.1, "A": 0.002, "C": 0.004}
    theta0, spin = 0.6, 60.0
    found = steady_motions(eqs, fixed={"theta": theta0}, cyclic={"psi": None, "phi": spin},
                           within=(-200.0, 200.0), **p)
    AO = p["A"] + p["m"] * p["l"]**2
    # in terms of phi': (A_O - C) cos theta psi'^2 - C phi' psi' + m g l = 0
    expected = np.sort(np.roots([(AO - p["C"]) * np.cos(theta0), -p["C"] * spin,
                                 p["m"] * p["g"] * p["l"]]).real)
    got = np.sort([s.rates["psi"] for s in found])
    assert got == pytest.approx(expected, rel=1e-10)
    for s in found:
        w3 = spin + s.rates["psi"] * np.cos(theta0)
        assert AO * s.rates["psi"]**2 * np.cos(theta0) - p["C"] * w3 * s.rates["psi"] \
            + p["m"] * p["g"] * p["l"] == pytest.approx(0.0, abs=1e-9)
        # every steady precession of the Lagrange top is stable (its reduced potential has
        # a minimum there)
        assert steady_stability(eqs, s, **p) == "stable"


def test_heavy_top_steady_precession_symbolic_closed_form():
    # the same relation with symbols: nutation alpha, spin rate p, both roots psi'
    top = models.heavy_top()
    eqs = top.system.equations_of_motion()
    m_, g_, l_, A, C = top.constants
    alpha, p = sp.symbols("alpha p", positive=True)
    found = steady_motions(eqs, fixed={"theta": alpha}, cyclic={"psi": None, "phi": p})
    assert len(found) == 2
    AO = A + m_ * l_**2
    for s in found:
        w = s.rates["psi"]
        assert sp.simplify(AO * w**2 * sp.cos(alpha) - C * (p + w * sp.cos(alpha)) * w
                           + m_ * g_ * l_) == 0


def _cardan_top():
    # the heavy top oriented by tilts a (about R0.i), b (about the next j) and its spin phi:
    # regular at the vertical, where the Euler angles are singular
    a, b, phi = rm.coordinates("a b phi")
    mm, gg, ll, A, C = rm.constants("m g l A C", positive=True)
    R0 = rm.Frame("R0")
    R1 = R0.rotated("R1", about=R0.i, angle=a)
    R2 = R1.rotated("R2", about=R1.j, angle=b)
    R = R2.rotated("R", about=R2.k, angle=phi)
    G = R0.origin.moved("G", ll * R.k)
    body = rm.Body("top", frame=R, mass=mm, centre=G,
                   inertia=rm.inertia.InertiaOperator.from_products(A, A, C, frame=R, at=G))
    s = rm.System(galilean=R0)
    s.connect(R0, body, rm.actions.Spherical(at=R0.origin))
    s.act(rm.gravity(-gg * R0.k))
    return s.equations_of_motion()


TOP = {"m": 1.0, "g": 9.81, "l": 0.1, "A": 0.002, "C": 0.004}
# the sleeping top is stable (gyroscopically) for C^2 w^2 > 4 A_O m g l, A_O = A + m l^2
W_CRIT = np.sqrt(4 * (TOP["A"] + TOP["m"] * TOP["l"]**2) * TOP["m"] * TOP["g"] * TOP["l"]) \
    / TOP["C"]


@pytest.mark.parametrize(("factor", "verdict"), [
    (1.001, "linearly stable"), (1 + 1e-6, "linearly stable"), (1 - 1e-6, "unstable"),
    (0.999, "unstable"), (0.5, "unstable")])
def test_sleeping_top_critical_spin(factor, verdict):
    eqs = _cardan_top()
    motion = SteadyMotion({"a": 0, "b": 0, "phi": 0}, {"a": 0, "b": 0, "phi": factor * W_CRIT},
                          ("phi",))
    assert steady_stability(eqs, motion, **TOP) == verdict


def test_sleeping_top_at_the_critical_spin_is_not_stable():
    # at C w = 2 sqrt(A_O m g l) the two exponents coincide (a Jordan block: the tilt grows
    # like t): not stable
    eqs = _cardan_top()
    motion = SteadyMotion({"a": 0, "b": 0, "phi": 0}, {"a": 0, "b": 0, "phi": W_CRIT}, ("phi",))
    assert steady_stability(eqs, motion, **TOP) in ("unstable", "undecided")


def test_sleeping_top_found_as_a_steady_motion():
    found = steady_motions(_cardan_top(), fixed={"a": 0, "b": None}, cyclic={"phi": 50.0},
                           within=(-0.5, 0.5), **TOP)
    assert [s.positions["b"] for s in found] == pytest.approx([0.0], abs=1e-12)


DISC = {"m": 1.0, "g": 9.81, "r": 0.3}


def test_rolling_disc_upright_stable_above_g_over_3r():
    # the thin disc rolling straight upright is stable iff phi'^2 > g / (3 r) (Routh; the
    # lean's stiffness -m g r + 3 m r^2 phi'^2 after eliminating the heading rate)
    eqs = models.rolling_disc("given").system.equations_of_motion()
    crit = np.sqrt(DISC["g"] / (3 * DISC["r"]))
    verdicts = []
    for factor in (1.01, 1 + 1e-6, 1.0, 1 - 1e-6, 0.99):
        motion = SteadyMotion({"x": 0, "y": 0, "psi": 0, "theta": sp.pi / 2, "phi": 0},
                              {"psi": 0, "theta": 0, "phi": factor * crit}, ("psi", "phi"))
        verdicts.append(steady_stability(eqs, motion, **DISC))
    assert verdicts == ["stable", "stable", "undecided", "unstable", "unstable"]


def test_rolling_disc_in_a_circle_stays_steady_in_a_simulation():
    eqs = models.rolling_disc("given").system.equations_of_motion()
    theta0, spin = 1.2, -12.0
    found = steady_motions(eqs, fixed={"theta": theta0}, cyclic={"psi": None, "phi": spin},
                           within=(-50.0, 50.0), **DISC)
    assert found
    for s in found:
        rates = s.rates
        # the dependent rates follow the rolling: x' = -r cos(psi) phi', y' = -r sin(psi) phi'
        u0 = [-DISC["r"] * spin, 0.0, rates["psi"], 0.0, spin]
        sim = eqs.simulate((0.0, 2.0), q0=[0.0, 0.0, 0.0, theta0, 0.0], u0=u0, rtol=1e-11,
                           atol=1e-12, n_output=201, **DISC)
        assert np.max(np.abs(sim.q[3] - theta0)) < 1e-9
        assert np.max(np.abs(sim.u[2] - rates["psi"])) < 1e-9 * max(abs(rates["psi"]), 1)
    # a heading rate off by 1 % does not keep the lean: the check discriminates
    u0 = [-DISC["r"] * spin, 0.0, 1.01 * found[0].rates["psi"], 0.0, spin]
    sim = eqs.simulate((0.0, 2.0), q0=[0.0, 0.0, 0.0, theta0, 0.0], u0=u0, rtol=1e-11,
                       atol=1e-12, n_output=201, **DISC)
    assert np.max(np.abs(sim.q[3] - theta0)) > 1e-4


@pytest.mark.parametrize(("gap", "count"), [(0.0, 1), (2e-9 * (1 - 1e-3), 1),
                                             (2e-9 * (1 + 1e-3), 0), (1e-6, 0)])
def test_more_equations_than_unknowns_least_squares_root_within_tol(gap, count):
    # rows x - 1 and x - 1 - gap: the least-squares root x = 1 + gap/2 leaves gap/2 in each
    # row, a steady motion while gap/2 <= 1e-9 (the boundary at gap = 2e-9)
    x, y, vx, vy = sp.symbols("x y v_x v_y")
    eqs = EquationsOfMotion(coordinates=(x, y), q=(x, y), u=(vx, vy),
                            mass_matrix=sp.eye(2),
                            forcing=sp.Matrix([x - 1, x - 1 - sp.Float(gap, 30)]))
    found = steady_motions(eqs, fixed={x: None}, cyclic={y: 0.5}, within=(0.0, 2.0))
    assert len(found) == count
    if count:
        assert found[0].positions["x"] == pytest.approx(1 + gap / 2, abs=1e-12)


def test_errors_name_the_argument():
    eqs = _spherical_pendulum()
    with pytest.raises(ArgumentError, match="`fixed` names an unknown coordinate"):
        steady_motions(eqs, fixed={"x": 0}, cyclic={"phi": None})
    with pytest.raises(ArgumentError, match=r"\['phi'\] are neither"):
        steady_motions(eqs, fixed={"theta": None}, cyclic={})
    with pytest.raises(ArgumentError, match="no unknown"):
        steady_motions(eqs, fixed={"theta": 1}, cyclic={"phi": 1})
    # q' = 1 solves f(0, q') = 0 but f depends on q: not a steady motion
    x, v = sp.symbols("x v")
    driven = EquationsOfMotion(coordinates=(x,), q=(x,), u=(v,), mass_matrix=sp.Matrix([[1]]),
                               forcing=sp.Matrix([-sp.sin(x) + v - 1]))
    with pytest.raises(ArgumentError, match="a steady rate is possible only"):
        steady_motions(driven, fixed={}, cyclic={x: None})
    with pytest.raises(ArgumentError, match="`within` must give a range"):
        steady_motions(eqs, fixed={"theta": None}, cyclic={"phi": 4.0}, within=(1, 0),
                       m=1, g=1, L=1)
    with pytest.raises(ArgumentError, match="`motion` must be a SteadyMotion"):
        steady_stability(eqs, {"theta": 1})


def _fd_exponents(eqs, motion, h=1e-6):
    # an independent route: central differences of the nonlinear right-hand side in
    # (theta, theta', phi') about the steady state (phi does not enter)
    rhs = eqs.rhs()
    y0 = np.array([motion.positions["theta"], 0.0, 0.0, motion.rates["phi"]])
    keep = [0, 2, 3]
    J = np.empty((3, 3))
    for col, j in enumerate(keep):
        e = np.zeros(4)
        e[j] = h
        J[:, col] = ((rhs(0.0, y0 + e) - rhs(0.0, y0 - e)) / (2 * h))[keep]
    return np.linalg.eigvals(J)


@pytest.mark.parametrize("d", [0.5, 0.0, -0.2, -1.0])
def test_driven_conical_pendulum_with_a_motor_characteristic(d):
    # the azimuth driven by a motor whose torque c (W - phi') holds the rate at W: the cyclic
    # row has damping (C_cc = c), so it is not a momentum: decided on (theta, theta', phi');
    # the polar angle damped by d
    c, W = 2.0, 3.0
    eqs = EquationsOfMotion(
        coordinates=(th, ph), q=(th, ph), u=(thd, phd),
        mass_matrix=sp.diag(1, sp.sin(th)**2),
        forcing=sp.Matrix([sp.sin(th) * sp.cos(th) * phd**2 - sp.sin(th) - d * thd,
                           -2 * sp.sin(th) * sp.cos(th) * thd * phd + c * (W - phd)]))
    (motion,) = steady_motions(eqs, fixed={"theta": None}, cyclic={"phi": W},
                               within=(0.1, 1.5))
    assert np.cos(motion.positions["theta"]) == pytest.approx(1 / W**2, rel=1e-12)
    s = _fd_exponents(eqs, motion)
    assert abs(np.max(s.real)) > 1e-3            # not a borderline case
    expected = "asymptotically stable" if np.max(s.real) < 0 else "unstable"
    assert steady_stability(eqs, motion) == expected
