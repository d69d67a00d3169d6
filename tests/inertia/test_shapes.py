"""The catalogue's operators carry the shape of their body (rigidmech.inertia.shapes), which a
Body keeps through placing and change of basis; the drawing reads it."""

import pytest
import sympy as sp

import rigidmech as rm
from rigidmech.errors import ArgumentError
from rigidmech.inertia import InertiaOperator, Shape

m, L, R, h, a, b, c = sp.symbols("m L R h a b c", positive=True)
R0 = rm.Frame("R0")
R1 = R0.rotated("R1", about=R0.k, angle=rm.coordinates("q"))


@pytest.mark.parametrize("op, kind, dims", [
    pytest.param(rm.inertia.rod(m, L, axis=R1.i), "rod", {"length": L}, id="rod"),
    pytest.param(rm.inertia.ring(m, R, axis=R1.k), "ring", {"radius": R}, id="ring"),
    pytest.param(rm.inertia.disk(m, R, axis=R1.k), "disk", {"radius": R}, id="disk"),
    pytest.param(rm.inertia.cylinder(m, R, L, axis=R1.k), "cylinder",
                 {"radius": R, "length": L}, id="cylinder"),
    pytest.param(rm.inertia.tube(m, R / 2, R, L, axis=R1.k), "tube",
                 {"r_in": R / 2, "r_out": R, "length": L}, id="tube"),
    pytest.param(rm.inertia.cylindrical_shell(m, R, L, axis=R1.k), "cylindrical_shell",
                 {"radius": R, "length": L}, id="cylindrical_shell"),
    pytest.param(rm.inertia.cone(m, R, h, axis=-R1.k), "cone", {"radius": R, "height": h},
                 id="cone"),
    pytest.param(rm.inertia.hemisphere(m, R, axis=R1.k), "hemisphere", {"radius": R},
                 id="hemisphere"),
    pytest.param(rm.inertia.sphere(m, R, frame=R1), "sphere", {"radius": R}, id="sphere"),
    pytest.param(rm.inertia.spherical_shell(m, R, frame=R1), "spherical_shell", {"radius": R},
                 id="spherical_shell"),
    pytest.param(rm.inertia.block(m, a, b, c, frame=R1), "block", {"a": a, "b": b, "c": c},
                 id="block"),
    pytest.param(rm.inertia.rectangular_plate(m, a, b, frame=R1), "block",
                 {"a": a, "b": b, "c": 0}, id="plate"),
    pytest.param(rm.inertia.ellipsoid(m, a, b, c, frame=R1), "ellipsoid",
                 {"a": a, "b": b, "c": c}, id="ellipsoid"),
    pytest.param(rm.inertia.point_mass(m, frame=R1), "point_mass", {}, id="point_mass"),
])
def test_catalogue_operator_has_its_shape(op, kind, dims):
    assert op.shape.kind == kind
    assert op.shape.dimensions == dims
    assert op.shape.frame is R1


def test_cone_keeps_the_sign_of_its_axis():
    shape = rm.inertia.cone(m, R, h, axis=-R1.k).shape
    assert (shape.axis_index, shape.axis_sign) == (2, -1)
    assert shape.axis == -R1.k


def test_body_keeps_the_shape_through_placing_and_change_of_basis():
    R2 = R1.rotated("R2", about=R1.i, angle=sp.pi / 2)   # fixed in the body
    G = R0.origin.moved("G", L / 2 * R1.i)
    bar = rm.Body("bar", frame=R1, mass=m, centre=G, inertia=rm.inertia.rod(m, L, axis=R2.k))
    assert bar.inertia.at == G and bar.inertia.frame is R1
    assert bar.shape == Shape("rod", [L], axis=R2.k)


def test_operators_without_a_shape():
    J = InertiaOperator.from_products(1, 1, 1, frame=R1)
    assert J.shape is None
    assert (J + J).shape is None
    assert rm.Body("b", frame=R1, mass=1).shape is None
    assert rm.Body("b", frame=R1).shape is None


def test_shape_is_not_part_of_equality():
    rod = rm.inertia.rod(m, L, axis=R1.i)
    same = InertiaOperator.from_products(0, m * L**2 / 12, m * L**2 / 12, frame=R1)
    assert rod == same and hash(rod) == hash(same)


def test_subs_substitutes_the_dimensions():
    assert rm.inertia.disk(m, R, axis=R1.k).subs(R, 2).shape.dimension("radius") == 2


def test_shape_value_semantics():
    assert Shape("rod", [L], axis=R1.i) == Shape("rod", [L], axis=R1.i)
    assert Shape("rod", [L], axis=R1.i) != Shape("rod", [L], axis=R1.j)
    assert hash(Shape("block", [a, b, c], frame=R1)) == hash(Shape("block", [a, b, c], frame=R1))
    assert repr(Shape("block", [1, 2, 3], frame=R1)) == "Shape('block', a=1, b=2, c=3, frame=R1)"


@pytest.mark.parametrize("kwargs, match", [
    pytest.param(dict(kind="beam", dimensions=[L], axis=R1.i), "`kind` must be one of",
                 id="kind"),
    pytest.param(dict(kind="rod", dimensions=[L, L], axis=R1.i),
                 r"`dimensions` of a rod must be \(length\): 1 values; got 2", id="count"),
    pytest.param(dict(kind="rod", dimensions=[L], frame=R1), "give its `axis`", id="no-axis"),
    pytest.param(dict(kind="block", dimensions=[a, b, c], axis=R1.i), "oriented by a `frame`",
                 id="block-axis"),
    pytest.param(dict(kind="rod", dimensions=[L], axis=R1.i + R1.j),
                 "`axis` must be a basis vector", id="oblique"),
])
def test_shape_bad_input(kwargs, match):
    with pytest.raises(ArgumentError, match=match):
        Shape(**kwargs)


def test_unknown_dimension_name():
    with pytest.raises(ArgumentError, match=r"`name` must be a dimension of a rod \(length\)"):
        Shape("rod", [L], axis=R1.i).dimension("radius")


# --- a shape given to a body whose inertia is given by its moments (drawing only) ---

def test_body_given_a_shape_with_an_operator_by_moments():
    J = InertiaOperator.from_products(a, a, c, frame=R1)
    cone = Shape("cone", [R, h], axis=-R1.k)
    top = rm.Body("top", frame=R1, mass=m, inertia=J, shape=cone)
    assert top.shape == cone
    # the shape is for drawing only: the operator keeps the given moments
    assert top.inertia.matrix == sp.diag(a, a, c)


def test_massless_link_and_particle_may_be_given_a_shape():
    rod = Shape("rod", [L], axis=R1.i)
    assert rm.Body("link", frame=R1, shape=rod).shape == rod
    assert rm.Body("p", frame=R1, mass=m, shape=rod).shape == rod


def test_shape_given_in_a_frame_fixed_in_the_body():
    R2 = R1.rotated("R2", about=R1.i, angle=sp.pi / 2)
    disk = Shape("disk", [R], axis=R2.k)
    assert rm.Body("w", frame=R1, mass=m, shape=disk).shape == disk


def test_shape_bad_input_on_a_body():
    with pytest.raises(rm.errors.ArgumentTypeError, match=r"`shape` must be a "
                       r"rigidmech.inertia.Shape \(such as .*\); got str"):
        rm.Body("b", frame=R1, mass=m, shape="cone")
    R2 = R0.rotated("R2", about=R0.i, angle=rm.coordinates("p"))
    with pytest.raises(ArgumentError, match="`shape` must be given in a basis fixed in the "
                       "body: its frame R2 turns"):
        rm.Body("b", frame=R1, mass=m, shape=Shape("disk", [R], axis=R2.k))
    with pytest.raises(ArgumentError, match="`shape` given with a catalogue operator"):
        rm.Body("b", frame=R1, mass=m, inertia=rm.inertia.rod(m, L, axis=R1.i),
                shape=Shape("rod", [L], axis=R1.i))
