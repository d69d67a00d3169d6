"""A loop-closing joint's hyperstatic unknowns are taken zero by the connection actions, and
the library says so (book, ch. 14.2): a :class:`~rigidmech.errors.HyperstaticWarning` naming
the unknowns the fundamental principle cannot determine, issued where a connection action is
computed, and only where it depends on them.

The four-bar of :func:`rigidmech.models.four_bar` is planar but its pivots are spatial: the
out-of-plane components (Z, L, M) of the closing pivot are hyperstatic (h = 3, ch. 13.2), the
in-plane ones are determined. Reference values (a static case, closed form): the
parallelogram four-bar (ground 2, crank 1, coupler 2, rocker 1) hanging at rest, crank and
rocker vertical below O and D, coupler horizontal, uniform bars of mass m, gravity -g j. The
crank carries no moment at O and its weight passes through O: the horizontal force at B is
zero; likewise at C; the coupler's moments about B give the vertical force at C, m g / 2, and
at B, m g / 2. So the ground holds the crank at O with 3 m g / 2 j (its weight and half the
coupler's), the rocker at D with 3 m g / 2 j, and the coupler pulls the rocker down at C with
-m g / 2 j; no in-plane horizontal force, no moment about k.
"""

import math
import warnings

import numpy as np
import pytest

import rigidmech as rm
from rigidmech import models
from rigidmech.errors import HyperstaticWarning, RigidmechWarning

M, G = 1.3, 9.81
HANGING = [-math.pi / 2, math.pi / 2, -math.pi / 2]     # crank down, coupler along i, rocker down


def hanging_parallelogram():
    bar4 = models.four_bar(lengths=(2.0, 1.0, 2.0, 1.0))
    sim = bar4.system.equations_of_motion().simulate(t=(0, 0.1), q0=HANGING, n_output=3,
                                                     m=M, g=G)
    return bar4, sim


def test_the_category():
    assert issubclass(HyperstaticWarning, RigidmechWarning)
    assert issubclass(HyperstaticWarning, UserWarning)


def test_the_closing_pivot_of_a_planar_loop_in_space_has_three_hyperstatic_unknowns():
    bar4 = models.four_bar()
    assert bar4.system.hyperstatic_unknowns() == ("4.Z", "4.L", "4.M")


@pytest.mark.parametrize("pair", [(0, 1), (1, 2), (0, 3), (2, 3)],
                         ids=["ground-crank", "crank-coupler", "ground-rocker",
                              "coupler-rocker"])
def test_every_action_of_the_loop_warns_naming_the_unknowns(pair):
    bar4 = models.four_bar()
    solids = (bar4.frames[0], *bar4.bodies)
    parent, child = (solids[i] for i in pair)
    with pytest.warns(HyperstaticWarning, match=r"4\.Z, 4\.L, 4\.M,.*taken zero"):
        bar4.system.connection_action(parent, child)
    with pytest.warns(HyperstaticWarning, match=r"4\.Z, 4\.L, 4\.M"):   # again: cached too
        bar4.system.connection_components(parent, child)


def test_an_isostatic_system_does_not_warn():
    q = rm.coordinates("q")
    R0 = rm.Frame("R0")
    R1 = R0.rotated("R1", about=R0.k, angle=q)
    s = rm.System(galilean=R0)
    s.connect(R0, rm.Body("disc", frame=R1, mass=1), rm.joints.Pivot(at=R0.origin, axis=R0.k))
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        s.connection_action(R0, s.bodies[0])


def test_determined_components_equal_the_closed_form_of_the_hanging_parallelogram():
    bar4, sim = hanging_parallelogram()
    R0 = bar4.frames[0]
    crank, coupler, rocker = bar4.bodies
    expected = {(R0, crank): 1.5 * M * G, (R0, rocker): 1.5 * M * G,
                (coupler, rocker): -0.5 * M * G}
    for (parent, child), Y in expected.items():
        with pytest.warns(HyperstaticWarning, match=r"4\.Z, 4\.L, 4\.M"):
            action = sim.connection_action(parent, child, basis=R0)
        np.testing.assert_allclose(action["X"], 0.0, atol=1e-9)
        np.testing.assert_allclose(action["Y"], Y, rtol=1e-9)
        np.testing.assert_allclose(action["N"], 0.0, atol=1e-9)
