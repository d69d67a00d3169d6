"""Derivations step by step, the book's way (book, ch. 9, 16, 18, 20, 25).

:func:`derivation` lays out how the equations of motion of a system come out of the
fundamental principle (or of Lagrange's equations): the parameters of situation, the
kinematic, kinetic and dynamic torsors, the action torsors, the partial kinematic torsors and
power coefficients, the projected principle and the equations. The :class:`Derivation` it
returns prints as plain text, as LaTeX (a complete document or a fragment), renders in
Jupyter and writes a ``.tex`` file.

Examples
--------
>>> from rigidmech import models, report
>>> rep = report.derivation(models.compound_pendulum())
>>> rep.equations.mass_matrix
Matrix([[L**2*m/3]])
>>> "\\\\documentclass" in rep.to_latex(), "\\\\documentclass" in rep.to_latex(standalone=False)
(True, False)
"""

from .derive import ROUTES, default_point, derivation
from .document import LATEX_PACKAGES, Derivation, Line, Step

__all__ = ["derivation", "default_point", "ROUTES", "Derivation", "Step", "Line",
           "LATEX_PACKAGES"]
