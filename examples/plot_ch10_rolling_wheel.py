"""
A wheel rolling without slipping; a ladder sliding on a wall (ch. 9.4.5, 10.1)
==============================================================================

A wheel of radius r rolls without slipping on the line (O, i0). rigidmech finds the contact
point from the two surfaces (a circle and a line), writes the condition "without slipping"
v(I in wheel/R0) = 0, recognises it as **holonomic** and integrates it: x = -r theta. A point
of the rim then traces a **cycloid**; at every instant the wheel turns about its contact point,
the **instantaneous centre of rotation**, so the velocity of each rim point is perpendicular
to the line joining it to the contact point.

Second, the book's classic ladder: end A on the floor, end B on the wall. Its instantaneous
centre is the fourth corner of the rectangle built on OA and OB; the **centrodes** are a
circle of radius L about the corner O (base curve, fixed) and a circle of radius L/2 about the
middle of the ladder (rolling curve, carried by the ladder), which rolls inside the first.
"""

# %%
# The wheel: contact, no-slip condition, cycloid
# ----------------------------------------------
import matplotlib.pyplot as plt
import numpy as np
import sympy as sp

import rigidmech as rm
from rigidmech.kinematics import Circle, ContactKinematics, Solid, centrodes, instantaneous_centre

x, theta = rm.coordinates("x theta")
r = sp.Symbol("r", positive=True)
R0 = rm.Frame("R0")
wheel = R0.rotated("R1", about=R0.k, angle=theta, origin=R0.point("C", x, r, 0))
contact = ContactKinematics.between(wheel, Circle(wheel.origin, r, normal=R0.k),
                          R0, rm.Line(R0.origin, R0.i))
rolling = rm.joints.RollingContact(contact)
print("contact point:", contact.point.coordinates(R0).T, " normal:", contact.normal)
print("without slipping:", [c.expression for c in rolling.velocity_constraints()], "= 0")
print("holonomic:", rolling.holonomic, " relation:", rolling.position_constraints({x: 0, theta: 0}))

x_of_theta = sp.solve(rolling.position_constraints({x: 0, theta: 0})[0], x)[0]
P = wheel.origin.moved("P", -r * wheel.j)  # the rim point touching the ground at theta = 0
print("rim point:", [sp.simplify(c) for c in P.coordinates(R0).subs(x, x_of_theta)[:2]])

# rim points every 60 degrees, their positions and velocities from the wheel's velocity field
alpha = sp.Symbol("alpha", real=True)
M = wheel.origin.moved("M", r * (sp.cos(alpha) * wheel.i + sp.sin(alpha) * wheel.j))
on_rolling = {x: x_of_theta, r: 1}
w = sp.Symbol("w")  # theta'
M_xy = list(M.coordinates(R0).subs(on_rolling))[:2]
v_M = Solid("wheel", wheel).velocity(M, relative_to=R0).subs(on_rolling)
v_M = [c.doit().subs(theta.diff(rm.t), w) for c in v_M.components(R0)[:2]]
f_M = sp.lambdify((theta, alpha), M_xy, "numpy")
f_v = sp.lambdify((theta, w, alpha), v_M, "numpy")

# numbers: r = 1, the wheel turning clockwise, theta = -phi, theta' = -1
phi = np.linspace(0, 4 * np.pi, 400)
xP, yP = f_M(-phi, -np.pi / 2)

fig, (ax1, ax2) = plt.subplots(2, 1, figsize=(8, 8))
ax1.plot(xP, yP, color="tab:blue", label="cycloid of a rim point")
for phi0 in (1.0, 4.0, 7.5, 10.5):
    ax1.add_patch(plt.Circle((phi0, 1.0), 1.0, fill=False, color="0.6"))
    ax1.plot(phi0, 0.0, "o", color="tab:red")  # the contact point, the ICR
    for a0 in np.linspace(0, 2 * np.pi, 6, endpoint=False):
        mx, my = f_M(-phi0, a0)
        vx, vy = f_v(-phi0, -1.0, a0)
        ax1.plot(mx, my, ".", color="k")
        ax1.quiver(mx, my, vx, vy, angles="xy", scale_units="xy", scale=3, color="tab:green",
                   width=3e-3)
ax1.set_aspect("equal")
ax1.set_title("Wheel rolling without slipping: cycloid, ICR (red), velocities (green)")
ax1.legend(loc="upper right")

# %%
# The ladder: instantaneous centre and centrodes
# ----------------------------------------------
q = rm.coordinates("q")
L = sp.Symbol("L", positive=True)
A = R0.point("A", L * sp.cos(q), 0, 0)
ladder = R0.rotated("R2", about=R0.k, angle=sp.pi - q, origin=A)
I = instantaneous_centre(ladder, relative_to=R0)
base, moving = centrodes(ladder, relative_to=R0, parameter=q)
print("ICR of the ladder:", I.coordinates(R0).T)
print("base curve:", base.position(), " curvature", base.curvature())
print("rolling curve:", moving.position(), " curvature", moving.curvature())

s = base.parameter
f_base = sp.lambdify(s, list(base.position().components(R0).subs(L, 1))[:2], "numpy")
f_roll = sp.lambdify(s, list(moving.position().components(ladder).subs(L, 1))[:2], "numpy")
u = np.linspace(0.05, np.pi / 2 - 0.05, 200)
ax2.plot(*f_base(u), color="tab:blue", label="base curve (circle of radius L about O)")
for q0, shade in ((0.4, "0.7"), (0.8, "0.45"), (1.2, "0.2")):
    a_pt, b_pt = np.array([np.cos(q0), 0]), np.array([0, np.sin(q0)])
    ax2.plot(*zip(a_pt, b_pt, strict=True), color=shade, lw=3)
    # the rolling curve drawn where it is at q0: carried by the ladder (origin A, angle pi - q0)
    xr, yr = f_roll(np.linspace(0, 2 * np.pi, 200))
    c, s0 = np.cos(np.pi - q0), np.sin(np.pi - q0)
    ax2.plot(a_pt[0] + c * xr - s0 * yr, a_pt[1] + s0 * xr + c * yr, "--", color=shade)
    ax2.plot(np.cos(q0), np.sin(q0), "o", color="tab:red")
ax2.set_aspect("equal")
ax2.set_xlim(-0.1, 1.2)
ax2.set_ylim(-0.1, 1.2)
ax2.set_title("Ladder on a floor and a wall: ICR (red) and rolling curves (dashed)")
ax2.legend(loc="upper right")
fig.tight_layout()
plt.show()
