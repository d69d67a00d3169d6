"""Rolling models shared by the tests: a wheel on an incline (planar) and a disc rolling on a
plane (3D), built with rigidmech and with sympy.physics.mechanics."""

import sympy as sp
import sympy.physics.mechanics as me

import rigidmech as rm
from rigidmech.dynamics import System
from rigidmech.kinematics import Circle, ContactKinematics
from rigidmech.kinematics.surfaces import Plane


def wheel_on_incline(alpha, inertia="disk"):
    """A wheel of radius r on the line through O along Ri.i, inclined by -alpha: x along the
    slope (downwards positive), theta its rotation."""
    x, th = rm.coordinates("x theta")
    m, g, r = rm.constants("m g r", positive=True)
    R0 = rm.Frame("R0")
    Ri = R0.rotated("Ri", about=R0.k, angle=-alpha)
    C = R0.origin.moved("C", x * Ri.i + r * Ri.j)
    R1 = Ri.rotated("R1", about=R0.k, angle=th, origin=C)
    J = getattr(rm.inertia, inertia)(m, r, axis=R1.k, centre=C)
    wheel = rm.Body("wheel", frame=R1, mass=m, centre=C, inertia=J)
    contact = ContactKinematics.between(R1, Circle(C, r, normal=R0.k), R0, rm.Line(R0.origin, Ri.i))
    s = System(galilean=R0)
    s.connect(R0, wheel, rm.actions.RollingContact(contact))
    s.act(rm.gravity(-g * R0.j))
    return s, (x, th), (m, g, r)


def rolling_disc():
    """Disc of radius r: contact point (x, y), heading psi, lean theta, spin phi."""
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
    contact = ContactKinematics.between(D, Circle(G, r, normal=D.k), R0, Plane(R0.origin, R0.k))
    s = System(galilean=R0)
    s.connect(R0, disc, rm.actions.RollingContact(contact))
    s.act(rm.gravity(-g * R0.k))
    return s, (x, y, psi, th, phi), (m, g, r)


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
