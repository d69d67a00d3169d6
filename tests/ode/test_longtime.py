"""Long-time energy behaviour on Kepler e = 0.6 (book 27.3.1; TARGETS.md, long-time section).

Symplectic, symmetric methods keep the energy error bounded: it oscillates within each orbit
(largest at the pericentre) but its maximum over a window of orbits does not grow. A
non-symplectic method (fixed-step RK4, adaptive DOP853) drifts by about the same amount every
orbit, so the maximum grows linearly with time. We fit the exponent ``g`` of
``max |dE/E| over [t_(i-1), t_i]  ~  t_i**g`` over 20 windows of 10 orbits each.
"""

import numpy as np
import pytest

from rigidmech import ode
from rigidmech.testing.problems import kepler

ORBITS = 200
WINDOWS = 20


def _growth_exponent(p, r):
    rel = np.abs((p.energy(r.y) - p.energy(p.y0)) / p.energy(p.y0))
    edges = np.linspace(0.0, r.t[-1], WINDOWS + 1)
    idx = np.searchsorted(r.t, edges)
    peaks = np.array([rel[idx[i]: idx[i + 1] + 1].max() for i in range(WINDOWS)])
    return np.polyfit(np.log(edges[1:]), np.log(peaks), 1)[0], peaks


@pytest.fixture(scope="module")
def problem():
    return kepler(0.6, orbits=ORBITS)


@pytest.mark.parametrize(("method", "per_orbit", "bound"),
                         [("verlet", 200, 1e-2), ("yoshida4", 200, 2e-4),
                          ("yoshida6", 100, 2e-5)])
def test_symplectic_energy_error_is_bounded(problem, method, per_orbit, bound):
    r = ode.solve(problem.acceleration, problem.t_span, problem.y0, method=method,
                  step=problem.period / per_orbit)
    g, peaks = _growth_exponent(problem, r)
    # measured g = 0.000 (peaks equal to 8 digits); 0.1 is the target of TARGETS.md
    assert g <= 0.1, (g, peaks)
    assert peaks.max() < bound  # O(h^p) size, measured 7.4e-3, 9.5e-5, 1.7e-5


def test_rk4_energy_error_grows_linearly(problem):
    r = ode.solve(problem.fun, problem.t_span, problem.y0, method="rk4",
                  step=problem.period / 200)
    g, peaks = _growth_exponent(problem, r)
    # a constant drift per orbit gives g = 1 (measured 0.99); the band leaves room for the
    # first window, where the oscillation within an orbit is a sizeable part of the peak
    assert 0.85 <= g <= 1.15, (g, peaks)


def test_dop853_energy_error_grows_linearly(problem):
    r = ode.solve(problem.fun, problem.t_span, problem.y0, method="dop853", rtol=1e-8,
                  atol=1e-11)
    g, peaks = _growth_exponent(problem, r)
    assert 0.85 <= g <= 1.15, (g, peaks)  # measured 0.975
