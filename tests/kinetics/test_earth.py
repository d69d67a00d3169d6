"""The Earth as a reference (ch. 12.2.1, 19): the local frame's geometry and its rotation."""

import math

import pytest
import sympy as sp

import rigidmech as rm
from rigidmech._core.errors import ArgumentTypeError
from rigidmech.kinetics import EARTH_RADIUS, EARTH_ROTATION_RATE, earth_reference


def test_local_frame_geometry():
    """up = cos(l) i_T + sin(l) k_T (radial), north = -sin(l) i_T + cos(l) k_T, east = j_T;
    O at distance R from the centre; the local frame turns with the Earth:
    omega(local/R0) = Omega k0 = Omega (cos(l) north + sin(l) up)."""
    lam, W, R = sp.symbols("lambda Omega R", positive=True)
    E = earth_reference(latitude=lam, rate=W, radius=R)
    T = E.earth
    assert E.up.equals(sp.cos(lam) * T.i + sp.sin(lam) * T.k)
    assert E.north.equals(-sp.sin(lam) * T.i + sp.cos(lam) * T.k)
    assert E.east.equals(T.j)
    assert sp.simplify((E.frame.origin - E.geocentric.origin).magnitude() - R) == 0
    assert E.frame.rotation_vector(E.geocentric).equals(W * E.geocentric.k)
    assert E.rotation.equals(W * (sp.cos(lam) * E.north + sp.sin(lam) * E.up))
    assert E.latitude == lam and E.radius == R and E.rate == W


def test_defaults_and_repr():
    E = earth_reference(latitude=math.radians(45), name="Lyon")
    assert E.rate == sp.Float(EARTH_ROTATION_RATE) and E.radius == sp.Float(EARTH_RADIUS)
    assert E.frame.name == "Lyon" and E.earth.name == "Lyon_T"
    assert repr(E).startswith("EarthReference(latitude=0.785")
    R0 = rm.Frame("G")
    assert earth_reference(latitude=0, geocentric=R0).geocentric is R0
    with pytest.raises(ArgumentTypeError, match="`geocentric` must be a Frame"):
        earth_reference(latitude=0, geocentric="G")
    with pytest.raises(ArgumentTypeError, match="`latitude` must be a number"):
        earth_reference(latitude=[1, 2])
