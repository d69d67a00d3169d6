"""Wall time of ``import rigidmech`` against ``import sympy, numpy`` (its two eager dependencies).

Target: ``import rigidmech`` takes at most 1.2 times as long as ``import sympy, numpy``: scipy,
matplotlib, tqdm and the heavy subpackages are imported on first use (docs/performance).

Run::

    .venv/bin/python benchmarks/import_time.py           # about 20 s

Each sample is a fresh interpreter (``python -c "<statement>"``), timed from the parent
process, A and B alternating so that a drift of the machine's load hits both sides alike; the
medians of ``REPEAT`` samples each and their ratio are printed. Interpreter start-up is in both
samples (it is what a user waits for), so the ratio understates the library's own share
slightly.

Bytecode: an installed package has its ``.pyc`` files; a source checkout run with
``PYTHONDONTWRITEBYTECODE=1`` recompiles every rigidmech module at every start (about 0.5 s
more). The subprocesses therefore run with bytecode writing on and a private
``PYTHONPYCACHEPREFIX`` (nothing written into the source tree), after one warm-up import of
each side; ``--no-bytecode`` measures the recompiling case instead.
"""

import argparse
import os
import statistics
import subprocess
import sys
import tempfile
import time

REPEAT = 9
SIDES = {"sympy+numpy": "import sympy, numpy", "rigidmech": "import rigidmech"}


def sample(statement, env):
    """Seconds for one fresh interpreter to run `statement` and exit."""
    t0 = time.perf_counter()
    subprocess.run([sys.executable, "-c", statement], env=env, check=True)
    return time.perf_counter() - t0


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=REPEAT, help="samples per side (>= 7)")
    parser.add_argument("--no-bytecode", action="store_true",
                        help="do not cache bytecode (every rigidmech module is recompiled)")
    args = parser.parse_args()
    env = dict(os.environ)
    with tempfile.TemporaryDirectory() as cache:
        if args.no_bytecode:
            env["PYTHONDONTWRITEBYTECODE"] = "1"
        else:
            env.pop("PYTHONDONTWRITEBYTECODE", None)
            env["PYTHONPYCACHEPREFIX"] = cache
        for statement in SIDES.values():  # warm-up: write the bytecode, fill the OS caches
            sample(statement, env)
        times = {name: [] for name in SIDES}
        for _ in range(args.repeat):
            for name, statement in SIDES.items():
                times[name].append(sample(statement, env))
    med = {name: statistics.median(ts) for name, ts in times.items()}
    print(f"python {sys.version.split()[0]}, {args.repeat} samples per side, "
          f"bytecode {'off' if args.no_bytecode else 'cached'}")
    for name, statement in SIDES.items():
        ts = sorted(times[name])
        print(f"  {statement:<22} median {med[name]:.3f} s  (min {ts[0]:.3f}, max {ts[-1]:.3f})")
    print(f"  ratio rigidmech / (sympy + numpy): {med['rigidmech'] / med['sympy+numpy']:.2f}"
          "  (target <= 1.2)")


if __name__ == "__main__":
    main()
