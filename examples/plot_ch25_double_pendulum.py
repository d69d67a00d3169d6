"""
Double pendulum of two uniform rods (ch. 25.4.3, 27.5)
======================================================

Two uniform rods of mass m and length L: the first hangs from a pivot at O fixed in the
Galilean reference R0, the second from a pivot at the free end A of the first. We build the
system the book's way (frames, bodies, connections, actions), obtain the equations of motion
M(q) q'' = f from the fundamental principle, ask for the action of the upper pivot only when
we want it, then integrate and check the energy.

The angles are **absolute**: theta1 and theta2 are the angles of the rods from the downward
vertical i0 (the book also works with the relative angle theta2 - theta1).
"""

# %%
# Frames, bodies, connections, actions
# ------------------------------------
# R1 and R2 are attached to the rods, each turned about k0 from R0 (elementary basis changes,
# ch. 2.5.2). The operator of inertia of each rod is taken at its mass centre (ch. 15).
import matplotlib.pyplot as plt
import numpy as np
import sympy as sp

import rigidmech as rm
from rigidmech import models, scenes

theta1, theta2 = rm.coordinates("theta1 theta2")
m, L, g = rm.constants("m L g", positive=True)

R0 = rm.Frame("R0")                                       # Galilean, i0 points down
R1 = R0.rotated("R1", about=R0.k, angle=theta1)
R2 = R0.rotated("R2", about=R0.k, angle=theta2)
O = R0.origin
A = O.moved("A", L * R1.i)
G1 = O.moved("G1", L / 2 * R1.i)
G2 = A.moved("G2", L / 2 * R2.i)

bar1 = rm.Body("bar1", frame=R1, mass=m, centre=G1,
               inertia=rm.inertia.rod(m, L, axis=R1.i, centre=G1))
bar2 = rm.Body("bar2", frame=R2, mass=m, centre=G2,
               inertia=rm.inertia.rod(m, L, axis=R2.i, centre=G2))

system = rm.System(galilean=R0)
system.connect(R0, bar1, rm.joints.Pivot(at=O, axis=R0.k))     # pivot (ch. 13.2.2)
system.connect(bar1, bar2, rm.joints.Pivot(at=A, axis=R0.k))
system.act(rm.gravity(g * R0.i))                                # ch. 12.2
print(system)

# %%
# Equations of motion
# -------------------
# The perfect pivots have zero power coefficients and drop out (ch. 25.1.4): two equations,
# free of connection unknowns.
eqs = system.equations_of_motion()
print(scenes.equations_text(eqs, pretty=True))

# %%
# Action of the pivot at O on the first rod
# -----------------------------------------
# Derived only now, on demand (ch. 18.2): the fundamental principle for the set {bar1, bar2}
# carried by that connection. It is a torsor reduced at O, written with the parameters of
# situation theta1(t), theta2(t) and their derivatives. Its moment about k0 is the
# first equation of motion of the set {bar1, bar2} written as "left minus right side": it
# vanishes along every motion, as it must for a perfect pivot (N = 0, ch. 13.2.2).
action = system.connection_action(R0, bar1)
print(action)
resultant = sp.Matrix(action.resultant.components(R0)).applyfunc(sp.simplify)
resultant

# %%
# Numbers: integrate and check the energy
# ---------------------------------------
# Released at theta1 = 2 rad, theta2 = -0.2 rad with m = 1 kg, L = 1 m, g = 9.81 m/s^2, the
# motion is chaotic; the total mechanical energy T + V is a first integral and tells how well
# the solver did.
values = {"m": 1.0, "L": 1.0, "g": 9.81}
sim = eqs.simulate(t=(0.0, 10.0), q0=[2.0, -0.2], method="dop853", rtol=1e-10, atol=1e-12,
                   **values)
e = sim.energy()
print(f"{sim.result.nfev} evaluations of the right-hand side; "
      f"relative energy drift {sim.energy_drift():.2e}")

fig, (ax1, ax2) = plt.subplots(2, 1, sharex=True, figsize=(7, 5.5))
ax1.plot(sim.t, sim.q[0], label=r"$\theta_1$")
ax1.plot(sim.t, sim.q[1], label=r"$\theta_2$")
ax1.set_ylabel("angle [rad]")
ax1.legend()
ax1.grid(True, alpha=0.3)
ax2.plot(sim.t, (e - e[0]) / np.max(np.abs(e)))
ax2.set_xlabel("t [s]")
ax2.set_ylabel(r"$(E - E_0)/\max|E|$")
ax2.grid(True, alpha=0.3)
fig.tight_layout()

# %%
# The same from the catalogue
# ---------------------------
# The catalogue's builder :func:`rigidmech.models.double_pendulum` builds this very system
# (same symbols, same equations) and returns it with its handles (coordinates, constants,
# frames, bodies, points); the scene ``double-pendulum`` uses it, and ``python -m rigidmech
# run double-pendulum`` prints the report below from the command line.
model = models.double_pendulum()
same = model.system.equations_of_motion()
print(same.mass_matrix == eqs.mass_matrix and same.forcing == eqs.forcing)
report = scenes.run("double-pendulum", t_end=10.0)
print(report)
