"""Forced vibrations of one degree of freedom (book, ch. 21.2.3, 21.3.3-21.3.5, 21.5): the
steady response to a harmonic force, resonance and the half-power band, support motion and
transmissibility, the equivalent viscous damping of dry friction and of structural damping,
the response to any force by Duhamel's integral.

Part of :mod:`rigidmech.vibrations.one_dof`, which re-exports every name here and states the
conventions (F0 cos(omega t), phase lag in [0, pi], r = omega / omega0).
"""

from __future__ import annotations

import math

import numpy as np
import sympy as sp

from .._core.errors import ArgumentError
from ._scalars import _as, _lib, _nonnegative, _positive, _symbolic
from .one_dof_free import damping_case, free_response

__all__ = [
    "harmonic_response", "resonance", "half_power_frequencies", "quality_factor",
    "transmissibility", "support_motion_response", "equivalent_viscous_damping",
    "dry_friction_equivalent_damping", "structural_equivalent_damping", "duhamel_response",
]


def harmonic_response(omega, omega0, zeta=0, static_deflection=1):
    """Steady response to a harmonic force :math:`F_0\\cos\\omega t` (ch. 21.2.3, 21.3.3):
    amplitude and phase lag.

    .. math:: X = \\frac{F_0/k}{\\sqrt{(1 - r^2)^2 + (2\\zeta r)^2}},\\qquad
              \\varphi = \\operatorname{atan2}(2\\zeta r,\\ 1 - r^2),\\qquad r = \\omega/\\omega_0.

    Parameters
    ----------
    omega : float, array or sympy expression
        Angular frequency of the force.
    omega0, zeta : natural frequency and damping ratio
    static_deflection : F0 / k (default 1: the amplification factor)

    Returns
    -------
    (amplitude, phase)

    Examples
    --------
    >>> X, phi = harmonic_response(10.0, 10.0, 0.05)
    >>> round(float(X), 12), round(float(phi), 12)
    (10.0, 1.570796326795)
    """
    lib = _lib(omega, omega0, zeta, static_deflection)
    w, w0, z, xs = (_as(a, lib) for a in (omega, omega0, zeta, static_deflection))
    r = w / w0
    amplitude = xs / lib.sqrt((1 - r**2) ** 2 + (2 * z * r) ** 2)
    phase = lib.atan2(2 * z * r, 1 - r**2) if lib is sp else np.arctan2(2 * z * r, 1 - r**2)
    return amplitude, phase


def resonance(omega0, zeta, static_deflection=1):
    """Peak of the amplitude of the forced response (ch. 21.3.3): frequency
    :math:`\\omega_r = \\omega_0\\sqrt{1 - 2\\zeta^2}` and amplitude
    :math:`X_r = (F_0/k) / (2\\zeta\\sqrt{1-\\zeta^2})`, for :math:`\\zeta < 1/\\sqrt 2`
    (above, the amplitude decreases from :math:`F_0/k` at ω = 0: no resonance).

    Returns
    -------
    (peak frequency, peak amplitude)

    Examples
    --------
    >>> import sympy as sp
    >>> w0, z = sp.symbols("omega_0 zeta", positive=True)
    >>> resonance(w0, z)
    (omega_0*sqrt(1 - 2*zeta**2), 1/(2*zeta*sqrt(1 - zeta**2)))
    >>> resonance(1.0, 0.8)
    Traceback (most recent call last):
    ...
    rigidmech._core.errors.ArgumentError: `zeta` must be < 1/sqrt(2) = 0.7071 for a resonance ...
    """
    lib = _lib(omega0, zeta, static_deflection)
    w0, z, xs = (_as(a, lib) for a in (omega0, zeta, static_deflection))
    if lib is np and np.any((z <= 0) | (z >= 1 / math.sqrt(2))):
        raise ArgumentError(
            f"`zeta` must be < 1/sqrt(2) = 0.7071 for a resonance peak; got {zeta}."
            if np.any(z > 0) else f"`zeta` must be > 0 for a finite peak; got {zeta}.")
    return w0 * lib.sqrt(1 - 2 * z**2), xs / (2 * z * lib.sqrt(1 - z**2))


def half_power_frequencies(omega0, zeta):
    """The two frequencies where the amplitude is the peak amplitude over √2 (ch. 21.3.3),
    exactly: :math:`\\omega_{1,2} = \\omega_0\\sqrt{1 - 2\\zeta^2 \\mp 2\\zeta\\sqrt{1 -
    \\zeta^2}}`. Their difference, the half-power bandwidth, is :math:`\\approx 2\\zeta
    \\omega_0` for light damping.

    Examples
    --------
    >>> w1, w2 = half_power_frequencies(10.0, 0.01)
    >>> round(float(w2 - w1), 4)
    0.2
    """
    lib = _lib(omega0, zeta)
    w0, z = _as(omega0, lib), _as(zeta, lib)
    s = 2 * z * lib.sqrt(1 - z**2)
    if lib is np and np.any(1 - 2 * z**2 - s <= 0):
        raise ArgumentError(
            f"`zeta` too large for a lower half-power frequency (needs 1 - 2 zeta^2 > 2 zeta "
            f"sqrt(1 - zeta^2), zeta < 0.3827); got {zeta}.")
    return w0 * lib.sqrt(1 - 2 * z**2 - s), w0 * lib.sqrt(1 - 2 * z**2 + s)


def quality_factor(zeta):
    """Quality factor :math:`Q = 1/(2\\zeta)`: the amplification at ω = ω0, and
    :math:`\\omega_0 / \\Delta\\omega` to first order in ζ (ch. 21.3.3).

    Examples
    --------
    >>> quality_factor(0.05)
    10.0
    """
    _positive(zeta, "zeta")
    lib = _lib(zeta)
    return 1 / (2 * _as(zeta, lib)) if lib is sp else 1.0 / (2.0 * float(zeta))


def transmissibility(r, zeta=0):
    """Transmissibility :math:`T = \\sqrt{1 + (2\\zeta r)^2} / \\sqrt{(1 - r^2)^2 +
    (2\\zeta r)^2}` (ch. 21.3.6): the ratio of the amplitude of the motion of the mass to
    that of a harmonic motion of the support (displacement transmissibility), and equally the
    ratio of the force transmitted to the support by spring and damper to a harmonic force on
    the mass (force transmissibility). T < 1 (isolation) for :math:`r > \\sqrt 2`.

    Examples
    --------
    >>> import sympy as sp
    >>> transmissibility(sp.sqrt(2), sp.Symbol("zeta", positive=True))
    1
    >>> round(float(transmissibility(3.0, 0.0)), 12)
    0.125
    """
    lib = _lib(r, zeta)
    r, z = _as(r, lib), _as(zeta, lib)
    num = 1 + (2 * z * r) ** 2
    den = (1 - r**2) ** 2 + (2 * z * r) ** 2
    return lib.sqrt(num / den) if lib is np else sp.simplify(lib.sqrt(num) / lib.sqrt(den))


def support_motion_response(omega, omega0, zeta, amplitude):
    """Steady response to a harmonic motion :math:`y = Y\\cos\\omega t` of the support
    (ch. 21.3.6), spring and damper between the support and the mass.

    Returns
    -------
    (absolute amplitude X, phase lag of x behind y, relative amplitude Z of x - y)
        :math:`X = T\\,Y`,
        :math:`\\varphi = \\operatorname{atan2}(2\\zeta r^3,\\ 1 - r^2 + (2\\zeta r)^2)`,
        :math:`Z = r^2 Y / \\sqrt{(1-r^2)^2 + (2\\zeta r)^2}`.

    Examples
    --------
    >>> X, phi, Z = support_motion_response(30.0, 10.0, 0.0, 0.01)
    >>> round(float(X), 12), round(float(Z), 12)
    (0.00125, 0.01125)
    """
    lib = _lib(omega, omega0, zeta, amplitude)
    w, w0, z, Y = (_as(a, lib) for a in (omega, omega0, zeta, amplitude))
    r = w / w0
    den = lib.sqrt((1 - r**2) ** 2 + (2 * z * r) ** 2)
    X = Y * lib.sqrt(1 + (2 * z * r) ** 2) / den
    atan2 = sp.atan2 if lib is sp else np.arctan2
    phase = atan2(2 * z * r**3, 1 - r**2 + (2 * z * r) ** 2)
    return X, phase, r**2 * Y / den


def equivalent_viscous_damping(energy_per_cycle, omega, amplitude):
    """Viscous damping coefficient dissipating the same energy per cycle of a harmonic
    motion :math:`X\\cos\\omega t` (ch. 21.5): :math:`c_{eq} = \\Delta E / (\\pi \\omega X^2)`,
    from :math:`\\Delta E = \\pi c \\omega X^2` for a viscous damper (ch. 21.5.2).

    Examples
    --------
    >>> import sympy as sp
    >>> c, w, X = sp.symbols("c omega X", positive=True)
    >>> equivalent_viscous_damping(sp.pi * c * w * X**2, w, X)
    c
    """
    lib = _lib(energy_per_cycle, omega, amplitude)
    e, w, X = (_as(a, lib) for a in (energy_per_cycle, omega, amplitude))
    return e / (lib.pi * w * X**2)


def dry_friction_equivalent_damping(friction_force, omega, amplitude):
    """Equivalent viscous damping of dry friction F (ch. 21.5.4): the energy dissipated per
    cycle is 4 F X, so :math:`c_{eq} = 4F / (\\pi\\omega X)`.

    Examples
    --------
    >>> import sympy as sp
    >>> F, w, X = sp.symbols("F omega X", positive=True)
    >>> dry_friction_equivalent_damping(F, w, X)
    4*F/(pi*X*omega)
    """
    _nonnegative(friction_force, "friction_force")
    return equivalent_viscous_damping(4 * friction_force * amplitude, omega, amplitude)


def structural_equivalent_damping(loss_coefficient, omega):
    """Equivalent viscous damping of structural (hysteretic) damping (ch. 21.5.3): the energy
    dissipated per cycle is :math:`\\Delta E = \\alpha X^2`, independent of the frequency,
    so :math:`c_{eq} = \\alpha / (\\pi\\omega)`. With a loss factor η of a spring k,
    :math:`\\alpha = \\pi\\eta k` and :math:`c_{eq} = \\eta k/\\omega`.

    Examples
    --------
    >>> import sympy as sp
    >>> alpha, w = sp.symbols("alpha omega", positive=True)
    >>> structural_equivalent_damping(alpha, w)
    alpha/(pi*omega)
    """
    _nonnegative(loss_coefficient, "loss_coefficient")
    X = sp.Symbol("X", positive=True)
    if _symbolic(loss_coefficient, omega):
        return sp.simplify(equivalent_viscous_damping(loss_coefficient * X**2, omega, X))
    return float(loss_coefficient) / (math.pi * np.asarray(omega, dtype=float))


def duhamel_response(force, t, *, mass, omega0, zeta=0.0, x0=0.0, v0=0.0, rtol=1e-10):
    """Response to an arbitrary force F(t) by Duhamel's integral (ch. 21.3.5), numerically:

    .. math:: x(t) = x_{free}(t) + \\int_0^t F(\\tau)\\,h(t - \\tau)\\,d\\tau,

    with the impulse response h(s) the free response from x = 0, x' = 1/m (closed form,
    :func:`free_response`, any damping case) and the integral by ``scipy.integrate.quad``
    at each time.

    Parameters
    ----------
    force : callable F(tau) -> float
    t : array of times >= 0
    mass, omega0, zeta, x0, v0 : floats
    rtol : relative tolerance of each quadrature

    Examples
    --------
    A step force F0 on an undamped oscillator: x = (F0/k)(1 - cos ω0 t).

    >>> import numpy as np
    >>> x = duhamel_response(lambda tau: 2.0, np.array([0.5, 1.0]), mass=1.0, omega0=2.0)
    >>> bool(np.allclose(x, 0.5 * (1 - np.cos(2.0 * np.array([0.5, 1.0]))), rtol=1e-9))
    True
    """
    import scipy.integrate  # imported on use (slow import)

    if not callable(force):
        raise ArgumentError(f"`force` must be a callable F(tau); got {type(force).__name__}.")
    _positive(mass, "mass")
    _positive(omega0, "omega0")
    _nonnegative(zeta, "zeta")
    times = np.atleast_1d(np.asarray(t, dtype=float))
    if np.any(times < 0):
        raise ArgumentError("`t` must hold times >= 0 (the force acts from t = 0).")
    case = damping_case(float(zeta))
    m, w0, z = float(mass), float(omega0), float(zeta)

    def h(s):
        return free_response(s, 0.0, 1.0 / m, w0, z, case=case)

    out = np.empty_like(times)
    for n, ti in enumerate(times):
        if ti == 0:
            out[n] = 0.0
            continue
        limit = max(50, int(4 * ti * w0))
        out[n] = scipy.integrate.quad(lambda tau, ti=ti: float(force(tau)) * float(h(ti - tau)),
                                      0.0, ti, epsrel=rtol, epsabs=0.0, limit=limit)[0]
    out = out + free_response(times, float(x0), float(v0), w0, z, case=case)
    return out if np.ndim(t) else float(out[0])
