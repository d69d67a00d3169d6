"""The derivation's speed-ups keep the equations: the mass matrix, the forcing and the
constraints (velocity rows, Jacobian A, bias b) of the derivation agree with those of the
previous code path (kept behind a private flag for this test only) at random numeric states,
to 1e-12 relative to the entries' scale.

Reference: the previous code path (the rolling rows expanded, :mod:`rigidmech.systems.closure`;
q'' dropped from the accelerations by sympy's ``xreplace``, :mod:`rigidmech.dynamics._derivation`),
which the crosscheck suite checks against sympy.physics.mechanics's KanesMethod. No value is
stored: both sides are computed here.
"""

import numpy as np
import pytest
import sympy as sp
from numpy.testing import assert_allclose

from rigidmech import models
from rigidmech.dynamics import _derivation
from rigidmech.systems import closure
from rigidmech.vectors import t

BUILDERS = {
    "whipple_bicycle": models.whipple_bicycle,
    "spherical_chain_3": lambda: models.spherical_chain(3),
    "four_bar": models.four_bar,
    "rolling_disc": models.rolling_disc,
    "sleigh": models.sleigh,
}


def _matrices(system):
    eqs = system.equations_of_motion()
    out = {"M": eqs.mass_matrix, "f": eqs.forcing}
    c = system.constraints()
    if c is not None:
        out.update(velocity=sp.ImmutableMatrix(len(c.velocity), 1, list(c.velocity)),
                   A=c.jacobian, b=c.bias)
    return out


def _state(system, exprs, seed):
    """Random values of q, q', q'' and of the constants (positive, O(1))."""
    rng = np.random.default_rng(seed)
    rule = {}
    for q in system.coordinates:
        rule[sp.Derivative(q, (t, 2))] = sp.Float(rng.uniform(-1, 1))
        rule[sp.Derivative(q, t)] = sp.Float(rng.uniform(-1, 1))
    coords = {q: sp.Float(rng.uniform(-1, 1)) for q in system.coordinates}
    symbols = set().union(*(e.free_symbols for e in exprs)) - {t}
    consts = {s: sp.Float(rng.uniform(0.5, 1.5)) for s in sorted(symbols, key=str)}
    return rule, {**coords, **consts}


def _values(matrix, rule, rest):
    # derivatives first (they contain q(t)), then q(t) and the constants
    m = matrix.xreplace(rule).xreplace(rest)
    return np.array(m.evalf(30).tolist(), dtype=float)


@pytest.mark.parametrize("name", [pytest.param(n, marks=pytest.mark.slow) if n == "whipple_bicycle"
                                  else n for n in sorted(BUILDERS)])
def test_derivation_agrees_with_the_previous_path(name, monkeypatch):
    build = BUILDERS[name]
    system = build().system
    new = _matrices(system)
    monkeypatch.setattr(closure, "_EXPAND_CONTACT_ROWS", True)
    monkeypatch.setattr(_derivation, "_SHARED_REPLACE", False)
    old = _matrices(build().system)
    assert new.keys() == old.keys()
    exprs = [e for m in new.values() for e in m] + [e for m in old.values() for e in m]
    for seed in (1, 2):
        rule, rest = _state(system, exprs, seed)
        for key in new:
            a, b = _values(new[key], rule, rest), _values(old[key], rule, rest)
            scale = max(1.0, float(np.abs(b).max()))
            assert_allclose(a, b, rtol=1e-12, atol=1e-12 * scale, err_msg=f"{name}: {key}")
