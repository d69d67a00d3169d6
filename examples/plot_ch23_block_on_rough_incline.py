"""
A block on a rough incline: limiting equilibrium and regimes (ch. 13.1, 14.4, 23)
=================================================================================

A block of mass m rests on a plane inclined by :math:`\\alpha` to the horizontal; the contact
obeys Coulomb's laws with the static coefficient :math:`f_s` and the kinetic one
:math:`f_k \\le f_s` (ch. 13.1.2). Axes attached to the incline: x down the slope, y along the
outward normal; gravity :math:`\\mathbf{g} = g(\\sin\\alpha\\,\\mathbf{i} -
\\cos\\alpha\\,\\mathbf{j})`, the normal action :math:`N = m g \\cos\\alpha`.

* **At rest** the tangential action :math:`T = m g \\sin\\alpha` must lie in the friction cone,
  :math:`|T| \\le f_s N`: the block stays at rest up to :math:`\\tan\\alpha = f_s`, the
  half-angle of the cone :math:`\\varphi_s = \\arctan f_s` (ch. 13.1.2, 14.4).
* **Sliding**, the friction :math:`\\mp f_k N` opposes the sliding velocity: the block
  accelerates down the slope at :math:`\\ddot x = g(\\sin\\alpha - f_k\\cos\\alpha)` while it
  slides down, at :math:`\\ddot x = g(\\sin\\alpha + f_k\\cos\\alpha)` while it slides up
  (ch. 23). When the sliding velocity vanishes it sticks if :math:`\\tan\\alpha \\le f_s`,
  else it slides down.

Without friction this is the catalogue's :func:`rigidmech.models.block_on_incline`
(:math:`\\ddot x = g \\sin\\alpha`), the ``block-on-incline`` scene.
"""

# %%
# Limiting equilibrium: statics
# -----------------------------
# :func:`rigidmech.statics.limiting_equilibrium` scans the angle and finds where the
# equilibrium breaks (the linear programme of the contact laws loses its solution).
import math

import matplotlib.pyplot as plt
import sympy as sp

import rigidmech as rm
from rigidmech import models
from rigidmech.actions import ContactLaws, Coulomb, FrictionContact
from rigidmech.kinematics import ContactKinematics
from rigidmech.regimes import contact_motion
from rigidmech.statics import Statics, limiting_equilibrium

law = Coulomb(static=0.4, kinetic=0.3)
f_s, f_k, g = float(law.static), float(law.kinetic), 9.81

alpha = sp.Symbol("alpha", real=True)
R0 = rm.Frame("R0")
R1 = R0.rotated("R1", about=R0.k, angle=alpha)          # the incline's frame
block = rm.Body("block", frame=R1, mass=1.0, centre=R1.origin)
st = Statics(R0)
st.connect(R0, block, ContactLaws(at=R1.origin, normal=R1.j, tangent=R1.i, friction=law),
           label="I")
st.act(rm.gravity(-g * R0.j))
lim = limiting_equilibrium(st, alpha, (0.0, 1.2))
print(f"equilibrium breaks at alpha = {math.degrees(lim.value):.6f} deg by {lim.kinds}; "
      f"arctan f_s = {math.degrees(math.atan(f_s)):.6f} deg")
assert math.isclose(lim.value, math.atan(f_s), rel_tol=1e-8)
assert lim.kinds == ("sliding",)


# %%
# The block and its contact, for the motion
# -----------------------------------------
# The block translates: its centre G = (x, y) in the incline's axes; a
# :class:`~rigidmech.actions.FrictionContact` at I = G with the normal j;
# :func:`rigidmech.regimes.contact_motion` derives each regime (stick, slip+, slip-) itself
# and switches where the sliding velocity vanishes.
def rough_incline(angle):
    x, y = rm.coordinates("x y")
    R0 = rm.Frame("R0")
    G = R0.point("G", x, y, 0)
    Rb = R0.translated("Rb", G)                         # the block's frame
    s = rm.System(galilean=R0)
    s.connect(R0, rm.Body("block", frame=Rb, mass=1.0, centre=G),
              FrictionContact(ContactKinematics(Rb, R0, at=R0.point("I", x, y, 0),
                                                normal=R0.j), friction=law))
    s.act(rm.gravity(g * (math.sin(angle) * R0.i - math.cos(angle) * R0.j)))
    return s


def down(angle):                                        # x'' sliding down (x' > 0)
    return g * (math.sin(angle) - f_k * math.cos(angle))


def up(angle):                                          # x'' sliding up (x' < 0)
    return g * (math.sin(angle) + f_k * math.cos(angle))


# %%
# Three launches
# --------------
# On a gentle slope (15 deg, below the cone's 21.8 deg) the block pushed down the slope at
# 1 m/s slows down (tan alpha < f_k) and sticks; pushed up it slows down faster and sticks.
# On a steep slope (30 deg) pushed up, it stops and slides back down.
v0, t_end = 1.0, 5.0
cases = [(math.radians(15), v0, ("slip+", "stick")),
         (math.radians(15), -v0, ("slip-", "stick")),
         (math.radians(30), -v0, ("slip-", "slip+"))]
motions = []
for angle, u, expected in cases:
    motion = contact_motion(rough_incline(angle), t_end, {"x": 0.0, "y": 0.0},
                            {"x": u, "y": 0.0}, rtol=1e-12)
    print(f"alpha = {math.degrees(angle):.0f} deg, x'(0) = {u:+.0f} m/s:", motion.regimes,
          "switch at", [round(t, 9) for t in motion.switch_times])
    assert motion.regimes == expected
    # the first phase: the closed-form deceleration, the stop at v0 / |a|
    a1 = down(angle) if u > 0 else up(angle)
    t_stop = -u / a1
    assert math.isclose(motion.switch_times[0], t_stop, rel_tol=1e-9)
    assert abs(motion.accelerations(0.5 * t_stop)[0] - a1) < 1e-9
    after = motion.accelerations(t_stop + 0.1)[0]
    if expected[1] == "stick":
        assert abs(after) < 1e-12 and abs(motion(t_end - 0.1)[2]) < 1e-9      # at rest
    else:
        assert abs(after - down(angle)) < 1e-9
    motions.append(motion)

# without friction the rough model's acceleration is the catalogue's block_on_incline's
frictionless = models.block_on_incline().system.equations_of_motion()
m_, g_, alpha_ = models.block_on_incline().constants
a0 = (frictionless.forcing[0] / frictionless.mass_matrix[0, 0]).subs(g_, g)
assert math.isclose(float(a0.subs(alpha_, 0.5)), g * math.sin(0.5), rel_tol=1e-15)

# %%
# Position and velocity along the slope, phase by phase
# -----------------------------------------------------
# :meth:`~rigidmech.regimes.PhasedMotion.plot`: one panel per component, each phase in its
# regime's colour, the switching instants dotted.
fig, axes = plt.subplots(2, 3, figsize=(10, 5.5), sharex=True, layout="constrained")
titles = ["15 deg, pushed down", "15 deg, pushed up", "30 deg, pushed up"]
for column, (motion, title) in enumerate(zip(motions, titles, strict=True)):
    motion.plot(axes[:, column], components=["x", "x'"], names=["x", "y", "x'", "y'"],
                units={"x": "m", "x'": "m/s"})
    axes[0, column].set_title(title, fontsize=9, loc="left")
plt.show()
