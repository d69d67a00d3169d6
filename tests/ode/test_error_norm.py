"""DOP853's combined error norm has one definition (``_floatpath.ERROR_NORM_LINES``): the
generated step, the numpy step and the batch form must all compute it."""

import math

import numpy as np
import pytest

from rigidmech.ode import adaptive
from rigidmech.ode._floatpath import error_norm


def _hairer(h_abs, s5, s3, n):
    # Hairer's DOP853 (and scipy's DOP853): err5^2 / sqrt(err5^2 + 0.01 err3^2), RMS over n
    den = s5 + 0.01 * s3
    if den == 0:
        return 0.0
    return h_abs * s5 / math.sqrt(den * n)


@pytest.mark.parametrize(("s5", "s3"), [(4.0, 0.0), (1e-3, 2.0), (0.0, 0.0), (0.0, 3.0),
                                        (2.5e-20, 1e-18)])
def test_the_definition_is_hairers(s5, s3):
    assert error_norm(2)(0.3, s5, s3, 4) == pytest.approx(_hairer(0.3, s5, s3, 4), rel=1e-15)
    assert error_norm(1)(0.3, s5, None, 4) == pytest.approx(0.3 * math.sqrt(s5 / 4), rel=1e-15)


def test_batch_form_is_the_definition_member_by_member():
    rng = np.random.default_rng(1)
    s5, s3 = rng.random(50) ** 4, rng.random(50) ** 4
    s5[[3, 7]] = 0.0
    s3[7] = 0.0
    norm = error_norm(2)
    members = [norm(0.01, a, b, 6) for a, b in zip(s5.tolist(), s3.tolist(), strict=True)]
    assert adaptive.batch_error_norm(0.01, s5, s3, 6) == max(members)
    s5[11] = np.nan  # a nan member makes the error nan (the step is rejected), as for one
    assert math.isnan(norm(0.01, math.nan, 0.0, 6))
    assert math.isnan(adaptive.batch_error_norm(0.01, s5, s3, 6))


def test_generated_step_computes_the_definition():
    # one DOP853 step on y' = -y, n = 2: the generated step's error against the definition
    # applied to the step's own error vectors (recomputed with numpy from its stages)
    pair = adaptive.DOP853
    rtol, atols = 1e-6, [1e-9, 1e-9]
    step = pair.kernel(2)(lambda t, y: -y, rtol, atols)
    y, h = [1.0, -0.5], 0.3
    r = step(0.0, y, [-1.0, 0.5], h)
    K = np.array(r.data[0])  # the stages, FSAL stage last
    scale = np.array(atols) + rtol * np.maximum(np.abs(y), np.abs(r.y))
    s5, s3 = (((pair.E @ K) / scale) ** 2).sum(axis=1)
    assert r.error == pytest.approx(error_norm(2)(h, s5, s3, 2), rel=1e-12)
