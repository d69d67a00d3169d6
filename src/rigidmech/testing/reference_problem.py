"""The type of the reference problems (book, ch. 27): an initial-value problem with a known
exact solution, immutable. The problems themselves are built by the functions of
:mod:`rigidmech.testing.problems`, which re-exports :class:`ReferenceProblem`.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np

from rigidmech._core.errors import ArgumentError

__all__ = ["ReferenceProblem"]


class ReferenceProblem:
    """An initial-value problem with a known exact solution (book, ch. 27).

    Instances are immutable; build them with :func:`pendulum`, :func:`kepler`,
    :func:`damped_oscillator`, :func:`arenstorf` or :func:`free_rigid_body`.

    Parameters
    ----------
    name : str
        Short identifier, e.g. ``"kepler-e0.6"``.
    fun : callable
        First-order right-hand side ``fun(t, y)``, ``y`` of shape ``(n,)`` or ``(n, batch)``.
    t_span : tuple of float
        Integration interval ``(t0, t1)``.
    y0 : array_like, shape (n,)
        Initial state (stored as a read-only copy).
    exact : callable
        ``exact(t)``: state of shape ``(n,)`` for a scalar ``t``, ``(n, k)`` for ``k`` times.
    acceleration : callable or None
        ``a(t, q)`` of the separable second-order form ``q'' = a(t, q)``, ``q`` of shape
        ``(n // 2,)`` or ``(n // 2, batch)``; then ``y = [q, q']``. None if the force depends
        on the velocity.
    energy : callable or None
        A quantity conserved along the exact motion, ``energy(y)`` for ``y`` of shape ``(n,)``
        or ``(n, k)``; None for dissipative problems.
    period : float or None
        Period of the motion, when it is periodic.
    description : str
        One line stating the physics and the book's section.

    Examples
    --------
    >>> from rigidmech.testing.problems import kepler, pendulum
    >>> p = kepler(0.6)
    >>> p
    ReferenceProblem('kepler-e0.6', n=4, t_span=(0.0, 62.83185307179586))
    >>> p.y0.flags.writeable
    False
    >>> p.name = "other"
    Traceback (most recent call last):
    ...
    AttributeError: ReferenceProblem is immutable
    """

    __slots__ = (
        "name",
        "fun",
        "t_span",
        "y0",
        "exact",
        "acceleration",
        "energy",
        "period",
        "description",
    )

    def __init__(
        self,
        name: str,
        fun: Callable,
        t_span: tuple[float, float],
        y0,
        exact: Callable,
        *,
        acceleration: Callable | None = None,
        energy: Callable | None = None,
        period: float | None = None,
        description: str = "",
    ):
        y0 = np.array(y0, dtype=float)
        y0.setflags(write=False)
        values = dict(
            name=name,
            fun=fun,
            t_span=(float(t_span[0]), float(t_span[1])),
            y0=y0,
            exact=exact,
            acceleration=acceleration,
            energy=energy,
            period=None if period is None else float(period),
            description=description,
        )
        for key, value in values.items():
            object.__setattr__(self, key, value)

    def __setattr__(self, key, value):
        raise AttributeError("ReferenceProblem is immutable")

    def __delattr__(self, key):
        raise AttributeError("ReferenceProblem is immutable")

    def __repr__(self) -> str:
        return f"ReferenceProblem({self.name!r}, n={self.y0.size}, t_span={self.t_span})"

    @property
    def q0(self) -> np.ndarray:
        """Initial positions (first half of `y0`), for second-order methods."""
        return self.y0[: self.y0.size // 2]

    def final_error(self, y_final) -> float:
        """Max-norm error of a final state against the exact one at ``t_span[1]``.

        Examples
        --------
        >>> from rigidmech.testing.problems import pendulum
        >>> p = pendulum()
        >>> p.final_error(p.exact(p.t_span[1]))
        0.0
        """
        ref = self.exact(self.t_span[1])
        return float(np.max(np.abs(np.asarray(y_final, dtype=float) - ref)))


def _check_positive(name: str, value: float) -> float:
    value = float(value)
    if not (value > 0.0 and math.isfinite(value)):
        raise ArgumentError(f"`{name}` must be a finite number > 0; got {value!r}.")
    return value
