"""Embedded Runge-Kutta-Nystrom pairs (rigidmech.ode.rkn, book ch. 26-27)."""

import numpy as np
import pytest
import sympy as sp
from numpy.testing import assert_allclose

from rigidmech import ode
from rigidmech._core.errors import ArgumentError, ArgumentTypeError
from rigidmech.ode import rkn
from rigidmech.testing.problems import kepler, pendulum

PAIRS = [rkn.DPRKN6, rkn.DPRKN12]
#: DPRKN6 is exact in Q(sqrt(8581)); the published DPRKN12 rationals are ~50-digit
#: approximations (rows sums and order conditions measured to hold to 4e-53): a transcription
#: slip would show far above 1e-45, and anything below 1e-30 is invisible in double precision
TOL = {"rkn64": 0, "rkn1210": 1e-45}


def _small(r, pair):
    return r == 0 if TOL[pair.name] == 0 else abs(sp.Float(r, 60)) <= TOL[pair.name]


def _exact(pair):
    """The coefficients as exact sympy numbers (``p + q sqrt(root)`` or rationals)."""
    root = sp.sqrt(pair.root) if pair.root else 0

    def e(x):
        if isinstance(x, tuple):
            return sp.Rational(x[0].numerator, x[0].denominator) + sp.Rational(
                x[1].numerator, x[1].denominator) * root
        return sp.Rational(x.numerator, x.denominator)

    return ([e(x) for x in pair.c], [[e(x) for x in row] for row in pair.abar],
            [e(x) for x in pair.bbar], [e(x) for x in pair.b],
            [e(x) for x in pair.bbar_hat], [e(x) for x in pair.b_hat])


def _conditions(c, A, bbar, b, p):
    """Residuals of RKN order conditions up to order `p` (Hairer, Norsett and Wanner I, II.14).

    Quadrature: sum b_i c_i^k = 1/(k+1) (order k+1), sum bbar_i c_i^k = 1/((k+1)(k+2))
    (order k+2); one-level trees sum b_i c_i^k abar_ij c_j^m = 1/((m+1)(m+2)(k+m+3)) (order
    k+m+3), sum bbar_i c_i^k abar_ij c_j^m = 1/((m+1)(m+2)(k+m+3)(k+m+4)) (order k+m+4): the
    exact values are the integrals of t^k t^(m+2)/((m+1)(m+2)) against the weights 1 and (1-t).
    """
    s = len(c)
    out = []
    for k in range(p):
        out.append((f"b c^{k}", sum(b[i] * c[i] ** k for i in range(s)) - sp.Rational(1, k + 1)))
    for k in range(p - 1):
        out.append((f"bbar c^{k}", sum(bbar[i] * c[i] ** k for i in range(s))
                    - sp.Rational(1, (k + 1) * (k + 2))))
    for k in range(p):
        for m in range(p):
            inner = [sum(A[i][j] * c[j] ** m for j in range(s)) for i in range(s)]
            if k + m + 3 <= p:
                out.append((f"b c^{k} A c^{m}", sum(b[i] * c[i] ** k * inner[i] for i in range(s))
                            - sp.Rational(1, (m + 1) * (m + 2) * (k + m + 3))))
            if k + m + 4 <= p:
                out.append((f"bbar c^{k} A c^{m}",
                            sum(bbar[i] * c[i] ** k * inner[i] for i in range(s))
                            - sp.Rational(1, (m + 1) * (m + 2) * (k + m + 3) * (k + m + 4))))
    return [(name, sp.expand(r)) for name, r in out]


@pytest.mark.parametrize("pair", PAIRS, ids=lambda p: p.name)
def test_row_sums_and_explicitness(pair):
    c, A, *_ = _exact(pair)
    for i, row in enumerate(A):
        assert _small(sp.expand(sum(row) - c[i] ** 2 / 2), pair), i
        assert all(x == 0 for x in row[i:]), i


@pytest.mark.parametrize("pair", PAIRS, ids=lambda p: p.name)
def test_order_conditions_exact(pair):
    c, A, bbar, b, bbar_hat, b_hat = _exact(pair)
    bad = [n for n, r in _conditions(c, A, bbar, b, pair.order) if not _small(r, pair)]
    assert bad == []
    bad = [n for n, r in _conditions(c, A, bbar_hat, b_hat, pair.order_embedded)
           if not _small(r, pair)]
    assert bad == []
    # and the orders are not higher than claimed: the next quadrature conditions fail
    s = len(c)
    p = pair.order
    r = sp.expand(sum(b[i] * c[i] ** p for i in range(s)) - sp.Rational(1, p + 1))
    assert abs(sp.Float(r, 30)) > 1e-12
    q = pair.order_embedded
    r = sp.expand(sum(b_hat[i] * c[i] ** q for i in range(s)) - sp.Rational(1, q + 1))
    assert abs(sp.Float(r, 30)) > 1e-12


@pytest.mark.parametrize("pair", PAIRS, ids=lambda p: p.name)
def test_fsal_last_row_is_the_position_update(pair):
    if pair.fsal:
        assert pair.abar[-1] == pair.bbar
        assert pair.c[-1] in (1, (1, 0)) or pair.floats()["c"][-1] == 1.0


def test_observed_order_six_on_kepler():
    # fixed step (direct call with a step): half an orbit of Kepler e = 0.3, ending at the
    # apocentre; 150-300 steps per orbit are in the asymptotic range (local slopes 6.12, 6.09,
    # then 6.02 at 400, before the rounding floor near 1e-13). After whole orbits the error of
    # this pair cancels to O(h^7) (measured slopes 7.0-7.3), hence the half orbit.
    p = kepler(0.3, orbits=0.5)
    hs, errs = [], []
    for n in (150, 200, 300):
        h = 2 * p.t_span[1] / n
        r = rkn.rkn64(p.acceleration, p.t_span, p.y0, step=h)
        hs.append(h)
        errs.append(p.final_error(r.y[:, -1]))
    slope = np.polyfit(np.log(hs), np.log(errs), 1)[0]
    assert abs(slope - 6) <= 0.05 * 6, (slope, errs)


def test_observed_order_twelve_on_kepler():
    # fixed step, half an orbit of Kepler e = 0.6 with 40-70 steps per orbit: errors 7.6e-11
    # to 1.0e-13, above the rounding floor (about 3e-15 here). The local slopes scatter
    # (11.9, 11.3, 12.4: the steps sample the pericentre passage differently), the fit over
    # the four gives 11.77.
    p = kepler(0.6, orbits=0.5)
    hs, errs = [], []
    for n in (40, 50, 60, 70):
        h = 2 * p.t_span[1] / n
        r = rkn.rkn1210(p.acceleration, p.t_span, p.y0, step=h)
        hs.append(h)
        errs.append(p.final_error(r.y[:, -1]))
    slope = np.polyfit(np.log(hs), np.log(errs), 1)[0]
    assert abs(slope - 12) <= 0.05 * 12, (slope, errs)


@pytest.mark.parametrize(("method", "per_step"), [(rkn.rkn64, 5), (rkn.rkn1210, 17)])
@pytest.mark.parametrize("rtol", [1e-6, 1e-9, 1e-11])
def test_reaches_tolerance_on_kepler(method, per_step, rtol):
    # Kepler e = 0.6 over 10 orbits against the exact solution (Kepler's equation, 27.3.1):
    # the global error stays within 60 rtol (measured for rkn64 20, 0.6 and 1.2 rtol, for
    # rkn1210 2.8, 5.1 and 1.0 rtol: local errors ~rtol per step add up over 10 orbits and the
    # pericentre passages; a per-step tolerance does not bound the global error).
    p = kepler(0.6)
    r = method(p.acceleration, p.t_span, p.y0, rtol=rtol, atol=1e-3 * rtol)
    assert r.status == 0
    assert r.t[-1] == p.t_span[1]
    assert p.final_error(r.y[:, -1]) <= 60 * rtol
    # shape probe, first-step estimate, then per_step calls per attempted step
    assert r.nfev == 1 + 1 + per_step * (r.nsteps + r.nrejected)


def test_matches_solve_ivp_style_first_order_solution_on_pendulum():
    p = pendulum(170.0, periods=2)
    r = rkn.rkn64(p.acceleration, p.t_span, p.y0, rtol=1e-10, atol=1e-13)
    # 2 periods: global error measured 3.4e-12; bound 100 rtol
    assert_allclose(r.y[:, -1], p.exact(p.t_span[1]), atol=1e-8)


def test_backwards_and_time_dependent_force():
    # x'' = -x + cos 2t, x(0) = 1, x'(0) = 0: x = 4/3 cos t - 1/3 cos 2t (book 21.2.3)
    def acc(t, q):
        return -q + np.cos(2 * t)

    def exact(t):
        return np.array([4 / 3 * np.cos(t) - np.cos(2 * t) / 3,
                         -4 / 3 * np.sin(t) + 2 / 3 * np.sin(2 * t)])

    r = rkn.rkn64(acc, (0.0, 5.0), [1.0, 0.0], rtol=1e-10, atol=1e-12)
    assert_allclose(r.y[:, -1], exact(5.0), atol=1e-9)  # measured 1e-14
    back = rkn.rkn64(acc, (5.0, 0.0), exact(5.0), rtol=1e-10, atol=1e-12)
    assert_allclose(back.y[:, -1], [1.0, 0.0], atol=1e-9)


def test_dense_output_quintic_hermite():
    # dense q has local error O(h^6), v O(h^5); on the oscillator at rtol 1e-10 both stay
    # within 1e-8 between the steps (measured 6.7e-12)
    r = rkn.rkn64(lambda t, q: -q, (0.0, 10.0), [1.0, 0.0], rtol=1e-10, atol=1e-12,
                  dense_output=True)
    t = np.linspace(0.0, 10.0, 101)
    assert_allclose(r.sol(t), [np.cos(t), -np.sin(t)], atol=1e-8)
    # a polynomial of degree 5 in t is reproduced exactly by the quintic interpolant
    # q'' = 20 t^3, q = t^5: the step's q, v are exact (order 6 integrates it exactly)
    r = rkn.rkn64(lambda t, q: np.array([20.0 * t**3]), (0.0, 1.0), [0.0, 0.0], step=0.25,
                  dense_output=True)
    tt = np.array([0.1, 0.33, 0.8])
    assert_allclose(r.sol(tt), [tt**5, 5 * tt**4], atol=1e-13)


def test_via_solve_adaptive_dense_and_events():
    """solve() drives the pairs with error control (kind "adaptive_second_order")."""
    r = ode.solve(lambda t, q: -q, (0.0, np.pi), [1.0, 0.0], method="rkn64", rtol=1e-10,
                  atol=1e-12, dense_output=True, events=lambda t, y: y[0])
    assert_allclose(r.t_events[0], [np.pi / 2], atol=1e-8)
    assert_allclose(r.y[:, -1], [-1.0, 0.0], atol=1e-8)
    assert {"rkn64", "rkn1210"} <= set(ode.methods("adaptive_second_order"))
    with pytest.raises(ValueError, match="`step` is only for fixed-step methods"):
        ode.solve(lambda t, q: -q, (0.0, 1.0), [1.0, 0.0], method="rkn1210", step=0.1)


def test_rkn1210_via_solve_reaches_tight_error_on_kepler():
    p = kepler(0.6, orbits=1)
    r = ode.solve(p.acceleration, p.t_span, p.y0, method="rkn1210", rtol=1e-13, atol=1e-16)
    assert p.final_error(r.y[:, -1]) < 1e-10


def test_events_adaptive_direct_call():
    from rigidmech.ode.events import EventTracker

    y0 = np.array([1.0, 0.0])
    tr = EventTracker(lambda t, y: y[0], 0.0, y0)
    r = rkn.rkn64(lambda t, q: -q, (0.0, 4.0), y0, rtol=1e-10, atol=1e-12, events=tr)
    assert_allclose(r.t_events[0], [np.pi / 2], atol=1e-9)


def test_buffer_safety_same_array_returned():
    p = kepler(0.6, orbits=1)
    buf = np.empty(2)

    def acc_buf(t, q):
        r2 = q[0] * q[0] + q[1] * q[1]
        c = -1.0 / (r2 * np.sqrt(r2))
        buf[0] = c * q[0]
        buf[1] = c * q[1]
        return buf

    def acc_fresh(t, q):
        return acc_buf(t, q).copy()

    for method, kw in [(m, kw) for m in (rkn.rkn64, rkn.rkn1210)
                       for kw in ({"rtol": 1e-9, "atol": 1e-12, "dense_output": True},
                                  {"step": 0.05})]:
        a = method(acc_buf, p.t_span, p.y0, **kw)
        b = method(acc_fresh, p.t_span, p.y0, **kw)
        assert np.array_equal(a.y, b.y) and np.array_equal(a.t, b.t)
        if a.sol is not None:
            assert np.array_equal(a.sol(1.0), b.sol(1.0))


def test_large_system_numpy_path_matches_unrolled():
    # d = 10 > FLOAT_PATH_MAX_D runs the whole-array kernel: ten oscillators, exact solution
    w = np.linspace(1.0, 2.0, 10)
    y0 = np.concatenate([np.ones(10), np.zeros(10)])
    for method in (rkn.rkn64, rkn.rkn1210):
        r = method(lambda t, q: -(w**2) * q, (0.0, 3.0), y0, rtol=1e-10, atol=1e-12)
        assert_allclose(r.y[:10, -1], np.cos(3.0 * w), atol=1e-9)
        assert_allclose(r.y[10:, -1], -w * np.sin(3.0 * w), atol=1e-9)


def test_max_steps_status():
    p = kepler(0.6)
    r = rkn.rkn64(p.acceleration, p.t_span, p.y0, rtol=1e-10, max_steps=5)
    assert r.status == -1 and "max_steps" in r.message


def test_zero_length_span_returns_y0_with_or_without_step():
    for kw in ({}, {"step": 0.1}):
        r = rkn.rkn64(lambda t, q: -q, (1.0, 1.0), [1.0, 0.0], **kw)
        assert r.status == 0 and r.t.tolist() == [1.0] and r.y[:, 0].tolist() == [1.0, 0.0]


@pytest.mark.parametrize(("kwargs", "exc", "match"), [
    ({"fun": 3}, ArgumentTypeError, "`fun` must be callable"),
    # the rules and messages of ode.solve (issue 15: one validation for every entry point)
    ({"t_span": (0.0, np.inf)}, ArgumentError, "`t_span` must hold finite times"),
    ({"t_span": (1.0,)}, ArgumentError, "`t_span` must be a pair"),
    ({"t_span": "ab"}, ArgumentTypeError, r"`t_span\[0\]` must be a real number"),
    ({"y0": [1.0, 0.0, 2.0]}, ArgumentError, r"`y0` must be \[q0, v0\] of even length"),
    ({"y0": [np.nan, 0.0]}, ArgumentError, "`y0` must be finite"),
    ({"rtol": -1.0}, ArgumentError, "`rtol` must be a finite number > 0"),
    ({"atol": [1.0, 2.0, 3.0]}, ArgumentError, r"`atol` must be a number or an array of shape"),
    ({"rtol": 0.0, "atol": 0.0}, ArgumentError, "`rtol` must be a finite number > 0; got 0"),
    ({"max_step": 0.0}, ArgumentError, "`max_step` must be > 0"),
    ({"max_steps": 0}, ArgumentError, "`max_steps` must be an int >= 1"),
    ({"step": -0.1}, ArgumentError, "`step` must be a finite number > 0"),
    ({"step": 1e-6, "max_steps": 10}, ArgumentError, "needs .* steps"),
    ({"fun": lambda t, q: np.zeros(3)}, ArgumentError,
     r"`fun\(t0, y0\)` must return an array of the shape of its `y` argument, \(1,\)"),
])
def test_errors(kwargs, exc, match):
    args = {"fun": lambda t, q: -q, "t_span": (0.0, 1.0), "y0": [1.0, 0.0]}
    args.update(kwargs)
    with pytest.raises(exc, match=match):
        rkn.rkn64(args.pop("fun"), args.pop("t_span"), args.pop("y0"), **args)
