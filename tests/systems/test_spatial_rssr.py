"""A spatial RSSR four-bar: a multi-body spatial loop (book, ch. 13.2, 25.3).

A crank turns on a pivot about R0.k at O (q1), a rocker on a pivot about R0.i at D (q3): the
two axes are skew. The coupler AB is joined to the crank at A and the loop is closed by a
spherical joint at B between the coupler and the rocker. Two ways of joining the coupler to
the crank:

* a spherical joint (yaw psi, pitch theta, roll phi): the coupler's spin phi about its own
  axis AB is an *idle mobility* (it moves no other body), so the mechanism has m = 2;
* a spherical joint with finger (a universal-like joint: the coupler turns relative to the
  crank by a about R1.k, then by b about the coupler's j; the finger blocks the rotation
  about the third axis): no idle spin, m = 1.

Everything is checked against numbers computed without rigidmech: the input-output equation
of the RSSR, |B(q3) - A(q1)|^2 = L^2, i.e. P cos q3 + Q sin q3 = R, solved in closed form
(and checked against scipy's brentq), its finite differences for velocities and
accelerations, the positions of the points written with rotation matrices by hand, and the
fundamental principle on each body (m a_G and d sigma_G / dt by finite differences of the
hand-written motion).
"""

import functools

import numpy as np
import pytest
import sympy as sp
from scipy.optimize import brentq

import rigidmech as rm
from rigidmech.dynamics import System
from rigidmech.errors import ConnectionError_
from rigidmech.inertia import InertiaOperator

# crank OA, ground pivot D of the rocker, rocker DB, coupler AB; masses and inertias at G
A_, D_, C_, L_ = 0.25, np.array([0.9, 0.1, 0.4]), 0.8, 1.3
M = {"crank": 1.0, "coupler": 0.8, "rocker": 1.2}
J = {"crank": np.diag([0.001, 0.006, 0.006]),
     "coupler": np.array([[0.004, 0.0, 0.0], [0.0, 0.11, 0.001], [0.0, 0.001, 0.112]]),
     "rocker": np.diag([0.07, 0.002, 0.07])}
G = 9.81
EX, EY, EZ = np.eye(3)


def _body(name, frame, origin, offset, inertia=None):
    Gp = origin.moved("G" + name, offset)
    inertia = J[name] if inertia is None else inertia
    return rm.Body(name, frame=frame, mass=M[name], centre=Gp,
                   inertia=InertiaOperator.from_matrix(inertia.tolist(), frame=frame, at=Gp))


def _shared(build):
    """``build`` once per module for each set of hashable arguments (the tests read the
    systems, never change them: each derivation is done once, not once per test)."""
    built = {}

    @functools.wraps(build)
    def shared(*args, **kwargs):
        try:
            key = (args, tuple(sorted(kwargs.items())))
            hash(key)
        except TypeError:               # an array among the arguments: built for the caller
            return build(*args, **kwargs)
        if key not in built:
            built[key] = build(*args, **kwargs)
        return built[key]

    return shared


@_shared
def rssr(finger=False, g=G, meets=True, coupler_inertia=None):
    """The RSSR four-bar; the coupler on the crank by a spherical joint (coordinates q1, q3,
    psi, theta, phi) or by a spherical joint with finger (q1, q3, a, b). ``meets=False``
    forgets to say which point of the rocker meets the coupler's B."""
    q1, q3 = rm.coordinates("q1 q3")
    R0 = rm.Frame("R0")
    R1 = R0.rotated("R1", about=R0.k, angle=q1)
    A = R0.origin.moved("A", A_ * R1.i)
    if finger:
        a, b = rm.coordinates("a b")
        U = R1.rotated("U", about=R1.k, angle=a, origin=A)
        R2 = U.rotated("R2", about=U.j, angle=b)
        joint_A = rm.joints.SphericalWithFinger(at=A, axis=U.i)
    else:
        psi, th, ph = rm.coordinates("psi theta phi")
        Ca = R0.rotated("Ca", about=R0.k, angle=psi, origin=A)
        Cb = Ca.rotated("Cb", about=Ca.j, angle=th)
        R2 = Cb.rotated("R2", about=Cb.i, angle=ph)
        joint_A = rm.joints.Spherical(at=A)
    D = R0.point("D", *D_)
    R3 = R0.rotated("R3", about=R0.i, angle=q3, origin=D)
    crank = _body("crank", R1, R0.origin, A_ / 2 * R1.i)
    coupler = _body("coupler", R2, A, L_ / 2 * R2.i, coupler_inertia)
    rocker = _body("rocker", R3, D, C_ / 2 * R3.j)
    s = System(galilean=R0)
    s.connect(R0, crank, rm.joints.Pivot(at=R0.origin, axis=R0.k))
    s.connect(crank, coupler, joint_A)
    s.connect(R0, rocker, rm.joints.Pivot(at=D, axis=R0.i))
    s.connect(coupler, rocker, rm.joints.Spherical(at=A.moved("B", L_ * R2.i)),
              meets=D.moved("B3", C_ * R3.j) if meets else None)
    if g:
        s.act(rm.gravity(-g * R0.k))
    return s


# -- the loop by hand -------------------------------------------------------------------
def rot(axis, angle):
    c, s = np.cos(angle), np.sin(angle)
    if axis == "x":
        return np.array([[1, 0, 0], [0, c, -s], [0, s, c]])
    if axis == "y":
        return np.array([[c, 0, s], [0, 1, 0], [-s, 0, c]])
    return np.array([[c, -s, 0], [s, c, 0], [0, 0, 1]])


def io_coefficients(q1):
    """|D + c (0, cos q3, sin q3) - a (cos q1, sin q1, 0)|^2 = L^2 as P cos q3 + Q sin q3 = R."""
    dx, dy, dz = D_ - A_ * np.array([np.cos(q1), np.sin(q1), 0.0])
    return 2 * C_ * dy, 2 * C_ * dz, L_**2 - dx**2 - dy**2 - dz**2 - C_**2


def rocker_angle(q1):
    """The branch q3 = atan2(Q, P) + arccos(R / sqrt(P^2 + Q^2)) of the input-output equation
    (the crank turns fully: |R| / sqrt(P^2 + Q^2) < 0.72 for every q1)."""
    P, Q, R = io_coefficients(q1)
    return np.arctan2(Q, P) + np.arccos(R / np.hypot(P, Q))


def loop(q1, finger=False):
    """The dependent coordinates (by name) for the crank angle q1: q3, then the coupler's
    direction e = (B - A) / L as yaw and pitch."""
    q3 = rocker_angle(q1)
    A = A_ * rot("z", q1)[:, 0]
    B = D_ + C_ * rot("x", q3)[:, 1]
    e = (B - A) / L_
    psi, th = np.arctan2(e[1], e[0]), -np.arcsin(e[2])
    if finger:
        return {"q3": q3, "a": np.angle(np.exp(1j * (psi - q1))), "b": th}
    return {"q3": q3, "psi": psi, "theta": th}


def kinematics(q, finger=False):
    """Rotation matrices of crank, coupler, rocker and their mass centres, from the
    coordinates (a dict by name), by hand."""
    R1, R3 = rot("z", q["q1"]), rot("x", q["q3"])
    if finger:
        R2 = rot("z", q["q1"] + q["a"]) @ rot("y", q["b"])
    else:
        R2 = rot("z", q["psi"]) @ rot("y", q["theta"]) @ rot("x", q["phi"])
    A = A_ * R1[:, 0]
    centres = {"crank": A / 2, "coupler": A + L_ / 2 * R2[:, 0],
               "rocker": D_ + C_ / 2 * R3[:, 1]}
    return {"crank": R1, "coupler": R2, "rocker": R3}, centres, A + L_ * R2[:, 0], (
        D_ + C_ * R3[:, 1])


def angular_velocity(q, u, finger=False):
    """omega of each body in R0 (components in R0) by hand."""
    if finger:
        w2 = (u["q1"] + u["a"]) * EZ + u["b"] * rot("z", q["q1"] + q["a"])[:, 1]
    else:
        Rz = rot("z", q["psi"])
        w2 = u["psi"] * EZ + u["theta"] * Rz[:, 1] + u["phi"] * (Rz @ rot("y", q["theta"]))[:, 0]
    return {"crank": u["q1"] * EZ, "coupler": w2, "rocker": u["q3"] * EX}


def names(s):
    return [c.func.__name__ for c in s.coordinates]


def dynamics_by_hand(s, q, u, acc, finger=False, h=1e-4):
    """m a_G and d sigma_G / dt of each body at the state (q, u, q''), from the hand-written
    motion along q(t) = q + u t + q'' t^2 / 2 (exact to second order), by central
    differences."""
    n = names(s)

    def state(dt):
        qq = dict(zip(n, q + u * dt + acc * dt**2 / 2, strict=True))
        return qq, dict(zip(n, u + acc * dt, strict=True))

    def centres(dt):
        return kinematics(state(dt)[0], finger)[1]

    def momenta(dt):
        qq, uu = state(dt)
        R, _, _, _ = kinematics(qq, finger)
        w = angular_velocity(qq, uu, finger)
        return {b: R[b] @ J[b] @ R[b].T @ w[b] for b in R}

    cp, c0, cm = centres(h), centres(0.0), centres(-h)
    hp, hm = momenta(h), momenta(-h)
    return {b: (M[b] * (cp[b] - 2 * c0[b] + cm[b]) / h**2, (hp[b] - hm[b]) / (2 * h))
            for b in M}


def state_rule(s, q, u, acc, lam):
    rule = {}
    for c, qq, uu, aa in zip(s.coordinates, q, u, acc, strict=True):
        rule[c.diff(rm.t, 2)] = aa
        rule[c.diff(rm.t)] = uu
        rule[c] = qq
    rule.update(dict(zip(s.multiplier_symbols(), lam, strict=True)))
    return rule


def numeric(torsor, at, rule, R0):
    T = torsor.at(at)
    return tuple(np.array([float(sp.sympify(x).xreplace(rule)) for x in v.components(R0)])
                 for v in (T.resultant, T.moment))


def assembled(s, q1, rate, finger=False, spin=0.0, spin_rate=0.0):
    guess = {k: v + 0.05 for k, v in loop(q1, finger).items()}
    guess["q1"] = q1
    independent, rates = ["q1"], {"q1": rate}
    if not finger:
        guess["phi"], rates["phi"] = spin, spin_rate
        independent.append("phi")
    return s.assemble(guess, independent=independent, rates=rates)


# -- tests ------------------------------------------------------------------------------
def gap(q3, q1):
    """|B(q3) - A(q1)|^2 - L^2, the loop's equation written on the points."""
    A = A_ * rot("z", q1)[:, 0]
    return np.sum((D_ + C_ * rot("x", q3)[:, 1] - A) ** 2) - L_**2


def test_input_output_equation_closed_form_agrees_with_brentq():
    for q1 in np.linspace(-3.0, 3.0, 7):
        P, Q, _ = io_coefficients(q1)
        start = np.arctan2(Q, P)  # the branch runs from the maximum of gap to its minimum
        root = brentq(gap, start, start + np.pi, args=(q1,), xtol=1e-15)
        assert rocker_angle(q1) == pytest.approx(root, abs=1e-12)
        assert gap(root, q1) == pytest.approx(0.0, abs=1e-12)


def test_mobility_counts_the_idle_spin_of_the_coupler():
    # spherical + spherical: N_c = 1 + 3 + 1 + 3 = 8, rank 6 of one spatial loop, m = 2 (the
    # output and the coupler's spin about AB), h = N_s - 6 N_b + m = 16 - 18 + 2 = 0
    r = rssr().mobility()
    assert (r.mobility, r.hyperstaticity, r.loops) == (2, 0, 1)
    assert (r.kinematic_unknowns, r.kinematics_rank, r.static_unknowns) == (8, 6, 16)
    # with a finger at A the spin is blocked: N_c = 7, m = 1, N_s = 17, still isostatic
    r = rssr(finger=True).mobility()
    assert (r.mobility, r.hyperstaticity, r.loops) == (1, 0, 1)
    assert (r.kinematic_unknowns, r.static_unknowns) == (7, 17)


def test_closure_conditions_are_the_three_of_the_spherical_joint():
    for finger in (False, True):
        s = rssr(finger=finger)
        assert [row[0] for row in s.closure_conditions()] == ["4.u", "4.v", "4.w"]
        # three conditions on 5 (4) coordinates: 2 (1) independent parameters, as mobility()
        assert len(s.coordinates) - 3 == s.mobility().mobility


def test_closing_joint_at_a_point_of_one_solid_only_is_refused():
    # without `meets`, B (a point of the coupler) would be taken as the rocker's point too:
    # the three conditions vanish identically and the loop would silently stay open
    with pytest.raises(ConnectionError_, match=r"Spherical at B closes a loop between "
                                               r"coupler and rocker, but B moves with only "
                                               r"one of them .* Give `meets`, the point of "
                                               r"rocker that meets B"):
        rssr(meets=False)


@pytest.mark.parametrize("finger", [False, True])
def test_assembled_positions_match_the_loop_solution(finger):
    s = rssr(finger=finger, g=0.0)
    for q1 in (-2.5, -0.8, 0.4, 1.9, 3.0):
        q0, _ = assembled(s, q1, 1.0, finger, spin=0.7)
        expected = loop(q1, finger)
        for k, v in expected.items():
            assert q0[k] == pytest.approx(v, abs=1e-10), k
        assert q0["q1"] == q1
        if not finger:
            assert q0["phi"] == 0.7  # the idle spin is kept as given
        _, _, B2, B3 = kinematics(q0, finger)
        assert B2 == pytest.approx(B3, abs=1e-12)


@pytest.mark.parametrize("finger", [False, True])
def test_velocities_match_finite_differences_of_the_loop_solution(finger):
    s = rssr(finger=finger, g=0.0)
    rate, h = 1.7, 1e-6
    for q1 in (-2.5, 0.4, 1.9):
        _, u0 = assembled(s, q1, rate, finger, spin_rate=-0.6)
        plus, minus = loop(q1 + h, finger), loop(q1 - h, finger)
        for k in plus:
            assert u0[k] == pytest.approx(rate * (plus[k] - minus[k]) / (2 * h), rel=1e-7,
                                          abs=1e-8), k
        if not finger:
            assert u0["phi"] == -0.6


@pytest.mark.parametrize("finger", [False, True])
def test_accelerations_match_finite_differences_of_the_loop_solution(finger):
    # along any motion, x(t) = f(q1(t)) for each dependent x: x'' = f''(q1) q1'^2 + f'(q1) q1''
    s = rssr(finger=finger)
    eqs = s.equations_of_motion()
    n = names(s)
    h = 1e-4
    for q1 in (-2.5, 0.4, 1.9):
        q0, u0 = assembled(s, q1, 1.7, finger, spin=0.3, spin_rate=-0.6)
        y = np.array([q0[k] for k in n] + [u0[k] for k in n])
        acc = dict(zip(n, eqs.rhs()(0.0, y)[len(n):], strict=True))
        plus, mid, minus = loop(q1 + h, finger), loop(q1, finger), loop(q1 - h, finger)
        for k in plus:
            d1 = (plus[k] - minus[k]) / (2 * h)
            d2 = (plus[k] - 2 * mid[k] + minus[k]) / h**2
            assert acc[k] == pytest.approx(d2 * u0["q1"] ** 2 + d1 * acc["q1"], rel=1e-6,
                                           abs=1e-6), k


def test_simulation_keeps_the_loop_closed_and_the_energy():
    # perfect joints and gravity only: the mechanical energy is conserved; the closure |B2 -
    # B3| (by hand, from the simulated coordinates) stays small (Baumgarte stabilisation)
    s = rssr()
    eqs = s.equations_of_motion()
    q0, u0 = assembled(s, 0.4, 3.0, spin_rate=1.0)
    sim = eqs.simulate(t=(0.0, 5.0), q0=q0, u0=u0, rtol=1e-10, atol=1e-12, n_output=201)
    n = names(s)
    gaps = [np.linalg.norm(np.subtract(*kinematics(dict(zip(n, sim.q[:, i], strict=True)))[2:]))
            for i in range(sim.q.shape[1])]
    assert max(gaps) < 1e-8
    E = sim.evaluate(s.mechanical_energy())
    assert np.ptp(E) < 1e-7 * np.max(np.abs(E))
    assert np.ptp(sim.q[0]) > 2 * np.pi  # the crank turns over


@pytest.mark.parametrize("finger", [False, True])
def test_connection_actions_satisfy_newton_on_each_body(finger):
    # at states of a simulated motion: for each body, the sum of the actions exerted on it
    # (connection actions from System, gravity) equals its dynamic torsor at G, computed by
    # hand; the pivots transmit no moment about their axes, the spherical joints no moment
    # at their centres
    s = rssr(finger=finger)
    eqs = s.equations_of_motion()
    n = names(s)
    q0, u0 = assembled(s, 0.4, 3.0, finger, spin_rate=1.0)
    sim = eqs.simulate(t=(0.0, 1.0), q0=q0, u0=u0, rtol=1e-11, atol=1e-12, n_output=3)
    R0 = s.galilean
    crank, coupler, rocker = s.bodies
    actions = {"O": s.connection_action(R0, crank), "A": s.connection_action(crank, coupler),
               "D": s.connection_action(R0, rocker), "B": s.connection_action(coupler, rocker)}
    for i in range(sim.q.shape[1]):
        q, u = sim.q[:, i], sim.u[:, i]
        acc = eqs.rhs()(0.0, np.concatenate([q, u]))[len(n):]
        lam = s.multipliers(q, u)
        rule = state_rule(s, q, u, acc, lam)
        _, centres, B2, _ = kinematics(dict(zip(n, q, strict=True)), finger)
        hand = dynamics_by_hand(s, q, u, acc, finger)
        on = {"crank": [(crank, "O", 1), (crank, "A", -1)],
              "coupler": [(coupler, "A", 1), (coupler, "B", -1)],
              "rocker": [(rocker, "D", 1), (rocker, "B", 1)]}
        for name, terms in on.items():
            F, Mo = M[name] * G * -EZ, np.zeros(3)
            for body, key, sign in terms:
                f, mo = numeric(actions[key], body.centre, rule, R0)
                F, Mo = F + sign * f, Mo + sign * mo
            ma, dsigma = hand[name]
            assert F == pytest.approx(ma, abs=1e-6), name
            assert Mo == pytest.approx(dsigma, abs=1e-6), name
        # perfect joints
        assert numeric(actions["O"], R0.origin, rule, R0)[1][2] == pytest.approx(0, abs=1e-9)
        assert numeric(actions["D"], rocker.frame.origin, rule, R0)[1][0] == pytest.approx(
            0, abs=1e-9)
        assert numeric(actions["B"], actions["B"].point, rule, R0)[1] == pytest.approx(
            np.zeros(3), abs=1e-9)
        # the closing spherical joint's force is its multipliers (components along i, j, k)
        assert numeric(actions["B"], actions["B"].point, rule, R0)[0] == pytest.approx(
            lam, rel=1e-12, abs=1e-12)
        mA = numeric(actions["A"], coupler.frame.origin, rule, R0)[1]
        if finger:
            # the finger transmits a couple only about its axis U.i = R2.j ^ R1.k
            R2 = kinematics(dict(zip(n, q, strict=True)), finger)[0]["coupler"]
            axis = np.cross(R2[:, 1], EZ)
            assert np.cross(mA, axis / np.linalg.norm(axis)) == pytest.approx(np.zeros(3),
                                                                            abs=1e-8)
        else:
            assert mA == pytest.approx(np.zeros(3), abs=1e-8)
            # idle spin: only forces through A and B (and the weight at G on AB) act on the
            # coupler, so d sigma_G / dt has no component along AB
            e = (B2 - centres["coupler"]) / (L_ / 2)
            assert hand["coupler"][1] @ e == pytest.approx(0.0, abs=1e-7)


# -- the same mechanism with the loop closed at the rocker's pivot ------------------------
@_shared
def rssr_closed_at_the_pivot(g=G):
    """The RSSR as the tree ground -pivot- crank -spherical- coupler -spherical- rocker (the
    rocker's orientation yaw alpha, pitch beta, roll gamma about B), the loop closed by the
    rocker's pivot at D about R0.i: three conditions on the points and two on the axes
    (``meets`` is a frame of the rocker whose origin is its point at D and whose k is its
    pivot axis)."""
    q1, psi, th, ph, al, be, ga = rm.coordinates("q1 psi theta phi alpha beta gamma")
    R0 = rm.Frame("R0")
    R1 = R0.rotated("R1", about=R0.k, angle=q1)
    A = R0.origin.moved("A", A_ * R1.i)
    Ca = R0.rotated("Ca", about=R0.k, angle=psi, origin=A)
    Cb = Ca.rotated("Cb", about=Ca.j, angle=th)
    R2 = Cb.rotated("R2", about=Cb.i, angle=ph)
    B = A.moved("B", L_ * R2.i)
    Ra = R0.rotated("Ra", about=R0.k, angle=al, origin=B)
    Rb = Ra.rotated("Rb", about=Ra.j, angle=be)
    R3 = Rb.rotated("R3", about=Rb.i, angle=ga)
    crank = _body("crank", R1, R0.origin, A_ / 2 * R1.i)
    coupler = _body("coupler", R2, A, L_ / 2 * R2.i)
    rocker = _body("rocker", R3, B, -C_ / 2 * R3.j)
    s = System(galilean=R0)
    s.connect(R0, crank, rm.joints.Pivot(at=R0.origin, axis=R0.k))
    s.connect(crank, coupler, rm.joints.Spherical(at=A))
    s.connect(coupler, rocker, rm.joints.Spherical(at=B))
    axes = R3.rotated("R3k", about=R3.j, angle=sp.pi / 2, origin=B.moved("D3", -C_ * R3.j))
    s.connect(R0, rocker, rm.joints.Pivot(at=R0.point("D", *D_), axis=R0.i), meets=axes)
    if g:
        s.act(rm.gravity(-g * R0.k))
    return s


def rocker_matrix(q):
    return rot("z", q["alpha"]) @ rot("y", q["beta"]) @ rot("x", q["gamma"])


def test_loop_closed_at_the_rocker_pivot_has_point_and_axis_conditions():
    s = rssr_closed_at_the_pivot()
    assert [row[0] for row in s.closure_conditions()] == ["4.ru", "4.rv", "4.u", "4.v", "4.w"]
    r = s.mobility()
    assert (r.mobility, r.hyperstaticity) == (2, 0)


def test_loop_closed_at_the_rocker_pivot_assembles_to_the_loop_solution():
    s = rssr_closed_at_the_pivot(g=0.0)
    rate, h = 1.7, 1e-6
    for q1 in (-2.5, 0.4, 1.9):
        hand = loop(q1)
        guess = {"q1": q1, "psi": hand["psi"] + 0.05, "theta": hand["theta"] - 0.05,
                 "phi": 0.2, "alpha": 0.05, "beta": -0.05, "gamma": hand["q3"] + 0.05}
        q0, u0 = s.assemble(guess, independent=["q1", "phi"], rates={"q1": rate})
        assert (q0["psi"], q0["theta"]) == pytest.approx((hand["psi"], hand["theta"]),
                                                         abs=1e-10)
        # the rocker turns about R0.i by q3: alpha = beta = 0, gamma = q3
        assert (q0["alpha"], q0["beta"], q0["gamma"]) == pytest.approx((0.0, 0.0, hand["q3"]),
                                                                       abs=1e-10)
        plus, minus = loop(q1 + h), loop(q1 - h)
        assert u0["gamma"] == pytest.approx(rate * (plus["q3"] - minus["q3"]) / (2 * h),
                                            rel=1e-7)
        assert (u0["alpha"], u0["beta"]) == pytest.approx((0.0, 0.0), abs=1e-10)


def test_both_closures_give_the_same_motion():
    # the same mechanism, loop closed at B (three multipliers) or at the rocker's pivot D
    # (five): the simulated crank and rocker angles agree, and the second one keeps the
    # rocker's axis on R0.i and its point D on D
    s1, s2 = rssr(), rssr_closed_at_the_pivot()
    q0, u0 = assembled(s1, 0.4, 3.0, spin_rate=1.0)
    sim1 = s1.equations_of_motion().simulate(t=(0.0, 2.0), q0=q0, u0=u0, rtol=1e-11,
                                             atol=1e-12, n_output=41)
    q0b = {"q1": q0["q1"], "psi": q0["psi"], "theta": q0["theta"], "phi": q0["phi"],
           "alpha": 0.0, "beta": 0.0, "gamma": q0["q3"]}
    u0b = {"q1": u0["q1"], "psi": u0["psi"], "theta": u0["theta"], "phi": u0["phi"],
           "alpha": 0.0, "beta": 0.0, "gamma": u0["q3"]}
    sim2 = s2.equations_of_motion().simulate(t=(0.0, 2.0), q0=q0b, u0=u0b, rtol=1e-11,
                                             atol=1e-12, n_output=41)
    n2 = names(s2)
    assert sim2.q[n2.index("q1")] == pytest.approx(sim1.q[0], abs=1e-7)
    assert sim2.q[n2.index("phi")] == pytest.approx(sim1.q[4], abs=1e-7)
    for i in range(41):
        q = dict(zip(n2, sim2.q[:, i], strict=True))
        R3 = rocker_matrix(q)
        assert R3 == pytest.approx(rot("x", sim1.q[1, i]), abs=1e-7)
        _, _, B, _ = kinematics(q | {"q3": 0.0})
        assert B - C_ * R3[:, 1] == pytest.approx(D_, abs=1e-8)


def test_both_closures_give_the_same_connection_actions():
    # the actions of the ground on the rocker (pivot D) and of the coupler on the rocker
    # (spherical B) at the same state: a tree joint's action in one model, a closing joint's
    # (its multipliers: forces and the pivot's two couples) in the other
    s1, s2 = rssr(), rssr_closed_at_the_pivot()
    q1, rate = 1.1, 2.5
    q0, u0 = assembled(s1, q1, rate, spin=0.3, spin_rate=1.0)
    n1, n2 = names(s1), names(s2)
    qa = np.array([q0[k] for k in n1])
    ua = np.array([u0[k] for k in n1])
    to2 = {"alpha": "", "beta": "", "gamma": "q3"}
    qb = np.array([q0[to2.get(k, k)] if to2.get(k, k) else 0.0 for k in n2])
    ub = np.array([u0[to2.get(k, k)] if to2.get(k, k) else 0.0 for k in n2])
    eq1, eq2 = s1.equations_of_motion(), s2.equations_of_motion()
    acc1 = eq1.rhs()(0.0, np.concatenate([qa, ua]))[len(n1):]
    acc2 = eq2.rhs()(0.0, np.concatenate([qb, ub]))[len(n2):]
    assert acc2[n2.index("gamma")] == pytest.approx(acc1[n1.index("q3")], rel=1e-9)
    r1 = state_rule(s1, qa, ua, acc1, s1.multipliers(qa, ua))
    r2 = state_rule(s2, qb, ub, acc2, s2.multipliers(qb, ub))
    R0 = s1.galilean
    D1 = s1.bodies[2].frame.origin
    D2 = s2.connection_action(s2.galilean, s2.bodies[2]).point
    for (p1, c1), (p2, c2) in [((s1.galilean, s1.bodies[2]), (s2.galilean, s2.bodies[2])),
                               ((s1.bodies[1], s1.bodies[2]), (s2.bodies[1], s2.bodies[2]))]:
        T1 = numeric(s1.connection_action(p1, c1), D1, r1, R0)
        T2 = numeric(s2.connection_action(p2, c2), D2, r2, s2.galilean)
        assert np.concatenate(T2) == pytest.approx(np.concatenate(T1), abs=1e-8)
    # the pivot transmits no moment about its axis R0.i
    T = numeric(s2.connection_action(s2.galilean, s2.bodies[2]), D2, r2, s2.galilean)
    assert T[1][0] == pytest.approx(0.0, abs=1e-10)


@pytest.mark.parametrize("finger", [False, True])
def test_reduced_equations_on_the_independent_speeds_agree(finger):
    # ch. 25.3: the equations reduced to q1' (and the idle spin phi') give the dependent rates
    # of the loop solution and the accelerations of the augmented system
    s = rssr(finger=finger)
    eqs = s.equations_of_motion()
    n = names(s)
    independent = ["q1"] if finger else ["q1", "phi"]
    reduced = eqs.reduced(independent=independent)
    for q1 in (-2.5, 0.4, 1.9):
        q0, u0 = assembled(s, q1, 1.7, finger, spin=0.3, spin_rate=-0.6)
        q = np.array([q0[k] for k in n])
        u = np.array([u0[k] for k in n])
        acc = eqs.rhs()(0.0, np.concatenate([q, u]))[len(n):]
        out = reduced.rhs()(0.0, np.concatenate([q, [u0[k] for k in independent]]))
        assert out[:len(n)] == pytest.approx(u, rel=1e-10, abs=1e-12)
        assert out[len(n):] == pytest.approx([acc[n.index(k)] for k in independent],
                                             rel=1e-9, abs=1e-12)


def test_idle_spin_of_an_axisymmetric_coupler_is_constant():
    # a coupler symmetric about AB, its centre on AB: the forces at A and B and its weight
    # have no moment about AB, so Euler's equation about its axis of symmetry gives
    # J_a d(omega . e)/dt = 0: the spin omega . e keeps its initial value
    s = rssr(coupler_inertia=np.diag([0.004, 0.11, 0.11]))
    n = names(s)
    q0, u0 = assembled(s, 0.4, 3.0, spin_rate=1.0)
    sim = s.equations_of_motion().simulate(t=(0.0, 3.0), q0=q0, u0=u0, rtol=1e-11,
                                           atol=1e-12, n_output=31)
    spins = []
    for i in range(31):
        q = dict(zip(n, sim.q[:, i], strict=True))
        u = dict(zip(n, sim.u[:, i], strict=True))
        e = kinematics(q)[0]["coupler"][:, 0]
        spins.append(angular_velocity(q, u)["coupler"] @ e)
    assert spins == pytest.approx([spins[0]] * 31, abs=1e-8)
    assert np.ptp(sim.u[n.index("phi")]) > 1.0  # while phi' itself varies
