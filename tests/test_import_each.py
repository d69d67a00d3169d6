"""Every module of rigidmech imports without help from modules imported before it.

A module that only works when some other module happened to be imported first hides a missing
import or a cycle between layers (ARCHITECTURE.md, "Layers"). Importing the whole package in the
test process proves nothing about that, so the imports run in fresh interpreters:

* one subprocess walks the package with :func:`pkgutil.walk_packages` and imports every module
  in sequence (a quick check that everything imports at all, with warnings as errors);
* one subprocess per layer package imports that layer first, then its modules, with no other
  rigidmech layer imported beforehand (marked slow: twenty fresh interpreters, each importing
  sympy and most of rigidmech; CI runs it in its slow stage).

CI additionally imports each module in its own interpreter (``.ci/import_each.py``), which
contains the per-layer check: the default run keeps the walk in one interpreter.
"""

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

SRC = Path(__file__).resolve().parent.parent / "src"
PACKAGE_DIR = SRC / "rigidmech"

# Runs in the subprocess: walk `root`, import each module, print a JSON report on the last line.
WALK_AND_IMPORT = r"""
import importlib, json, pkgutil, sys, traceback
root = sys.argv[1]
walk_errors, failures, names = [], {}, [root]
package = importlib.import_module(root)
if hasattr(package, "__path__"):
    names += [m.name for m in pkgutil.walk_packages(
        package.__path__, prefix=root + ".", onerror=walk_errors.append)]
for name in names:
    try:
        importlib.import_module(name)
    except BaseException:
        failures[name] = traceback.format_exc(limit=-3)
print(json.dumps({"names": names, "walk_errors": walk_errors, "failures": failures}))
"""


def layer_packages():
    """The subpackages of rigidmech present in the tree (found without importing them)."""
    if not PACKAGE_DIR.is_dir():
        return []
    return sorted(
        f"rigidmech.{p.name}"
        for p in PACKAGE_DIR.iterdir()
        if p.is_dir() and (p / "__init__.py").exists()
    )


def import_in_fresh_interpreter(root):
    env = dict(os.environ)
    env["PYTHONPATH"] = os.pathsep.join(filter(None, [str(SRC), env.get("PYTHONPATH")]))
    env["MPLBACKEND"] = "Agg"
    proc = subprocess.run(
        [sys.executable, "-W", "error", "-c", WALK_AND_IMPORT, root],
        capture_output=True,
        text=True,
        timeout=600,
        stdin=subprocess.DEVNULL,
        env=env,
    )
    assert proc.returncode == 0, f"importing {root!r} failed:\n{proc.stdout}\n{proc.stderr}"
    return json.loads(proc.stdout.strip().splitlines()[-1])


def format_failures(report):
    lines = [f"walk_packages could not import {name!r}" for name in report["walk_errors"]]
    lines += [f"--- {name}\n{tb}" for name, tb in report["failures"].items()]
    return "\n".join(lines)


def test_package_has_no_namespace_directories():
    # A directory with Python files but no __init__.py is skipped by pkgutil and by
    # setuptools' find_packages: its modules would silently miss from checks and wheels.
    assert (PACKAGE_DIR / "__init__.py").exists(), "src/rigidmech/__init__.py is missing"
    bad = [
        str(Path(d).relative_to(SRC))
        for d, dirs, files in os.walk(PACKAGE_DIR)
        if "__pycache__" not in d
        and any(f.endswith(".py") for f in files)
        and "__init__.py" not in files
    ]
    assert bad == [], f"directories with Python files but no __init__.py: {bad}"


def test_every_module_imports_in_sequence():
    report = import_in_fresh_interpreter("rigidmech")
    assert len(report["names"]) > 1, f"walk_packages found only {report['names']}"
    assert not report["walk_errors"] and not report["failures"], format_failures(report)


@pytest.mark.slow  # one interpreter per layer; also contained in CI's .ci/import_each.py stage
@pytest.mark.parametrize("layer", layer_packages())
def test_layer_imports_on_its_own(layer):
    report = import_in_fresh_interpreter(layer)
    assert not report["walk_errors"] and not report["failures"], format_failures(report)
