"""The Whipple bicycle benchmark (Meijaard et al. 2007): rigidmech against sympy's KanesMethod.

Anchors, side by side in one run (each in a fresh process, sympy's cache cold):

* sympy's own Kane bicycle (``test_bicycle`` of sympy/physics/mechanics/tests/test_kane3.py,
  reproduced here): ``kanes_equations`` (derive), then ``KanesMethod.linearize`` with the
  benchmark values substituted and ``evalf`` (the numeric A(v) of lean, steer and their rates);
* "Kane-8": KanesMethod deriving the planar 8-link pendulum (``benchmarks/derive.py``), the
  unit the issue's targets are written in;
* numpy's ``eigvals`` of the state matrix A = [[0, I], [-M^-1 K, -M^-1 C]] built from the same
  numeric M, C, K, against ``LinearSystem.eigenvalues(v=...)`` (one call: the matrices
  evaluated, A built, its eigenvalues).

rigidmech's side: build the System and derive its equations, linearise about the upright run at
speed v (pitch eliminated, independent speeds roll, steer, rear wheel), the first
``numeric(v=...)`` (compiles M, C, K once), then per-call costs. The previous ``numeric`` (the
exact entries through ``evalf``) is timed once for the record (``--no-evalf`` skips it).
Correctness: the roll/steer eigenvalues of both sides at v = 1..6 m/s (the two sides use
different coordinates, eigenvalues do not depend on them).

Run::

    python benchmarks/bicycle.py            # ~5 min on a 2-core machine
    python benchmarks/bicycle.py --no-evalf
    python benchmarks/bicycle.py --derive-only 5   # the derivations alone, 5 alternated pairs
"""

from __future__ import annotations

import argparse
import os
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from derive import _best, _emit, _preimport, header, kane_pendulum, run_case  # noqa: E402

SPEEDS = (1.0, 2.0, 3.0, 4.0, 5.0, 6.0)
V_CALL = 5.0


def whipple_bicycle():
    """The bicycle's equations of motion and rear radius: from rigidmech.models when it exists,
    else the builder of tests/vibrations/test_whipple_bicycle.py."""
    try:
        from rigidmech.models import BENCHMARK_BICYCLE
        from rigidmech.models import whipple_bicycle as build  # type: ignore[import-not-found]
    except ImportError:
        here = os.path.dirname(os.path.abspath(__file__))
        sys.path.insert(0, os.path.join(here, os.pardir, "tests", "vibrations"))
        from test_whipple_bicycle import whipple_bicycle as build
        return build()
    # the catalogue's builder returns a Model (system, coordinates, ...), not the equations
    return build().system.equations_of_motion(), BENCHMARK_BICYCLE["rR"]


def kane_bicycle(linearize=True):
    """sympy's test_bicycle (test_kane3.py), timed in two parts; returns the numeric A(v)
    (with ``linearize=False``: the derivation's wall and CPU seconds only)."""
    from sympy import acos, cos, pi, sin, sqrt, symbols
    from sympy.physics.mechanics import (
        KanesMethod,
        Point,
        ReferenceFrame,
        RigidBody,
        dot,
        dynamicsymbols,
        inertia,
    )

    start, cpu = time.perf_counter(), time.process_time()
    q1, q2, q4, q5 = dynamicsymbols("q1 q2 q4 q5")
    q1d, q2d, q4d, q5d = dynamicsymbols("q1 q2 q4 q5", 1)
    u1, u2, u3, u4, u5, u6 = dynamicsymbols("u1 u2 u3 u4 u5 u6")
    WFrad, WRrad, htangle, forkoffset = symbols("WFrad WRrad htangle forkoffset")
    forklength, framelength, forkcg1 = symbols("forklength framelength forkcg1")
    forkcg3, framecg1, framecg3, Iwr11 = symbols("forkcg3 framecg1 framecg3 Iwr11")
    Iwr22, Iwf11, Iwf22, Iframe11 = symbols("Iwr22 Iwf11 Iwf22 Iframe11")
    Iframe22, Iframe33, Iframe31, Ifork11 = symbols("Iframe22 Iframe33 Iframe31 Ifork11")
    Ifork22, Ifork33, Ifork31, g = symbols("Ifork22 Ifork33 Ifork31 g")
    mframe, mfork, mwf, mwr = symbols("mframe mfork mwf mwr")
    N = ReferenceFrame("N")
    Y = N.orientnew("Y", "Axis", [q1, N.z])
    R = Y.orientnew("R", "Axis", [q2, Y.x])
    Frame = R.orientnew("Frame", "Axis", [q4 + htangle, R.y])
    WR = ReferenceFrame("WR")
    TempFrame = Frame.orientnew("TempFrame", "Axis", [-htangle, Frame.y])
    Fork = Frame.orientnew("Fork", "Axis", [q5, Frame.x])
    TempFork = Fork.orientnew("TempFork", "Axis", [-htangle, Fork.y])
    WF = ReferenceFrame("WF")
    WR_cont = Point("WR_cont")
    WR_mc = WR_cont.locatenew("WR_mc", WRrad * R.z)
    Steer = WR_mc.locatenew("Steer", framelength * Frame.z)
    Frame_mc = WR_mc.locatenew("Frame_mc", -framecg1 * Frame.x + framecg3 * Frame.z)
    Fork_mc = Steer.locatenew("Fork_mc", -forkcg1 * Fork.x + forkcg3 * Fork.z)
    WF_mc = Steer.locatenew("WF_mc", forklength * Fork.x + forkoffset * Fork.z)
    WF_cont = WF_mc.locatenew("WF_cont", WFrad * (dot(Fork.y, Y.z) * Fork.y - Y.z).normalize())
    Y.set_ang_vel(N, u1 * Y.z)
    R.set_ang_vel(Y, u2 * R.x)
    WR.set_ang_vel(Frame, u3 * Frame.y)
    Frame.set_ang_vel(R, u4 * Frame.y)
    Fork.set_ang_vel(Frame, u5 * Fork.x)
    WF.set_ang_vel(Fork, u6 * Fork.y)
    WR_cont.set_vel(N, 0)
    WR_mc.v2pt_theory(WR_cont, N, WR)
    Steer.v2pt_theory(WR_mc, N, Frame)
    Frame_mc.v2pt_theory(WR_mc, N, Frame)
    Fork_mc.v2pt_theory(Steer, N, Fork)
    WF_mc.v2pt_theory(Steer, N, Fork)
    WF_cont.v2pt_theory(WF_mc, N, WF)
    Frame_I = (inertia(TempFrame, Iframe11, Iframe22, Iframe33, 0, 0, Iframe31), Frame_mc)
    Fork_I = (inertia(TempFork, Ifork11, Ifork22, Ifork33, 0, 0, Ifork31), Fork_mc)
    WR_I = (inertia(Frame, Iwr11, Iwr22, Iwr11), WR_mc)
    WF_I = (inertia(Fork, Iwf11, Iwf22, Iwf11), WF_mc)
    BodyFrame = RigidBody("BodyFrame", Frame_mc, Frame, mframe, Frame_I)
    BodyFork = RigidBody("BodyFork", Fork_mc, Fork, mfork, Fork_I)
    BodyWR = RigidBody("BodyWR", WR_mc, WR, mwr, WR_I)
    BodyWF = RigidBody("BodyWF", WF_mc, WF, mwf, WF_I)
    kd = [q1d - u1, q2d - u2, q4d - u4, q5d - u5]
    conlist_speed = [WF_cont.vel(N) & Y.x, WF_cont.vel(N) & Y.y, WF_cont.vel(N) & Y.z]
    conlist_coord = [WF_cont.pos_from(WR_cont) & Y.z]
    FL = [(Frame_mc, -mframe * g * Y.z), (Fork_mc, -mfork * g * Y.z),
          (WF_mc, -mwf * g * Y.z), (WR_mc, -mwr * g * Y.z)]
    BL = [BodyFrame, BodyFork, BodyWR, BodyWF]
    KM = KanesMethod(N, q_ind=[q1, q2, q5], q_dependent=[q4],
                     configuration_constraints=conlist_coord, u_ind=[u2, u3, u5],
                     u_dependent=[u1, u4, u6], velocity_constraints=conlist_speed,
                     kd_eqs=kd, constraint_solver="CRAMER")
    KM.kanes_equations(BL, FL)
    derive = time.perf_counter() - start
    if not linearize:
        return derive, time.process_time() - cpu

    PaperRadRear, PaperRadFront = 0.3, 0.35
    HTA = (pi / 2 - pi / 10).evalf()
    TrailPaper = 0.08
    rake = (-(TrailPaper * sin(HTA) - (PaperRadFront * cos(HTA)))).evalf()
    PaperWb, PaperFrameCgX, PaperFrameCgZ, PaperForkCgX, PaperForkCgZ = 1.02, 0.3, 0.9, 0.9, 0.7
    FrameLength = (PaperWb * sin(HTA) - (rake - (PaperRadFront - PaperRadRear) * cos(HTA))
                   ).evalf()
    FrameCGNorm = ((PaperFrameCgZ - PaperRadRear - (PaperFrameCgX / sin(HTA)) * cos(HTA))
                   * sin(HTA)).evalf()
    FrameCGPar = (PaperFrameCgX / sin(HTA) + (PaperFrameCgZ - PaperRadRear - PaperFrameCgX
                                              / sin(HTA) * cos(HTA)) * cos(HTA)).evalf()
    tempa, tempb = (PaperForkCgZ - PaperRadFront), (PaperWb - PaperForkCgX)
    tempc = (sqrt(tempa**2 + tempb**2)).evalf()
    PaperForkL = (PaperWb * cos(HTA) - (PaperRadFront - PaperRadRear) * sin(HTA)).evalf()
    ForkCGNorm = (rake + (tempc * sin(pi / 2 - HTA - acos(tempa / tempc)))).evalf()
    ForkCGPar = (tempc * cos((pi / 2 - HTA) - acos(tempa / tempc)) - PaperForkL).evalf()
    v = symbols("v")
    val_dict = {WFrad: PaperRadFront, WRrad: PaperRadRear, htangle: HTA, forkoffset: rake,
                forklength: PaperForkL, framelength: FrameLength, forkcg1: ForkCGPar,
                forkcg3: ForkCGNorm, framecg1: FrameCGNorm, framecg3: FrameCGPar,
                Iwr11: 0.0603, Iwr22: 0.12, Iwf11: 0.1405, Iwf22: 0.28, Ifork11: 0.05892,
                Ifork22: 0.06, Ifork33: 0.00708, Ifork31: 0.00756, Iframe11: 9.2,
                Iframe22: 11, Iframe33: 2.8, Iframe31: -2.4, mfork: 4, mframe: 85, mwf: 3,
                mwr: 2, g: 9.81, q1: 0, q2: 0, q4: 0, q5: 0, u1: 0, u2: 0,
                u3: v / PaperRadRear, u4: 0, u5: 0, u6: v / PaperRadFront}
    op_point = {u.diff(): 0 for u in (u1, u2, u3, u4, u5, u6)}
    op_point |= {u1: 0, u2: 0, u3: v / PaperRadRear, u4: 0, u5: 0, u6: v / PaperRadFront,
                 q1: 0, q2: 0, q4: 0, q5: 0}
    A, _, _ = KM.linearize(A_and_B=True, op_point=op_point, linear_solver="CRAMER")
    A = A.xreplace(val_dict).evalf().extract([1, 2, 3, 5], [1, 2, 3, 5])
    linearize = time.perf_counter() - start
    return derive, linearize, A, v


def case_kane8():
    _preimport()
    start = time.perf_counter()
    km, _, _, _ = kane_pendulum(8)
    km.mass_matrix, km.forcing  # noqa: B018 - what derive.py times
    _emit(derive=time.perf_counter() - start)


def case_kane():
    import numpy as np
    from sympy.physics import mechanics  # noqa: F401  (import excluded from the timing)

    _preimport()
    derive, linearize, A, v = kane_bicycle()
    _emit(derive=derive, linearize=linearize)
    eig = [np.linalg.eigvals(np.array(A.xreplace({v: s}).tolist(), dtype=float)).tolist()
           for s in SPEEDS]
    _emit(eig=[[(z.real, z.imag) for z in e] for e in eig])


def case_kane_derive():
    from sympy.physics import mechanics  # noqa: F401  (import excluded from the timing)

    _preimport()
    wall, cpu = kane_bicycle(linearize=False)
    _emit(derive=wall, cpu=cpu)


def _import_ours():
    """Import rigidmech's modules before the timing (Kane's side imports
    sympy.physics.mechanics before its own)."""
    try:
        import rigidmech.models  # noqa: F401
    except ImportError:
        import rigidmech  # noqa: F401


def case_ours_derive():
    _import_ours()
    _preimport()
    start, cpu = time.perf_counter(), time.process_time()
    whipple_bicycle()
    _emit(derive=time.perf_counter() - start, cpu=time.process_time() - cpu)


def derive_only(pairs, timeout):
    """The derivations alone (ours: build + equations; Kane: ``kanes_equations``), each in a
    fresh process, ``pairs`` pairs alternated (the order swapped every pair), CPU seconds;
    the ratio taken pair by pair, its median printed."""
    import statistics

    ours, kane = [], []
    for i in range(pairs):
        order = ("ours-derive", "kane-derive") if i % 2 == 0 else ("kane-derive",
                                                                   "ours-derive")
        got = {side: run_case(0, side, timeout, script=__file__) for side in order}
        ours.append(got["ours-derive"].get("cpu", float("nan")))
        kane.append(got["kane-derive"].get("cpu", float("nan")))
        print(f"pair {i + 1}: ours {ours[-1]:.2f} s, Kane {kane[-1]:.2f} s CPU, "
              f"Kane/ours {kane[-1] / ours[-1]:.2f}", flush=True)
    ratios = [b / a for a, b in zip(ours, kane, strict=True)]
    print(f"\nderive (CPU s, median of {pairs}): ours {statistics.median(ours):.2f}, Kane "
          f"{statistics.median(kane):.2f}; Kane/ours pair by pair: median "
          f"{statistics.median(ratios):.2f} (min {min(ratios):.2f}, max {max(ratios):.2f})")


def case_ours(evalf):
    import numpy as np
    import sympy as sp

    from rigidmech.vibrations import linearize
    from rigidmech.vibrations._numeric import state_matrix

    _import_ours()
    _preimport()
    start = time.perf_counter()
    eqs, rR = whipple_bicycle()
    derive = time.perf_counter() - start
    v = sp.Symbol("v")
    start = time.perf_counter()
    lin = linearize(eqs, velocities={"theta_R": v / rR}, parameters={"g": 9.81},
                    independent=["phi", "delta", "theta_R"], simplify=False)
    linearize_time = time.perf_counter() - start
    start = time.perf_counter()
    M, C, K, _ = lin.numeric(v=V_CALL)
    first = time.perf_counter() - start
    _emit(derive=derive, linearize=linearize_time, first_numeric=first,
          n_ops=lin._cache["compiled"].function.n_ops,
          ops_exact=int(sp.count_ops(list(lin.M) + list(lin.C) + list(lin.K))))
    A = state_matrix(M, C, K)
    _emit(eigvals=_best(lambda: np.linalg.eigvals(A)),
          eigenvalues=_best(lambda: lin.eigenvalues(v=V_CALL)),
          numeric=_best(lambda: lin.numeric(v=V_CALL)))
    eig = []
    for s in SPEEDS:
        M, C, K, _ = lin.numeric(v=s)
        eig.append(np.linalg.eigvals(state_matrix(M[:2, :2], C[:2, :2], K[:2, :2])).tolist())
    _emit(eig=[[(z.real, z.imag) for z in e] for e in eig])
    if evalf:
        start = time.perf_counter()
        for X in (lin.M, lin.C, lin.K):
            np.array(X.xreplace({v: V_CALL}).evalf().tolist(), dtype=float)
        _emit(evalf_numeric=time.perf_counter() - start)


def _eig_diff(a, b):
    import numpy as np

    worst = 0.0
    for ea, eb in zip(a, b, strict=True):
        za = np.sort_complex(np.array([complex(*z) for z in ea]))
        zb = np.sort_complex(np.array([complex(*z) for z in eb]))
        worst = max(worst, float(np.max(np.abs(za - zb)) / np.max(np.abs(zb))))
    return worst


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--no-evalf", action="store_true", help="skip the evalf numeric")
    parser.add_argument("--timeout", type=float, default=900.0, help="seconds per case")
    parser.add_argument("--derive-only", type=int, metavar="PAIRS",
                        help="time the two derivations only, PAIRS alternated pairs")
    parser.add_argument("--case", nargs=2, help=argparse.SUPPRESS)
    args = parser.parse_args(argv)
    if args.case:
        side, flag = args.case
        {"kane8": case_kane8, "kane": case_kane, "kane-derive": case_kane_derive,
         "ours-derive": case_ours_derive,
         "ours": lambda: case_ours(flag == "1")}[side]()
        return 0
    if args.derive_only:
        print(header().splitlines()[1:][0])
        print(header().splitlines()[2])
        derive_only(args.derive_only, args.timeout)
        print(f"load average at end: {' '.join(f'{x:.2f}' for x in os.getloadavg())}")
        return 0
    print(header().replace("Planar n-link pendulum: deriving M(q) q'' = f with rigidmech vs "
                           "sympy KanesMethod", "Whipple bicycle: rigidmech vs sympy "
                           "KanesMethod (test_kane3.test_bicycle)"), flush=True)
    kane8 = run_case(0, "kane8", args.timeout, script=__file__)
    ours = run_case(0 if args.no_evalf else 1, "ours", args.timeout, script=__file__)
    kane = run_case(0, "kane", args.timeout, script=__file__)
    for name, res in (("Kane-8", kane8), ("ours", ours), ("Kane bicycle", kane)):
        if "status" in res:
            print(f"{name}: {res['status']} {res.get('stderr', '')}")
    k8 = kane8.get("derive", float("nan"))
    print(f"\nKane-8 (KanesMethod, planar 8-link pendulum, derive): {k8:.2f} s\n")
    rows = [
        ("derive (build + equations)", ours.get("derive"), kane.get("derive")),
        ("derive + linearise to numeric", None if "derive" not in ours else
         ours["derive"] + ours["linearize"] + ours["first_numeric"], kane.get("linearize")),
        ("  of which linearise", ours.get("linearize"), None if "linearize" not in kane else
         kane["linearize"] - kane["derive"]),
        ("  of which first numeric (compile)", ours.get("first_numeric"), None),
    ]
    print(f"{'':38s}{'ours':>10s}{'Kane':>10s}{'Kane/ours':>11s}{'ours/Kane-8':>13s}")
    for label, a, b in rows:
        def fmt(x):
            return "--" if x is None else f"{x:.2f} s"
        ratio = "--" if a is None or b is None else f"{b / a:.1f}"
        per_k8 = "--" if a is None else f"{a / k8:.2f}"
        print(f"{label:38s}{fmt(a):>10s}{fmt(b):>10s}{ratio:>11s}{per_k8:>13s}")
    if "eigvals" in ours:
        print(f"\nper call at v = {V_CALL} (best of 7):")
        print(f"  numpy.linalg.eigvals(A), A {2 * 3}x{2 * 3} prebuilt: "
              f"{ours['eigvals'] * 1e6:8.1f} us")
        print(f"  LinearSystem.numeric(v=...):                 {ours['numeric'] * 1e6:8.1f} us")
        print(f"  LinearSystem.eigenvalues(v=...):             "
              f"{ours['eigenvalues'] * 1e6:8.1f} us  "
              f"= {ours['eigenvalues'] / ours['eigvals']:.1f} x eigvals (target <= 10)")
        print(f"  compiled code: {ours['n_ops']} operations (exact entries of M, C, K: "
              f"{ours['ops_exact']})")
    if "evalf_numeric" in ours:
        print(f"  before: numeric through evalf, one call: {ours['evalf_numeric']:.1f} s "
              f"(= {ours['evalf_numeric'] / ours['eigenvalues']:.0f} x the compiled "
              f"eigenvalues)")
    if "eig" in ours and "eig" in kane:
        print(f"\nroll/steer eigenvalues, ours vs Kane at v = {SPEEDS}: max relative "
              f"difference {_eig_diff(ours['eig'], kane['eig']):.1e}")
    load = os.getloadavg()
    print(f"\nload average at end: {load[0]:.2f} {load[1]:.2f} {load[2]:.2f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
