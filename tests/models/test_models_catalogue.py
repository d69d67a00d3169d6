"""The listing of rigidmech.models: every builder listed once, each building a valid model."""

import pytest

from rigidmech import models
from rigidmech.dynamics import System
from rigidmech.errors import ArgumentError
from rigidmech.statics import Statics

_ARGS = {"n_link_pendulum": (3,), "spherical_chain": (2,), "four_bar_chain": (2,),
         "wheel_on_incline": (0.2,),
         "sleigh_on_incline": (0.3,)}
_STATICS = ("ladder",)


def test_names_are_unique_and_cover_the_public_builders():
    names = models.names()
    assert len(set(names)) == len(names) == len(models.catalogue())
    assert all(callable(getattr(models, n)) for n in names)


@pytest.mark.parametrize("name", [n for n in models.names() if n != "whipple_bicycle"])
def test_every_builder_returns_a_model_of_its_system(name):
    model = models.get(name).build(*_ARGS.get(name, ()))
    assert isinstance(model, models.Model)
    if name in _STATICS:                   # a problem of statics: no parameters of situation
        assert isinstance(model.system, Statics) and model.coordinates == ()
        assert model.frames[0] is model.system.reference
    else:
        assert isinstance(model.system, System)
        assert model.system.coordinates == model.coordinates
        assert model.frames[0] is model.system.galilean
    assert models.get(name).section.startswith("ch. ")


def test_get_names_an_unknown_model():
    with pytest.raises(ArgumentError, match=r"`name` must be one of the catalogue's models"):
        models.get("triple_pendulum")
