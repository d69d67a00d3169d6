"""
A solid placed on a wagon (ch. 24.2)
====================================

A block of mass :math:`m` rests on the horizontal floor of a wagon. The wagon starts on a
straight track with an acceleration that grows linearly, :math:`a(t) = \\alpha t`. The
contact block/wagon follows Coulomb's laws (ch. 13.1.2) with a coefficient of static friction
:math:`f_s` and a coefficient of kinetic friction :math:`f_k`.

The book writes the equations of dynamics in the reference attached to the wagon (ch. 24.2.5):
there the block is subjected to gravity, to the action of the floor :math:`(T, N)`, and to the
inertial force of entrainment :math:`-m\\,a(t)`. Along the track, with :math:`x_r` the position
of the block relative to the wagon,

.. math:: m \\ddot x_r = -m\\, a(t) + T, \\qquad N = m g.

While the block does not slide, :math:`T = m a` and the law of adherence
:math:`|T| \\le f_s N` holds up to :math:`t_s = f_s g / \\alpha`; then the block slides
backwards (:math:`\\dot x_r < 0`) and :math:`T = + f_k m g`.
"""

# %%
# The motion, regime by regime
# ----------------------------
# :func:`rigidmech.regimes.block_on_wagon` integrates the relative motion phase after phase and
# finds the instant where the law of adherence stops holding.
import matplotlib.pyplot as plt
import numpy as np

import rigidmech as rm

alpha, g = 2.0, 9.81            # m/s^3, m/s^2
fs, fk = 0.3, 0.2
motion = rm.regimes.block_on_wagon(acceleration=lambda t: alpha * t,
                                   friction=rm.Coulomb(fs, fk), g=g, t_end=3.0)
print(motion.table())

# %%
# Check: the instant of sliding and the relative motion in closed form
# --------------------------------------------------------------------
# Sliding starts when :math:`\alpha t = f_s g`. Afterwards
# :math:`\ddot x_r = -\alpha t + f_k g`, integrated from rest at :math:`t_s`:
#
# .. math:: \dot x_r = -\frac{\alpha}{2}(t^2 - t_s^2) + f_k g (t - t_s), \qquad
#           x_r = -\frac{\alpha}{6}(t - t_s)^2 (t + 2 t_s) + \frac{f_k g}{2} (t - t_s)^2.
ts = fs * g / alpha
assert motion.regimes == ("stick", "slide-")
assert abs(motion.switch_times[0] - ts) < 1e-9


def x_closed(t):
    tau = np.clip(t - ts, 0.0, None)
    return -alpha / 6 * tau**2 * (tau + 3 * ts) + fk * g / 2 * tau**2


def v_closed(t):
    tau = np.clip(t - ts, 0.0, None)
    return -alpha / 2 * tau * (tau + 2 * ts) + fk * g * tau


x_end, v_end = motion.phases[-1].y_end
print(f"t_s = {ts:.4f} s; at t = 3 s: x_r = {x_end:.6f} m (closed form {x_closed(3.0):.6f}),"
      f" x_r' = {v_end:.6f} m/s (closed form {v_closed(3.0):.6f})")
assert abs(x_end - x_closed(3.0)) < 1e-8 and abs(v_end - v_closed(3.0)) < 1e-8

# %%
# The relative position of the block
# ----------------------------------
fig, ax = plt.subplots(figsize=(7, 4), constrained_layout=True)
motion.plot(ax, component=0, label="rigidmech (phases)")
tt = np.linspace(0, 3, 200)
ax.plot(tt, x_closed(tt), "k:", lw=2, label="closed form")
ax.axvline(ts, color="tab:gray", ls="--", lw=1)
ax.text(ts, -0.5, r"  $t_s = f_s g / \alpha$", color="tab:gray")
ax.set(xlabel="time t (s)", ylabel="relative position $x_r$ (m)",
       title="Block on an accelerating wagon: stick, then slide backwards")
ax.legend()
plt.show()
