"""The Whipple bicycle of rigidmech.models: its geometry and inertia in the upright
reference configuration against the definitions of Meijaard et al. (2007). (The benchmark
matrices themselves are checked in tests/vibrations/test_whipple_bicycle.py.)"""

import pytest
import sympy as sp

from rigidmech import models
from rigidmech.errors import ArgumentError

P = models.BENCHMARK_BICYCLE


@pytest.fixture(scope="module")
def bike():
    return models.whipple_bicycle()


def _at_rest(model, name):
    upright = {q: 0 for q in model.coordinates}
    return [sp.nsimplify(sp.simplify(c.subs(upright)))
            for c in model.point(name).coordinates(model.frame("R0"))]


def test_upright_geometry_is_the_papers(bike):
    # x forward, z up: rear contact at O, front contact at the wheelbase w, the steer axis
    # meets the ground at w + c (trail c), the wheels' centres at rR and rF, the mass
    # centres at (xB, -zB) and (xH, -zH)
    assert _at_rest(bike, "P") == [0, 0, 0]
    assert _at_rest(bike, "PF") == [P["w"], 0, 0]
    assert _at_rest(bike, "S0") == [P["w"] + P["c"], 0, 0]
    assert _at_rest(bike, "Cr") == [0, 0, P["rR"]]
    assert _at_rest(bike, "Cf") == [P["w"], 0, P["rF"]]
    assert _at_rest(bike, "GB") == [P["xB"], 0, -P["zB"]]
    assert _at_rest(bike, "GH") == [P["xH"], 0, -P["zH"]]


def test_steer_axis_is_tilted_back_by_lambda(bike):
    R0, E2 = bike.frame("R0"), bike.frame("E2")
    upright = {q: 0 for q in bike.coordinates}
    k = E2.k
    assert sp.simplify(k.dot(R0.k).subs(upright) - sp.cos(P["lam"])) == 0
    assert sp.simplify(k.dot(R0.i).subs(upright) + sp.sin(P["lam"])) == 0


def test_masses_and_inertias_are_the_papers_in_z_up_axes(bike):
    # the paper's tensors in (x, y right, z down) turned to (x, y left, z up) by
    # S = diag(1, -1, -1): the moments stay, I_xz changes sign
    assert [b.mass for b in bike.bodies] == [P["mR"], P["mB"], P["mH"], P["mF"]]
    IB = bike.body("rear_frame").inertia.matrix
    assert IB == sp.Matrix([[P["IBxx"], 0, -P["IBxz"]], [0, P["IByy"], 0],
                            [-P["IBxz"], 0, P["IBzz"]]])
    IH = bike.body("front_frame").inertia.matrix
    assert IH == sp.Matrix([[P["IHxx"], 0, -P["IHxz"]], [0, P["IHyy"], 0],
                            [-P["IHxz"], 0, P["IHzz"]]])
    assert bike.body("rear_wheel").inertia.matrix == sp.diag(P["IRxx"], P["IRyy"], P["IRxx"])


def test_float_parameters_are_made_exact():
    model = models.whipple_bicycle(w=1.1, c=0.09)
    assert _at_rest(model, "PF") == [sp.Rational(11, 10), 0, 0]
    assert _at_rest(model, "S0") == [sp.Rational(119, 100), 0, 0]


def test_unknown_parameter_is_named():
    with pytest.raises(ArgumentError, match=r"`wheelbase` is not a parameter of the Whipple"):
        models.whipple_bicycle(wheelbase=1.0)


def test_the_paper_has_25_parameters():
    assert len(P) == 25


def test_wheels_are_drawn_as_discs_of_the_papers_radii(bike):
    # drawing only: a disc about the axle (the wheel's j), of radius rR / rF
    for name, frame, radius in [("rear_wheel", "RW", P["rR"]), ("front_wheel", "FW", P["rF"])]:
        shape = bike.body(name).shape
        assert (shape.kind, shape.dimension("radius")) == ("disk", radius)
        assert shape.axis == bike.frame(frame).j
    # the wheel's edge touches the ground at the contact: centre - radius along R0.k upright
    assert _at_rest(bike, "Cr") == [0, 0, P["rR"]]
    # the moments stay the paper's (not the thin disc's m r^2 / 2)
    assert bike.body("rear_wheel").inertia.matrix == sp.diag(P["IRxx"], P["IRyy"], P["IRxx"])
