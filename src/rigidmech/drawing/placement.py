"""A system at a state, in numbers: where its points are and how its frames are turned.

:class:`Placer` compiles, once, the positions of a system's points (mass centres, frame
origins, the points of its connections) and the direction cosines of its frames relative to
the reference of its equations (book, ch. 1.5.2, 2.3.3), as functions of the parameters of
situation q, the time t and the constants; :meth:`Placer.at` evaluates them at one state and
returns a :class:`Placement`, the numbers every drawing is made from. :func:`place` does both
for one state.
"""

from __future__ import annotations

import numpy as np
import sympy as sp

from .._core.errors import ArgumentError, ArgumentTypeError
from ..actions import Damper, Gravity, Joint, Spring
from ..vectors import Frame, Point, Vector, t

__all__ = ["Placer", "Placement", "place", "connection_point"]


def connection_point(connection):
    """The point where a connection is drawn: a joint's centre ``at``, a contact's point, a
    knife edge's point, a gear mesh's pitch point; None for a connection without one.

    Examples
    --------
    >>> import rigidmech as rm
    >>> R0 = rm.Frame("R0")
    >>> connection_point(rm.joints.Pivot(at=R0.point("A", 1, 0, 0), axis=R0.k)).name
    'A'
    """
    if isinstance(connection, Joint):
        return connection.at
    for name in ("contact", "at", "pitch_point"):
        value = getattr(connection, name, None)
        if isinstance(value, Point):
            return value
        if value is not None and isinstance(getattr(value, "point", None), Point):
            return value.point
    return None


def _system_of(system):
    """A System from a System or a Model of :mod:`rigidmech.models`."""
    inner = getattr(system, "system", None)
    system = inner if inner is not None and hasattr(inner, "bodies") else system
    if not (hasattr(system, "bodies") and hasattr(system, "mechanism")):
        raise ArgumentTypeError(
            f"`system` must be a rigidmech System (or a Model of rigidmech.models); got "
            f"{type(system).__name__}.")
    return system


class Placer:
    """The positions and orientations of a system, compiled for numbers (ch. 1.5.2, 2.3.3).

    Parameters
    ----------
    system : System or Model
        The system (a :class:`~rigidmech.models.Model`'s system is taken).
    params : dict, optional
        Values of the constants, by name or symbol (``{"L": 1.0}``); those the positions
        depend on are required, the others (``g``, masses) are accepted and ignored.
    points : sequence of Point, optional
        More points to compile besides the mass centres, frame origins and connection
        points.

    Raises
    ------
    ArgumentError
        If a constant the positions depend on has no value, a name is not a constant of
        the system, or a value is not a finite number.

    Examples
    --------
    >>> from rigidmech import models
    >>> dp = models.double_pendulum()
    >>> placer = Placer(dp, {"L": 1.0})
    >>> [str(q) for q in placer.coordinates], placer.plane
    (['theta1(t)', 'theta2(t)'], 2)
    >>> placer.at([0.0, 0.0]).point("G2").round(6).tolist()
    [1.5, 0.0, 0.0]
    """

    def __init__(self, system, params=None, *, points=()):
        self._system = system = _system_of(system)
        self._reference = ref = system.reference
        self._coordinates = tuple(system.coordinates)
        frames, pts = [], []
        for body in system.bodies:
            frames.append(body.frame)
            if body.shape is not None:
                frames.append(body.shape.frame)
            pts.append(body.centre)
        meets = getattr(system, "meets", None)     # a loop's closing point (dynamics)
        for link in system.mechanism.links:
            p = connection_point(link.connection)
            if p is not None:
                pts.append(p)
            other = None if meets is None else meets(link)
            if other is not None:
                pts.append(getattr(other, "origin", other))
        for _, _, contact in system.contacts:
            pts.append(contact.contact.point)
        for action in system.actions:
            if isinstance(action, Spring | Damper):
                pts += [action.a, action.b]
        for p in points:
            if not isinstance(p, Point):
                raise ArgumentTypeError(
                    f"`points` must hold Points; got {type(p).__name__}.")
            pts.append(p)
        self._frames = tuple(dict.fromkeys(f for f in frames if f != ref))
        self._points = tuple(dict.fromkeys(pts + [f.origin for f in self._frames]))
        gravity = [a.field for a in system.actions if isinstance(a, Gravity)]
        exprs = []
        for f in self._frames:
            exprs += list(ref.dcm(f))
        for p in self._points:
            exprs += list(p.coordinates(ref))
        self._dummies = tuple(sp.Dummy(f"q{n}") for n in range(len(self._coordinates)))
        to_dummy = dict(zip(self._coordinates, self._dummies, strict=True))
        exprs = [sp.sympify(e).xreplace(to_dummy) for e in exprs]
        dims = [sp.sympify(d) for b in system.bodies if b.shape is not None
                for d in b.shape.dimensions.values()]
        self._values = _parameter_values(system, params, exprs + dims,
                                         set(self._dummies) | {t})
        exprs = [e.xreplace(self._values) for e in exprs]
        # the direction of gravity only: a positive constant without a value (g) counts as 1
        self._gravity = None
        if gravity:
            field = [sp.sympify(c).xreplace(self._values) for c in gravity[0].components(ref)]
            ones = {s: sp.S.One for c in field for s in c.free_symbols if s.is_positive}
            field = [sp.sympify(c).xreplace(ones) for c in field]
            if all(c.is_number for c in field) and any(c != 0 for c in field):
                self._gravity = np.array([float(c) for c in field])
                self._gravity /= np.linalg.norm(self._gravity)
        self._plane = _plane(exprs, len(self._frames), len(self._points),
                             set(self._dummies) | {t})
        self._function = sp.lambdify((t, *self._dummies), exprs, modules="numpy", cse=True)

    system = property(lambda self: self._system, doc="The system.")
    reference = property(lambda self: self._reference,
                         doc="The frame the positions are taken in (the system's reference).")
    coordinates = property(lambda self: self._coordinates,
                           doc="The parameters of situation, in the order ``at`` takes them.")

    @property
    def parameters(self) -> dict:
        """The values of the constants used, by symbol (a new dict)."""
        return dict(self._values)

    def number(self, expr) -> float:
        """The value of a constant expression (dimensions, moments of inertia) with the
        values of :attr:`parameters`.

        Raises
        ------
        ArgumentError
            If symbols without a value remain (named in the message).

        Examples
        --------
        >>> from rigidmech import models
        >>> pendulum = models.compound_pendulum()
        >>> Placer(pendulum, {"L": 2.0}).number(pendulum.constant("L") ** 2 / 2)
        2.0
        """
        x = sp.sympify(expr).xreplace(self._values)
        if not x.is_number:
            names = ", ".join(sorted(s.name for s in x.free_symbols))
            raise ArgumentError(
                f"`params` must give a value to {names} (in {expr}); pass them in params.")
        return float(x)

    @property
    def plane(self):
        """0, 1 or 2 when the system is planar, normal to the reference's i, j or k (every
        point keeps its coordinate along it and every frame turns about it whatever q and
        t); None for a motion in space."""
        return self._plane

    def at(self, q, t=0.0) -> Placement:
        """The system at the state ``q`` (a sequence in the order of :attr:`coordinates`, or
        a dict by name or coordinate) and time ``t``.

        Raises
        ------
        ArgumentError
            For a wrong number of values, an unknown name, or a value that is not finite.

        Examples
        --------
        >>> from rigidmech import models
        >>> placer = Placer(models.compound_pendulum(), {"L": 2.0})
        >>> placer.at({"theta": 0.0}).point("G").tolist()
        [1.0, 0.0, 0.0]
        """
        qv = _state(q, self._coordinates)
        out = [float(x) for x in self._function(float(t), *qv)]
        n = 0
        poses = {}
        for f in self._frames:
            poses[f] = np.array(out[n:n + 9]).reshape(3, 3)
            n += 9
        points = {}
        for p in self._points:
            points[p] = np.array(out[n:n + 3])
            n += 3
        return Placement(self, qv, float(t), poses, points, self._gravity)


def _parameter_values(system, params, exprs, moving):
    """{symbol: float} for the constants; required those the expressions depend on."""
    needed = set().union(*(e.free_symbols for e in exprs)) - moving
    known = {s.name: s for s in (*system.parameters, *needed)}
    if params is None:
        params = {}
    if not isinstance(params, dict):
        raise ArgumentTypeError(
            f"`params` must be a dict of the constants' values (such as {{'L': 1.0}}); got "
            f"{type(params).__name__}.")
    values = {}
    for key, value in params.items():
        name = key.name if isinstance(key, sp.Symbol) else key
        if name not in known:
            raise ArgumentError(
                f"`params` names {name!r}, which is not a constant of the system; its "
                f"constants are {', '.join(sorted(known)) or 'none'}.")
        try:
            number = float(value)
        except (TypeError, ValueError):
            raise ArgumentError(
                f"`params` must give numbers; got {name}={value!r}.") from None
        if not np.isfinite(number):
            raise ArgumentError(f"`params` must give finite numbers; got {name}={value!r}.")
        values[known[name]] = sp.Float(number)
    missing = sorted(s.name for s in needed if s not in values)
    if missing:
        example = ", ".join(repr(m) + ": ..." for m in missing)
        raise ArgumentError(
            f"`params` must give a value to every constant the positions depend on; missing "
            f"{', '.join(missing)}. Pass params={{{example}}}.")
    return values


def _state(q, coordinates):
    names = [str(c.func) for c in coordinates]
    if isinstance(q, dict):
        by_name = {}
        for key, value in q.items():
            name = str(key.func) if hasattr(key, "func") and key in coordinates else str(key)
            if name not in names:
                raise ArgumentError(
                    f"`q` names {name!r}, which is not a coordinate of the system "
                    f"({', '.join(names)}).")
            by_name[name] = value
        missing = [n for n in names if n not in by_name]
        if missing:
            raise ArgumentError(f"`q` must give every coordinate; missing {', '.join(missing)}.")
        q = [by_name[n] for n in names]
    try:
        values = np.asarray(q, dtype=float).reshape(-1)
    except (TypeError, ValueError):
        raise ArgumentError(
            f"`q` must be a sequence of numbers (or a dict by name); got {q!r}.") from None
    if values.size != len(names):
        raise ArgumentError(
            f"`q` must give {len(names)} values ({', '.join(names)}), one per coordinate of the "
            f"system; got {values.size}.")
    if not np.all(np.isfinite(values)):
        raise ArgumentError(f"`q` must be finite; got {values.tolist()}.")
    return values


def _plane(exprs, n_frames, n_points, moving):
    """The index of the normal of the plane of motion, or None (see Placer.plane)."""
    def fixed(e):
        return not (e.free_symbols & moving)
    for n in (2, 0, 1):
        ok = all(fixed(exprs[9 * f + 3 * n + c]) and fixed(exprs[9 * f + 3 * c + n])
                 for f in range(n_frames) for c in range(3))
        base = 9 * n_frames
        ok = ok and all(fixed(exprs[base + 3 * p + n]) for p in range(n_points))
        if ok:
            return n
    return None


class Placement:
    """A system at one state, in numbers: positions of points and poses of frames in the
    reference (ch. 1.5.2, 2.3.3). Made by :meth:`Placer.at` or :func:`place`.

    Examples
    --------
    >>> import numpy as np
    >>> from rigidmech import models
    >>> four = models.four_bar()
    >>> p = place(four, [np.pi / 2, -np.pi / 2, np.pi / 2])
    >>> p.point("B").round(12).tolist(), p.point("C").round(12).tolist()
    ([0.0, 1.0, 0.0], [2.0, 1.0, 0.0])
    >>> p.rotation("R1").round(12)[:, 0].tolist()          # R1.i in R0
    [0.0, 1.0, 0.0]
    """

    __slots__ = ("_placer", "_q", "_t", "_rotations", "_points", "_gravity")

    def __init__(self, placer, q, t, rotations, points, gravity):
        self._placer, self._t, self._gravity = placer, t, gravity
        self._q = q
        self._q.flags.writeable = False
        self._rotations, self._points = rotations, points
        for a in (*rotations.values(), *points.values()):
            a.flags.writeable = False

    placer = property(lambda self: self._placer, doc="The Placer that made it.")
    system = property(lambda self: self._placer.system, doc="The system.")
    q = property(lambda self: self._q, doc="The coordinates (read-only array).")
    t = property(lambda self: self._t, doc="The time.")

    @property
    def gravity(self):
        """The direction of gravity (a unit vector in the reference's basis), or None."""
        return self._gravity

    def _substitution(self):
        values = {c: sp.Float(x) for c, x in zip(self._placer.coordinates, self._q.tolist(),
                                                 strict=True)}
        return {**values, t: sp.Float(self._t), **self._placer._values}

    def _evaluate(self, matrix, what):
        try:
            return np.array([float(x) for x in sp.Matrix(matrix).xreplace(
                self._substitution())], dtype=float)
        except TypeError:
            raise ArgumentError(
                f"{what} depends on symbols without a value; give them in `params`.") from None

    def _find(self, table, key, kind):
        if isinstance(key, str):
            found = [k for k in table if k.name == key]
            if len(found) == 1:
                return found[0]
            raise ArgumentError(
                f"`{kind}` must name one {kind} of the placement; {key!r} names "
                f"{len(found)} (known: {', '.join(sorted({k.name for k in table}))}).")
        return key

    def point(self, point) -> np.ndarray:
        """The coordinates (x, y, z) of a point in the reference, a Point or a name of a
        compiled one (others are evaluated by substitution)."""
        point = self._find(self._points, point, "point")
        if point in self._points:
            return self._points[point]
        if not isinstance(point, Point):
            raise ArgumentTypeError(f"`point` must be a Point; got {type(point).__name__}.")
        return self._evaluate(point.coordinates(self._placer.reference), f"point {point.name}")

    def rotation(self, frame) -> np.ndarray:
        """The direction cosines of a frame (a Frame or a name): columns its basis vectors
        in the reference's basis (book, ch. 1.5.2)."""
        frame = self._find(self._rotations, frame, "frame")
        if frame == self._placer.reference:
            return np.eye(3)
        if frame in self._rotations:
            return self._rotations[frame]
        if not isinstance(frame, Frame):
            raise ArgumentTypeError(f"`frame` must be a Frame; got {type(frame).__name__}.")
        return self._evaluate(self._placer.reference.dcm(frame),
                              f"frame {frame.name}").reshape(3, 3)

    def origin(self, frame) -> np.ndarray:
        """The coordinates of a frame's origin in the reference."""
        frame = self._find(self._rotations, frame, "frame")
        return self.point(frame.origin)

    def vector(self, vector: Vector) -> np.ndarray:
        """The components of a vector in the reference's basis, evaluated at this state.

        Examples
        --------
        >>> import numpy as np
        >>> from rigidmech import models
        >>> dp = models.double_pendulum()
        >>> p = place(dp, [np.pi / 2, 0.0], {"L": 1.0})
        >>> p.vector(dp.frame("R1").i).round(12).tolist()
        [0.0, 1.0, 0.0]
        """
        if not isinstance(vector, Vector):
            raise ArgumentTypeError(f"`vector` must be a Vector; got {type(vector).__name__}.")
        return self._evaluate(vector.components(self._placer.reference), "the vector")

    @property
    def points(self) -> dict:
        """{Point: coordinates} of every compiled point (a new dict)."""
        return dict(self._points)

    def extent(self):
        """(low, high): the corners of the box holding every compiled point.

        Examples
        --------
        >>> from rigidmech import models
        >>> low, high = place(models.compound_pendulum(), [0.0], {"L": 2.0}).extent()
        >>> low.tolist(), high.tolist()                # O and the mass centre G
        ([0.0, 0.0, 0.0], [1.0, 0.0, 0.0])
        """
        xyz = np.array(list(self._points.values()) or [np.zeros(3)])
        return xyz.min(axis=0), xyz.max(axis=0)


def place(system, q, params=None, *, t=0.0) -> Placement:
    """The system at one state, in numbers: ``Placer(system, params).at(q, t)``.

    Examples
    --------
    >>> from rigidmech import models
    >>> place(models.compound_pendulum(), [0.0], {"L": 2.0}).point("G").tolist()
    [1.0, 0.0, 0.0]
    """
    return Placer(system, params).at(q, t)
