"""A student's test: for three problems of the book, the torsors the report shows equal the
ones the student computes by hand (the difference simplifies to zero).

* a bar pivoted at its end (the compound pendulum, ch. 22.2.1): rigidmech.models.
  compound_pendulum, theta from the downward vertical i, gravity g i;
* a block sliding down a rough incline (ch. 23.2.5): rigidmech.models.block_on_incline (a
  prismatic joint along the slope Ri.i, x downwards, gravity -g j) plus the friction of the
  sliding phase x' > 0, a given force -f N Ri.i with N = m g cos(alpha) (Coulomb's law,
  ch. 13.1);
* a disc rolling without slipping on a plane (ch. 10.1, 13.1): rigidmech.models.rolling_disc
  (heading psi, lean theta, spin phi, contact point I0 = (x, y, 0), G = I0 + r B.j), checked
  against sympy.physics.mechanics.

The hand computations use the book's formulas (v(P) = v(O) + omega x OP, sigma(G) =
J_G(omega), delta(G) = d sigma(G)/dt) on vectors written here, never the report's path.
"""

import pytest
import sympy as sp
import sympy.physics.mechanics as me

import rigidmech as rm
from rigidmech import models, report

pytestmark = pytest.mark.filterwarnings("error")


def zero_vector(vector, frame, rule=None):
    comps = sp.Matrix(vector.components(frame))
    if rule:
        comps = comps.xreplace(rule)
    return all(sp.simplify(c) == 0 for c in comps)


def same_torsor(got, expected, frame):
    """Same resultant, same moment at got's point (the moment of ``expected`` moved there by
    hand: M(P) = M(Q) + R x QP)."""
    moment_there = expected.moment + expected.resultant.cross(got.point - expected.point)
    return (zero_vector(got.resultant - expected.resultant, frame)
            and zero_vector(got.moment - moment_there, frame))


# -- a pivoted bar ----------------------------------------------------------------------------
@pytest.fixture(scope="module")
def bar():
    model = models.compound_pendulum()
    return model, report.derivation(model)


def test_pivoted_bar_torsors(bar):
    model, rep = bar
    theta = model.coordinates[0]
    m, L, g = model.constants
    R0, R1 = model.frames
    O, G = model.point("O_R0"), model.point("G")
    w, dw = theta.diff(rm.t), theta.diff(rm.t, 2)
    # kinematic torsor at the pivot O: {theta' k ; 0}
    assert same_torsor(rep.kinematic_torsor("bar"), rm.Torsor(w * R0.k, 0 * R0.i, O), R0)
    # kinetic torsor at G: {m v(G) = m L/2 theta' j1 ; J_G(omega) = m L^2/12 theta' k}
    assert same_torsor(rep.kinetic_torsor("bar"),
                       rm.Torsor(m * L / 2 * w * R1.j, m * L**2 / 12 * w * R0.k, G), R0)
    # dynamic torsor at G: {m a(G) = m L/2 (theta'' j1 - theta'^2 i1) ; m L^2/12 theta'' k};
    # moved to O its moment is m L^2/3 theta'' k (Huygens)
    D = rep.dynamic_torsor("bar")
    assert same_torsor(D, rm.Torsor(m * L / 2 * (dw * R1.j - w**2 * R1.i),
                                    m * L**2 / 12 * dw * R0.k, G), R0)
    assert zero_vector(D.moment_at(O) - m * L**2 / 3 * dw * R0.k, R0)
    # the weight {m g i ; 0} at G and the pivot's unknowns at O
    assert same_torsor(rep.action_torsors["Gravity -> bar"], rm.Torsor(m * g * R0.i, 0 * R0.i,
                                                                       G), R0)
    pivot = rep.action_torsors["R0 -> bar (1)"]
    X, Y, Z, Lm, M = sp.symbols("X_1 Y_1 Z_1 L_1 M_1", real=True)
    assert same_torsor(pivot, rm.Torsor(X * R0.i + Y * R0.j + Z * R0.k, Lm * R0.i + M * R0.j,
                                        O), R0)
    # the equation: m L^2/3 theta'' = -m g L/2 sin(theta)
    assert sp.simplify(rep.power_coefficients[0] + m * g * L / 2 * sp.sin(theta)) == 0
    assert sp.simplify(rep.equations.mass_matrix[0, 0] - m * L**2 / 3) == 0


# -- a block on a rough incline ---------------------------------------------------------------
@pytest.fixture(scope="module")
def block():
    model = models.block_on_incline()
    m, g, alpha = model.constants
    f = sp.Symbol("f", positive=True)
    Ri, P, body = model.frame("Ri"), model.point("P"), model.body("block")
    # sliding down (x' > 0): the tangential action of the plane is -f N Ri.i, N = m g cos(alpha)
    model.system.act(rm.Force(on=body, vector=-f * m * g * sp.cos(alpha) * Ri.i, at=P))
    return model, f, report.derivation(model)


def test_block_on_rough_incline_torsors(block):
    model, f, rep = block
    x = model.coordinates[0]
    m, g, alpha = model.constants
    R0, Ri = model.frame("R0"), model.frame("Ri")
    P = model.point("P")
    v, a = x.diff(rm.t), x.diff(rm.t, 2)
    # translation along the slope: {0 ; x' Ri.i}, {m x' Ri.i ; 0}, {m x'' Ri.i ; 0} at P
    assert same_torsor(rep.kinematic_torsor("block"), rm.Torsor(0 * R0.i, v * Ri.i, P), R0)
    assert same_torsor(rep.kinetic_torsor("block"), rm.Torsor(m * v * Ri.i, 0 * R0.i, P), R0)
    assert same_torsor(rep.dynamic_torsor("block"), rm.Torsor(m * a * Ri.i, 0 * R0.i, P), R0)
    # weight -m g j, friction -f m g cos(alpha) along the slope; Ri.i = cos(a) i - sin(a) j
    assert same_torsor(rep.action_torsors["Gravity -> block"],
                       rm.Torsor(-m * g * R0.j, 0 * R0.i, P), R0)
    assert same_torsor(rep.action_torsors["Force -> block"],
                       rm.Torsor(-f * m * g * sp.cos(alpha) * (sp.cos(alpha) * R0.i
                                                               - sp.sin(alpha) * R0.j),
                                 0 * R0.i, P), R0)
    # the partial kinematic torsor {0 ; Ri.i} and the equation m x'' = m g (sin a - f cos a)
    (Vx,) = rep.partial_kinematic_torsors("block")
    assert same_torsor(Vx, rm.Torsor(0 * R0.i, Ri.i, P), R0)
    expected = m * g * (sp.sin(alpha) - f * sp.cos(alpha))
    assert sp.simplify(rep.power_coefficients[0] - expected) == 0
    assert sp.simplify(rep.equations.forcing[0] - expected) == 0
    assert "{A(Force -> block)}" in rep.to_text()


# -- a rolling disc ---------------------------------------------------------------------------
@pytest.fixture(scope="module")
def disc():
    model = models.rolling_disc()
    return model, report.derivation(model, simplify=False)


@pytest.fixture(scope="module")
def disc_by_mechanics(disc):
    """The disc in sympy.physics.mechanics, with the same angles, and the rules that write
    both with the same plain symbols."""
    model, _ = disc
    m, g, r = model.constants
    rule = model.system.symbols()[3]
    x, y, psi, th, phi = me.dynamicsymbols("x y psi theta phi")
    t = me.dynamicsymbols._t
    plain = dict(zip(model.coordinates, model.system.symbols()[0], strict=True))
    rates = dict(zip(model.coordinates, model.system.symbols()[1], strict=True))
    accs = dict(zip(model.coordinates, model.system.symbols()[2], strict=True))
    me_rule = {}
    for q_me, q in zip((x, y, psi, th, phi), model.coordinates, strict=True):
        me_rule.update({q_me.diff(t, 2): accs[q], q_me.diff(t): rates[q], q_me: plain[q]})
    N = me.ReferenceFrame("N")
    A = N.orientnew("A", "Axis", [psi, N.z])
    B = A.orientnew("B", "Axis", [th, A.x])
    D = B.orientnew("D", "Axis", [phi, B.z])
    O = me.Point("O")
    I0 = O.locatenew("I0", x * N.x + y * N.y)
    G = I0.locatenew("G", r * B.y)
    omega = D.ang_vel_in(N)
    vG = G.pos_from(O).dt(N)
    # the disc's point at I0: v(G) + omega x GI0 (ch. 9.2.4)
    vI = vG + omega.cross(I0.pos_from(G))
    J = me.inertia(D, m * r**2 / 4, m * r**2 / 4, m * r**2 / 2)
    sigma = J.dot(omega)
    return dict(N=N, B=B, rule=rule, me_rule=me_rule, omega=omega, vG=vG, vI=vI, aG=vG.dt(N),
                sigma=sigma, delta=sigma.dt(N), m=m)


def same(rm_vector, me_vector, ctx, frame):
    """Equal components in the basis of the disc's frame B (rigidmech's ``frame``, the
    mechanics' B): the simplest there."""
    got = sp.Matrix(rm_vector.components(frame)).xreplace(ctx["rule"])
    expected = sp.Matrix(me_vector.to_matrix(ctx["B"])).xreplace(ctx["me_rule"])
    return all(sp.simplify(c) == 0 for c in got - expected)


def test_rolling_disc_torsors_equal_sympy_mechanics(disc, disc_by_mechanics):
    model, rep = disc
    ctx = disc_by_mechanics
    R0, m = model.frame("B"), ctx["m"]
    V = rep.kinematic_torsor("disc")
    assert V.point.name == "I"     # at the contact point by default
    assert same(V.rotation, ctx["omega"], ctx, R0)
    assert same(V.velocity, ctx["vI"], ctx, R0)
    C, D = rep.kinetic_torsor("disc"), rep.dynamic_torsor("disc")
    assert C.point == model.point("G") == D.point
    assert same(C.resultant, m * ctx["vG"], ctx, R0)
    assert same(C.moment, ctx["sigma"], ctx, R0)
    assert same(D.resultant, m * ctx["aG"], ctx, R0)
    assert same(D.moment, ctx["delta"], ctx, R0)


def test_rolling_disc_report_shows_the_conditions_and_multipliers(disc):
    _, rep = disc
    text = rep.to_text()
    assert "Linked parameters (ch. 25.3.3)" in text
    assert "lambda = (lambda_1.t1, lambda_1.t2)" in text
    assert "M(q) q'' = f(q, q', t) + A^T lambda" in text
    assert rep.named   # long expressions are named, not printed in full
