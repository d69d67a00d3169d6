"""Vibrations of a system with one degree of freedom (book, ch. 21).

The equation of motion of ch. 21.3.1,

.. math:: m\\,\\ddot x + c\\,\\dot x + k\\,x = F(t),

has the natural (angular) frequency :math:`\\omega_0 = \\sqrt{k/m}`, the damping ratio
:math:`\\zeta = c / (2\\sqrt{k m})` and, for :math:`\\zeta < 1`, the damped frequency
:math:`\\omega_d = \\omega_0\\sqrt{1-\\zeta^2}`. Every function here is a closed form and works
on numbers (numpy arrays broadcast) or on sympy expressions (then the result is symbolic),
except :func:`duhamel_response`, which integrates numerically.

Conventions: a harmonic force is :math:`F_0\\cos\\omega t`; the steady response is
:math:`X\\cos(\\omega t - \\varphi)` with the phase lag :math:`\\varphi \\in [0, \\pi]`;
:math:`r = \\omega/\\omega_0` is the frequency ratio.
"""

# The closed forms live in two modules, free and forced vibrations; this module is their
# public home (the names below, the documentation, the references from the chapters).
from ._scalars import _as, _lib, _nonnegative, _positive, _symbolic  # noqa: F401  (shared helpers)
from .one_dof_forced import (
    dry_friction_equivalent_damping,
    duhamel_response,
    equivalent_viscous_damping,
    half_power_frequencies,
    harmonic_response,
    quality_factor,
    resonance,
    structural_equivalent_damping,
    support_motion_response,
    transmissibility,
)
from .one_dof_free import (
    coulomb_free_response,
    coulomb_stop,
    critical_damping,
    damped_frequency,
    damping_case,
    damping_coefficient,
    damping_ratio,
    free_response,
    logarithmic_decrement,
    natural_frequency,
)

__all__ = [
    "natural_frequency", "critical_damping", "damping_ratio", "damping_coefficient",
    "damped_frequency", "logarithmic_decrement",
    "damping_case", "free_response", "harmonic_response", "resonance",
    "half_power_frequencies", "quality_factor", "transmissibility", "support_motion_response",
    "coulomb_stop", "coulomb_free_response", "equivalent_viscous_damping",
    "dry_friction_equivalent_damping", "structural_equivalent_damping", "duhamel_response",
]
