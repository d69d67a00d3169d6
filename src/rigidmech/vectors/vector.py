"""Vectors of the Euclidean vector space, possibly mixing bases (book, ch. 1 and 3).

A :class:`Vector` is a sum of parts, each a triple of components in the basis of one frame.
Vectors are expressed in a single basis only when asked (:meth:`Vector.express`,
:meth:`Vector.components`); operations keep each part in the basis where it is shortest.
The derivative relative to a frame uses the derivation formula (ch. 3.1, 9.2.3):

.. math:: \\left.\\frac{d\\mathbf{u}}{dt}\\right|_{R_a} =
          \\left.\\frac{d\\mathbf{u}}{dt}\\right|_{R_b} + \\boldsymbol{\\omega}(R_b/R_a)
          \\wedge \\mathbf{u}
"""

from __future__ import annotations

from functools import lru_cache

import numpy as np
import sympy as sp
from sympy.printing.latex import LatexPrinter

from .._core.errors import ArgumentError, ArgumentTypeError, FrameError
from .._core.symbolic import is_exactly_zero, is_identically_zero
from ._rotations import (
    ZERO,
    FrameBase,
    bilinear,
    common_ancestor,
    direction_cosines,
    dot3,
    matmul,
    matvec,
    path_to_ancestor,
    transpose,
)
from .euler_parameters import euler_parameters_of
from .symbols import _is_rate, partial_derivative, time_derivative

__all__ = ["Vector", "dot", "cross", "mixed", "rotation_vector", "partial_rotation_vector"]

_ZERO3 = (ZERO, ZERO, ZERO)


def _cross3(u, v):
    def term(a, b, c, d):
        p = a * b if a != 0 and b != 0 else ZERO
        q = c * d if c != 0 and d != 0 else ZERO
        return p - q

    return (term(u[1], v[2], u[2], v[1]), term(u[2], v[0], u[0], v[2]),
            term(u[0], v[1], u[1], v[0]))


def _check_scalar(given, s):
    """Refuse a factor that is a non-finite or complex number (cheap: only atoms and Python
    complex numbers are inspected, the product stays fast in derivations)."""
    if isinstance(given, str):
        raise ArgumentTypeError(
            f"`scalar` must be a number or a sympy expression; got str {given!r}.")
    if (isinstance(given, complex | np.complexfloating) or s is sp.I
            or (s.is_Number and s.is_finite is not True)):
        raise ArgumentError(f"`scalar` must be a finite real number; got {given}.")


def _partial(x, variable):
    """dx/d(variable): structural for a symbol, a q(t) or a q'(t), sympy's diff otherwise."""
    if isinstance(variable, sp.Symbol) or _is_rate(variable):
        return partial_derivative(x, variable)
    return sp.diff(x, variable)


def _any_nonzero(c):
    return not all(is_exactly_zero(x) for x in c)


def _nonzero(c):
    return sum(1 for x in c if x != 0)


def _check_frame(frame, argument):
    if not isinstance(frame, FrameBase):
        raise ArgumentTypeError(
            f"`{argument}` must be a Frame; got {type(frame).__name__}."
        )


class Vector:
    """A vector, as a sum of component triples in the bases of one or more frames.

    Build vectors from basis vectors (``2 * R0.i + 3 * R1.j``) or with
    :meth:`from_components`. Vectors are immutable; ``==`` is exact and structural (the same
    parts in the same bases); use :meth:`equals` for a symbolic comparison and
    :meth:`is_close` for a numeric one.

    Examples
    --------
    >>> from rigidmech.vectors import Frame, coordinates
    >>> psi = coordinates("psi")
    >>> R0 = Frame("R0")
    >>> R1 = R0.rotated("R1", about=R0.k, angle=psi)
    >>> u = 2 * R0.i + 3 * R1.j
    >>> u.components(R0).T
    Matrix([[2 - 3*sin(psi(t)), 3*cos(psi(t)), 0]])
    >>> u.dt(R0)
    -3*Derivative(psi(t), t)*R1.i
    """

    __slots__ = ("_parts", "_hash")

    def __init__(self, *args, **kwargs):
        raise TypeError(
            "build a Vector from basis vectors (2*R0.i + R0.j), with Frame.vector(x, y, z) "
            "or with Vector.from_components(frame, components)."
        )

    # -- construction -------------------------------------------------------------------
    @classmethod
    def _from_parts(cls, parts):
        obj = object.__new__(cls)
        obj._parts = tuple(parts)
        obj._hash = None
        return obj

    @classmethod
    def zero(cls) -> Vector:
        """The zero vector.

        Examples
        --------
        >>> Vector.zero()
        0
        """
        return cls._from_parts(())

    @classmethod
    def from_components(cls, frame, components) -> Vector:
        """The vector with the given components in the basis of ``frame``.

        Parameters
        ----------
        frame : Frame
        components : sequence of 3 scalars (numbers or sympy expressions)

        Examples
        --------
        >>> from rigidmech.vectors import Frame
        >>> R0 = Frame("R0")
        >>> Vector.from_components(R0, [1, 0, -2])
        R0.i - 2*R0.k
        """
        _check_frame(frame, "frame")
        try:
            items = tuple(components)
            if isinstance(components, str) or any(isinstance(c, str) for c in items):
                raise TypeError("a string is not read as a symbol")
            comps = tuple(sp.sympify(c) for c in items)
        except (sp.SympifyError, TypeError) as exc:
            raise ArgumentTypeError(
                f"`components` must be 3 numbers or sympy expressions; got {components!r}."
            ) from exc
        if len(comps) != 3:
            raise ArgumentError(
                f"`components` must have 3 entries; got {len(comps)}: {components!r}."
            )
        if any(isinstance(c, sp.MatrixBase) for c in comps):
            raise ArgumentTypeError("`components` must be scalars; got a matrix entry.")
        if any(not isinstance(c, sp.Expr) or (c.is_Number and c.is_finite is not True)
               for c in comps):
            raise ArgumentError(
                f"`components` must be finite real numbers or sympy expressions; got "
                f"{components!r}.")
        # Float(0.0) != 0 in sympy: normalise float zeros so that zero tests stay exact.
        comps = tuple(ZERO if c.is_Float and c.is_zero else c for c in comps)
        if all(c == 0 for c in comps):
            return cls.zero()
        return cls._from_parts(((frame, comps),))

    # -- access -------------------------------------------------------------------------
    @property
    def parts(self):
        """Tuple of ``(frame, (x, y, z))``: the components in each basis used."""
        return self._parts

    @property
    def frames(self):
        """The frames whose bases this vector uses."""
        return tuple(f for f, _ in self._parts)

    @property
    def is_zero(self) -> bool:
        """True if the vector is structurally zero (no non-zero component)."""
        return not self._parts

    def _comps(self, frame):
        if len(self._parts) == 1 and self._parts[0][0] is frame:
            return self._parts[0][1]
        return _components(self._parts, frame)

    def components(self, frame) -> sp.ImmutableMatrix:
        """Column of the components in the basis of ``frame``.

        Examples
        --------
        >>> from rigidmech.vectors import Frame
        >>> R0 = Frame("R0")
        >>> (R0.i + R0.k).components(R0).T
        Matrix([[1, 0, 1]])
        """
        _check_frame(frame, "frame")
        return sp.ImmutableMatrix(3, 1, self._comps(frame))

    def express(self, frame) -> Vector:
        """The same vector with all its parts in the basis of ``frame``.

        Examples
        --------
        >>> from rigidmech.vectors import Frame, coordinates
        >>> q = coordinates("q")
        >>> R0 = Frame("R0"); R1 = R0.rotated("R1", about=R0.k, angle=q)
        >>> R1.i.express(R0)
        cos(q(t))*R0.i + sin(q(t))*R0.j
        """
        _check_frame(frame, "frame")
        if len(self._parts) == 1 and self._parts[0][0] == frame:
            return self
        comps = self._comps(frame)
        if all(c == 0 for c in comps):
            return Vector.zero()
        return Vector._from_parts(((frame, comps),))

    # -- algebra ------------------------------------------------------------------------
    def __add__(self, other):
        if not isinstance(other, Vector):
            if other == 0:
                return self
            return NotImplemented
        if not other._parts:
            return self
        if not self._parts:
            return other
        merged = dict(self._parts)
        for f, c in other._parts:
            if f in merged:
                old = merged[f]
                merged[f] = tuple(a + b for a, b in zip(old, c, strict=True))
            else:
                merged[f] = c
        return Vector._from_parts(
            (f, c) for f, c in merged.items() if _any_nonzero(c)
        )

    def __radd__(self, other):
        if isinstance(other, int | float | sp.Expr) and other == 0:
            return self
        return NotImplemented

    def __rsub__(self, other):
        if isinstance(other, int | float | sp.Expr) and other == 0:
            return -self
        return NotImplemented

    def __neg__(self):
        return Vector._from_parts((f, tuple(-x for x in c)) for f, c in self._parts)

    def __sub__(self, other):
        if not isinstance(other, Vector):
            if other == 0:
                return self
            return NotImplemented
        return self + (-other)

    def __mul__(self, scalar):
        if isinstance(scalar, Vector):
            raise ArgumentTypeError(
                "the product of two vectors is ambiguous: use u.dot(v) for the scalar product "
                "and u.cross(v) for the vector product."
            )
        try:
            s = sp.sympify(scalar)
        except (sp.SympifyError, TypeError):
            return NotImplemented
        if not isinstance(s, sp.Expr):
            return NotImplemented
        _check_scalar(scalar, s)
        if is_exactly_zero(s):
            return Vector.zero()
        if s == 1:
            return self
        return Vector._from_parts((f, tuple(s * x for x in c)) for f, c in self._parts)

    __rmul__ = __mul__

    def __truediv__(self, scalar):
        if isinstance(scalar, Vector):
            raise ArgumentTypeError(
                "`scalar` must be a number or a sympy expression; got a Vector (a vector "
                "cannot be divided by a vector)."
            )
        try:
            s = sp.sympify(scalar)
        except (sp.SympifyError, TypeError):
            return NotImplemented
        if not isinstance(s, sp.Expr):
            return NotImplemented
        _check_scalar(scalar, s)
        if s == 0:
            raise ArgumentError("`scalar` must be non-zero to divide a vector; got 0.")
        return self * (1 / s)

    def dot(self, other) -> sp.Expr:
        """Scalar product (book, ch. 1.3).

        Examples
        --------
        >>> from rigidmech.vectors import Frame, coordinates
        >>> q = coordinates("q")
        >>> R0 = Frame("R0"); R1 = R0.rotated("R1", about=R0.k, angle=q)
        >>> R0.i.dot(R1.i)
        cos(q(t))
        """
        _check_vector(other, "other")
        if len(self._parts) * len(other._parts) > 4:
            # Many bases on both sides: one change of basis per part beats a direction-
            # cosine product per pair of parts (chains of n bodies: n^2 pairs, n parts).
            frame = other._parts[-1][0]
            return dot3(self._comps(frame), other._comps(frame))
        terms = []
        for fa, ca in self._parts:
            for fb, cb in other._parts:
                if fa is fb or fa == fb:
                    terms.append(dot3(ca, cb))
                else:
                    terms.append(bilinear(ca, direction_cosines(fa, fb), cb))
        return sp.Add(*terms) if terms else ZERO

    def cross(self, other) -> Vector:
        """Vector product (book, ch. 1.4), computed part by part in the basis that keeps the
        converted operand shortest.

        Examples
        --------
        >>> from rigidmech.vectors import Frame
        >>> R0 = Frame("R0")
        >>> R0.i.cross(R0.j)
        R0.k
        """
        _check_vector(other, "other")
        acc = {}
        for fa, ca in self._parts:
            for fb, cb in other._parts:
                if fa is fb or fa == fb:
                    frame, w = fa, _cross3(ca, cb)
                else:
                    cb_in_a = matvec(direction_cosines(fa, fb), cb)
                    if _nonzero(cb_in_a) <= _nonzero(cb):
                        frame, w = fa, _cross3(ca, cb_in_a)
                    else:
                        ca_in_b = matvec(direction_cosines(fb, fa), ca)
                        if _nonzero(ca_in_b) <= _nonzero(ca):
                            frame, w = fb, _cross3(ca_in_b, cb)
                        else:
                            frame, w = fa, _cross3(ca, cb_in_a)
                old = acc.get(frame)
                acc[frame] = w if old is None else tuple(
                    a + b for a, b in zip(old, w, strict=True))
        return Vector._from_parts((f, c) for f, c in acc.items() if _any_nonzero(c))

    def magnitude(self) -> sp.Expr:
        """Norm of the vector (book, ch. 1.3.2).

        Examples
        --------
        >>> from rigidmech.vectors import Frame
        >>> R0 = Frame("R0")
        >>> (3 * R0.i + 4 * R0.j).magnitude()
        5
        """
        return sp.sqrt(self.dot(self))

    def normalized(self) -> Vector:
        """The unit vector of the same direction.

        Raises
        ------
        ArgumentError
            For the zero vector, also when it is zero only after simplification.

        Examples
        --------
        >>> from rigidmech.vectors import Frame
        >>> R0 = Frame("R0")
        >>> (2 * R0.k).normalized()
        R0.k
        """
        if self.is_zero:
            raise ArgumentError("cannot normalise the zero vector: it has no direction.")
        square = self.dot(self)
        if is_identically_zero(square):
            raise ArgumentError(
                f"cannot normalise the zero vector: {self!r} simplifies to zero, it has no "
                "direction.")
        return self / sp.sqrt(square)

    # -- calculus -----------------------------------------------------------------------
    def dt(self, frame) -> Vector:
        """Derivative with respect to time relative to ``frame`` (book, ch. 3.1, 9.2.3).

        Each part is differentiated in its own basis and the derivation formula adds
        omega(basis/frame) ^ part.

        Examples
        --------
        >>> from rigidmech.vectors import Frame, coordinates
        >>> q = coordinates("q")
        >>> R0 = Frame("R0"); R1 = R0.rotated("R1", about=R0.k, angle=q)
        >>> R1.i.dt(R0)
        Derivative(q(t), t)*R1.j
        >>> R1.i.dt(R1)
        0
        """
        _check_frame(frame, "frame")
        out = Vector.zero()
        for f, c in self._parts:
            out = out + _dt_part(f, c, frame)
        return out

    def diff(self, variable, frame=None) -> Vector:
        """Partial derivative with respect to ``variable`` (book, ch. 3.2-3.3).

        Relative to ``frame`` each part is differentiated in its own basis and the
        derivation formula adds the partial rotation vector of that basis:
        du/dx|R = du/dx|F + Omega_x(F/R) ^ u, with Omega_x(F/R) = d omega(F/R) / dx'
        (see :func:`partial_rotation_vector`). Parts stay in their own bases.

        Parameters
        ----------
        variable : sympy expression
            A symbol, a parameter ``q(t)`` or a derivative ``q'(t)``.
        frame : Frame, optional
            Frame relative to which the derivative is taken. May be omitted only when no
            basis used by the vector depends on ``variable``.

        Examples
        --------
        >>> from rigidmech.vectors import Frame, coordinates, t
        >>> q = coordinates("q")
        >>> R0 = Frame("R0"); R1 = R0.rotated("R1", about=R0.k, angle=q)
        >>> (q.diff(t) * R1.j).diff(q.diff(t))
        R1.j
        >>> R1.i.diff(q, R0)
        R1.j
        """
        if frame is not None:
            _check_frame(frame, "frame")
        variable = sp.sympify(variable)
        out = Vector.zero()
        for f, c in self._parts:
            d = tuple(_partial(x, variable) if x.has(variable) else ZERO for x in c)
            if _any_nonzero(d):
                out = out + Vector._from_parts(((f, d),))
            if frame is None:
                if _frame_depends_on(f, f.root, variable):
                    raise FrameError(
                        f"the basis of {f.name} depends on {variable}: pass `frame`, the "
                        "frame relative to which the partial derivative is taken."
                    )
            elif f != frame:
                w = partial_rotation_vector(f, frame, variable)
                if w._parts:
                    out = out + w.cross(Vector._from_parts(((f, c),)))
        return out

    def compact(self) -> Vector:
        """The same vector with each part along one axis moved into another part's basis
        when that axis is also an axis of the other basis (k of frames turning about k, for
        instance): such parts join instead of standing apart. Not done automatically: it
        needs direction cosines between every pair of bases used.

        Examples
        --------
        >>> from rigidmech.vectors import Frame, coordinates
        >>> q1, q2 = coordinates("q1 q2")
        >>> R0 = Frame("R0")
        >>> R1 = R0.rotated("R1", about=R0.k, angle=q1)
        >>> R2 = R0.rotated("R2", about=R0.k, angle=q2)
        >>> (2 * R1.k + 3 * R2.k + R2.i).compact()
        R2.i + 5*R2.k
        """
        parts = list(self._parts)
        changed = True
        while changed and len(parts) > 1:
            changed = False
            for a in range(len(parts)):
                fa, ca = parts[a]
                if _nonzero(ca) != 1:
                    continue
                for b in range(len(parts)):
                    if a == b:
                        continue
                    fb, cb = parts[b]
                    moved = matvec(direction_cosines(fb, fa), ca)
                    if _nonzero(moved) == 1:
                        merged = tuple(x + y for x, y in zip(cb, moved, strict=True))
                        parts[b] = (fb, merged)
                        del parts[a]
                        changed = True
                        break
                if changed:
                    break
        return Vector._from_parts((f, c) for f, c in parts if _any_nonzero(c))

    # -- element-wise transforms --------------------------------------------------------
    def applyfunc(self, func) -> Vector:
        """Apply ``func`` to every component (of every part).

        Examples
        --------
        >>> import sympy as sp
        >>> from rigidmech.vectors import Frame
        >>> x = sp.Symbol("x")
        >>> R0 = Frame("R0")
        >>> ((x + x) * R0.i).applyfunc(lambda c: c / 2)
        x*R0.i
        """
        return Vector._from_parts(
            (f, cc) for f, cc in ((f, tuple(sp.sympify(func(x)) for x in c))
                                  for f, c in self._parts) if _any_nonzero(cc)
        )

    def subs(self, *args, **kwargs) -> Vector:
        """Substitute in every component and in the frames whose bases the vector uses
        (their angles and origins, see :meth:`Frame.subs`), with sympy's ``subs``
        arguments: the result no longer depends on what was substituted.

        Examples
        --------
        >>> import sympy as sp
        >>> from rigidmech.vectors import Frame, coordinates
        >>> a = sp.Symbol("a"); R0 = Frame("R0")
        >>> (a * R0.i).subs(a, 2)
        2*R0.i
        >>> q = coordinates("q"); R1 = R0.rotated("R1", about=R0.k, angle=q)
        >>> R1.i.subs(q, 0).components(R0).T
        Matrix([[1, 0, 0]])
        """
        return self._subs(args, kwargs, {})

    def _subs(self, args, kwargs, memo):
        acc = {}
        for f, c in self._parts:
            g = f._subs(args, kwargs, memo)
            cc = tuple(x.subs(*args, **kwargs) for x in c)
            old = acc.get(g)
            acc[g] = cc if old is None else tuple(a + b for a, b in zip(old, cc, strict=True))
        return Vector._from_parts((g, c) for g, c in acc.items() if _any_nonzero(c))

    def xreplace(self, rule) -> Vector:
        """Exact structural replacement in every component (sympy's ``xreplace``); unlike
        :meth:`subs`, the frames are left as they are."""
        return self.applyfunc(lambda x: x.xreplace(rule))

    def simplify(self, frame=None) -> Vector:
        """Simplified components, optionally after expressing in ``frame``.

        Examples
        --------
        >>> import sympy as sp
        >>> from rigidmech.vectors import Frame
        >>> x = sp.Symbol("x"); R0 = Frame("R0")
        >>> ((sp.sin(x)**2 + sp.cos(x)**2) * R0.i).simplify()
        R0.i
        """
        v = self if frame is None else self.express(frame)
        return v.applyfunc(sp.simplify)

    # -- comparison ---------------------------------------------------------------------
    def equals(self, other, frame=None) -> bool:
        """Symbolic equality: the difference simplifies to zero in one basis.

        Examples
        --------
        >>> from rigidmech.vectors import Frame, coordinates
        >>> q = coordinates("q")
        >>> R0 = Frame("R0"); R1 = R0.rotated("R1", about=R0.k, angle=q)
        >>> R1.i.equals(R1.i.express(R0))
        True
        """
        _check_vector(other, "other")
        diff = self - other
        if diff.is_zero:
            return True
        frame = frame if frame is not None else diff._parts[0][0]
        return all(sp.simplify(c) == 0 for c in diff._comps(frame))

    def is_close(self, other, *, rtol=1e-9, atol=0.0, frame=None) -> bool:
        """Numeric closeness component-wise in one basis (components must be numbers).

        Examples
        --------
        >>> from rigidmech.vectors import Frame
        >>> R0 = Frame("R0")
        >>> (R0.i * 1.0).is_close(R0.i * (1 + 1e-12))
        True
        """
        _check_vector(other, "other")
        if frame is not None:
            _check_frame(frame, "frame")
        frames = self.frames + other.frames
        if not frames:
            return True
        frame = frame if frame is not None else frames[0]
        try:
            a = np.array([complex(x) for x in self._comps(frame)])
            b = np.array([complex(x) for x in other._comps(frame)])
        except TypeError as exc:
            raise ArgumentError(
                "`is_close` needs numeric components; substitute values first or use "
                "`equals` for symbolic comparison."
            ) from exc
        return bool(np.allclose(a, b, rtol=rtol, atol=atol))

    def __eq__(self, other):
        if isinstance(other, Vector):
            return set(self._parts) == set(other._parts)
        if isinstance(other, int | float | sp.Expr) and other == 0:
            return self.is_zero
        return NotImplemented

    def __hash__(self):
        if self._hash is None:
            self._hash = hash(frozenset(self._parts))
        return self._hash

    # -- printing -----------------------------------------------------------------------
    def _terms(self, fmt_coeff, fmt_unit):
        out = []
        for f, c in self._parts:
            for n, x in enumerate(c):
                if x == 0:
                    continue
                unit = fmt_unit(f, n)
                if x == 1:
                    out.append(unit)
                elif x == -1:
                    out.append("-" + unit)
                else:
                    out.append(fmt_coeff(x) + unit)
        return out

    @staticmethod
    def _join(terms):
        if not terms:
            return "0"
        s = terms[0]
        for term in terms[1:]:
            s += " - " + term[1:] if term.startswith("-") else " + " + term
        return s

    def __repr__(self):
        def coeff(x):
            s = sp.sstr(x)
            if isinstance(x, sp.Add):
                s = f"({s})"
            return s + "*"

        return self._join(self._terms(coeff, lambda f, n: f"{f.label}.{'ijk'[n]}"))

    def __str__(self):
        def coeff(x):
            s = sp.sstr(x)
            return (f"({s})" if isinstance(x, sp.Add) else s) + " "

        return self._join(self._terms(coeff, lambda f, n: f"{'ijk'[n]}_{f.label}"))

    def _latex(self, printer=None):
        printer = printer or LatexPrinter()

        def coeff(x):
            s = printer._print(x)
            return (rf"\left({s}\right)" if isinstance(x, sp.Add) else s) + " "

        def unit(f, n):
            name = sp.latex(sp.Symbol(f.name))
            if f._at is not None:
                at = f._at.replace("_", r"\_")
                name += rf"\left[\mathrm{{{at}}}\right]"
            return rf"\vec{{{'ijk'[n]}}}_{{{name}}}"

        return self._join(self._terms(coeff, unit))

    def _repr_latex_(self):
        return f"$\\displaystyle {self._latex()}$"


@lru_cache(maxsize=65536)
def _components(parts, frame):
    """Components in the basis of ``frame`` of the vector made of ``parts`` (memoised: the
    same partial velocities are dotted with many others in a derivation)."""
    acc = [ZERO, ZERO, ZERO]
    for f, c in parts:
        v = c if (f is frame or f == frame) else matvec(direction_cosines(frame, f), c)
        for n in range(3):
            if v[n] != 0:
                acc[n] = acc[n] + v[n]
    return tuple(acc)


@lru_cache(maxsize=65536)
def _dt_part(f, c, frame):
    """d/dt|frame of the part ``c`` (components in the basis of ``f``), memoised: bodies of a
    chain share the parts of their position vectors, so each is differentiated once."""
    d = tuple(time_derivative(x) for x in c)
    out = Vector._from_parts(((f, d),)) if _any_nonzero(d) else Vector.zero()
    if f != frame:
        w = rotation_vector(f, frame)
        if w._parts:
            out = out + w.cross(Vector._from_parts(((f, c),)))
    return out


def _check_vector(v, argument):
    if not isinstance(v, Vector):
        raise ArgumentTypeError(f"`{argument}` must be a Vector; got {type(v).__name__}.")


def _frame_depends_on(f, relative_to, variable):
    """Whether the basis of ``f`` moves relative to ``relative_to`` with ``variable``."""
    if f == relative_to:
        return False
    anc = common_ancestor(f, relative_to)
    for g in path_to_ancestor(f, anc) + path_to_ancestor(relative_to, anc):
        value = g._angle if g._axis is not None else g._matrix
        if sp.sympify(value).has(variable) if g._axis is not None else any(
                x.has(variable) for row in value for x in row):
            return True
    return False


def dot(u: Vector, v: Vector):
    """Scalar product u . v (book, ch. 1.3).

    Examples
    --------
    >>> from rigidmech.vectors import Frame
    >>> R0 = Frame("R0")
    >>> dot(R0.i + R0.j, R0.j)
    1
    """
    _check_vector(u, "u")
    return u.dot(v)


def cross(u: Vector, v: Vector) -> Vector:
    """Vector product u ^ v (book, ch. 1.4).

    Examples
    --------
    >>> from rigidmech.vectors import Frame
    >>> R0 = Frame("R0")
    >>> cross(R0.j, R0.k)
    R0.i
    """
    _check_vector(u, "u")
    return u.cross(v)


def mixed(u: Vector, v: Vector, w: Vector):
    """Mixed product (u, v, w) = u . (v ^ w) (book, ch. 1.4.5).

    Examples
    --------
    >>> from rigidmech.vectors import Frame
    >>> R0 = Frame("R0")
    >>> mixed(R0.i, R0.j, R0.k)
    1
    """
    _check_vector(u, "u")
    _check_vector(v, "v")
    return u.dot(v.cross(w))


def _own_rotation(f, variable=None):
    """omega(f / f.parent) as a 3-tuple in the basis of f; with ``variable``, its partial
    derivative with respect to the rate of ``variable`` (the partial rotation vector)."""

    def rate(x):
        return time_derivative(x) if variable is None else (
            _partial(x, variable) if x.has(variable) else ZERO)

    if f._axis is not None:
        r = rate(f._angle)
        return tuple(r if n == f._axis else ZERO for n in range(3))
    e = euler_parameters_of(f)
    if e is not None:
        return _euler_parameter_rotation(e, [rate(x) for x in e])
    c = f._matrix
    cdot = tuple(tuple(rate(x) for x in row) for row in c)
    w = matmul(transpose(c), cdot)  # skew: [[0,-wz,wy],[wz,0,-wx],[-wy,wx,0]]
    return tuple(sp.simplify(x) for x in (w[2][1], w[0][2], w[1][0]))


def _euler_parameter_rotation(e, rates):
    """omega of the frame of Euler parameters ``e`` (its matrix normalised by |e|^2, see
    :mod:`rigidmech.vectors.euler_parameters`) in its own basis, from the rates e' (or their
    partial derivatives: the expression is linear in them):
    omega = 2 vec(conj(e) * e') / |e|^2. The axial vector of C^T C' for C of p = e / |e| is
    2 vec(conj(p) * p'), and vec(conj(e) * e) = 0 leaves only the term above; written in
    closed form here because ``simplify`` of C^T C' took seconds (book, ch. 9.1.2)."""
    a, b, c, d = e
    da, db, dc, dd = rates
    k = 2 / (a**2 + b**2 + c**2 + d**2)
    return (k * (a * db - b * da + d * dc - c * dd),
            k * (a * dc - c * da + b * dd - d * db),
            k * (a * dd - d * da + c * db - b * dc))


@lru_cache(maxsize=16384)
def rotation_vector(frame, relative_to) -> Vector:
    """The rotation vector omega(frame/relative_to) (book, ch. 9.2.3).

    For an elementary rotation by q about an axis the contribution is q' times that axis;
    for a general rotation C(t) it is the axial vector of C^T C'. Contributions are summed
    along the path through the common ancestor (composition of rotations, ch. 9.3.1), each
    in the basis of ``frame`` when that keeps it as short, otherwise in its own basis.

    Examples
    --------
    >>> from rigidmech.vectors import Frame, coordinates
    >>> q = coordinates("q")
    >>> R0 = Frame("R0")
    >>> R1 = R0.rotated("R1", about=R0.j, angle=q)
    >>> rotation_vector(R0, R1)
    -Derivative(q(t), t)*R0.j
    """
    _check_frame(frame, "frame")
    _check_frame(relative_to, "relative_to")
    return _rotation(frame, relative_to, None)


@lru_cache(maxsize=16384)
def partial_rotation_vector(frame, relative_to, variable) -> Vector:
    """The partial rotation vector Omega_q(frame/relative_to) = d omega / d q' (ch. 25.1.2).

    omega(frame/relative_to) is linear in the rates of the parameters of situation; this is
    the coefficient of the rate of ``variable``: d/dq|R of a vector fixed in ``frame`` is
    Omega_q ^ u. For a variable on which no rotation depends it is zero.

    Examples
    --------
    >>> from rigidmech.vectors import Frame, coordinates
    >>> q1, q2 = coordinates("q1 q2")
    >>> R0 = Frame("R0")
    >>> R2 = R0.rotated("R1", about=R0.k, angle=q1).rotated("R2", about=R0.k, angle=q2)
    >>> partial_rotation_vector(R2, R0, q1)
    R2.k
    """
    _check_frame(frame, "frame")
    _check_frame(relative_to, "relative_to")
    return _rotation(frame, relative_to, sp.sympify(variable))


def _rotation(frame, relative_to, variable):
    if frame == relative_to:
        return Vector.zero()
    anc = common_ancestor(frame, relative_to)
    acc = {frame: (ZERO, ZERO, ZERO)}

    def add(f, sign):
        w = _own_rotation(f, variable)
        if all(x == 0 for x in w):
            return
        w = tuple(sign * x for x in w)
        # Keep each contribution in a basis where it stays as short as in its own: the
        # moving frame first, then a basis already used; else its own (book's form, e.g.
        # psi' k0 + theta' u + phi' k for Euler angles).
        for g in acc:
            wg = w if g == f else matvec(direction_cosines(g, f), w)
            if _nonzero(wg) <= _nonzero(w):
                acc[g] = tuple(a + b for a, b in zip(acc[g], wg, strict=True))
                return
        acc[f] = w

    for f in path_to_ancestor(frame, anc):
        add(f, 1)
    for f in path_to_ancestor(relative_to, anc):
        add(f, -1)
    return Vector._from_parts((g, c) for g, c in acc.items() if _any_nonzero(c))
