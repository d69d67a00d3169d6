"""The catalogue of connections (book, ch. 13.2.2-13.2.4).

The invariant checked here is the book's definition of a perfect connection (ch. 13.2.4): the
power of the mutual actions, i.e. the comoment of the action torsor with the relative
kinematic torsor, is zero for every motion the connection allows. It is checked by
``Torsor.comoment`` at a point other than the joint's own (so the transport of both torsors
takes part), for random unknown values and random allowed motions, with the joint's axis in a
frame turned by a random fixed rotation. check() must accept every allowed motion and refuse a
motion with any one forbidden component.
"""

import math

import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

import rigidmech as rm
from rigidmech._core.errors import ConnectionError_
from rigidmech.kinematics import kinematic_torsor

p_sym = sp.Symbol("p", positive=True)


def _catalogue(R, O):
    """Every connection of the catalogue, on the frame R at the point O."""
    return {
        "pivot": rm.joints.Pivot(at=O, axis=R.k),
        "prismatic": rm.joints.Prismatic(at=O, axis=R.i),
        "helical": rm.joints.Helical(at=O, axis=R.k, pitch=sp.Rational(3, 2)),
        "helical_left": rm.joints.Helical(at=O, axis=R.j, pitch=-p_sym),
        "cylindrical": rm.joints.Cylindrical(at=O, axis=R.k),
        "spherical": rm.joints.Spherical(at=O, axis=R.k),
        "spherical_with_finger": rm.joints.SphericalWithFinger(at=O, axis=R.j),
        "planar_support": rm.joints.PlanarSupport(at=O, normal=R.k),
        "linear_annular": rm.joints.LinearAnnular(at=O, axis=R.i),
        "linear_rectilinear": rm.joints.LinearRectilinear(at=O, normal=R.k, direction=R.j),
        "point_contact": rm.joints.PointContact(at=O, normal=-R.j),
        "embedding": rm.joints.Embedding(at=O, axis=R.i),
    }


#: degrees of freedom of each connection (book, ch. 13.2.2 table), counted by hand from the
#: allowed motions: rotations + translations (helical: one, the linked screw motion)
DOF = {"pivot": 1, "prismatic": 1, "helical": 1, "helical_left": 1, "cylindrical": 2,
       "spherical": 3, "spherical_with_finger": 2, "planar_support": 3, "linear_annular": 4,
       "linear_rectilinear": 4, "point_contact": 5, "embedding": 0}
#: unknowns of each perfect connection (ch. 13.2.4): 6 - dof, since each allowed motion
#: cancels one component of the action
UNKNOWNS = {"pivot": "XYZLM", "prismatic": "XYLMN", "helical": "XYZLM", "helical_left": "XYZLM",
            "cylindrical": "XYLM", "spherical": "XYZ", "spherical_with_finger": "XYZN",
            "planar_support": "ZLM", "linear_annular": "XY", "linear_rectilinear": "ZM",
            "point_contact": "Z", "embedding": "XYZLMN"}
NAMES = sorted(DOF)


def _setup(angle, x, y, z):
    R0 = rm.Frame("R0")
    # a fixed frame turned about a skew axis: the joint's basis is not R0's
    R = R0.rotated("R", about=R0.vector(1, 2, 2), angle=sp.Rational(angle).limit_denominator(97))
    O = R0.point("O", sp.nsimplify(x), sp.nsimplify(y), sp.nsimplify(z))
    return R0, R, O


coords = st.integers(-3, 3)
values = st.floats(-10, 10, allow_nan=False, allow_infinity=False)


@pytest.mark.parametrize("name", NAMES)
def test_degrees_of_freedom_and_unknowns(name):
    R0, R, O = _setup(0.5, 1, 0, 0)
    joint = _catalogue(R, O)[name]
    assert joint.degrees_of_freedom == DOF[name]
    assert "".join(joint.unknown_names) == UNKNOWNS[name]
    _, free = joint.allowed_motion("a")
    assert len(free) == DOF[name]
    _, unknowns = joint.action_torsor("a")
    assert [s.name[0] for s in unknowns] == list(UNKNOWNS[name])


@pytest.mark.parametrize("name", NAMES)
@settings(max_examples=8, deadline=None)
@given(angle=st.floats(-3, 3), x=coords, y=coords, z=coords, data=st.data())
def test_power_of_a_perfect_connection_is_zero(name, angle, x, y, z, data):
    """Ch. 13.2.4: comoment {A(1 -> 2)} . {V(2/1)} = 0 for every allowed motion."""
    R0, R, O = _setup(angle, x, y, z)
    joint = _catalogue(R, O)[name]
    T, unknowns = joint.action_torsor("12")
    V, free = joint.allowed_motion("12")
    rule = {s: data.draw(values) for s in (*unknowns, *free)}
    rule[p_sym] = data.draw(st.floats(0.1, 5))
    B = R0.point("B", 2, -1, 3)
    power = sp.N(T.subs(rule).at(B).comoment(V.subs(rule).at(B)))
    scale = sum(abs(v) for v in rule.values()) ** 2 + 1
    assert abs(float(power)) <= 1e-12 * scale
    # and a forbidden component adds power: the action is not a zero torsor in disguise
    if unknowns:
        assert sp.simplify(T.comoment(_general_motion(R, O))) != 0


def _general_motion(R, O):
    w = sp.symbols("w1:4", real=True)
    v = sp.symbols("v1:4", real=True)
    return rm.Torsor(R.vector(*w), R.vector(*v), O)


@pytest.mark.parametrize("name", NAMES)
@settings(max_examples=5, deadline=None)
@given(data=st.data())
def test_check_accepts_allowed_and_refuses_forbidden_motion(name, data):
    R0, R, O = _setup(1.0, 1, 2, 0)
    joint = _catalogue(R, O)[name]
    V, free = joint.allowed_motion("12")
    joint.check(V)  # symbolic: every allowed motion passes
    rule = {s: sp.Integer(data.draw(st.integers(-5, 5))) for s in free}
    joint.check(V.subs(rule))
    blocked = [n for n in range(6) if n in joint.blocked_motion] + (
        [5] if joint.linked_motion else [])
    n = data.draw(st.sampled_from(blocked)) if blocked else None
    if n is None:
        return
    eps = sp.Rational(data.draw(st.integers(1, 9)), 7)
    u, v, w = joint.basis
    e = (u, v, w)[n % 3] * eps
    rot, vel = (e, rm.Vector.zero()) if n < 3 else (rm.Vector.zero(), e)
    bad = rm.Torsor(V.resultant + rot, V.moment + vel, V.point).subs(rule)
    with pytest.raises(ConnectionError_, match="is not allowed by the joint"):
        joint.check(bad)


@pytest.mark.parametrize(("size", "allowed"), [
    (1e-12, True), (0.5e-9, True), (2e-9, False), (1e-6, False)])
def test_check_tolerates_float_rounding_only(size, allowed):
    """With float constants, a forbidden component at most SAMPLE_ZERO = 1e-9 of the largest
    magnitude met in it (here x', the sliding rate) is their rounding and is accepted; 2e-9
    and 1e-6 of it are a motion the joint forbids and are refused. An exact constant has no
    rounding: 1e-12 as a rational is refused."""
    x = rm.coordinates("x")
    R0 = rm.Frame("R0")
    joint = rm.joints.Prismatic(at=R0.origin, axis=R0.i)
    xd = x.diff(rm.t)
    motion = rm.Torsor(rm.Vector.zero(), R0.vector(xd, size * xd, 0), R0.origin)
    if allowed:
        joint.check(motion)
    else:
        with pytest.raises(ConnectionError_, match="is not allowed by the joint"):
            joint.check(motion)
    exact = rm.Torsor(rm.Vector.zero(), R0.vector(xd, sp.Rational(1, 10**12) * xd, 0), R0.origin)
    with pytest.raises(ConnectionError_, match="is not allowed by the joint"):
        joint.check(exact)


def test_helical_links_translation_to_rotation():
    """A screw of pitch p advances p per turn: a frame turning by q and moving p q / (2 pi)
    along the axis passes check(); moving p q / pi does not."""
    q = rm.coordinates("q")
    p = sp.Symbol("p", positive=True)
    R0 = rm.Frame("R0")
    R1 = R0.rotated("R1", about=R0.k, angle=q,
                    origin=R0.point("P", 0, 0, p * q / (2 * sp.pi)))
    R2 = R0.rotated("R2", about=R0.k, angle=q, origin=R0.point("P2", 0, 0, p * q / sp.pi))
    screw = rm.joints.Screw(at=R0.origin, axis=R0.k, pitch=p)
    screw.check(kinematic_torsor(R1, relative_to=R0, at=R0.origin))
    with pytest.raises(ConnectionError_, match=r"Z - h\*wZ"):
        screw.check(kinematic_torsor(R2, relative_to=R0, at=R0.origin))
    assert screw.reduced_pitch == p / (2 * sp.pi)
    assert math.isclose(float(rm.joints.Helical(at=R0.origin, axis=R0.k, pitch=2).reduced_pitch),
                        1 / math.pi)


def test_rolling_ball_on_a_plane_is_a_point_contact():
    """A ball of radius r rolling on the plane z = 0 (centre at height r): the point contact
    at the contact point accepts its motion; a ball sinking into the plane is refused."""
    x, y, psi, theta, phi, h = rm.coordinates("x y psi theta phi h")
    r = sp.Symbol("r", positive=True)
    R0 = rm.Frame("R0")
    ball = R0.euler("B", psi, theta, phi, origin=R0.point("C", x, y, r))
    I = R0.point("I", x, y, 0)
    contact = rm.joints.SpherePlane(at=I, normal=R0.k)
    contact.check(kinematic_torsor(ball, relative_to=R0, at=I))
    sinking = R0.euler("B2", psi, theta, phi, origin=R0.point("C2", x, y, h))
    with pytest.raises(ConnectionError_, match=r"components \[Z\]"):
        contact.check(kinematic_torsor(sinking, relative_to=R0, at=I))


def test_aliases_are_the_same_classes():
    j = rm.joints
    assert j.Screw is j.Helical and j.Planar is j.PlanarSupport and j.Fixed is j.Embedding
    assert j.SphereCylinder is j.LinearAnnular and j.SpherePlane is j.PointContact
    assert j.LineContact is j.CylinderPlane is j.LinearRectilinear
    assert j.Revolute is j.Pivot and j.Slide is j.Prismatic and j.BallJoint is j.Spherical


def test_bad_input_is_refused_clearly():
    R0 = rm.Frame("R0")
    O = R0.origin
    with pytest.raises(ValueError, match="`pitch` must be non-zero"):
        rm.joints.Helical(at=O, axis=R0.k, pitch=0)
    with pytest.raises(TypeError, match="`pitch` must be a number"):
        rm.joints.Helical(at=O, axis=R0.k, pitch="a b")
    with pytest.raises(ValueError, match="`direction` must be orthogonal to `normal`"):
        rm.joints.LinearRectilinear(at=O, normal=R0.k, direction=R0.k)
    with pytest.raises(ValueError, match="`direction` must be a unit basis vector"):
        rm.joints.LinearRectilinear(at=O, normal=R0.k, direction=R0.i + R0.j)
    with pytest.raises(TypeError, match="`normal` must be a Vector; got the Point"):
        rm.joints.PointContact(at=O, normal=O)
    with pytest.raises(ValueError, match="`normal` must be a unit basis vector"):
        rm.joints.PlanarSupport(at=O, normal=2 * R0.k)
    with pytest.raises(TypeError, match="`at` must be a Point"):
        rm.joints.Embedding(at=R0.k)
