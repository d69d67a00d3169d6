"""The page for users of sympy.physics.mechanics (docs/from_sympy_mechanics.rst) promises only
what exists: every Python block runs, in order, and the two sides give the same equations
(double pendulum: M and f equal symbolically, Kane's full form equal; rolling disc and four-bar:
the same accelerations at a state on the constraints)."""

import pathlib
import re

import numpy as np
import sympy as sp

PAGE = pathlib.Path(__file__).resolve().parents[1] / "docs" / "from_sympy_mechanics.rst"


def test_every_block_runs_and_the_two_sides_agree(tmp_path, monkeypatch):
    text = PAGE.read_text()
    blocks = re.findall(r"\.\. code-block:: python\n\n((?:   .*\n|\n)+)", text)
    assert len(blocks) == text.count(".. code-block::") >= 9
    monkeypatch.chdir(tmp_path)
    ns = {}
    for k, block in enumerate(blocks):
        code = "\n".join(line[3:] for line in block.splitlines())
        exec(compile(code, f"{PAGE}:block{k}", "exec"), ns)  # noqa: S102
    # the checks the page makes, made again here (a block without its assert would pass)
    assert sp.simplify(ns["ours"].mass_matrix - ns["lm"].mass_matrix) == sp.zeros(2, 2)
    assert sp.simplify(ns["ours"].forcing - ns["lm"].forcing) == sp.zeros(2, 1)
    assert sp.simplify(ns["mass_matrix_full"] - ns["kane"].mass_matrix_full) == sp.zeros(4, 4)
    assert sp.simplify(ns["forcing_full"] - ns["kane"].forcing_full) == sp.zeros(4, 1)
    np.testing.assert_allclose(ns["ours_acc"][[2, 3, 4, 0, 1]], ns["theirs_acc"], rtol=1e-10,
                               atol=1e-12)
    np.testing.assert_allclose(ns["ours_bar"], ns["theirs_bar"], rtol=1e-9, atol=1e-10)
    assert np.max(np.abs(ns["theirs_acc"])) > 0.1 and np.max(np.abs(ns["theirs_bar"])) > 0.1


def test_the_page_is_in_the_index():
    index = (PAGE.parent / "index.rst").read_text()
    assert "from_sympy_mechanics" in index
