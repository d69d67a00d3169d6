"""Compare the accelerations of one model built by rigidmech and by sympy.physics.mechanics.

Both sides are reduced to numbers the same way: at a random state (q, q') the accelerations
q'' solve M q'' = f. rigidmech's side is the compiled right-hand side
:meth:`~rigidmech.EquationsOfMotion.rhs` (what a simulation runs); sympy's side is
``KanesMethod.mass_matrix`` and ``forcing`` (u = q'), evaluated at the state by substituting
floats (or lambdified, ``evaluate="lambdify"``) and solved by ``numpy.linalg.solve``.
Coordinates are matched by name.

A constrained model (a closing joint, rolling contacts, knife edges) is compared at
consistent states (:func:`closed_state`). The reference there is the tree's ``KanesMethod``
with the constraint force A^T lambda of the velocity conditions A q' = 0 (an augmented linear
system with the acceleration rows A q'' = -A' q'), not ``KanesMethod`` with ``q_dependent``
and ``u_dependent`` (kept as ``to_sympy(..., closure="kane")``, checked on written-out models
by the tests): on a loop found by the fuzzer (a prismatic body carrying a spherical one,
closed to the ground, its slider locked by the loop) Kane's accelerations changed with the
choice of the dependent speeds, and only one choice agreed with rigidmech, whose q'' satisfy
both J q'' = -J' q' and M q'' - f in the range of J^T (the principle with a perfect joint) to
round-off.

Tolerance: :data:`RTOL` relative to the largest ``|q''|`` of the state (at least
:data:`SCALE_FLOOR`). Both sides evaluate
closed forms of the same mechanics in double precision at states away from the singular
sets of the angles (see :func:`~rigidmech.testing.fuzz.description.coordinate_ranges`);
states where sympy's mass matrix has a condition number above :data:`MAX_CONDITION` are
drawn again, so that an agreement to about 1e-12 is expected and 1e-8 leaves a wide margin,
while a modelling error (a whole term) is far above it.

Examples
--------
>>> from rigidmech.testing.fuzz import BodySpec, Model, compare
>>> report = compare(Model(bodies=(BodySpec(name="b0", parent=-1, joint="pivot",
...                                         centre=(0.5, 0.0, 0.0)),),
...                        gravity=(0.0, -9.81, 0.0)), seed=0)
>>> report.status, report.worst < 1e-10
('agree', True)
"""

from __future__ import annotations

import time
from dataclasses import dataclass

import numpy as np
import scipy.linalg
import sympy as sp

from .build_rigidmech import to_rigidmech
from .build_sympy import DegenerateModel, to_sympy
from .description import Model, coordinate_names, coordinate_ranges

__all__ = ["RTOL", "MAX_CONDITION", "Report", "compare", "compare_action",
           "rigidmech_accelerations", "sympy_accelerations", "random_states"]

_T = sp.Symbol("t")

#: relative tolerance on q'' (of the largest ``|q''|`` of the state)
RTOL = 1e-8
#: accelerations below this size are compared in absolute terms (a state where every q'' is
#: zero, such as a body at rest with no action, is not a relative disagreement of round-off)
SCALE_FLOOR = 1e-6
#: states whose mass matrix is worse conditioned are drawn again
MAX_CONDITION = 1e6


@dataclass(frozen=True)
class Report:
    """Outcome of :func:`compare`.

    ``status`` is ``'agree'``, ``'disagree'`` (q'' differ beyond the tolerance),
    ``'coordinates'`` (the two sides do not have the same coordinates), ``'rigidmech-error'``
    or ``'sympy-error'`` (one side raised: ``detail`` holds the message), or ``'degenerate'``
    (no state with a well-conditioned mass matrix was found). ``worst`` is the largest
    relative difference seen; ``seconds`` the time of each side (build, derive, evaluate).
    """

    model: Model
    status: str
    worst: float = 0.0
    detail: str = ""
    seconds: tuple = (0.0, 0.0)

    @property
    def ok(self) -> bool:
        """True unless the two sides disagree (``degenerate`` counts as agreement)."""
        return self.status in ("agree", "degenerate")


def _name(q):
    return q.func.__name__


def rigidmech_accelerations(system):
    """(names, function of (q, u) arrays in that order -> q'') from a rigidmech System."""
    eqs = system.equations_of_motion()
    names = [_name(q) for q in eqs.coordinates]
    n = len(names)
    cache = []

    def qdd(q, u):
        if not cache:  # compiled when first needed: not when the coordinates differ
            cache.append(eqs.rhs())
        return np.asarray(cache[0](0.0, np.concatenate([q, u])), dtype=float)[n:]

    return names, qdd


def _evaluator(exprs, symbols, evaluate):
    """A function of the symbols' values -> list of float arrays, one per matrix of
    ``exprs``: the values substituted as floats (``"substitute"``: no code is printed or
    compiled, the cheapest for the few states a comparison needs) or the expressions
    lambdified with common subexpressions (``"lambdify"``: the cheapest per call)."""
    if evaluate == "lambdify":
        # common subexpressions: Kane's forcing repeats the partial velocities (cse prints it
        # about 3 times faster than the plain expression)
        f = sp.lambdify([symbols], exprs, "numpy", cse=True)
        return lambda values: [np.array(x, dtype=float) for x in f(values)]
    if evaluate != "substitute":
        raise ValueError(f"`evaluate` must be 'substitute' or 'lambdify'; got {evaluate!r}.")

    def f(values):
        rule = {x: sp.Float(float(v)) for x, v in zip(symbols, values, strict=True)}
        return [np.array(sp.Matrix(e).xreplace(rule).evalf(), dtype=float) for e in exprs]

    return f


def sympy_accelerations(kane, evaluate="substitute"):
    """(names, function of (q, u) -> (q'', condition number of M)) from a KanesMethod.

    If the KanesMethod carries the numeric conditions of a closing joint or of other
    velocity conditions formed without them (``kane.closure`` with ``to_sympy(...,
    closure="multipliers")``), q'' solve the equations of the tree with the constraint
    force, M q'' = f + A^T lambda and A q'' = -A' q' (the fundamental principle with perfect
    connections, ch. 18, 25.3). ``evaluate``: see :func:`_evaluator`.
    """
    names = [_name(q) for q in kane.q]
    qs = [sp.Symbol(f"_q{k}") for k in range(len(names))]
    us = [sp.Symbol(f"_u{k}") for k in range(len(names))]
    # the speed u_<name> is the rate of the coordinate <name> (Kane's u may be in another
    # order than its q: independent speeds first)
    rows = [names.index(_name(x)[2:]) for x in kane.u]
    rule = {**{x: us[k] for x, k in zip(kane.u, rows, strict=True)},
            **dict(zip(kane.q, qs, strict=True))}
    values = _evaluator([kane.mass_matrix.xreplace(rule), kane.forcing.xreplace(rule)],
                        qs + us, evaluate)

    closure = getattr(kane, "closure", None)
    tree = closure is not None and getattr(kane, "closure_method", None) == "multipliers"

    def qdd(q, u):
        M, f = values(np.concatenate([q, u]))
        f = f.reshape(-1)
        if tree:
            J = closure["jacobian"](q)
            m = J.shape[0]
            K = np.block([[M, J.T], [J, np.zeros((m, m))]])
            rhs = np.concatenate([f, -closure["bias"](q, u)])
            return np.linalg.solve(K, rhs)[:len(f)], np.linalg.cond(K)
        out = np.empty(len(f))
        out[rows] = np.linalg.solve(M, f)
        return out, np.linalg.cond(M)

    return names, qdd


def random_states(model: Model, rng, count):
    """``count`` pairs of arrays (q, u) in the order of ``coordinate_names(model)``."""
    ranges = coordinate_ranges(model)
    names = coordinate_names(model)
    out = []
    for _ in range(count):
        q = np.array([rng.uniform(*ranges[n]) for n in names])
        out.append((q, rng.uniform(-2.0, 2.0, len(names))))
    return out


def closed_state(closure, rng, spread=0.15):
    """A state (q, u) in the order of Kane's coordinates (independent first) that satisfies
    the conditions and their derivative: with holonomic conditions, the independent
    coordinates moved from the assembly by at most ``spread`` and the dependent ones found by
    Newton's method (to 1e-13); without, coordinates drawn in their ranges; then speeds
    drawn at random in the null space of the velocity conditions A(q) q' = 0 (an orthonormal
    basis from the SVD). (None, None) if Newton's method does not converge or if the
    conditions leave no motion (a locked mechanism: q'' = 0 on both sides up to round-off,
    nothing to compare; :func:`compare` calls it ``'degenerate'``).

    Examples
    --------
    >>> from rigidmech.testing.fuzz import BodySpec, ClosureSpec, Model, to_sympy
    >>> model = Model(bodies=(BodySpec(name="b0", parent=-1, joint="annular"),),
    ...               closure=ClosureSpec(0, (0.5, 0.0, 0.0), ((0.25, 0.5, 1.0, 0.5),)))
    >>> closure = to_sympy(model).closure
    >>> q, u = closed_state(closure, np.random.default_rng(0))
    >>> bool(np.max(np.abs(closure["phi"](q))) < 1e-12)
    True
    >>> bool(np.max(np.abs(closure["jacobian"](q) @ u)) < 1e-12)
    True
    """
    order = closure["order"]
    if closure["assembly"] is None:
        lo, hi = closure["ranges"].T
        x = rng.uniform(lo, hi)
    else:
        dep = closure["dependent"]
        ind = [k for k in range(len(closure["assembly"])) if k not in dep]
        x = closure["assembly"].copy()
        x[ind] += rng.uniform(-spread, spread, len(ind))
        for _ in range(30):
            r = closure["phi"](x)
            if np.max(np.abs(r)) < 1e-13:
                break
            x[dep] -= np.linalg.solve(closure["phi_jacobian"](x)[:, dep], r)
        else:
            return None, None
    basis = scipy.linalg.null_space(closure["jacobian"](x))
    if basis.shape[1] == 0:  # a locked mechanism: no motion to compare
        return None, None
    v = basis @ rng.uniform(-1.0, 1.0, basis.shape[1])
    return x[order], v[order]


def _degenerate(builder, model) -> bool:
    try:
        builder(model)
    except DegenerateModel:
        return True
    except Exception:  # noqa: BLE001 -- not the question asked here
        return False
    return False


def compare(model: Model, seed=0, *, states=4, rtol=RTOL, coordinates=None,
            builders=(to_rigidmech, to_sympy), evaluate="substitute") -> Report:
    """Build ``model`` on both sides and compare q'' at ``states`` random states.

    Parameters
    ----------
    model : Model
    seed : int
        Seed of the random states.
    states : int
        Number of states compared.
    rtol : float
        Tolerance relative to the largest ``|q''|`` of each state.
    coordinates : sequence of str, optional
        Order of the coordinates given to rigidmech's System.
    builders : (callable, callable)
        The two builders (model -> System, model -> KanesMethod); the tests plant errors
        through them to check that a disagreement is seen.
    evaluate : {"substitute", "lambdify"}
        How Kane's M and f are evaluated: floats substituted (default: cheaper for a few
        states) or lambdified (cheaper for many).
    """
    t0 = time.perf_counter()
    try:
        system = (builders[0](model, coordinates=coordinates) if coordinates is not None
                  else builders[0](model))
        names_rm, ours = rigidmech_accelerations(system)
    except Exception as exc:  # noqa: BLE001 -- any failure of one side is a finding
        status = "rigidmech-error"
        if model.closure is not None and _degenerate(builders[1], model):
            status = "degenerate"  # a locked or redundant loop, refused by both sides
        return Report(model, status, detail=f"{type(exc).__name__}: {exc}",
                      seconds=(time.perf_counter() - t0, 0.0))
    t1 = time.perf_counter()
    try:
        kane = builders[1](model)
        names_sp, theirs = sympy_accelerations(kane, evaluate)
    except DegenerateModel as exc:
        return Report(model, "degenerate", detail=str(exc),
                      seconds=(t1 - t0, time.perf_counter() - t1))
    except Exception as exc:  # noqa: BLE001
        return Report(model, "sympy-error", detail=f"{type(exc).__name__}: {exc}",
                      seconds=(t1 - t0, time.perf_counter() - t1))
    t2 = time.perf_counter()
    if sorted(names_rm) != sorted(names_sp):
        return Report(model, "coordinates", detail=f"rigidmech {names_rm}, sympy {names_sp}",
                      seconds=(t1 - t0, t2 - t1))
    order = [names_sp.index(n) for n in names_rm]
    rng = np.random.default_rng(seed)
    worst, compared, tried, detail = 0.0, 0, 0, ""
    t_rm = t_sp = 0.0
    closure = getattr(kane, "closure", None)
    while compared < states and tried < 20 * states:
        tried += 1
        if closure is None:
            q, u = random_states(model, rng, 1)[0]
        else:
            q, u = closed_state(closure, rng)
            if q is None:
                continue
        s0 = time.perf_counter()
        b, cond = theirs(q, u)
        s1 = time.perf_counter()
        if not cond < MAX_CONDITION:
            continue
        a = ours(q[order], u[order])
        t_rm += time.perf_counter() - s1
        t_sp += s1 - s0
        b = b[order]
        scale = max(float(np.max(np.abs(b))), float(np.max(np.abs(a))), SCALE_FLOOR)
        err = float(np.max(np.abs(a - b))) / scale if np.all(np.isfinite(a)) else np.inf
        compared += 1
        if not err <= worst:
            worst = err
            detail = (f"at q={dict(zip(names_rm, q[order].round(6).tolist(), strict=True))}, "
                      f"q'={dict(zip(names_rm, u[order].round(6).tolist(), strict=True))}: "
                      f"rigidmech q''={a.tolist()}, sympy q''={b.tolist()}")
    seconds = (t1 - t0 + t_rm, t2 - t1 + t_sp)
    if compared == 0:
        return Report(model, "degenerate", detail="no well-conditioned state", seconds=seconds)
    status = "agree" if worst <= rtol else "disagree"
    return Report(model, status, worst, detail if status != "agree" else "", seconds)


def _lambdified(exprs, q, u, a):
    """A numeric function of (q, u, a) arrays for expressions in q(t), q', q''."""
    n = len(q)
    qs, us, as_ = (sp.symbols(f"_{c}0:{n}") for c in "qua")
    rule = {}
    for k in range(n):
        rule[q[k].diff(_T, 2)] = as_[k]
        rule[q[k].diff(_T)] = us[k]
        if u is not None:
            rule[u[k].diff(_T)] = as_[k]
            rule[u[k]] = us[k]
    rule.update({q[k]: qs[k] for k in range(n)})
    f = sp.lambdify([qs, us, as_], [sp.sympify(e).xreplace(rule) for e in exprs], "numpy",
                    cse=True)
    return lambda qv, uv, av: np.array(f(qv, uv, av), dtype=float).reshape(-1)


def compare_action(model: Model, body: int, seed=0, *, states=2, rtol=RTOL) -> Report:
    """Compare the action of the parent of ``body`` on it, components (X, Y, Z, L, M, N) in
    its joint's local basis at the joint's point: rigidmech's
    :meth:`~rigidmech.System.connection_components` against sympy's auxiliary equations of
    Kane (``u_auxiliary``, see :func:`~rigidmech.testing.fuzz.to_sympy`), each side with
    its own q''. Same statuses and tolerance as :func:`compare` (relative to the largest
    component of the state).

    Examples
    --------
    >>> from rigidmech.testing.fuzz import BodySpec, Model
    >>> model = Model(bodies=(BodySpec(name="b0", parent=-1, joint="pivot",
    ...                                centre=(0.5, 0.0, 0.0)),), gravity=(0.0, -9.75, 0.0))
    >>> compare_action(model, 0).status
    'agree'
    """
    t0 = time.perf_counter()
    try:
        system = to_rigidmech(model)
        names, qdd_rm = rigidmech_accelerations(system)
        parent = model.bodies[body].parent
        solids = system.bodies
        comps = system.connection_components(system.galilean if parent < 0 else solids[parent],
                                             solids[body])
        keys = ("X", "Y", "Z", "L", "M", "N")
        eqs = system.equations_of_motion()
        ours = _lambdified([comps[k] for k in keys], list(eqs.coordinates), None, None)
    except Exception as exc:  # noqa: BLE001 -- any failure of one side is a finding
        return Report(model, "rigidmech-error", detail=f"{type(exc).__name__}: {exc}")
    t1 = time.perf_counter()
    try:
        kane = to_sympy(model, action_of=body)
        unknowns = kane.action_symbols
        zero = dict.fromkeys(unknowns, 0)
        _, qdd_sp = sympy_accelerations(_Main(kane, zero))
        aux = sp.Matrix(kane.auxiliary_eqs)
        A = _lambdified(list(aux.jacobian(unknowns)), list(kane.q), list(kane.u), None)
        b = _lambdified(list(aux.xreplace(zero)), list(kane.q), list(kane.u), None)
    except Exception as exc:  # noqa: BLE001
        return Report(model, "sympy-error", detail=f"{type(exc).__name__}: {exc}")
    t2 = time.perf_counter()
    names_sp = [_name(q) for q in kane.q]
    order = [names_sp.index(n) for n in names]
    rng = np.random.default_rng(seed)
    worst, detail = 0.0, ""
    m = len(unknowns)
    for q, u in random_states(model, rng, states):
        acc_sp, _ = qdd_sp(q, u)
        r_sp = np.linalg.solve(A(q, u, acc_sp).reshape(m, m), -b(q, u, acc_sp))
        qr, ur = q[order], u[order]
        r_rm = ours(qr, ur, qdd_rm(qr, ur))
        scale = max(float(np.max(np.abs(r_sp))), float(np.max(np.abs(r_rm))), SCALE_FLOOR)
        err = float(np.max(np.abs(r_rm - r_sp))) / scale
        if not err <= worst:
            worst = err
            detail = f"rigidmech {r_rm.tolist()}, sympy {r_sp.tolist()}"
    status = "agree" if worst <= rtol else "disagree"
    return Report(model, status, worst, detail if status != "agree" else "",
                  (t1 - t0, t2 - t1))


class _Main:
    """Kane's main equations with the unknown action set to zero (duck-typed KanesMethod
    for :func:`sympy_accelerations`)."""

    def __init__(self, kane, zero):
        self.q, self.u = kane.q, kane.u
        self.mass_matrix = kane.mass_matrix.xreplace(zero)
        self.forcing = kane.forcing.xreplace(zero)
