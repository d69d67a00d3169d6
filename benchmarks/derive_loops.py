"""Derivation time of closed-loop and nonholonomic mechanisms: rigidmech vs
sympy.physics.mechanics' KanesMethod on the same models, same run (book, ch. 13.2, 25.3).

* four-bar linkage (three rods, four pivots, the loop closed at C): rigidmech keeps q1, q2,
  q3 with two closure conditions (Lagrange multipliers); KanesMethod with q2, q3 and their
  speeds dependent, the configuration and velocity constraints;
* disc rolling on a plane (contact point (x, y), heading, lean, spin; no slip): rigidmech with
  a RollingContact (velocity constraints, multipliers); KanesMethod with the speeds of x and y
  dependent.

Both sides stop at their equations of motion (rigidmech: ``System.equations_of_motion()``
with its constraint block; sympy: ``kanes_equations``), nothing simplified. Minimum over a few
repeats (shared machine). Run::

    PYTHONPATH=src python benchmarks/derive_loops.py
"""

import time

import sympy as sp
import sympy.physics.mechanics as me

import rigidmech as rm
from rigidmech.dynamics import System
from rigidmech.kinematics import ContactKinematics

L0, L1, L2, L3 = 2.0, 1.0, 2.0, 1.5


def four_bar_rigidmech():
    return four_bar_system().equations_of_motion()


def four_bar_system(stabilization=(5.0, 5.0)):
    """The four-bar as a rigidmech System (the loop closed by the pivot at C)."""
    q1, q2, q3 = rm.coordinates("q1 q2 q3")
    m, g = rm.constants("m g", positive=True)
    R0 = rm.Frame("R0")
    k = R0.k
    R1 = R0.rotated("R1", about=k, angle=q1)
    B = R0.origin.moved("B", L1 * R1.i)
    R2 = R1.rotated("R2", about=k, angle=q2, origin=B)
    D = R0.point("D", L0, 0, 0)
    R3 = R0.rotated("R3", about=k, angle=q3, origin=D)

    def bar(name, F, L, O):
        G = O.moved("G" + name, L / 2 * F.i)
        return rm.Body(name, frame=F, mass=m, centre=G,
                       inertia=rm.inertia.rod(m, L, axis=F.i, centre=G))

    crank, coupler, rocker = bar("crank", R1, L1, R0.origin), bar("coupler", R2, L2, B), bar(
        "rocker", R3, L3, D)
    s = System(galilean=R0, stabilization=stabilization)
    s.connect(R0, crank, rm.joints.Pivot(at=R0.origin, axis=k))
    s.connect(crank, coupler, rm.joints.Pivot(at=B, axis=k))
    s.connect(R0, rocker, rm.joints.Pivot(at=D, axis=k))
    s.connect(coupler, rocker, rm.joints.Pivot(at=B.moved("C", L2 * R2.i), axis=k),
              meets=D.moved("C3", L3 * R3.i))
    s.act(rm.gravity(-g * R0.j))
    return s


def four_bar_kane():
    q1, q2, q3 = me.dynamicsymbols("q1 q2 q3")
    u1, u2, u3 = me.dynamicsymbols("u1 u2 u3")
    m, g = sp.symbols("m g", positive=True)
    N = me.ReferenceFrame("N")
    A = N.orientnew("A", "Axis", (q1, N.z))
    B = A.orientnew("B", "Axis", (q2, A.z))
    C = N.orientnew("C", "Axis", (q3, N.z))
    A.set_ang_vel(N, u1 * N.z)
    B.set_ang_vel(N, (u1 + u2) * N.z)
    C.set_ang_vel(N, u3 * N.z)
    O = me.Point("O")
    O.set_vel(N, 0)
    Bp = O.locatenew("Bp", L1 * A.x)
    Bp.v2pt_theory(O, N, A)
    Cp = Bp.locatenew("Cp", L2 * B.x)
    Cp.v2pt_theory(Bp, N, B)
    Dp = O.locatenew("Dp", L0 * N.x)
    Dp.set_vel(N, 0)
    Cr = Dp.locatenew("Cr", L3 * C.x)
    Cr.v2pt_theory(Dp, N, C)
    bodies, loads = [], []
    for name, frame, start, L in (("crank", A, O, L1), ("coupler", B, Bp, L2),
                                  ("rocker", C, Dp, L3)):
        G = start.locatenew("G" + name, L / 2 * frame.x)
        G.v2pt_theory(start, N, frame)
        I = me.inertia(frame, 0, m * L**2 / 12, m * L**2 / 12)
        bodies.append(me.RigidBody(name, G, frame, m, (I, G)))
        loads.append((G, -m * g * N.y))
    gap = Cp.pos_from(O) - Cr.pos_from(O)
    dv = Cp.vel(N) - Cr.vel(N)
    kane = me.KanesMethod(
        N, q_ind=[q1], q_dependent=[q2, q3], u_ind=[u1], u_dependent=[u2, u3],
        kd_eqs=[q1.diff() - u1, q2.diff() - u2, q3.diff() - u3],
        configuration_constraints=[gap.dot(N.x), gap.dot(N.y)],
        velocity_constraints=[dv.dot(N.x), dv.dot(N.y)])
    kane.kanes_equations(bodies, loads)
    return kane


def disc_rigidmech():
    x, y, psi, th, phi = rm.coordinates("x y psi theta phi")
    m, g, r = rm.constants("m g r", positive=True)
    R0 = rm.Frame("R0")
    A = R0.rotated("A", about=R0.k, angle=psi)
    B = A.rotated("B", about=A.i, angle=th)
    I0 = R0.point("I0", x, y, 0)
    G = I0.moved("G", r * B.j)
    D = B.rotated("D", about=B.k, angle=phi, origin=G)
    disc = rm.Body("disc", frame=D, mass=m, centre=G,
                   inertia=rm.inertia.disk(m, r, axis=D.k, centre=G))
    s = System(galilean=R0)
    s.connect(R0, disc, rm.actions.RollingContact(ContactKinematics(D, R0, at=I0, normal=R0.k)))
    s.act(rm.gravity(-g * R0.k))
    return s.equations_of_motion()


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


def best(fn, repeat=3):
    times = []
    for _ in range(repeat):
        sp.core.cache.clear_cache()
        t0 = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t0)
    return min(times)


if __name__ == "__main__":
    print(f"{'model':<12}{'rigidmech [s]':>15}{'KanesMethod [s]':>18}{'ratio':>8}")
    for name, ours, theirs in (("four-bar", four_bar_rigidmech, four_bar_kane),
                               ("rolling disc", disc_rigidmech, disc_kane)):
        a, b = best(ours), best(theirs)
        print(f"{name:<12}{a:>15.3f}{b:>18.3f}{b / a:>8.1f}")
