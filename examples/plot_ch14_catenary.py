"""
A heavy cable between two supports: the catenary (ch. 14.3.3)
=============================================================

A cable of weight w per unit length hangs between two supports A and B at different heights.
Its equilibrium (ch. 14.3.2) gives the catenary :math:`y = a\\cosh((x - x_0)/a) + c` with
:math:`a = H/w`, H the horizontal component of the tension, constant along the cable; the
tension is :math:`T = H\\cosh((x - x_0)/a) = H + w\\,(y - y_0)`, largest at the higher
support. We build the same cable twice: from its horizontal tension, and from its length
(the transcendental length equation is solved by bracketing and Brent's method), then
compare the catenary with the parabola of a load uniform along the horizontal.
"""

# %%
# From the horizontal tension, then from the length
# --------------------------------------------------
import matplotlib.pyplot as plt
import numpy as np

from rigidmech.statics import Catenary, ParabolicCable

span, height, w = 100.0, 20.0, 15.0            # m, m, N/m
cable = Catenary(span=span, weight_per_length=w, horizontal_tension=1500.0, height=height)
again = Catenary(span=span, weight_per_length=w, length=cable.length, height=height)
print(f"length S = {cable.length:.9f} m, sag below the chord = {cable.sag:.6f} m")
print(f"H from the length: {again.horizontal_tension:.9f} N (asked 1500)")
TA, TB = cable.support_tensions
VA, VB = cable.support_vertical_forces
print(f"T_A = {TA:.3f} N, T_B = {TB:.3f} N, T_B - T_A = {TB - TA:.6f} = w h = {w * height}")
print(f"V_A + V_B = {VA + VB:.6f} N = w S = {w * cable.length:.6f} N")

# %%
# The shape and the tension along the cable
# -----------------------------------------
# The shape is also a :class:`~rigidmech.vectors.Curve`: its curvature at the lowest point
# is 1/a = w/H.
x = np.linspace(0, span, 400)
para = ParabolicCable(span=span, load_per_horizontal_length=w * cable.length / span,
                      sag=cable.sag, height=height)
fig, (ax1, ax2) = plt.subplots(2, 1, figsize=(7, 6), sharex=True)
ax1.plot(x, cable.y(x), label="catenary")
ax1.plot(x, para.y(x), "--", label="parabola, same sag")
ax1.plot([0, span], [0, height], ":", color="0.5", label="chord AB")
x0, y0 = cable.lowest_point
ax1.plot([x0], [y0], "o", color="C0")
ax1.set_ylabel("y (m)")
ax1.set_aspect("equal", adjustable="datalim")
ax1.legend()
ax2.plot(x, cable.tension(x), label="tension T(x)")
ax2.axhline(cable.horizontal_tension, color="0.5", linestyle=":", label="H")
ax2.plot([0, span], [TA, TB], "o", color="C3", label="support tensions")
ax2.set_xlabel("x (m)")
ax2.set_ylabel("T (N)")
ax2.legend()
curve = cable.shape()
print("curvature at the vertex:", float(curve.curvature(at=x0)), "= w/H =", w / 1500.0)
plt.tight_layout()
plt.show()
