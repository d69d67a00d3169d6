"""The actions exerted on an isolated body or set of bodies, as numbers to draw (book,
ch. 13-14, 18.2).

A free-body diagram isolates a body, or a set S of bodies, and shows every action the rest
of the world exerts on it (ch. 14.2.3): the given actions (forces at their points, couples,
the weights at the mass centres, springs and dampers as forces at their ends) and the actions
of the connections that join S to the outside, each with the unknown components the book
names after the connection's label (``X_A, Y_A, Z_A, L_A, M_A, N_A`` for a joint,
``N_A, T_A`` for a contact with friction, the names :mod:`rigidmech.actions` gives them).
Actions between two bodies of S are internal and left out.

:func:`external_actions` lists them as :class:`ExternalAction` values, in numbers, at one
state or along a motion; :func:`rigidmech.drawing.free_body_diagram` draws them.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import sympy as sp

from .._core.errors import ArgumentError, ArgumentTypeError
from .._core.validation import substitutions
from ..statics import Limit, Statics
from ..statics.limits import largest_margin  # the limit's own program
from ._fbd_sources import Source, plan, state_numbers

__all__ = ["Component", "Cone", "ExternalAction", "external_actions", "limiting_values",
           "CONE_RTOL"]

#: relative tolerance (on the magnitude of R) of the decision "the action lies on the edge of
#: its friction cone": ``abs(|T| - f N) <= CONE_RTOL |R|`` (the limits of
#: :mod:`rigidmech.statics.limits` are accurate to about 1e-9 relative; a margin above that,
#: far below a visible difference)
CONE_RTOL = 1e-6


def _frozen(a):
    a = np.array(a, dtype=float)
    a.setflags(write=False)
    return a


@dataclass(frozen=True)
class Component:
    """One unknown component of a connection's action, as exerted on the isolated set.

    Attributes
    ----------
    name : str
        The unknown's name (``"X_A"``, ``"N_B"``), that of :mod:`rigidmech.actions`.
    kind : str
        ``"force"`` or ``"moment"``.
    direction : numpy.ndarray
        Unit vector (components in the reference's basis) along which the unknown acts on
        the isolated set (the opposite of its basis vector when the set is the connection's
        first end: the reaction).
    value : float or None
        The unknown's value when known (statics solved, or a state of a motion).
    """

    name: str
    kind: str
    direction: np.ndarray
    value: float | None


@dataclass(frozen=True)
class Cone:
    """The friction cone of a contact (ch. 13.1.2): apex at the contact point, axis the
    normal into the isolated set, half-angle arctan f_s.

    Attributes
    ----------
    normal : numpy.ndarray
        Unit normal into the isolated set.
    half_angle : float
        arctan f_s, in radians.
    status : str or None
        Where the action lies when known: ``"inside"``, ``"edge"`` (limiting equilibrium or
        sliding: ``abs(|T| - f_s N) <= CONE_RTOL |R|``) or ``"outside"``; None when unknown.
    side : numpy.ndarray or None
        Unit direction of the tangential part of the action (the side of the cone it leans
        on), None when unknown or purely normal.
    """

    normal: np.ndarray
    half_angle: float
    status: str | None
    side: np.ndarray | None


@dataclass(frozen=True)
class ExternalAction:
    """An action exerted on the isolated set, in numbers (see :func:`external_actions`).

    Attributes
    ----------
    kind : str
        ``"weight"``, ``"force"``, ``"couple"``, ``"spring"`` (springs and dampers),
        ``"contact"`` (one-sided contacts with their laws), ``"rolling"`` (rolling without
        slipping) or ``"connection"`` (joints, gear meshes).
    label : str
        The connection's label, or a name for a given action (``"W_ladder"``, ``"F"``).
    point : numpy.ndarray
        Point of application (the connection's point), in the reference's basis.
    force : numpy.ndarray or None
        Resultant on the isolated set; None when some unknown has no value.
    moment : numpy.ndarray or None
        Moment at ``point``; None when some unknown has no value.
    components : tuple of Component
        The connection's unknown components (empty for a given action).
    cone : Cone or None
        The friction cone of a contact with friction.
    """

    kind: str
    label: str
    point: np.ndarray
    force: np.ndarray | None
    moment: np.ndarray | None
    components: tuple = ()
    cone: Cone | None = None


def _cone(item, force, numbers):
    normal, f = item.cone
    n = np.asarray(numbers(normal), dtype=float)
    n = n / np.linalg.norm(n)
    if force is None:
        return Cone(_frozen(n), float(np.arctan(f)), None, None)
    N = float(force @ n)
    T = force - N * n
    t = float(np.linalg.norm(T))
    scale = float(np.linalg.norm(force))
    side = _frozen(T / t) if t > CONE_RTOL * scale and t > 0 else None
    gap = t - f * N
    status = ("edge" if abs(gap) <= CONE_RTOL * scale and N > 0
              else "inside" if gap < 0 and N >= 0 else "outside")
    return Cone(_frozen(n), float(np.arctan(f)), status, side)


def _build(items, numbers, link_numbers=None):
    """The ExternalAction values of ``items`` from ``numbers`` (expressions -> floats) and,
    for connection actions from dynamics along a motion, ``link_numbers``."""
    out = []
    for item in items:
        if item.link is not None and link_numbers is not None:
            force, moment = (_frozen(v) for v in link_numbers(item))
        else:
            force = None if item.force is None else _frozen(numbers(item.force))
            moment = None if item.moment is None else _frozen(numbers(item.moment))
        comps = []
        for name, kind, direction, value in item.components:
            d = np.array(numbers(direction), dtype=float)
            norm = float(np.linalg.norm(d))
            if value is not None:
                v = float(numbers([value])[0])
            elif item.link is not None:        # the unknown's value: its part of the action
                part = force if kind == "force" else moment
                v = float(part @ d) / norm**2
            else:
                v = None
            comps.append(Component(name, kind, _frozen(d / norm if norm else d), v))
        cone = None if item.cone is None else _cone(item, force, numbers)
        out.append(ExternalAction(item.kind, item.label, _frozen(numbers(item.point)),
                                  force, moment, tuple(comps), cone))
    return tuple(out)


def external_actions(system, bodies, *, q=None, u=None, t=0.0, params=None,
                     equilibrium=None, values=None) -> tuple:
    """The actions exerted on ``bodies`` by everything else, in numbers (ch. 14.2.3).

    Parameters
    ----------
    system : System, Model, Mechanism or Statics
        The bodies, their connections and the given actions (a
        :class:`~rigidmech.models.Model` stands for its system).
    bodies : Body or sequence of Body
        The isolated body or set of bodies.
    q, u : sequence or dict, optional
        The coordinates and their rates (a dynamics state), in the order of the system's
        coordinates or keyed by coordinate or name; u defaults to zeros. For a
        :class:`~rigidmech.dynamics.System` the connection actions are then evaluated at
        that state by the fundamental principle (:meth:`System.connection_action
        <rigidmech.dynamics.System.connection_action>`, q'' from the equations of motion).
    t : float
        The time of the state.
    params : dict, optional
        Numbers for the constants (masses, lengths, loads), keyed by symbol or name.
    equilibrium : Equilibrium, optional
        A solved statics problem (:meth:`Statics.solve
        <rigidmech.statics.Statics.solve>`): its determined unknowns give the values.
    values : dict, optional
        Values of connection unknowns keyed by symbol or name (``{"N_A": 3.0}``), e.g. at a
        limiting equilibrium (:func:`limiting_values`); they take precedence.

    Returns
    -------
    tuple of ExternalAction

    Examples
    --------
    A block of weight 10 resting on a floor, isolated:

    >>> import rigidmech as rm
    >>> from rigidmech.actions import ContactLaws, Force
    >>> R0 = rm.Frame("R0"); box = rm.Body("box", frame=R0)
    >>> st = rm.statics.Statics(R0)
    >>> st.connect(R0, box, ContactLaws(at=R0.origin, normal=R0.j), label="A")
    >>> st.act(Force(on=box, vector=-10 * R0.j, at=R0.point("G", 0, 1, 0)))
    >>> acts = external_actions(st, box, equilibrium=st.solve())
    >>> [(a.kind, a.label) for a in acts]
    [('contact', 'A'), ('force', 'F')]
    >>> acts[0].components[0].name, acts[0].force.tolist()
    ('N_A', [0.0, 10.0, 0.0])
    """
    source = Source(system, bodies)
    dynamic = source.dynamics is not None and q is not None
    items = plan(source, equilibrium=equilibrium, values=values, dynamic=dynamic)
    return _build(items, state_numbers(source, items, q=q, u=u, t=t, params=params))


def limiting_values(statics, limit, *, values=None) -> dict:
    """The connection unknowns of ``statics`` at its limiting equilibrium ``limit`` (the
    :class:`~rigidmech.statics.Limit` of :meth:`Statics.limit
    <rigidmech.statics.Statics.limit>`), with the parameter at ``limit.value``: the
    solution of the equations of statics that lies inside every contact's laws with the
    largest margin (zero at the limit), found by the same linear program as the limit
    (ch. 14.4). At a limit where every contact of a hyperstatic problem is on the edge of its
    cone (a ladder sliding at both ends) it is the only one.

    Parameters
    ----------
    statics : Statics
    limit : Limit
        Its ``value`` must not be None (the equilibrium must break in the interval).
    values : dict, optional
        Numbers for the other symbols, as given to :meth:`Statics.limit`.

    Returns
    -------
    dict
        ``{unknown symbol: float}``.

    Examples
    --------
    A block of weight 10 pulled along a floor with f_s = 0.3 slides at P = 3; there the
    friction is -3 (it holds the block back) and N = 10:

    >>> import sympy as sp
    >>> import rigidmech as rm
    >>> from rigidmech.actions import ContactLaws, Coulomb, Force
    >>> P = sp.Symbol("P")
    >>> R0 = rm.Frame("R0"); block = rm.Body("block", frame=R0)
    >>> st = rm.statics.Statics(R0)
    >>> st.connect(R0, block, ContactLaws(at=R0.origin, normal=R0.j, tangent=R0.i,
    ...                                   friction=Coulomb(0.3)), label="I")
    >>> st.act(Force(on=block, vector=-10 * R0.j + P * R0.i, at=R0.origin))
    >>> lim = st.limit(P, (0, 10))
    >>> {k: round(v, 9) for k, v in limiting_values(st, lim).items()}
    {N_I: 10.0, T_I: -3.0}
    """
    return _limiting_values(statics, limit, values)


def _limiting_values(statics, limit, values) -> dict:
    """``{unknown: value}`` at ``limit.value`` (see :func:`limiting_values`)."""
    if not isinstance(statics, Statics):
        raise ArgumentTypeError(f"`statics` must be a Statics; got {type(statics).__name__}.")
    if not isinstance(limit, Limit):
        raise ArgumentTypeError(
            f"`limit` must be a Limit (Statics.limit(...)); got {type(limit).__name__}.")
    if limit.value is None:
        raise ArgumentError(
            "`limit` must be a limit reached in its interval; got one where the equilibrium "
            "holds throughout (limit.value is None): there is no limiting equilibrium to "
            "draw.")
    xs = list(statics.unknowns)
    rows = [e for _, _, e in statics.equations()]
    conds = [e for _, _, e in statics.contact_conditions()]
    symbols = set().union(*(e.free_symbols for e in rows + conds))
    subs = substitutions(values, symbols)
    subs[limit.parameter] = limit.value
    A, b = sp.linear_eq_to_matrix([e.xreplace(subs) for e in rows], xs)
    G, _ = sp.linear_eq_to_matrix([e.xreplace(subs) for e in conds], xs)
    free = (A.free_symbols | b.free_symbols | G.free_symbols)
    if free:
        raise ArgumentError(f"`values` must give numbers for {sorted(free, key=str)}.")
    An, bn, Gn = (np.array(M.tolist(), dtype=float) for M in (A, b, G))
    norms = np.linalg.norm(Gn, axis=1)
    Gn = Gn / np.where(norms > 0, norms, 1.0)[:, None]
    _, x = largest_margin(An, bn.reshape(-1), Gn)
    if x is None:
        raise ArgumentError("`limit`: the equations of statics have no solution at "
                            f"{limit.parameter} = {limit.value}.")
    return {u: float(v) for u, v in zip(xs, x, strict=True)}
