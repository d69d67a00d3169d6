"""The Whipple bicycle of the benchmark of Meijaard, Papadopoulos, Ruina and Schwab (2007,
Proc. R. Soc. A 463, 1955-1982): a rear frame, a front frame (fork and handlebar) on a
tilted steer axis, two knife-edge wheels rolling without slipping on a horizontal plane
(book, ch. 13.1, 25.3.3: parameters linked by rolling conditions and a closed loop).

Conventions: x forward, y to the left, z up (the paper: y right, z down). The paper's 25
parameters keep its symbols and its signs (z_B, z_H negative: the mass centres are above the
ground; the products I_Bxz, I_Hxz as the paper tabulates them); g is a constant symbol.
Numbers given as floats are made exact (``sympy.Rational(str(x))``), so the equations of the
benchmark values are exact.
"""

from __future__ import annotations

import sympy as sp

from .._core.errors import ArgumentError
from ..actions import Pivot, PointContact, RollingContact, gravity
from ..dynamics import System
from ..inertia import InertiaOperator, Shape
from ..kinematics import ContactKinematics
from ..kinetics import Body
from ..vectors import Frame, constants, coordinates
from ._model import Model

__all__ = ["BENCHMARK_BICYCLE", "whipple_bicycle"]


def _Q(x):
    return sp.Rational(x)


#: The paper's benchmark values (its Table 1), SI units, exact.
BENCHMARK_BICYCLE = {
    "w": _Q("1.02"), "c": _Q("0.08"), "lam": sp.pi / 10,
    "rR": _Q("0.3"), "mR": _Q(2), "IRxx": _Q("0.0603"), "IRyy": _Q("0.12"),
    "xB": _Q("0.3"), "zB": _Q("-0.9"), "mB": _Q(85),
    "IBxx": _Q("9.2"), "IByy": _Q(11), "IBzz": _Q("2.8"), "IBxz": _Q("2.4"),
    "xH": _Q("0.9"), "zH": _Q("-0.7"), "mH": _Q(4),
    "IHxx": _Q("0.05892"), "IHyy": _Q("0.06"), "IHzz": _Q("0.00708"), "IHxz": _Q("-0.00756"),
    "rF": _Q("0.35"), "mF": _Q(3), "IFxx": _Q("0.1405"), "IFyy": _Q("0.28"),
}


def _exact(value):
    if isinstance(value, float):
        return sp.Rational(str(value))
    return sp.sympify(value)


def whipple_bicycle(**parameters) -> Model:
    """The Whipple bicycle (Meijaard et al. 2007) as a System.

    Eight parameters of situation: the rear contact (x, y), yaw psi (frame A), roll phi
    (frame Bf), pitch theta (the rear frame E), steer delta (the front frame HE, about the
    steer axis tilted back by lam), the wheels' angles theta_R, theta_F (frames RW, FW).
    Four rolling conditions (two per wheel) and the front contact, a loop closed by a point
    contact on the ground (its height condition eliminates the pitch). Gravity ``-g R0.k``.

    Parameters
    ----------
    **parameters
        Any of the paper's 25 parameters by its symbol, numbers or sympy expressions; the
        defaults are the benchmark values :data:`BENCHMARK_BICYCLE`: wheelbase ``w`` = 1.02,
        trail ``c`` = 0.08, steer axis tilt ``lam`` = pi/10; rear wheel ``rR`` = 0.3,
        ``mR`` = 2, ``IRxx`` = 0.0603, ``IRyy`` = 0.12; rear frame ``xB`` = 0.3, ``zB`` =
        -0.9, ``mB`` = 85, ``IBxx`` = 9.2, ``IByy`` = 11, ``IBzz`` = 2.8, ``IBxz`` = 2.4;
        front frame ``xH`` = 0.9, ``zH`` = -0.7, ``mH`` = 4, ``IHxx`` = 0.05892, ``IHyy`` =
        0.06, ``IHzz`` = 0.00708, ``IHxz`` = -0.00756; front wheel ``rF`` = 0.35, ``mF`` = 3,
        ``IFxx`` = 0.1405, ``IFyy`` = 0.28 (SI units).

    Returns
    -------
    Model
        coordinates (x, y, psi, phi, theta, delta, theta_R, theta_F), constants (g,),
        frames (R0, A, Bf, E, RW, E2, H, HE, FW), bodies (rear_wheel, rear_frame,
        front_frame, front_wheel), points (P, Cr, S0, Cf, GB, GH, PF): P and PF the rear and
        front contacts, Cr and Cf the wheels' centres, S0 where the steer axis meets the
        ground. The wheels are drawn as discs of radii ``rR`` and ``rF`` (their ``shape``,
        for drawing only: their moments are the paper's).

    Raises
    ------
    ArgumentError
        If a keyword is not one of the 25 parameters.

    Examples
    --------
    >>> from rigidmech import models
    >>> bike = models.whipple_bicycle()
    >>> [b.name for b in bike.bodies]
    ['rear_wheel', 'rear_frame', 'front_frame', 'front_wheel']
    >>> bike.body("rear_frame").mass
    85
    """
    unknown = sorted(set(parameters) - set(BENCHMARK_BICYCLE))
    if unknown:
        raise ArgumentError(
            f"`{unknown[0]}` is not a parameter of the Whipple bicycle; expected keywords "
            f"among {', '.join(BENCHMARK_BICYCLE)} (the symbols of Meijaard et al. 2007).")
    p = dict(BENCHMARK_BICYCLE)
    p.update((k, _exact(v)) for k, v in parameters.items())
    w, c, lam, rR, rF = p["w"], p["c"], p["lam"], p["rR"], p["rF"]
    x, y, psi, phi, th, dl, thr, thf = coordinates("x y psi phi theta delta theta_R theta_F")
    g = constants("g", positive=True)
    R0 = Frame("R0")
    A = R0.rotated("A", about=R0.k, angle=psi)              # yaw
    Bf = A.rotated("Bf", about=A.i, angle=phi)              # roll
    P = R0.point("P", x, y, 0)                               # rear contact
    Cr = P.moved("Cr", rR * Bf.k)
    E = Bf.rotated("E", about=Bf.j, angle=th, origin=Cr)    # pitch: the rear frame
    RW = Bf.rotated("RW", about=Bf.j, angle=thr, origin=Cr)
    S0 = Cr.moved("S0", (w + c) * E.i - rR * E.k)           # steer axis meets the ground
    E2 = E.rotated("E2", about=E.j, angle=-lam, origin=S0)  # E2.k along the steer axis
    H = E2.rotated("H", about=E2.k, angle=dl, origin=S0)    # steer
    HE = H.rotated("HE", about=H.j, angle=lam, origin=S0)   # the front frame, E's basis at 0
    Cf = S0.moved("Cf", -c * HE.i + rF * HE.k)
    FW = HE.rotated("FW", about=HE.j, angle=thf, origin=Cf)
    GB = Cr.moved("GB", p["xB"] * E.i + (-p["zB"] - rR) * E.k)
    GH = S0.moved("GH", (p["xH"] - w - c) * HE.i + (-p["zH"]) * HE.k)
    axle = HE.j
    down = axle.cross(R0.k.cross(axle))
    PF = Cf.moved("PF", -rF * down / sp.sqrt(1 - axle.dot(R0.k) ** 2))   # front contact
    op = InertiaOperator.from_products
    # the wheels' moments are the paper's; their shapes (discs of radii rR, rF about the
    # axles) are for drawing only
    rear = Body("rear_wheel", frame=RW, mass=p["mR"], centre=Cr,
                inertia=op(p["IRxx"], p["IRyy"], p["IRxx"], frame=RW),
                shape=Shape("disk", [rR], axis=RW.j))
    front = Body("front_wheel", frame=FW, mass=p["mF"], centre=Cf,
                 inertia=op(p["IFxx"], p["IFyy"], p["IFxx"], frame=FW),
                 shape=Shape("disk", [rF], axis=FW.j))
    # products: the paper's I_xz in (x, y right, z down) is -int x z; z up flips its sign
    body = Body("rear_frame", frame=E, mass=p["mB"], centre=GB,
                inertia=op(p["IBxx"], p["IByy"], p["IBzz"], 0, p["IBxz"], 0, frame=E, at=GB))
    fork = Body("front_frame", frame=HE, mass=p["mH"], centre=GH,
                inertia=op(p["IHxx"], p["IHyy"], p["IHzz"], 0, p["IHxz"], 0, frame=HE, at=GH))
    s = System(galilean=R0)
    s.connect(R0, rear, RollingContact(ContactKinematics(RW, R0, at=P, normal=R0.k)))
    s.connect(rear, body, Pivot(at=Cr, axis=E.j))
    s.connect(body, fork, Pivot(at=S0, axis=E2.k))
    s.connect(fork, front, Pivot(at=Cf, axis=HE.j))
    s.connect(R0, front, RollingContact(ContactKinematics(FW, R0, at=PF, normal=R0.k)))
    s.connect(R0, front, PointContact(at=R0.origin, normal=R0.k), meets=PF)
    s.act(gravity(-g * R0.k))
    return Model(s, (x, y, psi, phi, th, dl, thr, thf), (g,),
                 (R0, A, Bf, E, RW, E2, H, HE, FW), (rear, body, fork, front),
                 (P, Cr, S0, Cf, GB, GH, PF))
