"""Derivation time of the Chaplygin sleigh (a knife edge, one nonholonomic constraint):
rigidmech vs sympy.physics.mechanics' KanesMethod on the same model, same run (book, ch. 25.3).

The sleigh: a uniform disc of mass m and radius r moving on the horizontal plane, (x, y) its
centre G and theta its heading, the blade at P = G - a i1 along its axis. rigidmech: a
``KnifeEdge`` in a ``System``, ``equations_of_motion()`` (multiplier form with its constraint
block); KanesMethod: u = q', the speed of y dependent, the lateral condition as its velocity
constraint, ``kanes_equations`` then ``mass_matrix`` and ``forcing``; rigidmech's mass
matrix, forcing and constraint block (Jacobian, Baumgarte-stabilised bias) are touched. Each
side runs in a fresh process (this script re-run with ``--side``), cold caches, CPU time
(``time.process_time``), the sides alternated, the minimum over ``--repeat`` runs. Before
timing, the script checks that both sides give the same accelerations at a state on the
constraint.

Run::

    PYTHONPATH=src python benchmarks/derive_sleigh.py --repeat 3
"""

import argparse
import json
import os
import subprocess
import sys
import time

import numpy as np
import sympy as sp
import sympy.physics.mechanics as me

from rigidmech import models


def sleigh_rigidmech():
    """The catalogue's :func:`rigidmech.models.sleigh` (the blade a behind G, a a symbol)."""
    return models.sleigh().system.equations_of_motion()


def sleigh_kane():
    q = me.dynamicsymbols("x y theta")
    u = me.dynamicsymbols("ux uy utheta")
    x, y, th = q
    m, r, g = sp.symbols("m r g", positive=True)
    a = sp.Symbol("a", real=True)
    N = me.ReferenceFrame("N")
    B = N.orientnew("B", "Axis", (th, N.z))
    B.set_ang_vel(N, u[2] * N.z)
    O = me.Point("O")
    O.set_vel(N, 0)
    G = O.locatenew("G", x * N.x + y * N.y)
    G.set_vel(N, u[0] * N.x + u[1] * N.y)
    P = G.locatenew("P", -a * B.x)
    P.v2pt_theory(G, N, B)
    body = me.RigidBody("sleigh", G, B, m, (me.inertia(B, m * r**2 / 4, m * r**2 / 4,
                                                      m * r**2 / 2), G))
    kane = me.KanesMethod(N, q_ind=list(q), u_ind=[u[0], u[2]], u_dependent=[u[1]],
                          kd_eqs=[qi.diff() - ui for qi, ui in zip(q, u, strict=True)],
                          velocity_constraints=[P.vel(N).dot(B.y)])
    kane.kanes_equations([body], [(G, -m * g * N.z)])
    return kane, q, u, (m, r, g, a)


def sleigh_kane_timed():
    """What is timed on Kane's side: ``kanes_equations``, then ``mass_matrix`` and
    ``forcing`` (the dynamic rows with the constraint; as in derive_loops.py)."""
    kane = sleigh_kane()[0]
    return kane.mass_matrix, kane.forcing


def check():
    """Largest relative difference of the accelerations at a state on the constraint."""
    vals = dict(m=1.3, r=0.4, g=9.81, a=0.35)
    rhs = sleigh_rigidmech().rhs(**vals)
    kane, q, u, (m, r, g, a) = sleigh_kane()
    MM, FF = kane.mass_matrix_full, kane.forcing_full
    sub = {m: 1.3, r: 0.4, g: 9.81, a: 0.35}
    qv, ux, w = np.array([0.2, -0.1, 0.7]), 1.1, -0.8
    uy = (0.35 * w + np.sin(qv[2]) * ux) / np.cos(qv[2])
    ours = rhs(0.0, np.array([*qv, ux, uy, w]))[3:]
    f = sp.lambdify(list(q) + list(u), (MM.subs(sub), FF.subs(sub)), "numpy")
    Mk, Fk = f(*qv, ux, uy, w)
    theirs = np.linalg.solve(Mk, Fk).ravel()[3:]
    theirs = np.array([theirs[0], theirs[2], theirs[1]])
    return float(np.max(np.abs(ours - theirs)) / np.max(np.abs(theirs)))


def run_side(side):
    t0 = time.process_time()
    if side == "rigidmech":
        eqs = sleigh_rigidmech()
        eqs.mass_matrix, eqs.forcing, eqs.constraints.jacobian, eqs.constraints.stabilized_bias()
    else:
        sleigh_kane_timed()
    return time.process_time() - t0


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--repeat", type=int, default=3)
    p.add_argument("--side", choices=["rigidmech", "kane"])
    args = p.parse_args()
    if args.side:
        print(json.dumps(run_side(args.side)))
        return
    print(f"accelerations, max relative difference rigidmech vs Kane: {check():.1e}")
    env = dict(os.environ)
    times = {"rigidmech": [], "kane": []}
    for _ in range(args.repeat):
        for side in ("rigidmech", "kane"):
            out = subprocess.run([sys.executable, __file__, "--side", side], env=env,
                                 capture_output=True, text=True, check=True)
            times[side].append(json.loads(out.stdout.strip().splitlines()[-1]))
    ours, kane = min(times["rigidmech"]), min(times["kane"])
    print(f"sleigh derivation (CPU s, min of {args.repeat}): rigidmech {ours:.3f}, "
          f"KanesMethod {kane:.3f}, ratio Kane/rigidmech {kane / ours:.1f}x")


if __name__ == "__main__":
    main()
