"""Scenes of solids, machines and tops, built from the catalogue :mod:`rigidmech.models`
(book, ch. 20-25, 27).

* ``block-on-incline`` (ch. 23.2.5, 27.4): a block sliding without friction down an incline
  of angle alpha, x(t) = g sin(alpha) t^2 / 2 from rest;
* ``cart-pendulum`` (ch. 24.3, 27.5): a point mass on a rod pivoted on a cart free to slide,
  the coupled motions of two solids;
* ``triple-pendulum`` (ch. 25.3): three uniform rods on pivots, relative angles;
* ``four-bar`` (ch. 13.2, 25.3.3): the four-bar linkage under gravity, parameters linked by
  the closure of its loop (the default q0 closes it: the dependent angles in closed form);
* ``slider-crank`` (ch. 13.2, 25.3.3): crank, connecting rod and slider;
* ``wheel-on-incline`` (ch. 23.4): a disk rolling without slipping down an incline;
* ``heavy-top`` (ch. 20, 25): the symmetric heavy top on a ball joint, Euler angles;
* ``gyroscope`` (ch. 20, 25): the same top spinning fast with its axis near the horizontal:
  it precesses at about m g l / (C phi') instead of falling.

Examples
--------
>>> [s.name for s in MACHINE_SCENES][:3]
['block-on-incline', 'cart-pendulum', 'triple-pendulum']
>>> from rigidmech import scenes
>>> rep = scenes.run("block-on-incline", t_end=1.0)
>>> round(rep.final_q[0], 6) == round(9.81 * 0.5 * 0.5, 6)      # g sin(30 deg) t^2 / 2
True
"""

from __future__ import annotations

import math

from .. import models
from .catalogue import Built, Scene

__all__ = ["MACHINE_SCENES"]


def _built(model) -> Built:
    return Built(model.system, model.bodies)


def _triple_pendulum() -> Built:
    return _built(models.n_link_pendulum(3))


def _four_bar_closed(q1, lengths=models.FOUR_BAR_LENGTHS) -> tuple:
    """(q1, q2, q3) of :func:`rigidmech.models.four_bar` on its loop for the crank angle
    ``q1`` (book, ch. 13.2): C is where the circles of centres B = L1 (cos q1, sin q1),
    radius BC = L2, and D = (L0, 0), radius DC = L3, meet, on the branch with C to the left
    of B->D (the coupler's angle is that of B->D plus the angle at B of the triangle BDC).

    Examples
    --------
    >>> q1, q2, q3 = _four_bar_closed(1.5)
    >>> round(q2, 6), round(q3, 6)
    (-1.246033, 1.566407)
    """
    L0, L1, L2, L3 = (float(v) for v in lengths)
    bx, by = L1 * math.cos(q1), L1 * math.sin(q1)
    dx, dy = L0 - bx, -by
    bd = math.hypot(dx, dy)
    at_b = math.acos((L2**2 + bd**2 - L3**2) / (2 * L2 * bd))   # law of cosines
    coupler = math.atan2(dy, dx) + at_b                           # absolute angle of BC
    cx, cy = bx + L2 * math.cos(coupler), by + L2 * math.sin(coupler)
    return (q1, coupler - q1, math.atan2(cy, cx - L0))


def _slider_crank_closed(q1, r=0.5, ell=1.5) -> tuple:
    """(q1, q2, x) of :func:`rigidmech.models.slider_crank` on its loop for the crank angle
    ``q1`` (book, ch. 13.2): the slider at x = r cos q1 + sqrt(ell^2 - r^2 sin^2 q1), the rod
    from A = r (cos q1, sin q1) to (x, 0).

    Examples
    --------
    >>> [round(v, 6) for v in _slider_crank_closed(1.0)]
    [1.0, -1.284305, 1.709936]
    """
    ax, ay = r * math.cos(q1), r * math.sin(q1)
    x = ax + math.sqrt(ell**2 - ay**2)
    return (q1, math.atan2(-ay, x - ax) - q1, x)


MACHINE_SCENES = (
    Scene("block-on-incline", "A block sliding without friction down an inclined plane",
          "ch. 23.2.5, 27.4",
          coordinates=("x",),
          parameters=(("m", 1.0, "mass of the block"), ("g", 9.81, "gravity"),
                      ("alpha", math.pi / 6, "angle of the incline, rad")),
          q0=(0.0,), t_end=2.0, builder=lambda: _built(models.block_on_incline()),
          units={"x": "m"},
          notes="x: distance travelled down the slope from O; x = g sin(alpha) t^2 / 2 from "
                "rest."),
    Scene("cart-pendulum", "A pendulum on a cart sliding freely: coupled motions of two solids",
          "ch. 24.3, 27.5",
          coordinates=("x", "theta"),
          parameters=(("M", 2.0, "mass of the cart"), ("m", 1.0, "mass of the bob"),
                      ("L", 1.0, "length of the rod"), ("g", 9.81, "gravity")),
          q0=(0.0, 0.5), t_end=10.0, builder=lambda: _built(models.cart_pendulum()),
          units={"x": "m"},
          notes="x: position of the cart along i; theta: angle of the rod from the downward "
                "vertical; small oscillations at w^2 = (M + m) g / (M L)."),
    Scene("triple-pendulum", "Triple pendulum of three uniform rods (relative angles)",
          "ch. 25.3",
          coordinates=("q1", "q2", "q3"),
          parameters=(("g", 9.81, "gravity"),
                      *((f"{s}{i}", 1.0, f"{w} of rod {i}") for i in (1, 2, 3)
                        for s, w in (("m", "mass"), ("l", "length")))),
          q0=(-0.5, 0.3, 0.2), t_end=5.0, builder=_triple_pendulum,
          notes="q1: angle of the first rod from i (gravity -g j: q1 = -pi/2 hangs down); "
                "q2, q3: angles of each rod relative to the previous one."),
    Scene("four-bar", "Four-bar linkage under gravity (a closed loop)", "ch. 13.2, 25.3.3",
          coordinates=("q1", "q2", "q3"),
          parameters=(("m", 1.0, "mass of each bar"), ("g", 9.81, "gravity")),
          q0=_four_bar_closed(1.5), t_end=5.0, builder=lambda: _built(models.four_bar()),
          notes="lengths: ground 2, crank 1, coupler 2, rocker 1.5; q1 crank angle, q2 "
                "coupler relative to the crank, q3 rocker angle; q2, q3 follow q1 through the "
                "closure (a q0 off it is moved onto it, q1 kept)."),
    Scene("slider-crank", "Slider-crank mechanism under gravity", "ch. 13.2, 25.3.3",
          coordinates=("q1", "q2", "x"),
          parameters=(("m", 1.0, "mass of each part"), ("g", 9.81, "gravity")),
          q0=_slider_crank_closed(1.0), t_end=5.0, builder=lambda: _built(models.slider_crank()),
          units={"x": "m"},
          notes="crank 0.5, rod 1.5; q1 crank angle, q2 rod relative to the crank, x the "
                "slider; q2 and x follow q1 through the closure."),
    Scene("wheel-on-incline", "A disk rolling without slipping down an incline", "ch. 23.4",
          coordinates=("x", "theta"),
          parameters=(("m", 1.0, "mass of the wheel"), ("g", 9.81, "gravity"),
                      ("r", 0.3, "radius of the wheel")),
          q0=(0.0, 0.0), t_end=2.0,
          builder=lambda: _built(models.wheel_on_incline(math.pi / 6)), units={"x": "m"},
          notes="slope 30 degrees; x: abscissa of the centre down the slope, theta: rotation "
                "of the wheel; rolling: x'' = 2 g sin(alpha) / 3."),
    Scene("heavy-top", "The symmetric heavy top on a ball joint", "ch. 20, 25",
          coordinates=("psi", "theta", "phi"),
          parameters=(("m", 1.0, "mass"), ("g", 9.81, "gravity"),
                      ("l", 0.05, "distance from the ball joint to the mass centre"),
                      ("A", 0.01, "moment of inertia about a transverse axis at G"),
                      ("C", 0.005, "moment of inertia about the axis")),
          q0=(0.0, 0.5, 0.0), u0=(0.0, 0.0, 50.0), t_end=5.0,
          builder=lambda: _built(models.heavy_top()),
          notes="Euler angles: psi precession, theta nutation (axis from the upward vertical),"
                " phi spin; singular at theta = 0."),
    Scene("gyroscope", "A gyroscope: a fast top with its axis near the horizontal precesses",
          "ch. 20, 25",
          coordinates=("psi", "theta", "phi"),
          parameters=(("m", 1.0, "mass"), ("g", 9.81, "gravity"),
                      ("l", 0.1, "distance from the ball joint to the mass centre"),
                      ("A", 0.006, "moment of inertia about a transverse axis at G"),
                      ("C", 0.01, "moment of inertia about the axis")),
          q0=(0.0, 1.5, 0.0), u0=(0.0, 0.0, 200.0), t_end=5.0,
          builder=lambda: _built(models.heavy_top()),
          notes="the heavy top with a spin of 200 rad/s: slow precession at about m g l / "
                "(C phi') = 0.49 rad/s with a small fast nutation."),
)
