"""The test suite's time budget: the README's default test command against Kane-8, in one run.

Target (issue 21, "fast to start and to test"): the README's default ``python -m pytest -n auto``
takes at most 30 Kane-8 on a 2-core machine, where Kane-8 is the time sympy.physics.mechanics's
``KanesMethod`` takes to derive the planar 8-link rod pendulum on the same machine
(``benchmarks/derive.py --case kane 8``: fresh process, sympy's cache cold, import excluded).

Order A B A: Kane-8, then the suite (the command read from README.md, run in this checkout with
``src`` first on the path), then Kane-8 again; the suite's time is divided by the mean of the
Kane-8 runs (the spread of A and B says how steady the machine was). Each Kane-8 is run under
``PYTHONHASHSEED`` 0, 1, 2, 3 (``--seeds``): the derivation's time depends on the process (sympy
visits sets in hash order; 3.4 s to 5.3 s over four seeds on the idle reference machine), so a
single run can move the ratio by half. Printed for both: wall time (the
target) and the CPU time of the process tree (user + system, from ``getrusage`` of the
children), which a loaded machine inflates much less than wall time; the suite's CPU time over
the number of cores it used estimates its wall time on an idle machine.

Run::

    python benchmarks/suite_budget.py              # the README's command, as written
    python benchmarks/suite_budget.py --cpus 2     # pinned to 2 cores (Linux), -n auto = 2
    python benchmarks/suite_budget.py --slow       # the slow stage (-m slow) as well
    python benchmarks/suite_budget.py --cold       # bytecode as found (no warm-up)

Bytecode: by default one ``pytest --collect-only`` runs first with bytecode writing on, so that
the timed run reads compiled modules and assertion-rewritten tests from ``__pycache__`` as any
second run does (a fresh clone's first run, or ``PYTHONDONTWRITEBYTECODE=1`` without caches,
compiles them in every worker: about 6 s of CPU per worker on the reference machine).

The suite runs once (``--slow``: twice, the slow stage after the default one); its own pass/fail
is printed and the exit status is non-zero if it failed.
"""

from __future__ import annotations

import argparse
import json
import os
import re
import resource
import shlex
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
BUDGET = 30.0          # the suite's wall time in Kane-8


def readme_test_command():
    """The README's default test command (the second set-up line, after ``&&``) as argv."""
    text = (ROOT / "README.md").read_text()
    block = text.split("## Set up on a fresh machine", 1)[1].split("```", 2)[1]
    line = [ln for ln in block.splitlines() if "pytest" in ln][0]
    argv = shlex.split(line.split("&&", 1)[1])
    if argv[0] != "python":
        raise SystemExit(f"unexpected README test command: {line!r}")
    return [sys.executable, *argv[1:]]


def _env(cpus):
    env = dict(os.environ)
    env["PYTHONPATH"] = os.pathsep.join(filter(None, [str(ROOT / "src"),
                                                      env.get("PYTHONPATH")]))
    env.setdefault("MPLBACKEND", "Agg")
    if cpus:
        env["PYTEST_XDIST_AUTO_NUM_WORKERS"] = str(cpus)
    return env


def _pin(cpus):
    if not cpus:
        return None
    cores = sorted(os.sched_getaffinity(0))[:cpus]
    return lambda: os.sched_setaffinity(0, cores)


def timed(argv, cpus, capture=False, extra_env=None):
    """(wall s, CPU s of the process tree, completed process) of ``argv`` run in ROOT."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    proc = subprocess.run(argv, cwd=ROOT, env={**_env(cpus), **(extra_env or {})},
                          preexec_fn=_pin(cpus),
                          capture_output=capture, text=True, stdin=subprocess.DEVNULL)
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return wall, cpu, proc


# Kane-8 in a child: derive.py's own case (the official figure, wall time of the derivation),
# plus the CPU time of the same span
KANE_CHILD = r"""
import importlib.util, json, sys, time
spec = importlib.util.spec_from_file_location("derive", sys.argv[1])
derive = importlib.util.module_from_spec(spec); spec.loader.exec_module(derive)
from sympy.physics import mechanics  # noqa: F401  (import excluded, as in derive.py)
derive._preimport()
w0, c0 = time.perf_counter(), time.process_time()
km, *_ = derive.kane_pendulum(8)
km.mass_matrix, km.forcing
print(json.dumps({"wall": time.perf_counter() - w0, "cpu": time.process_time() - c0}))
"""


def kane8(cpus, seed=None):
    """Kane-8 in a fresh process, with ``PYTHONHASHSEED=seed`` when given."""
    env = None if seed is None else {"PYTHONHASHSEED": str(seed)}
    _, _, proc = timed([sys.executable, "-c", KANE_CHILD, str(ROOT / "benchmarks/derive.py")],
                       cpus, capture=True, extra_env=env)
    if proc.returncode:
        raise SystemExit(f"Kane-8 failed:\n{proc.stderr}")
    return json.loads(proc.stdout.strip().splitlines()[-1])


def kane8_over_seeds(cpus, seeds, label):
    """Kane-8 once per hash seed: sympy's derivation visits sets in the order of the string
    hashes, so its time depends on the process's hash seed (3.4 s to 5.3 s over seeds 0-3 on
    the idle reference machine). Returns the runs; prints each."""
    runs = [kane8(cpus, seed) for seed in seeds]
    print(f"Kane-8 ({label}), PYTHONHASHSEED {', '.join(map(str, seeds))}: " + "; ".join(
        f"{r['wall']:.2f} s wall {r['cpu']:.2f} s CPU" for r in runs), flush=True)
    return runs


def run_suite(argv, cpus, label):
    print(f"\n$ {' '.join(shlex.quote(a) for a in argv)}    ({label})", flush=True)
    wall, cpu, proc = timed(argv, cpus, capture=True)
    tail = [ln for ln in proc.stdout.splitlines() if re.search(r"\d+ (passed|failed)", ln)]
    print(f"  {tail[-1] if tail else '(no summary line)'}")
    if proc.returncode:
        print(proc.stdout[-4000:], proc.stderr[-2000:], sep="\n")
    return wall, cpu, proc.returncode


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cpus", type=int, default=0,
                        help="pin every child to this many cores (Linux) and run that many "
                             "pytest workers")
    parser.add_argument("--slow", action="store_true", help="also time the slow stage")
    parser.add_argument("--seeds", type=int, default=4,
                        help="Kane-8 under PYTHONHASHSEED 0 .. SEEDS-1, before and after the "
                             "suite (default 4: 8 derivations)")
    parser.add_argument("--cold", action="store_true",
                        help="no warm-up: the bytecode caches as found")
    args = parser.parse_args(argv)

    cores = args.cpus or len(os.sched_getaffinity(0))
    command = readme_test_command()
    print("The README's test command against Kane-8 (sympy KanesMethod, planar 8-link pendulum)")
    load0 = os.getloadavg()[0]
    print(f"python {sys.version.split()[0]}, {os.cpu_count()} cores on the machine, "
          f"{cores} used; load average at start {load0:.2f}")

    if not args.cold:   # compiled modules and rewritten tests cached, as for a second run
        env = _env(args.cpus)
        env.pop("PYTHONDONTWRITEBYTECODE", None)
        subprocess.run([*command[:3], "--collect-only", "-q"], cwd=ROOT, env=env,
                       capture_output=True, stdin=subprocess.DEVNULL, check=False)
    print(f"bytecode: {'as found (--cold)' if args.cold else 'cached by a warm-up collection'}")

    seeds = list(range(max(args.seeds, 1)))
    before = kane8_over_seeds(args.cpus, seeds, "A, before")
    wall, cpu, rc = run_suite(command, args.cpus, "the README's default")
    slow = run_suite([*command[:3], "-m", "slow", *command[3:]], args.cpus, "the slow stage") \
        if args.slow else None
    after = kane8_over_seeds(args.cpus, seeds, "B, after")

    def mean(runs, key):
        return sum(r[key] for r in runs) / len(runs)

    kw = mean(before + after, "wall")
    kc = mean(before + after, "cpu")
    print(f"\nload average at the end {os.getloadavg()[0]:.2f}; Kane-8 mean of A "
          f"{mean(before, 'wall'):.2f} s, of B {mean(after, 'wall'):.2f} s (wall); over the "
          f"seeds {min(r['cpu'] for r in before + after):.2f} to "
          f"{max(r['cpu'] for r in before + after):.2f} s CPU")
    print(f"{'':34}{'seconds':>10}{'Kane-8':>10}")
    print(f"{'Kane-8 (mean of A, B), wall':34}{kw:10.2f}{1:10.1f}")
    print(f"{'Kane-8 (mean of A, B), CPU':34}{kc:10.2f}{1:10.1f}")
    print(f"{'default suite, wall':34}{wall:10.1f}{wall / kw:10.1f}")
    print(f"{'default suite, CPU / ' + str(cores) + ' cores':34}{cpu / cores:10.1f}"
          f"{cpu / cores / kc:10.1f}   (idle-machine estimate; Kane-8 in CPU s)")
    if slow:
        print(f"{'slow stage, wall':34}{slow[0]:10.1f}{slow[0] / kw:10.1f}")
        print(f"{'slow stage, CPU / ' + str(cores) + ' cores':34}{slow[1] / cores:10.1f}"
              f"{slow[1] / cores / kc:10.1f}")
    by_wall, by_cpu = wall / kw, cpu / cores / kc
    print(f"\nbudget: the default suite <= {BUDGET:.0f} Kane-8 on {cores} cores")
    print(f"  by wall time (the target):      {by_wall:5.1f} Kane-8  "
          f"{'met' if by_wall <= BUDGET else 'NOT met'}")
    print(f"  by CPU time / {cores} cores (idle est.): {by_cpu:5.1f} Kane-8  "
          f"{'met' if by_cpu <= BUDGET else 'NOT met'}")
    print(f"  load average {load0:.2f} at start, {os.getloadavg()[0]:.2f} at the end: on a "
          "shared machine the CPU figure is the steadier one")
    return 1 if rc or (slow and slow[2]) else 0


if __name__ == "__main__":
    sys.exit(main())
