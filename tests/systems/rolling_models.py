"""Rolling models shared by the tests: a wheel on an incline (planar) and a disc rolling on a
plane (3D), from the catalogue :mod:`rigidmech.models` and, independently, with
sympy.physics.mechanics (the Kane route is never built from the catalogue)."""

import sympy as sp
import sympy.physics.mechanics as me

from rigidmech import models


def wheel_on_incline(alpha, inertia="disk"):
    """A wheel of radius r on the line through O along Ri.i, inclined by -alpha: x along the
    slope (downwards positive), theta its rotation (:func:`rigidmech.models.wheel_on_incline`).
    Returns ``(system, (x, theta), (m, g, r))``."""
    m = models.wheel_on_incline(alpha, inertia)
    return m.system, m.coordinates, m.constants


def rolling_disc():
    """Disc of radius r: contact point (x, y), heading psi, lean theta, spin phi, the contact
    found from the rim and the plane (:func:`rigidmech.models.rolling_disc`). Returns
    ``(system, (x, y, psi, theta, phi), (m, g, r))``."""
    m = models.rolling_disc("between")
    return m.system, m.coordinates, m.constants


def rolling_disc_kane():
    """The same disc with sympy.physics.mechanics.KanesMethod: u_i = q_i', the speeds of x
    and y dependent, the no-slip conditions as velocity constraints."""
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
    P = G.locatenew("P", -r * B.y)        # the point of the disc in contact
    P.v2pt_theory(G, N, D)
    vP = P.vel(N)
    constraints = [vP.dot(N.x), vP.dot(N.y)]
    I = me.inertia(D, m * r**2 / 4, m * r**2 / 4, m * r**2 / 2)
    body = me.RigidBody("disc", G, D, m, (I, G))
    kane = me.KanesMethod(N, q_ind=list(q), u_ind=u[2:], u_dependent=u[:2],
                          kd_eqs=[qi.diff() - ui for qi, ui in zip(q, u, strict=True)],
                          velocity_constraints=constraints)
    kane.kanes_equations([body], [(G, -m * g * N.z)])
    return kane, q, u, (m, g, r)
