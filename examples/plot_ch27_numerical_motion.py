"""
Numerical motion: pendulum, planet, satellite (ch. 27)
======================================================

The book's chapter 27 integrates the equations of motion step by step. We redo its three cases
with :mod:`rigidmech.ode` and compare with the exact solutions of
:mod:`rigidmech.testing.problems`: the simple pendulum of large amplitude (27.1.3), a planet about
the Sun (27.3.1) and a satellite about the Earth (27.3.2). A small work-precision plot closes
the tour.
"""

# %%
# Simple pendulum released at 170 degrees (27.1.3)
# ------------------------------------------------
# :math:`\ddot\theta + \omega_0^2\sin\theta = 0`. At such an amplitude the period is
# :math:`4K(k)/\omega_0`, about 2.44 times the small-oscillation period :math:`2\pi/\omega_0`.
import matplotlib.pyplot as plt
import numpy as np

from rigidmech import ode
from rigidmech.testing import problems

pend = problems.pendulum(170.0, omega0=1.0, periods=2)
sol = ode.solve(pend.fun, pend.t_span, pend.y0, method="dop853", rtol=1e-10, atol=1e-13,
                dense_output=True)
t = np.linspace(*pend.t_span, 600)
fig, ax = plt.subplots(figsize=(7, 3))
ax.plot(t, np.degrees(sol.sol(t)[0]), label="dop853")
ax.plot(t, np.degrees(pend.exact(t)[0]), "--", label="exact (Jacobi sn)")
ax.plot(t, 170 * np.cos(t), ":", label="linearised")
ax.set_xlabel("t [s]")
ax.set_ylabel("theta [deg]")
ax.legend()
print(f"period 4K/omega0 = {pend.period:.6f} s; final error {pend.final_error(sol.y[:, -1]):.1e}")

# %%
# A planet about the Sun (27.3.1)
# -------------------------------
# Mercury-like orbit (e = 0.2056, a = 0.387 AU) in SI units, :math:`\mu_\odot = 1.327\,10^{20}`
# m^3/s^2, over 5 revolutions, with the symplectic Stormer-Verlet scheme and its order-6
# composition: the position error stays small and the energy error stays bounded.
AU = 1.495978707e11
planet = problems.kepler(0.2056, orbits=5, mu=1.32712440018e20, a=0.387 * AU)
for method, per_orbit in [("verlet", 2000), ("yoshida6", 200)]:
    r = ode.solve(planet.acceleration, planet.t_span, planet.y0, method=method,
                  step=planet.period / per_orbit)
    dE = np.abs(planet.energy(r.y) / planet.energy(planet.y0) - 1).max()
    print(f"{method:9s} position error {planet.final_error(r.y[:, -1]) / AU:.1e} AU, "
          f"max |dE/E| = {dE:.1e}")
fig, ax = plt.subplots(figsize=(4, 4))
ax.plot(r.y[0] / AU, r.y[1] / AU)
ax.plot(0, 0, "o", color="orange")
ax.set_aspect("equal")
ax.set_title("planet about the Sun [AU]")

# %%
# A satellite about the Earth (27.3.2)
# ------------------------------------
# An elliptic orbit from 500 km perigee altitude to 20,000 km apogee, :math:`\mu_E =
# 3.986\,10^{14}` m^3/s^2. The Adams-Bashforth-Moulton predictor-corrector of order 5 (the
# book's multiple-step methods, 26.3) and DOP853 against Kepler's equation.
RE = 6.371e6
rp, ra = RE + 5e5, RE + 2.0e7
sat = problems.kepler((ra - rp) / (ra + rp), orbits=3, mu=3.986004418e14, a=(ra + rp) / 2)
print(f"satellite period {sat.period / 3600:.3f} h")
for method, opts in [("abm5", dict(step=sat.period / 2000)),
                     ("dop853", dict(rtol=1e-10, atol=1e-4))]:
    r = ode.solve(sat.fun, sat.t_span, sat.y0, method=method, **opts)
    print(f"{method:7s} nfev {r.nfev:6d}  final position error {sat.final_error(r.y[:, -1]):.2e} m")

# %%
# Work and precision
# ------------------
# Final error against the number of evaluations of the right-hand side on Kepler e = 0.6 over
# 10 orbits. The full comparison with scipy, timed, is ``benchmarks/work_precision.py``.
kep = problems.kepler(0.6, orbits=10)
fig, ax = plt.subplots(figsize=(6, 4))
for method in ["dopri5", "dop853"]:
    pts = []
    for rtol in [1e-4, 1e-6, 1e-8, 1e-10, 1e-12]:
        r = ode.solve(kep.fun, kep.t_span, kep.y0, method=method, rtol=rtol, atol=1e-3 * rtol)
        pts.append((r.nfev, kep.final_error(r.y[:, -1])))
    ax.loglog(*zip(*pts, strict=True), "o-", label=method)
for method, f in [("yoshida6", kep.acceleration), ("abm5", kep.fun)]:
    pts = []
    for n in [1000, 2000, 4000, 8000]:
        r = ode.solve(f, kep.t_span, kep.y0, method=method, step=kep.t_span[1] / n)
        pts.append((r.nfev, kep.final_error(r.y[:, -1])))
    ax.loglog(*zip(*pts, strict=True), "s--", label=method)
ax.set_xlabel("evaluations of f")
ax.set_ylabel("final error")
ax.set_title("Kepler e = 0.6, 10 orbits")
ax.legend()
plt.show()
