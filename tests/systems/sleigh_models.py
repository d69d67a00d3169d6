"""The Chaplygin sleigh shared by the tests: a body moving on a horizontal plane, its blade
at the point P = G - a i1 along its axis i1 (G the mass centre), from the catalogue
:mod:`rigidmech.models` and, independently, with sympy.physics.mechanics (the Kane route is
never built from the catalogue)."""

import sympy as sp
import sympy.physics.mechanics as me

from rigidmech import models


def sleigh(a=None, *, gravity=True):
    """Coordinates (x, y) of G and heading theta; a uniform disc of mass m and radius r in
    the plane; the blade at a distance a behind G (:func:`rigidmech.models.sleigh`). Returns
    ``(system, (x, y, theta), (m, r, g, a), knife)``."""
    m = models.sleigh(a, gravity=gravity)
    return m.system, m.coordinates, m.constants, m.connections[0]


def sleigh_kane():
    """The same sleigh with KanesMethod: u_i = q_i' for (x, y, theta), the speed of y
    dependent, the lateral condition as the velocity constraint."""
    kane, q, u, (m, r, g, a, _) = _kane_sleigh(0, 0)
    return kane, q, u, (m, r, g, a)


def sleigh_on_incline(beta):
    """The sleigh on a plane inclined by beta about R0.i, the blade a behind G and b to its
    left (:func:`rigidmech.models.sleigh_on_incline`). Returns ``(system, (x, y, theta),
    (m, r, g, a, b))``."""
    m = models.sleigh_on_incline(beta)
    return m.system, m.coordinates, m.constants


def sleigh_on_incline_kane(beta):
    """The same with KanesMethod (u = q', the speed of y dependent)."""
    return _kane_sleigh(beta, sp.Symbol("b", real=True))


def _kane_sleigh(beta, b):
    """The sleigh with KanesMethod on a plane inclined by beta about N.x, the blade a behind
    G and b to its left; returns (kane, q, u, (m, r, g, a, b))."""
    q = me.dynamicsymbols("x y theta")
    u = me.dynamicsymbols("ux uy utheta")
    x, y, th = q
    m, r, g = sp.symbols("m r g", positive=True)
    a = sp.Symbol("a", real=True)
    N = me.ReferenceFrame("N")
    Ni = N.orientnew("Ni", "Axis", (beta, N.x))
    B = Ni.orientnew("B", "Axis", (th, Ni.z))
    B.set_ang_vel(N, u[2] * Ni.z)
    O = me.Point("O")
    O.set_vel(N, 0)
    G = O.locatenew("G", x * Ni.x + y * Ni.y)
    G.set_vel(N, u[0] * Ni.x + u[1] * Ni.y)
    P = G.locatenew("P", -a * B.x + b * B.y)
    P.v2pt_theory(G, N, B)
    inertia = me.inertia(B, m * r**2 / 4, m * r**2 / 4, m * r**2 / 2)
    body = me.RigidBody("sleigh", G, B, m, (inertia, G))
    kane = me.KanesMethod(N, q_ind=list(q), u_ind=[u[0], u[2]], u_dependent=[u[1]],
                          kd_eqs=[qi.diff() - ui for qi, ui in zip(q, u, strict=True)],
                          velocity_constraints=[P.vel(N).dot(B.y)])
    kane.kanes_equations([body], [(G, -m * g * N.z)])
    return kane, q, u, (m, r, g, a, b)


def sleigh_on_turntable():
    """The sleigh on a turntable pivoted about R0.k by phi
    (:func:`rigidmech.models.sleigh_on_turntable`). Returns ``(system, (phi, x, y, theta),
    (m, r, M, R, a))``."""
    m = models.sleigh_on_turntable()
    return m.system, m.coordinates, m.constants


def sleigh_on_turntable_kane():
    """The same with KanesMethod: u = q' for (phi, x, y, theta), the speed of y dependent."""
    q = me.dynamicsymbols("phi x y theta")
    u = me.dynamicsymbols("uphi ux uy utheta")
    phi, x, y, th = q
    m, r, M, R = sp.symbols("m r M R", positive=True)
    a = sp.Symbol("a", real=True)
    kd = {qi.diff(): ui for qi, ui in zip(q, u, strict=True)}
    N = me.ReferenceFrame("N")
    T = N.orientnew("T", "Axis", (phi, N.z))
    T.set_ang_vel(N, u[0] * N.z)
    B = T.orientnew("B", "Axis", (th, T.z))
    B.set_ang_vel(T, u[3] * T.z)
    O = me.Point("O")
    O.set_vel(N, 0)
    G = O.locatenew("G", x * T.x + y * T.y)
    G.set_vel(N, G.pos_from(O).dt(N).subs(kd))
    # v(P in B/T) = v(G/T) + omega(B/T) ^ GP
    vP_T = G.pos_from(O).dt(T).subs(kd) + (u[3] * T.z).cross(-a * B.x)
    table = me.RigidBody("table", O, T, M, (me.inertia(T, M * R**2 / 4, M * R**2 / 4,
                                                      M * R**2 / 2), O))
    sleigh = me.RigidBody("sleigh", G, B, m, (me.inertia(B, m * r**2 / 4, m * r**2 / 4,
                                                        m * r**2 / 2), G))
    kane = me.KanesMethod(N, q_ind=list(q), u_ind=[u[0], u[1], u[3]], u_dependent=[u[2]],
                          kd_eqs=[qi.diff() - ui for qi, ui in zip(q, u, strict=True)],
                          velocity_constraints=[vP_T.dot(B.y)])
    kane.kanes_equations([table, sleigh], [])
    return kane, q, u, (m, r, M, R, a)
