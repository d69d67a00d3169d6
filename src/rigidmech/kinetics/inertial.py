"""Inertial actions of entrainment and of Coriolis (book, ch. 17.2, 19.1.1).

A body S moves relative to a reference R1 which moves relative to a Galilean reference R0.
Since a(M/R0) = a(M/R1) + a_e(M) + a_c(M) at every point (ch. 17.1), the dynamic torsors
add up (ch. 17.2.3):

.. math::
    \\{\\mathcal{D}(S/R_0)\\} = \\{\\mathcal{D}(S/R_1)\\} + \\{\\mathcal{D}_e\\} +
    \\{\\mathcal{D}_c\\},\\qquad
    \\{\\mathcal{D}_e\\} = \\Big\\{\\int_S \\mathbf{a}_e\\,dm \\;;\\;
    \\int_S \\mathbf{GM}\\wedge\\mathbf{a}_e\\,dm\\Big\\}_G, \\quad
    \\{\\mathcal{D}_c\\} = \\Big\\{\\int_S \\mathbf{a}_c\\,dm \\;;\\;
    \\int_S \\mathbf{GM}\\wedge\\mathbf{a}_c\\,dm\\Big\\}_G,

and the fundamental principle written in R1 holds with the inertial action torsors
{F_ie} = -{D_e} and {F_ic} = -{D_c} added to the actions (ch. 19.1.1). For a rigid body of mass m,
mass centre G and operator of inertia J_G, with omega = omega(R1/R0), omega' its derivative
relative to R0 and Omega = omega(S/R1):

.. math::
    \\{\\mathcal{D}_e\\} = \\{ m\\,\\mathbf{a}_e(G) \\;;\\; \\mathcal{J}_G(\\boldsymbol{\\omega}')
    + \\boldsymbol{\\omega}\\wedge\\mathcal{J}_G(\\boldsymbol{\\omega}) \\}_G,

    \\{\\mathcal{D}_c\\} = \\{ 2m\\,\\boldsymbol{\\omega}\\wedge\\mathbf{v}(G/R_1) \\;;\\;
    2\\,\\boldsymbol{\\Omega}\\wedge\\mathcal{J}_G(\\boldsymbol{\\omega})
    - (\\operatorname{tr}\\mathcal{J}_G)\\,\\boldsymbol{\\Omega}\\wedge\\boldsymbol{\\omega}
    \\}_G .

(The second moment follows from GM ^ (omega ^ (Omega ^ GM)) = -(GM . omega) Omega ^ GM and
the integral of GM (GM . omega) dm = (tr J_G / 2) omega - J_G(omega).)
"""

from __future__ import annotations

import sympy as sp

from .._core.errors import ArgumentError, ArgumentTypeError, FrameError
from ..actions import Action
from ..kinematics import acceleration_composition
from ..torsors import Torsor
from ..vectors import Frame, Point, Vector, t
from .body import Body

__all__ = ["entrainment_dynamic_torsor", "coriolis_dynamic_torsor",
           "entrainment_inertial_torsor", "coriolis_inertial_torsor", "InertialActions"]


def _check(body, relative_to, absolute, at):
    if not isinstance(body, Body):
        raise ArgumentTypeError(f"`body` must be a Body; got {type(body).__name__}.")
    for f, name in ((relative_to, "relative_to"), (absolute, "absolute")):
        if not isinstance(f, Frame):
            raise ArgumentTypeError(f"`{name}` must be a Frame; got {type(f).__name__}.")
    if relative_to.root != absolute.root or body.frame.root != absolute.root:
        raise FrameError(
            f"`body` ({body.name}), `relative_to` ({relative_to.name}) and `absolute` "
            f"({absolute.name}) must belong to the same frame tree.")
    if body.mass is None:
        raise ArgumentError(
            f"`body` {body.name} has no mass: the inertial actions need one; create it with "
            "mass=...")
    if at is not None and not isinstance(at, Point):
        raise ArgumentTypeError(f"`at` must be a Point; got {type(at).__name__}.")


def _apply(body, w):
    return Vector.zero() if body.inertia is None else body.inertia.apply(w)


def entrainment_dynamic_torsor(body: Body, *, relative_to: Frame, absolute: Frame,
                               at: Point | None = None) -> Torsor:
    """{D_e} = {m a_e(G) ; J_G(omega') + omega ^ J_G(omega)}_G, the dynamic torsor of the
    entrainment accelerations (ch. 17.2.1).

    Parameters
    ----------
    body : Body
        The body S, with a mass (and an operator of inertia, zero for a particle).
    relative_to : Frame
        The moving reference R1.
    absolute : Frame
        The Galilean reference R0.
    at : Point, optional
        Point of reduction (default: the mass centre G).

    Examples
    --------
    A particle at distance d on a turntable turning at the constant rate w: m d w^2 towards the
    axis.

    >>> import rigidmech as rm
    >>> th = rm.coordinates("theta"); m, d = rm.constants("m d", positive=True)
    >>> R0 = rm.Frame("R0"); R1 = R0.rotated("R1", about=R0.k, angle=th)
    >>> b = rm.Body("b", frame=R1, mass=m, centre=R1.point("G", d, 0, 0))
    >>> entrainment_dynamic_torsor(b, relative_to=R1, absolute=R0).resultant
    -d*m*Derivative(theta(t), t)**2*R1.i + d*m*Derivative(theta(t), (t, 2))*R1.j
    """
    _check(body, relative_to, absolute, at)
    G = body.centre
    a_e = acceleration_composition(G, relative_to=relative_to, absolute=absolute).entrainment
    w = relative_to.rotation_vector(absolute)
    moment = _apply(body, w.dt(absolute)) + w.cross(_apply(body, w))
    T = Torsor(body.mass * a_e, moment, G)
    return T if at is None else T.at(at)


def coriolis_dynamic_torsor(body: Body, *, relative_to: Frame, absolute: Frame,
                            at: Point | None = None) -> Torsor:
    """{D_c} = {2 m omega ^ v(G/R1) ; 2 Omega ^ J_G(omega) - tr(J_G) Omega ^ omega}_G, the
    dynamic torsor of the Coriolis accelerations (ch. 17.2.2), omega = omega(R1/R0),
    Omega = omega(S/R1).

    Examples
    --------
    A wheel of axial moment C spinning at phi' about i1 on a turntable turning at theta'
    about k0: the Coriolis moment is the gyroscopic C phi' theta' j1.

    >>> import sympy as sp
    >>> import rigidmech as rm
    >>> th, ph = rm.coordinates("theta phi"); m, A, C = rm.constants("m A C", positive=True)
    >>> R0 = rm.Frame("R0"); R1 = R0.rotated("R1", about=R0.k, angle=th)
    >>> RS = R1.rotated("RS", about=R1.i, angle=ph)
    >>> J = rm.InertiaOperator.from_products(C, A, A, frame=RS)
    >>> wheel = rm.Body("wheel", frame=RS, mass=m, inertia=J)
    >>> D = coriolis_dynamic_torsor(wheel, relative_to=R1, absolute=R0)
    >>> sp.simplify(D.moment.components(R1).T)
    Matrix([[0, C*Derivative(phi(t), t)*Derivative(theta(t), t), 0]])
    """
    _check(body, relative_to, absolute, at)
    G = body.centre
    w = relative_to.rotation_vector(absolute)
    W = body.frame.rotation_vector(relative_to)
    resultant = 2 * body.mass * w.cross(G.velocity(relative_to))
    if body.inertia is None:
        moment = Vector.zero()
    else:
        trace = body.inertia.matrix.trace()
        moment = 2 * W.cross(body.inertia.apply(w)) - trace * W.cross(w)
    T = Torsor(resultant, moment, G)
    return T if at is None else T.at(at)


def entrainment_inertial_torsor(body: Body, *, relative_to: Frame, absolute: Frame,
                                at: Point | None = None) -> Torsor:
    """{F_ie} = -{D_e}: the inertial action torsor of entrainment on ``body`` (ch. 19.1.1).

    Examples
    --------
    >>> import rigidmech as rm
    >>> th = rm.coordinates("theta"); m, d, w = rm.constants("m d w", positive=True)
    >>> R0 = rm.Frame("R0"); R1 = R0.rotated("R1", about=R0.k, angle=w * rm.t)
    >>> b = rm.Body("b", frame=R1, mass=m, centre=R1.point("G", d, 0, 0))
    >>> entrainment_inertial_torsor(b, relative_to=R1, absolute=R0).resultant
    d*m*w**2*R1.i
    """
    return -entrainment_dynamic_torsor(body, relative_to=relative_to, absolute=absolute, at=at)


def coriolis_inertial_torsor(body: Body, *, relative_to: Frame, absolute: Frame,
                             at: Point | None = None) -> Torsor:
    """{F_ic} = -{D_c}: the inertial action torsor of Coriolis on ``body`` (ch. 19.1.1).

    Examples
    --------
    A bead sliding at r' along a rod turning at w about k0: -2 m w r' on the normal.

    >>> import rigidmech as rm
    >>> r = rm.coordinates("r"); m, w = rm.constants("m w", positive=True)
    >>> R0 = rm.Frame("R0"); R1 = R0.rotated("R1", about=R0.k, angle=w * rm.t)
    >>> bead = rm.Body("bead", frame=R1.translated("Rb", R1.point("B", r, 0, 0)), mass=m)
    >>> coriolis_inertial_torsor(bead, relative_to=R1, absolute=R0).resultant
    -2*m*w*Derivative(r(t), t)*R1.j
    """
    return -coriolis_dynamic_torsor(body, relative_to=relative_to, absolute=absolute, at=at)


class InertialActions(Action):
    """The inertial actions of entrainment and Coriolis on every massive body, for the
    fundamental principle written in a reference ``reference`` moving relative to the
    Galilean ``galilean`` (ch. 19.1.1).

    Its :meth:`contributions` are the pairs (body, {F_ie} + {F_ic}), reduced at each mass
    centre; bodies without mass receive none.

    Examples
    --------
    >>> import rigidmech as rm
    >>> m, d, w = rm.constants("m d w", positive=True)
    >>> R0 = rm.Frame("R0"); R1 = R0.rotated("R1", about=R0.k, angle=w * rm.t)
    >>> b = rm.Body("b", frame=R1, mass=m, centre=R1.point("G", d, 0, 0))
    >>> (body, F), = InertialActions(reference=R1, galilean=R0).contributions([b])
    >>> F.resultant
    d*m*w**2*R1.i
    """

    __slots__ = ("_reference", "_galilean")

    def __init__(self, *, reference: Frame, galilean: Frame):
        for f, name in ((reference, "reference"), (galilean, "galilean")):
            if not isinstance(f, Frame):
                raise ArgumentTypeError(f"`{name}` must be a Frame; got {type(f).__name__}.")
        if reference.root != galilean.root:
            raise FrameError(f"`reference` ({reference.name}) and `galilean` "
                             f"({galilean.name}) must belong to the same frame tree.")
        self._reference, self._galilean = reference, galilean

    @property
    def reference(self) -> Frame:
        """The moving reference R1 in which the principle is written."""
        return self._reference

    @property
    def galilean(self) -> Frame:
        """The Galilean reference R0."""
        return self._galilean

    def contributions(self, solids):
        out = []
        for s in solids:
            if isinstance(s, Body) and s.mass is not None and s.mass != 0:
                kw = {"relative_to": self._reference, "absolute": self._galilean}
                out.append((s, entrainment_inertial_torsor(s, **kw)
                            + coriolis_inertial_torsor(s, **kw)))
        return out

    def _steady(self):
        """(omega, a(O)) when R turns at a constant rotation vector and its origin O has an
        acceleration of constant components in R's basis; None otherwise."""
        R, R0 = self._reference, self._galilean
        w = R.rotation_vector(R0)
        a = R.origin.acceleration(R0)
        comps = list(w.components(R)) + list(a.components(R))
        if any(sp.simplify(c).has(t) for c in comps if c.has(t)):
            return None
        return w, a

    def potential_energy(self, solids, frame):
        """The potential energy of the inertial actions in a steady motion of the reference
        (rotation vector omega constant, acceleration a(O) of its origin constant in its
        basis: a turntable at a constant rate, a wagon at a constant acceleration, the Earth):

        .. math:: E_p = \\sum_S m\\,\\mathbf{a}(O)\\cdot\\mathbf{OG}
            - \\tfrac12 m\\,|\\boldsymbol{\\omega}\\wedge\\mathbf{OG}|^2
            - \\tfrac12\\,\\boldsymbol{\\omega}\\cdot\\mathcal{J}_G(\\boldsymbol{\\omega}),

        O the origin of the reference (ch. 19.1.1). The entrainment action derives from it
        and the Coriolis action has zero power relative to the reference. None in any other
        motion of the reference. ``frame`` must be the reference.

        Examples
        --------
        A particle at distance r on a turntable turning at w: -m w^2 r^2 / 2.

        >>> import rigidmech as rm
        >>> r = rm.coordinates("r"); m, w = rm.constants("m w", positive=True)
        >>> R0 = rm.Frame("R0"); R1 = R0.rotated("R1", about=R0.k, angle=w * rm.t)
        >>> b = rm.Body("b", frame=R1.translated("Rb", R1.point("B", r, 0, 0)), mass=m)
        >>> InertialActions(reference=R1, galilean=R0).potential_energy([b], R1)
        -m*w**2*r(t)**2/2
        """
        if frame is not self._reference:
            raise FrameError(
                f"the potential energy of the inertial actions is relative to their reference "
                f"{self._reference.name}; got `frame` {getattr(frame, 'name', frame)}.")
        steady = self._steady()
        if steady is None:
            return None
        w, a = steady
        terms = []
        for s in solids:
            if isinstance(s, Body) and s.mass is not None and s.mass != 0:
                OG = s.centre - self._reference.origin
                wOG = w.cross(OG)
                terms.append(s.mass * a.dot(OG) - s.mass * wOG.dot(wOG) / 2
                             - w.dot(_apply(s, w)) / 2)
        return sp.Add(*terms)

    def __repr__(self):
        return (f"InertialActions(reference={self._reference.name}, "
                f"galilean={self._galilean.name})")
