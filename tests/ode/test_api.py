"""The boundary of rigidmech.ode: argument checks of solve(), the registry, results."""

import numpy as np
import pytest
from _ode_exact import oscillator_exact, oscillator_rhs
from numpy.testing import assert_allclose

from rigidmech import ode
from rigidmech._core.errors import ArgumentError, ArgumentTypeError, RigidmechError
from rigidmech.ode import _registry


def decay(t, y):
    return -y


@pytest.mark.parametrize(
    ("kwargs", "error", "match"),
    [
        # an empty t_span is no longer an error: it returns y0 like scipy (issue 15, defect 10;
        # test_issue15_defects.py); a bad option is still refused on an empty span
        pytest.param(dict(t_span=(0.0, 0.0), rtol=-1.0), ArgumentError, r"`rtol` must be",
                     id="empty-span-bad-rtol"),
        pytest.param(dict(t_span=(0.0, np.inf)), ArgumentError, r"`t_span` must hold finite",
                     id="infinite-span"),
        pytest.param(dict(t_span=(0.0,)), ArgumentError, r"`t_span` must be a pair",
                     id="span-length"),
        pytest.param(dict(t_span=("a", 1.0)), ArgumentTypeError, r"`t_span\[0\]` must be a real",
                     id="span-type"),
        pytest.param(dict(y0=[1.0, np.nan]), ArgumentError, r"`y0` must be finite; got nan at "
                     r"index \(1,\)", id="nan-y0"),
        pytest.param(dict(y0=[]), ArgumentError, r"`y0` must have shape \(n,\) or \(n, batch\)",
                     id="empty-y0"),
        pytest.param(dict(y0=np.ones((2, 2, 2))), ArgumentError, r"got shape \(2, 2, 2\)",
                     id="3d-y0"),
        pytest.param(dict(y0=[1j]), ArgumentTypeError, r"`y0` must be real", id="complex-y0"),
        pytest.param(dict(y0="abc"), ArgumentTypeError, r"`y0` must be an array of real",
                     id="string-y0"),
        pytest.param(dict(method="dopri"), ArgumentError,
                     r"`method` must be one of .*dop853.*; got 'dopri'", id="unknown-method"),
        pytest.param(dict(method=3), ArgumentTypeError, r"`method` must be a string",
                     id="method-type"),
        pytest.param(dict(method="rk4"), ArgumentError,
                     r"`step` is required by the fixed-step method 'rk4'; got None",
                     id="fixed-without-step"),
        pytest.param(dict(method="rk4", step=-0.1), ArgumentError,
                     r"`step` must be a finite number > 0; got -0.1", id="negative-step"),
        pytest.param(dict(method="rk4", step=1e-9, max_steps=10), ArgumentError,
                     r"needs 1000000000 steps over `t_span`, more than `max_steps` = 10",
                     id="too-many-fixed-steps"),
        pytest.param(dict(step=0.1), ArgumentError,
                     r"`step` is only for fixed-step methods; method 'dop853'", id="adaptive-step"),
        pytest.param(dict(rtol=0.0), ArgumentError, r"`rtol` must be a finite number > 0; got 0",
                     id="rtol-zero"),
        pytest.param(dict(rtol=1e-17), ArgumentError, r"`rtol` must be >= 1e-15", id="rtol-tiny"),
        pytest.param(dict(atol=-1.0), ArgumentError, r"`atol` must be a finite number >= 0",
                     id="atol-negative"),
        pytest.param(dict(atol=[1e-9, 1e-9, 1e-9]), ArgumentError,
                     r"`atol` must be a number or an array of shape \(n,\) = \(2,\)",
                     id="atol-shape"),
        pytest.param(dict(y0=[0.0, 1.0], atol=0.0), ArgumentError,
                     r"`atol` must be > 0 for the components of `y0` that are zero",
                     id="atol-zero-at-zero"),
        pytest.param(dict(max_step=0.0), ArgumentError, r"`max_step` must be > 0", id="max-step"),
        pytest.param(dict(first_step=5.0), ArgumentError,
                     r"`first_step` must be in \(0, \|t1 - t0\|\] = \(0, 1.0\]; got 5.0",
                     id="first-step"),
        pytest.param(dict(max_steps=0), ArgumentError, r"`max_steps` must be an int >= 1",
                     id="max-steps"),
        pytest.param(dict(t_eval=[0.5, 0.2]), ArgumentError,
                     r"`t_eval` must be strictly monotonic", id="t-eval-order"),
        pytest.param(dict(t_eval=[0.5, 2.0]), ArgumentError,
                     r"`t_eval` must lie within `t_span` \[0.0, 1.0\]", id="t-eval-range"),
        pytest.param(dict(args=5), ArgumentTypeError, r"`args` must be a tuple", id="args"),
        pytest.param(dict(fun=3), ArgumentTypeError, r"`fun` must be callable", id="fun"),
        pytest.param(dict(events=5), ArgumentTypeError, r"`events` must be a callable",
                     id="events-type"),
        pytest.param(dict(y0=np.ones((2, 3)), events=lambda t, y: y[0]), ArgumentError,
                     r"`events` are not available with a batch", id="events-batch"),
        pytest.param(dict(nstiff=2.5), ArgumentError, r"`nstiff` must be an int >= 0",
                     id="nstiff"),
        pytest.param(dict(jac=None), ArgumentError,
                     r"`jac` is not an option of method 'dop853'; its own options are \['nstiff'",
                     id="foreign-option"),
        pytest.param(dict(method="rk4", step=0.1, nstiff=3), ArgumentError,
                     r"`nstiff` is not an option of method 'rk4'; its own options are none",
                     id="fixed-option"),
        pytest.param(dict(method="gbs", k_max=2), ArgumentError, r"`k_max` must be an int in",
                     id="kmax"),
        pytest.param(dict(method="radau", jac=3), ArgumentTypeError, r"`jac` must be a callable",
                     id="radau-jac"),
    ],
)
def test_misuse_raises_clear_errors(kwargs, error, match):
    args = dict(fun=oscillator_rhs, t_span=(0.0, 1.0), y0=[1.0, 0.0])
    args.update(kwargs)
    with pytest.raises(error, match=match) as info:
        ode.solve(**args)
    assert isinstance(info.value, RigidmechError)


def test_public_names():
    assert {"solve", "OdeResult", "StiffnessWarning", "tableaux", "METHODS"} <= set(ode.__all__)
    assert issubclass(ode.StiffnessWarning, RuntimeWarning)
    assert {"euler", "heun", "midpoint", "rk4", "dopri5", "rk45", "dop853", "gbs",
            "radau"} <= set(ode.METHODS)
    assert ode.methods("stiff") == ["radau"]
    with pytest.raises(ArgumentError, match=r"`kind` must be one of"):
        ode.methods("implicit")


def test_registry_plug_in_and_errors():
    calls = []

    def my_method(fun, t_span, y0, *, step, max_steps):
        calls.append((t_span, step))
        return ode.solve(fun, t_span, y0, method="euler", step=abs(step))

    _registry.register("test-plugin", my_method, kind="fixed")
    try:
        r = ode.solve(decay, (0.0, 1.0), [1.0], method="TEST-plugin", step=0.3)
        # the dispatcher rounds the step so that 4 equal steps land on t1
        assert calls == [((0.0, 1.0), 0.25)]
        assert r.t[-1] == 1.0 and len(r.t) == 5
        with pytest.raises(ArgumentError, match=r"`name` 'test-plugin' is already registered"):
            _registry.register("test-plugin", decay, kind="fixed")
    finally:
        _registry.unregister("test-plugin")
    with pytest.raises(ArgumentError, match=r"`kind` must be one of"):
        _registry.register("x", decay, kind="implicit")
    with pytest.raises(ArgumentTypeError, match=r"`fn` must be callable"):
        _registry.register("x", 3, kind="fixed")
    with pytest.raises(ArgumentTypeError, match=r"`name` must be a non-empty string"):
        _registry.register("", decay, kind="fixed")


def test_tableau_as_method_and_args():
    # a user tableau runs as a fixed-step method; args are passed on to fun
    r1 = ode.solve(lambda t, y, k: -k * y, (0.0, 1.0), [1.0], method=ode.tableaux.RK38,
                   step=0.01, args=(2.0,))
    # 4th order: global error ~ (lambda h)^4 / 120 * lambda t = 2.7e-9 measured here
    assert_allclose(r1.y[0, -1], np.exp(-2.0), rtol=1e-8)
    assert r1.method == "rk38"


def test_result_holds_fresh_arrays_and_counters():
    r = ode.solve(oscillator_rhs, (0.0, 2.0), [1.0, 0.0], method="dopri5", rtol=1e-8)
    assert r.success and r.status == 0 and "end of `t_span`" in r.message
    assert r.y.shape == (2, len(r.t)) and r.t[0] == 0.0 and r.t[-1] == 2.0
    assert r.nsteps == len(r.t) - 1
    # FSAL: 6 evaluations per attempted step, plus 1 initial and 1 for the first step size
    assert r.nfev == 6 * (r.nsteps + r.nrejected) + 2
    assert r.y.flags.writeable and r.y.base is None or r.y.base.flags.owndata


def test_t_eval_and_dense_output_agree_with_exact():
    te = np.linspace(0.0, 10.0, 7)
    for method in ("dopri5", "dop853", "radau"):
        r = ode.solve(oscillator_rhs, (0.0, 10.0), [1.0, 0.0], method=method, rtol=1e-10,
                      atol=1e-12, t_eval=te, dense_output=True)
        assert_allclose(r.t, te)
        # global error of these runs ~1e-9; the interpolants keep it (tolerance 1e-7)
        assert_allclose(r.y, oscillator_exact(te), atol=1e-7)
        ts = np.linspace(0, 10, 101)
        assert_allclose(r.sol(ts), oscillator_exact(ts), atol=1e-7)
        assert r.sol(3.0).shape == (2,)


def test_fixed_step_t_eval_uses_hermite_interpolation():
    te = [0.05, 0.5, 0.95]
    r = ode.solve(oscillator_rhs, (0.0, 1.0), [1.0, 0.0], method="rk4", step=0.01, t_eval=te,
                  dense_output=True)
    # cubic Hermite on h = 0.01: interpolation error ~ h^4/384 |y''''| ~ 3e-11
    assert_allclose(r.y, oscillator_exact(te), atol=1e-10)
    assert r.stats["nfev_interpolation"] == 101
    assert r.sol is not None


def test_backwards_integration():
    for method, kw in (("dop853", {}), ("rk4", {"step": 1e-3}), ("gbs", {}), ("radau", {})):
        r = ode.solve(decay, (1.0, 0.0), [np.exp(-1.0)], method=method, rtol=1e-10,
                      atol=1e-12, **kw)
        assert r.t[-1] == 0.0 and np.all(np.diff(r.t) < 0)
        assert_allclose(r.y[0, -1], 1.0, rtol=1e-8)


@pytest.mark.parametrize("method", ["dop853", "dopri5", "gbs", "radau"])
def test_blow_up_is_reported_in_the_result(method):
    # y' = y^2, y(0) = 1 has y = 1 / (1 - t): it blows up at t = 1
    r = ode.solve(lambda t, y: y * y, (0.0, 2.0), [1.0], method=method)
    assert r.status == -1 and not r.success
    assert "step size underflow" in r.message and "at t = 1.0000" in r.message
    assert "state y = [" in r.message
    assert 0.99 < r.t[-1] < 1.0 + 1e-6


def test_non_finite_state_in_fixed_step_reported():
    r = ode.solve(lambda t, y: y * y, (0.0, 2.0), [1.0], method="rk4", step=0.01)
    assert r.status == -1
    assert r.message.startswith("The state became non-finite at t = ")
    assert np.all(np.isfinite(r.y))


def test_max_steps_reached_is_a_failure():
    r = ode.solve(oscillator_rhs, (0.0, 100.0), [1.0, 0.0], rtol=1e-10, max_steps=5)
    assert r.status == -1 and "`max_steps` = 5 was reached" in r.message
    assert r.nsteps == 5


def test_max_step_and_first_step_are_honoured():
    r = ode.solve(decay, (0.0, 1.0), [1.0], method="dopri5", max_step=0.05, first_step=1e-3)
    assert r.t[1] == pytest.approx(1e-3)
    assert np.max(np.diff(r.t)) <= 0.05 + 1e-15


@pytest.mark.parametrize("method", ["dop853", "rk4", "radau", "verlet"])
def test_wrong_output_shape_of_fun_is_refused(method):
    kw = {"step": 0.1} if method in ("rk4", "verlet") else {}
    with pytest.raises(ArgumentError, match=r"`fun\(t0, y0\)` must return an array of the "
                       r"shape of its `y` argument, \(\d,\); got shape \(3,\)"):
        ode.solve(lambda t, y: np.zeros(3), (0.0, 1.0), [1.0, 0.0], method=method, **kw)
    with pytest.raises(ArgumentTypeError, match=r"must return an array of real numbers"):
        ode.solve(lambda t, y: "abc", (0.0, 1.0), [1.0, 0.0], method=method, **kw)
