"""Motion with regime changes: stick, slip, roll, tip (book, ch. 21.4, 23, 24).

* :mod:`~rigidmech.regimes.phased`: a generic phase-by-phase integrator (:class:`Regime`,
  :class:`Guard`, :func:`integrate_phases`, :class:`PhasedMotion`);
* :mod:`~rigidmech.regimes.friction`: the book's systems with dry friction written regime by
  regime (Coulomb-damped oscillator, cylinder rolling or slipping on an incline, block on an
  accelerating wagon, box pushed on a floor);
* :mod:`~rigidmech.regimes.contact_motion`: the regimes of a
  :class:`~rigidmech.dynamics.System` with one-sided contacts and friction
  (:class:`~rigidmech.actions.FrictionContact`), derived from the system
  (:func:`contact_motion`).
"""

from .contact_motion import ContactMotion, contact_motion
from .friction import block_on_wagon, coulomb_oscillator, cylinder_on_incline, pushed_box
from .phased import Guard, Phase, PhasedMotion, Regime, integrate_phases

__all__ = ["Guard", "Regime", "Phase", "PhasedMotion", "integrate_phases",
           "coulomb_oscillator", "cylinder_on_incline", "block_on_wagon", "pushed_box",
           "contact_motion", "ContactMotion"]
