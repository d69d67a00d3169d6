"""What a free-body diagram reads from a System, a Mechanism or a Statics: the isolated set,
the connections that join it to the rest, the given actions on it (book, ch. 14.2.3), as
symbolic items evaluated later at a state (:func:`state_numbers`) or along a motion
(:func:`motion_numbers`).

Examples
--------
>>> import rigidmech as rm
>>> from rigidmech.actions import ContactLaws
>>> R0 = rm.Frame("R0"); box = rm.Body("box", frame=R0)
>>> st = rm.statics.Statics(R0)
>>> st.connect(R0, box, ContactLaws(at=R0.origin, normal=R0.j), label="A")
>>> [link.label for link in Source(st, box).links]
['A']
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import sympy as sp

from .._core.errors import ArgumentError, ArgumentTypeError, ConnectionError_
from .._core.validation import finite_real, substitutions
from ..actions import (
    ContactLaws,
    Couple,
    Force,
    FrictionContact,
    Gravity,
    RollingContact,
    Spring,
)
from ..actions.dampers import Damper
from ..dynamics import System
from ..kinematics import Solid
from ..statics import Statics
from ..systems import Mechanism
from ..vectors import Frame, Vector
from ..vectors import t as _t

__all__ = ["Source", "Item", "plan", "state_numbers", "motion_numbers"]


@dataclass(frozen=True)
class _Link:
    first: object
    second: object
    connection: object
    label: str
    torsor: object
    unknowns: tuple


@dataclass(frozen=True)
class Item:
    """One action on the isolated set, symbolic: point, resultant and moment (3 components
    each in the reference's basis, or None), components ``(name, kind, direction, value)``
    and cone ``(normal, f_s)``; ``link`` and ``sign`` when its values come from dynamics."""

    kind: str
    label: str
    point: list
    force: list | None
    moment: list | None
    components: tuple = ()
    cone: tuple | None = None
    link: object = None
    sign: int = 1


class Source:
    """The isolated set ``bodies`` of ``system`` (a System, Mechanism or Statics): its
    reference, its external links and the given actions' contributions on it."""

    def __init__(self, system, bodies):
        inner = getattr(system, "system", None)      # a Model of rigidmech.models
        system = inner if isinstance(inner, System) else system
        if isinstance(system, System):
            graph, self.dynamics = system.mechanism, system
        elif isinstance(system, Mechanism):
            graph, self.dynamics = system, None
        elif isinstance(system, Statics):
            graph, self.dynamics = None, None
        else:
            raise ArgumentTypeError(
                "`system` must be a System (or a Model), a Mechanism or a Statics; got "
                f"{type(system).__name__}.")
        self.ground = None if graph is None else graph.ground
        if graph is not None:
            self.reference = graph.reference
            self.all_bodies = tuple(graph.bodies)
            links = [_Link(k.first, k.second, k.connection, k.label,
                           *k.connection.action_torsor(k.label)) for k in graph.links]
            links += _contact_links(self.dynamics)
            solids = list(graph.solids)
            loads = [(None, a) for a in graph.actions]
        else:
            # a Statics: its connections and loads as given (its public views)
            self.reference = system.reference
            self.all_bodies = tuple(system.bodies)
            links = [_Link(*c) for c in system.connections]
            solids = list(system.bodies)
            loads = list(system.loads)
        self.bodies = _isolated(bodies, self.all_bodies)
        self.links = [k for k in links if self.inside(k.first) != self.inside(k.second)]
        self.loads = self._external_loads(loads, solids)

    def end(self, solid):
        """``solid`` as the dynamics' methods take it (the reference frame for the ground)."""
        return self.reference if solid is self.ground else solid

    def inside(self, solid) -> bool:
        return any(solid is b for b in self.bodies)

    def _external_loads(self, loads, solids):
        out, counts = [], {}
        for body, action in loads:
            if body is not None:
                if self.inside(body):
                    out.append(("force", "load", action))
                continue
            contributions = action.contributions(solids)
            if _internal(action, contributions, self):
                continue
            for solid, torsor in contributions:
                if not self.inside(solid):
                    continue
                kind, name = _kind(action, solid, len(self.bodies) > 1)
                counts[name] = counts.get(name, 0) + 1
                out.append((kind, name, torsor))
        numbered = {n for n, c in counts.items() if c > 1}
        seen = {}
        labelled = []
        for kind, name, torsor in out:
            if name in numbered:
                seen[name] = seen.get(name, 0) + 1
                name = f"{name}{seen[name]}"
            labelled.append((kind, name, torsor))
        return labelled


def _contact_links(system):
    """The one-sided contacts with friction of a dynamics System (not in its graph), labelled
    as :mod:`rigidmech.regimes` names them: the contact point's name, with the contact's rank
    appended when that name is taken."""
    out, names = [], []
    for k, (parent, child, contact) in enumerate(system.contacts if system else ()):
        name = contact.contact.point.name
        name = name if name not in names else f"{name}{k + 1}"
        names.append(name)
        out.append(_Link(parent, child, contact, name, *contact.action_torsor(name)))
    return out


def _isolated(bodies, all_bodies):
    group = [bodies] if isinstance(bodies, Solid) else bodies
    try:
        group = list(group)
    except TypeError:
        raise ArgumentTypeError(
            f"`bodies` must be a Body or a sequence of Bodies; got {type(bodies).__name__}."
        ) from None
    if not group:
        raise ArgumentError("`bodies` must name at least one body to isolate; got none.")
    out = []
    for b in group:
        if isinstance(b, Frame) or not any(b is x for x in all_bodies):
            names = [x.name for x in all_bodies]
            raise ArgumentError(
                f"`bodies` must be bodies of the system {names}; got {b!r}. The ground "
                "cannot be isolated; pass the system's Body objects.")
        if not any(b is x for x in out):
            out.append(b)
    return tuple(out)


def _kind(action, solid, several):
    if isinstance(action, Gravity):
        return "weight", f"W_{solid.name}" if several else "W"
    if isinstance(action, Spring | Damper):
        return "spring", type(action).__name__.lower()
    if isinstance(action, Couple):
        return "couple", "C"
    if isinstance(action, Force):
        return "force", "F"
    return "force", type(action).__name__


def _internal(action, contributions, source):
    """A mutual action between bodies of the set (a spring, a motor couple): every
    contribution on the set, at least two, summing to the zero torsor."""
    if len(contributions) < 2 or not all(source.inside(s) for s, _ in contributions):
        return False
    O = source.reference.origin
    total = sum((T.at(O) for _, T in contributions[1:]), contributions[0][1].at(O))
    comps = (list(total.resultant.components(source.reference))
             + list(total.moment.components(source.reference)))
    return all(sp.simplify(c) == 0 for c in comps)


def _vec(v, R0):
    return list(v.components(R0)) if isinstance(v, Vector) else [sp.S.Zero] * 3


def _nonzero(exprs):
    return any(sp.simplify(e) != 0 for e in exprs)


def _connection_kind(connection):
    if isinstance(connection, ContactLaws | FrictionContact):
        return "contact"
    if isinstance(connection, RollingContact):
        return "rolling"
    return "connection"


def _cone_of(connection, sign, R0):
    law = getattr(connection, "friction", None)
    if law is None:
        return None
    normal = getattr(connection, "normal", None)
    if normal is None:
        normal = connection.contact.normal
    f = float(law.static)
    return ([sign * c for c in _vec(normal, R0)], f)


def _values_of(equilibrium, values, unknowns):
    known = {}
    if equilibrium is not None:
        if not callable(getattr(equilibrium, "solution", None)):
            raise ArgumentTypeError(
                "`equilibrium` must be an Equilibrium (Statics.solve()); got "
                f"{type(equilibrium).__name__}.")
        known.update(equilibrium.values)
    by_name = {u.name: u for u in unknowns}
    for key, v in _mapping(values, "values").items():
        name = key if isinstance(key, str) else getattr(key, "name", None)
        if name not in by_name:
            raise ArgumentError(
                f"`values`: {key!r} is no unknown of the connections of the isolated set; "
                f"expected some of {sorted(by_name)}.")
        known[by_name[name]] = sp.Float(_number(v, f"values[{name!r}]"))
    return known


def plan(source, *, equilibrium=None, values=None, dynamic=False):
    """The symbolic items of the diagram."""
    R0, O = source.reference, source.reference.origin
    items = []
    unknowns = [u for k in source.links for u in k.unknowns]
    known = _values_of(equilibrium, values, unknowns)
    for link in source.links:
        sign = 1 if source.inside(link.second) else -1
        T = link.torsor
        P = T.point
        R, M = _vec(T.resultant, R0), _vec(T.moment, R0)
        comps = []
        for u in link.unknowns:
            dR = [sp.diff(c, u) for c in R]
            dM = [sp.diff(c, u) for c in M]
            kind, d = ("force", dR) if _nonzero(dR) else ("moment", dM)
            comps.append((u.name, kind, [sign * c for c in d], known.get(u)))
        solved = all(u in known for u in link.unknowns)
        rule = {u: known[u] for u in link.unknowns if u in known}
        force = [sign * c.xreplace(rule) for c in R] if solved else None
        moment = [sign * c.xreplace(rule) for c in M] if solved else None
        dynamics_link = None
        if dynamic and not solved and source.dynamics is not None:
            try:
                A = source.dynamics.connection_action(
                    source.end(link.first), source.end(link.second), label=link.label)
            except ConnectionError_:   # one-sided contacts: the actions depend on the regime
                A = None
            if A is not None:
                force = [sign * c for c in _vec(A.resultant, R0)]
                moment = [sign * c for c in _vec(A.moment_at(P), R0)]
                dynamics_link = link
        cone = _cone_of(link.connection, sign, R0)
        items.append(Item(_connection_kind(link.connection), link.label,
                          _vec(P - O, R0), force, moment, tuple(comps), cone,
                          dynamics_link, sign))
    for kind, name, T in source.loads:
        P = T.point
        R, M = _vec(T.resultant, R0), _vec(T.moment, R0)
        if kind == "couple" or not _nonzero(R):
            items.append(Item("couple", name, _vec(P - O, R0), None, M))
        else:
            items.append(Item(kind, name, _vec(P - O, R0), R,
                              M if _nonzero(M) else None))
    return items


def _number(x, argument):
    """A finite real float for ``argument``, or a clear error."""
    v = finite_real(x, argument)
    if not v.is_number:
        raise ArgumentError(f"`{argument}` must be a number; got {x!r}.")
    return float(v)


def _mapping(x, argument):
    if x is None:
        return {}
    if not isinstance(x, dict):
        raise ArgumentTypeError(
            f"`{argument}` must be a dict (values by name or symbol); got {type(x).__name__}.")
    return x


def _free_symbols(exprs):
    return set().union(*(sp.sympify(e).free_symbols for e in exprs)) - {_t}


def state_numbers(source, items, *, q, u, t, params):
    """A function: list of expressions -> floats at the state (q, u, t) with ``params``."""
    exprs = [e for it in items for e in _expressions(it)]
    coords = _coordinates(source, exprs)
    subs = {}
    qv = _state_vector(q, coords, "q", default=None)
    uv = _state_vector(u, coords, "u", default=0.0)
    for c, qi, ui in zip(coords, qv, uv, strict=True):
        subs[c.diff(_t)] = sp.Float(float(ui))
        subs[c] = sp.Float(float(qi))
    symbols = _free_symbols(exprs)
    needs_dynamics = source.dynamics is not None and any(it.link is not None for it in items)
    dyn = source.dynamics if needs_dynamics else None
    if dyn is not None:
        symbols |= set(dyn.equations_of_motion().parameters)
    params = _mapping(params, "params")
    subs.update({k: _number(v, f"params[{k.name!r}]")
                 for k, v in substitutions(params, symbols, "params").items()})
    subs[_t] = t = _number(t, "t")
    lams = set(dyn.multiplier_symbols()) if dyn is not None else set()
    missing = sorted(s.name for s in symbols - set(subs) - lams)
    if missing:
        raise ArgumentError(
            f"`params` must give numbers for {missing} to draw the free-body diagram; got "
            f"{sorted(str(k) for k in (params or {}))}.")
    dynamic = {}
    if dyn is not None:
        dynamic = _dynamic_state(dyn, coords, qv, uv, float(t), params or {})

    def numbers(batch):
        out = []
        for e in batch:
            v = sp.sympify(e).xreplace(dynamic).xreplace(subs)
            if v.free_symbols:
                raise ArgumentError(
                    f"`params` must give numbers for {sorted(map(str, v.free_symbols))} to "
                    "draw the free-body diagram.")
            out.append(float(sp.re(sp.N(v))))
        return np.array(out)

    return numbers


def _dynamic_state(system, coords, q, u, t, params):
    """{q''(t): value, multiplier: value} at the state, from the equations of motion."""
    eqs = system.equations_of_motion()
    named = {getattr(k, "name", k): float(v) for k, v in params.items()}
    keep = {p.name for p in eqs.parameters}
    rhs = eqs.rhs(**{k: v for k, v in named.items() if k in keep})
    acc = rhs(t, np.concatenate([q, u]))[len(coords):]
    out = {c.diff(_t, 2): float(a) for c, a in zip(coords, acc, strict=True)}
    lams = system.multiplier_symbols()
    if lams:
        vals = system.multipliers(q, u, t, params=named)
        out.update({lam: float(v) for lam, v in zip(lams, vals, strict=True)})
    return out


def _expressions(item, dynamic=True):
    out = list(item.point)
    if item.link is None or dynamic:
        for part in (item.force, item.moment):
            out += list(part or [])
    for _, _, d, v in item.components:
        out += list(d) + ([] if v is None else [v])
    if item.cone is not None:
        out += list(item.cone[0])
    return out


def _coordinates(source, exprs):
    if source.dynamics is not None:
        return tuple(source.dynamics.coordinates)
    funcs = set().union(*(sp.sympify(e).atoms(sp.core.function.AppliedUndef) for e in exprs))
    return tuple(sorted((f for f in funcs if f.args == (_t,)), key=lambda f: f.func.__name__))


def _state_vector(given, coords, argument, default):
    if given is None:
        if default is None and coords:
            raise ArgumentError(
                f"`{argument}` must give the coordinates {[c.func.__name__ for c in coords]} "
                "to place the bodies; got None.")
        return np.full(len(coords), 0.0 if default is None else default)
    if isinstance(given, dict):
        by_name = {}
        for k, v in given.items():
            by_name[k if isinstance(k, str) else k.func.__name__] = v
        names = [c.func.__name__ for c in coords]
        extra = sorted(set(by_name) - set(names))
        if extra:
            raise ArgumentError(f"`{argument}`: {extra} name no coordinate of the diagram; "
                                f"expected some of {names}.")
        missing = [n for n in names if n not in by_name]
        if missing and default is None:
            raise ArgumentError(f"`{argument}` must give a value for {missing}; got "
                                f"{sorted(by_name)}.")
        return np.array([_number(by_name.get(c.func.__name__, default),
                                 f"{argument}[{c.func.__name__!r}]") for c in coords])
    if isinstance(given, str | bytes) or not hasattr(given, "__len__"):
        raise ArgumentTypeError(
            f"`{argument}` must be a sequence of numbers or a dict by coordinate name; got "
            f"{type(given).__name__}.")
    arr = np.array([_number(v, argument) for v in np.asarray(given, dtype=object).reshape(-1)])
    if arr.size != len(coords):
        raise ArgumentError(
            f"`{argument}` must hold {len(coords)} values, one per coordinate "
            f"{[c.func.__name__ for c in coords]}; got {arr.size}.")
    return arr


def motion_numbers(simulation, source, items):
    """Every expression of ``items`` along ``simulation``, evaluated once: a function
    (expressions, sample index) -> floats, and one (item, sample index) -> (force, moment)
    for the connection actions that come from dynamics (Lagrange multipliers included)."""
    exprs = list(dict.fromkeys(e for it in items for e in _expressions(it, dynamic=False)))
    if exprs:
        table = simulation.evaluate(sp.ImmutableMatrix(len(exprs), 1, exprs))[:, 0]
    else:
        table = np.zeros((0, simulation.t.size))
    row = {e: i for i, e in enumerate(exprs)}
    R0 = source.reference
    actions = {}
    for it in items:
        if it.link is not None:
            c = simulation.connection_action(source.end(it.link.first),
                                             source.end(it.link.second), basis=R0,
                                             system=source.dynamics, label=it.link.label)
            actions[id(it)] = (it.sign * np.array([c["X"], c["Y"], c["Z"]]),
                               it.sign * np.array([c["L"], c["M"], c["N"]]))

    def numbers(batch, k):
        return np.array([table[row[e], k] for e in batch])

    def link_numbers(item, k):
        force, moment = actions[id(item)]
        return force[:, k], moment[:, k]

    return numbers, link_numbers
