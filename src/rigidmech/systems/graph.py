"""The graph of bodies, connections and actions (book, ch. 13.2, 14.2, 18.2).

A mechanism is a graph whose vertices are the solids (the reference, or ground, and the
bodies) and whose edges are the connections between them (ch. 13.2.1, the *graphe des
liaisons*). Statics, dynamics and vibrations all work on this graph; :class:`Mechanism`
holds it as a value:

* it is **immutable**: :meth:`Mechanism.with_body`, :meth:`Mechanism.with_connection` and
  :meth:`Mechanism.with_action` return a new graph, checked, and leave the old one as it was
  (a layer above keeps the current graph and may keep older ones as snapshots);
* it **validates** what enters it, with the same messages in every layer: one body per name,
  one frame per name, every body in the reference's frame tree, actions on bodies of the graph,
  gravity once;
* it knows its **structure**: a spanning tree of connections (a connection is in the tree
  when it joined two separate groups of solids at the time it was given; a connection between
  solids already joined closes a loop) and, for each connection not in the tree, the loop it
  closes (a cycle basis: the number of independent loops is :math:`\\gamma = N_c - N_b`,
  connections minus moving bodies, for a graph connected to the ground).

A connection is anything with the connection protocol: ``action_torsor(label)`` returning
(Torsor, unknowns) and ``allowed_motion(label)`` returning (kinematic Torsor, free
components) of the second solid relative to the first: the joints of the catalogue
(:mod:`rigidmech.actions.joints`, :mod:`rigidmech.actions.connections`),
:class:`~rigidmech.actions.RollingContact`, :class:`~rigidmech.actions.GearMesh`. Its degree
of mobility and of hyperstaticity are computed by :mod:`rigidmech.systems.mobility`.
"""

from __future__ import annotations

from collections import deque

from .._core.errors import ArgumentError, ArgumentTypeError, ConnectionError_
from ..actions import Action, Gravity
from ..kinematics import Solid
from ..vectors import Frame
from .mobility import analyse

__all__ = ["Mechanism", "Link"]


class Link:
    """One connection of a mechanism: the action of ``first`` on ``second`` goes through it.

    Parameters
    ----------
    first, second : Solid
        The two solids; the connection's action torsor is the action of ``first`` on
        ``second`` and its allowed motion that of ``second`` relative to ``first``.
    connection : object
        The connection (a joint of the catalogue, a rolling contact, a gear mesh, ...).
    label : str
        Suffix of the names of its unknowns (``X_label``, ...).

    Examples
    --------
    >>> import rigidmech as rm
    >>> R0 = rm.Frame("R0"); g = rm.kinematics.Solid("R0", R0)
    >>> b = rm.Body("b", frame=R0.rotated("R1", about=R0.k, angle=rm.coordinates("q")))
    >>> link = Link(g, b, rm.joints.Pivot(at=R0.origin, axis=R0.k), "1")
    >>> link.first.name, link.second.name, link.label
    ('R0', 'b', '1')
    """

    __slots__ = ("_first", "_second", "_connection", "_label")

    def __init__(self, first: Solid, second: Solid, connection, label: str):
        self._first, self._second = first, second
        self._connection, self._label = connection, str(label)

    first = property(lambda self: self._first, doc="The solid that exerts the action.")
    second = property(lambda self: self._second, doc="The solid that receives the action.")
    connection = property(lambda self: self._connection, doc="The connection.")
    label = property(lambda self: self._label, doc="Suffix of the unknowns' names.")

    def other(self, solid):
        """The end of the link that is not ``solid``."""
        return self._second if solid is self._first else self._first

    def __repr__(self):
        return (f"Link({self._first.name} -> {self._second.name}, "
                f"{type(self._connection).__name__}, label={self._label!r})")


def _check_connection(connection):
    if not callable(getattr(connection, "action_torsor", None)):
        raise ArgumentTypeError(
            "`connection` must have an action_torsor(label) method (a joint of rm.joints, a "
            "RollingContact, a GearMesh, a KnifeEdge, a FrictionContact); got "
            f"{type(connection).__name__}.")


class Mechanism:
    """The graph of a set of bodies in a reference: bodies, connections, actions (ch. 13.2).

    Parameters
    ----------
    reference : Frame
        The reference (the ground): the solid every other is placed relative to.

    Examples
    --------
    A four-bar linkage: three bodies, four pivots, one loop.

    >>> import rigidmech as rm
    >>> q1, q2, q3 = rm.coordinates("q1 q2 q3")
    >>> R0 = rm.Frame("R0"); k = R0.k
    >>> R1 = R0.rotated("R1", about=k, angle=q1)
    >>> B = R0.origin.moved("B", 2 * R1.i)
    >>> R2 = R1.rotated("R2", about=k, angle=q2, origin=B)
    >>> D = R0.point("D", 4, 0, 0)
    >>> R3 = R0.rotated("R3", about=k, angle=q3, origin=D)
    >>> crank, coupler, rocker = (rm.Body(n, frame=f) for n, f in
    ...                           [("crank", R1), ("coupler", R2), ("rocker", R3)])
    >>> C = B.moved("C", 3 * R2.i)
    >>> g = (Mechanism(R0)
    ...      .with_connection(R0, crank, rm.joints.Pivot(at=R0.origin, axis=k))
    ...      .with_connection(crank, coupler, rm.joints.Pivot(at=B, axis=k))
    ...      .with_connection(R0, rocker, rm.joints.Pivot(at=D, axis=k))
    ...      .with_connection(coupler, rocker, rm.joints.Pivot(at=C, axis=k)))
    >>> len(g.loops()), [link.label for link in g.closing_links()]
    (1, ['4'])
    >>> g.mobility(plane=k).mobility, g.mobility(plane=k).hyperstaticity
    (1, 0)
    """

    __slots__ = ("_reference", "_ground", "_bodies", "_links", "_actions")

    def __init__(self, reference: Frame):
        if not isinstance(reference, Frame):
            raise ArgumentTypeError(
                f"`reference` must be a Frame; got {type(reference).__name__}.")
        self._reference = reference
        self._ground = Solid(reference.name, frame=reference)
        self._bodies: tuple = ()
        self._links: tuple = ()
        self._actions: tuple = ()

    def _copy(self, **changes):
        new = object.__new__(Mechanism)
        for name in self.__slots__:
            setattr(new, name, changes.get(name, getattr(self, name)))
        return new

    # -- views ----------------------------------------------------------------------------
    reference = property(lambda self: self._reference, doc="The reference frame (ground).")
    ground = property(lambda self: self._ground, doc="The ground as a Solid.")
    bodies = property(lambda self: self._bodies, doc="The bodies, in the order they came.")
    links = property(lambda self: self._links, doc="The connections (:class:`Link`).")
    actions = property(lambda self: self._actions, doc="The given actions.")

    @property
    def solids(self) -> tuple:
        """The ground followed by the bodies."""
        return (self._ground, *self._bodies)

    def solid(self, s, argument: str = "solid") -> Solid:
        """The solid that ``s`` stands for: a body of the graph, or the reference frame for
        the ground.

        Raises
        ------
        ConnectionError\\_
            For a frame other than the reference.
        ArgumentTypeError
            For anything else than a Solid or a Frame.
        """
        if isinstance(s, Frame):
            if s != self._reference:
                raise ConnectionError_(
                    f"`{argument}` is the frame {s.name}; only the Galilean reference "
                    f"{self._reference.name} may stand for a solid. Pass a Body.")
            return self._ground
        if s is self._ground:
            return s
        if not isinstance(s, Solid):
            raise ArgumentTypeError(
                f"`{argument}` must be a Body or the Galilean frame; got {type(s).__name__}.")
        return s

    def contains(self, solid) -> bool:
        """Whether ``solid`` is the ground or one of the bodies (by identity)."""
        return solid is self._ground or any(solid is b for b in self._bodies)

    # -- building (each returns a new graph) ------------------------------------------------
    def check_body(self, body) -> None:
        """Raise ``ConnectionError_`` if ``body`` cannot join the graph: already in it, in
        another frame tree, a second body of the same name, or a different frame of a name
        already used."""
        if any(body is b for b in self._bodies):
            raise ConnectionError_(f"body {body.name} is already in the system.")
        if body.frame.root != self._reference.root:
            raise ConnectionError_(
                f"body {body.name} is attached to frame {body.frame.name} of another tree "
                f"than {self._reference.name}.")
        if any(b.name == body.name for b in self._bodies):
            raise ConnectionError_(
                f"two bodies named {body.name!r} in one system: give each body its own name "
                "(results and connection actions are reported by name).")
        known = {}
        for owner, frame in [(self._reference.name, self._reference),
                             *((b.name, b.frame) for b in self._bodies)]:
            f = frame
            while f is not None:
                known.setdefault(f.name, (f, owner))
                f = f.parent
        f = body.frame
        while f is not None:
            k = known.get(f.name)
            if k is not None and k[0] != f:
                raise ConnectionError_(
                    f"two different frames named {f.name!r} (of bodies {k[1]} and "
                    f"{body.name}) in one system: give each frame its own name.")
            f = f.parent

    def with_body(self, body) -> Mechanism:
        """A new graph with ``body`` added (not yet connected: a free body).

        Examples
        --------
        >>> import rigidmech as rm
        >>> R0 = rm.Frame("R0")
        >>> g = Mechanism(R0).with_body(rm.Body("b", frame=R0.translated(
        ...     "R1", R0.point("P", *rm.coordinates("x y z")))))
        >>> [b.name for b in g.bodies]
        ['b']
        """
        body = self.solid(body, "body")
        if body is self._ground:
            raise ConnectionError_("the Galilean reference is not a body to add.")
        self.check_body(body)
        return self._copy(_bodies=(*self._bodies, body))

    def with_connection(self, first, second, connection, *, label: str | None = None
                        ) -> Mechanism:
        """A new graph with ``connection`` between ``first`` and ``second`` (a body not yet
        in the graph is added). The action torsor of the connection is the action of
        ``first`` on ``second``.

        Parameters
        ----------
        first, second : Body or the reference Frame
        connection : object with ``action_torsor(label)``
        label : str, optional
            Suffix of the unknowns' names; default the connection's rank ``"1"``, ``"2"``...

        Raises
        ------
        ConnectionError\\_
            If ``first`` is ``second``, or a label is used twice, or a new body cannot join.

        Examples
        --------
        >>> import rigidmech as rm
        >>> R0 = rm.Frame("R0")
        >>> b = rm.Body("b", frame=R0.rotated("R1", about=R0.k, angle=rm.coordinates("q")))
        >>> g = Mechanism(R0).with_connection(R0, b, rm.joints.Pivot(at=R0.origin, axis=R0.k),
        ...                                   label="O")
        >>> g.links
        (Link(R0 -> b, Pivot, label='O'),)
        """
        first = self.solid(first, "first")
        second = self.solid(second, "second")
        _check_connection(connection)
        if first is second:
            raise ConnectionError_(
                f"`first` and `second` must be two different solids; got {first.name} twice.")
        label = str(len(self._links) + 1) if label is None else str(label)
        if any(link.label == label for link in self._links):
            raise ArgumentError(f"`label` must be unique; {label!r} is already used.")
        g = self
        for s in (first, second):
            if not g.contains(s):
                g = g.with_body(s)
        return g._copy(_links=(*g._links, Link(first, second, connection, label)))

    def check_action(self, action) -> None:
        """Raise if ``action`` cannot act on this graph: not an Action, already there, a
        second gravity, or acting on a body that is not in the graph."""
        if not isinstance(action, Action):
            raise ArgumentTypeError(
                f"`action` must be an Action (rm.gravity, rm.actions.Force, ...); got "
                f"{type(action).__name__}.")
        if any(a is action for a in self._actions):
            raise ConnectionError_(
                f"this action is already in the system: {action!r}; it would count twice.")
        present = [a for a in self._actions if isinstance(a, Gravity)]
        if isinstance(action, Gravity) and present:
            raise ConnectionError_(
                f"gravity is already acting on the system ({present[0]!r}); a second gravity "
                "would double the weights. Give one field (the sum, if several are meant).")
        for solid, _ in action.contributions(list(self.solids)):
            if not self.contains(solid):
                raise ConnectionError_(
                    f"`action` acts on body {solid.name}, which is not in the system: "
                    "connect (or add) the body before acting on it.")

    def with_action(self, action) -> Mechanism:
        """A new graph with ``action`` exerted on its bodies (checked by
        :meth:`check_action`).

        Examples
        --------
        >>> import rigidmech as rm
        >>> R0 = rm.Frame("R0")
        >>> len(Mechanism(R0).with_action(rm.gravity(-R0.j)).actions)
        1
        """
        self.check_action(action)
        return self._copy(_actions=(*self._actions, action))

    # -- structure --------------------------------------------------------------------------
    def links_of(self, solid) -> tuple:
        """The links that have ``solid`` at one end."""
        return tuple(k for k in self._links if k.first is solid or k.second is solid)

    def tree_links(self) -> tuple:
        """The links of a spanning tree (a forest if some bodies are not connected to the
        ground): each joined two separate groups of solids when it was given."""
        return self._structure()[0]

    def closing_links(self) -> tuple:
        """The links that are not in the spanning tree: each one closes a loop (examples: see
        :class:`Mechanism`)."""
        tree = self._structure()[0]
        return tuple(k for k in self._links if not any(k is x for x in tree))

    def carried_by(self, link) -> tuple:
        """The bodies a tree link carries: those cut off from the ground when the link is
        removed from the spanning tree (its subtree), in the order of :attr:`bodies`.

        Examples
        --------
        >>> import rigidmech as rm
        >>> R0 = rm.Frame("R0"); q1, q2 = rm.coordinates("q1 q2")
        >>> R1 = R0.rotated("R1", about=R0.k, angle=q1)
        >>> R2 = R1.rotated("R2", about=R0.k, angle=q2, origin=R0.origin.moved("A", R1.i))
        >>> a, b = rm.Body("a", frame=R1), rm.Body("b", frame=R2)
        >>> g = (Mechanism(R0).with_connection(R0, a, rm.joints.Pivot(at=R0.origin, axis=R0.k))
        ...      .with_connection(a, b, rm.joints.Pivot(at=R2.origin, axis=R0.k)))
        >>> [x.name for x in g.carried_by(g.links[0])], [x.name for x in g.carried_by(g.links[1])]
        (['a', 'b'], ['b'])
        """
        tree = [k for k in self.tree_links() if k is not link]
        if len(tree) == len(self.tree_links()):
            raise ConnectionError_(
                f"`link` {link!r} is not in the spanning tree: it closes a loop and carries "
                "no subtree.")
        reached = {id(self._ground)}
        queue = deque([self._ground])
        while queue:
            s = queue.popleft()
            for k in tree:
                if k.first is s or k.second is s:
                    o = k.other(s)
                    if id(o) not in reached:
                        reached.add(id(o))
                        queue.append(o)
        return tuple(b for b in self._bodies if id(b) not in reached)

    def loops(self) -> tuple:
        """A basis of independent loops (cycles), one per closing link: each loop is a tuple
        of (link, sign) in the order they are met going round from the closing link's
        ``first`` solid; sign +1 when the link is travelled from ``first`` to ``second``.

        Examples
        --------
        >>> import rigidmech as rm
        >>> R0 = rm.Frame("R0"); th = rm.coordinates("theta")
        >>> shaft = rm.Body("shaft", frame=R0.rotated("R1", about=R0.k, angle=th))
        >>> g = (Mechanism(R0)
        ...      .with_connection(R0, shaft, rm.joints.Pivot(at=R0.origin, axis=R0.k))
        ...      .with_connection(R0, shaft, rm.joints.Pivot(at=R0.point("B", 0, 0, 1),
        ...                                                  axis=R0.k)))
        >>> [[(k.label, s) for k, s in loop] for loop in g.loops()]
        [[('2', 1), ('1', -1)]]
        """
        tree, parent = self._structure()
        out = []
        for closing in self.closing_links():
            a, b = closing.first, closing.second
            path_a = self._path_to_root(a, parent)   # [(solid, link to its parent)]
            path_b = self._path_to_root(b, parent)
            ids_a = [id(s) for s, _ in path_a]
            common = next(s for s, _ in path_b if id(s) in ids_a)
            up_b = []
            for s, link in path_b:
                if s is common:
                    break
                up_b.append((s, link))
            down_a = []
            for s, link in path_a:
                if s is common:
                    break
                down_a.append((s, link))
            loop = [(closing, 1)]          # a -> b
            for s, link in up_b:           # b -> ... -> common
                loop.append((link, 1 if link.first is s else -1))
            for s, link in reversed(down_a):  # common -> ... -> a
                loop.append((link, 1 if link.second is s else -1))
            out.append(tuple(loop))
        return tuple(out)

    def _path_to_root(self, s, parent):
        path = []
        while True:
            link = parent.get(id(s))
            path.append((s, link))
            if link is None:
                return path
            s = link.other(s)

    def _structure(self):
        # the tree: the links that joined two separate groups of solids when they were given
        # (Kruskal's rule in the order of the links); the others close loops
        group = {id(x): id(x) for x in (self._ground, *self._bodies)}

        def find(x):
            while group[x] != x:
                group[x] = group[group[x]]
                x = group[x]
            return x

        tree = []
        for link in self._links:
            a, b = find(id(link.first)), find(id(link.second))
            if a != b:
                group[a] = b
                tree.append(link)
        # parent links from the ground (or from the first body of a floating group)
        parent = {}
        for root in (self._ground, *self._bodies):
            if id(root) in parent:
                continue
            parent[id(root)] = None
            queue = deque([root])
            while queue:
                s = queue.popleft()
                for link in tree:
                    if link.first is s or link.second is s:
                        o = link.other(s)
                        if id(o) not in parent:
                            parent[id(o)] = link
                            queue.append(o)
        return tuple(tree), parent

    def mobility(self, plane=None, values=None, *, seed: int = 0):
        """The degree of mobility and of hyperstaticity of the mechanism (ch. 13.2, 14.2):
        see :func:`rigidmech.systems.mobility.analyse`."""
        return analyse(self, plane=plane, values=values, seed=seed)

    def __repr__(self):
        return (f"Mechanism(reference={self._reference.name}, "
                f"bodies={[b.name for b in self._bodies]}, links={len(self._links)}, "
                f"actions={len(self._actions)})")
