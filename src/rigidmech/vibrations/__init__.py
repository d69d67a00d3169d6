"""Equilibria, linearisation and vibrations (book, ch. 21, 22, 25.4).

One degree of freedom in closed form (:mod:`~rigidmech.vibrations.one_dof`), natural modes of
several degrees of freedom (:mod:`~rigidmech.vibrations.modes`), the linearisation of
equations of motion about an equilibrium or a steady motion
(:mod:`~rigidmech.vibrations.linearize`), equilibria, their stability and bifurcations
(:mod:`~rigidmech.vibrations.equilibria`), the critical value of a parameter where a
linearised motion changes stability (:mod:`~rigidmech.vibrations.critical`), steady motions
with q' ≠ 0 (:mod:`~rigidmech.vibrations.steady`), rotors and pendulums
(:mod:`~rigidmech.vibrations.rotors`).
"""

from .critical import StabilityChange, critical_value, growth, stability_changes
from .equilibria import Bifurcation, bifurcation, equilibria, potential_stability, stability
from .linearize import LinearSystem, linearize
from .modes import Modes, harmonic_response_direct, natural_modes, plot_frequency_response
from .one_dof import (
    coulomb_free_response,
    coulomb_stop,
    critical_damping,
    damped_frequency,
    damping_case,
    damping_coefficient,
    damping_ratio,
    dry_friction_equivalent_damping,
    duhamel_response,
    equivalent_viscous_damping,
    free_response,
    half_power_frequencies,
    harmonic_response,
    logarithmic_decrement,
    natural_frequency,
    quality_factor,
    resonance,
    structural_equivalent_damping,
    support_motion_response,
    transmissibility,
)
from .pendulum import PERIOD_SERIES, pendulum_period, pendulum_period_series
from .rotors import (
    balancing_masses,
    bearing_forces,
    centre_of_percussion,
    compound_pendulum_period,
    equivalent_length,
    kater_conjugate,
    rotor_bearing_action,
    torsion_pendulum_period,
)
from .steady import SteadyMotion, steady_motions, steady_stability

__all__ = [
    "natural_frequency", "critical_damping", "damping_ratio", "damping_coefficient",
    "damped_frequency", "logarithmic_decrement",
    "damping_case", "free_response", "harmonic_response", "resonance",
    "half_power_frequencies", "quality_factor", "transmissibility", "support_motion_response",
    "coulomb_stop", "coulomb_free_response", "equivalent_viscous_damping",
    "dry_friction_equivalent_damping", "structural_equivalent_damping", "duhamel_response",
    "Modes", "natural_modes", "harmonic_response_direct", "plot_frequency_response",
    "LinearSystem", "linearize", "equilibria", "stability", "potential_stability",
    "Bifurcation", "bifurcation", "critical_value", "stability_changes", "StabilityChange",
    "growth",
    "SteadyMotion", "steady_motions", "steady_stability",
    "rotor_bearing_action", "bearing_forces", "balancing_masses", "equivalent_length",
    "centre_of_percussion", "kater_conjugate", "compound_pendulum_period",
    "torsion_pendulum_period",
    "pendulum_period", "pendulum_period_series", "PERIOD_SERIES",
]
