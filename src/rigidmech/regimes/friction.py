"""Motions with dry friction from the book, phase by phase (ch. 21.4, 23, 24).

Each function writes the equations of motion of one classical system in each of its regimes
(closed-form right-hand sides from the fundamental principle, with Coulomb's laws of
:class:`~rigidmech.actions.contact_laws.Coulomb`), the guards that end each regime and the
transition rules, and integrates with :func:`~rigidmech.regimes.phased.integrate_phases`:

* :func:`coulomb_oscillator`: a mass on a spring sliding on a rough floor (ch. 21.4);
* :func:`cylinder_on_incline`: a cylinder that rolls without slipping or slips (ch. 23);
* :func:`block_on_wagon`: a block on the floor of an accelerating wagon (ch. 24, relative
  motion in the wagon's non-Galilean frame);
* :func:`pushed_box`: a box pushed horizontally, at rest, sliding or tipping (ch. 24).

Posed from bodies (a :class:`~rigidmech.dynamics.System` with
:class:`~rigidmech.actions.FrictionContact` connections; the box with one at each bottom
corner) and integrated by :func:`~rigidmech.regimes.contact_motion`, which derives the
regimes itself, they give the same phases and switching instants (to 1e-9 at rtol 1e-12);
these hand-written versions are faster (closed-form right-hand sides) and serve as its
references. ``contact_motion`` also lets the box tip while sliding or its edge slip while
it tips, which :func:`pushed_box` assumes away.
"""

from __future__ import annotations

import math

import numpy as np

from .._core.errors import ArgumentError, ArgumentTypeError
from ..actions.contact_laws import Coulomb
from ._contact_rules import within_cone
from .phased import Guard, PhasedMotion, Regime, integrate_phases

__all__ = ["coulomb_oscillator", "cylinder_on_incline", "block_on_wagon", "pushed_box"]


def _positive(value, argument):
    try:
        v = float(value)
    except (TypeError, ValueError):
        raise ArgumentTypeError(f"`{argument}` must be a number; got {value!r}.") from None
    if not (math.isfinite(v) and v > 0):
        raise ArgumentError(f"`{argument}` must be a finite number > 0; got {value!r}.")
    return v


def _law(friction):
    if not isinstance(friction, Coulomb):
        raise ArgumentTypeError(f"`friction` must be a Coulomb law; got "
                                f"{type(friction).__name__}.")
    try:
        return float(friction.static), float(friction.kinetic)
    except TypeError:
        raise ArgumentError(f"`friction` must have numeric coefficients; got {friction!r}.") \
            from None


def _velocity_stops(component, direction, rule):
    def reset(t, y):
        y = np.array(y, dtype=float)
        y[component] = 0.0
        return y

    return Guard("stops", lambda t, y: y[component], target=rule, direction=direction,
                 reset=reset)


def coulomb_oscillator(*, mass, stiffness, friction: Coulomb, normal_force, x0, v0=0.0,
                       t_end, rtol=1e-12, atol=1e-12) -> PhasedMotion:
    """A mass on a spring sliding on a rough plane: the oscillator damped by dry friction
    (ch. 21.4). State y = (x, x'), x the elongation of the spring.

    Regimes ``"slide+"`` (x' > 0: m x'' = -k x - f_k N), ``"slide-"`` (x' < 0:
    m x'' = -k x + f_k N) and ``"stick"`` (at rest). When the velocity vanishes the mass
    sticks if the spring force is within the static bound, ``|k x| <= f_s N``, otherwise it
    slides back.

    Notes
    -----
    Each half-cycle lasts pi/omega, omega = sqrt(k/m), and is a half-oscillation about
    x = -+ f_k N/k: the amplitude decreases by 2 f_k N / k per half-cycle, 4 f_k N / k per
    cycle, linearly (not exponentially as with viscous damping); the mass stops at the first
    turning point where ``|x| <= f_s N / k``.

    Examples
    --------
    >>> m = coulomb_oscillator(mass=1.0, stiffness=1.0, friction=Coulomb(0.15),
    ...                        normal_force=1.0, x0=1.0, t_end=20.0)
    >>> m.regimes
    ('slide-', 'slide+', 'slide-', 'stick')
    >>> round(m.phases[-1].y_start[0], 9), round(m.phases[-1].start, 9)   # -(1 - 6 f), 3 pi
    (-0.1, 9.424777961)
    """
    m, k, N = (_positive(v, a) for v, a in ((mass, "mass"), (stiffness, "stiffness"),
                                             (normal_force, "normal_force")))
    fs, fk = _law(friction)

    def after_stop(t, y):
        spring = -k * y[0]
        if within_cone(abs(spring), fs * N):
            return "stick"
        return "slide+" if spring > 0 else "slide-"

    plus = Regime("slide+", lambda t, y: np.array([y[1], (-k * y[0] - fk * N) / m]),
                  [_velocity_stops(1, -1, after_stop)])
    minus = Regime("slide-", lambda t, y: np.array([y[1], (-k * y[0] + fk * N) / m]),
                   [_velocity_stops(1, 1, after_stop)])
    stick = Regime("stick")

    def start(t, y):
        return "slide+" if y[1] > 0 else "slide-" if y[1] < 0 else after_stop(t, y)

    return integrate_phases([plus, minus, stick], start, (0.0, float(t_end)),
                            [float(x0), float(v0)], rtol=rtol, atol=atol)


def cylinder_on_incline(*, radius, angle, friction: Coulomb, g=9.81, inertia_factor=0.5,
                        v0=0.0, omega0=0.0, t_end, rtol=1e-12, atol=1e-12) -> PhasedMotion:
    """A cylinder (or a ball, a hoop: moment of inertia beta m r^2 about its axis) on a rough
    incline of ``angle`` alpha: it rolls without slipping or slips (ch. 23). State
    y = (x, x', theta, theta'), x down the slope, theta the rotation (rolling: x' = r theta').

    Regimes: ``"rolling"`` (x'' = g sin(alpha) / (1 + beta), friction T = beta m x'' up the
    slope), ``"slipping+"`` / ``"slipping-"`` (slip velocity s = x' - r theta' > 0 or < 0:
    x'' = g (sin(alpha) -+ f_k cos(alpha)), r theta'' = +- f_k g cos(alpha) / beta). A slipping
    phase ends where s = 0; rolling is then kept if it needs no more friction than f_s N,
    i.e. tan(alpha) <= (1 + beta) f_s / beta (= 3 f_s for a solid cylinder).

    Examples
    --------
    >>> import math
    >>> law = Coulomb(0.2, 0.15)
    >>> cylinder_on_incline(radius=0.1, angle=math.atan(0.5), friction=law, t_end=1.0).regimes
    ('rolling',)
    >>> cylinder_on_incline(radius=0.1, angle=math.atan(0.7), friction=law, t_end=1.0).regimes
    ('slipping+',)
    """
    r = _positive(radius, "radius")
    alpha = float(angle)
    g = _positive(g, "g")
    beta = _positive(inertia_factor, "inertia_factor")
    fs, fk = _law(friction)
    sin, cos = math.sin(alpha), math.cos(alpha)
    a_roll = g * sin / (1 + beta)
    rolls = within_cone(abs(beta * a_roll), fs * g * cos)   # friction needed / m, f_s N / m

    def at_no_slip(t, y):
        if rolls:
            return "rolling"
        return "slipping+" if sin > 0 else "slipping-"

    def slip(sign):
        def rhs(t, y):
            return np.array([y[1], g * (sin - sign * fk * cos), y[3],
                             sign * fk * g * cos / (beta * r)])
        return rhs

    def stick_rolling(t, y):
        y = np.array(y, dtype=float)
        y[3] = y[1] / r
        return y

    def slip_stops(direction):
        return Guard("slip stops", lambda t, y: y[1] - r * y[3], target=at_no_slip,
                     direction=direction, reset=stick_rolling)

    rolling = Regime("rolling", lambda t, y: np.array([y[1], a_roll, y[3], a_roll / r]),
                     [Guard("friction exceeds f_s N",
                            lambda t, y: fs * g * cos - abs(beta * a_roll),
                            target="slipping+" if sin > 0 else "slipping-", direction=-1)])
    plus = Regime("slipping+", slip(1.0), [slip_stops(-1)])
    minus = Regime("slipping-", slip(-1.0), [slip_stops(1)])

    def start(t, y):
        s = y[1] - r * y[3]
        return "slipping+" if s > 0 else "slipping-" if s < 0 else at_no_slip(t, y)

    return integrate_phases([rolling, plus, minus], start, (0.0, float(t_end)),
                            [0.0, float(v0), 0.0, float(omega0)], rtol=rtol, atol=atol)


def block_on_wagon(*, acceleration, friction: Coulomb, g=9.81, t_end, rtol=1e-12,
                   atol=1e-12) -> PhasedMotion:
    """A block on the floor of a wagon whose acceleration along its track is
    ``acceleration(t)`` (a number or a callable): does it slide? (ch. 24; relative motion in
    the wagon's frame, with the inertial force of entrainment -m a(t).) State
    y = (x_r, x_r'), the position of the block relative to the wagon.

    Regimes ``"stick"`` (while ``|a(t)| <= f_s g``), ``"slide+"`` / ``"slide-"`` (relative
    velocity > 0 or < 0: x_r'' = -a(t) -+ f_k g).

    Examples
    --------
    >>> m = block_on_wagon(acceleration=lambda t: 2.0 * t, friction=Coulomb(0.3, 0.2),
    ...                    t_end=3.0)
    >>> m.regimes, round(m.switch_times[0], 10)     # slips at a = f_s g: t = 0.3 g / 2
    (('stick', 'slide-'), 1.4715)
    """
    a = acceleration if callable(acceleration) else (lambda t, _a=float(acceleration): _a)
    g = _positive(g, "g")
    fs, fk = _law(friction)

    def direction_of_slip(t):
        return "slide-" if a(t) > 0 else "slide+"

    def after_stop(t, y):
        return "stick" if within_cone(abs(a(t)), fs * g) else direction_of_slip(t)

    stick = Regime("stick", None, [Guard("slips", lambda t, y: fs * g - abs(a(t)),
                                         target=lambda t, y: direction_of_slip(t),
                                         direction=-1)])
    plus = Regime("slide+", lambda t, y: np.array([y[1], -a(t) - fk * g]),
                  [_velocity_stops(1, -1, after_stop)])
    minus = Regime("slide-", lambda t, y: np.array([y[1], -a(t) + fk * g]),
                   [_velocity_stops(1, 1, after_stop)])
    return integrate_phases([stick, plus, minus], lambda t, y: after_stop(t, y),
                            (0.0, float(t_end)), [0.0, 0.0], rtol=rtol, atol=atol)


def pushed_box(*, mass, half_width, half_height, push_height, push, friction: Coulomb,
               g=9.81, t_end, rtol=1e-12, atol=1e-12, max_step=math.inf) -> PhasedMotion:
    """A box (width 2a, height 2b) at rest on a rough floor, pushed horizontally at height h
    by a force ``push(t)`` >= 0 on its rear face: it slides or tips first (ch. 24).
    State y = (x, x', phi, phi'), phi the angle of tipping about the front edge.

    Regimes: ``"rest"``; ``"slide"`` (x'' = (P - f_k m g)/m, until the box stops);
    ``"tip"`` (rotation about the front edge, I phi'' = P (2a sin(phi) + h cos(phi))
    + m g (b sin(phi) - a cos(phi)), I = 4 m (a^2 + b^2)/3, until it falls back to phi = 0).
    At rest it starts sliding when P = f_s m g and tipping when P h = m g a, whichever comes
    first. While sliding the box is assumed not to tip, and while tipping its edge not to
    slide.

    At rest the right-hand side is zero, so the integrator may take one step over the
    whole interval: with a push that rises and falls, give a ``max_step`` shorter than its
    variations or a threshold crossed and recrossed within one step goes unseen.

    Examples
    --------
    >>> m = pushed_box(mass=1.0, half_width=0.5, half_height=0.5, push_height=1.0,
    ...                push=lambda t: 2.0 * t, friction=Coulomb(0.6), g=10.0, t_end=3.0)
    >>> m.regimes[:2], round(m.switch_times[0], 10)      # tips at P = m g a / h = 5
    (('rest', 'tip'), 2.5)
    """
    m = _positive(mass, "mass")
    a, b = _positive(half_width, "half_width"), _positive(half_height, "half_height")
    h = _positive(push_height, "push_height")
    g = _positive(g, "g")
    fs, fk = _law(friction)
    P = push if callable(push) else (lambda t, _p=float(push): _p)
    inertia = 4.0 * m * (a * a + b * b) / 3.0

    def tip_rhs(t, y):
        phi = y[2]
        moment = P(t) * (2 * a * math.sin(phi) + h * math.cos(phi)) + m * g * (
            b * math.sin(phi) - a * math.cos(phi))
        return np.array([0.0, 0.0, y[3], moment / inertia])

    def rest_again(t, y):
        return np.array([y[0], 0.0, 0.0, 0.0])

    rest = Regime("rest", None, [
        Guard("starts sliding", lambda t, y: fs * m * g - P(t), target="slide", direction=-1),
        Guard("starts tipping", lambda t, y: m * g * a - P(t) * h, target="tip", direction=-1),
    ])
    slide = Regime("slide", lambda t, y: np.array([y[1], (P(t) - fk * m * g) / m, 0.0, 0.0]),
                   [Guard("stops", lambda t, y: y[1], target="rest", direction=-1,
                          reset=rest_again)])
    tip = Regime("tip", tip_rhs, [Guard("falls back", lambda t, y: y[2], target="rest",
                                        direction=-1, reset=rest_again)])

    def start(t, y):
        if m * g * a - P(t) * h < 0 or fs * m * g - P(t) < 0:
            return "tip" if (m * g * a - P(t) * h) / h < fs * m * g - P(t) else "slide"
        return "rest"

    return integrate_phases([rest, slide, tip], start, (0.0, float(t_end)),
                            [0.0, 0.0, 0.0, 0.0], rtol=rtol, atol=atol, max_step=max_step)
