"""A system's equations of motion derived step by step, as the book writes them (book, ch. 9,
11, 13, 16, 18, 20, 25).

:func:`derivation` reads what the library computes when it derives the equations of a
:class:`~rigidmech.dynamics.System` (the kinematic, kinetic and dynamic torsors of its bodies,
the actions' torsors, the partial kinematic torsors and the power coefficients the equations
are assembled from, the equations themselves) and lays them out the book's way:

1. the parameters of situation (and, for linked parameters, the closure conditions and their
   Lagrange multipliers, ch. 25.3.3, with the hyperstatic unknowns of a loop-closing joint
   named and taken zero, ch. 14.2);
2. each body's kinematic torsor {V(S/R)} at a chosen point (ch. 9.2.4);
3. the kinetic and dynamic torsors {C(S/R)}, {D(S/R)} at the mass centre and the kinetic
   energy (ch. 16);
4. the action torsors: the given actions, and the connections' with their unknowns
   (``X_1``, ``Y_1``, ... as :meth:`Joint.action_torsor
   <rigidmech.actions.Joint.action_torsor>` names them) or, for a linking connection, its
   multipliers (ch. 11, 13.2);
5. the partial kinematic torsors {V_i(S/R)} and the power coefficients (ch. 25.1.2-25.1.4);
6. route ``"principle"``: the fundamental principle {D(S/R)} = {A(ext -> S)} for each
   isolated body, projected on the partial kinematic torsors and summed over the set
   (ch. 18.1, 25.1.4); route ``"lagrange"``: T, dT/dq_i', its derivative, dT/dq_i and the
   power coefficients Q_i (ch. 25.3.2);
7. the equations of motion M(q) q'' = f (+ A^T lambda for linked parameters).

The report re-derives nothing: each value is the library's own (the same cached partial
kinematic torsors and action contributions the equations were assembled from); only the
comoments of step 6 are formed here, with :meth:`Torsor.comoment
<rigidmech.torsors.Torsor.comoment>`, to show the projection.
"""

from __future__ import annotations

from collections.abc import Mapping

import sympy as sp

from .._core.errors import ArgumentError, ArgumentTypeError, ConnectionError_
from ..dynamics import System
from ..lagrange import lagrange_equations
from ..models import Model
from ..vectors import Point
from ._display import Display, Relation, check_max_ops
from ._steps import StepsWriter
from .document import Derivation, Line, Step

__all__ = ["derivation", "ROUTES", "default_point"]

#: The routes to the equations: the fundamental principle projected on the partial kinematic
#: torsors (ch. 18, 25.1.4), or Lagrange's equations (ch. 25.3).
ROUTES = ("principle", "lagrange")


def _checked_system(system):
    if isinstance(system, Model):
        system = system.system
    if not isinstance(system, System):
        raise ArgumentTypeError(
            f"`system` must be a System or a Model of rigidmech.models; got "
            f"{type(system).__name__}.")
    if system.contacts:
        raise ConnectionError_(
            f"`system` has {len(system.contacts)} one-sided contact(s) with friction whose "
            "equations change with the regime (stick, slip, lift-off): a single derivation "
            "does not describe it. Model the regime you want to show (a sliding block: a "
            "prismatic joint and the friction force as a given Force).")
    return system


def default_point(system, body) -> Point:
    """The point at which a report gives ``body``'s kinematic torsor by default: the point
    of its first connection to a parent (a joint's point, a rolling contact's point), or its
    mass centre for a body without one.

    Examples
    --------
    >>> from rigidmech import models
    >>> dp = models.double_pendulum()
    >>> [default_point(dp.system, b).name for b in dp.bodies]
    ['O_R0', 'A']
    """
    for link in system.mechanism.links:
        if link.second is body:
            conn = link.connection
            contact = getattr(conn, "contact", None)
            point = getattr(contact, "point", None) or getattr(conn, "at", None)
            if isinstance(point, Point):
                return point
    return body.centre


def _points(system, at):
    points = {b.name: default_point(system, b) for b in system.bodies}
    if at is None:
        return points
    if isinstance(at, Point):
        return dict.fromkeys(points, at)
    if not isinstance(at, Mapping):
        raise ArgumentTypeError(
            f"`at` must be None, a Point or a dict {{body or name: Point}}; got "
            f"{type(at).__name__}.")
    for key, point in at.items():
        name = getattr(key, "name", key)
        if name not in points:
            raise ArgumentError(
                f"`at` must map bodies of the system ({', '.join(points)}) to points; got the "
                f"key {key!r}.")
        if not isinstance(point, Point):
            raise ArgumentTypeError(
                f"`at` must map each body to a Point; got {type(point).__name__} for {name}.")
        points[name] = point
    return points


def derivation(system, *, route: str = "principle", at=None, simplify: bool = True,
               max_ops: int = 40) -> Derivation:
    """The equations of motion of ``system`` derived step by step, the book's way.

    Parameters
    ----------
    system : System or rigidmech.models.Model
        A system without one-sided friction contacts (their equations change with the
        regime).
    route : {"principle", "lagrange"}, default "principle"
        ``"principle"``: the fundamental principle for each isolated body projected on the
        partial kinematic torsors and summed over the set (ch. 18.1, 25.1.4);
        ``"lagrange"``: Lagrange's equations (ch. 25.3.2).
    at : None, Point or dict, optional
        Where each body's kinematic torsor (and its partial kinematic torsors) is reduced:
        by default the point of its connection to its parent (:func:`default_point`), else
        its mass centre; one point for every body, or a dict {body or name: point}. The
        kinetic and dynamic torsors are always reduced at the mass centre (ch. 16.1.2).
    simplify : bool, default True
        Simplify every expression shown (``sympy.simplify``: slow on large systems, pass
        False there). The values in :attr:`Derivation.results` are never simplified.
    max_ops : int, default 40
        An expression shown with more operations (``sympy.count_ops``) than this is named
        (common subexpressions by ``sympy.cse``, z1, z2, ...), its definition given at the
        end.

    Returns
    -------
    Derivation

    Raises
    ------
    ArgumentTypeError
        For a ``system`` that is neither a System nor a Model, an ``at`` that is not a
        point or a dict of points, a ``max_ops`` that is not an int.
    ArgumentError
        For an unknown ``route``, a key of ``at`` that is not a body of the system, a
        ``max_ops`` < 1.
    ConnectionError\\_
        For a system with one-sided contacts with friction.

    Examples
    --------
    >>> from rigidmech import models, report
    >>> rep = report.derivation(models.double_pendulum())
    >>> rep.kinematic_torsor("bar2").velocity
    L*Derivative(theta1(t), t)*R1.j
    >>> print(rep.steps[-1].to_text())  # doctest: +ELLIPSIS
    8. Equations of motion (ch. 20.2, 25.1.4)
       ...
       (theta1) 4*L**2*m*theta1_ddot/3 + L**2*m*theta2_ddot*cos(theta1 - theta2)/2 = ...
    """
    system = _checked_system(system)
    if route not in ROUTES:
        raise ArgumentError(f"`route` must be one of {ROUTES}; got {route!r}.")
    max_ops = check_max_ops(max_ops)
    points = _points(system, at)
    writer = StepsWriter(system, points)
    writer.situation()
    writer.kinematics()
    writer.kinetics()
    writer.actions()
    writer.partials()
    if route == "principle":
        writer.principle()
        eqs = system.equations_of_motion()
    else:
        writer.lagrange()
        eqs = lagrange_equations(system)
    writer.equations(eqs)
    return _render(writer, route, simplify, max_ops)


def _render(writer, route, simplify, max_ops):
    """Shown form of the writer's steps (one naming of long expressions for all)."""
    q_sym, u_sym, a_sym, rule = writer.system.symbols()
    dots = {}
    for q, u, a in zip(q_sym, u_sym, a_sym, strict=True):
        base = sp.latex(q)
        dots[q], dots[u], dots[a] = base, rf"\dot{{{base}}}", rf"\ddot{{{base}}}"
    display = Display(rule, dots, simplify=simplify, max_ops=max_ops)
    raw = [value for step in writer.steps for _, value, _ in step[3]]
    prepared = display.prepare(raw)
    display.name_long(prepared)
    shown = iter(prepared)
    steps = []
    for number, (title, section, intro, lines) in enumerate(writer.steps, start=1):
        rendered = []
        for label, _, note in lines:
            value = display.final(next(shown))
            text = tex = ""
            if value is not None:
                text, tex = display.text(value), display.latex(value)
                if isinstance(value, Relation) and label is not None:
                    text, tex = f"{label.text}  {text}", rf"{label.latex}\quad {tex}"
                elif label is not None:
                    text, tex = f"{label.text} = {text}", f"{label.latex} = {tex}"
            rendered.append(Line(text, tex, note))
        steps.append((number, title, section, intro, tuple(rendered)))
    named_lines = tuple((f"{s} = {display.text(e)}", f"{display.latex(s)} = {display.latex(e)}")
                        for s, e in display.named)
    how = ("the fundamental principle projected on the partial kinematic torsors"
           if route == "principle" else "Lagrange's equations")
    names = ", ".join(b.name for b in writer.system.bodies)
    return Derivation(route=route, steps=[Step(*s) for s in steps], named=display.named,
                      named_lines=named_lines, results=writer.results,
                      title=f"Equations of motion of {names} by {how}")

