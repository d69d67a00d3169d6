"""Drawings compared with reference images (matplotlib's image comparison, text removed).

Marked ``images``: deselected by default (pyproject's addopts) and run by CI in a stage of its
own that installs the matplotlib the references were made with (the version in
``reference_images/MATPLOTLIB_VERSION``): ``python -m pytest -m images``. Another matplotlib
may rasterise differently; the test is skipped there outside CI and fails in CI. To make the
references again (after a deliberate change of the drawings), run with
``RIGIDMECH_UPDATE_IMAGES=1`` and look at the images before committing them.
"""

import os
from pathlib import Path

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt
import pytest
from matplotlib.testing.compare import compare_images
from matplotlib.testing.decorators import remove_ticks_and_titles

from rigidmech import models
from rigidmech.drawing import draw

pytestmark = pytest.mark.images

HERE = Path(__file__).resolve().parent / "reference_images"
PINNED = (HERE / "MATPLOTLIB_VERSION").read_text().strip()
#: RMS difference allowed (0-255 scale): anti-aliasing noise, not a moved symbol
TOLERANCE = 2.0

CASES = {
    "double_pendulum": (models.double_pendulum, [0.6, 1.2], {"L": 1.0}),
    "four_bar": (models.four_bar, [1.2, -0.9266, 1.3776], {}),   # closed (to 1e-4)
    "heavy_top": (models.heavy_top, [0.4, 0.5, 0.0], {"l": 1.0, "A": 1.0, "C": 0.5}),
}


@pytest.mark.parametrize("name", sorted(CASES))
def test_drawing_matches_its_reference_image(name, tmp_path):
    if matplotlib.__version__ != PINNED:
        message = (f"the reference images were made with matplotlib {PINNED}; this is "
                   f"{matplotlib.__version__} (pip install matplotlib=={PINNED})")
        if os.environ.get("CI"):
            pytest.fail(message)
        pytest.skip(message)
    build, q, params = CASES[name]
    with matplotlib.style.context("default"):
        d = draw(build(), q, params, labels=False, frames=True, figsize=(4, 4))
        remove_ticks_and_titles(d.figure)
        for text in list(d.ax.texts):    # remove_text: the trihedra's labels too
            text.remove()
        actual = tmp_path / f"{name}.png"
        d.figure.savefig(actual, dpi=80)
        plt.close(d.figure)
    expected = HERE / f"{name}.png"
    if os.environ.get("RIGIDMECH_UPDATE_IMAGES"):
        expected.write_bytes(actual.read_bytes())
    result = compare_images(str(expected), str(actual), tol=TOLERANCE)
    assert result is None, result
