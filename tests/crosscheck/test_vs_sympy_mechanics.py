"""Cross-check of the equations of motion against sympy.physics.mechanics (issue 9).

Each model is built twice, independently: in rigidmech's API (frames, bodies, joints, actions;
the fundamental principle of :meth:`System.equations_of_motion`) and in
sympy.physics.mechanics (``KanesMethod`` with the kinematic differential equations u = q', so
that Kane's speeds are the coordinates' derivatives, or ``LagrangesMethod``). q'' is compared
at random states (q, q') and random parameter values, by solving M q'' = f numerically on both
sides (helpers in ``_sympy_crosscheck``), to a relative tolerance of 1e-10 of the largest |q''|.

Why 1e-10: both sides evaluate closed-form expressions of the same mechanics in double
precision; the states are drawn away from the singular configurations of the
parametrisations, where the mass matrices have condition numbers below about 1e3, so the two
solutions of M q'' = f agree to about 1e-13 and 1e-10 leaves a wide margin while any modelling
or sign error (of the order of a whole term) is far above it.

Conventions of sympy.physics.mechanics used below: ``inertia(frame, ixx, iyy, izz, ixy, iyz,
izx)`` takes the entries of the inertia tensor, whose off-diagonal entries are minus the
products of inertia; rigidmech's ``from_products(A, B, C, D, E, F)`` takes the book's products
D = int yz dm, E = int zx dm, F = int xy dm (ch. 15.1.3), hence ``ixy=-F, iyz=-D, izx=-E``.
``orientnew(..., "Body", [psi, theta, phi], "313")`` is the z-x-z sequence of body-fixed
rotations, the book's Euler angles (ch. 9.1.2) as made by :meth:`Frame.euler`.
"""

import numpy as np
import pytest
import sympy as sp
from _sympy_crosscheck import (
    assert_same_accelerations,
    random_states,
    sympy_accelerations,
)
from sympy.physics import mechanics as me
from sympy.physics.mechanics import models

import rigidmech as rm
from rigidmech.inertia import InertiaOperator

#: relative tolerance on q'' (see the module docstring)
RTOL = 1e-10
#: random states per model
N_STATES = 6

# ranges of the random values: moments of inertia in [1, 2] satisfy the triangle inequalities
# (2 <= 1 + 1) and with products in [-0.2, 0.2] the matrix is positive definite (Gershgorin)
_MOMENTS = (1.0, 2.0)
_PRODUCTS = (-0.2, 0.2)
_POSITIVE = (0.5, 2.0)
_ANGLE = (-np.pi, np.pi)
_NUTATION = (0.3, np.pi - 0.3)  # away from sin(theta) = 0, the singular set of z-x-z


def _kane(frame, coordinates, speeds, bodies, loads):
    kd = [q.diff() - u for q, u in zip(coordinates, speeds, strict=True)]
    kane = me.KanesMethod(frame, q_ind=coordinates, u_ind=speeds, kd_eqs=kd)
    kane.kanes_equations(bodies, loads)
    return sympy_accelerations(kane.mass_matrix, kane.forcing, coordinates, speeds)


def _general_inertia_rm(frame, at):
    A, B, C, D, E, F = rm.constants("A B C D E F")
    return InertiaOperator.from_products(A, B, C, D, E, F, frame=frame, at=at)


def _general_inertia_sympy(frame):
    A, B, C, D, E, F = sp.symbols("A B C D E F")
    return me.inertia(frame, A, B, C, ixy=-F, iyz=-D, izx=-E)


_INERTIA_RANGES = {"A": _MOMENTS, "B": _MOMENTS, "C": _MOMENTS,
                   "D": _PRODUCTS, "E": _PRODUCTS, "F": _PRODUCTS}


# -- 1. heavy top ------------------------------------------------------------------------------
def heavy_top_rigidmech():
    psi, theta, phi = rm.coordinates("psi theta phi")
    m, g, a, b, c = rm.constants("m g a b c")
    R0 = rm.Frame("R0")
    R = R0.euler("R", psi, theta, phi)
    O = R0.origin
    G = O.moved("G", a * R.i + b * R.j + c * R.k)
    top = rm.Body("top", frame=R, mass=m, centre=G, inertia=_general_inertia_rm(R, G))
    system = rm.System(galilean=R0)
    system.connect(R0, top, rm.joints.Spherical(at=O))
    system.act(rm.gravity(-g * R0.k))
    return system.equations_of_motion()


def heavy_top_sympy():
    psi, theta, phi = q = me.dynamicsymbols("psi theta phi")
    u = me.dynamicsymbols("u1:4")
    m, g, a, b, c = sp.symbols("m g a b c")
    N = me.ReferenceFrame("N")
    B = N.orientnew("B", "Body", [psi, theta, phi], "313")
    O = me.Point("O")
    O.set_vel(N, 0)
    G = O.locatenew("G", a * B.x + b * B.y + c * B.z)
    G.v2pt_theory(O, N, B)
    body = me.RigidBody("top", G, B, m, (_general_inertia_sympy(B), G))
    return _kane(N, list(q), u, [body], [(G, -m * g * N.z)])


def test_heavy_top_with_products_of_inertia():
    """Heavy top about a fixed point (spherical joint), Euler angles z-x-z (ch. 9.1.2,
    ch. 23): an asymmetric body with all six inertia constants (three moments, three
    products, book's sign convention) and its mass centre off every axis of the body.
    Checks the rotation vector of an Euler chain, the dynamic moment d/dt J_G(omega) with a
    full operator, the transport of moments to the fixed point and gravity's power."""
    eqs = heavy_top_rigidmech()
    states = random_states(
        np.random.default_rng(1), {"psi": _ANGLE, "theta": _NUTATION, "phi": _ANGLE},
        {"m": _POSITIVE, "g": _POSITIVE, "a": _PRODUCTS, "b": _PRODUCTS, "c": _POSITIVE,
         **_INERTIA_RANGES}, N_STATES)
    assert_same_accelerations(eqs, heavy_top_sympy(), states=states, rtol=RTOL)


# -- 2. free rigid body --------------------------------------------------------------------------
def free_body_rigidmech():
    x, y, z, psi, theta, phi = rm.coordinates("x y z psi theta phi")
    m, g = rm.constants("m g")
    R0 = rm.Frame("R0")
    G = R0.point("G", x, y, z)
    R = R0.euler("R", psi, theta, phi, origin=G)
    body = rm.Body("body", frame=R, mass=m, centre=G, inertia=_general_inertia_rm(R, G))
    system = rm.System(galilean=R0)
    system.add(body)
    system.act(rm.gravity(-g * R0.k))
    return system.equations_of_motion()


def free_body_sympy():
    q = me.dynamicsymbols("x y z psi theta phi")
    x, y, z, psi, theta, phi = q
    u = me.dynamicsymbols("u1:7")
    m, g = sp.symbols("m g")
    N = me.ReferenceFrame("N")
    B = N.orientnew("B", "Body", [psi, theta, phi], "313")
    O = me.Point("O")
    O.set_vel(N, 0)
    G = O.locatenew("G", x * N.x + y * N.y + z * N.z)
    G.set_vel(N, G.pos_from(O).dt(N))
    body = me.RigidBody("body", G, B, m, (_general_inertia_sympy(B), G))
    return _kane(N, list(q), u, [body], [(G, -m * g * N.z)])


def test_free_rigid_body():
    """Free body (six parameters of situation: mass centre x, y, z and Euler angles z-x-z)
    under gravity, with a full operator of inertia (ch. 18.4). Checks a body added without
    connection, the mass centre as the origin of the Euler chain, and that the coordinate
    order rigidmech chooses is matched by name (q'' compared coordinate by coordinate)."""
    eqs = free_body_rigidmech()
    states = random_states(
        np.random.default_rng(2),
        {"x": (-1, 1), "y": (-1, 1), "z": (-1, 1), "psi": _ANGLE, "theta": _NUTATION,
         "phi": _ANGLE},
        {"m": _POSITIVE, "g": _POSITIVE, **_INERTIA_RANGES}, N_STATES)
    assert_same_accelerations(eqs, free_body_sympy(), states=states, rtol=RTOL)


# -- 3. spherical double pendulum --------------------------------------------------------------
def spherical_double_pendulum_rigidmech():
    a1, b1, a2, b2 = rm.coordinates("a1 b1 a2 b2")
    m1, m2, L1, L2, g = rm.constants("m1 m2 L1 L2 g")
    R0 = rm.Frame("R0")
    R1 = R0.rotated("R1a", about=R0.k, angle=a1)
    R1 = R1.rotated("R1", about=R1.i, angle=b1)
    R2 = R0.rotated("R2a", about=R0.k, angle=a2)
    R2 = R2.rotated("R2", about=R2.i, angle=b2)
    O = R0.origin
    A = O.moved("A", L1 * R1.k)
    G1 = O.moved("G1", L1 / 2 * R1.k)
    G2 = A.moved("G2", L2 / 2 * R2.k)
    bar1 = rm.Body("bar1", frame=R1, mass=m1, centre=G1,
                   inertia=rm.inertia.rod(m1, L1, axis=R1.k, centre=G1))
    bar2 = rm.Body("bar2", frame=R2, mass=m2, centre=G2,
                   inertia=rm.inertia.rod(m2, L2, axis=R2.k, centre=G2))
    system = rm.System(galilean=R0)
    system.connect(R0, bar1, rm.joints.Spherical(at=O))
    system.connect(bar1, bar2, rm.joints.Spherical(at=A))
    system.act(rm.gravity(-g * R0.k))
    return system.equations_of_motion()


def spherical_double_pendulum_sympy():
    q = me.dynamicsymbols("a1 b1 a2 b2")
    a1, b1, a2, b2 = q
    u = me.dynamicsymbols("u1:5")
    m1, m2, L1, L2, g = sp.symbols("m1 m2 L1 L2 g")
    N = me.ReferenceFrame("N")
    B1 = N.orientnew("B1a", "Axis", [a1, N.z])
    B1 = B1.orientnew("B1", "Axis", [b1, B1.x])
    B2 = N.orientnew("B2a", "Axis", [a2, N.z])
    B2 = B2.orientnew("B2", "Axis", [b2, B2.x])
    O = me.Point("O")
    O.set_vel(N, 0)
    A = O.locatenew("A", L1 * B1.z)
    G1 = O.locatenew("G1", L1 / 2 * B1.z)
    G2 = A.locatenew("G2", L2 / 2 * B2.z)
    G1.v2pt_theory(O, N, B1)
    A.v2pt_theory(O, N, B1)
    G2.v2pt_theory(A, N, B2)
    I1 = m1 * L1**2 / 12
    I2 = m2 * L2**2 / 12
    bar1 = me.RigidBody("bar1", G1, B1, m1, (me.inertia(B1, I1, I1, 0), G1))
    bar2 = me.RigidBody("bar2", G2, B2, m2, (me.inertia(B2, I2, I2, 0), G2))
    return _kane(N, list(q), u, [bar1, bar2],
                 [(G1, -m1 * g * N.z), (G2, -m2 * g * N.z)])


def test_spherical_double_pendulum():
    """Two thin rods on spherical joints (ball joints at O and at the end A of the first
    rod), each oriented by absolute angles (a about the vertical, then b about the rotated
    i): four parameters of situation; a thin rod has no inertia about its own axis, so its
    spin is not a degree of freedom. Checks the spherical joint, a body whose connection
    point moves, and rods of unequal masses and lengths. States keep sin(b) away from 0,
    where the angle a of a rod is not defined."""
    eqs = spherical_double_pendulum_rigidmech()
    states = random_states(
        np.random.default_rng(3),
        {"a1": _ANGLE, "b1": _NUTATION, "a2": _ANGLE, "b2": _NUTATION},
        {"m1": _POSITIVE, "m2": _POSITIVE, "L1": _POSITIVE, "L2": _POSITIVE,
         "g": _POSITIVE}, N_STATES)
    assert_same_accelerations(eqs, spherical_double_pendulum_sympy(), states=states,
                              rtol=RTOL)


# -- 4. cart-pole with a spring and dampers -----------------------------------------------------
def cart_pole_rigidmech():
    x, th = rm.coordinates("x th")
    M, m, L, g, k, l0, d, c, c2 = rm.constants("M m L g k l0 d c c2")
    R0 = rm.Frame("R0")
    P = R0.point("P", x, 0, 0)
    Rc = R0.translated("Rc", P)
    Rp = R0.rotated("Rp", about=R0.k, angle=th, origin=P)
    G = P.moved("G", L / 2 * Rp.j)
    cart = rm.Body("cart", frame=Rc, mass=M)
    pole = rm.Body("pole", frame=Rp, mass=m, centre=G,
                   inertia=rm.inertia.rod(m, L, axis=Rp.j, centre=G))
    system = rm.System(galilean=R0)
    system.connect(R0, cart, rm.joints.Prismatic(at=P, axis=R0.i))
    system.connect(cart, pole, rm.joints.Pivot(at=P, axis=R0.k))
    system.act(rm.gravity(-g * R0.j))
    system.act(rm.Spring(k, l0, a=R0.point("A", -d, 0, 0), b=P, on_b=cart))
    # viscous dampers: forces written with the user's x'(t) and th'(t)
    system.act(rm.Force(on=cart, vector=-c * x.diff(rm.t) * R0.i, at=P))
    system.act(rm.Couple(on=pole, moment=-c2 * th.diff(rm.t) * R0.k, reaction_on=cart))
    return system.equations_of_motion()


def cart_pole_sympy():
    q = me.dynamicsymbols("x th")
    x, th = q
    u = me.dynamicsymbols("u1:3")
    M, m, L, g, k, l0, d, c, c2 = sp.symbols("M m L g k l0 d c c2")
    N = me.ReferenceFrame("N")
    B = N.orientnew("B", "Axis", [th, N.z])
    O = me.Point("O")
    O.set_vel(N, 0)
    P = O.locatenew("P", x * N.x)
    P.set_vel(N, x.diff() * N.x)
    G = P.locatenew("G", L / 2 * B.y)
    G.v2pt_theory(P, N, B)
    cart = me.Particle("cart", P, M)
    I = m * L**2 / 12
    pole = me.RigidBody("pole", G, B, m, (me.inertia(B, I, 0, I), G))
    loads = [(P, -M * g * N.y), (G, -m * g * N.y),
             (P, -k * (x + d - l0) * N.x),        # spring from (-d, 0, 0), length x + d
             (P, -c * x.diff() * N.x),             # damper on the cart
             (B, -c2 * th.diff() * N.z)]           # rotational damper, pole on cart
    # (the reaction couple on the cart does no work: the cart does not rotate)
    return _kane(N, list(q), u, [cart, pole], loads)


def test_cart_pole_with_spring_and_dampers():
    """Cart on a prismatic joint with a pole on a pivot (ch. 20), a linear spring of free
    length l0 from a fixed point to the cart (the cart stays on the side where the length is
    x + d > 0), a viscous damper on the cart written as an ``rm.Force`` whose vector contains
    the user's x'(t), and a rotational damper between pole and cart written as an
    ``rm.Couple`` containing th'(t) with its reaction on the cart. Checks velocity-dependent
    actions, the spring's action and the prismatic joint."""
    eqs = cart_pole_rigidmech()
    states = random_states(
        np.random.default_rng(4), {"x": (-0.5, 0.5), "th": _ANGLE},
        {"M": _POSITIVE, "m": _POSITIVE, "L": _POSITIVE, "g": _POSITIVE, "k": _POSITIVE,
         "l0": (0.1, 0.5), "d": (1.0, 2.0), "c": _POSITIVE, "c2": _POSITIVE}, N_STATES)
    assert_same_accelerations(eqs, cart_pole_sympy(), states=states, rtol=RTOL)


# -- 5. sympy's n-link pendulum on a cart --------------------------------------------------------
def n_link_pendulum_on_cart_rigidmech(n):
    q = rm.coordinates(" ".join(f"q{i}" for i in range(n + 1)))
    m = rm.constants(" ".join(f"m{i}" for i in range(n + 1)))
    ls = rm.constants(" ".join(f"l{i}" for i in range(n)))
    ls = ls if n > 1 else (ls,)
    g, F = rm.constants("g F")
    T = rm.constants(" ".join(f"T{i}" for i in range(1, n + 1)))
    T = T if n > 1 else (T,)
    R0 = rm.Frame("R0")
    P = R0.point("P0", q[0], 0, 0)
    cart = rm.Body("cart", frame=R0.translated("C", P), mass=m[0])
    system = rm.System(galilean=R0)
    system.connect(R0, cart, rm.joints.Prismatic(at=P, axis=R0.i))
    system.act(rm.Force(on=cart, vector=F * R0.i, at=P))
    parent = cart
    for i in range(n):
        Bi = R0.rotated(f"B{i}", about=R0.k, angle=q[i + 1], origin=P)
        Pi = P.moved(f"P{i + 1}", ls[i] * Bi.j)
        link = rm.Body(f"Pa{i + 1}", frame=Bi, mass=m[i + 1], centre=Pi)  # a particle
        system.connect(parent, link, rm.joints.Pivot(at=P, axis=R0.k))
        # joint torque T_{i+1} on link i, its reaction on the body below
        system.act(rm.Couple(on=link, moment=T[i] * R0.k, reaction_on=parent))
        parent, P = link, Pi
    system.act(rm.gravity(-g * R0.j))
    return system.equations_of_motion()


@pytest.mark.parametrize("n", [1, 3])
def test_n_link_pendulum_on_cart(n):
    """sympy's ``models.n_link_pendulum_on_cart(n, cart_force=True, joint_torques=True)``:
    a cart (particle) on a line, n massless links with a particle at each end, absolute link
    angles, a lateral force F on the cart and torques T1..Tn at the joints (each on the link
    above, its reaction on the body below; sympy applies the reaction of T1 to the ground
    frame, which is the same since the cart does not rotate). rigidmech builds the particles
    as massive bodies without inertia on pivots. The specified inputs F(t), Ti(t) of sympy
    take the constant values of rigidmech's F, Ti at the instant compared."""
    eqs = n_link_pendulum_on_cart_rigidmech(n)
    kane = models.n_link_pendulum_on_cart(n, cart_force=True, joint_torques=True)
    side = sympy_accelerations(kane.mass_matrix, kane.forcing, kane.q, kane.u)
    params = {f"m{i}": _POSITIVE for i in range(n + 1)}
    params.update({f"l{i}": _POSITIVE for i in range(n)})
    params.update({f"T{i}": (-1, 1) for i in range(1, n + 1)})
    params.update({"g": _POSITIVE, "F": (-1, 1)})
    states = random_states(np.random.default_rng(5),
                           {f"q{i}": (-1, 1) if i == 0 else _ANGLE for i in range(n + 1)},
                           params, N_STATES)
    assert_same_accelerations(eqs, side, states=states, rtol=RTOL)


# -- 6. sympy's multi mass spring damper --------------------------------------------------------
def multi_mass_spring_damper_rigidmech(n):
    x = rm.coordinates(" ".join(f"x{i}" for i in range(n)))
    x = x if n > 1 else (x,)
    m, k, c, f = ([rm.constants(" ".join(f"{s}{i}" for i in range(n)))] for s in "mkcf")
    m, k, c, f = (v[0] if n > 1 else (v[0],) for v in (m, k, c, f))
    g = rm.constants("g")
    R0 = rm.Frame("R0")
    system = rm.System(galilean=R0)
    system.act(rm.gravity(g * R0.i))           # the ceiling's x axis points down
    previous, P_prev = None, R0.origin
    for i in range(n):
        P = P_prev.moved(f"center{i}", x[i] * R0.i)
        block = rm.Body(f"block{i}", frame=R0.translated(f"Rb{i}", P), mass=m[i])
        system.connect(R0 if previous is None else previous, block,
                       rm.joints.Prismatic(at=P, axis=R0.i))
        # spring of zero free length and damper between the block and the one above
        system.act(rm.Spring(k[i], 0, a=P_prev, b=P, on_a=previous, on_b=block))
        damper = -c[i] * x[i].diff(rm.t) * R0.i
        system.act(rm.Force(on=block, vector=damper, at=P))
        if previous is not None:
            system.act(rm.Force(on=previous, vector=-damper, at=P_prev))
        system.act(rm.Force(on=block, vector=f[i] * R0.i, at=P))
        previous, P_prev = block, P
    return system.equations_of_motion()


@pytest.mark.parametrize("n", [1, 3])
def test_multi_mass_spring_damper(n):
    """sympy's ``models.multi_mass_spring_damper(n, apply_gravity=True,
    apply_external_forces=True)``: blocks in series hanging from a ceiling, each coordinate
    x_i the displacement of block i relative to block i - 1 (frames translated from one
    another), springs of zero free length and viscous dampers between neighbours (the
    damper as an ``rm.Force`` on each of the two blocks, with x_i'(t) in its vector),
    gravity and external forces f_i."""
    eqs = multi_mass_spring_damper_rigidmech(n)
    kane = models.multi_mass_spring_damper(n, apply_gravity=True, apply_external_forces=True)
    side = sympy_accelerations(kane.mass_matrix, kane.forcing, kane.q, kane.u)
    params = {"g": _POSITIVE}
    for i in range(n):
        params.update({f"m{i}": _POSITIVE, f"k{i}": _POSITIVE, f"c{i}": _POSITIVE,
                       f"f{i}": (-1, 1)})
    states = random_states(np.random.default_rng(6), {f"x{i}": (0.1, 1.0) for i in range(n)},
                           params, N_STATES)
    assert_same_accelerations(eqs, side, states=states, rtol=RTOL)


# -- 7. collar sliding on a rotating rod -----------------------------------------------------------
def collar_rigidmech():
    phi, r = rm.coordinates("phi r")
    mr, Lr, mc, Rc, hc, k, l0, g, alpha = rm.constants("mr Lr mc Rc hc k l0 g alpha")
    R0 = rm.Frame("R0")
    O = R0.origin
    R1 = R0.rotated("R1", about=R0.k, angle=phi)
    Rrod = R1.rotated("Rrod", about=R1.j, angle=alpha)   # rod inclined at alpha to k
    Grod = O.moved("Grod", Lr / 2 * Rrod.k)
    C = O.moved("C", r * Rrod.k)
    Rcol = Rrod.translated("Rcol", C)
    rod = rm.Body("rod", frame=Rrod, mass=mr, centre=Grod,
                  inertia=rm.inertia.rod(mr, Lr, axis=Rrod.k, centre=Grod))
    collar = rm.Body("collar", frame=Rcol, mass=mc, centre=C,
                     inertia=rm.inertia.cylinder(mc, Rc, hc, axis=Rcol.k, centre=C))
    system = rm.System(galilean=R0)
    system.connect(R0, rod, rm.joints.Pivot(at=O, axis=R0.k))
    system.connect(rod, collar, rm.joints.Prismatic(at=C, axis=Rrod.k))
    system.act(rm.gravity(-g * R0.k))
    system.act(rm.Spring(k, l0, a=O, b=C, on_a=rod, on_b=collar))
    return system.equations_of_motion()


def collar_sympy():
    q = me.dynamicsymbols("phi r")
    phi, r = q
    u = me.dynamicsymbols("u1:3")
    mr, Lr, mc, Rc, hc, k, l0, g, alpha = sp.symbols("mr Lr mc Rc hc k l0 g alpha")
    N = me.ReferenceFrame("N")
    B1 = N.orientnew("B1", "Axis", [phi, N.z])
    B = B1.orientnew("B", "Axis", [alpha, B1.y])
    O = me.Point("O")
    O.set_vel(N, 0)
    Grod = O.locatenew("Grod", Lr / 2 * B.z)
    Grod.v2pt_theory(O, N, B)
    C = O.locatenew("C", r * B.z)
    C.set_vel(B, r.diff() * B.z)
    C.v1pt_theory(O, N, B)
    Irod = mr * Lr**2 / 12
    It = mc * (3 * Rc**2 + hc**2) / 12
    rod = me.RigidBody("rod", Grod, B, mr, (me.inertia(B, Irod, Irod, 0), Grod))
    collar = me.RigidBody("collar", C, B, mc, (me.inertia(B, It, It, mc * Rc**2 / 2), C))
    loads = [(Grod, -mr * g * N.z), (C, -mc * g * N.z),
             (C, -k * (r - l0) * B.z)]   # r > 0: the spring's length is r
    # (the spring's reaction on the rod acts at O, on the fixed axis: no power)
    return _kane(N, list(q), u, [rod, collar], loads)


def test_collar_on_rotating_rod():
    """A collar (a short cylinder) sliding on a rod that turns about the vertical, the rod
    inclined at a constant angle alpha (a constant rotation in the frame chain), a spring
    between the pivot O and the collar, gravity (ch. 17, 20: the collar's motion relative to
    the rotating rod carries the entrainment and Coriolis terms). Checks the prismatic joint
    on a rotating body, a constant angle in a chain of frames and the spring's action on both
    bodies."""
    eqs = collar_rigidmech()
    states = random_states(
        np.random.default_rng(7), {"phi": _ANGLE, "r": (0.2, 1.5)},
        {"mr": _POSITIVE, "Lr": _POSITIVE, "mc": _POSITIVE, "Rc": (0.05, 0.2),
         "hc": (0.05, 0.2), "k": _POSITIVE, "l0": (0.1, 0.5), "g": _POSITIVE,
         "alpha": (0.2, 1.4)}, N_STATES)
    assert_same_accelerations(eqs, collar_sympy(), states=states, rtol=RTOL)


# -- 8. planar double pendulum, unequal bodies ---------------------------------------------------
def double_pendulum_rigidmech():
    q1, q2 = rm.coordinates("q1 q2")
    m1, m2, L1, d1, d2, I1, I2, g = rm.constants("m1 m2 L1 d1 d2 I1 I2 g")
    R0 = rm.Frame("R0")
    R1 = R0.rotated("R1", about=R0.k, angle=q1)
    R2 = R0.rotated("R2", about=R0.k, angle=q2)
    O = R0.origin
    A = O.moved("A", L1 * R1.i)
    G1 = O.moved("G1", d1 * R1.i)
    G2 = A.moved("G2", d2 * R2.i)
    bar1 = rm.Body("bar1", frame=R1, mass=m1, centre=G1,
                   inertia=InertiaOperator.from_products(I1 / 4, I1, I1, frame=R1, at=G1))
    bar2 = rm.Body("bar2", frame=R2, mass=m2, centre=G2,
                   inertia=InertiaOperator.from_products(I2 / 4, I2, I2, frame=R2, at=G2))
    system = rm.System(galilean=R0)
    system.connect(R0, bar1, rm.joints.Pivot(at=O, axis=R0.k))
    system.connect(bar1, bar2, rm.joints.Pivot(at=A, axis=R0.k))
    system.act(rm.gravity(g * R0.i))
    return system.equations_of_motion()


def double_pendulum_sympy():
    q1, q2 = q = me.dynamicsymbols("q1 q2")
    m1, m2, L1, d1, d2, I1, I2, g = sp.symbols("m1 m2 L1 d1 d2 I1 I2 g")
    N = me.ReferenceFrame("N")
    B1 = N.orientnew("B1", "Axis", [q1, N.z])
    B2 = N.orientnew("B2", "Axis", [q2, N.z])
    O = me.Point("O")
    O.set_vel(N, 0)
    A = O.locatenew("A", L1 * B1.x)
    G1 = O.locatenew("G1", d1 * B1.x)
    G2 = A.locatenew("G2", d2 * B2.x)
    G1.v2pt_theory(O, N, B1)
    A.v2pt_theory(O, N, B1)
    G2.v2pt_theory(A, N, B2)
    b1 = me.RigidBody("b1", G1, B1, m1, (me.inertia(B1, I1 / 4, I1, I1), G1))
    b2 = me.RigidBody("b2", G2, B2, m2, (me.inertia(B2, I2 / 4, I2, I2), G2))
    b1.potential_energy = -m1 * g * d1 * sp.cos(q1)
    b2.potential_energy = -m2 * g * (L1 * sp.cos(q1) + d2 * sp.cos(q2))
    lm = me.LagrangesMethod(me.Lagrangian(N, b1, b2), list(q))
    lm.form_lagranges_equations()
    return sympy_accelerations(lm.mass_matrix, lm.forcing, list(q))


def test_planar_double_pendulum_unequal_bodies():
    """Planar double pendulum with two different bodies: masses m1, m2, distance L1 between
    the pivots, mass centres at d1, d2 from their pivots, central moments I1, I2 about the
    pivot axis (ch. 25.4.3 in general form). The sympy side uses ``LagrangesMethod`` with the
    potential energy (a second route, independent of Kane's)."""
    eqs = double_pendulum_rigidmech()
    states = random_states(
        np.random.default_rng(8), {"q1": _ANGLE, "q2": _ANGLE},
        {"m1": _POSITIVE, "m2": _POSITIVE, "L1": _POSITIVE, "d1": _POSITIVE,
         "d2": _POSITIVE, "I1": _POSITIVE, "I2": _POSITIVE, "g": _POSITIVE}, N_STATES)
    assert_same_accelerations(eqs, double_pendulum_sympy(), states=states, rtol=RTOL)


# -- 9. heavy top in Cardan angles -----------------------------------------------------------------
def cardan_top_rigidmech():
    a, b, c = rm.coordinates("a b c")
    m, g, l = rm.constants("m g l")
    R0 = rm.Frame("R0")
    R1 = R0.rotated("R1", about=R0.k, angle=a)
    R2 = R1.rotated("R2", about=R1.j, angle=b)
    R = R2.rotated("R", about=R2.i, angle=c)
    G = R0.origin.moved("G", l * R.i)
    top = rm.Body("top", frame=R, mass=m, centre=G, inertia=_general_inertia_rm(R, G))
    system = rm.System(galilean=R0)
    system.connect(R0, top, rm.joints.Spherical(at=R0.origin))
    system.act(rm.gravity(-g * R0.k))
    return system.equations_of_motion()


def cardan_top_sympy():
    q = me.dynamicsymbols("a b c")
    u = me.dynamicsymbols("u1:4")
    m, g, l = sp.symbols("m g l")
    N = me.ReferenceFrame("N")
    B = N.orientnew("B", "Body", list(q), "321")   # z, then the new y, then the new x
    O = me.Point("O")
    O.set_vel(N, 0)
    G = O.locatenew("G", l * B.x)
    G.v2pt_theory(O, N, B)
    body = me.RigidBody("top", G, B, m, (_general_inertia_sympy(B), G))
    return _kane(N, list(q), u, [body], [(G, -m * g * N.z)])


def test_heavy_top_in_cardan_angles():
    """The heavy top of model 1 oriented by Cardan (Tait-Bryan) angles z-y-x (sympy's
    ``"Body", "321"``), its mass centre on the body's i axis: checks chains of elementary
    rotations about different axes of successive frames. The states keep cos(b) away from
    0, the singular set of this sequence (see ``Frame.singular_set``)."""
    eqs = cardan_top_rigidmech()
    assert eqs.singular_sets[0].condition == sp.Eq(sp.cos(rm.coordinates("b")), 0)
    states = random_states(
        np.random.default_rng(10), {"a": _ANGLE, "b": (-1.2, 1.2), "c": _ANGLE},
        {"m": _POSITIVE, "g": _POSITIVE, "l": _POSITIVE, **_INERTIA_RANGES}, N_STATES)
    assert_same_accelerations(eqs, cardan_top_sympy(), states=states, rtol=RTOL)
