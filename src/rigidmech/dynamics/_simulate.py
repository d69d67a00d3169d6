"""The entry of :meth:`EquationsOfMotion.simulate <rigidmech.dynamics.EquationsOfMotion.simulate>`
(book, ch. 27.2.2): its arguments checked (finite real numbers, a time span, a method name, a
count of outputs, initial values by position or by name), the right-hand side chosen for the
method, the run (:mod:`rigidmech.dynamics._run`) and the warning near a singular set of the
orientation angles.

Examples
--------
>>> import sympy as sp
>>> import rigidmech as rm
>>> x, y = rm.coordinates("x y")
>>> eqs = rm.EquationsOfMotion(coordinates=(x, y), mass_matrix=sp.eye(2),
...                            forcing=sp.Matrix([-x, -y]))
>>> initial(eqs, {"y": 2.0}, "q0", default_zero=False).tolist()
[0.0, 2.0]
"""

from __future__ import annotations

import numpy as np
import sympy as sp

from .. import ode
from .._core.errors import ArgumentError, ArgumentTypeError
from ._compiled import acceleration_only, trouble
from ._compiled import coordinate_name as _name
from ._initial import on_constraints
from ._run import Reduced, canonical_method, merge_values, projector, run
from ._singularities import warn_near_singularities

__all__ = ["check_simulation_inputs", "initial", "simulate", "simulate_reduced"]


def _prologue(eqs, t, q0, u0, method, n_output, params, values, independent):
    """The values, the method's registered name and the initial state (on the constraints)
    of a run of `eqs`, checked: (values, method, q0, u0, given, notes)."""
    values = merge_values(params, values)
    inputs = {_name(w) for w in eqs._inputs}
    check_simulation_inputs(len(eqs._q), t, q0, u0, method, n_output,
                             {k: v for k, v in values.items() if k not in inputs})
    named = ({k if isinstance(k, str) else _name(k) for k in q0} if isinstance(q0, dict)
             else set())
    q0 = initial(eqs, q0, "q0", default_zero=False)
    u0 = initial(eqs, u0, "u0", default_zero=True)
    given = (q0, u0)
    q0, u0, moved = on_constraints(eqs, float(t[0]), q0, u0, independent=independent,
                                   named=named, values=values)
    return values, canonical_method(method), q0, u0, given, moved


def _finish(eqs, sim, values, raise_on_failure):
    if sim.result is not None and sim.t.size:
        warn_near_singularities(eqs.singular_sets, eqs._coordinates, sim.result, values)
    return sim.check() if raise_on_failure else sim


def simulate(eqs, t, q0, u0, *, method, rtol, atol, step, n_output, t_eval, events, max_steps,
             first_step, max_step, dense_output, progress, project, raise_on_failure, params,
             values, independent=None):
    """Integrate ``eqs`` from (q0, u0) over ``t`` (see :meth:`EquationsOfMotion.simulate
    <rigidmech.dynamics.EquationsOfMotion.simulate>`, which documents the arguments)."""
    values, method, q0, u0, given, moved = _prologue(eqs, t, q0, u0, method, n_output, params,
                                                     values, independent)
    y0 = np.concatenate((q0, u0))
    if method in ode.methods("second_order") + ode.methods("adaptive_second_order"):
        fun = acceleration_only(eqs, method, values)
    else:
        fun = eqs.rhs(**values)
    if dense_output is None:
        dense_output = bool(eqs.singular_sets)
    sim = run(eqs, fun, t, y0, method=method, rtol=rtol, atol=atol, step=step,
              n_output=n_output, t_eval=t_eval, events=events, max_steps=max_steps,
              first_step=first_step, max_step=max_step, dense_output=dense_output,
              progress=progress, values=values, notes=(*fun.notes, *moved), project=project,
              given=given)
    return _finish(eqs, sim, values, raise_on_failure)


def simulate_reduced(red, t, q0, u0, *, method, rtol, atol, step, n_output, t_eval, events,
                     max_steps, first_step, max_step, dense_output, progress, project,
                     raise_on_failure, params, values):
    """Integrate the reduced equations ``red`` (state (q, u_I)) from (q0, u0) over ``t``: the
    same checks, initial state (the independent coordinates of ``red`` kept), run and result
    as :func:`simulate`, the samples given as (q, q') (see
    :meth:`ReducedEquations.simulate <rigidmech.dynamics.reduced.ReducedEquations.simulate>`)."""
    eqs = red.equations
    keep = [_name(c) for c in red.independent]
    values, method, q0, u0, given, moved = _prologue(eqs, t, q0, u0, method, n_output, params,
                                                     values, keep)
    if method in ode.methods("second_order") + ode.methods("adaptive_second_order"):
        raise ArgumentError(
            f"`method` {method!r} integrates q'' = a(t, q), but reduced equations are first "
            "order in (q, u) (q' = T u + s, u' = M_r^-1 f_r); use a first-order method such "
            "as 'dop853' or 'rk4'.")
    ind = [eqs.names.index(nm) for nm in keep]
    y0 = np.concatenate((q0, u0[ind]))
    inner = red.rhs(**values)

    def fun(t, y):  # an error of the right-hand side: kept, nan returned (as eqs.rhs)
        try:
            return inner(t, y)
        except (ArithmeticError, ValueError, TypeError) as exc:
            if fun.trouble is None:
                raise
            return trouble(fun, exc, t, np.shape(y))

    fun.notes, fun.trouble = inner.notes, None
    if dense_output is None:
        dense_output = bool(eqs.singular_sets)
    layout = Reduced(keep, red._full_state(values), projector(eqs, values, rates=False))
    sim = run(eqs, fun, t, y0, method=method, rtol=rtol, atol=atol, step=step,
              n_output=n_output, t_eval=t_eval, events=events, max_steps=max_steps,
              first_step=first_step, max_step=max_step, dense_output=dense_output,
              progress=progress, values=values, notes=(*fun.notes, *moved), project=project,
              given=given, reduced=layout)
    return _finish(eqs, sim, values, raise_on_failure)


def initial(eqs, values, what, default_zero):
    """Initial coordinates or rates from a sequence (in the order of :attr:`coordinates`)
    or a mapping by name (missing names: 0)."""
    n = len(eqs._q)
    names = eqs.names
    if values is None:
        if default_zero:
            return np.zeros(n)
        raise ArgumentError(
            f"`{what}` must give {n} initial values (a sequence in the order "
            f"{', '.join(names)}, or a dict by name); got None.")
    if isinstance(values, dict):
        out = np.zeros(n)
        unknown = []
        for key, value in values.items():
            if isinstance(key, str) and key in names:
                k = names.index(key)
            elif key in eqs._coordinates:
                k = eqs._coordinates.index(key)
            else:
                unknown.append(key)
                continue
            out[k] = float(value)
        if unknown:
            raise ArgumentError(
                f"`{what}` names {', '.join(repr(str(x)) for x in unknown)}, which "
                f"{'are' if len(unknown) > 1 else 'is'} not a coordinate; the coordinates "
                f"are {', '.join(names)}.")
        return out
    try:
        out = np.asarray(values, dtype=float)
    except (TypeError, ValueError):
        raise ArgumentError(
            f"`{what}` must be {n} numbers or a dict by name; got {values!r}.") from None
    if out.shape != (n,):
        raise ArgumentError(
            f"`{what}` must give {n} initial values (in the order {', '.join(names)}, or "
            f"a dict by name); got {values!r}.")
    return out


def _finite_reals(values, argument, n=None):
    """Raise unless ``values`` is a sequence (of length ``n``) of finite real numbers."""
    if isinstance(values, str | bytes) or not hasattr(values, "__len__"):
        raise ArgumentTypeError(
            f"`{argument}` must be a sequence of {n or 'several'} numbers; got "
            f"{type(values).__name__} {values!r}.")
    if n is not None and len(values) != n:
        raise ArgumentError(f"`{argument}` must give {n} initial values; got {values!r}.")
    for v in values:
        _finite_real_number(v, f"`{argument}` must hold finite real numbers")


def _finite_real_number(v, rule):
    if isinstance(v, bool) or not isinstance(v, int | float | np.integer | np.floating
                                             | sp.Number):
        raise ArgumentTypeError(f"{rule}; got {type(v).__name__} {v!r}.")
    if not np.isfinite(float(v)):
        raise ArgumentError(f"{rule}; got {v!r}.")


def check_simulation_inputs(n, t, q0, u0, method, n_output, params):
    """The checks of :meth:`EquationsOfMotion.simulate` on the values it is given (numbers
    finite and real, a time span of two numbers, a method name, a count of outputs), so that a
    wrong value is an error here rather than a nan motion or an error from numpy."""
    _finite_reals(t, "t", 2)
    if q0 is not None and not isinstance(q0, dict):
        _finite_reals(q0, "q0")
    if u0 is not None and not isinstance(u0, dict):
        _finite_reals(u0, "u0")
    if not isinstance(method, str):
        raise ArgumentTypeError(
            f"`method` must be the name of a method of rigidmech.ode.solve (such as "
            f"'dop853'); got {type(method).__name__} {method!r}.")
    if isinstance(n_output, bool) or not isinstance(n_output, int | np.integer) \
            or n_output < 2:
        raise ArgumentError(
            f"`n_output` must be an integer >= 2 (the output times include both ends of "
            f"`t`); got {n_output!r}.")
    for name, value in params.items():
        _finite_real_number(value, f"`{name}` must be a finite real number")
