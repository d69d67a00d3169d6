"""The ladder of the catalogue (book, ch. 14.4.1): a uniform ladder against a wall, Coulomb
friction f1 at the foot (ground) and f2 at the top (wall).

Reference (statics by hand, conventions of :func:`rigidmech.models.ladder`): at the limit both
contacts slide, T_A = -f1 N_A and T_B = f2 N_B; horizontal N_B + T_A = 0, vertical
N_A + T_B = W, moments about A: N_B L sin(alpha) + T_B L cos(alpha) = W (L/2) cos(alpha), so
N_A = W / (1 + f1 f2) and tan(alpha_min) = (1 - f1 f2) / (2 f1).
"""

import math

import pytest

from rigidmech import models
from rigidmech.errors import ArgumentError, ArgumentTypeError
from rigidmech.statics import Statics

VALUES = {"m": 10.0, "g": 9.81, "L": 4.0}


@pytest.mark.parametrize("f1, f2", [(0.4, 0.3), (0.6, 0.0), (0.25, 0.5)])
def test_limiting_angle_and_actions_are_the_closed_form(f1, f2):
    lad = models.ladder(f1, f2)
    assert isinstance(lad.system, Statics) and lad.frames[0] is lad.system.reference
    alpha = lad.constant("alpha")
    lim = lad.system.limit(alpha, (1.5, 0.02), values=VALUES)
    assert lim.value == pytest.approx(math.atan((1 - f1 * f2) / (2 * f1)), rel=1e-9)


def test_hyperstatic_of_degree_one_while_it_holds():
    lad = models.ladder()
    assert lad.system.solve(values={**VALUES, "alpha": 1.2}).hyperstaticity == 1
    assert [p.name for p in lad.points] == ["A", "B", "G"]
    assert lad.body("ladder").mass == lad.constant("m")


@pytest.mark.parametrize("kwargs, name, error", [({"f1": -0.1}, "f1", ArgumentError),
                                                 ({"f2": "rough"}, "f2", ArgumentTypeError)])
def test_a_coefficient_that_is_not_one_is_refused_by_its_name(kwargs, name, error):
    with pytest.raises(error, match=rf"`{name}` must be a friction coefficient, a "
                                            rf"number >= 0; got .*Pass e\.g\. {name}=0\.4"):
        models.ladder(**kwargs)


def test_the_ladder_is_in_the_catalogue():
    entry = models.get("ladder")
    assert entry.section == "ch. 14.4.1" and entry.family == "friction"
