"""The layer contracts of pyproject.toml hold (ARCHITECTURE.md, "Layers").

import-linter checks that each layer imports only from the layers below it and that the ODE
solvers import no mechanics and no sympy. This runs the same check as ``lint-imports`` in CI, in
a subprocess, and checks that the contract leaves no package of the tree unlisted.
"""

import importlib.util
import os
import subprocess
import sys
import tomllib
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
SRC = ROOT / "src"
PYPROJECT = ROOT / "pyproject.toml"


def importlinter_config():
    return tomllib.loads(PYPROJECT.read_text(encoding="utf-8"))["tool"]["importlinter"]


def layers_contract():
    contracts = importlinter_config()["contracts"]
    (layers,) = [c for c in contracts if c["type"] == "layers"]
    return layers


def test_every_package_of_the_tree_is_a_listed_layer():
    # A new top-level subpackage or module outside the contract would escape the layer check.
    listed = {name.strip("()").split(".")[1] for name in layers_contract()["layers"]}
    present = {
        p.stem if p.is_file() else p.name
        for p in (SRC / "rigidmech").iterdir()
        if (p.is_file() and p.suffix == ".py" and p.name != "__init__.py")
        or (p.is_dir() and (p / "__init__.py").exists())
    }
    assert present - listed == set(), (
        f"modules {sorted(present - listed)} of src/rigidmech are in no layer of the "
        "import-linter contract in pyproject.toml; add them to the `layers` list"
    )


@pytest.mark.skipif(
    importlib.util.find_spec("importlinter") is None,
    reason="import-linter is not installed (pip install -e '.[test]')",
)
def test_import_contracts_are_kept():
    env = dict(os.environ)
    env["PYTHONPATH"] = os.pathsep.join(filter(None, [str(SRC), env.get("PYTHONPATH")]))
    code = (
        "import sys; from importlinter.cli import lint_imports; "
        f"sys.exit(lint_imports(config_filename={str(PYPROJECT)!r}, no_cache=True, no_logo=True))"
    )
    proc = subprocess.run(
        [sys.executable, "-c", code],
        cwd=ROOT,
        capture_output=True,
        text=True,
        timeout=600,
        stdin=subprocess.DEVNULL,
        env=env,
    )
    assert proc.returncode == 0, f"import-linter contracts broken:\n{proc.stdout}\n{proc.stderr}"
