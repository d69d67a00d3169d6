"""Reference systems: an origin and a direct orthonormal basis (book, ch. 2.1.5, 2.5, 9.1.2).

Frames form a tree. A child frame is made from its parent by an elementary basis change
(rotation about one axis of the parent by one angle, ch. 2.5.2), by a rotation about any fixed
axis, by Euler angles (precession, nutation, spin: z-x-z, ch. 9.1.2) or by moving the origin.
A frame is an immutable value: the relation to its parent is part of the value; there is no
mutable global graph. Direction cosines and rotation vectors between frames are derived on
demand (see :mod:`rigidmech.vectors._rotations`).
"""

from __future__ import annotations

import sympy as sp

from .._core.errors import ArgumentError, ArgumentTypeError, FrameError
from .._core.validation import finite_real
from ._rotations import ONE, ZERO, FrameBase, direction_cosines
from .euler_parameters import euler_parameter_matrix
from .points import Point
from .singularities import orientation_singularity
from .symbols import t
from .vector import Vector, rotation_vector

__all__ = ["Frame"]

_AXES = "ijk"
_ANGLE_HINT = "For a parameter of situation use rm.coordinates (q = rm.coordinates('q'))."


def _coordinates3(x, y, z):
    """The coordinates x, y, z given by the user, checked (finite real numbers or sympy
    expressions; a string is refused rather than read as a symbol)."""
    return tuple(finite_real(v, n) for v, n in ((x, "x"), (y, "y"), (z, "z")))


def _pairs(args):
    """sympy's ``subs`` arguments as (old, new) pairs."""
    if len(args) == 2:
        return [(sp.sympify(args[0]), sp.sympify(args[1]))]
    if len(args) == 1:
        items = args[0].items() if isinstance(args[0], dict) else args[0]
        try:
            return [(sp.sympify(a), sp.sympify(b)) for a, b in items]
        except (TypeError, ValueError):
            return []
    return []


def _shown(x):
    """q(t) as q, q'(t) as q' (the names of the parameters of situation), else sympy's."""
    if isinstance(x, sp.Derivative) and len(x.variables) == 1 and x.variables[0] == t \
            and isinstance(x.expr, sp.core.function.AppliedUndef):
        return f"{x.expr.func.__name__}'"
    if isinstance(x, sp.core.function.AppliedUndef) and x.args == (t,):
        return x.func.__name__
    return sp.sstr(x)


def _reaches(frame, old):
    """Whether ``old`` occurs in the angle, rotation matrix or origin of ``frame`` or of an
    ancestor: a value substituted for it changes the frame."""
    f = frame
    while f._parent is not None:
        own = [f._angle] + ([x for row in f._matrix for x in row] if f._matrix else [])
        if any(sp.sympify(x).has(old) for x in own):
            return True
        for g, comps in f._origin.position._parts:
            if any(c.has(old) for c in comps) or (g is not f and _reaches(g, old)):
                return True
        f = f._parent
    return False


def _substituted(frame, args, before):
    """The label of the frame made by substituting ``args`` in ``frame``: the values that
    reach it, sorted (``a=5, q=1/3``), after those of an earlier substitution."""
    shown = sorted(f"{_shown(old)}={sp.sstr(new)}" for old, new in _pairs(args)
                   if _reaches(frame, old))
    parts = ([before] if before else []) + ([", ".join(shown)] if shown else [])
    return "; ".join(parts) or "subs"


class Frame(FrameBase):
    """A reference system (O; i, j, k): an origin and a direct orthonormal basis.

    Parameters
    ----------
    name : str
        Name used in printing. ``Frame(name)`` creates a root frame (for example the
        Galilean reference); children come from :meth:`rotated`, :meth:`euler` and
        :meth:`translated`.

    Notes
    -----
    For a rotation by :math:`\\psi` about :math:`\\mathbf{k}_0` the book writes (ch. 2.5.2)

    .. math:: \\mathbf{i}_1 = \\cos\\psi\\,\\mathbf{i}_0 + \\sin\\psi\\,\\mathbf{j}_0,\\quad
              \\mathbf{j}_1 = -\\sin\\psi\\,\\mathbf{i}_0 + \\cos\\psi\\,\\mathbf{j}_0,\\quad
              \\mathbf{k}_1 = \\mathbf{k}_0 .

    Examples
    --------
    >>> from rigidmech.vectors import Frame, coordinates
    >>> psi = coordinates("psi")
    >>> R0 = Frame("R0")
    >>> R1 = R0.rotated("R1", about=R0.k, angle=psi)
    >>> R1.i.components(R0).T
    Matrix([[cos(psi(t)), sin(psi(t)), 0]])
    >>> R1.rotation_vector(R0)
    Derivative(psi(t), t)*R1.k
    """

    __slots__ = ()

    def __init__(self, name: str):
        self._set(name, None, None, ZERO, None, None)
        self._origin = Point._root_origin(self)

    @classmethod
    def _child(cls, name, parent, *, axis=None, angle=ZERO, matrix=None, origin):
        obj = cls.__new__(cls)
        obj._set(name, parent, axis, angle, matrix, origin)
        return obj

    def rotated(self, name: str, *, about, angle, origin=None) -> Frame:
        """Frame obtained by rotating this basis by ``angle`` about ``about``.

        Parameters
        ----------
        name : str
            Name of the new frame.
        about : Vector
            Axis of rotation. A basis vector of this frame (``R0.k``, or its opposite) gives
            the book's elementary basis change (ch. 2.5.2); any other constant vector gives
            a rotation about that fixed axis (Rodrigues' formula).
        angle : sympy expression
            Angle of rotation, usually a parameter of situation ``q(t)``.
        origin : Point, optional
            Origin of the new frame; defaults to this frame's origin.

        Returns
        -------
        Frame

        Raises
        ------
        FrameError
            If ``about`` is the zero vector or moves relative to this frame.

        Examples
        --------
        >>> from rigidmech.vectors import Frame, coordinates
        >>> q = coordinates("q")
        >>> R0 = Frame("R0")
        >>> R1 = R0.rotated("R1", about=R0.i, angle=q)
        >>> R1.k.components(R0).T
        Matrix([[0, -sin(q(t)), cos(q(t))]])
        """
        if not isinstance(about, Vector):
            raise ArgumentTypeError(
                f"`about` must be a Vector (for example {self._name}.k); "
                f"got {type(about).__name__}."
            )
        angle = finite_real(angle, "angle", hint=_ANGLE_HINT)
        origin = self._check_origin(origin)
        c = about._comps(self)
        nonzero = [n for n in range(3) if c[n] != 0]
        if not nonzero:
            raise FrameError("`about` must be a non-zero vector; got the zero vector.")
        if any(x.atoms(sp.core.function.AppliedUndef) or x.has(t)
               for x in c):
            raise FrameError(
                f"`about` must be a fixed axis of {self._name}; got {about!r}, which moves "
                f"relative to {self._name}. Chain two rotations instead."
            )
        if len(nonzero) == 1:
            n = nonzero[0]
            sign = sp.sign(c[n])
            if sign in (1, -1):
                return Frame._child(name, self, axis=n, angle=sign * angle, origin=origin)
        norm = sp.sqrt(sum(x**2 for x in c))
        ux, uy, uz = (sp.simplify(x / norm) for x in c)
        cs, sn = sp.cos(angle), sp.sin(angle)
        v = 1 - cs
        m = (
            (cs + ux * ux * v, ux * uy * v - uz * sn, ux * uz * v + uy * sn),
            (uy * ux * v + uz * sn, cs + uy * uy * v, uy * uz * v - ux * sn),
            (uz * ux * v - uy * sn, uz * uy * v + ux * sn, cs + uz * uz * v),
        )
        return Frame._child(name, self, matrix=m, origin=origin)

    def euler(self, name: str, precession, nutation, spin, *, origin=None) -> Frame:
        """Frame given by Euler angles relative to this one (book, ch. 9.1.2): z-x-z.

        Precession ``psi`` about k0 gives (u, w, k0), nutation ``theta`` about the line of
        nodes u gives (u, v, k), spin ``phi`` about k gives the body basis (i, j, k). The two
        intermediate frames are named ``name + "_psi"`` and ``name + "_theta"``; they are the
        returned frame's parent and grandparent.

        Examples
        --------
        >>> from rigidmech.vectors import Frame, coordinates
        >>> psi, theta, phi = coordinates("psi theta phi")
        >>> R0 = Frame("R0")
        >>> R = R0.euler("R", psi, theta, phi)
        >>> R.parent.name, R.parent.parent.name
        ('R_theta', 'R_psi')
        >>> R.rotation_vector(R0)
        Derivative(phi(t), t)*R.k + Derivative(theta(t), t)*R_psi.i + Derivative(psi(t), t)*R_psi.k
        >>> R.rotation_vector(R0).components(R.parent).T
        Matrix([[Derivative(theta(t), t), sin(theta(t))*Derivative(psi(t), t),
                 cos(theta(t))*Derivative(psi(t), t) + Derivative(phi(t), t)]])
        """
        if not isinstance(name, str) or not name:
            raise ArgumentError(f"`name` must be a non-empty string; got {name!r}.")
        f1 = self.rotated(name + "_psi", about=self.k, angle=precession, origin=origin)
        f2 = f1.rotated(name + "_theta", about=f1.i, angle=nutation)
        return f2.rotated(name, about=f2.k, angle=spin)

    def euler_parameters(self, name: str, e0, e1, e2, e3, *, origin=None) -> Frame:
        """Frame oriented by four Euler parameters (a quaternion) relative to this one: no
        singular set, unlike any three angles (book, ch. 9.1.2).

        The direction cosines are those of :math:`e / |e|` (see
        :func:`rigidmech.vectors.euler_parameter_matrix`): e0 = cos(alpha/2) and
        (e1, e2, e3) = sin(alpha/2) n for the rotation by alpha about n. Equations of motion
        keep :math:`|e|` constant; initial rates follow from the rotation vector with
        :func:`rigidmech.vectors.euler_parameter_rates`.

        Examples
        --------
        >>> from rigidmech.vectors import Frame, coordinates
        >>> e0, e1, e2, e3 = coordinates("e0 e1 e2 e3")
        >>> R = Frame("R0").euler_parameters("R", e0, e1, e2, e3)
        >>> R.dcm(R.parent)[2, 2] * (e0**2 + e1**2 + e2**2 + e3**2)
        e0(t)**2 - e1(t)**2 - e2(t)**2 + e3(t)**2
        >>> R.singular_set() is None
        True
        """
        e = [finite_real(x, f"e{n}", hint=_ANGLE_HINT) for n, x in enumerate((e0, e1, e2, e3))]
        return Frame._child(name, self, matrix=euler_parameter_matrix(*e),
                            origin=self._check_origin(origin))

    def translated(self, name: str, origin: Point) -> Frame:
        """Frame with the same basis as this one and the origin ``origin``.

        Examples
        --------
        >>> from rigidmech.vectors import Frame
        >>> R0 = Frame("R0")
        >>> R1 = R0.translated("R1", R0.point("A", 1, 0, 0))
        >>> R1.origin - R0.origin
        R0.i
        """
        return Frame._child(name, self, axis=2, angle=ZERO, origin=self._check_origin(origin))

    def subs(self, *args, **kwargs) -> Frame:
        """The frame with values substituted in its angle (or rotation matrix), its origin and
        those of its ancestors (sympy's ``subs`` arguments).

        The result keeps the names; it is the same frame (``is``) when nothing changes. A
        root frame is returned as it is. A frame that changed prints with the values that
        reached it (its :attr:`label`, ``R1[q=0]``, also in the vectors that use it): it is
        fixed at that instant, not the moving frame of the same name.

        Examples
        --------
        >>> from rigidmech.vectors import Frame, coordinates
        >>> q = coordinates("q")
        >>> R0 = Frame("R0"); R1 = R0.rotated("R1", about=R0.k, angle=q)
        >>> R1.subs(q, 0.5).angle
        0.500000000000000
        >>> R1.subs(q, 0).dcm(R0)
        Matrix([
        [1, 0, 0],
        [0, 1, 0],
        [0, 0, 1]])
        >>> print(R1.subs(q, 0)), R1.subs(q, 0).name
        R1[q=0]
        (None, 'R1')
        """
        return self._subs(args, kwargs, {})

    def _subs(self, args, kwargs, memo):
        if self._parent is None:
            return self
        hit = memo.get(self)
        if hit is not None:
            return hit
        parent = self._parent._subs(args, kwargs, memo)
        angle = sp.sympify(self._angle).subs(*args, **kwargs)
        matrix = self._matrix if self._matrix is None else tuple(
            tuple(sp.sympify(x).subs(*args, **kwargs) for x in row) for row in self._matrix)
        origin = self._origin._subs(args, kwargs, memo)
        if (parent is self._parent and angle == self._angle and matrix == self._matrix
                and origin == self._origin):
            out = self
        else:
            out = Frame._child(self._name, parent, axis=self._axis, angle=angle, matrix=matrix,
                               origin=origin)
            out._at = _substituted(self, args, self._at)
        memo[self] = out
        return out

    def _check_origin(self, origin):
        if origin is None:
            return self._origin
        if not isinstance(origin, Point):
            raise ArgumentTypeError(
                f"`origin` must be a Point; got {type(origin).__name__}. "
                f"For a position vector v use {self._name}.origin.moved(name, v)."
            )
        if origin.root != self.root:
            raise FrameError(
                f"`origin` belongs to the tree of {origin.root.name}, not {self.root.name}."
            )
        return origin

    @property
    def origin(self) -> Point:
        """The origin O of the reference system."""
        return self._origin

    @property
    def angle(self):
        """Angle of the elementary rotation from the parent (0 for a root or a general
        rotation)."""
        return self._angle

    def _unit(self, n):
        if self._basis is None:
            self._basis = tuple(
                Vector._from_parts(((self, tuple(ONE if m == k else ZERO for m in range(3))),))
                for k in range(3)
            )
        return self._basis[n]

    @property
    def i(self) -> Vector:
        """First basis vector."""
        return self._unit(0)

    @property
    def j(self) -> Vector:
        """Second basis vector."""
        return self._unit(1)

    @property
    def k(self) -> Vector:
        """Third basis vector."""
        return self._unit(2)

    @property
    def basis(self):
        """The basis (i, j, k) as a tuple of vectors."""
        return (self.i, self.j, self.k)

    def vector(self, x, y, z) -> Vector:
        """The vector x i + y j + z k of this basis.

        Examples
        --------
        >>> from rigidmech.vectors import Frame
        >>> Frame("R0").vector(1, 2, 3)
        R0.i + 2*R0.j + 3*R0.k
        """
        return Vector.from_components(self, _coordinates3(x, y, z))

    def point(self, name: str, x, y, z) -> Point:
        """The point of coordinates (x, y, z) in this reference system (ch. 2.3.3).

        Examples
        --------
        >>> from rigidmech.vectors import Frame
        >>> R0 = Frame("R0")
        >>> R0.point("A", 1, 2, 0).coordinates(R0).T
        Matrix([[1, 2, 0]])
        """
        return self._origin.moved(name, Vector.from_components(self, _coordinates3(x, y, z)))

    def dcm(self, other: Frame) -> sp.ImmutableMatrix:
        """Direction cosines C: components in ``self`` = C @ components in ``other``; the
        columns are ``other``'s basis vectors expressed in ``self`` (book, ch. 1.5.2).

        Examples
        --------
        >>> from rigidmech.vectors import Frame, coordinates
        >>> q1, q2 = coordinates("q1 q2")
        >>> R0 = Frame("R0")
        >>> R1 = R0.rotated("R1", about=R0.k, angle=q1)
        >>> R2 = R1.rotated("R2", about=R1.k, angle=q2)
        >>> R0.dcm(R2)[0, 0]
        cos(q1(t) + q2(t))
        """
        if not isinstance(other, FrameBase):
            raise ArgumentTypeError(f"`other` must be a Frame; got {type(other).__name__}.")
        return sp.ImmutableMatrix(direction_cosines(self, other))

    def rotation_vector(self, relative_to: Frame) -> Vector:
        """The rotation vector omega(self/relative_to) (book, ch. 9.2.3).

        Examples
        --------
        >>> from rigidmech.vectors import Frame, coordinates
        >>> q1, q2 = coordinates("q1 q2")
        >>> R0 = Frame("R0")
        >>> R2 = R0.rotated("R1", about=R0.k, angle=q1).rotated("R2", about=R0.k, angle=q2)
        >>> R2.rotation_vector(R0)
        (Derivative(q1(t), t) + Derivative(q2(t), t))*R2.k
        """
        return rotation_vector(self, relative_to)

    def singular_set(self, relative_to=None):
        """The singular set of the angles orienting this frame relative to ``relative_to``
        (default: the root), or None if they have none (book, ch. 9.1.2).

        Euler angles z-x-z are singular where sin(theta) = 0, Cardan sequences where the
        cosine of the middle angle vanishes; see
        :func:`rigidmech.vectors.orientation_singularity`.

        Examples
        --------
        >>> from rigidmech.vectors import Frame, coordinates
        >>> psi, theta, phi = coordinates("psi theta phi")
        >>> R0 = Frame("R0")
        >>> R0.euler("R", psi, theta, phi).singular_set().condition
        Eq(sin(theta(t)), 0)
        >>> R0.rotated("R1", about=R0.k, angle=psi).singular_set() is None
        True
        """
        return orientation_singularity(self, relative_to)

    def __repr__(self):
        if self._parent is None:
            return f"Frame({self._name!r})"
        if self._at is not None:
            return f"<Frame {self.label}: {self._repr_plain()}>"
        return self._repr_plain()

    def _repr_plain(self):
        parent = self._parent.label
        moved = self._origin != self._parent._origin
        origin = f", origin={self._origin.name}" if moved else ""
        if self._axis is not None:
            if moved and self._angle == 0:
                return f"{parent}.translated({self._name!r}, {self._origin.name})"
            return (f"{parent}.rotated({self._name!r}, about={parent}.{_AXES[self._axis]}, "
                    f"angle={self._angle}{origin})")
        return f"<Frame {self._name!r}: general rotation from {parent!r}{origin}>"

