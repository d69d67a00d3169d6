"""Singular sets of orientation parametrisations (book, ch. 9.1.2).

Three angles locate a body's basis relative to a reference (ch. 9.1.2: precession psi,
nutation theta, spin phi), but no three angles do so everywhere: the rotation vector

.. math:: \\boldsymbol{\\omega} = \\dot q_1\\,\\mathbf{e}_1 + \\dot q_2\\,\\mathbf{e}_2
          + \\dot q_3\\,\\mathbf{e}_3

is a combination of the three axes of rotation e_1, e_2, e_3, and where they fall in one
plane some rotation vectors are not reached and the rates of the angles are not determined
(gimbal lock). For the Euler angles z-x-z, e_1 = k0, e_2 = u (line of nodes), e_3 = k and the
mixed product (e_1, e_2, e_3) is -sin(theta): the parametrisation is singular where
sin(theta) = 0, the body's k axis along k0, where only psi + phi is defined. For the Cardan
(Tait-Bryan) sequences, with three different axes such as z-y-x, it is singular where the
cosine of the middle angle vanishes.

:func:`orientation_singularity` (also :meth:`Frame.singular_set`) finds this set for the chain
of rotations between two frames, whatever the sequence of elementary rotations: it returns an
:class:`OrientationSingularity` holding the condition as a sympy expression of the angles and
a numeric measure of the distance to it. Near the set the mass matrix of the equations of
motion is nearly singular: a simulation that comes close loses accuracy and needs many small
steps (rigidmech warns, see :class:`rigidmech._core.errors.SingularityWarning`).
"""

from __future__ import annotations

import numpy as np
import sympy as sp

from .._core.compile import compile_expressions
from .._core.errors import ArgumentError, ArgumentTypeError, FrameError
from ._rotations import FrameBase, common_ancestor, path_to_ancestor, rotation_steps
from .euler_parameters import euler_parameters_of
from .symbols import is_coordinate
from .symbols import t as _t
from .vector import partial_rotation_vector

__all__ = ["OrientationSingularity", "orientation_singularity"]

_AXES = "xyz"


def _coordinates_of(steps):
    found = []
    for _, value in steps:
        exprs = [value] if not isinstance(value, tuple) else [x for row in value for x in row]
        for e in exprs:
            for a in sorted(sp.sympify(e).atoms(sp.core.function.AppliedUndef), key=str):
                if is_coordinate(a) and a not in found:
                    found.append(a)
    return found


def _frames_between(a, b):
    anc = common_ancestor(a, b)
    return [a, b, anc, *path_to_ancestor(a, anc), *path_to_ancestor(b, anc)]


def _tidy(expr):
    """Expand; call trigsimp (costly: about 0.1 s) only if that leaves a long expression."""
    expr = sp.expand(expr)
    return expr if sp.count_ops(expr) <= 4 else sp.trigsimp(expr)


def _axes_matrix(vectors, frames):
    """The unit axes as the columns of a 3x3 (or 3xn) matrix, in the basis among ``frames``
    where they are shortest (for z-x-z the nutation frame: (0, sin, cos), (1, 0, 0),
    (0, 0, 1)), so that their mixed product needs no trigonometric simplification."""
    best, best_ops = None, None
    for f in dict.fromkeys(frames):
        cols = [sp.Matrix(v.components(f)) for v in vectors]
        ops = sum(sp.count_ops(list(c)) for c in cols)
        if best is None or ops < best_ops:
            best, best_ops = cols, ops
    unit = []
    for c in best:
        norm2 = _tidy(sum(x**2 for x in c))
        unit.append(c if norm2 == 1 else c / sp.sqrt(norm2))
    return sp.Matrix.hstack(*unit)


def _sequence(steps, coords):
    """The axes ("zxz", ...) when every step is an elementary rotation by one coordinate."""
    if len(steps) != len(coords) or any(axis is None for axis, _ in steps):
        return None
    for (_, angle), q in zip(steps, coords, strict=True):
        if angle not in (q, -q):
            return None
    return "".join(_AXES[axis] for axis, _ in steps)


class OrientationSingularity:
    """The singular set of the angles orienting ``frame`` relative to ``relative_to``.

    Made by :func:`orientation_singularity` or :meth:`Frame.singular_set`; not meant to be
    built directly.

    Attributes
    ----------
    frame, relative_to : Frame
    coordinates : tuple of q(t)
        The parameters of situation in the angles, in the order of the rotations.
    sequence : str or None
        The axes of the elementary rotations (``"zxz"`` for the Euler angles, ``"zyx"``
        for a Cardan sequence), None for another chain.
    expression : sympy expression
        The parametrisation is singular where it vanishes: the mixed product of the unit
        axes of the three rotations (``-sin(theta)`` for z-x-z), or for fewer than three
        angles the Gram determinant of the axes.
    condition : sympy.Eq
        ``Eq(expression, 0)``.
    parameters : tuple of sympy.Symbol
        Constants of ``expression`` (constant angles in the chain), sorted by name.

    Notes
    -----
    :meth:`measure` is :math:`|(\\mathbf{e}_1, \\mathbf{e}_2, \\mathbf{e}_3)|` with unit axes,
    between 0 (on the set) and 1: for a sequence of elementary rotations about perpendicular
    axes it is :math:`|\\sin\\theta|` for the Euler angles and :math:`|\\cos\\theta|` for a
    Cardan sequence (theta the middle angle), so that
    :meth:`distance`, its arcsine, is the angle between the middle angle and its nearest
    singular value.

    Examples
    --------
    >>> from rigidmech.vectors import Frame, coordinates
    >>> psi, theta, phi = coordinates("psi theta phi")
    >>> s = Frame("R0").euler("R", psi, theta, phi).singular_set()
    >>> s
    OrientationSingularity(frame=R, relative_to=R0, sequence='zxz', condition=Eq(sin(theta(t)), 0))
    >>> float(s.distance({"theta": 0.01, "psi": 1.0, "phi": 2.0}))
    0.01
    """

    __slots__ = ("_frame", "_relative_to", "_coordinates", "_sequence", "_expression",
                 "_measure", "_parameters", "_compiled")

    def __init__(self, *args, **kwargs):
        raise TypeError("get an OrientationSingularity from Frame.singular_set(relative_to) "
                        "or rigidmech.vectors.orientation_singularity(frame, relative_to).")

    @classmethod
    def _make(cls, frame, relative_to, coordinates, sequence, expression, measure):
        obj = object.__new__(cls)
        obj._frame, obj._relative_to = frame, relative_to
        obj._coordinates, obj._sequence = tuple(coordinates), sequence
        obj._expression, obj._measure = expression, measure
        known = set(coordinates)
        params = {s for s in measure.free_symbols if s not in known} - {_t}
        obj._parameters = tuple(sorted(params, key=lambda s: s.name))
        obj._compiled = None
        return obj

    frame = property(lambda self: self._frame, doc="The oriented frame.")
    relative_to = property(lambda self: self._relative_to, doc="The reference frame.")
    coordinates = property(lambda self: self._coordinates, doc="The angles q(t).")
    sequence = property(lambda self: self._sequence, doc="Axes of the rotations, or None.")
    expression = property(lambda self: self._expression, doc="Vanishes on the set.")
    parameters = property(lambda self: self._parameters, doc="Constants of the expression.")

    @property
    def condition(self) -> sp.Eq:
        """The singular set as an equation ``Eq(expression, 0)``."""
        return sp.Eq(self._expression, 0)

    def _values(self, values, params):
        if isinstance(values, dict):
            out = []
            for q in self._coordinates:
                name = q.func.__name__
                if q in values:
                    out.append(values[q])
                elif name in values:
                    out.append(values[name])
                else:
                    raise ArgumentError(
                        f"`values` must give the angle {name}; got the keys {list(values)}.")
            values = out
        try:
            arr = np.asarray(values, dtype=float)
        except (TypeError, ValueError) as exc:
            raise ArgumentTypeError(
                f"`values` must be numbers for {[q.func.__name__ for q in self._coordinates]}"
                f"; got {values!r}.") from exc
        if arr.ndim == 0 or arr.shape[0] != len(self._coordinates):
            raise ArgumentError(
                f"`values` must give {len(self._coordinates)} angles "
                f"({', '.join(q.func.__name__ for q in self._coordinates)}); got shape "
                f"{arr.shape}.")
        missing = [p.name for p in self._parameters if p.name not in params]
        if missing:
            raise ArgumentError(f"missing values for the constants {missing} of the angles; "
                                f"pass them as keywords.")
        return arr, [float(params[p.name]) for p in self._parameters]

    def measure(self, values, **params):
        """Absolute value of the mixed product of the unit axes at ``values``: 0 on the
        singular set, 1 at most.

        Parameters
        ----------
        values : sequence, array of shape (n_angles, ...), or mapping
            The angles in the order of :attr:`coordinates`, or a mapping from their names
            (or the q(t) themselves) to values; arrays broadcast.
        **params
            Values of :attr:`parameters`.

        Returns
        -------
        float, or ndarray of the shape of the trailing axes of ``values``

        Examples
        --------
        >>> from rigidmech.vectors import Frame, coordinates
        >>> a, b, c = coordinates("a b c")
        >>> R0 = Frame("R0")
        >>> R1 = R0.rotated("R1", about=R0.k, angle=a)
        >>> R2 = R1.rotated("R2", about=R1.j, angle=b)
        >>> R = R2.rotated("R", about=R2.i, angle=c)   # Cardan z-y-x
        >>> s = R.singular_set()
        >>> s.condition
        Eq(cos(b(t)), 0)
        >>> round(s.measure([0.0, 1.5, 0.0]), 4)   # |cos(1.5)|
        0.0707
        """
        arr, pv = self._values(values, params)
        if self._compiled is None:
            syms = [sp.Dummy(q.func.__name__) for q in self._coordinates]
            expr = self._measure.xreplace(dict(zip(self._coordinates, syms, strict=True)))
            self._compiled = compile_expressions(expr, [syms, *self._parameters],
                                                 name="singularity_measure")
        out = np.abs(np.asarray(self._compiled(arr, *pv), dtype=float))
        out = np.broadcast_to(out, arr.shape[1:]).copy()
        return float(out) if out.ndim == 0 else out

    def distance(self, values, **params):
        """arcsin of :meth:`measure`: for Euler and Cardan sequences, the angle (rad) between
        the middle angle and its nearest singular value.

        Examples
        --------
        >>> from rigidmech.vectors import Frame, coordinates
        >>> psi, theta, phi = coordinates("psi theta phi")
        >>> s = Frame("R0").euler("R", psi, theta, phi).singular_set()
        >>> s.distance([[0.0, 0.0], [3.1, 0.2], [0.0, 0.0]]).round(4)
        array([0.0416, 0.2   ])
        """
        out = np.arcsin(np.minimum(self.measure(values, **params), 1.0))
        return float(out) if np.ndim(out) == 0 else out

    def suggestion(self) -> str:
        """What to do near the set: another sequence whose singular set is elsewhere.

        Examples
        --------
        >>> from rigidmech.vectors import Frame, coordinates
        >>> psi, theta, phi = coordinates("psi theta phi")
        >>> Frame("R0").euler("R", psi, theta, phi).singular_set().suggestion()
        'use a Cardan sequence such as z-x-y instead (singular where cos(theta) = 0) ...'
        """
        seq = self._sequence
        if seq is not None and len(seq) == 3 and seq[1] not in (seq[0], seq[2]):
            middle = self._coordinates[1].func.__name__
            if seq[0] == seq[2]:
                other = next(a for a in _AXES if a not in seq)
                return (f"use a Cardan sequence such as {seq[0]}-{seq[1]}-{other} instead "
                        f"(singular where cos({middle}) = 0) or start the motion away from "
                        "the singular set")
            return (f"use the Euler sequence {seq[0]}-{seq[1]}-{seq[0]} instead (singular "
                    f"where sin({middle}) = 0) or start the motion away from the singular "
                    "set")
        return ("use another sequence of rotations whose singular set is away from this "
                "motion, or start the motion away from the singular set")

    def describe(self) -> str:
        """One line: which angles of which frame, and where they are singular.

        Examples
        --------
        >>> from rigidmech.vectors import Frame, coordinates
        >>> psi, theta, phi = coordinates("psi theta phi")
        >>> print(Frame("R0").euler("R", psi, theta, phi).singular_set().describe())
        the angles z-x-z (psi, theta, phi) of frame R relative to R0, singular where
        sin(theta) = 0
        """
        names = ", ".join(q.func.__name__ for q in self._coordinates)
        kind = f"the angles {'-'.join(self._sequence)}" if self._sequence else "the angles"
        cond = sp.sstr(self._expression.xreplace(
            {q: sp.Symbol(q.func.__name__) for q in self._coordinates}))
        return (f"{kind} ({names}) of frame {self._frame.name} relative to "
                f"{self._relative_to.name}, singular where {cond} = 0")

    def _key(self):
        return (self._frame, self._relative_to, self._coordinates, self._expression)

    def __eq__(self, other):
        return isinstance(other, OrientationSingularity) and self._key() == other._key()

    def __hash__(self):
        return hash(self._key())

    def __repr__(self):
        seq = f"{self._sequence!r}" if self._sequence else "None"
        return (f"OrientationSingularity(frame={self._frame.name}, "
                f"relative_to={self._relative_to.name}, sequence={seq}, "
                f"condition={self.condition})")


def orientation_singularity(frame, relative_to=None):
    """The singular set of the angles that orient ``frame`` relative to ``relative_to``
    (book, ch. 9.1.2), or None if they have none.

    The angles are the parameters of situation in the rotations between the two frames. The
    partial rotation vectors e_i = d omega / d q_i' (ch. 25.1.2) are the axes of rotation;
    the parametrisation is singular where they are linearly dependent: where their mixed
    product vanishes for three angles, their Gram determinant for one or two.

    Parameters
    ----------
    frame : Frame
    relative_to : Frame, optional
        The reference; defaults to the root of ``frame``'s tree.

    Returns
    -------
    OrientationSingularity or None
        None when there is no singular set (no angle; one or two angles about axes at a
        constant angle to each other, as for every chain of one or two elementary rotations;
        Euler parameters, :meth:`Frame.euler_parameters`).

    Raises
    ------
    FrameError
        If more than three angles lie between the frames (give a nearer ``relative_to``), or
        if the angles are redundant everywhere (two angles about one axis).

    Examples
    --------
    >>> from rigidmech.vectors import Frame, coordinates
    >>> psi, theta, phi = coordinates("psi theta phi")
    >>> R0 = Frame("R0")
    >>> orientation_singularity(R0.euler("R", psi, theta, phi)).condition
    Eq(sin(theta(t)), 0)
    >>> R1 = R0.rotated("R1", about=R0.k, angle=psi)
    >>> orientation_singularity(R1.rotated("R2", about=R1.i, angle=theta)) is None
    True
    """
    if not isinstance(frame, FrameBase):
        raise ArgumentTypeError(f"`frame` must be a Frame; got {type(frame).__name__}.")
    if relative_to is None:
        relative_to = frame.root
    if not isinstance(relative_to, FrameBase):
        raise ArgumentTypeError(
            f"`relative_to` must be a Frame; got {type(relative_to).__name__}.")
    steps = rotation_steps(relative_to, frame)
    coords = _coordinates_of(steps)
    if not coords:
        return None
    if len(steps) == 1 and steps[0][0] is None and any(
            euler_parameters_of(f) is not None for f in (frame, relative_to)):
        return None  # Euler parameters: a rotation for every e != 0
    if len(coords) > 3:
        raise FrameError(
            f"`relative_to`: {len(coords)} angles ({', '.join(str(q) for q in coords)}) lie "
            f"between {relative_to.name} and {frame.name}, more than a rotation has; give a "
            "nearer reference frame.")
    vectors = [partial_rotation_vector(frame, relative_to, q) for q in coords]
    E = _axes_matrix(vectors, _frames_between(relative_to, frame))
    if len(coords) == 3:
        expr = _tidy(E.det(method="berkowitz"))
        if expr.could_extract_minus_sign():
            expr = -expr
        measure = expr
    else:
        expr = _tidy((E.T * E).det(method="berkowitz"))
        measure = sp.sqrt(expr)
    if expr == 0:
        raise FrameError(
            f"the angles {', '.join(str(q) for q in coords)} between {relative_to.name} and "
            f"{frame.name} turn about dependent axes everywhere: they do not parametrise an "
            "orientation.")
    if expr.is_number:
        return None
    return OrientationSingularity._make(frame, relative_to, coords, _sequence(steps, coords),
                                        expr, measure)
