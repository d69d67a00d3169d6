"""Progress of a run: a callback and/or a progress bar, updated once per accepted step (book,
ch. 26-27).

Every loop of :mod:`rigidmech.ode` calls ``progress(t)`` after each accepted step (never per
evaluation of the right-hand side) and stops the run with status 2 when it returns False.
:class:`Progress` is such a callable that throttles a user's callback (at most one call every
`every` seconds) and drives a tqdm bar on stderr that appears only once the run has lasted
`delay` seconds.
"""

from __future__ import annotations

import sys
import time

__all__ = ["Progress", "interactive", "progress_option"]


def interactive():
    """Whether stderr is a terminal (a bar is shown by default only then)."""
    try:
        return sys.stderr.isatty()
    except (AttributeError, ValueError):
        return False


class Progress:
    """``progress(t)`` for the loops: a throttled callback and/or a progress bar.

    Parameters
    ----------
    t_span : (float, float)
        The span of the run (the bar's 0 % and 100 %).
    callback : callable or None
        ``callback(t)``, called at most every `every` seconds; returning False stops the run.
    bar : bool
        Show a tqdm bar on stderr once the run has lasted `delay` seconds.
    every, delay : float
        Seconds between two updates; seconds before the bar appears.

    Examples
    --------
    >>> seen = []
    >>> p = Progress((0.0, 1.0), callback=lambda t: seen.append(t) or t < 0.5, every=0.0)
    >>> p(0.25), p(0.75), p.stopped, seen
    (True, False, True, [0.25, 0.75])
    """

    __slots__ = ("callback", "bar_wanted", "span", "every", "delay", "start", "last", "bar",
                 "stopped", "t")

    def __init__(self, t_span, callback=None, bar=False, every=0.1, delay=2.0):
        self.span = (float(t_span[0]), float(t_span[1]))
        self.callback, self.bar_wanted = callback, bool(bar)
        self.every, self.delay = float(every), float(delay)
        self.start = self.last = time.monotonic()
        self.bar = None
        self.stopped = False
        self.t = self.span[0]

    def __call__(self, t):
        self.t = t
        now = time.monotonic()
        if now - self.last < self.every:
            return True
        self.last = now
        if self.callback is not None and self.callback(float(t)) is False:
            self.stopped = True
            return False
        if self.bar_wanted and now - self.start >= self.delay:
            self._show(t)
        return True

    def _show(self, t):
        t0, t1 = self.span
        if self.bar is None:
            from tqdm import tqdm  # imported on use

            self.bar = tqdm(total=abs(t1 - t0), unit="s", desc="rigidmech: integrating",
                            file=sys.stderr, leave=False, dynamic_ncols=True,
                            bar_format="{desc} {percentage:3.0f}%|{bar}| t = {n:.4g} of "
                            "{total:.4g} [{elapsed}<{remaining}]")
        self.bar.n = abs(float(t) - t0)
        self.bar.refresh()

    def close(self):
        """Remove the bar, if shown."""
        if self.bar is not None:
            self.bar.close()
            self.bar = None


def progress_option(progress, t_span):
    """The ``progress`` option of :func:`~rigidmech.ode.solve` as the loops take it.

    None or False: None (no progress); a callable: itself (called after every accepted
    step); True: a :class:`Progress` bar shown once the run has lasted 2 s.

    Examples
    --------
    >>> progress_option(False, (0, 1)) is None, type(progress_option(True, (0, 1))).__name__
    (True, 'Progress')
    """
    if progress is None or progress is False:
        return None
    if progress is True:
        return Progress(t_span, bar=True)
    return progress


def for_run(progress, t_span, *, every, delay):
    """The progress of a run of the mechanics (``simulate``, ``contact_motion``): one rule for
    its ``progress`` argument. A callable ``progress(t)``: called about every `every` seconds
    (returning False stops the run); True: a bar on stderr once the run has lasted `delay`
    seconds; None: the bar only when stderr is a terminal; False: nothing. Returns a
    :class:`Progress` (give it to :func:`~rigidmech.ode.solve` as ``progress``; close it at
    the end) or None.

    Examples
    --------
    >>> for_run(False, (0, 1), every=0.1, delay=2.0) is None
    True
    >>> p = for_run(lambda t: t < 0.5, (0, 1), every=0.0, delay=2.0)
    >>> p(0.25), p(0.75), p.stopped
    (True, False, True)
    """
    from rigidmech._core.errors import ArgumentTypeError

    if progress is not None and not isinstance(progress, bool) and not callable(progress):
        raise ArgumentTypeError(f"`progress` must be None, True, False or a callable "
                                f"progress(t); got {progress!r}.")
    if callable(progress) or progress is True or (progress is None and interactive()):
        return Progress(t_span, callback=progress if callable(progress) else None,
                        bar=not callable(progress), every=every, delay=delay)
    return None
