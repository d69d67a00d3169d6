"""Derivation time of closed-loop and nonholonomic mechanisms: rigidmech vs
sympy.physics.mechanics' KanesMethod on the same models, same run (book, ch. 13.2, 25.3).

* chain of n four-bar linkages (n = 1 is the four-bar): a crank pivoted at D0, then for each
  loop k a coupler (length L2, then L2B) pivoted at the tip of the previous driver (the crank,
  then rocker k - 1) and a rocker pivoted at D_k = (k L0, 0), the loop closed where the
  coupler's tip meets the rocker's; 2n + 1 parameters, 2n closure conditions, mobility 1.
  rigidmech keeps every parameter with the 2n closure conditions (Lagrange multipliers, the
  loops closed with ``meets=``); KanesMethod with the crank's speed independent, the 2n
  others dependent, the configuration and velocity constraints;
* disc rolling on a plane (contact point (x, y), heading, lean, spin; no slip): rigidmech with
  a RollingContact (velocity constraints, multipliers); KanesMethod with the speeds of x and y
  dependent. "rolling disc" gives rigidmech the contact point and normal; "disc, between"
  has them found from the geometry (``ContactKinematics.between`` of the rim and the plane, contact
  decided exactly); Kane is given them in both.

Both sides build their model from the symbols and stop at their equations of motion, nothing
simplified: rigidmech ``System.equations_of_motion()`` with its constraint block (Jacobian A,
bias b, Baumgarte-stabilised bias); KanesMethod ``kanes_equations`` then ``mass_matrix`` and
``forcing`` (the constraint rows included). Each (case, side) runs in a fresh process (this
script re-run with ``--case``): sympy's cache and rigidmech's own caches are cold for both
sides, as in a user's session. CPU time (``time.process_time``), the two sides alternated,
the minimum over ``--repeat`` runs (the machine is shared). Before timing, the script checks
that both sides give the same accelerations at an assembled state of each chain (q'' from
rigidmech's augmented system against Kane's, relative difference printed).

Run::

    PYTHONPATH=src python benchmarks/derive_loops.py               # n = 1, 2, 4 and the disc
    PYTHONPATH=src python benchmarks/derive_loops.py --chains 1 2 4 8 --repeat 3
    PYTHONPATH=src python benchmarks/derive_loops.py --phases 4    # where rigidmech's time goes
"""

import argparse
import contextlib
import json
import math
import os
import subprocess
import sys
import time

import sympy as sp
import sympy.physics.mechanics as me

from rigidmech import models
from rigidmech.dynamics import System

L0, L1, L2, L3 = models.FOUR_BAR_LENGTHS
#: coupler of the loops after the first (2.0 would make them parallelograms, whose
#: singular branch points are no fair test)
L2B = models.CHAIN_COUPLER


def four_bar_rigidmech():
    return four_bar_system().equations_of_motion()


def four_bar_system(stabilization=(5.0, 5.0)):
    """The four-bar as a rigidmech System (the loop closed by the pivot at C)."""
    return chain_system(1, stabilization)


class _Clock:
    """CPU time spent in named phases (``--phases``); a no-op without ``on``."""

    def __init__(self, on=False):
        self.on, self.spent, self._last = on, {}, time.process_time()

    def mark(self, phase):
        if self.on:
            now = time.process_time()
            self.spent[phase] = self.spent.get(phase, 0.0) + now - self._last
            self._last = now


@contextlib.contextmanager
def _timed_connections(clock):
    """Charge the time before each ``System.connect`` to building frames and bodies, and the
    call itself to the tree joints or, with ``meets=``, to the closure conditions (the
    phases of the catalogue's builder, which knows no clock)."""
    original = System.connect

    def connect(self, *args, **kwargs):
        clock.mark("frames and bodies")
        out = original(self, *args, **kwargs)
        clock.mark("closure conditions" if kwargs.get("meets") is not None
                   else "tree joints (checked)")
        return out

    System.connect = connect
    try:
        yield
    finally:
        System.connect = original


def chain_system(n, stabilization=(5.0, 5.0), clock=None):
    """A chain of n four-bars as a rigidmech System (parameters q1, q2, q3, ...: the crank's
    absolute angle, then per loop the coupler's angle relative to its driver and the rocker's
    absolute angle): the catalogue's :func:`rigidmech.models.four_bar_chain`."""
    if clock is None:
        return models.four_bar_chain(n, (L0, L1, L2, L3), L2B, stabilization).system
    with _timed_connections(clock):
        return models.four_bar_chain(n, (L0, L1, L2, L3), L2B, stabilization).system


def chain_rigidmech(n):
    return chain_system(n).equations_of_motion()


def phases(n):
    """Where rigidmech's derivation time goes for the chain of n four-bars (CPU seconds per
    phase, one cold run)."""
    clock = _Clock(on=True)
    s = chain_system(n, clock=clock)
    clock.mark("frames and bodies")
    s.constraints()
    clock.mark("constraints A, b (derivatives)")
    s.equations_of_motion()
    clock.mark("M, f and the equations' object")
    return clock.spent


def chain_kane(n):
    """The same chain for KanesMethod: u_i = q_i', the crank's speed independent."""
    q = me.dynamicsymbols(" ".join(f"q{i}" for i in range(1, 2 * n + 2)), seq=True)
    u = me.dynamicsymbols(" ".join(f"u{i}" for i in range(1, 2 * n + 2)), seq=True)
    m, g = sp.symbols("m g", positive=True)
    N = me.ReferenceFrame("N")
    O = me.Point("O")
    O.set_vel(N, 0)
    bodies, loads, conf, vel = [], [], [], []

    def bar(name, frame, start, L):
        G = start.locatenew("G" + name, L / 2 * frame.x)
        G.v2pt_theory(start, N, frame)
        inertia = me.inertia(frame, 0, m * L**2 / 12, m * L**2 / 12)
        bodies.append(me.RigidBody(name, G, frame, m, (inertia, G)))
        loads.append((G, -m * g * N.y))

    A = N.orientnew("A1", "Axis", (q[0], N.z))
    A.set_ang_vel(N, u[0] * N.z)
    bar("b1", A, O, L1)
    driver, start, length, w_driver = A, O, L1, u[0]
    for j in range(1, n + 1):
        a, b, ua, ub = q[2 * j - 1], q[2 * j], u[2 * j - 1], u[2 * j]
        Bp = start.locatenew(f"B{j}", length * driver.x)
        Bp.v2pt_theory(start, N, driver)
        C = driver.orientnew(f"A{2 * j}", "Axis", (a, driver.z))
        C.set_ang_vel(N, (w_driver + ua) * N.z)
        Dp = O.locatenew(f"D{j}", j * L0 * N.x)
        Dp.set_vel(N, 0)
        Rk = N.orientnew(f"A{2 * j + 1}", "Axis", (b, N.z))
        Rk.set_ang_vel(N, ub * N.z)
        lc = L2 if j == 1 else L2B
        bar(f"b{2 * j}", C, Bp, lc)
        bar(f"b{2 * j + 1}", Rk, Dp, L3)
        Cp = Bp.locatenew(f"C{j}", lc * C.x)
        Cp.v2pt_theory(Bp, N, C)
        Ep = Dp.locatenew(f"E{j}", L3 * Rk.x)
        Ep.v2pt_theory(Dp, N, Rk)
        gap, dv = Cp.pos_from(O) - Ep.pos_from(O), Cp.vel(N) - Ep.vel(N)
        conf += [gap.dot(N.x), gap.dot(N.y)]
        vel += [dv.dot(N.x), dv.dot(N.y)]
        driver, start, length, w_driver = Rk, Dp, L3, ub
    kane = me.KanesMethod(
        N, q_ind=q[:1], q_dependent=q[1:], u_ind=u[:1], u_dependent=u[1:],
        kd_eqs=[qi.diff() - ui for qi, ui in zip(q, u, strict=True)],
        configuration_constraints=conf, velocity_constraints=vel)
    kane.kanes_equations(bodies, loads)
    return kane


def four_bar_kane():
    return chain_kane(1)


def disc_rigidmech(between=False):
    """The rolling disc; with ``between``, its contact point and normal found by
    ``ContactKinematics.between`` from the disc's rim (a circle) and the plane (the
    catalogue's :func:`rigidmech.models.rolling_disc`)."""
    return models.rolling_disc("between" if between else "given").system.equations_of_motion()


def disc_kane():
    q = me.dynamicsymbols("x y psi theta phi")
    x, y, psi, th, phi = q
    u = me.dynamicsymbols("ux uy upsi utheta uphi")
    m, g, r = sp.symbols("m g r", positive=True)
    N = me.ReferenceFrame("N")
    A = N.orientnew("A", "Axis", (psi, N.z))
    B = A.orientnew("B", "Axis", (th, A.x))
    D = B.orientnew("D", "Axis", (phi, B.z))
    kd = {qi.diff(): ui for qi, ui in zip(q, u, strict=True)}
    O = me.Point("O")
    O.set_vel(N, 0)
    Ic = O.locatenew("Ic", x * N.x + y * N.y)
    G = Ic.locatenew("G", r * B.y)
    D.set_ang_vel(N, D.ang_vel_in(N).subs(kd))
    G.set_vel(N, G.pos_from(O).dt(N).subs(kd))
    P = G.locatenew("P", -r * B.y)
    P.v2pt_theory(G, N, D)
    vP = P.vel(N)
    I = me.inertia(D, m * r**2 / 4, m * r**2 / 4, m * r**2 / 2)
    kane = me.KanesMethod(N, q_ind=list(q), u_ind=u[2:], u_dependent=u[:2],
                          kd_eqs=[qi.diff() - ui for qi, ui in zip(q, u, strict=True)],
                          velocity_constraints=[vP.dot(N.x), vP.dot(N.y)])
    kane.kanes_equations([me.RigidBody("disc", G, D, m, (I, G))], [(G, -m * g * N.z)])
    return kane


def _derive(case, side):
    """Build and derive one model; returns what the accelerations check needs."""
    if case.startswith("disc"):
        if side == "rigidmech":
            return disc_rigidmech(between=case == "disc-between")
        kane = disc_kane()
        return kane, kane.mass_matrix, kane.forcing
    n = int(case)
    if side == "rigidmech":
        return chain_rigidmech(n)
    kane = chain_kane(n)
    return kane, kane.mass_matrix, kane.forcing


def _case_main(case, side):
    """Child process: one cold derivation, its CPU time as a JSON line."""
    if case.startswith("phases"):
        print(json.dumps(phases(int(case[6:]))), flush=True)
        return
    t0 = time.process_time()
    _derive(case, side)
    print(json.dumps({"cpu": time.process_time() - t0}), flush=True)


def _run(case, side, timeout):
    cmd = [sys.executable, os.path.abspath(__file__), "--case", case, side]
    try:
        out = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout,
                             env=dict(os.environ), check=True).stdout
    except subprocess.TimeoutExpired:
        return math.inf
    return json.loads(out.strip().splitlines()[-1])["cpu"]


def chain_positions(n, q1):
    """The chain's parameters for a crank angle q1, each loop closed by hand: the tip E of
    the rocker at distance L3 from its pivot D and lc from the driver's tip P (the
    intersection of two circles, the one on the right of P -> D)."""
    out, angle, tip = {"q1": q1}, q1, (L1 * math.cos(q1), L1 * math.sin(q1))
    for j in range(1, n + 1):
        lc, D = (L2 if j == 1 else L2B), (j * L0, 0.0)
        dx, dy = D[0] - tip[0], D[1] - tip[1]
        d = math.hypot(dx, dy)
        x = (d * d + lc * lc - L3 * L3) / (2 * d)
        h = -math.sqrt(lc * lc - x * x)
        E = (tip[0] + (x * dx - h * dy) / d, tip[1] + (x * dy + h * dx) / d)
        coupler = math.atan2(E[1] - tip[1], E[0] - tip[0])
        out[f"q{2 * j}"] = coupler - angle
        angle = out[f"q{2 * j + 1}"] = math.atan2(E[1] - D[1], E[0] - D[0])
        tip = E
    return out


def accelerations_gap(n):
    """Largest relative difference between rigidmech's and Kane's q'' for the chain of n
    four-bars at an assembled state (q1 = 1, q1' = 0.7, m = 1, g = 9.81)."""
    import numpy as np

    s = chain_system(n)
    guess = chain_positions(n, 1.0)
    q0, u0 = s.assemble(guess, independent=["q1"], rates={"q1": 0.7})
    eqs = s.equations_of_motion()
    ours = eqs._solver().full(0.0, np.array(list(q0.values())), np.array(list(u0.values())),
                              *[{"m": 1.0, "g": 9.81}[p.name] for p in eqs.parameters])
    ours = np.asarray(ours)[: 2 * n + 1]
    kane = chain_kane(n)
    qs, us = kane.q, kane.u
    rule = {sp.Symbol("m", positive=True): 1.0, sp.Symbol("g", positive=True): 9.81}
    rule.update({q: q0[str(q.func)] for q in qs})
    rule.update({u: u0["q" + str(u.func)[1:]] for u in us})
    M = np.array(kane.mass_matrix.xreplace(rule), float)
    f = np.array(kane.forcing.xreplace(rule), float).ravel()
    theirs = np.linalg.solve(M, f)
    return float(np.max(np.abs(ours - theirs)) / np.max(np.abs(theirs)))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--chains", type=int, nargs="+", default=[1, 2, 4])
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--timeout", type=float, default=300.0)
    parser.add_argument("--phases", type=int, metavar="N",
                        help="print where the derivation of the chain of N four-bars goes")
    parser.add_argument("--case", nargs=2, help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.case:
        _case_main(*args.case)
        return
    if args.phases:
        cmd = [sys.executable, os.path.abspath(__file__), "--case", f"phases{args.phases}", "-"]
        out = subprocess.run(cmd, capture_output=True, text=True, check=True).stdout
        spent = json.loads(out.strip().splitlines()[-1])
        total = sum(spent.values())
        for phase, x in spent.items():
            print(f"{phase:<34}{x:>8.3f} s {100 * x / total:>5.0f} %")
        print(f"{'total':<34}{total:>8.3f} s")
        return
    print(f"{'model':<16}{'rigidmech [s]':>15}{'KanesMethod [s]':>18}{'ratio':>8}"
          f"{'qdd gap':>10}")
    cases = [(str(n), f"{n} four-bar" + ("s" if n > 1 else "")) for n in args.chains]
    for case, name in [*cases, ("disc", "rolling disc"), ("disc-between", "disc, between")]:
        ours, theirs = [], []
        for _ in range(args.repeat):  # alternated
            ours.append(_run(case, "rigidmech", args.timeout))
            theirs.append(_run(case, "kane", args.timeout))
        a, b = min(ours), min(theirs)
        gap = "" if case.startswith("disc") else f"{accelerations_gap(int(case)):>10.1e}"
        print(f"{name:<16}{a:>15.3f}{b:>18.3f}{b / a:>8.1f}{gap}", flush=True)


if __name__ == "__main__":
    main()
