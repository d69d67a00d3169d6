"""The options of rigidmech.report.derivation and their errors: the route, the points of the
kinematic torsors, simplification, the naming of long expressions (one rule, tested at its
boundary), loops with their closure conditions and multipliers, systems refused."""

import re

import pytest
import sympy as sp

import rigidmech as rm
from rigidmech import models, report
from rigidmech.errors import ArgumentError, ArgumentTypeError, ConnectionError_

pytestmark = pytest.mark.filterwarnings("error")


@pytest.fixture(scope="module")
def pendulum():
    return models.compound_pendulum()


@pytest.fixture(scope="module")
def rep(pendulum):
    return report.derivation(pendulum)


def test_a_model_or_its_system_give_the_same_report(pendulum, rep):
    assert report.derivation(pendulum.system).to_text() == rep.to_text()


def test_the_report_is_an_immutable_value(rep):
    assert repr(rep) == "Derivation(route='principle', steps=8, named=0)"
    with pytest.raises(AttributeError):
        rep.route = "lagrange"
    with pytest.raises(TypeError):
        rep.results["kinematic"] = {}
    assert str(rep) == rep.to_text()


def test_unknown_body(rep):
    with pytest.raises(ArgumentError, match=r"`body` must be a body of the report \(bar\); "
                                            r"got 'wheel'"):
        rep.kinematic_torsor("wheel")


def test_points_of_the_kinematic_torsors(pendulum):
    G, O = pendulum.point("G"), pendulum.point("O_R0")
    bar = pendulum.body("bar")
    assert report.default_point(pendulum.system, bar) is O
    for at in (G, {"bar": G}, {bar: G}):
        got = report.derivation(pendulum, at=at, simplify=False)
        V = got.kinematic_torsor("bar")
        assert V.point is G
        # the field of velocities: v(G) = v(O) + omega x OG, written here by hand
        theta, L = pendulum.coordinates[0], pendulum.constant("L")
        expected = L / 2 * theta.diff(rm.t) * pendulum.frame("R1").j
        assert sp.simplify((V.velocity - expected).components(pendulum.frame("R0"))) \
            == sp.zeros(3, 1)
        assert got.partial_kinematic_torsors("bar")[0].point is G


@pytest.mark.parametrize("at, error, match", [
    pytest.param(3, ArgumentTypeError, r"`at` must be None, a Point or a dict .*; got int",
                 id="type"),
    pytest.param({"wheel": None}, ArgumentError,
                 r"`at` must map bodies of the system \(bar\) to points; got the key 'wheel'",
                 id="key"),
    pytest.param({"bar": 1}, ArgumentTypeError, "`at` must map each body to a Point; got int",
                 id="value"),
])
def test_bad_points(pendulum, at, error, match):
    with pytest.raises(error, match=match):
        report.derivation(pendulum, at=at)


def test_bad_arguments(pendulum):
    with pytest.raises(ArgumentError, match=r"`route` must be one of \('principle', "
                                            r"'lagrange'\); got 'kane'"):
        report.derivation(pendulum, route="kane")
    with pytest.raises(ArgumentTypeError, match="`system` must be a System or a Model .*; "
                                                "got str"):
        report.derivation("pendulum")
    with pytest.raises(ArgumentTypeError, match="`max_ops` must be an int .*; got float"):
        report.derivation(pendulum, max_ops=4.0)
    with pytest.raises(ArgumentTypeError, match="`max_ops` must be an int .*; got bool"):
        report.derivation(pendulum, max_ops=True)
    with pytest.raises(ArgumentError, match=r"`max_ops` must be >= 1 .*; got 0"):
        report.derivation(pendulum, max_ops=0)


def test_systems_with_friction_contacts_are_refused():
    with pytest.raises(ConnectionError_, match="one-sided contact.*with friction"):
        report.derivation(models.sliding_ball())


def test_long_expressions_are_named_above_max_ops_and_only_above(pendulum):
    theta_dot, L, m = sp.Symbol("theta_dot", real=True), *sp.symbols("L m", positive=True)
    T = L**2 * m * theta_dot**2 / 6
    n = sp.count_ops(T)
    for max_ops, named in ((n - 1, True), (n, False), (n + 1, False)):
        got = report.derivation(pendulum, max_ops=max_ops)
        text = got.to_text()
        (line,) = [x for x in text.splitlines() if x.startswith("   T = ")]
        shown = line.split(" = ", 1)[1].split("   [")[0]
        if not named:
            assert shown == sp.sstr(T), max_ops
            continue
        assert "Named expressions" in text and shown != sp.sstr(T)
        definitions = dict(got.named)
        names = {s.name: s for s in definitions} | {"theta_dot": theta_dot, "L": L, "m": m}
        expr = sp.sympify(shown, locals=names)
        assert expr.free_symbols & set(definitions)       # written with names z1, ...
        assert sp.count_ops(expr) <= max_ops              # and no longer long
        while expr.free_symbols & set(definitions):
            expr = expr.xreplace(definitions)
        assert sp.simplify(expr - T) == 0                 # the names stand for T's parts


def test_simplify_false_shows_the_library_s_expressions_unsimplified():
    dp = models.double_pendulum()
    got = report.derivation(dp, simplify=False)
    rule = dp.system.symbols()[3]
    raw = dp.system.kinetic_energy().xreplace(rule)
    assert f"T = {sp.sstr(raw)}" in got.to_text()
    assert sp.simplify(raw) != raw      # the library's T is not in simplest form
    assert got.equations.mass_matrix == dp.system.equations_of_motion().mass_matrix


def test_a_loop_shows_its_closure_conditions_and_multipliers():
    four_bar = models.four_bar()
    # the pivots are spatial: the closing pivot's out-of-plane 4.Z, 4.L, 4.M are hyperstatic
    with pytest.warns(rm.errors.HyperstaticWarning, match=r"4\.Z, 4\.L, 4\.M, "):
        got = report.derivation(four_bar, simplify=False)
    text = got.to_text()
    s = four_bar.system
    assert [lab for lab, _, _ in s.closure_conditions()] == ["4.u", "4.v"]
    assert "2. Linked parameters (ch. 25.3.3)" in text
    assert "Phi_4.u  " in text and "Phi'_4.v  " in text
    assert "lambda = (lambda_4.u, lambda_4.v)" in text
    assert "{A(coupler -> rocker)} = {lambda_4.u i_R0 + lambda_4.v j_R0 ; 0}_C3" in text
    assert "M(q) q'' = f(q, q', t) + A^T lambda" in text
    # the power coefficients of the multipliers are A^T lambda (ch. 25.3.3)
    lam = sp.Matrix(s.multiplier_symbols())
    A = s.constraints().jacobian
    assert got.results["equations"].constraints.jacobian == A
    assert "A^T lambda = " in text and str(lam[0]) in text


def test_the_hyperstatic_unknowns_of_a_closing_joint_are_named_in_the_report():
    # the warning's names (4.Z, 4.L, 4.M: the closing pivot's out-of-plane components, ch.
    # 14.2) are in the report's linked parameters, text and LaTeX, said to be taken zero
    four_bar = models.four_bar()
    names = ", ".join(four_bar.system.hyperstatic_unknowns())
    with pytest.warns(rm.errors.HyperstaticWarning, match=re.escape(names)):
        got = report.derivation(four_bar, simplify=False)
    linked = got.steps[1]
    assert linked.title == "Linked parameters"
    line = ("hyperstatic unknowns 4.Z, 4.L, 4.M: components of the action of the "
            "loop-closing joint 4 that the equations do not determine; taken zero (the tree "
            "joints carry the load, ch. 14.2)")
    assert "   " + line in linked.to_text().splitlines()
    assert line in linked.to_latex()
    assert "closes a loop: its multipliers; hyperstatic 4.Z, 4.L, 4.M taken zero" in got.to_text()


def test_the_hyperstatic_unknowns_of_a_loop_without_conditions_are_named():
    # a shaft in two coaxial pivots: the second closes a loop with no condition on the
    # parameters (no linked parameters step) and 5 undetermined components
    R0 = rm.Frame("R0")
    Rr = R0.rotated("Rr", about=R0.i, angle=rm.coordinates("q"))
    s = rm.System(galilean=R0)
    shaft = rm.Body("shaft", frame=Rr, mass=1)
    s.connect(R0, shaft, rm.joints.Pivot(at=R0.origin, axis=R0.i), label="A")
    s.connect(R0, shaft, rm.joints.Pivot(at=R0.point("B", 1, 0, 0), axis=R0.i), label="B")
    with pytest.warns(rm.errors.HyperstaticWarning, match=r"B\.X, B\.Y, B\.Z, B\.L, B\.M"):
        text = report.derivation(s, simplify=False).to_text()
    assert "Linked parameters" not in text
    assert "closes a loop: its multipliers; hyperstatic B.X, B.Y, B.Z, B.L, B.M taken zero" in text


def test_a_rolling_contact_is_shown_with_its_unknowns_and_its_multipliers():
    # the rolling contact is the disc's tree connection and it links the parameters: its
    # power goes through A^T lambda, and is not announced as zero (ch. 25.3.3)
    got = report.derivation(models.rolling_disc(), simplify=False)
    text = got.to_text()
    assert ("{A(R0 -> disc)} = {T1_1 i_R0 + T2_1 j_R0 + N_1 k_R0 ; 0}_I   [RollingContact 1: "
            "unknowns N_1, T1_1, T2_1; linking: in the equations through its multipliers]"
            ) in text
    assert "(connection 1)" not in text
    assert "hyperstatic" not in text              # an isostatic linking connection
    assert "A^T lambda = [[lambda_1.t1], [lambda_1.t2], [0], [0], " in text


def test_a_loop_closed_on_the_ground_is_shown_with_its_multipliers():
    # two bars on pivots, the tip T of the second kept on the plane y = 0 of the ground by a
    # point contact: the closing connection goes from the ground R0 to bar2
    q1, q2 = rm.coordinates("q1 q2")
    R0 = rm.Frame("R0")
    R1 = R0.rotated("R1", about=R0.k, angle=q1)
    A = R0.origin.moved("A", R1.i)
    R2 = R1.rotated("R2", about=R0.k, angle=q2, origin=A)
    bar1, bar2 = rm.Body("bar1", frame=R1, mass=1), rm.Body("bar2", frame=R2, mass=1)
    s = rm.System(galilean=R0)
    s.connect(R0, bar1, rm.joints.Pivot(at=R0.origin, axis=R0.k))
    s.connect(bar1, bar2, rm.joints.Pivot(at=A, axis=R0.k))
    s.connect(R0, bar2, rm.actions.PointContact(at=R0.origin, normal=R0.j),
              meets=A.moved("T", R2.i))
    s.act(rm.gravity(-R0.j))
    got = report.derivation(s, simplify=False)
    (label,) = [lab for lab, _, _ in s.closure_conditions()]
    text = got.to_text()
    assert f"lambda = (lambda_{label})" in text
    assert f"{{A(R0 -> bar2)}} = {{lambda_{label} j_R0 ; 0}}_T" in text
    assert "closes a loop: its multipliers" in text


def test_a_massless_body_has_no_kinetic_torsor_in_the_report():
    x = rm.coordinates("x")
    R0 = rm.Frame("R0")
    P = R0.point("P", x, 0, 0)
    s = rm.System(galilean=R0)
    s.connect(R0, rm.Body("link", frame=R0.translated("R1", P)),
              rm.joints.Prismatic(at=P, axis=R0.i))
    got = report.derivation(s)
    assert "link is massless: no kinetic torsor" in got.to_text()
    assert got.kinematic_torsor("link").velocity.is_zero is False
    with pytest.raises(ArgumentError, match="`body` link is massless: it has no kinetic torsor"):
        got.kinetic_torsor("link")
