"""The initial state of a run with constraints (book, ch. 13.2, 25.3): used as given when it is
on the constraints, else assembled on them, the coordinates the user chose kept.

A state (q0, u0) is **on the constraints** when every closure condition |Φ_i(q0, t0)| and every
velocity condition |A_i q0' + a_i| is at most :data:`ON_CONSTRAINTS` (1e-9) of the magnitude
of its terms (:func:`rigidmech._core.rules.on_constraints`, the rule
:func:`~rigidmech.dynamics.assembly.assemble` reaches): it is then used exactly as given.
Otherwise the **dependent** coordinates are moved onto the constraints by
:func:`~rigidmech.dynamics.assembly.assemble` (Newton's method from the values given, so they
move little), the **independent** ones kept, with their rates; the dependent rates follow from
the velocity conditions. The independent coordinates are the caller's ``independent``, else:
the dependent ones are taken, among the coordinates whose columns of the constraint Jacobian A
add to its rank (A at a generic configuration, so that an accidental alignment of the values
given, such as a coupler parallel to the rocker, does not decide), first among those a dict
``q0`` does not name (their 0 is only a guess), then from the last coordinate backwards
(the coordinates of a tree are listed from the ground outwards: the last ones are those of the
bodies that close the loop, the first ones the driving crank). A loop that cannot be closed
is refused (``ConnectionError_``), as ``assemble`` refuses it. What was moved is said in a
note of the simulation, which keeps the values given
(:attr:`Simulation.q0_given <rigidmech.dynamics.Simulation.q0_given>`).

Examples
--------
>>> import sympy as sp, rigidmech as rm
>>> from rigidmech.dynamics import Constraints
>>> x, y = rm.coordinates("x y")
>>> phi = x**2 + y**2 - 1
>>> eqs = rm.EquationsOfMotion(coordinates=(x, y), mass_matrix=sp.eye(2),
...     forcing=sp.Matrix([0, 0]), constraints=Constraints((x, y), [("circle", phi.diff(rm.t),
...     phi)]))
>>> sim = eqs.simulate(t=(0, 1), q0=[0.6, 1.0], n_output=2)    # y moved, x kept
>>> sim.q[:, 0].round(12).tolist(), sim.q0_given.tolist()
([0.6, 0.8], [0.6, 1.0])
"""

from __future__ import annotations

import inspect

import numpy as np

from .._core.errors import ArgumentError, ConnectionError_
from .._core.rules import ON_CONSTRAINTS, numeric_rank, rates_for_scale
from .._core.rules import on_constraints as holds
from ._run import closure_functions, closure_scales
from .assembly import assemble

# ON_CONSTRAINTS and its rule (rigidmech._core.rules.on_constraints) are those of assembly
# (what ``assemble`` reaches and ``multipliers`` requires): one rule, one place
__all__ = ["ON_CONSTRAINTS", "on_constraints"]


def _residuals(eqs, t0, q0, u0, consts, inputs):
    hol, phi_f, A_f, c_f = closure_functions(eqs)
    w = [v(t0) if callable(v) else v for v in inputs]
    phi = (np.zeros(0) if phi_f is None else
           np.asarray(phi_f(t0, q0, *consts, *w), dtype=float).reshape(-1))
    A = np.asarray(A_f(t0, q0, *consts, *w), dtype=float).reshape(len(eqs.constraints), -1)
    vel = np.asarray(c_f(t0, q0, u0, *consts, *w), dtype=float).reshape(-1)
    return phi, A, vel


def _off_constraints(eqs, t0, q0, u0, consts, inputs, phi, A, vel):
    """(largest |Φ| or None, largest |A q' + a| or None): None where every condition holds
    by the rule :func:`~rigidmech._core.rules.on_constraints` (its terms' magnitudes)."""
    phi_s, a_s = closure_scales(eqs)
    w = [v(t0) if callable(v) else v for v in inputs]
    sq = (np.zeros(0) if phi_s is None else
          np.asarray(phi_s(t0, q0, *consts, *w), dtype=float).reshape(-1))
    su = np.asarray(a_s(t0, q0, rates_for_scale(u0), *consts, *w), float).reshape(-1)
    return _off(phi, sq), _off(vel, su)


def _generic_jacobian(eqs, t0, consts, inputs):
    """A at a generic configuration (random coordinates in [0.3, 1.3], a fixed seed as
    :mod:`rigidmech.dynamics.reduced` takes): its structural rank."""
    q = np.random.default_rng(20260).uniform(0.3, 1.3, len(eqs.names))
    return _residuals(eqs, t0, q, np.zeros_like(q), consts, inputs)[1]


def _off(r, scales):
    """The largest residual if one is off by the rule of the module notes, else None."""
    if not r.size or np.all(holds(r, scales)):
        return None
    return float(np.max(np.abs(r)))


def default_independent(names, A, named):
    """The independent coordinates by the rule of the module notes."""
    order = [k for k in reversed(range(len(names))) if names[k] not in named]
    order += [k for k in reversed(range(len(names))) if names[k] in named]
    rank = numeric_rank(A)
    dependent = []
    for k in order:
        if len(dependent) == rank:
            break
        if numeric_rank(A[:, [*dependent, k]]) == len(dependent) + 1:
            dependent.append(k)
    return [nm for k, nm in enumerate(names) if k not in dependent]


def _moves(names, before, after, keep):
    moved = [f"{nm} {b:.6g} -> {a:.6g}" for nm, b, a, in zip(names, before, after, strict=True)
             if nm not in keep and a != b]
    return ", ".join(moved) if moved else "none"


def on_constraints(eqs, t0, q0, u0, *, independent, named, values):
    """(q0, u0, notes): the initial state used for a run of `eqs` (see the module notes).
    ``named``: the names a dict ``q0`` gave (empty for a sequence)."""
    c = eqs.constraints
    if c is None:
        if independent is not None:
            raise ArgumentError(
                f"`independent` chooses the coordinates kept when q0 is assembled on the "
                f"constraints; these equations have no constraints: got independent="
                f"{list(independent)!r}. Remove it.")
        return q0, u0, ()
    consts, inputs, _ = eqs._values(values)
    phi, A, vel = _residuals(eqs, t0, q0, u0, consts, inputs)
    off_q, off_u = _off_constraints(eqs, t0, q0, u0, consts, inputs, phi, A, vel)
    if off_q is None and off_u is None:
        return q0, u0, ()
    names = list(eqs.names)
    if independent is None:
        keep = default_independent(names, _generic_jacobian(eqs, t0, consts, inputs),
                                   set(named))
    else:
        if isinstance(independent, str):
            independent = [independent]
        keep = [x if isinstance(x, str) else getattr(getattr(x, "func", None), "__name__",
                                                    str(x)) for x in independent]
    params = {p.name: v for p, v in zip(eqs.parameters, consts, strict=True)}
    options = {}
    if "t" in inspect.signature(assemble).parameters:  # an assemble that takes the time
        options["t"] = t0
    try:
        q, u = assemble(c, dict(zip(names, q0.tolist(), strict=True)), independent=keep,
                        rates={nm: float(u0[names.index(nm)]) for nm in keep
                               if nm in names}, params=params, **options)
    except ConnectionError_ as exc:
        off = (f"`q0` = {q0.tolist()} is off the closure conditions (largest residual "
               f"{off_q:.3g})" if off_q is not None else
               f"`u0` = {u0.tolist()} is off the velocity conditions (largest residual "
               f"{off_u:.3g})")
        raise ConnectionError_(
            f"{off} and the state cannot be assembled on them: {exc} Kept: "
            f"{', '.join(keep)} (pass `independent=` to keep others).") from None
    q1 = np.array([q[nm] for nm in names])
    u1 = np.array([u[nm] for nm in names])
    notes = []
    if off_q is not None:
        notes.append(
            f"`q0` was off the closure conditions (largest residual {off_q:.3g}, more than "
            f"{ON_CONSTRAINTS:g} of the magnitude of its terms): the dependent coordinates "
            f"were moved onto them by Newton's method from the values given "
            f"({_moves(names, q0, q1, keep)}), kept: "
            f"{', '.join(keep)} (`independent=` chooses them); the dependent rates follow "
            "from the velocity conditions. The values given are in q0_given.")
    if off_q is not None or off_u is not None:
        if not np.array_equal(u0, u1):
            notes.append(
                f"`u0` was off the velocity conditions (largest residual "
                f"{float(np.max(np.abs(vel))):.3g}): the dependent rates were solved from them "
                f"({_moves(names, u0, u1, keep)}), kept: {', '.join(keep)}. The values given "
                "are in u0_given.")
    return q1, u1, tuple(notes)
