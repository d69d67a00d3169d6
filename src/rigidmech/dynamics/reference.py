"""The reference in which a :class:`~rigidmech.dynamics.System` writes its equations: a
Galilean one, or one moving relative to a Galilean one (book, ch. 19, 24).

The fundamental principle holds relative to a Galilean reference R0. Relative to a reference
R whose motion relative to R0 is prescribed (a turntable turning with time, a wagon with a
given acceleration, the Earth turning about its axis) it holds with the inertial actions of
entrainment and of Coriolis added to the actions on each body (ch. 19.1.1):

.. math::
    \\{\\mathcal{D}(S/R)\\} = \\{\\mathcal{A}(\\bar S \\to S)\\} + \\{\\mathcal{F}_{ie}\\}
    + \\{\\mathcal{F}_{ic}\\} .

``System(galilean=R0, reference=R)`` (or ``System(reference=earth_reference(...))``) writes
everything relative to R: the bodies are connected to R, the velocities, the kinetic energy,
the equations of motion and the connection actions are relative to R, and an
:class:`~rigidmech.kinetics.InertialActions` is among the system's actions. The motion of R
relative to R0 must be prescribed: it may depend on time, not on the parameters of
situation.

Examples
--------
A bead on a rod turning at the constant rate w about the vertical k0: relative to the rod,
m r'' = m w^2 r (the inertial action of entrainment), and the rod pushes on the bead with the
opposite of the Coriolis action, 2 m w r' j1, besides m g k0.

>>> import rigidmech as rm
>>> r = rm.coordinates("r"); m, w, g = rm.constants("m w g", positive=True)
>>> R0 = rm.Frame("R0"); R1 = R0.rotated("R1", about=R0.k, angle=w * rm.t)
>>> B = R1.point("B", r, 0, 0)
>>> bead = rm.Body("bead", frame=R1.translated("Rb", B), mass=m, centre=B)
>>> s = rm.System(galilean=R0, reference=R1)
>>> s.connect(R1, bead, rm.joints.Prismatic(at=B, axis=R1.i))
>>> s.act(rm.gravity(-g * R0.k))
>>> s.equations_of_motion().forcing
Matrix([[m*w**2*r(t)]])
>>> s.connection_action(R1, bead).resultant.components(R1).T   # first: 0 along the motion
Matrix([[-m*w**2*r(t) + m*Derivative(r(t), (t, 2)), 2*m*w*Derivative(r(t), t), g*m]])
"""

from __future__ import annotations

import sympy as sp

from .._core.errors import ArgumentTypeError, ConnectionError_, FrameError
from ..kinetics import EarthReference, InertialActions
from ..vectors import Frame, t
from ..vectors.symbols import is_coordinate

__all__ = ["resolve_reference", "check_inertial_action"]


def _placing(frame, stop=None):
    """The expressions that place ``frame`` relative to ``stop`` (default: the root): for
    each frame of the chain, its origin's position and its rotation from its parent, and
    recursively the placing of every frame in whose basis an origin's position is written
    (a position r Rp.i depends on the angle of Rp even if no component does)."""
    out = []
    _place_frame(frame, stop, out, set())
    return out


def _point_placing(point):
    """The expressions that place ``point``: the components of its position and the
    placing of every frame in whose basis the position is written (see :func:`_placing`)."""
    return _vector_placing(point.position)


def _vector_placing(v):
    """The components of the vector ``v`` and the placing of every frame in whose basis it
    is written (see :func:`_placing`)."""
    out = []
    _place_vector(v, out, set())
    return out


def _place_frame(frame, stop, out, seen):
    chain = []
    f = frame
    while f is not None and f is not stop:
        chain.append(f)
        f = f.parent
    for g in reversed(chain):
        if g in seen:
            continue
        seen.add(g)
        _place_vector(g.origin.position, out, seen)
        out.append(g.angle)
        if g._matrix is not None:
            out.extend(x for row in g._matrix for x in row)


def _place_vector(v, out, seen):
    for basis, components in v.parts:
        out.extend(components)
        _place_frame(basis, None, out, seen)


def check_fixed_reference(galilean, argument="galilean"):
    """Refuse a Galilean reference that moves (with a coordinate or with time) relative to
    the root frame of its tree."""
    moving = [e for e in _placing(galilean) if sp.sympify(e).has(t)]
    if moving:
        raise FrameError(
            f"`{argument}` frame {galilean.name} moves relative to the root frame "
            f"{galilean.root.name} (its orientation or origin depends on {moving[0]}); the "
            "Galilean reference must not move relative to the root frame. Use a frame fixed "
            "in the root as `galilean`, and pass a moving frame as `reference=` to write the "
            "equations relative to it with the inertial actions.")


def _coordinates_of(exprs):
    return [a for e in exprs for a in sp.sympify(e).atoms(sp.core.function.AppliedUndef)
            if is_coordinate(a)]


def resolve_reference(galilean, reference):
    """The frame of the equations, the inertial actions to add (or None) and the Galilean
    frame, from the arguments of :class:`~rigidmech.dynamics.System`.

    Parameters
    ----------
    galilean : Frame or None
        The Galilean reference R0 (fixed in the root frame of its tree).
    reference : Frame, EarthReference or None
        The reference R in which the equations are written; None for R0 itself. An
        :class:`~rigidmech.kinetics.EarthReference` gives its local frame, and its geocentric
        frame as the default ``galilean``.

    Raises
    ------
    ArgumentTypeError
        Arguments of the wrong type, or neither given.
    FrameError
        A Galilean frame moving relative to the root, frames of two trees, or a reference
        whose motion depends on the parameters of situation.

    Examples
    --------
    >>> import rigidmech as rm
    >>> R0 = rm.Frame("R0"); R1 = R0.rotated("R1", about=R0.k, angle=2 * rm.t)
    >>> frame, inertial, galilean = resolve_reference(R0, R1)
    >>> frame is R1, galilean is R0, inertial
    (True, True, InertialActions(reference=R1, galilean=R0))
    """
    if isinstance(reference, EarthReference):
        if galilean is None:
            galilean = reference.geocentric
        elif galilean is not reference.geocentric:
            raise FrameError(
                f"`galilean` ({getattr(galilean, 'name', galilean)}) must be the geocentric "
                f"frame of the Earth reference ({reference.geocentric.name}), or omitted.")
        reference = reference.frame
    if galilean is None:
        raise ArgumentTypeError(
            "`galilean` must be a Frame (the Galilean reference); got None. Give "
            "System(galilean=R0), System(galilean=R0, reference=R) or "
            "System(reference=earth_reference(...)).")
    if not isinstance(galilean, Frame):
        raise ArgumentTypeError(f"`galilean` must be a Frame; got {type(galilean).__name__}.")
    check_fixed_reference(galilean)
    if reference is None or reference is galilean:
        return galilean, None, galilean
    if not isinstance(reference, Frame):
        raise ArgumentTypeError(
            "`reference` must be a Frame or an EarthReference (rm.kinetics.earth_reference); got "
            f"{type(reference).__name__}.")
    if reference.root is not galilean.root:
        raise FrameError(f"`reference` ({reference.name}) and `galilean` ({galilean.name}) "
                         "must belong to the same frame tree.")
    placing = _placing(reference)
    found = _coordinates_of(placing)
    if found:
        raise FrameError(
            f"`reference` frame {reference.name} moves with the parameter of situation "
            f"{found[0]}: the motion of the reference relative to the Galilean one must be "
            "prescribed (a function of time). Write the system in the Galilean reference, "
            "with that body as one of its bodies.")
    if not any(sp.sympify(e).has(t) for e in placing):
        return reference, None, galilean       # fixed in R0: Galilean as well
    return reference, InertialActions(reference=reference, galilean=galilean), galilean


def check_inertial_action(system, action):
    """Refuse inertial actions given to a system whose reference already adds them (they
    would count twice)."""
    if isinstance(action, InertialActions) and any(
            isinstance(a, InertialActions) for a in system.actions):
        raise ConnectionError_(
            f"the system is written in the moving reference {system.reference.name} and "
            "already adds its inertial actions of entrainment and Coriolis; adding "
            f"{action!r} would count them twice.")
