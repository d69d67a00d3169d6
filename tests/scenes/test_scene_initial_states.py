"""Every scene's default initial state is on its constraints (book, ch. 13.2, 25.3): the
closure conditions Φ(q0) = 0 and the velocity conditions A(q0) u0 + a = 0 hold by the
library's relative rule (:func:`rigidmech._core.rules.on_constraints`: a residual at most
1e-9 of the magnitude of its terms), so that a run starts from the state the scene states and
does not move it (a run would otherwise note the move and start elsewhere).

The residuals are evaluated here by sympy's substitution of the scene's default values into
the conditions (not the compiled functions the run uses). The regime scenes give only the
coordinates their contact leaves free (the others are put on the contact by construction) and
the bicycle is a linear analysis without an initial state: neither is concerned.

The four-bar's and the slider-crank's dependent coordinates are also checked against their
closed forms: the circles of centres B (radius BC) and D (radius DC) meet at C; the slider is
at x = r cos q1 + sqrt(l^2 - r^2 sin^2 q1).
"""

import math

import numpy as np
import pytest
import sympy as sp

from rigidmech import scenes
from rigidmech._core.rules import magnitude, on_constraints, rates_for_scale
from rigidmech.vectors import t


def _residuals_and_scales(scene):
    eqs = scene.build().system.equations_of_motion()
    c = eqs.constraints
    if c is None:
        return None
    q0, u0 = np.array(scene.q0), np.array(scene.u0)
    params = {p: scene.defaults[p.name] for p in eqs.parameters}
    at_q = {**{q: v for q, v in zip(eqs.coordinates, q0, strict=True)}, **params}
    rates = {q.diff(t): v for q, v in zip(eqs.coordinates, u0, strict=True)}
    scaled = {q.diff(t): v for q, v in zip(eqs.coordinates, rates_for_scale(u0), strict=True)}

    def value(e, rate_values):
        return float(sp.sympify(e).subs(rate_values).subs(at_q).evalf(30))

    hol = [p for p in c.position if p is not None]
    phi = np.array([value(p, {}) for p in hol])
    phi_scale = np.array([value(magnitude(p), {}) for p in hol])
    vel = np.array([value(v, rates) for v in c.velocity])
    vel_scale = np.array([value(magnitude(v), scaled) for v in c.velocity])
    return phi, phi_scale, vel, vel_scale


@pytest.mark.parametrize("scene", scenes.catalogue(), ids=lambda s: s.name)
def test_default_initial_state_is_on_the_constraints(scene):
    found = _residuals_and_scales(scene)
    if found is None:
        return                                   # no constraints: any state is on them
    phi, phi_scale, vel, vel_scale = found
    assert np.all(on_constraints(phi, phi_scale)), (scene.name, phi.tolist())
    assert np.all(on_constraints(vel, vel_scale)), (scene.name, vel.tolist())


def test_a_run_of_a_scene_with_loops_starts_where_the_scene_says():
    for name in ("four-bar", "slider-crank"):
        sc = scenes.get(name)
        rep = scenes.run(name, t_end=0.01, n_output=2)
        assert rep.simulation.q[:, 0].tolist() == list(sc.q0), name


def test_four_bar_default_state_closed_form():
    q1, q2, q3 = scenes.get("four-bar").q0
    L0, L1, L2, L3 = 2.0, 1.0, 2.0, 1.5
    B = np.array([L1 * math.cos(q1), L1 * math.sin(q1)])
    C = B + L2 * np.array([math.cos(q1 + q2), math.sin(q1 + q2)])
    C3 = np.array([L0 + L3 * math.cos(q3), L3 * math.sin(q3)])
    assert np.abs(C - C3).max() < 1e-14
    assert q1 == 1.5                              # the crank angle the scene states


def test_slider_crank_default_state_closed_form():
    q1, q2, x = scenes.get("slider-crank").q0
    r, ell = 0.5, 1.5
    assert x == pytest.approx(r * math.cos(q1) + math.sqrt(ell**2 - (r * math.sin(q1))**2),
                              rel=1e-15, abs=1e-15)
    assert math.sin(q1 + q2) == pytest.approx(-r * math.sin(q1) / ell, rel=1e-14)
    assert q1 == 1.0
