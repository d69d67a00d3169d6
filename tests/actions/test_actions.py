"""Mechanical actions, power, connections (book, ch. 11-13)."""

import pytest
import sympy as sp

import rigidmech as rm
from rigidmech.kinematics import Solid, kinematic_torsor


def test_power_of_a_force_is_force_dot_velocity():
    """Ch. 11.3.5: P = F . v(A) for a force applied at A."""
    q = rm.coordinates("q")
    F, r = sp.symbols("F r")
    R0 = rm.Frame("R0")
    R1 = R0.rotated("R1", about=R0.k, angle=q)
    A = R0.origin.moved("A", r * R1.i)
    S = Solid("S", frame=R1)
    (_, T), = rm.Force(on=S, vector=F * R0.i, at=A).contributions([S])
    V = kinematic_torsor(R1, relative_to=R0, at=R0.origin)
    assert sp.simplify(rm.power(T, V) - F * R0.i.dot(A.velocity(R0))) == 0


def test_perfect_pivot_and_prismatic_connections_develop_no_power():
    """Ch. 13.2.4: the unknown action torsor of a perfect joint has zero comoment with every
    relative motion the joint allows."""
    q, x = rm.coordinates("q x")
    R0 = rm.Frame("R0")
    R1 = R0.rotated("R1", about=R0.k, angle=q)
    pivot = rm.joints.Pivot(at=R0.origin, axis=R0.k)
    T, unknowns = pivot.action_torsor("01")
    assert sp.simplify(rm.power(T, kinematic_torsor(R1, relative_to=R0, at=R0.origin))) == 0
    assert [u.name for u in unknowns] == ["X_01", "Y_01", "Z_01", "L_01", "M_01"]
    R2 = R0.translated("R2", R0.point("P", x, 0, 0))
    prismatic = rm.joints.Prismatic(at=R2.origin, axis=R0.i)
    T2, _ = prismatic.action_torsor("02")
    assert sp.simplify(rm.power(T2, kinematic_torsor(R2, relative_to=R0, at=R2.origin))) == 0


def test_gravity_potential_energy_gives_its_power():
    """Ch. 12.2.3: the power of gravity is -dV/dt with V = -m g . OG."""
    q = rm.coordinates("q")
    m, L, g = rm.constants("m L g", positive=True)
    R0 = rm.Frame("R0")
    R1 = R0.rotated("R1", about=R0.k, angle=q)
    G = R0.origin.moved("G", L / 2 * R1.i)
    body = rm.Body("b", frame=R1, mass=m, centre=G)
    grav = rm.gravity(g * R0.i)
    (_, T), = grav.contributions([body])
    V = grav.potential_energy([body], R0)
    P = rm.power(T, body.kinematic_torsor(relative_to=R0, at=G))
    assert sp.simplify(P + rm.vectors.time_derivative(V)) == 0


def test_spring_potential_and_force_agree():
    """Force of a spring = -grad of k (l - l0)^2 / 2 (power of the spring = -dV/dt)."""
    x = rm.coordinates("x")
    k, l0 = sp.symbols("k l0", positive=True)
    R0 = rm.Frame("R0")
    R1 = R0.translated("R1", R0.point("P", x, 0, 0))
    S = Solid("S", frame=R1)
    spring = rm.Spring(k, l0, a=R0.point("A", -1, 0, 0), b=R1.origin, on_b=S)
    (_, T), = spring.contributions([S])
    P = rm.power(T, kinematic_torsor(R1, relative_to=R0, at=R1.origin))
    V = spring.potential_energy([S], R0)
    residual = P + rm.vectors.time_derivative(V)
    # zero wherever the length |x + 1| is not zero (there the direction is undefined)
    for xv in (-3.0, -0.5, 0.0, 0.7, 2.0):
        value = residual.xreplace({x.diff(): 1.3}).xreplace({x: xv}).subs({k: 2, l0: 0.4})
        assert abs(float(value)) < 1e-12


def test_joint_axis_must_be_a_basis_vector():
    R0 = rm.Frame("R0")
    with pytest.raises(ValueError, match="must be a unit basis vector of a frame"):
        rm.joints.Pivot(at=R0.origin, axis=2 * R0.k)
    with pytest.raises(TypeError, match="`axis` must be a Vector; got the Point"):
        rm.joints.Pivot(at=R0.origin, axis=R0.origin)
    with pytest.raises(TypeError, match="`at` must be a Point"):
        rm.joints.Pivot(at=R0.k, axis=R0.k)


def test_system_refuses_a_joint_the_frames_do_not_realise():
    """A body turning about k0 at O cannot be pivoted at A != O."""
    q = rm.coordinates("q")
    R0 = rm.Frame("R0")
    R1 = R0.rotated("R1", about=R0.k, angle=q)
    body = rm.Body("b", frame=R1, mass=1, centre=R0.origin.moved("G", R1.i))
    s = rm.System(galilean=R0)
    with pytest.raises(ValueError, match="Pivot at A: the relative motion is not allowed"):
        s.connect(R0, body, rm.joints.Pivot(at=R0.point("A", 1, 0, 0), axis=R0.k))
    with pytest.raises(ValueError, match="Pivot at O_R0: the relative motion is not allowed"):
        s.connect(R0, body, rm.joints.Pivot(at=R0.origin, axis=R0.i))


def test_system_argument_errors():
    R0 = rm.Frame("R0")
    s = rm.System(galilean=R0)
    with pytest.raises(TypeError, match="`action` must be an Action"):
        s.act(R0.i)
    with pytest.raises(TypeError, match="`galilean` must be a Frame"):
        rm.System(galilean="R0")
    with pytest.raises(ValueError, match="no parameter of situation"):
        s.equations_of_motion()


def test_heavy_top_on_a_ball_joint_and_its_reaction():
    """Heavy symmetric top with its tip O on a spherical joint (ch. 13.2.2, 22-24): the
    joint is accepted, M(q) is the book's [[A sin^2 + C cos^2, 0, C cos], [0, A, 0],
    [C cos, 0, C]] with A the moment about a transverse axis through O, and at rest in the
    upright position the reaction at O balances the weight."""
    psi, theta, phi = rm.coordinates("psi theta phi")
    m, g, l, A, C = rm.constants("m g l A C", positive=True)
    R0 = rm.Frame("R0")
    R = R0.euler("R", psi, theta, phi)
    G = R0.origin.moved("G", l * R.k)
    top = rm.Body("top", frame=R, mass=m, centre=G,
                  inertia=rm.InertiaOperator.from_products(A, A, C, frame=R, at=G))
    s = rm.System(galilean=R0)
    s.connect(R0, top, rm.joints.Spherical(at=R0.origin))
    s.act(rm.gravity(-g * R0.k))
    eqs = s.equations_of_motion()
    th = eqs.q[1]
    AO = A + m * l**2
    expected = sp.Matrix([[AO * sp.sin(th)**2 + C * sp.cos(th)**2, 0, C * sp.cos(th)],
                          [0, AO, 0], [C * sp.cos(th), 0, C]])
    assert sp.simplify(eqs.mass_matrix - expected) == sp.zeros(3, 3)
    q_sym, u_sym, a_sym, rule = s.symbols()
    comps = {k: v.xreplace(rule) for k, v in s.connection_components(R0, top).items()}
    rest = {**{x: 0 for x in (*q_sym, *u_sym, *a_sym)}}
    assert sp.simplify(comps["Z"].xreplace(rest) - m * g) == 0
    assert comps["X"].xreplace(rest) == 0


def test_cylindrical_joint_allows_rotation_and_sliding():
    q, z = rm.coordinates("q z")
    R0 = rm.Frame("R0")
    R1 = R0.rotated("R1", about=R0.k, angle=q, origin=R0.point("P", 0, 0, z))
    body = rm.Body("b", frame=R1, mass=1)
    s = rm.System(galilean=R0)
    s.connect(R0, body, rm.joints.Cylindrical(at=R0.origin, axis=R0.k))
    assert s.coordinates == (q, z)
    with pytest.raises(ValueError, match="Spherical at O_R0: the relative motion"):
        rm.System(galilean=R0).connect(R0, body, rm.joints.Spherical(at=R0.origin))


def test_bodies_sharing_a_name_are_kept_apart():
    """Regression: the system's caches were keyed by body name, so with two bodies both named
    "bar" the action of the upper pivot was returned for the lower one. The connection
    actions of the double pendulum must not depend on the names chosen."""
    def actions(name1, name2):
        q1, q2 = rm.coordinates("q1 q2")
        m, L, g = rm.constants("m L g", positive=True)
        R0 = rm.Frame("R0")
        R1 = R0.rotated("R1", about=R0.k, angle=q1)
        R2 = R0.rotated("R2", about=R0.k, angle=q2)
        A = R0.origin.moved("A", L * R1.i)
        b1 = rm.Body(name1, frame=R1, mass=m, centre=R0.origin.moved("G1", L / 2 * R1.i))
        b2 = rm.Body(name2, frame=R2, mass=m, centre=A.moved("G2", L / 2 * R2.i))
        s = rm.System(galilean=R0)
        s.connect(R0, b1, rm.joints.Pivot(at=R0.origin, axis=R0.k))
        s.connect(b1, b2, rm.joints.Pivot(at=A, axis=R0.k))
        s.act(rm.gravity(g * R0.i))
        return [s.connection_components(R0, b1)["X"], s.connection_components(b1, b2)["X"]]

    same, distinct = actions("bar", "bar"), actions("bar1", "bar2")
    for a, b in zip(same, distinct, strict=True):
        assert sp.simplify(a - b) == 0
