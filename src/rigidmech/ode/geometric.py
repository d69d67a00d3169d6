r"""Geometric integrators for separable second-order systems :math:`\ddot q = a(t, q)` (ch. 27).

The book writes the equations of motion of a conservative system as
:math:`M(q)\ddot q = f(q, t)` (27.2.1) and integrates them step by step. For long runs (orbits,
27.3) the methods of this module keep the energy error *bounded* instead of letting it grow: they
are symplectic and symmetric (time-reversible), so they exactly conserve a modified energy
close to the true one.

Methods (registered in :func:`rigidmech.ode.solve` with kind ``"second_order"``: ``fun`` is the
acceleration ``a(t, q)`` and ``y0 = [q0, v0]``):

``"verlet"``
    Stormer-Verlet / leapfrog, order 2, one evaluation of ``a`` per step.
``"yoshida4"``
    Forest-Ruth / Yoshida triple jump, order 4, 3 evaluations per step.
``"yoshida6"``
    Yoshida's 7-stage composition (solution A), order 6, 7 evaluations per step.
"""

from __future__ import annotations

import numpy as np

from ._fixed import FixedRecorder, check_fixed, fixed_loop
from ._loop import check_progress
from ._registry import register

__all__ = [
    "verlet",
    "yoshida4",
    "yoshida6",
    "compose",
    "COMPOSITIONS",
]

_CBRT2 = 2.0 ** (1.0 / 3.0)

#: Weights of the symmetric compositions of the Stormer-Verlet step (the basic method has
#: weight 1). Yoshida (1990), Phys. Lett. A 150, 262; Forest and Ruth (1990), Physica D 43, 105;
#: the order-6 values (solution A) to 30 digits from Hairer, Lubich and Wanner, *Geometric
#: Numerical Integration*, section V.3.2, the middle weight from ``sum = 1``.
COMPOSITIONS = {
    "verlet": (1.0,),
    "yoshida4": (
        1.0 / (2.0 - _CBRT2),
        -_CBRT2 / (2.0 - _CBRT2),
        1.0 / (2.0 - _CBRT2),
    ),
}
_W6 = (
    0.784513610477557263819497633866,
    0.235573213359358133684793182978,
    -1.17767998417887100694641568096,
)
COMPOSITIONS["yoshida6"] = (*_W6, 1.0 - 2.0 * sum(_W6), *_W6[::-1])


def compose(acceleration, t_span, y0, *, step, weights, max_steps=None, save_every=1,
            dense_output=False, method="compose", progress=None):
    r"""Symmetric composition of Stormer-Verlet steps with the given `weights`.

    Parameters
    ----------
    acceleration : callable
        ``a(t, q)`` returning an array of the shape of ``q``: ``(d,)`` or ``(d, batch)``.
    t_span : tuple of float
        ``(t0, t1)``; ``t1 < t0`` integrates backwards.
    y0 : array_like, shape (2 d,) or (2 d, batch)
        Initial ``[q0, v0]``; a trailing batch axis integrates many initial states at once.
    step : float
        Requested step, rounded down so that a whole number of steps spans `t_span`.
    weights : sequence of float
        Composition weights :math:`\gamma_i` (summing to 1, symmetric).
    max_steps : int, optional
        Refuse to start if more steps would be needed.
    save_every : int
        Keep the state only every `save_every` steps (and at the end), for long runs.
    dense_output : bool
        Attach a cubic Hermite interpolant ``sol(t)`` through the kept states.
    method : str
        Name recorded in the result.
    progress : callable, optional
        ``progress(t)`` after every step; returning False stops the run (status 2, as
        Ctrl-C does), with everything computed so far kept.

    Returns
    -------
    OdeResult
        ``y`` of shape ``(2 d, m)`` or ``(2 d, m, batch)``; ``nfev`` counts calls of `a`.

    Raises
    ------
    ArgumentError
        On a bad `t_span`, `y0` (odd length, non-finite), `step`, `max_steps` or `save_every`.

    Notes
    -----
    One Stormer-Verlet (velocity form, kick-drift-kick) step of size :math:`h` is

    .. math::

        v_{1/2} = v_n + \tfrac h2\, a(t_n, q_n), \quad
        q_{n+1} = q_n + h\, v_{1/2}, \quad
        v_{n+1} = v_{1/2} + \tfrac h2\, a(t_{n+1}, q_{n+1}),

    and the composition applies it with sizes :math:`\gamma_1 h, \dots, \gamma_s h`. The last
    acceleration of a step is the first of the next (one evaluation per stage). Time advances
    with the drift, so a time-dependent ``a`` keeps the method symmetric.

    Examples
    --------
    >>> import numpy as np
    >>> r = compose(lambda t, q: -q, (0.0, np.pi), [1.0, 0.0], step=0.01,
    ...             weights=COMPOSITIONS["yoshida4"])
    >>> bool(np.allclose(r.y[:, -1], [-1.0, 0.0], atol=1e-8))
    True
    """
    t0, h, nsteps, y, save_every = check_fixed(t_span, y0, step, max_steps, save_every,
                                               even=True)
    d = y.shape[0] // 2
    a = np.array(acceleration(t0, y[:d].copy()), dtype=float)
    rec = FixedRecorder(t0, y, np.concatenate([y[d:], a]), save_every, dense_output)
    advance, nfev = _composed_step(acceleration, [h * w for w in weights], y, a, rec.dense)
    # overflow to inf/nan is reported in the result (status -1), not raised as a warning
    with np.errstate(over="ignore", invalid="ignore"):
        done = fixed_loop(advance, rec, t0, h, nsteps, progress=check_progress(progress))
    return rec.result(method, nfev(), done, stats={"step": abs(h), "stages": len(weights)})


def _composed_step(acceleration, hw, y, a, dense):
    """The step ``advance(t, h) -> (y, f)`` of the composition of Stormer-Verlet steps of
    sizes `hw` from ``y = [q, v]`` with ``a = a(t0, q)``, and its counter of evaluations."""
    d = y.shape[0] // 2
    # merged kicks: v += half[0] a before the first drift, then (w_i + w_{i+1}) h / 2 after
    kick_in = 0.5 * hw[0]
    kicks = [0.5 * (hw[i] + hw[i + 1]) for i in range(len(hw) - 1)] + [0.5 * hw[-1]]
    box = [y[:d].copy(), y[d:].copy(), a]
    nfev = [1]

    def advance(t, h):
        q, v, a = box
        v = v + kick_in * a
        tau = t
        for w_h, k in zip(hw, kicks, strict=True):
            q = q + w_h * v
            tau += w_h
            a = acceleration(tau, q)
            v = v + k * a
        box[:] = q, v, a
        nfev[0] += len(hw)
        return np.concatenate([q, v]), np.concatenate([v, a]) if dense else None

    return advance, lambda: nfev[0]


def verlet(acceleration, t_span, y0, *, step, **options):
    r"""Stormer-Verlet (leapfrog), order 2, symplectic and symmetric (book, 27.1-27.3).

    Parameters are those of :func:`compose` (without `weights`).

    Returns
    -------
    OdeResult

    Notes
    -----
    The kick-drift-kick scheme of :func:`compose` with the single weight 1: one evaluation of
    the acceleration per step, global error :math:`O(h^2)`, energy error bounded by
    :math:`O(h^2)` for all times as long as the motion stays bounded (Hairer, Lubich and Wanner,
    *Geometric Numerical Integration*, IX.8).

    Examples
    --------
    >>> import numpy as np
    >>> r = verlet(lambda t, q: -q, (0.0, 2 * np.pi), [1.0, 0.0], step=1e-3)
    >>> r.nfev, bool(np.allclose(r.y[:, -1], [1.0, 0.0], atol=1e-5))
    (6285, True)
    """
    return compose(acceleration, t_span, y0, step=step, weights=COMPOSITIONS["verlet"],
                   method="verlet", **options)


def yoshida4(acceleration, t_span, y0, *, step, **options):
    r"""Triple-jump composition of Stormer-Verlet, order 4 (Forest-Ruth, Yoshida 1990).

    Parameters are those of :func:`compose` (without `weights`).

    Returns
    -------
    OdeResult

    Notes
    -----
    With :math:`\gamma_1 = \gamma_3 = 1/(2 - 2^{1/3})` and
    :math:`\gamma_2 = -2^{1/3}/(2 - 2^{1/3})`, the conditions
    :math:`\sum\gamma_i = 1` and :math:`\sum\gamma_i^3 = 0` cancel the :math:`h^3` term of the
    symmetric Verlet step's error expansion; symmetry then gives order 4.

    Examples
    --------
    >>> import numpy as np
    >>> r = yoshida4(lambda t, q: -q, (0.0, 2 * np.pi), [1.0, 0.0], step=0.01)
    >>> bool(np.allclose(r.y[:, -1], [1.0, 0.0], atol=1e-8))
    True
    """
    return compose(acceleration, t_span, y0, step=step, weights=COMPOSITIONS["yoshida4"],
                   method="yoshida4", **options)


def yoshida6(acceleration, t_span, y0, *, step, **options):
    r"""Yoshida's 7-stage symmetric composition of Stormer-Verlet, order 6 (solution A).

    Parameters are those of :func:`compose` (without `weights`).

    Returns
    -------
    OdeResult

    Notes
    -----
    The weights :math:`(\gamma_1, \gamma_2, \gamma_3, \gamma_4, \gamma_3, \gamma_2,
    \gamma_1)` satisfy :math:`\sum\gamma_i = 1`, :math:`\sum\gamma_i^3 = 0`,
    :math:`\sum\gamma_i^5 = 0` and the condition on the nested commutators of order 5
    (Yoshida 1990, solution A).

    Examples
    --------
    >>> import numpy as np
    >>> r = yoshida6(lambda t, q: -q, (0.0, 2 * np.pi), [1.0, 0.0], step=0.05)
    >>> bool(np.allclose(r.y[:, -1], [1.0, 0.0], atol=1e-9))
    True
    """
    return compose(acceleration, t_span, y0, step=step, weights=COMPOSITIONS["yoshida6"],
                   method="yoshida6", **options)


register("verlet", verlet, kind="second_order")
register("yoshida4", yoshida4, kind="second_order")
register("yoshida6", yoshida6, kind="second_order")
