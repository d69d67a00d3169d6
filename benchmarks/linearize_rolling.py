"""Linearising a nonholonomic system about a steady motion: a thin disc rolling upright at
speed v, rigidmech against ``KanesMethod.linearize``.

The same model on both sides: contact point (x, y), heading psi, lean theta (pi/2 upright),
spin phi; rolling without slipping as two velocity constraints (the speeds of x and y
dependent). Each side runs in a fresh process (this script re-run with ``--case``), so that
sympy's cache is cold; CPU time (``time.process_time``) of build + derivation +
linearisation, the parameters and the speed symbolic.

- rigidmech: ``System.equations_of_motion`` then ``rigidmech.vibrations.linearize`` about
  theta = pi/2 with the spin rate Omega (M, C, K on psi, theta, phi).
- sympy: ``KanesMethod.kanes_equations`` with ``u_dependent`` and ``velocity_constraints``,
  then ``KanesMethod.linearize(op_point=..., A_and_B=True)`` (the first-order A on the
  independent states).

Printed: the time of each side, the ratio (> 1: we are faster) and the largest difference of
the nonzero eigenvalues at one speed.

Run::

    python benchmarks/linearize_rolling.py
"""

from __future__ import annotations

import json
import subprocess
import sys
import time

VALUES = {"m": 1.3, "g": 9.81, "r": 0.7, "Omega": -3.0}


def case_ours():
    import sympy as sp

    from rigidmech import models
    from rigidmech.vibrations import linearize

    start = time.process_time()
    s = models.rolling_disc("given").system          # contact point and normal given
    lin = linearize(s.equations_of_motion(), about={"theta": sp.pi / 2},
                    velocities={"phi": sp.Symbol("Omega")})
    elapsed = time.process_time() - start
    ev = lin.eigenvalues(**VALUES)
    print(json.dumps({"time": elapsed, "eig": sorted(ev.imag.tolist())}))


def case_kane():
    import numpy as np
    import sympy as sp
    import sympy.physics.mechanics as me

    start = time.process_time()
    q = me.dynamicsymbols("x y psi theta phi")
    x, y, psi, th, phi = q
    u = me.dynamicsymbols("ux uy upsi utheta uphi")
    m, g, r, Om = sp.symbols("m g r Omega")
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
    body = me.RigidBody("disc", G, D, m, (I, G))
    kane = me.KanesMethod(N, q_ind=list(q), u_ind=u[2:], u_dependent=u[:2],
                          kd_eqs=[qi.diff() - ui for qi, ui in zip(q, u, strict=True)],
                          velocity_constraints=[vP.dot(N.x), vP.dot(N.y)])
    kane.kanes_equations([body], [(G, -m * g * N.z)])
    op = {x: 0, y: 0, psi: 0, th: sp.pi / 2, phi: 0, u[0]: -r * Om, u[1]: 0, u[2]: 0,
          u[3]: 0, u[4]: Om}
    op |= {ui.diff(): 0 for ui in u}
    Alin = kane.linearize(op_point=op, A_and_B=True)[0]
    elapsed = time.process_time() - start
    vals = {m: VALUES["m"], g: VALUES["g"], r: VALUES["r"], Om: VALUES["Omega"]}
    ev = np.linalg.eigvals(np.array(Alin.subs(vals).evalf().tolist(), dtype=float))
    print(json.dumps({"time": elapsed, "eig": sorted(ev.imag.tolist())}))


def main():
    if len(sys.argv) > 2 and sys.argv[1] == "--case":
        {"ours": case_ours, "kane": case_kane}[sys.argv[2]]()
        return
    out = {}
    for side in ("ours", "kane"):
        run = subprocess.run([sys.executable, __file__, "--case", side], capture_output=True,
                             text=True, check=True)
        out[side] = json.loads(run.stdout.strip().splitlines()[-1])
    big = [e for e in out["ours"]["eig"] if abs(e) > 1e-6]
    theirs = [e for e in out["kane"]["eig"] if abs(e) > 1e-6]
    diff = max(abs(a - b) for a, b in zip(big, theirs, strict=True))
    print(f"rolling disc upright, steady motion: rigidmech {out['ours']['time']:.2f} s, "
          f"KanesMethod.linearize {out['kane']['time']:.2f} s (CPU), ratio "
          f"{out['kane']['time'] / out['ours']['time']:.1f}x; nonzero eigenvalues "
          f"{big} agree to {diff:.1e}")


if __name__ == "__main__":
    main()
