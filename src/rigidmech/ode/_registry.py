"""The registry of integration methods behind :func:`rigidmech.ode.solve` (book, ch. 26).

Every method of :mod:`rigidmech.ode` is a plain function registered here under a short name,
together with its *kind*, which tells :func:`~rigidmech.ode.solve` which arguments it takes:

``"fixed"``
    Fixed-step method for ``y' = f(t, y)``; called as ``fn(fun, t_span, y0, step=h,
    max_steps=m)``.
``"second_order"``
    Fixed-step method for ``q'' = a(t, q)`` (Stormer-Verlet, compositions); ``fun`` is the
    acceleration ``a(t, q)`` and ``y0`` is the concatenation ``[q0, v0]``; called like
    ``"fixed"``.
``"adaptive_second_order"``
    Error-controlled method for ``q'' = a(t, q)`` (Runge-Kutta-Nystrom pairs): ``fun`` and
    ``y0`` as for ``"second_order"``, called like ``"adaptive"``.
``"adaptive"``
    Error-controlled explicit method; called as ``fn(fun, t_span, y0, step=None, rtol=...,
    atol=..., first_step=..., max_step=..., max_steps=..., dense_output=..., events=...)``.
``"stiff"``
    Error-controlled implicit method; called like ``"adaptive"``.

Every method returns an :class:`~rigidmech.ode.OdeResult`.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

from rigidmech._core.errors import ArgumentError, ArgumentTypeError

__all__ = ["KINDS", "MethodEntry", "alias", "register", "unregister", "get", "names"]

#: The kinds of method the dispatcher knows how to call.
KINDS = ("fixed", "adaptive", "second_order", "adaptive_second_order", "stiff")


@dataclass(frozen=True)
class MethodEntry:
    """A registered integration method: its name, its function and its kind.

    Examples
    --------
    >>> get("rk4").kind
    'fixed'
    """

    name: str
    function: Callable
    kind: str
    #: Declared capabilities: ``"t_eval"`` (the method takes ``t_eval=`` and keeps only those
    #: samples, memory proportional to them when no dense output is asked for) and
    #: ``"t_eval_at_steps"`` (it takes ``t_eval=`` and lands its steps on those times,
    #: because its interpolant is less accurate than its steps).
    capabilities: frozenset = frozenset()


_METHODS: dict[str, MethodEntry] = {}


#: The capabilities a method may declare (see :class:`MethodEntry`).
CAPABILITIES = ("t_eval", "t_eval_at_steps")


def register(name: str, fn: Callable, *, kind: str, capabilities=()) -> Callable:
    """Register the integration function `fn` under `name`.

    Parameters
    ----------
    name : str
        Short lower-case name used as ``solve(..., method=name)``.
    fn : callable
        ``fn(fun, t_span, y0, *, step, **options) -> OdeResult``.
    kind : {"fixed", "adaptive", "second_order", "adaptive_second_order", "stiff"}
        How :func:`~rigidmech.ode.solve` calls `fn` (see the module docstring).
    capabilities : sequence of str
        Among :data:`CAPABILITIES`.

    Returns
    -------
    callable
        `fn` itself, so that ``register`` can decorate.

    Raises
    ------
    ArgumentError
        If `kind` is unknown or `name` is already registered to another function.
    ArgumentTypeError
        If `name` is not a string or `fn` is not callable.

    Examples
    --------
    >>> def my_euler(fun, t_span, y0, *, step, **options): ...
    >>> _ = register("my-euler-doc", my_euler, kind="fixed")
    >>> get("my-euler-doc").function is my_euler
    True
    >>> unregister("my-euler-doc")
    """
    if not isinstance(name, str) or not name:
        raise ArgumentTypeError(f"`name` must be a non-empty string; got {name!r}.")
    if not callable(fn):
        raise ArgumentTypeError(f"`fn` must be callable; got {type(fn).__name__}.")
    if kind not in KINDS:
        raise ArgumentError(f"`kind` must be one of {KINDS}; got {kind!r}.")
    unknown = set(capabilities) - set(CAPABILITIES)
    if unknown:
        raise ArgumentError(
            f"`capabilities` must be among {CAPABILITIES}; got {sorted(unknown)}."
        )
    key = name.lower()
    old = _METHODS.get(key)
    if old is not None and old.function is not fn:
        raise ArgumentError(
            f"`name` {name!r} is already registered to {old.function.__module__}."
            f"{old.function.__qualname__}; choose another name."
        )
    _METHODS[key] = MethodEntry(key, fn, kind, frozenset(capabilities))
    return fn


def alias(name: str, of: str) -> None:
    """Register `name` as another name of the method `of`: :func:`get` returns the very
    entry of `of` (its name included), so that the alias behaves exactly as its method
    wherever a method is recognised by name.

    Examples
    --------
    >>> get("rk45") is get("dopri5"), get("rk45").name
    (True, 'dopri5')
    """
    if not isinstance(name, str) or not name:
        raise ArgumentTypeError(f"`name` must be a non-empty string; got {name!r}.")
    entry = get(of)
    key = name.lower()
    old = _METHODS.get(key)
    if old is not None and old is not entry:
        raise ArgumentError(f"`name` {name!r} is already registered to {old.name!r}; choose "
                            "another name.")
    _METHODS[key] = entry


def unregister(name: str) -> None:
    """Remove the method `name` from the registry (used by tests and plug-ins).

    Examples
    --------
    >>> unregister("no-such-method")  # silently ignored
    """
    _METHODS.pop(name.lower(), None)


def get(name: str) -> MethodEntry:
    """Return the registered method `name` (case-insensitive).

    Raises
    ------
    ArgumentError
        If no method of that name is registered; the message lists the known names.

    Examples
    --------
    >>> get("DOP853").name
    'dop853'
    >>> get("dopri")
    Traceback (most recent call last):
    ...
    rigidmech._core.errors.ArgumentError: `method` must be one of ...; got 'dopri'.
    """
    if not isinstance(name, str):
        raise ArgumentTypeError(f"`method` must be a string; got {type(name).__name__}.")
    try:
        return _METHODS[name.lower()]
    except KeyError:
        raise ArgumentError(
            f"`method` must be one of {', '.join(sorted(_METHODS))}; got {name!r}."
        ) from None


def names(kind: str | None = None) -> list[str]:
    """Sorted names of the registered methods, optionally only those of one `kind`.

    Examples
    --------
    >>> "rk4" in names("fixed")
    True
    """
    return sorted(k for k, e in _METHODS.items() if kind is None or e.kind == kind)
