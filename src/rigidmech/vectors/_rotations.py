"""The structure of a frame tree and the direction cosines between two frames.

Private foundation of :mod:`rigidmech.vectors`: :class:`FrameBase` holds what makes a frame a
value (its parent, the rotation from the parent, its origin) and this module computes the
direction cosines between any two frames of a tree (book, ch. 1.5.2 and 2.5). Consecutive
rotations about the same axis are merged before any matrix is built, so that in a planar chain
the basis change between two frames is one rotation by the sum of the angles in between
(``cos(q2 + q3)``, not a product of trigonometric factors): this keeps equations of jointed
chains small (no expression swell). Results are memoised: they are pure functions of
immutable values.
"""

from __future__ import annotations

from functools import lru_cache

import sympy as sp

from .._core.errors import ArgumentError, FrameError

__all__ = ["FrameBase", "direction_cosines", "bilinear", "rotation_steps", "path_to_ancestor",
           "common_ancestor", "IDENTITY"]

ZERO = sp.S.Zero
ONE = sp.S.One
IDENTITY = ((ONE, ZERO, ZERO), (ZERO, ONE, ZERO), (ZERO, ZERO, ONE))


class FrameBase:
    """Structural part of a frame: name, parent, rotation from the parent, origin.

    ``axis`` is 0, 1 or 2 for an elementary rotation by ``angle`` about that axis of the
    parent, None for a general rotation given by ``matrix`` (the child's basis vectors, as
    columns, in the parent's basis).
    """

    __slots__ = ("_name", "_parent", "_axis", "_angle", "_matrix", "_origin", "_depth",
                 "_hash", "_basis", "_at")

    def _set(self, name, parent, axis, angle, matrix, origin):
        if not isinstance(name, str) or not name:
            raise ArgumentError(f"`name` must be a non-empty string; got {name!r}.")
        self._name = name
        self._parent = parent
        self._axis = axis
        self._angle = angle
        self._matrix = matrix
        self._origin = origin
        self._depth = 0 if parent is None else parent._depth + 1
        self._hash = hash((name, parent, axis, angle, matrix))
        self._basis = None
        self._at = None      # the values substituted into it (Frame.subs), for printing

    @property
    def name(self) -> str:
        """Name of the frame."""
        return self._name

    @property
    def parent(self):
        """The frame this one was made from, or None for a root."""
        return self._parent

    @property
    def root(self):
        """The root of this frame's tree."""
        f = self
        while f._parent is not None:
            f = f._parent
        return f

    def __eq__(self, other):
        if self is other:
            return True
        if not isinstance(other, FrameBase) or self._hash != other._hash:
            return False
        return (
            self._name == other._name
            and self._axis == other._axis
            and self._angle == other._angle
            and self._matrix == other._matrix
            and self._parent == other._parent
            and (self._parent is None or self._origin == other._origin)
        )

    def __hash__(self):
        return self._hash

    @property
    def label(self) -> str:
        """The name as printed: the name, followed for a frame made by ``subs`` by the
        values substituted into it, ``R1[theta=0]`` (R1 fixed at theta = 0 is not the
        moving R1: its basis has a zero derivative)."""
        return self._name if self._at is None else f"{self._name}[{self._at}]"

    def __str__(self):
        return self.label


def elementary(axis, angle):
    """Child basis (columns) in the parent basis for a rotation by ``angle`` about ``axis``."""
    c, s = sp.cos(angle), sp.sin(angle)
    if axis == 2:
        return ((c, -s, ZERO), (s, c, ZERO), (ZERO, ZERO, ONE))
    if axis == 0:
        return ((ONE, ZERO, ZERO), (ZERO, c, -s), (ZERO, s, c))
    return ((c, ZERO, s), (ZERO, ONE, ZERO), (-s, ZERO, c))


def dot3(u, v):
    """Scalar product of two 3-tuples of sympy expressions, skipping zero factors."""
    terms = [x * y for x, y in zip(u, v, strict=True) if x != 0 and y != 0]
    return sp.Add(*terms) if terms else ZERO


def bilinear(u, m, v):
    """u . (m v) for 3-tuples u, v and a 3x3 tuple matrix m, visiting only the non-zero
    entries of u and v (parts of mechanical vectors are mostly sparse)."""
    iu = [r for r in range(3) if u[r] != 0]
    iv = [c for c in range(3) if v[c] != 0]
    terms = []
    for r in iu:
        row = m[r]
        inner = [row[c] * v[c] for c in iv if row[c] != 0]
        if inner:
            terms.append(u[r] * (inner[0] if len(inner) == 1 else sp.Add(*inner)))
    return sp.Add(*terms) if terms else ZERO


def matvec(m, v):
    """3x3 tuple matrix times 3-tuple."""
    return (dot3(m[0], v), dot3(m[1], v), dot3(m[2], v))


def matmul(a, b):
    """Product of two 3x3 tuple matrices."""
    cols = [(b[0][c], b[1][c], b[2][c]) for c in range(3)]
    return tuple(tuple(dot3(a[r], cols[c]) for c in range(3)) for r in range(3))


def transpose(a):
    """Transpose of a 3x3 tuple matrix."""
    return tuple(tuple(a[c][r] for c in range(3)) for r in range(3))


def path_to_ancestor(frame, ancestor):
    """Frames from just below ``ancestor`` down to ``frame``, in that order."""
    path = []
    f = frame
    while f is not ancestor and f != ancestor:
        path.append(f)
        f = f._parent
    path.reverse()
    return path


def common_ancestor(a, b):
    """The deepest frame that is an ancestor of both (raises if the trees differ)."""
    fa, fb = a, b
    while fa._depth > fb._depth:
        fa = fa._parent
    while fb._depth > fa._depth:
        fb = fb._parent
    while fa is not fb:
        if fa == fb:
            return fa
        if fa._parent is None:
            raise FrameError(
                f"frames {a.name} and {b.name} belong to different trees (roots "
                f"{a.root.name} and {b.root.name}); build every frame from one root."
            )
        fa, fb = fa._parent, fb._parent
    return fa


def rotation_steps(a, b):
    """Rotations taking basis ``a`` to basis ``b``: a list of ``(axis, angle)`` for
    elementary rotations and ``(None, matrix)`` for general ones, same-axis runs merged."""
    anc = common_ancestor(a, b)
    steps = []
    for f in reversed(path_to_ancestor(a, anc)):
        steps.append((f._axis, -f._angle) if f._axis is not None
                     else (None, transpose(f._matrix)))
    for f in path_to_ancestor(b, anc):
        steps.append((f._axis, f._angle) if f._axis is not None else (None, f._matrix))
    # Zero rotations (translated frames, angles that cancel) are dropped as they appear, so
    # that the rotations on either side of them are merged too.
    merged = []
    for axis, value in steps:
        if axis is not None and value == 0:
            continue
        if axis is not None and merged and merged[-1][0] == axis:
            total = merged[-1][1] + value
            if total == 0:
                merged.pop()
            else:
                merged[-1] = (axis, total)
        else:
            merged.append((axis, value))
    return merged


@lru_cache(maxsize=16384)
def direction_cosines(a, b):
    """Direction cosines C (3x3 tuple): components in ``a`` = C @ components in ``b``.

    Its columns are ``b``'s basis vectors expressed in ``a`` (book, ch. 1.5.2).
    """
    if a is b or a == b:
        return IDENTITY
    out = None
    for axis, value in rotation_steps(a, b):
        m = value if axis is None else elementary(axis, value)
        out = m if out is None else matmul(out, m)
    return IDENTITY if out is None else out
