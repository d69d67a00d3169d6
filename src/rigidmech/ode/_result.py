"""The result of a numerical integration (book, ch. 26-27).

Shared by every method of :mod:`rigidmech.ode`: one result type, in the spirit of scipy's
``OdeResult``, so that users and the scenes layer never care which method produced it.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np

__all__ = ["OdeResult"]


@dataclass(frozen=True, eq=False)
class OdeResult:
    """Outcome of :func:`rigidmech.ode.solve`.

    Parameters
    ----------
    t : ndarray, shape (n_points,)
        Times of the returned states (the accepted steps, or ``t_eval`` when given).
    y : ndarray, shape (n, n_points) or (n, n_points, batch)
        States at ``t``; a batch of initial states keeps its trailing batch axis.
    nfev : int
        Number of evaluations of the right-hand side (one call on a batch counts once).
    nsteps : int
        Accepted steps.
    nrejected : int
        Rejected steps (0 for fixed-step methods).
    status : int
        0: reached the end of ``t_span``; 1: a terminal event occurred; 2: stopped early on
        request (Ctrl-C, or a ``progress`` callback returning False), with everything computed
        so far; -1: numerical failure.
    message : str
        Human-readable reason for ``status``; on failure it names the time and the state.
    method : str
        Name of the method used.
    sol : callable or None
        Dense output ``sol(t) -> y`` over the integration interval, when requested.
    t_events : list of ndarray
        For each event function, the times where it fired.
    y_events : list of ndarray
        For each event function, the states where it fired.
    stats : dict
        Method-specific extra counters (``njev``, ``nlu``, order history, ...). After a
        failure on a non-finite or complex value, the methods of the one loop add
        ``stats["culprit"]``: a dict with ``what`` ("derivative" or "state"), ``component``
        (flat index), ``value`` and ``t``.
    t_stop : float or None
        The time the integration reached: the end of ``t_span``, the time of a terminal
        event, or, after a failure or an early stop, the last step accepted (the time the
        message names, except after a non-finite state, named at the step that produced it).
        ``t[-1]`` may be earlier when ``t_eval`` is given.
    y_stop : ndarray or None
        The state at ``t_stop`` (shape of ``y0``).

    Examples
    --------
    >>> import numpy as np
    >>> r = OdeResult(t=np.array([0.0, 1.0]), y=np.array([[1.0, 2.0]]), nfev=4, nsteps=1,
    ...               nrejected=0, status=0, message="ok", method="rk4")
    >>> r.success
    True
    """

    t: np.ndarray
    y: np.ndarray
    nfev: int
    nsteps: int
    nrejected: int
    status: int
    message: str
    method: str
    sol: Any = None
    t_events: list = field(default_factory=list)
    y_events: list = field(default_factory=list)
    stats: dict = field(default_factory=dict)
    t_stop: float | None = None
    y_stop: np.ndarray | None = None

    @property
    def success(self) -> bool:
        """True if the integration reached the end of ``t_span`` or a terminal event (``status``
        0 or 1): not after a numerical failure or an early stop on request."""
        return self.status in (0, 1)
