"""Equilibrium of a rigid body or a set of rigid bodies at rest (book, ch. 14.2).

The law of statics (ch. 14.2.1-14.2.2): a set of bodies is at rest in a Galilean reference
only if, for each body S, the torsor of the actions exerted on S by everything else is zero,

.. math:: \\{\\mathcal{A}(\\bar S\\to S)\\} = \\{0\\}
          \\iff \\mathbf{R}(\\bar S\\to S) = \\mathbf{0},\\quad
          \\mathbf{M}_O(\\bar S\\to S) = \\mathbf{0},

six scalar equations per body, linear in the unknown components of the connection actions
(ch. 13.2). :class:`Statics` collects the bodies, their connections (the joints of
:mod:`rigidmech.actions.joints`, the contacts of :mod:`rigidmech.actions.contact_laws`, or
anything with an ``action_torsor(label)``), the given actions (forces, couples, gravity,
springs, distributed loads) and writes these equations; :meth:`Statics.solve` solves them:

* the **rank** r of the equations in the n unknowns; the **degree of hyperstaticity**
  h = n - r and the unknowns that remain undetermined (ch. 13.2, 14.2);
* the **conditions** the given actions must satisfy: combinations of the equations that no
  unknown enters. A system with such equations is a **mechanism** for a general load; with
  numbers that violate them there is no equilibrium and :class:`EquilibriumError` is raised,
  naming the equations; with symbols they are reported (``Equilibrium.conditions``), and a
  load made unknown (``solve(unknowns=[P])``) is the one that holds the mechanism at rest.

The path is symbolic (``sympy``: independent equations by row reduction, then
``sympy.linsolve``) when symbols remain, numeric (``numpy``: rank and null space by SVD,
least squares) when only numbers do.
"""

from __future__ import annotations

from typing import NamedTuple

import sympy as sp

from .._core.errors import ArgumentError, ArgumentTypeError
from .._core.validation import substitutions
from ..actions import Action
from ..kinematics import Solid
from ..torsors import Torsor, torsor_of_field
from ..vectors import Frame
from .limits import Limit, limiting_equilibrium
from .solution import Equilibrium, _solve_numeric, _solve_symbolic

__all__ = ["Statics", "StaticsConnection"]

_COMPONENTS = ("resultant along i", "resultant along j", "resultant along k",
               "moment about i", "moment about j", "moment about k")


def _check_body(s, argument):
    if not isinstance(s, Solid | Frame):
        raise ArgumentTypeError(
            f"`{argument}` must be a Body (or a Frame for the fixed ground); got "
            f"{type(s).__name__}.")


class StaticsConnection(NamedTuple):
    """A connection of a :class:`Statics` as given to :meth:`Statics.connect`: its two ends,
    the connection, its label, its action torsor (of ``first`` on ``second``) and the
    unknowns of that torsor."""

    first: object
    second: object
    connection: object
    label: str
    torsor: Torsor
    unknowns: tuple


class Statics:
    """Bodies at rest in the reference ``reference``, their connections and loads (ch. 14).

    Parameters
    ----------
    reference : Frame
        The Galilean reference (the ground). Frames given as an end of a connection are fixed:
        no equation is written for them.

    Examples
    --------
    A beam of length L on a pivot at A and a roller at B, a load F at x = c:

    >>> import rigidmech as rm
    >>> from rigidmech.actions import ContactLaws, Force, Pivot
    >>> L, c, F = rm.constants("L c F", positive=True)
    >>> R0 = rm.Frame("R0"); A = R0.origin; B = R0.point("B", L, 0, 0)
    >>> beam = rm.Body("beam", frame=R0)
    >>> st = Statics(R0)
    >>> st.connect(R0, beam, Pivot(at=A, axis=R0.k), label="A")
    >>> st.connect(R0, beam, ContactLaws(at=B, normal=R0.j), label="B")
    >>> st.act(Force(on=beam, vector=-F * R0.j, at=R0.point("C", c, 0, 0)))
    >>> eq = st.solve()
    >>> eq.values[sp.Symbol("N_B", real=True)], eq.hyperstaticity
    (F*c/L, 0)
    """

    __slots__ = ("_reference", "_bodies", "_connections", "_loads", "_labels")

    def __init__(self, reference: Frame):
        if not isinstance(reference, Frame):
            raise ArgumentTypeError(
                f"`reference` must be a Frame; got {type(reference).__name__}.")
        self._reference = reference
        self._bodies: list = []
        self._connections: list = []      # StaticsConnection records
        self._loads: list = []            # (body, torsor)
        self._labels: set = set()

    reference = property(lambda self: self._reference, doc="The reference (ground).")

    @property
    def connections(self) -> tuple:
        """The connections as given, in order: :class:`StaticsConnection` records (first,
        second, connection, label, torsor, unknowns), the torsor being the action of
        ``first`` on ``second`` (a new tuple; the records are immutable).

        Examples
        --------
        >>> import rigidmech as rm
        >>> from rigidmech.actions import ContactLaws
        >>> R0 = rm.Frame("R0"); box = rm.Body("box", frame=R0)
        >>> st = Statics(R0)
        >>> st.connect(R0, box, ContactLaws(at=R0.origin, normal=R0.j), label="A")
        >>> [(c.second.name, c.label, c.unknowns) for c in st.connections]
        [('box', 'A', (N_A,))]
        """
        return tuple(self._connections)

    @property
    def loads(self) -> tuple:
        """The given actions and loads, in order: ``(None, action)`` for an action added with
        :meth:`act` (its torsors on the bodies are asked when the equations are written),
        ``(body, torsor)`` for a torsor added with :meth:`load` (a new tuple).

        Examples
        --------
        >>> import rigidmech as rm
        >>> R0 = rm.Frame("R0"); box = rm.Body("box", frame=R0)
        >>> st = Statics(R0)
        >>> st.load(box, rm.slider(-2 * R0.j, R0.origin))
        >>> [(b.name, T.resultant) for b, T in st.loads]
        [('box', -2*R0.j)]
        """
        return tuple(self._loads)

    @classmethod
    def from_mechanism(cls, mechanism) -> Statics:
        """The statics of the graph ``mechanism`` (:class:`rigidmech.systems.Mechanism`, or
        ``System.mechanism``): its bodies, its connections with their labels, its actions;
        the ground is the reference.

        Examples
        --------
        >>> import rigidmech as rm
        >>> from rigidmech.systems import Mechanism
        >>> R0 = rm.Frame("R0"); beam = rm.Body("beam", frame=R0)
        >>> g = (Mechanism(R0)
        ...      .with_connection(R0, beam, rm.joints.Pivot(at=R0.origin, axis=R0.k), label="A")
        ...      .with_connection(R0, beam, rm.actions.ContactLaws(at=R0.point("B", 2, 0, 0),
        ...                                                    normal=R0.j), label="B")
        ...      .with_action(rm.actions.Force(on=beam, vector=-R0.j, at=R0.point("C", 1, 0, 0))))
        >>> Statics.from_mechanism(g).solve().values[sp.Symbol("N_B", real=True)]
        0.5
        """
        st = cls(mechanism.reference)
        ground = mechanism.ground

        def end(s):
            return mechanism.reference if s is ground else s

        for body in mechanism.bodies:
            st.add(body)
        for link in mechanism.links:
            st.connect(end(link.first), end(link.second), link.connection, label=link.label)
        for action in mechanism.actions:
            st.act(action)
        return st

    def _add_body(self, s):
        if isinstance(s, Solid) and s not in self._bodies:
            self._bodies.append(s)

    @property
    def bodies(self) -> tuple:
        """The bodies whose equilibrium is written, in the order they appeared."""
        return tuple(self._bodies)

    def add(self, body) -> None:
        """Add a body that no connection mentions yet (a free body under loads only).

        Examples
        --------
        >>> import rigidmech as rm
        >>> st = Statics(rm.Frame("R0")); st.add(rm.Body("S", frame=st.reference))
        >>> [b.name for b in st.bodies]
        ['S']
        """
        if not isinstance(body, Solid):
            raise ArgumentTypeError(f"`body` must be a Body; got {type(body).__name__}.")
        self._add_body(body)

    def connect(self, first, second, connection, *, label: str | None = None) -> None:
        """Connect ``second`` to ``first``; the connection's action torsor is the action of
        ``first`` on ``second`` (``second`` receives it, ``first`` its opposite, ch. 14.2.3).

        Parameters
        ----------
        first, second : Body or Frame
            The two ends; a Frame is fixed (the ground).
        connection : Joint, ContactLaws or any object with ``action_torsor(label)``
            returning ``(Torsor, unknowns)``.
        label : str, optional
            Suffix of the unknowns' names (default: the connection's rank, ``"1"``, ...).

        Examples
        --------
        >>> import rigidmech as rm
        >>> from rigidmech.actions import ContactLaws, Force
        >>> R0 = rm.Frame("R0"); box = rm.Body("box", frame=R0)
        >>> st = Statics(R0)
        >>> st.connect(R0, box, ContactLaws(at=R0.origin, normal=R0.j), label="A")
        >>> st.unknowns
        (N_A,)
        """
        _check_body(first, "first")
        _check_body(second, "second")
        if first is second:
            raise ArgumentError(f"`first` and `second` must differ; got {first!r} twice.")
        if not callable(getattr(connection, "action_torsor", None)):
            raise ArgumentTypeError(
                "`connection` must have an action_torsor(label) method (a joint or a "
                f"ContactLaws); got {type(connection).__name__}.")
        label = str(len(self._connections) + 1) if label is None else str(label)
        if label in self._labels:
            raise ArgumentError(f"`label` must be unique; {label!r} is already used.")
        self._labels.add(label)
        torsor, unknowns = connection.action_torsor(label)
        for s in (first, second):
            self._add_body(s)
        self._connections.append(StaticsConnection(first, second, connection, label, torsor,
                                                   tuple(unknowns)))

    def act(self, action: Action) -> None:
        """Add a given action (:class:`~rigidmech.actions.Force`, ``Couple``, ``gravity``,
        ``Spring``): its torsors on the bodies are asked when the equations are written.

        Examples
        --------
        >>> import rigidmech as rm
        >>> from rigidmech.actions import ContactLaws, Force
        >>> R0 = rm.Frame("R0"); box = rm.Body("box", frame=R0)
        >>> st = Statics(R0)
        >>> st.connect(R0, box, ContactLaws(at=R0.origin, normal=R0.j), label="A")
        >>> st.act(Force(on=box, vector=-3 * R0.j, at=R0.origin))
        >>> st.solve().values
        {N_A: 3.0}
        """
        if not isinstance(action, Action):
            raise ArgumentTypeError(
                f"`action` must be an Action (Force, Couple, gravity, Spring); got "
                f"{type(action).__name__}. Use load(body, torsor) for a torsor.")
        self._loads.append((None, action))

    def load(self, body, torsor: Torsor) -> None:
        """Add the action torsor ``torsor`` exerted on ``body``.

        Examples
        --------
        >>> import rigidmech as rm
        >>> from rigidmech.actions import ContactLaws, Force
        >>> R0 = rm.Frame("R0"); box = rm.Body("box", frame=R0)
        >>> st = Statics(R0)
        >>> st.connect(R0, box, ContactLaws(at=R0.origin, normal=R0.j), label="A")
        >>> st.load(box, rm.slider(-2 * R0.j, R0.origin))
        >>> st.solve().values
        {N_A: 2.0}
        """
        if not isinstance(body, Solid):
            raise ArgumentTypeError(f"`body` must be a Body; got {type(body).__name__}.")
        if not isinstance(torsor, Torsor):
            raise ArgumentTypeError(f"`torsor` must be a Torsor; got {type(torsor).__name__}.")
        self._add_body(body)
        self._loads.append((body, torsor))

    def distributed_load(self, body, density, domain) -> Torsor:
        """Add a distributed load, a field of sliders of ``density`` (force per unit length,
        area or volume) over ``domain`` (:class:`~rigidmech.torsors.Domain`), reduced by
        :func:`~rigidmech.torsors.torsor_of_field` (ch. 5.3.2); returns its torsor.

        Examples
        --------
        >>> import rigidmech as rm
        >>> from rigidmech.actions import ContactLaws, Force
        >>> R0 = rm.Frame("R0"); box = rm.Body("box", frame=R0)
        >>> st = Statics(R0)
        >>> import sympy as sp
        >>> from rigidmech.torsors import Domain
        >>> x = sp.Symbol("x")
        >>> st.distributed_load(box, -5 * R0.j, Domain(R0, x * R0.i, (x, 0, 2)))
        Torsor(resultant=-10*R0.j, moment=-10*R0.k, at=O_R0)
        """
        T = torsor_of_field(density, domain)
        self.load(body, T)
        return T

    @property
    def unknowns(self) -> tuple:
        """The unknown components of the connection actions, connection by connection.

        Examples
        --------
        >>> import rigidmech as rm
        >>> from rigidmech.actions import ContactLaws, Force
        >>> R0 = rm.Frame("R0"); box = rm.Body("box", frame=R0)
        >>> st = Statics(R0)
        >>> from rigidmech.actions import Pivot
        >>> st.connect(R0, box, Pivot(at=R0.origin, axis=R0.k), label="O")
        >>> st.unknowns
        (X_O, Y_O, Z_O, L_O, M_O)
        """
        return tuple(u for c in self._connections for u in c[5])

    def contact_conditions(self) -> list:
        """The inequalities of the contacts' laws, ``(kind, label, expr)`` with expr >= 0.

        Examples
        --------
        >>> import rigidmech as rm
        >>> from rigidmech.actions import ContactLaws, Force
        >>> R0 = rm.Frame("R0"); box = rm.Body("box", frame=R0)
        >>> st = Statics(R0)
        >>> st.connect(R0, box, ContactLaws(at=R0.origin, normal=R0.j), label="A")
        >>> st.contact_conditions()
        [('lift-off', 'A', N_A)]
        """
        out = []
        for _, _, conn, label, _, _ in self._connections:
            if callable(getattr(conn, "conditions", None)):
                out += [(kind, label, e) for kind, e in conn.conditions(label)]
        return out

    def torsors_on(self, body) -> list:
        """Every action torsor exerted on ``body``: connection actions (with unknowns) and
        given actions.

        Examples
        --------
        >>> import rigidmech as rm
        >>> from rigidmech.actions import ContactLaws, Force
        >>> R0 = rm.Frame("R0"); box = rm.Body("box", frame=R0)
        >>> st = Statics(R0)
        >>> st.connect(R0, box, ContactLaws(at=R0.origin, normal=R0.j), label="A")
        >>> st.torsors_on(box)
        [Torsor(resultant=N_A*R0.j, moment=0, at=O_R0)]
        """
        out = []
        for first, second, _, _, T, _ in self._connections:
            if second is body:
                out.append(T)
            elif first is body:
                out.append(-T)
        for b, item in self._loads:
            if b is None:
                out += [T for s, T in item.contributions(list(self._bodies)) if s is body]
            elif b is body:
                out.append(item)
        return out

    def equations(self) -> list:
        """The equations of statics ``(body, component, expression = 0)``: the six components,
        in the reference's basis, of the sum of the torsors on each body reduced at the
        reference's origin (ch. 14.2).

        Examples
        --------
        >>> import rigidmech as rm
        >>> from rigidmech.actions import ContactLaws, Force
        >>> R0 = rm.Frame("R0"); box = rm.Body("box", frame=R0)
        >>> st = Statics(R0)
        >>> st.connect(R0, box, ContactLaws(at=R0.origin, normal=R0.j), label="A")
        >>> st.act(Force(on=box, vector=-3 * R0.j, at=R0.origin))
        >>> [(c, e) for _, c, e in st.equations() if e != 0]
        [('resultant along j', N_A - 3)]
        """
        O, R0 = self._reference.origin, self._reference
        rows = []
        for body in self._bodies:
            total = sum(self.torsors_on(body), Torsor.zero(O)).at(O)
            comps = list(total.resultant.components(R0)) + list(total.moment.components(R0))
            rows += [(body, name, sp.expand(c)) for name, c in zip(_COMPONENTS, comps,
                                                                  strict=True)]
        return rows

    def solve(self, values=None, *, unknowns=(), method: str = "auto") -> Equilibrium:
        """Solve the equations of statics for the connection unknowns (and ``unknowns``).

        Parameters
        ----------
        values : dict, optional
            Numbers for symbols (masses, lengths, loads) substituted first, keyed by symbol or
            by name; a number that contradicts the symbol's declaration (a negative value
            for a positive symbol) is refused.
        unknowns : sequence of sympy.Symbol
            Further unknowns, e.g. the load that holds a mechanism at rest.
        method : {"auto", "symbolic", "numeric"}
            "auto": numeric when no symbol remains but the unknowns.

        Returns
        -------
        Equilibrium

        Raises
        ------
        EquilibriumError
            If numbers violate an equation that no unknown enters (no equilibrium).

        Examples
        --------
        >>> import rigidmech as rm
        >>> from rigidmech.actions import ContactLaws, Force
        >>> R0 = rm.Frame("R0"); box = rm.Body("box", frame=R0)
        >>> st = Statics(R0)
        >>> st.connect(R0, box, ContactLaws(at=R0.origin, normal=R0.j), label="A")
        >>> W = rm.constants("W", positive=True)
        >>> st.act(Force(on=box, vector=-W * R0.j, at=R0.origin))
        >>> st.solve().values, st.solve(values={W: 2}).values
        ({N_A: W}, {N_A: 2.0})
        """
        if method not in ("auto", "symbolic", "numeric"):
            raise ArgumentError(
                f"`method` must be 'auto', 'symbolic' or 'numeric'; got {method!r}.")
        xs = list(self.unknowns)
        for u in unknowns:
            if not isinstance(u, sp.Symbol):
                raise ArgumentTypeError(f"`unknowns` must hold sympy Symbols; got {u!r}.")
            if u not in xs:
                xs.append(u)
        if not xs:
            raise ArgumentError("`unknowns`: the problem has no unknown; connect bodies or "
                                "name the unknown loads.")
        rows = self.equations()
        subs = substitutions(values, set().union(*(e.free_symbols for _, _, e in rows)))
        exprs = [e.xreplace(subs) if subs else e for _, _, e in rows]
        try:
            A, b = sp.linear_eq_to_matrix(exprs, xs)
        except sp.polys.polyerrors.PolyNonlinearError as exc:
            raise ArgumentError(
                f"`unknowns` must enter the equations linearly; got {exc}.") from None
        names = [f"{body.name}: {comp}" for body, comp, _ in rows]
        keep = [i for i in range(A.rows) if any(A[i, j] != 0 for j in range(A.cols))
                or b[i] != 0]
        A, b = A.extract(keep, list(range(A.cols))), b.extract(keep, [0])
        names = [names[i] for i in keep]
        free = (A.free_symbols | b.free_symbols) - set(xs)
        numeric = method == "numeric" or (method == "auto" and not free)
        if numeric and free:
            raise ArgumentError(f"`values` must give numbers for {sorted(free, key=str)} for "
                                "the numeric method.")
        solver = _solve_numeric if numeric else _solve_symbolic
        return Equilibrium(self, xs, subs, *solver(A, b, xs, names))


    def limit(self, parameter, interval, *, values=None, samples: int = 200) -> Limit:
        """Where the equilibrium breaks as ``parameter`` runs over ``interval``, and how:
        :func:`~rigidmech.statics.limits.limiting_equilibrium` on this problem.

        Examples
        --------
        A block of weight 10 on a floor with f_s = 0.3, pulled horizontally by P at the
        height of its contact point: it slides at P = 3.

        >>> import sympy as sp
        >>> import rigidmech as rm
        >>> from rigidmech.actions import ContactLaws, Coulomb, Force
        >>> P = sp.Symbol("P")
        >>> R0 = rm.Frame("R0"); block = rm.Body("block", frame=R0)
        >>> st = Statics(R0)
        >>> st.connect(R0, block, ContactLaws(at=R0.origin, normal=R0.j, tangent=R0.i,
        ...                               friction=Coulomb(0.3)), label="I")
        >>> st.act(Force(on=block, vector=-10 * R0.j + P * R0.i, at=R0.origin))
        >>> lim = st.limit(P, (0, 10))
        >>> round(lim.value, 9), lim.kinds, lim.contacts
        (3.0, ('sliding',), ('I',))
        """
        return limiting_equilibrium(self, parameter, interval, values=values, samples=samples)
