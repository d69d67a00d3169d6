"""``import rigidmech`` leaves the slow optional imports for first use (docs/performance).

scipy (about 0.7 s for scipy.linalg and scipy.optimize), matplotlib and tqdm are imported by the
functions that need them, and the subpackages above dynamics (statics, regimes, lagrange,
vibrations, scenes, models, testing) by the package's module ``__getattr__``; every public name
must still resolve, to the same object as before. Checked in fresh interpreters, since this
test process has imported everything already. No timing here (benchmarks/import_time.py).
"""

import functools
import json
import os
import subprocess
import sys
from pathlib import Path

import numpy as np

SRC = Path(__file__).resolve().parent.parent / "src"

LAZY_THIRD_PARTY = ("scipy", "matplotlib", "tqdm")
LAZY_SUBPACKAGES = ("statics", "regimes", "lagrange", "vibrations", "scenes", "models", "testing",
                    "report", "drawing")


@functools.cache     # the same script twice (two checks of one fresh import): run once
def run_json(code):
    """Run `code` in a fresh interpreter (warnings as errors); its last stdout line, as JSON."""
    env = dict(os.environ, PYTHONPATH=str(SRC) + os.pathsep + os.environ.get("PYTHONPATH", ""))
    out = subprocess.run([sys.executable, "-W", "error", "-c", code], env=env, check=True,
                         capture_output=True, text=True)
    return json.loads(out.stdout.strip().splitlines()[-1])


def test_import_rigidmech_does_not_import_scipy_matplotlib_tqdm():
    loaded = run_json(
        "import json, sys; import rigidmech; print(json.dumps(sorted(sys.modules)))")
    heavy = [m for m in loaded if m.split(".")[0] in LAZY_THIRD_PARTY]
    assert heavy == []


def test_import_rigidmech_leaves_upper_subpackages_for_first_use():
    loaded = run_json(
        "import json, sys; import rigidmech; print(json.dumps(sorted(sys.modules)))")
    assert [p for p in LAZY_SUBPACKAGES if f"rigidmech.{p}" in loaded] == []


def test_every_public_name_resolves_in_a_fresh_interpreter():
    report = run_json("""
import json, rigidmech
missing = [n for n in rigidmech.__all__ if not hasattr(rigidmech, n)]
print(json.dumps({"missing": missing, "all": list(rigidmech.__all__)}))
""")
    assert report["missing"] == []
    assert "Statics" in report["all"] and "lagrange_equations" in report["all"]


def test_star_import_and_dir_are_complete_in_a_fresh_interpreter():
    report = run_json("""
import json, rigidmech
namespace = {}
exec("from rigidmech import *", namespace)
print(json.dumps({"star": sorted(set(rigidmech.__all__) - set(namespace)),
                  "dir": sorted(set(rigidmech.__all__) - set(dir(rigidmech)))}))
""")
    assert report == {"star": [], "dir": []}


def test_lazy_names_are_the_subpackage_objects():
    report = run_json("""
import json, rigidmech as rm
import rigidmech.lagrange, rigidmech.statics
print(json.dumps([rm.Statics is rigidmech.statics.Statics,
                  rm.Catenary is rigidmech.statics.Catenary,
                  rm.lagrange_equations is rigidmech.lagrange.lagrange_equations,
                  rm.scenes is __import__("rigidmech.scenes").scenes,
                  "testing" in dir(rm)]))
""")
    assert report == [True, True, True, True, True]


def test_unknown_attribute_is_an_attribute_error():
    import pytest

    import rigidmech

    with pytest.raises(AttributeError, match="no attribute 'no_such_name'"):
        rigidmech.no_such_name  # noqa: B018


def test_lapack_stand_ins_are_replaced_by_the_functions_on_first_call():
    from scipy.linalg import lapack

    from rigidmech._core import compile as compiled

    x, reason = compiled._checked_solve(np.array([[2.0, 1.0], [1.0, 3.0]]),
                                        np.array([3.0, 5.0]), symmetric=True)
    assert reason is None
    np.testing.assert_allclose(x, [0.8, 1.4], rtol=1e-15)
    assert compiled._dposv is lapack.dposv
    x, reason = compiled._checked_solve(np.array([[0.0, 1.0], [1.0, 0.0]]),
                                        np.array([3.0, 5.0]), symmetric=False)
    assert reason is None
    np.testing.assert_allclose(x, [5.0, 3.0], rtol=1e-15)
    assert (compiled._dgetrf, compiled._dgecon, compiled._dgetrs) == (
        lapack.dgetrf, lapack.dgecon, lapack.dgetrs)
