"""Renamed public names: the old names still work, with a DeprecationWarning naming the new
one (rigidmech.kinematics.Contact -> ContactKinematics, rigidmech.actions.Contact ->
ContactLaws, the gravitational attractors point_mass... -> point_mass_attractor...)."""

import importlib

import pytest

import rigidmech as rm


@pytest.mark.parametrize("module, old, new", [
    ("rigidmech", "Contact", "ContactLaws"),
    ("rigidmech.actions", "Contact", "ContactLaws"),
    ("rigidmech.actions.contact_laws", "Contact", "ContactLaws"),
    ("rigidmech.kinematics", "Contact", "ContactKinematics"),
    ("rigidmech.kinematics.contact", "Contact", "ContactKinematics"),
    ("rigidmech.actions", "point_mass", "point_mass_attractor"),
    ("rigidmech.actions", "homogeneous_sphere", "homogeneous_sphere_attractor"),
    ("rigidmech.actions", "spherical_shell", "spherical_shell_attractor"),
    ("rigidmech.actions.gravitation", "point_mass", "point_mass_attractor"),
])
def test_old_name_warns_and_gives_the_new_object(module, old, new):
    mod = importlib.import_module(module)
    with pytest.warns(DeprecationWarning, match=rf"`{module}\.{old}` is deprecated: use `.*{new}`"):
        obj = getattr(mod, old)
    assert obj is getattr(mod, new)
    assert old not in getattr(mod, "__all__", ())


def test_the_two_contacts_and_the_two_point_masses_are_distinct_names():
    assert rm.kinematics.ContactKinematics is not rm.actions.ContactLaws
    assert rm.actions.point_mass_attractor is not rm.inertia.point_mass


def test_unknown_attribute_is_still_an_attribute_error():
    with pytest.raises(AttributeError, match="has no attribute 'Kontakt'"):
        rm.kinematics.Kontakt  # noqa: B018
