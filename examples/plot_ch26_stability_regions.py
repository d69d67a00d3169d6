"""
Stability regions of the Runge-Kutta methods (ch. 26.1.3, 26.2.2)
=================================================================

The methods of chapter 26 advance the solution of :math:`y' = f(t, y)` by one step
:math:`h` from :math:`y_n` to :math:`y_{n+1}`. Applied to the test equation
:math:`y' = \\lambda y`, a single-step method of Runge-Kutta type gives
:math:`y_{n+1} = R(z)\\, y_n` with :math:`z = h\\lambda`: the **stability function**
:math:`R` is read from the method's Butcher tableau :math:`(A, b, c)`,

.. math:: R(z) = 1 + z\\, b^T (I - zA)^{-1} \\mathbb{1}.

The numerical solution stays bounded when :math:`|R(z)| \\le 1`: this set of the complex plane
is the method's **region of absolute stability**. We draw it for Euler's method, the
midpoint and Heun methods (order 2), the classical Runge-Kutta method (order 4) and
Dormand-Prince 5, from the tableaux that :mod:`rigidmech.ode.tableaux` exposes.
"""

# %%
# The stability function from the tableau
# ---------------------------------------
# ``(I - zA)^{-1} 1`` is the vector of the stages; for an explicit method ``A`` is strictly lower
# triangular, so ``R`` is a polynomial of degree at most the number of stages.
# :func:`rigidmech.ode.stability.stability_function` evaluates it for an array of complex ``z``.
import math

import matplotlib.pyplot as plt
import numpy as np

from rigidmech import ode
from rigidmech.ode import tableaux
from rigidmech.ode.stability import real_stability_interval, stability_function

methods = [tableaux.EULER, tableaux.MIDPOINT, tableaux.HEUN, tableaux.RK4, tableaux.DOPRI5]
for tab in methods:
    print(f"{tab.name:8s} stages={tab.stages} order={tab.order}")

# %%
# Check: a method of order p with p = s stages has R(z) = 1 + z + ... + z^p/p!
# -----------------------------------------------------------------------------
# Euler gives ``1 + z``, the two order-2 methods ``1 + z + z^2/2`` and the classical method
# the Taylor polynomial of :math:`e^z` of degree 4 (ch. 26.2.2).
zs = np.array([-2.5, -1.0 + 1.0j, 0.3 - 2.0j, 1.5j])
for tab in (tableaux.EULER, tableaux.MIDPOINT, tableaux.HEUN, tableaux.RK4):
    taylor = sum(zs**k / math.factorial(k) for k in range(tab.order + 1))
    assert np.allclose(stability_function(tab, zs), taylor, rtol=0, atol=1e-13), tab.name

# %%
# Check: one step of the solver is one multiplication by R(h lambda)
# ------------------------------------------------------------------
# An independent route: the fixed-step solvers of :mod:`rigidmech.ode` applied to
# :math:`y' = \lambda y` for a single step return :math:`R(h\lambda)\, y_0`.
lam, h = -2.5, 1.0
for name, tab in (("euler", tableaux.EULER), ("midpoint", tableaux.MIDPOINT),
                  ("heun", tableaux.HEUN), ("rk4", tableaux.RK4)):
    sol = ode.solve(lambda t, y: lam * y, (0.0, h), np.array([1.0]), method=name, step=h)
    y1 = float(np.asarray(sol.y)[..., -1].ravel()[0])
    R = stability_function(tab, np.array([lam * h]))[0].real
    print(f"{name:8s} one step: {y1:+.6f}   R(h lambda) = {R:+.6f}")
    assert abs(y1 - R) < 1e-12, name

# %%
# Stability intervals on the negative real axis
# ---------------------------------------------
# Euler's method is stable for :math:`-2 \le h\lambda \le 0`, the order-2 methods also up to
# -2, the classical Runge-Kutta method up to about -2.785, Dormand-Prince 5 up to about -3.307:
# :func:`~rigidmech.ode.stability.real_stability_interval` scans the axis and bisects on
# :math:`|R| = 1`.
for tab, expected in ((tableaux.EULER, -2.0), (tableaux.HEUN, -2.0), (tableaux.RK4, -2.7853),
                      (tableaux.DOPRI5, -3.3066)):
    x_min, _ = real_stability_interval(tab)
    print(f"{tab.name:8s} stable on [{x_min:.4f}, 0]")
    assert abs(x_min - expected) < 1e-3, tab.name

# %%
# The regions of absolute stability
# ----------------------------------
# Where :math:`|R(z)| \le 1`, shaded, for each method.
re, im = np.meshgrid(np.linspace(-5, 1.5, 261), np.linspace(-4, 4, 321))
fig, ax = plt.subplots(figsize=(7, 6), constrained_layout=True)
colors = ["tab:blue", "tab:orange", "tab:green", "tab:red", "tab:purple"]
for tab, color in zip(methods, colors, strict=True):
    modulus = np.abs(stability_function(tab, re + 1j * im))
    ax.contourf(re, im, modulus, levels=[0, 1], colors=[color], alpha=0.12)
    ax.contour(re, im, modulus, levels=[1], colors=[color], linewidths=1.6)
    same = " = heun's region" if tab.name == "midpoint" else ""   # same R(z) = 1 + z + z^2/2
    ax.plot([], [], color=color, label=f"{tab.name} (order {tab.order}){same}")
ax.axhline(0, color="k", lw=0.6)
ax.axvline(0, color="k", lw=0.6)
ax.set(xlabel=r"Re$(h\lambda)$", ylabel=r"Im$(h\lambda)$", aspect="equal",
       title=r"Regions of absolute stability $|R(h\lambda)| \leq 1$")
ax.legend(loc="upper left")
plt.show()
