"""A set of bodies, their connections and actions; the fundamental principle of dynamics
(book, ch. 18, 20).

:class:`System` collects bodies joined in a tree by connections (ch. 13.2) and the actions
exerted on them. It derives, on demand and each only once:

* the equations of motion M(q) q'' = f(q, q', t), free of connection unknowns (ch. 20.2,
  25.1.4): the fundamental principle written for each body, {D(S/R)} = {A(ext -> S)}, is
  combined with weights given by the partial kinematic torsors {V_i(S/R)} = d{V(S/R)}/dq_i'.
  The actions of perfect connections have zero power coefficients and drop out, leaving
  for each parameter of situation q_i

  .. math:: \\sum_S \\{\\mathcal{D}(S/R)\\}\\cdot\\{\\mathcal{V}_i(S/R)\\}
            = \\sum_S \\{\\mathcal{A}(\\bar S \\to S)\\}\\cdot\\{\\mathcal{V}_i(S/R)\\},

  where the dot is the comoment. The mass matrix is assembled directly from the partial
  velocities (M_ij = sum m V_i.V_j + Omega_i.J_G(Omega_j)), never extracted from an
  expanded expression, and every vector of a body is kept in the body's own basis: the cost
  grows polynomially with the number of bodies (no expression swell);
* the action in one connection (ch. 18.2), only when asked: the fundamental principle for the
  set of bodies carried by that connection.

Where each concern lives (the methods of :class:`System` carry the documentation and
delegate to functions of private modules):

* this module: the system's state, its public methods and read-only views;
* :mod:`rigidmech.dynamics._tree`: the tree of bodies and coordinates (which connection moves
  each coordinate, their order) and how :meth:`System.connect` files a connection: a tree
  joint, a linking connection (closing joint, rolling contact, gear mesh, knife edge: its
  condition rows) or a one-sided contact with friction;
* :mod:`rigidmech.dynamics.linked`: what the linking connections give once filed (closure
  conditions, constraints, loops, mobility, assembly, Lagrange multipliers), a base class;
* :mod:`rigidmech.dynamics.reference`: the reference, Galilean or not, and its inertial
  actions;
* :mod:`rigidmech.dynamics._derivation`: partial velocities, mass matrix and forcing,
  energies, generalized forces, constants of the model;
* :mod:`rigidmech.dynamics._connection_actions`: the connection actions, on demand.
"""

from __future__ import annotations

import math

from .._core.errors import ArgumentError, ConnectionError_
from ..actions import Action
from ..kinetics import Body
from ..systems import Mechanism
from ..torsors import Torsor
from ..vectors import Frame
from ..vectors.points import check_point
from ..vectors.symbols import is_coordinate
from . import _connection_actions, _derivation, _tree
from ._singularities import orientation_singularities
from .equations import EquationsOfMotion
from .linked import LinkedParameters
from .reference import check_inertial_action, resolve_reference

__all__ = ["System"]


def _checked_stabilization(value):
    """Baumgarte's (alpha, beta) as two finite floats >= 0 (the residuals obey
    c' + 2 alpha c + beta^2 Phi = 0: damped for alpha >= 0)."""
    try:
        alpha, beta = (float(x) for x in value)
    except (TypeError, ValueError):
        alpha = beta = math.nan
    if not (math.isfinite(alpha) and math.isfinite(beta) and alpha >= 0 and beta >= 0):
        raise ArgumentError(
            "`stabilization` must be two finite numbers >= 0 (alpha, beta), Baumgarte's "
            f"rates in 1/time; got {value!r}. Pass for example (5.0, 5.0), or (0.0, 0.0) "
            "for no stabilization.")
    return (alpha, beta)


class System(LinkedParameters):
    """A set of rigid bodies in a reference, their connections and actions.

    Parameters
    ----------
    galilean : Frame
        The Galilean reference R0 (ch. 18.1.2). It must not move relative to the root frame
        of its tree (a frame rotating or translating with a coordinate or with time is
        refused with :class:`~rigidmech.errors.FrameError`: pass it as ``reference``).
        Optional when ``reference`` is an :class:`~rigidmech.kinetics.EarthReference`.
    coordinates : sequence of q(t), optional
        The parameters of situation, in the order of the equations. Default: those found in
        the bodies, in the order of :attr:`coordinates`.
    reference : Frame or EarthReference, optional
        A reference R whose motion relative to ``galilean`` is prescribed (it may depend on
        time, not on the parameters of situation): a turntable, a wagon, the Earth
        (:func:`~rigidmech.kinetics.earth_reference`). The system is then written relative
        to R (ch. 19, 24): bodies are connected to R, velocities, kinetic energy, equations
        of motion and connection actions are relative to R, and the inertial actions of
        entrainment and Coriolis (:class:`~rigidmech.kinetics.InertialActions`) are among
        its :attr:`actions`. Default: ``galilean`` itself.
    stabilization : (alpha, beta), optional
        Baumgarte's rates (in 1/time, finite, >= 0) with which the compiled equations of a
        system with linking connections damp the drift off the constraints (see
        :class:`~rigidmech.dynamics.Constraints`); (0, 0) for none.

    Notes
    -----
    Every result is written with the user's parameters of situation q(t) (made with
    :func:`rigidmech.coordinates`, or ``sympy.physics.mechanics.dynamicsymbols``), their
    derivatives ``q.diff(t)`` and the constants: ``subs``, evaluation along a simulation and
    compilation accept them (one symbol world).

    Examples
    --------
    >>> import rigidmech as rm
    >>> q = rm.coordinates("q"); m, L, g = rm.constants("m L g", positive=True)
    >>> R0 = rm.Frame("R0"); R1 = R0.rotated("R1", about=R0.k, angle=q)
    >>> G = R0.origin.moved("G", L / 2 * R1.i)
    >>> bar = rm.Body("bar", frame=R1, mass=m, centre=G,
    ...               inertia=rm.inertia.rod(m, L, axis=R1.i, centre=G))
    >>> system = System(galilean=R0)
    >>> system.connect(R0, bar, rm.joints.Pivot(at=R0.origin, axis=R0.k))
    >>> system.act(rm.gravity(g * R0.i))
    >>> eqs = system.equations_of_motion()
    >>> eqs.mass_matrix, eqs.forcing
    (Matrix([[L**2*m/3]]), Matrix([[-L*g*m*sin(q(t))/2]]))
    >>> eqs.forcing.subs(q, 0)
    Matrix([[0]])
    """

    def __init__(self, galilean: Frame | None = None, coordinates=None, *, reference=None,
                 stabilization=(5.0, 5.0)):
        # the reference of the equations (the Galilean one unless `reference` is given),
        # the inertial actions to add and the Galilean reference
        frame, inertial, self._inertial_frame = resolve_reference(galilean, reference)
        self._galilean = frame
        # the graph of bodies, connections and actions (validated there)
        self._graph = Mechanism(frame)
        if inertial is not None:
            self._graph = self._graph.with_action(inertial)
        # coordinate owners (coordinate -> (body, owner)): a dynamics-specific check
        self._owners: dict = {}
        self._joints: dict = {}  # child body -> (parent solid, joint): the tree joints
        self._closures: list = []  # (link, rows): connections that link parameters
        self._meets: dict = {}  # id(link) -> the point of the child that closes a loop
        self._stabilization = _checked_stabilization(stabilization)
        self._given_coordinates = None
        if coordinates is not None:
            coords = tuple(coordinates)
            bad = [c for c in coords if not is_coordinate(c)]
            if bad:
                raise ArgumentError(
                    f"`coordinates` must be parameters of situation q(t) made with "
                    f"rm.coordinates; got {bad}.")
            self._given_coordinates = coords
        self._cache: dict = {}
        # declaration ranks of the coordinates when their body joined the system: a name
        # declared again afterwards does not reorder this system's coordinates
        self._ranks: dict = {}
        self._contacts: list = []  # (parent, child, contact): one-sided contacts (regimes)

    # -- building -----------------------------------------------------------------------
    @property
    def _ground(self):
        return self._graph.ground

    @property
    def _bodies(self):
        return self._graph.bodies

    @property
    def _actions(self):
        return self._graph.actions

    @property
    def mechanism(self) -> Mechanism:
        """The graph of bodies, connections and actions (a snapshot: an immutable
        :class:`~rigidmech.systems.Mechanism`), for its loops, mobility and hyperstaticity.

        Examples
        --------
        >>> import rigidmech as rm
        >>> R0 = rm.Frame("R0"); s = System(galilean=R0)
        >>> s.connect(R0, rm.Body("b", frame=R0.rotated("R1", about=R0.k,
        ...                                             angle=rm.coordinates("q"))),
        ...           rm.joints.Pivot(at=R0.origin, axis=R0.k))
        >>> s.mechanism.mobility(plane=R0.k).mobility
        1
        """
        return self._graph

    def add(self, body: Body) -> None:
        """Add a body that is not connected to anything (a free body, ch. 18.4).

        Raises
        ------
        ConnectionError\\_
            If the body, a body of the same name, or a different frame of the same name is
            already in the system, or if one of its coordinates is already moved by a
            connection or another free body.

        Examples
        --------
        >>> import rigidmech as rm
        >>> R0 = rm.Frame("R0"); s = System(galilean=R0)
        >>> P = R0.point("P", *rm.coordinates("x y z"))
        >>> s.add(rm.Body("b", frame=R0.translated("R1", P), mass=1))
        >>> len(s.bodies)
        1
        """
        _tree.add(self, body)

    def connect(self, parent, child, joint, *, meets=None, label: str | None = None
                ) -> None:
        """Connect ``child`` to ``parent`` (a Body or the Galilean frame) by ``joint``.

        * A joint of the catalogue that gives ``child`` its first connection is a tree
          joint: it is checked against the frames (the relative motion of the child must be
          one the joint allows, ch. 13.2.2) and the coordinates of the child that are not its
          parent's become this connection's.
        * A joint between two solids already connected **closes a loop** (a four-bar, a
          shaft in two bearings): its conditions are written between the existing
          parameters (:func:`rigidmech.systems.closure_conditions`): the point ``joint.at``
          of ``parent`` and the point ``meets`` of ``child`` (default: the same point) must
          coincide along the directions the joint blocks. The equations of motion then carry
          Lagrange multipliers (:mod:`rigidmech.dynamics.constraints`).
        * A :class:`~rigidmech.actions.RollingContact`, :class:`~rigidmech.actions.GearMesh`
          or :class:`~rigidmech.actions.KnifeEdge` adds its velocity constraints (holonomic or
          not) the same way; if ``child`` is new its coordinates become this connection's.

        Each parameter of situation belongs to one connection: the coordinates of the
        child's frame and mass centre that are not its parent's are those of this connection,
        and must not be moved by another one (the same q in two bodies hanging from the
        ground would be counted twice).

        Parameters
        ----------
        parent, child : Body or the Galilean Frame (parent only)
        joint : a joint of ``rm.joints``, a RollingContact, a GearMesh, a KnifeEdge or a
            FrictionContact
        meets : Point or Frame, optional
            For a joint closing a loop: the point of ``child`` that meets ``joint.at``; or a
            frame of ``child`` whose origin meets ``joint.at`` and whose axes (i, j, k) meet
            the joint's basis (u, v, w) when the loop is closed, needed when the joint blocks
            a relative rotation that the frames do not (a spatial loop).
        label : str, optional
            Name of the connection in the graph (suffix of its unknowns); default its rank.

        Raises
        ------
        ConnectionError\\_
            For a parent not yet in the system, a second body or a different frame with a
            name already used, a coordinate already moved by another connection, a loop
            closed between points that cannot coincide, or a rolling contact or gear mesh
            between other solids than ``parent`` and ``child``.

        Examples
        --------
        A four-bar linkage: crank, coupler and rocker, the loop closed at C.

        >>> import rigidmech as rm
        >>> q1, q2, q3 = rm.coordinates("q1 q2 q3")
        >>> R0 = rm.Frame("R0"); k = R0.k
        >>> R1 = R0.rotated("R1", about=k, angle=q1)
        >>> R2 = R1.rotated("R2", about=k, angle=q2, origin=R0.origin.moved("B", R1.i))
        >>> R3 = R0.rotated("R3", about=k, angle=q3, origin=R0.point("D", 2, 0, 0))
        >>> crank, coupler, rocker = (rm.Body(n, frame=f, mass=1) for n, f in
        ...                           [("crank", R1), ("coupler", R2), ("rocker", R3)])
        >>> s = System(galilean=R0)
        >>> s.connect(R0, crank, rm.joints.Pivot(at=R0.origin, axis=k))
        >>> s.connect(crank, coupler, rm.joints.Pivot(at=R2.origin, axis=k))
        >>> s.connect(R0, rocker, rm.joints.Pivot(at=R3.origin, axis=k))
        >>> s.connect(coupler, rocker, rm.joints.Pivot(at=R2.origin.moved("C", 2 * R2.i),
        ...           axis=k), meets=R3.origin.moved("C3", 1.5 * R3.i))
        >>> [c[0] for c in s.closure_conditions()]
        ['4.u', '4.v']
        """
        _tree.connect(self, parent, child, joint, meets, label)

    @property
    def contacts(self) -> tuple:
        """The one-sided contacts with friction ``(parent, child, contact)`` (see
        :class:`~rigidmech.actions.FrictionContact`), in the order they were connected.
        Their actions depend on the regime: they are in none of the system's derivations
        (equations of motion, connection actions), only in
        :func:`rigidmech.regimes.contact_motion` (which gives them along the motion)."""
        return tuple(self._contacts)

    def act(self, action: Action) -> None:
        """Add an external or internal action (gravity, force, couple, spring, ...).

        Raises
        ------
        ConnectionError\\_
            If the action is already in the system, if it is a second gravity, or if it acts
            on a body that is not in the system (connect the body first), or inertial actions
            given to a system whose ``reference`` already adds them.
        """
        check_inertial_action(self, action)
        self._graph = self._graph.with_action(action)
        self._cache.clear()

    # -- read-only views ----------------------------------------------------------------
    @property
    def galilean(self) -> Frame:
        """The Galilean reference (ch. 18.1.2)."""
        return self._inertial_frame

    @property
    def reference(self) -> Frame:
        """The reference the equations are written in: :attr:`galilean` unless the system
        was given a moving ``reference`` (ch. 19)."""
        return self._galilean

    @property
    def bodies(self) -> tuple:
        """The bodies, in the order they were added."""
        return tuple(self._bodies)

    @property
    def actions(self) -> tuple:
        """The actions exerted on the bodies."""
        return tuple(self._actions)

    @property
    def coordinates(self) -> tuple:
        """The parameters of situation q(t) in the order of the equations.

        Unless given to the constructor, they come in the order they were declared with
        :func:`rigidmech.coordinates` (by call, then by position in the call; a name
        declared again takes the rank of its latest declaration *before its body joined the
        system*: declaring it again later does not reorder an existing system; see
        :func:`rigidmech.vectors.declared_order`). Functions of time made otherwise
        (``sympy.physics.mechanics.dynamicsymbols``) come after them, in the order they are
        met: body by body in the order the bodies were added or connected; for a body,
        along its frame's chain from the Galilean root down, for each frame first the
        coordinates of its origin (x, y, z) and then its rotation angle; then the body's
        centre of mass; coordinates met in one expression by name (q2 before q10). The
        order is fixed when first asked.

        Examples
        --------
        >>> import rigidmech as rm
        >>> x, y, z, psi, theta, phi = rm.coordinates("x y z psi theta phi")
        >>> R0 = rm.Frame("R0"); G = R0.point("G", x, y, z)
        >>> s = System(galilean=R0)
        >>> s.add(rm.Body("b", frame=R0.euler("R", psi, theta, phi, origin=G), mass=1,
        ...               centre=G))
        >>> s.coordinates
        (x(t), y(t), z(t), psi(t), theta(t), phi(t))
        """
        return _tree.ordered_coordinates(self)

    # -- derivations --------------------------------------------------------------------
    def _contributions(self):
        """The actions' contributions (solid, torsor, action) on the bodies (cached)."""
        return _derivation.contributions(self)

    def _partials(self, solid, point):
        """Partial kinematic torsor elements (Omega_i, V_i(point)) of ``solid`` for each
        parameter q_i (ch. 25.1.2; cached)."""
        return _derivation.partials(self, solid, point)

    def action_contributions(self) -> tuple:
        """The given actions' torsors on the bodies, as the equations of motion use them:
        ``(body, torsor, action)`` for each body an action is exerted on (the ground left
        out; ch. 11, 25.1.3). Read-only (a tuple).

        Examples
        --------
        >>> from rigidmech import models
        >>> [(b.name, type(a).__name__, T.resultant) for b, T, a in
        ...  models.compound_pendulum().system.action_contributions()]
        [('bar', 'Gravity', g*m*R0.i)]
        """
        return tuple(self._contributions())

    def partial_kinematic_torsors(self, body, point=None) -> tuple:
        """The partial kinematic torsors {V_i(S/R)} = {Omega_i ; V_i(P)} of ``body``, one per
        parameter q_i in the order of :attr:`coordinates`, reduced at ``point`` (default the
        body's mass centre): the derivatives of its kinematic torsor with respect to q_i'
        (ch. 25.1.2), as the equations of motion use them.

        Raises
        ------
        ArgumentError
            If ``body`` is not a body of the system.

        Examples
        --------
        >>> from rigidmech import models
        >>> pendulum = models.compound_pendulum()
        >>> (V,) = pendulum.system.partial_kinematic_torsors(pendulum.body("bar"))
        >>> V.resultant, V.moment
        (R0.k, L/2*R1.j)
        """
        if not isinstance(body, Body) or body not in self._bodies:
            raise ArgumentError(
                f"`body` must be a body of this system "
                f"({', '.join(b.name for b in self._bodies) or 'none'}); got {body!r}.")
        point = body.centre if point is None else point
        check_point(point, "point")
        return tuple(Torsor(W, V, point) for W, V in self._partials(body, point))

    def meets(self, link):
        """The point (or frame) of the second solid given as ``meets`` when ``link`` (one of
        :attr:`mechanism`'s links) was connected to close a loop (ch. 25.3); None when it
        was not given (the joint's own point then closes the loop).

        Examples
        --------
        >>> from rigidmech import models
        >>> s = models.four_bar().system
        >>> [(k.label, getattr(s.meets(k), "name", None)) for k in s.mechanism.links]
        [('1', None), ('2', None), ('3', None), ('4', 'C3')]
        """
        if not any(link is k for k in self._graph.links):
            raise ArgumentError(
                f"`link` must be one of this system's links (system.mechanism.links); got "
                f"{link!r}.")
        return self._meets.get(id(link))

    def equations_of_motion(self, *, open_contacts: bool = False) -> EquationsOfMotion:
        """The equations of motion M(q) q'' = f(q, q', t), free of connection unknowns,
        written with the coordinates q(t) and their derivatives.

        A system with one-sided contacts with friction (:attr:`contacts`) has no single set
        of equations: they change with the contacts' regimes (use
        :func:`rigidmech.regimes.contact_motion`). It is refused unless ``open_contacts`` is
        True, which gives the equations with every such contact open (no contact action).

        Derived once and cached; no connection action is derived (each quantity
        on demand). Nothing is simplified: ask for it on the result if wanted. The result
        is a snapshot: changing the system afterwards (``act``, ``connect``) leaves it as it
        is, its energy included.
        """
        return _derivation.equations_of_motion(self, open_contacts)

    @property
    def parameters(self) -> tuple:
        """The constant symbols of the model (masses, inertia, lengths of the bodies and
        frames, constants of the actions), sorted by name. The equations of motion depend on
        some of them (:attr:`EquationsOfMotion.parameters`); values given for the others are
        accepted and ignored with a note.

        Examples
        --------
        >>> import rigidmech as rm
        >>> x = rm.coordinates("x"); m, a = rm.constants("m a", positive=True)
        >>> R0 = rm.Frame("R0"); P = R0.point("P", x, a, 0)
        >>> s = System(galilean=R0)
        >>> s.add(rm.Body("b", frame=R0.translated("R1", P), mass=m, centre=P))
        >>> s.parameters, s.equations_of_motion().parameters
        ((a, m), (m,))
        """
        return _derivation.parameters(self)

    def mechanical_energy(self):
        """Total mechanical energy T + V with q(t), q'(t), or None if an action has no
        potential."""
        return _derivation.mechanical_energy(self)

    def kinetic_energy(self):
        """Kinetic energy of the set of bodies relative to the reference of the equations
        (:attr:`reference`, the Galilean one by default; ch. 16.3.3), in terms of q(t) and
        q'(t)."""
        return _derivation.kinetic_energy_of(self)

    def generalized_forces(self):
        """Power coefficients Q_i of the given actions (ch. 25.1.3), with q(t), q'(t): the
        power of the actions is sum Q_i q_i'."""
        return _derivation.generalized_forces(self)

    def orientation_singularities(self) -> tuple:
        """The singular sets of the angles orienting the bodies (book, ch. 9.1.2): for each
        body frame whose angles relative to the nearest frame it is built from (the Galilean
        frame, another body's frame or the root) have one, an
        :class:`~rigidmech.vectors.OrientationSingularity`. Simulations warn near them.

        Examples
        --------
        >>> import rigidmech as rm
        >>> psi, theta, phi = rm.coordinates("psi theta phi")
        >>> R0 = rm.Frame("R0"); R = R0.euler("R", psi, theta, phi)
        >>> system = System(galilean=R0)
        >>> system.add(rm.Body("b", frame=R, mass=1))
        >>> system.orientation_singularities()[0].condition
        Eq(sin(theta(t)), 0)
        """
        return orientation_singularities(tuple(self._bodies), self._galilean)

    def symbols(self):
        """Plain symbols (q, q_dot, q_ddot) for the coordinates and their first two
        derivatives, and the rule that replaces q(t) and its derivatives by them, for whoever
        wants expressions in plain symbols: ``expr.xreplace(rule)``. rigidmech's own results
        keep q(t)."""
        return _derivation.symbols(self)

    # -- connection actions -------------------------------------------------------------
    def connection_action(self, parent, child, *, label=None) -> Torsor:
        """The action exerted by ``parent`` on ``child`` through their connection (ch. 18.2),
        reduced at the joint's point.

        Derived only now, from the fundamental principle for the bodies carried by the
        connection: {A(parent -> child)} = sum over the carried bodies of their dynamic
        torsors minus the other actions exerted on them. Like every torsor of rigidmech it is
        written with the parameters of situation q(t) and their derivatives; for its
        components in the joint's basis, use :meth:`connection_components`.

        In a system with linking connections (loops, rolling, gears) the actions of those
        connections are written with their Lagrange multipliers (:meth:`multiplier_symbols`,
        values from :meth:`multipliers`): the action of a loop-closing joint is
        sum lambda_i e_i at its point, plus the components along the motions it blocks that
        the frames already block (a linear annular bearing on the axis of a rotor held by a
        ball joint): those are solved from the components the tree joints cannot transmit
        (ch. 14.2), and the actions of the other connections include all these actions on
        the bodies they carry. In a hyperstatic mounting (a shaft on two pivots) the split
        of the action between the redundant connections is not determined by the equations
        (see :meth:`mobility`): the one given takes the undetermined components of the
        closing connection zero (nothing, for a second coaxial pivot),
        :meth:`hyperstatic_unknowns` names them, and an action that depends on them issues a
        :class:`~rigidmech.errors.HyperstaticWarning` naming them (the planar four-bar of
        spatial pivots: its out-of-plane components).

        Parameters
        ----------
        parent, child : Body or the Galilean Frame
        label : str, optional
            The connection's label, when several connections join the same two solids.

        Examples
        --------
        >>> import rigidmech as rm
        >>> q = rm.coordinates("q"); m, L, g = rm.constants("m L g", positive=True)
        >>> R0 = rm.Frame("R0"); R1 = R0.rotated("R1", about=R0.k, angle=q)
        >>> G = R0.origin.moved("G", L * R1.i)
        >>> s = System(galilean=R0)
        >>> s.connect(R0, rm.Body("bob", frame=R1, mass=m, centre=G),
        ...           rm.joints.Pivot(at=R0.origin, axis=R0.k))
        >>> s.act(rm.gravity(g * R0.i))
        >>> s.connection_action(R0, s.bodies[0]).resultant
        -L*m*Derivative(q(t), t)**2*R1.i + L*m*Derivative(q(t), (t, 2))*R1.j - g*m*R0.i

        The resultant as a vector of R0 and the moment at another point A, in any frame
        (:meth:`~rigidmech.vectors.Vector.express`, :meth:`~rigidmech.vectors.Vector.components`,
        :meth:`~rigidmech.torsors.Torsor.moment_at`); along a motion,
        :meth:`Simulation.connection_action` with ``basis`` and ``at``:

        >>> A = R0.point("A", 0, 1, 0)
        >>> action = s.connection_action(R0, s.bodies[0])
        >>> action.resultant.express(R0).components(R0)[0]
        -L*m*sin(q(t))*Derivative(q(t), (t, 2)) - L*m*cos(q(t))*Derivative(q(t), t)**2 - g*m
        >>> M_A = action.moment_at(A).components(R0)      # M(A) = M(O) + R x OA
        >>> M_A[0], M_A[1]
        (0, 0)
        """
        return _connection_actions.connection_action(self, parent, child, label)

    def hyperstatic_unknowns(self) -> tuple:
        """The names (``<label>.<component>``) of the components of the actions of the
        loop-closing joints that the fundamental principle does not determine: the degree of
        hyperstaticity of those joints' blocked motions that the frames already block, taken
        zero by :meth:`connection_action`, which says so by a
        :class:`~rigidmech.errors.HyperstaticWarning` (ch. 14.2). Empty for an isostatic
        loop.

        Examples
        --------
        A shaft in two coaxial pivots: the load is shared between them in a way the
        equations do not tell.

        >>> import rigidmech as rm
        >>> R0 = rm.Frame("R0"); Rr = R0.rotated("Rr", about=R0.i, angle=rm.coordinates("q"))
        >>> s = System(galilean=R0); shaft = rm.Body("shaft", frame=Rr, mass=1)
        >>> s.connect(R0, shaft, rm.joints.Pivot(at=R0.origin, axis=R0.i), label="A")
        >>> s.connect(R0, shaft, rm.joints.Pivot(at=R0.point("B", 1, 0, 0), axis=R0.i),
        ...           label="B")
        >>> s.hyperstatic_unknowns()
        ('B.X', 'B.Y', 'B.Z', 'B.L', 'B.M')
        """
        return _connection_actions.hyperstatic_unknowns(self)

    def connection_components(self, parent, child, *, label=None) -> dict:
        """The components (X, Y, Z, L, M, N) of the action of ``parent`` on ``child`` in the
        joint's local basis (u, v, w), moment at the joint's point, written with q(t), q'(t)
        and q''(t) (evaluate them along a motion with :meth:`Simulation.evaluate`). For a
        perfect joint the components it cannot transmit (N for a pivot) vanish once q''
        satisfies the equations of motion.
        """
        return _connection_actions.connection_components(self, parent, child, label)

    def joint(self, child):
        """The (parent solid, joint) of a body."""
        child = _tree.solid(self, child, "child")
        if child not in self._joints:
            raise ConnectionError_(f"body {child.name} has no parent connection.")
        return self._joints[child]

    def __repr__(self):
        moving = ("" if self._galilean is self._inertial_frame
                  else f", reference={self._galilean.name}")
        return (f"System(galilean={self._inertial_frame.name}{moving}, "
                f"bodies={[b.name for b in self._bodies]}, actions={len(self._actions)})")
