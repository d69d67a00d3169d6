"""Derivation time of a ball on Euler parameters rolling on a driven turntable, against
Kane-8 (sympy's KanesMethod deriving the planar 8-link rod pendulum) and against KanesMethod
on the same ball, same run (book, ch. 9.1.2, 10.1.3, 25.3).

The model (the catalogue's ``rigidmech.models.ball_on_turntable``): a uniform ball (mass m,
radius r, inertia 2 m r^2 / 5) whose centre is G = (x, y, r) in the Galilean R0 and whose
frame is oriented relative to R0 by the Euler parameters (e0, e1, e2, e3)
(``Frame.euler_parameters``); it rolls without slipping (``RollingContact`` of
``ContactKinematics.between`` the sphere and the table's plane) on a turntable driven at the
prescribed rate Omega about R0.k: a body whose frame is ``R0.rotated("Rt", about=R0.k,
angle=Omega * t)``, pivoted to R0, with no parameter of its own. Gravity -g R0.k. Six
parameters, two nonholonomic conditions.

KanesMethod on the same ball: q = (x, y, e0..e3) with sympy's ``"Quaternion"`` orientation,
u = the rotation vector's body components (w1, w2, w3), independent, and the velocity of G
(vx, vy), dependent; e' = (1/2) e * (0, w), x' = vx, y' = vy; the two no-slip conditions
against the table's velocity Omega k ^ (x i + y j).

Timed (CPU time, ``time.process_time``; each run in a fresh process, sympy's cache cold; the
sides alternated; the minimum over ``--repeat`` runs): rigidmech from the System's build to
``equations_of_motion()`` with its mass matrix, forcing, constraint Jacobian and
Baumgarte-stabilised bias; Kane-8 as in ``benchmarks/derive.py`` (``kanes_equations``, then
``mass_matrix`` and ``forcing``); KanesMethod on the ball likewise. Before timing, the
script checks that rigidmech's compiled q'' equals Kane's at random states on the
conditions (unit e, e' from w, the dependent speeds solved), relative difference printed.

Run::

    PYTHONPATH=src python benchmarks/derive_ball_turntable.py --repeat 3
"""

import argparse
import json
import os
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import sympy as sp
import sympy.physics.mechanics as me

sys.path.insert(0, str(Path(__file__).resolve().parent))
import derive  # noqa: E402  (benchmarks/derive.py: Kane-8 and the pre-imports)

from rigidmech import models  # noqa: E402

TARGET = 0.2  # of Kane-8 (issue #20)
PARAMS = dict(m=1.3, r=0.4, g=9.81, Omega=1.7)


def ball_on_turntable():
    """The ball on the driven turntable with rigidmech (the catalogue's
    ``models.ball_on_turntable``); returns ``(system, (x, y, e0, e1, e2, e3), (m, r, g,
    Omega))``."""
    model = models.ball_on_turntable()
    return model.system, model.coordinates, model.constants


def ball_kane():
    """The same ball with KanesMethod; returns ``(kane, q, u, (m, r, g, Omega))`` with
    q = (x, y, e0..e3) and u = (w1, w2, w3, vx, vy)."""
    q = me.dynamicsymbols("x y e0 e1 e2 e3")
    u = me.dynamicsymbols("w1 w2 w3 vx vy")
    x, y, e0, e1, e2, e3 = q
    w1, w2, w3, vx, vy = u
    m, r, g, W = sp.symbols("m r g Omega", positive=True)
    t = me.dynamicsymbols._t
    N = me.ReferenceFrame("N")
    B = N.orientnew("B", "Quaternion", [e0, e1, e2, e3])
    B.set_ang_vel(N, w1 * B.x + w2 * B.y + w3 * B.z)
    O = me.Point("O")
    O.set_vel(N, 0)
    G = O.locatenew("G", x * N.x + y * N.y + r * N.z)
    G.set_vel(N, vx * N.x + vy * N.y)
    P = G.locatenew("P", -r * N.z)
    P.v2pt_theory(G, N, B)
    slip = P.vel(N) - W * N.z.cross(x * N.x + y * N.y)
    rates = [-(e1 * w1 + e2 * w2 + e3 * w3) / 2, (e0 * w1 + e2 * w3 - e3 * w2) / 2,
             (e0 * w2 + e3 * w1 - e1 * w3) / 2, (e0 * w3 + e1 * w2 - e2 * w1) / 2]
    kd = [x.diff(t) - vx, y.diff(t) - vy] + [
        ei.diff(t) - ri for ei, ri in zip((e0, e1, e2, e3), rates, strict=True)]
    body = me.RigidBody("ball", G, B, m, (me.inertia(B, *3 * [2 * m * r**2 / 5]), G))
    kane = me.KanesMethod(N, q_ind=list(q), u_ind=[w1, w2, w3], u_dependent=[vx, vy],
                          kd_eqs=kd, velocity_constraints=[slip.dot(N.x), slip.dot(N.y)])
    kane.kanes_equations([body], [(G, -m * g * N.z)])
    return kane, q, u, (m, r, g, W)


def _quat(a, b):
    """The quaternion product a * b (scalar first)."""
    a0, av, b0, bv = a[0], np.asarray(a[1:]), b[0], np.asarray(b[1:])
    return np.concatenate(([a0 * b0 - av @ bv], a0 * bv + b0 * av + np.cross(av, bv)))


def kane_accelerations(seed=0, n_states=5):
    """Random states on the conditions and KanesMethod's q'' there: a list of (y, q'') with
    y = (q, q') in rigidmech's order (x, y, e0..e3)."""
    kane, q, u, (m, r, g, W) = ball_kane()
    sub = {m: PARAMS["m"], r: PARAMS["r"], g: PARAMS["g"], W: PARAMS["Omega"]}
    MM = sp.lambdify(list(q) + list(u), kane.mass_matrix_full.subs(sub), "numpy")
    FF = sp.lambdify(list(q) + list(u), kane.forcing_full.subs(sub), "numpy")
    rng = np.random.default_rng(seed)
    out = []
    rad, Om = PARAMS["r"], PARAMS["Omega"]
    for _ in range(n_states):
        pos = rng.uniform(-2, 2, 2)
        e = rng.normal(size=4)
        e /= np.linalg.norm(e)
        w = rng.uniform(-3, 3, 3)
        # no slip: v(G) + omega ^ (-r k) = Omega k ^ (x, y); omega in R0 from the matrix
        C = _dcm(e)
        wi = C @ w
        v = Om * np.array([-pos[1], pos[0], 0.0]) - np.cross(wi, [0.0, 0.0, -rad])
        ed = 0.5 * _quat(e, [0.0, *w])
        qv = np.concatenate((pos, e))
        uv = np.concatenate((w, v[:2]))
        sol = np.linalg.solve(MM(*qv, *uv), FF(*qv, *uv)).ravel()
        ud = sol[6:]  # (w1', w2', w3', vx', vy')
        edd = 0.5 * (_quat(ed, [0.0, *w]) + _quat(e, [0.0, *ud[:3]]))
        y = np.concatenate((qv, v[:2], ed))
        out.append((y, np.concatenate((ud[3:], edd))))
    return out


def _dcm(e):
    """Direction cosines of unit Euler parameters (columns: the body axes in R0)."""
    a, b, c, d = e
    return np.array([[a*a + b*b - c*c - d*d, 2 * (b*c - a*d), 2 * (b*d + a*c)],
                     [2 * (b*c + a*d), a*a - b*b + c*c - d*d, 2 * (c*d - a*b)],
                     [2 * (b*d - a*c), 2 * (c*d + a*b), a*a - b*b - c*c + d*d]])


def check():
    """Largest relative difference between rigidmech's compiled q'' and Kane's."""
    rhs = ball_on_turntable()[0].equations_of_motion().rhs(**PARAMS)
    worst = 0.0
    for y, expected in kane_accelerations():
        got = rhs(0.0, y)[6:]
        worst = max(worst, float(np.max(np.abs(got - expected)) / np.max(np.abs(expected))))
    return worst


def run_side(side):
    derive._preimport()
    t0 = time.process_time()
    if side == "rigidmech":
        eqs = ball_on_turntable()[0].equations_of_motion()
        eqs.mass_matrix, eqs.forcing, eqs.constraints.jacobian, eqs.constraints.stabilized_bias()
    elif side == "kane-ball":
        kane = ball_kane()[0]
        _ = kane.mass_matrix, kane.forcing
    else:
        km = derive.kane_pendulum(8)[0]
        _ = km.mass_matrix, km.forcing
    return time.process_time() - t0


SIDES = ("rigidmech", "kane-8", "kane-ball")


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--repeat", type=int, default=3)
    p.add_argument("--no-check", action="store_true", help="skip the check against Kane")
    p.add_argument("--side", choices=SIDES, help=argparse.SUPPRESS)
    args = p.parse_args()
    if args.side:
        print(json.dumps(run_side(args.side)))
        return
    load = os.getloadavg()
    print(f"load average (1, 5, 15 min) at start: {load[0]:.2f} {load[1]:.2f} {load[2]:.2f}, "
          f"{os.cpu_count()} cores, sympy {sp.__version__}")
    if not args.no_check:
        print(f"q'' at 5 random states on the conditions, max relative difference rigidmech "
              f"vs KanesMethod: {check():.1e}")
    times = {side: [] for side in SIDES}
    for _ in range(args.repeat):
        for side in SIDES:
            out = subprocess.run([sys.executable, __file__, "--side", side], env=dict(os.environ),
                                 capture_output=True, text=True, check=True)
            times[side].append(json.loads(out.stdout.strip().splitlines()[-1]))
    best = {side: min(v) for side, v in times.items()}
    ratio = best["rigidmech"] / best["kane-8"]
    print(f"CPU s, min of {args.repeat} (fresh process each): rigidmech {best['rigidmech']:.3f}, "
          f"Kane-8 {best['kane-8']:.3f}, KanesMethod on the ball {best['kane-ball']:.3f}")
    print(f"rigidmech / Kane-8 = {ratio:.3f} (target <= {TARGET}: "
          f"{'PASS' if ratio <= TARGET else 'FAIL'}); KanesMethod ball / rigidmech = "
          f"{best['kane-ball'] / best['rigidmech']:.2f}")
    load = os.getloadavg()
    print(f"load average at end: {load[0]:.2f} {load[1]:.2f} {load[2]:.2f}")


if __name__ == "__main__":
    main()
