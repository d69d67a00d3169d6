"""Torsors (book, ch. 5): one algebra for kinematic, action, kinetic and dynamic torsors.

- :class:`Torsor` {R ; M(A)}: transport, sum, automoment, comoment, classification, pitch,
  central axis, moment about an axis, resolution into a slider plus a couple
  (:class:`Resolution`); :func:`slider` and :func:`couple` (ch. 5.1-5.2).
- Torsors of fields of sliders: :func:`torsor_of_sliders` for a finite set of points,
  :func:`torsor_of_field` over a parametrised :class:`Domain` (curve, surface, volume), the
  measure centre :func:`measure_centre`, :func:`total_measure` and, for weighted
  points, :func:`barycentre` (ch. 5.3).
"""

from .fields import (
    Domain,
    barycentre,
    measure_centre,
    torsor_of_field,
    torsor_of_sliders,
    total_measure,
)
from .torsor import Resolution, Torsor, couple, slider

__all__ = ["Torsor", "Resolution", "couple", "slider", "Domain", "torsor_of_sliders",
           "torsor_of_field", "total_measure", "measure_centre", "barycentre"]
