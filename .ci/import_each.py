"""Check that every module of rigidmech imports on its own, each in a fresh interpreter.

Run from anywhere: ``python .ci/import_each.py``. The modules are found with
:func:`pkgutil.walk_packages` over ``src/rigidmech``; each one is then imported in a new
subprocess (so that no module can rely on another having been imported first), with warnings
turned into errors as under pytest. Exits with status 1 if any import fails, if a package cannot
be walked, or if a directory of ``src/rigidmech`` holds Python files but no ``__init__.py`` (it
would be silently left out of a wheel built with ``setuptools.packages.find``).
"""

from __future__ import annotations

import argparse
import importlib
import os
import pkgutil
import subprocess
import sys
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
SRC = ROOT / "src"
PACKAGE = "rigidmech"


def missing_init_dirs(package_dir: Path) -> list[Path]:
    """Directories under `package_dir` that hold ``.py`` files but no ``__init__.py``."""
    bad = [] if (package_dir / "__init__.py").exists() else [package_dir]
    for dirpath, dirnames, filenames in os.walk(package_dir):
        dirnames[:] = [d for d in dirnames if d != "__pycache__" and not d.startswith(".")]
        has_py = any(f.endswith(".py") for f in filenames)
        if has_py and "__init__.py" not in filenames and Path(dirpath) != package_dir:
            bad.append(Path(dirpath))
    return bad


def discover(package: str = PACKAGE) -> tuple[list[str], list[str]]:
    """Names of the package and all its modules, and the packages that could not be walked."""
    sys.path.insert(0, str(SRC))
    walk_errors: list[str] = []
    root = importlib.import_module(package)
    names = [package]
    for info in pkgutil.walk_packages(
        root.__path__, prefix=package + ".", onerror=walk_errors.append
    ):
        names.append(info.name)
    return sorted(set(names)), walk_errors


def import_alone(name: str, timeout: float) -> tuple[str, bool, float, str]:
    """Import `name` in a fresh interpreter; return (name, ok, seconds, output)."""
    env = dict(os.environ)
    env["PYTHONPATH"] = os.pathsep.join(filter(None, [str(SRC), env.get("PYTHONPATH")]))
    env.setdefault("MPLBACKEND", "Agg")
    code = f"import importlib; importlib.import_module({name!r})"
    start = time.perf_counter()
    try:
        proc = subprocess.run(
            [sys.executable, "-W", "error", "-c", code],
            capture_output=True,
            text=True,
            timeout=timeout,
            stdin=subprocess.DEVNULL,
            env=env,
        )
    except subprocess.TimeoutExpired:
        return name, False, time.perf_counter() - start, f"timed out after {timeout:.0f} s"
    output = (proc.stdout + proc.stderr).strip()
    return name, proc.returncode == 0, time.perf_counter() - start, output


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--jobs", type=int, default=os.cpu_count() or 1)
    parser.add_argument("--timeout", type=float, default=300.0, help="seconds per module")
    args = parser.parse_args(argv)

    failures = 0
    for path in missing_init_dirs(SRC / PACKAGE):
        print(f"FAIL  {path.relative_to(ROOT)}/ has no __init__.py (no namespace packages)")
        failures += 1

    try:
        names, walk_errors = discover()
    except Exception as exc:  # the root package itself does not import
        print(f"FAIL  cannot import {PACKAGE!r}: {type(exc).__name__}: {exc}")
        return 1
    for name in walk_errors:
        print(f"FAIL  pkgutil.walk_packages could not import package {name!r}")
        failures += 1

    with ThreadPoolExecutor(max_workers=max(1, args.jobs)) as pool:
        results = list(pool.map(lambda n: import_alone(n, args.timeout), names))
    for name, ok, seconds, output in results:
        print(f"{'ok  ' if ok else 'FAIL'}  {name:<50} {seconds:6.2f} s")
        if not ok:
            failures += 1
            print("\n".join("      | " + line for line in output.splitlines()[-25:]))

    print(f"{len(names)} modules imported one by one in fresh interpreters; {failures} failure(s)")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
