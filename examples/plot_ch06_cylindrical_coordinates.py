"""
Kinematic vectors of a point in cylindrical coordinates (ch. 6.2-6.3)
=====================================================================

A point :math:`M` is located in the reference :math:`\\mathcal{T}_0 = (O; \\mathbf{i}_0,
\\mathbf{j}_0, \\mathbf{k}_0)` by its cylindrical coordinates :math:`(r, \\theta, z)`:
:math:`\\mathbf{OM} = r\\,\\mathbf{e}_r + z\\,\\mathbf{k}_0`, where :math:`\\mathbf{e}_r` turns by
:math:`\\theta` about :math:`\\mathbf{k}_0`. The book gives (ch. 6.3.2)

.. math:: \\mathbf{v} = \\dot r\\,\\mathbf{e}_r + r\\dot\\theta\\,\\mathbf{e}_\\theta
          + \\dot z\\,\\mathbf{k}_0, \\qquad
          \\mathbf{a} = (\\ddot r - r\\dot\\theta^2)\\,\\mathbf{e}_r
          + (2\\dot r\\dot\\theta + r\\ddot\\theta)\\,\\mathbf{e}_\\theta
          + \\ddot z\\,\\mathbf{k}_0,

and the tangential and normal components of the acceleration (ch. 6.2.3),
:math:`a_t = dV/dt` and :math:`a_n = V^2/\\rho`, :math:`\\rho` the radius of curvature of the
trajectory.
"""

# %%
# The point and its kinematic vectors
# -----------------------------------
import matplotlib.pyplot as plt
import numpy as np
import sympy as sp

import rigidmech as rm

r, theta, z = rm.coordinates("r theta z")
R0 = rm.Frame("R0")
R1 = R0.rotated("R1", about=R0.k, angle=theta)            # (e_r, e_theta, k0)
M = R0.origin.moved("M", r * R1.i + z * R0.k)
v = M.velocity(R0)
a = M.acceleration(R0)
print("v in (e_r, e_theta, k0):", sp.simplify(v.components(R1)).T)
print("a in (e_r, e_theta, k0):", sp.simplify(a.components(R1)).T)

# %%
# Check: the book's expressions
# -----------------------------
d = lambda f, n=1: f.diff(rm.t, n)  # noqa: E731
assert sp.simplify(v.components(R1) - sp.Matrix([d(r), r * d(theta), d(z)])) == sp.zeros(3, 1)
expected_a = sp.Matrix([d(r, 2) - r * d(theta) ** 2, 2 * d(r) * d(theta) + r * d(theta, 2),
                        d(z, 2)])
assert sp.simplify(a.components(R1) - expected_a) == sp.zeros(3, 1)

# %%
# A motion on a conical helix: tangential and normal accelerations
# ----------------------------------------------------------------
# :math:`r = 1 + t/2`, :math:`\theta = 2t`, :math:`z = 0.3\,t` (SI units). The radius of
# curvature comes from the geometry of the trajectory (:class:`rigidmech.Curve`, ch. 4.3), an
# independent route to :math:`a_n = V^2/\rho`.
motion = {r: 1 + rm.t / 2, theta: 2 * rm.t, z: sp.Rational(3, 10) * rm.t}


def along(expr):
    """Substitute the motion (derivatives first) into an expression of r, theta, z."""
    for q, f in motion.items():
        expr = expr.subs({d(q, 2): d(f, 2), d(q): d(f)}).subs(q, f)
    return sp.simplify(expr)


V = along(v.magnitude())
a_t = sp.diff(V, rm.t)
a_n2 = along(a.magnitude() ** 2) - a_t**2
path = rm.Curve(R0.vector(*[along(c) for c in M.position.components(R0)]), rm.t, R0)
rho = path.radius_of_curvature()
times = np.linspace(0.2, 4, 8)
for tk in times:
    lhs = float(a_n2.subs(rm.t, tk))
    rhs = float((V**2 / rho).subs(rm.t, tk)) ** 2
    assert abs(lhs - rhs) < 1e-9 * rhs, tk
print("a_n = V^2 / rho verified at", len(times), "instants")

# %%
# Drawing: the trajectory and the accelerations
# ---------------------------------------------
ts = np.linspace(0, 4, 400)
f_V, f_at, f_an2 = (sp.lambdify(rm.t, e, "numpy") for e in (V, a_t, a_n2))
fig = plt.figure(figsize=(10, 4.3), constrained_layout=True)
ax = fig.add_subplot(1, 2, 1, projection="3d")
rr, th = 1 + ts / 2, 2 * ts
ax.plot(rr * np.cos(th), rr * np.sin(th), 0.3 * ts)
ax.set(xlabel="x (m)", ylabel="y (m)", zlabel="z (m)", title="Trajectory of M")
ax2 = fig.add_subplot(1, 2, 2)
ax2.plot(ts, f_V(ts) * np.ones_like(ts), label="V (m/s)")
ax2.plot(ts, f_at(ts) * np.ones_like(ts), label=r"$a_t$ (m/s$^2$)")
ax2.plot(ts, np.sqrt(f_an2(ts)), label=r"$a_n$ (m/s$^2$)")
ax2.set(xlabel="time t (s)", ylabel="value (SI units)", title="Speed and acceleration components")
ax2.legend()
plt.show()
