"""Reference problems with exact solutions, to test and compare the solvers (book, ch. 27).

A layer above the mechanics: it may use every layer below it, and nothing in the library
imports it; the tests and the benchmarks do. :mod:`rigidmech.testing.problems` holds the
pendulum of large amplitude, Kepler orbits, a damped forced oscillator, the Arenstorf orbit and
the free asymmetric rigid body, each with its exact solution (they used to live in
``rigidmech.ode``, whose layer knows no mechanics).

Examples
--------
>>> from rigidmech.testing import problems
>>> problems.pendulum().name
'pendulum-170deg'
"""

from . import problems

__all__ = ["problems"]
