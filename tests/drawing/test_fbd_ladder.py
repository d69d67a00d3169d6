"""Free-body diagram of a ladder against a wall at its limiting equilibrium (book, ch. 14.4).

Conventions: R0 with x horizontal away from the wall (the wall is the plane x = 0) and y up
(the ground is y = 0). A uniform ladder AB of length L and weight W = m g makes the angle
alpha with the ground: foot A = (L cos alpha, 0) on the ground (friction f1), top
B = (0, L sin alpha) on the wall (friction f2), mass centre G its middle. The ground's action
on the ladder at A is N_A R0.j + T_A R0.i, the wall's at B is N_B R0.i + T_B R0.j (normals
into the ladder).

When alpha decreases the foot slides away from the wall and the top slides down: at the
limit both frictions are at f N, T_A = -f1 N_A (towards the wall) and T_B = +f2 N_B (up).
The equations of statics then give N_B = f1 N_A, N_A + f1 f2 N_A = W, and the moments about A,
N_B L sin(alpha) + T_B L cos(alpha) = W L cos(alpha) / 2, give

    tan(alpha_min) = (1 - f1 f2) / (2 f1),   N_A = W / (1 + f1 f2).
"""

import math
import os
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
import pytest
from matplotlib.testing.decorators import image_comparison

import rigidmech as rm
from rigidmech import models
from rigidmech.drawing import external_actions, free_body_diagram, limiting_values

F1, F2 = 0.4, 0.3
VALUES = {"m": 10.0, "g": 9.81, "L": 4.0}
W = 10.0 * 9.81


@pytest.fixture(autouse=True)
def _close():
    yield
    plt.close("all")


def ladder_statics():
    """The catalogue's ladder (rigidmech.models.ladder), the conventions above."""
    lad = models.ladder(F1, F2)
    return lad.system, lad.body("ladder"), lad.constant("alpha")


@pytest.fixture(scope="module")
def at_limit():
    st, ladder, alpha = ladder_statics()
    lim = st.limit(alpha, (1.4, 0.05), values=VALUES)
    values = limiting_values(st, lim, values=VALUES)
    return st, ladder, lim, values


def test_the_limiting_angle_is_the_closed_form(at_limit):
    _, _, lim, _ = at_limit
    assert lim.kinds == ("sliding",) and set(lim.contacts) == {"A", "B"}
    assert lim.value == pytest.approx(math.atan((1 - F1 * F2) / (2 * F1)), rel=1e-9)


def test_the_actions_at_the_limit_are_the_closed_form(at_limit):
    _, _, _, x = at_limit
    NA = W / (1 + F1 * F2)
    got = {u.name: v for u, v in x.items()}
    expected = {"N_A": NA, "T_A": -F1 * NA, "N_B": F1 * NA, "T_B": F1 * F2 * NA}
    assert got == pytest.approx(expected, rel=1e-8)


def test_the_diagram_at_the_limit(at_limit):
    st, ladder, lim, x = at_limit
    d = free_body_diagram(st, ladder, params={**VALUES, "alpha": lim.value}, values=x)
    assert [a.name for a in d.arrows] == ["A", "B", "W"]
    NA = W / (1 + F1 * F2)
    assert d.label_texts == [f"N_A = {NA:.3g}, T_A = {-F1 * NA:.3g}",
                             f"N_B = {F1 * NA:.3g}, T_B = {F1 * F2 * NA:.3g}",
                             f"W = {W:.3g}"]
    for action, f, side in zip(d.actions[:2], (F1, F2), ([-1, 0, 0], [0, 1, 0]), strict=True):
        # on the edge of its cone, on the side the friction points to
        assert action.cone.status == "edge"
        assert action.cone.half_angle == pytest.approx(math.atan(f), rel=1e-15)
        assert np.allclose(action.cone.side, side, atol=1e-9)
        # the arrow drawn is the computed action
        arrow = next(a for a in d.arrows if a.name == action.label)
        assert np.allclose(arrow.vector * d.scale, action.force, rtol=1e-12, atol=1e-12)
        n = action.cone.normal
        angle = math.acos(action.force @ n / np.linalg.norm(action.force))
        assert angle == pytest.approx(math.atan(f), rel=1e-8)
    assert [edge is not None for _, _, edge in d.cones] == [True, True]
    assert len(d.key) == 2 and d.key[1].get_text() == "force scale: 50 N"


def test_above_the_limit_inside_both_cones_and_undetermined():
    """At alpha = 1.2 (above the limit) statics leaves the ladder's four unknowns
    undetermined (hyperstatic of degree 1): only their names are drawn."""
    st, ladder, _ = ladder_statics()
    numbers = {**VALUES, "alpha": 1.2}
    eq = st.solve(values=numbers)
    assert eq.hyperstaticity == 1
    d = free_body_diagram(st, ladder, params=numbers, equilibrium=eq)
    assert [a.name for a in d.arrows] == ["N_A", "T_A", "N_B", "T_B", "W"]
    assert d.label_texts == ["N_A", "T_A", "N_B", "T_B", f"W = {W:.3g}"]
    assert [a.cone.status for a in d.actions[:2]] == [None, None]


def test_the_ground_cannot_be_isolated():
    st, ladder, _ = ladder_statics()
    with pytest.raises(rm.errors.ArgumentTypeError,
                       match="`bodies` must be a Body or a sequence of Bodies; got Frame"):
        external_actions(st, st.reference, params={**VALUES, "alpha": 1.0})
    with pytest.raises(rm.errors.ArgumentError, match="`bodies` must be bodies of the system"):
        external_actions(st, [ladder, st.reference], params={**VALUES, "alpha": 1.0})


#: the matplotlib the reference images of tests/drawing were made with, and their tolerance
#: (RMS difference, 0-255 scale), those of test_reference_images
PINNED = (Path(__file__).resolve().parent / "reference_images" / "MATPLOTLIB_VERSION"
          ).read_text().strip()
TOLERANCE = 2.0


@pytest.fixture
def pinned_matplotlib():
    if matplotlib.__version__ != PINNED:
        message = (f"the reference images were made with matplotlib {PINNED}; this is "
                   f"{matplotlib.__version__} (pip install matplotlib=={PINNED})")
        if os.environ.get("CI"):
            pytest.fail(message)
        pytest.skip(message)


@pytest.mark.images
@pytest.mark.usefixtures("pinned_matplotlib")
@image_comparison(["ladder_at_its_limit"], extensions=["png"], remove_text=True,
                  style="mpl20", tol=TOLERANCE)
def test_reference_image(at_limit):
    st, ladder, lim, x = at_limit
    fig, ax = plt.subplots(figsize=(4, 4))
    d = free_body_diagram(st, ladder, params={**VALUES, "alpha": lim.value}, values=x, ax=ax)
    for text in d.labels + d.key[1:]:     # remove_text takes the ticks and titles only
        text.remove()
