"""``solve(progress=True)``: a progress bar driven once per accepted step (issue 10), shown
only once the run has lasted its delay; the bar replaces the per-evaluation wrapper that
``simulate`` used to put around the right-hand side."""

import numpy as np

from rigidmech import ode
from rigidmech.ode import _progress


def osc(t, y):
    return np.array([y[1], -y[0]])


def test_progress_true_is_a_bar_shown_after_its_delay(monkeypatch, capsys):
    r = ode.solve(osc, (0.0, 10.0), [1.0, 0.0], method="dop853", rtol=1e-8, progress=True)
    assert r.status == 0 and capsys.readouterr().err == ""  # shorter than 2 s: no bar
    made = []
    real = _progress.Progress

    def now(span, **kw):  # the same bar without its delay
        made.append(real(span, **kw | {"delay": 0.0, "every": 0.0}))
        return made[-1]

    monkeypatch.setattr(_progress, "Progress", now)
    r = ode.solve(osc, (0.0, 10.0), [1.0, 0.0], method="dop853", rtol=1e-8, progress=True)
    assert r.status == 0 and r.t[-1] == 10.0
    assert "rigidmech: integrating" in capsys.readouterr().err
    assert made[0].bar is None and made[0].t == 10.0  # closed at the end, saw the last step


def test_progress_callback_is_called_once_per_accepted_step_not_per_evaluation():
    seen = []
    r = ode.solve(osc, (0.0, 10.0), [1.0, 0.0], method="dop853", rtol=1e-8,
                  progress=seen.append)
    assert len(seen) == r.nsteps < r.nfev / 10  # dop853: 12 evaluations a step
    assert seen == sorted(seen) and seen[-1] == 10.0
