"""Linked parameters in a :class:`~rigidmech.dynamics.System`: the conditions of the
connections that close loops, roll or mesh, their constraints, the loops, mobility and
hyperstaticity of the graph, assembly and Lagrange multipliers (book, ch. 13.2, 25.3).

:class:`LinkedParameters` holds these methods of :class:`~rigidmech.dynamics.System`; it
relies on the system's graph (``_graph``), its closures (``_closures``: the linking
connections and their condition rows) and its cache.
"""

from __future__ import annotations

import numpy as np
import sympy as sp

from .._core.errors import ArgumentError, ConnectionError_
from ..systems import closure_forces
from ..systems.mobility import GenericValues, numeric_rank
from ._run import merge_values
from .assembly import ON_CONSTRAINTS, Closure, assemble, explicit_time, time_of
from .constraints import Constraints

__all__ = ["LinkedParameters"]


def _check_independent(constraints):
    """Refuse closure conditions that depend on the others at a generic configuration (a
    connection repeating what others already impose): the multipliers would not be
    determined and the augmented matrix would be singular everywhere. The rank is decided
    by the rule of :func:`rigidmech.systems.analyse` (the same decision as the mobility)."""
    A = constraints.jacobian
    numbers = GenericValues(None, 0)
    An = np.array([[numbers(x) for x in row] for row in A.tolist()], dtype=float)
    kept, redundant = [], []
    for r, label in enumerate(constraints.labels):
        if numeric_rank(An[kept + [r]]) > len(kept):
            kept.append(r)
        else:
            redundant.append(label)
    if redundant:
        raise ConnectionError_(
            f"the closure conditions {', '.join(redundant)} depend on the other closure "
            f"conditions ({', '.join(constraints.labels[r] for r in kept)}) at every "
            "configuration: the Lagrange multipliers would not be determined and the "
            "equations could not be solved. The mounting is hyperstatic (see mobility()): "
            "remove the connection that repeats the others, or use one that blocks fewer "
            "motions (a linear annular or a point contact instead of a pivot).")


class LinkedParameters:
    """The linked-parameter methods of :class:`~rigidmech.dynamics.System` (a mixin: see
    the system for examples).

    Examples
    --------
    >>> import rigidmech as rm
    >>> issubclass(rm.System, LinkedParameters)
    True
    """

    __slots__ = ()

    def closure_conditions(self) -> tuple:
        """The conditions ``(label, velocity, position)`` of the connections that link the
        parameters (loop-closing joints, rolling contacts, gear meshes), in the order they
        were connected; ``position`` is None for a condition kept at the velocity level
        (see :func:`rigidmech.systems.closure_conditions`).

        Examples
        --------
        A slider-crank: crank q1, rod q2 (relative to the crank), slider x; the pivot at B
        between the rod and the slider closes the loop.

        >>> import rigidmech as rm
        >>> q1, q2, x = rm.coordinates("q1 q2 x")
        >>> R0 = rm.Frame("R0"); k = R0.k
        >>> R1 = R0.rotated("R1", about=k, angle=q1)
        >>> A = R0.origin.moved("A", R1.i)
        >>> R2 = R1.rotated("R2", about=k, angle=q2, origin=A)
        >>> P = R0.point("P", x, 0, 0)
        >>> s = rm.System(galilean=R0)
        >>> crank, rod = rm.Body("crank", frame=R1, mass=1), rm.Body("rod", frame=R2, mass=1)
        >>> s.connect(R0, crank, rm.joints.Pivot(at=R0.origin, axis=k))
        >>> s.connect(crank, rod, rm.joints.Pivot(at=A, axis=k))
        >>> s.connect(R0, rm.Body("slider", frame=R0.translated("R3", P), mass=1),
        ...           rm.joints.Prismatic(at=P, axis=R0.i))
        >>> s.connect(s.bodies[1], s.bodies[2], rm.joints.Pivot(at=A.moved("B", 3 * R2.i),
        ...           axis=k), meets=P)
        >>> for label, _, phi in s.closure_conditions():
        ...     print(label, phi)
        4.u x(t) - 3*cos(q1(t) + q2(t)) - cos(q1(t))
        4.v -3*sin(q1(t) + q2(t)) - sin(q1(t))
        >>> q0, u0 = s.assemble({"q1": 0.0, "q2": 0.1, "x": 3.5}, independent=["q1"],
        ...                     rates={"q1": 1.0})
        >>> round(q0["x"], 12), round(q0["q2"], 12), round(u0["x"], 12)
        (4.0, 0.0, 0.0)

        At this dead centre x = cos q1 + sqrt(9 - sin(q1)^2) has x'' = -4/3 q1'^2 and q1''
        = 0: the rod pulls the slider with -4/3 along i.

        >>> (s.multipliers(list(q0.values()), list(u0.values())).round(12) + 0.0).tolist()
        [-1.333333333333, 0.0]
        """
        return tuple(row for _, rows in self._closures for row in rows)

    def constraints(self):
        """The constraints between the coordinates as a
        :class:`~rigidmech.dynamics.Constraints` (Jacobian A, bias b with A q'' = b), or None
        for a tree without linking connections.

        Examples
        --------
        >>> import rigidmech as rm
        >>> R0 = rm.Frame("R0"); s = rm.System(galilean=R0)
        >>> s.constraints() is None
        True
        """
        rows = self.closure_conditions()
        if not rows:
            return None
        if "constraints" not in self._cache:
            c = Constraints(self.coordinates, rows, stabilization=self._stabilization)
            _check_independent(c)
            self._cache["constraints"] = c
        return self._cache["constraints"]

    def loops(self) -> tuple:
        """The independent loops of the graph of connections (see
        :meth:`rigidmech.systems.Mechanism.loops`).

        Examples
        --------
        >>> import rigidmech as rm
        >>> R0 = rm.Frame("R0"); s = rm.System(galilean=R0)
        >>> s.loops()
        ()
        """
        return self._graph.loops()

    def mobility(self, plane=None, values=None):
        """Degrees of mobility and hyperstaticity of the connections (ch. 13.2, 14.2), see
        :func:`rigidmech.systems.analyse`.

        Examples
        --------
        >>> import rigidmech as rm
        >>> R0 = rm.Frame("R0"); s = rm.System(galilean=R0)
        >>> shaft = rm.Body("shaft", frame=R0.rotated("R1", about=R0.k,
        ...                                         angle=rm.coordinates("theta")))
        >>> s.connect(R0, shaft, rm.joints.Pivot(at=R0.origin, axis=R0.k))
        >>> s.connect(R0, shaft, rm.joints.Pivot(at=R0.point("B", 0, 0, 1), axis=R0.k))
        >>> print(s.mobility())
        mobility m = 1 (N_c = 2 kinematic unknowns, rank 1 of the closure equations of 1 loop(s))
        hyperstaticity h = 5 = N_s - 6 N_b + m = 10 - 6*1 + 1
        undetermined by statics: X_1, Y_1, Z_1, L_1, M_1, X_2, Y_2, Z_2, L_2, M_2
        """
        return self._graph.mobility(plane=plane, values=values)

    def assemble(self, values, *, independent=None, rates=None, t=None, params=None,
                 **constants):
        """A configuration and velocities that satisfy the constraints: the dependent
        parameters solved from the closure conditions by Newton's method, the independent
        ones kept (see :func:`rigidmech.dynamics.assembly.assemble`).

        Parameters
        ----------
        values : dict
            Values of the coordinates (by q(t) or by name): exact for the independent ones,
            a first guess for the others.
        independent : sequence of q(t) or names, optional
            The independent parameters; default chosen by pivoting on the Jacobian of the
            constraints (the best conditioned set).
        rates : dict, optional
            The rates of the independent parameters (default zero).
        t : float, optional
            The time of the configuration. Required when the constraints depend on the time
            explicitly (a driven joint, a moving support): they are then refused without it,
            rather than assembled at an arbitrary t = 0. Not needed (and not used) otherwise.
        params : dict, optional
            Values of the constants by name, as in :meth:`EquationsOfMotion.simulate`: needed
            for a constant whose name is also an argument here (``u``, ``t``, ``values``,
            ``rates``, ...); the others may also be given as keywords (a name given both ways
            is refused).
        **constants
            Values of the constants the constraints depend on.

        Returns
        -------
        (dict, dict)
            q0 and u0 by name, ready for :meth:`EquationsOfMotion.simulate`.
        """
        c = self.constraints()
        if c is None:
            raise ConnectionError_(
                "the system has no linking connection: every set of values is consistent.")
        return assemble(c, values, independent=independent, rates=rates, t=t,
                        params=merge_values(params, constants))

    def multipliers(self, q, u, t=None, *, params=None, **constants):
        """The Lagrange multipliers lambda (one per closure condition, in the order of
        :meth:`closure_conditions`) at the state (q, u) at the time ``t``, from the augmented
        system: the generalised constraint forces are A^T lambda. For a joint closing a loop,
        the multiplier of the condition along e is the component along e of the action of
        ``parent`` on ``child`` at the point of the joint. The state must be on the
        constraints (:meth:`assemble`, at the same t): every residual Φ and A q' + a at most
        1e-9 of the magnitude of its terms (the rule assemble reaches,
        :func:`rigidmech._core.rules.on_constraints`), otherwise it is refused (the values
        would include Baumgarte's correction).

        ``t`` is required when the equations or the constraints depend on the time
        explicitly (a driven joint) or an input F(t) is given as a function of t, refused as
        missing then; otherwise it is not used. ``params`` gives the constants by name as in
        :meth:`EquationsOfMotion.simulate` (needed for a constant named ``q``, ``u`` or
        ``t``). Examples: see :meth:`closure_conditions`."""
        eqs = self.equations_of_motion()
        if eqs.constraints is None:
            raise ConnectionError_("the system has no linking connection: no multiplier.")
        c = eqs.constraints
        given = merge_values(params, constants)
        if "multipliers_explicit_time" not in eqs._cache:   # decided once for the equations
            eqs._cache["multipliers_explicit_time"] = explicit_time(
                [eqs.mass_matrix, eqs.forcing, *c.velocity, *c.bias,
                 *[p for p in c.position if p is not None]], eqs.coordinates, eqs.inputs)
        depends = any(callable(given.get(w.func.__name__)) for w in eqs.inputs) \
            or eqs._cache["multipliers_explicit_time"]
        t = time_of(t, depends, "the equations or the constraints (or an input given as a "
                    "function of t)")
        values, inputs, _ = eqs._values(given)
        inputs = [w(t) if callable(w) else w for w in inputs]   # an input F(t) at t
        if "closure" not in self._cache:
            self._cache["closure"] = Closure(c)
        closure = self._cache["closure"]
        q_arr, u_arr = np.asarray(q, float), np.asarray(u, float)
        off = closure.off(q_arr, u_arr, t, closure.constants(given))
        if off:
            raise ArgumentError(
                f"(`q`, `u`) is not on the constraints at t = {t}: the conditions "
                f"{', '.join(f'{lab} = {x:.3g}' for lab, x in off)} exceed {ON_CONSTRAINTS} "
                "of the magnitude of their terms (the multipliers there would carry "
                "Baumgarte's correction). Pass a state "
                "from System.assemble or from a simulation that keeps the constraints.")
        full = eqs._solver().full
        out = full(t, q_arr, u_arr, *values, *inputs)
        return -np.asarray(out)[len(eqs.coordinates):]

    def multiplier_symbols(self) -> tuple:
        """The symbols lambda_<condition> of the Lagrange multipliers, one per closure
        condition (:meth:`closure_conditions`), in which the connection actions of a system
        with linking connections are written; their values at a state come from
        :meth:`multipliers`.

        Examples
        --------
        >>> import rigidmech as rm
        >>> R0 = rm.Frame("R0"); rm.System(galilean=R0).multiplier_symbols()
        ()
        """
        return tuple(sp.Symbol(f"lambda_{row[0]}", real=True)
                     for row in self.closure_conditions())

    def _link(self, parent, child, label):
        links = [k for k in self._graph.links if k.first is parent and k.second is child
                 and (label is None or k.label == str(label))]
        if not links:
            known = [f"{k.first.name} -> {k.second.name} (label {k.label!r})"
                     for k in self._graph.links_of(child)]
            raise ConnectionError_(
                f"there is no connection from {parent.name} to {child.name}"
                + ("" if label is None else f" labelled {label!r}") + ": give the parent "
                "and the child as connected by System.connect; the connections of "
                f"{child.name} are: {'; '.join(known) or 'none'}.")
        if len(links) > 1:
            raise ConnectionError_(
                f"{len(links)} connections join {parent.name} to {child.name} (labels "
                f"{[k.label for k in links]}): give `label` to choose one.")
        return links[0]

    def _closure_actions(self):
        """[(link, [(lambda symbol, [(solid, unit torsor), ...] or None), ...]), ...]"""
        if "closure_actions" not in self._cache:
            lams = iter(self.multiplier_symbols())
            out = []
            for link, rows in self._closures:
                forces = closure_forces(link, meets=self._meets.get(id(link)))
                out.append((link, [(next(lams), f) for _, f in zip(rows, forces,
                                                                    strict=True)]))
            self._cache["closure_actions"] = out
        return self._cache["closure_actions"]

