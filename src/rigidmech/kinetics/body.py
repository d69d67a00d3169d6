"""Bodies with mass and their kinetic and dynamic torsors, kinetic energy (book, ch. 16).

For a body S of mass m, mass centre G and operator of inertia J_G, moving relative to R
(ch. 16.1.2, 16.2.2, 16.3.2):

.. math::
    \\{\\mathcal{C}(S/R)\\} = \\{ m\\,\\mathbf{v}(G/R) \\;;\\; \\boldsymbol{\\sigma}(G) =
    \\mathcal{J}_G(\\boldsymbol{\\omega}) \\},\\qquad
    \\{\\mathcal{D}(S/R)\\} = \\{ m\\,\\mathbf{a}(G/R) \\;;\\; \\boldsymbol{\\delta}(G) =
    \\left.\\tfrac{d\\boldsymbol{\\sigma}(G)}{dt}\\right|_R \\},

    E_k(S/R) = \\tfrac12 m\\,\\mathbf{v}(G/R)^2 + \\tfrac12\\,\\boldsymbol{\\omega}\\cdot
    \\mathcal{J}_G(\\boldsymbol{\\omega}).
"""

from __future__ import annotations

import sympy as sp

from .._core.errors import ArgumentError, ArgumentTypeError
from .._core.symbolic import zero_decision
from .._core.validation import nonnegative
from ..inertia import InertiaOperator, Shape
from ..kinematics import Solid
from ..torsors import Torsor
from ..vectors import Curve, Frame, Point, Vector
from ..vectors.points import check_point

__all__ = ["Body"]


class Body(Solid):
    """A rigid body: attached frame, mass, mass centre and operator of inertia (ch. 15-16).

    Parameters
    ----------
    name : str
    frame : Frame
        The frame attached to the body.
    mass : scalar, optional
        The mass m: a finite real number >= 0, or a symbol (``rm.constants("m",
        positive=True)``); a symbol known to be negative is refused, one of unknown sign is
        kept. **Massless link**: ``mass=None`` (the default) or ``mass=0`` is a solid with no
        weight and no inertia (``inertia`` must then be omitted), which takes part in the
        equations only through its connections; ``mass=None`` also refuses to give a kinetic
        energy or torsor, ``mass=0`` gives zero.
    centre : Point, optional
        The mass centre G; defaults to the origin of ``frame``.
    inertia : InertiaOperator, optional
        The operator of inertia in a basis fixed in the body (checked: the rotation of its
        basis relative to ``frame`` must be constant): an operator of the catalogue
        (:mod:`rigidmech.inertia`), which is the central one and is placed at G (built with
        ``centre=``, that centre must be G), or an operator given at any point of the body,
        moved to G by the relations of Huygens.
        Defaults to zero (a particle).
    shape : Shape, optional
        The body's shape **for drawing only** (:class:`~rigidmech.inertia.Shape`, centred on
        the mass centre, in a frame fixed in the body), when its operator of inertia does not
        carry one: an operator given by its moments, a particle, a massless link. It plays
        no part in the mass, the inertia or the equations. A catalogue operator already
        carries its shape (then omit ``shape``).

    Raises
    ------
    ArgumentTypeError
        For a mass that is not a number or a sympy expression (a string, say).
    ArgumentError
        For a mass that is not a finite real number >= 0, an inertia given without a mass
        (or with ``mass=0``), in a basis that turns relative to the body, or central at
        another point than ``centre``; for a ``shape`` in a frame that turns relative to the
        body, or given with a catalogue operator (which has its own).

    Examples
    --------
    >>> import sympy as sp
    >>> import rigidmech as rm
    >>> q = rm.coordinates("q"); m, L = rm.constants("m L", positive=True)
    >>> R0 = rm.Frame("R0"); R1 = R0.rotated("R1", about=R0.k, angle=q)
    >>> G = R0.origin.moved("G", L / 2 * R1.i)
    >>> bar = Body("bar", frame=R1, mass=m, centre=G,
    ...            inertia=rm.inertia.rod(m, L, axis=R1.i, centre=G))
    >>> sp.factor(bar.kinetic_energy(R0))
    L**2*m*Derivative(q(t), t)**2/6

    A body whose inertia is given by its moments, drawn as a cone (its shape is for drawing
    only):

    >>> J = rm.inertia.InertiaOperator.from_products(1, 1, 2, frame=R1, at=G)
    >>> top = Body("top", frame=R1, mass=m, centre=G, inertia=J,
    ...            shape=rm.inertia.Shape("cone", [L / 2, 4 * L / 3], axis=-R1.k))
    >>> top.shape.kind, top.inertia.matrix[2, 2]
    ('cone', 2)
    """

    __slots__ = ("_mass", "_centre", "_inertia", "_shape")

    def __init__(self, name: str, frame: Frame, *, mass=None, centre: Point | None = None,
                 inertia: InertiaOperator | None = None, shape: Shape | None = None):
        super().__init__(name, frame)
        if mass is not None:
            mass = nonnegative(mass, "mass")
        if centre is None:
            centre = frame.origin
        check_point(centre, "centre")
        if inertia is not None and not isinstance(inertia, InertiaOperator):
            raise ArgumentTypeError(
                f"`inertia` must be an InertiaOperator (see rigidmech.inertia); got "
                f"{type(inertia).__name__}."
            )
        if inertia is not None and mass is None:
            raise ArgumentError("`inertia` given without `mass`: give the body's mass too.")
        if inertia is not None and mass == 0:
            raise ArgumentError(
                "`inertia` given with `mass=0`: a massless link has no inertia; omit "
                "`inertia` or give the body's mass.")
        if inertia is not None:
            if inertia.at != centre:
                # a catalogue operator is the body's central one: place it at G; any other
                # operator is moved to G by the relations of Huygens
                if inertia.is_central and inertia.is_placed \
                        and not (centre - inertia.at).is_zero:
                    raise ArgumentError(
                        f"`inertia` is a central operator taken at {inertia.at.name}, but the "
                        f"body's mass centre `centre` is {centre.name}: two different mass "
                        f"centres. Build the operator with centre={centre.name} (or without "
                        f"`centre=`, and the body places it), or give the body "
                        f"centre={inertia.at.name}.")
                inertia = (inertia.placed_at(centre) if inertia.is_central
                           else inertia.moved(centre, mass=mass, centre=centre))
            if inertia.frame != frame:
                _check_fixed_in_body(inertia.frame, frame, "inertia", "the matrix")
                inertia = inertia.in_basis(frame)
        if shape is not None:
            if not isinstance(shape, Shape):
                raise ArgumentTypeError(
                    f"`shape` must be a rigidmech.inertia.Shape (such as Shape('cone', [R, h], "
                    f"axis=R1.k)); got {type(shape).__name__}.")
            if inertia is not None and inertia.shape is not None:
                raise ArgumentError(
                    f"`shape` given with a catalogue operator, which carries its own shape "
                    f"({inertia.shape!r}); omit `shape`.")
            _check_fixed_in_body(shape.frame, frame, "shape", "its shape")
        self._mass = mass
        self._centre = centre
        self._inertia = inertia
        self._shape = shape

    @classmethod
    def particle(cls, name: str, at: Point, *, mass, basis: Frame | None = None,
                 frame_name: str | None = None) -> Body:
        """A particle (point mass) at the point `at`: a body of mass `mass` concentrated at
        `at`, with no inertia of its own (book, ch. 15.5.1, 18.1, 21).

        The body needs a frame: it gets one translated to `at`, with the basis of `basis`
        (``basis.translated(frame_name, at)``); its mass centre is `at` and its operator of
        inertia is zero. The rotation of that frame plays no part in the particle's kinetic
        energy or torsors.

        Parameters
        ----------
        name : str
            The body's name.
        at : Point
            The particle's position, a point whose motion is known (it may depend on
            coordinates, e.g. ``R0.point("P", x, y, 0)`` or ``O.moved("P", L * R1.i)``).
        mass : scalar
            m, a finite real number >= 0 or a sympy expression (as for :class:`Body`);
            required.
        basis : Frame, optional
            The frame whose basis the particle's frame keeps; default the root frame of `at`.
        frame_name : str, optional
            Name of the frame made; default ``"R_" + name``.

        Returns
        -------
        Body

        Raises
        ------
        ArgumentError
            If `mass` is missing or not >= 0, or `name` is not a non-empty string.
        ArgumentTypeError
            If `at` is not a Point or `basis` not a Frame.

        Examples
        --------
        >>> import sympy as sp
        >>> import rigidmech as rm
        >>> q = rm.coordinates("q"); m, L = rm.constants("m L", positive=True)
        >>> R0 = rm.Frame("R0"); R1 = R0.rotated("R1", about=R0.k, angle=q)
        >>> bob = Body.particle("bob", R0.origin.moved("P", L * R1.i), mass=m)
        >>> sp.simplify(bob.kinetic_energy(R0))
        L**2*m*Derivative(q(t), t)**2/2
        >>> bob.inertia is None, bob.frame.name
        (True, 'R_bob')
        """
        if not isinstance(name, str) or not name:
            raise ArgumentError(f"`name` must be a non-empty string; got {name!r}.")
        if mass is None:
            raise ArgumentError(
                "`mass` must be given for a particle (a number >= 0 or a symbol); got None. "
                "For a massless link use Body(name, frame) instead.")
        check_point(at, "at")
        if basis is None:
            basis = at.root
        if not isinstance(basis, Frame):
            raise ArgumentTypeError(f"`basis` must be a Frame; got {type(basis).__name__}.")
        frame = basis.translated("R_" + name if frame_name is None else frame_name, at)
        return cls(name, frame, mass=mass, centre=at)

    @classmethod
    def particle_on_curve(cls, name: str, curve: Curve, coordinate, *, mass,
                          point_name: str | None = None,
                          frame_name: str | None = None) -> Body:
        """A particle constrained to a curve (a bead on a wire, a point on a given path;
        book, ch. 17-18, 25): its position is the point of ``curve`` at the parameter value
        ``coordinate``, a parameter of situation s(t) (or a function of time given in
        advance).

        The curve is described relative to its frame, which may move (a wire that turns:
        ``R0.rotated("R1", about=R0.k, angle=omega * t)``). The constraint is perfect: the
        particle's position is written with s(t) alone, so the wire's reaction, normal to the
        curve, does no work and does not appear in the equations of motion (Lagrange's way,
        ch. 25); along a motion it is m a(P) minus the given forces
        (:meth:`Simulation.evaluate <rigidmech.dynamics.Simulation.evaluate>` of that
        vector).

        Parameters
        ----------
        name : str
            The body's name.
        curve : Curve
            The curve r(s) relative to its frame (:class:`rigidmech.vectors.Curve`).
        coordinate : sympy expression
            The parameter of the curve along the motion, usually a coordinate s(t).
        mass : scalar
            As for :meth:`particle`.
        point_name : str, optional
            Name of the particle's point (its :attr:`centre`); default ``"P_" + name``.
        frame_name : str, optional
            As for :meth:`particle`.

        Returns
        -------
        Body

        Raises
        ------
        ArgumentTypeError
            If ``curve`` is not a Curve, or ``coordinate`` not a sympy expression.

        Examples
        --------
        A bead on a circular hoop of radius R turning at omega about the vertical
        (ch. 17-18): its kinetic energy is m (R^2 theta'^2 + R^2 omega^2 sin^2 theta) / 2.

        >>> import sympy as sp, rigidmech as rm
        >>> theta = rm.coordinates("theta"); R, w, m = rm.constants("R omega m", positive=True)
        >>> phi = sp.Symbol("phi", real=True)
        >>> R0 = rm.Frame("R0"); R1 = R0.rotated("R1", about=R0.k, angle=w * rm.t)
        >>> hoop = rm.Curve(R1.vector(R * sp.sin(phi), 0, -R * sp.cos(phi)), phi, R1)
        >>> bead = Body.particle_on_curve("bead", hoop, theta, mass=m)
        >>> sp.factor(sp.simplify(bead.kinetic_energy(R0)))
        R**2*m*(omega**2*sin(theta(t))**2 + Derivative(theta(t), t)**2)/2
        """
        if not isinstance(curve, Curve):
            raise ArgumentTypeError(
                f"`curve` must be a rigidmech.vectors.Curve; got {type(curve).__name__}.")
        try:
            value = sp.sympify(coordinate)
        except (sp.SympifyError, TypeError):
            raise ArgumentTypeError(
                f"`coordinate` must be a sympy expression (a coordinate s(t)); got "
                f"{coordinate!r}.") from None
        comps = curve.position().components(curve.frame).subs(curve.parameter, value)
        at = curve.frame.origin.moved("P_" + str(name) if point_name is None else point_name,
                                      Vector.from_components(curve.frame, list(comps)))
        return cls.particle(name, at, mass=mass, frame_name=frame_name)

    @property
    def mass(self):
        """The mass m (None for a massless solid)."""
        return self._mass

    @property
    def centre(self) -> Point:
        """The mass centre G."""
        return self._centre

    @property
    def anchor(self) -> Point:
        """The mass centre G: the point from which the velocity field is built."""
        return self._centre

    @property
    def inertia(self):
        """The operator of inertia at G in the body's basis (None for a particle)."""
        return self._inertia

    @property
    def shape(self):
        """The :class:`~rigidmech.inertia.Shape` of the body, centred on its mass centre: the
        one given as ``shape=``, else its operator's when that comes from the catalogue (a
        rod, a disk, a block...: ch. 15.5); None otherwise (an operator given by its moments,
        a particle, a massless link, without ``shape=``). :mod:`rigidmech.drawing` draws a
        body by its shape.

        Examples
        --------
        >>> import rigidmech as rm
        >>> R1 = rm.Frame("R1")
        >>> Body("bar", frame=R1, mass=1, inertia=rm.inertia.rod(1, 2, axis=R1.i)).shape
        Shape('rod', length=2, axis=R1.i)
        >>> Body("b", frame=R1, mass=1).shape is None
        True
        """
        if self._shape is not None:
            return self._shape
        return None if self._inertia is None else self._inertia.shape

    def _angular_momentum_at_centre(self, w: Vector) -> Vector:
        if self._inertia is None:
            return Vector.zero()
        return self._inertia.apply(w)

    def kinetic_torsor(self, relative_to: Frame, at: Point | None = None) -> Torsor:
        """{C(S/R)} = {m v(G/R) ; sigma(G) = J_G(omega)}, reduced at ``at`` (ch. 16.1.2).

        Examples
        --------
        >>> import rigidmech as rm
        >>> x = rm.coordinates("x")
        >>> R0 = rm.Frame("R0"); R1 = R0.translated("R1", R0.point("P", x, 0, 0))
        >>> Body("b", frame=R1, mass=2).kinetic_torsor(R0).resultant
        2*Derivative(x(t), t)*R0.i
        """
        self._need_mass("kinetic_torsor")
        w = self.rotation_vector(relative_to)
        v = self._centre.velocity(relative_to)
        T = Torsor(self._mass * v, self._angular_momentum_at_centre(w), self._centre)
        return T if at is None else T.at(at)

    def dynamic_torsor(self, relative_to: Frame, at: Point | None = None) -> Torsor:
        """{D(S/R)} = {m a(G/R) ; delta(G) = d/dt|R sigma(G)}, reduced at ``at``
        (ch. 16.2.2).

        Examples
        --------
        >>> import rigidmech as rm
        >>> q = rm.coordinates("q")
        >>> R0 = rm.Frame("R0"); R1 = R0.rotated("R1", about=R0.k, angle=q)
        >>> b = Body("b", frame=R1, mass=1, centre=R0.origin.moved("G", R1.i))
        >>> b.dynamic_torsor(R0).resultant
        -Derivative(q(t), t)**2*R1.i + Derivative(q(t), (t, 2))*R1.j
        """
        self._need_mass("dynamic_torsor")
        w = self.rotation_vector(relative_to)
        a = self._centre.acceleration(relative_to)
        delta = self._angular_momentum_at_centre(w).dt(relative_to)
        T = Torsor(self._mass * a, delta, self._centre)
        return T if at is None else T.at(at)

    def kinetic_energy(self, relative_to: Frame) -> sp.Expr:
        """E_k(S/R) = m v(G)^2 / 2 + omega . J_G(omega) / 2 (ch. 16.3.2).

        Examples
        --------
        >>> import rigidmech as rm
        >>> x = rm.coordinates("x")
        >>> R0 = rm.Frame("R0"); R1 = R0.translated("R1", R0.point("P", x, 0, 0))
        >>> Body("b", frame=R1, mass=2).kinetic_energy(R0)
        Derivative(x(t), t)**2
        """
        self._need_mass("kinetic_energy")
        w = self.rotation_vector(relative_to)
        v = self._centre.velocity(relative_to)
        return (self._mass * v.dot(v) + w.dot(self._angular_momentum_at_centre(w))) / 2

    def _need_mass(self, what):
        if self._mass is None:
            raise ArgumentError(
                f"`{what}` needs the mass of body {self._name}; create it with mass=...")

    def __repr__(self):
        return (f"Body({self._name!r}, frame={self._frame.name}, mass={self._mass}, "
                f"centre={self._centre.name})")


def _check_fixed_in_body(basis_frame, frame, argument, what):
    """Raise unless the basis of ``basis_frame`` is fixed relative to ``frame``: the rotation
    vector of one relative to the other is zero (ch. 9.2.3), so their direction cosines are
    constant and the matrix of inertia keeps its values in the body."""
    w = frame.rotation_vector(basis_frame)
    if w.is_zero or all(zero_decision(c) is True for c in w._comps(frame)):
        return
    raise ArgumentError(
        f"`{argument}` must be given in a basis fixed in the body: its frame {basis_frame.name} "
        f"turns relative to the body's frame {frame.name} (rotation vector {w}). Give "
        f"{what} in {frame.name} or in a frame fixed in it.")
