"""The regime solve of contact_motion at one state: formed and solved once for the right-hand
side, the contact forces and the scales of the normal forces (an event check after a step asks
for all three), never stale (another regime, another state, results changed by the caller)."""

import numpy as np

from rigidmech import models
from rigidmech.regimes._contact_model import _Model

PARAMS = {"m": 1.0, "r": 0.5, "g": 9.81}


def _ball():
    return _Model(models.sliding_ball(0.3).system, PARAMS)


def _state(model, speed):
    y = np.zeros(2 * model.n)
    y[:model.n] = 0.1
    y[model.n:] = speed
    return y


def test_one_state_forms_its_regime_once(monkeypatch):
    model = _ball()
    calls = []
    saddle = model._saddle
    monkeypatch.setattr(model, "_saddle", lambda *a: calls.append(a[2]) or saddle(*a))
    y, states = _state(model, 0.25), ("stick",)
    a, lam, layout = model.solve(0.0, y, states)
    model.normal_scales(0.0, y, states)
    model.solve(0.0, y, states)
    assert len(calls) == 1
    model.solve(0.0, y, ("slip",))               # another regime at the same state
    model.solve(0.0, _state(model, 0.5), states)  # another state
    assert len(calls) == 3


def test_the_kept_solve_is_never_stale():
    model, fresh = _ball(), _ball()
    y = _state(model, 0.25)
    a, lam, layout = model.solve(0.0, y, ("stick",))
    a[:], lam[:] = np.nan, np.nan                 # the caller changes what it got
    layout.clear()
    for states, yy in ((("stick",), y), (("slip",), y), (("stick",), _state(model, 0.5)),
                       (("stick",), y)):
        got, want = model.solve(0.0, yy, states), fresh.solve(0.0, yy, states)
        np.testing.assert_array_equal(got[0], want[0])
        np.testing.assert_array_equal(got[1], want[1])
        assert got[2] == want[2]
        assert model.normal_scales(0.0, yy, states) == fresh.normal_scales(0.0, yy, states)
