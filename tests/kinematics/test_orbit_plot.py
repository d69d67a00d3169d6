"""Orbit.plot on the conventions of Simulation.plot (Agg backend): the drawn points on the
polar equation r = p / (1 + e cos nu) (closed form, ch. 8.2), the centre and the apsides
marked where they are, equal aspect, axes "x [unit]", "y [unit]", the legend off the data,
no label cut, open and nearly parabolic conics finite."""

import math

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402
from matplotlib.figure import Figure  # noqa: E402
from plot_checks import texts_outside as _texts_outside  # noqa: E402

from rigidmech.errors import ArgumentError  # noqa: E402
from rigidmech.kinematics.orbits import Orbit  # noqa: E402


@pytest.fixture(autouse=True)
def _close_figures():
    yield
    plt.close("all")


def _curve(ax):
    x, y = ax.lines[0].get_data()
    return np.asarray(x), np.asarray(y)


def _on_polar_equation(orbit, x, y, direction_xy):
    """r of each point against p / (1 + e cos nu), nu measured from the periapsis."""
    r = np.hypot(x, y)
    cos_nu = (x * direction_xy[0] + y * direction_xy[1]) / r
    expected = orbit.semi_latus_rectum / (1 + orbit.eccentricity * cos_nu)
    np.testing.assert_allclose(r, expected, rtol=1e-12, atol=0)


# e = 0.44, periapsis along x, in the plane z = 0 (rotated to put the periapsis off the axes)
def _ellipse(angle=0.7):
    c, s = math.cos(angle), math.sin(angle)
    return Orbit([c, s, 0.0], [-1.2 * s, 1.2 * c, 0.0], mu=1.0)


def test_an_ellipse_is_drawn_closed_on_its_polar_equation_with_its_apsides():
    o = _ellipse()
    ax = o.plot(points=301, unit="AU")
    x, y = _curve(ax)
    assert len(x) == 301 and (x[0], y[0]) == pytest.approx((x[-1], y[-1]), abs=1e-15)
    _on_polar_equation(o, x, y, o.periapsis_direction[:2])
    assert np.hypot(x, y).max() == pytest.approx(o.apoapsis, rel=1e-12)
    assert np.hypot(x, y).min() == pytest.approx(o.periapsis, rel=1e-12)
    markers = {line.get_label(): line.get_xydata()[0] for line in ax.lines[1:]}
    np.testing.assert_allclose(markers["centre"], [0.0, 0.0])
    np.testing.assert_allclose(markers["periapsis"], o.periapsis * o.periapsis_direction[:2],
                               rtol=1e-15)
    np.testing.assert_allclose(markers["apoapsis"], -o.apoapsis * o.periapsis_direction[:2],
                               rtol=1e-15)
    assert np.linalg.norm(markers["periapsis"]) == pytest.approx(o.periapsis, rel=1e-15)
    assert (ax.get_xlabel(), ax.get_ylabel()) == ("x [AU]", "y [AU]")
    assert ax.get_aspect() == 1.0


def test_a_new_figure_is_constrained_with_its_legend_outside_and_nothing_cut(tmp_path):
    ax = _ellipse().plot(path=tmp_path / "orbit.png")
    fig = ax.figure
    assert isinstance(fig, Figure)
    assert fig.get_layout_engine().__class__.__name__ == "ConstrainedLayoutEngine"
    assert ax.get_legend() is None and len(fig.legends) == 1
    assert _texts_outside(fig) == []
    renderer = fig.canvas.get_renderer()
    assert not fig.legends[0].get_window_extent(renderer).overlaps(
        ax.get_window_extent(renderer))
    assert (tmp_path / "orbit.png").stat().st_size > 0


def test_given_axes_get_the_legend_beside_them():
    fig, ax = plt.subplots(layout="constrained")
    assert _ellipse().plot(ax, unit="km") is ax
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    assert ax.get_legend().get_window_extent(renderer).x0 >= ax.get_window_extent(renderer).x1
    assert _texts_outside(fig) == []


def test_no_plain_labels_without_unit_and_no_apsides_on_request():
    ax = _ellipse().plot(apsides=False, focus=False)
    assert (ax.get_xlabel(), ax.get_ylabel()) == ("x", "y")
    assert len(ax.lines) == 1


@pytest.mark.parametrize("velocity, kind", [
    ([0.0, 2.0, 0.0], "hyperbola"),                                  # e = 3
    ([0.0, math.sqrt(2.0), 0.0], "parabola"),                         # e = 1
    ([0.0, math.sqrt(2.0) * (1 + 1e-9), 0.0], "hyperbola"),           # e - 1 = 4e-9
    ([0.0, math.sqrt(2.0) * (1 - 1e-9), 0.0], "ellipse"),             # 1 - e = 4e-9
    ([1e-7, math.sqrt(2.0) * 1e-6, 0.0], "ellipse"),                  # nearly radial
])
def test_open_and_nearly_parabolic_conics_draw_finite(velocity, kind):
    o = Orbit([1.0, 0.0, 0.0], velocity, mu=1.0)
    assert o.kind == kind
    ax = o.plot(points=201, extent=10.0)          # odd: the periapsis is a drawn point
    x, y = _curve(ax)
    assert np.all(np.isfinite(x)) and np.all(np.isfinite(y))
    r = np.hypot(x, y)
    assert r[100] == pytest.approx(o.periapsis, rel=1e-12)
    assert r.min() >= o.periapsis * (1 - 1e-12)
    if o.is_bound:                           # closed, out to the apoapsis and no further
        assert r.max() == pytest.approx(o.apoapsis, rel=1e-12)
    else:                                    # the branch reaches out to 10 periapsis
        assert r.max() == pytest.approx(10 * o.periapsis, rel=1e-9)
        _on_polar_equation(o, x, y, o.periapsis_direction[:2])
    assert _texts_outside(ax.figure) == []


def test_a_hyperbola_stays_inside_its_asymptotes():
    o = Orbit([1.0, 0.0, 0.0], [0.0, 2.0, 0.0], mu=1.0)
    x, y = _curve(o.plot(extent=1e6))
    nu = np.arctan2(y, x)
    assert np.all(np.abs(nu) < math.acos(-1 / o.eccentricity))
    _on_polar_equation(o, x, y, o.periapsis_direction[:2])


def test_an_inclined_orbit_is_drawn_in_its_perifocal_axes():
    o = Orbit.from_apsides(1.0, 3.0, mu=1.0, inclination=0.5, raan=0.3,
                           argument_of_periapsis=1.0)
    ax = o.plot(unit="km")
    assert (ax.get_xlabel(), ax.get_ylabel()) == ("ξ [km]", "η [km]")
    x, y = _curve(ax)
    _on_polar_equation(o, x, y, (1.0, 0.0))                 # the periapsis along ξ
    assert np.hypot(x, y).max() == pytest.approx(3.0, rel=1e-12)


@pytest.mark.parametrize("kwargs, match", [
    ({"points": 2}, "`points` must be an integer >= 3"),
    ({"points": 3.5}, "`points` must be an integer >= 3"),
    ({"extent": 1.0}, "`extent` must be a finite number > 1"),
    ({"unit": ""}, "`unit` must be a non-empty string"),
])
def test_bad_arguments_are_named(kwargs, match):
    with pytest.raises(ArgumentError, match=match):
        _ellipse().plot(**kwargs)


@pytest.mark.parametrize("r1, r2", [(6678.0, 42164.0), (42164.0, 6678.0)])
def test_a_hohmann_transfer_draws_its_three_orbits_touching_at_the_burns(r1, r2):
    from rigidmech.kinematics.kepler import HohmannTransfer

    ax = HohmannTransfer(398600.0, r1, r2).plot(unit="km")
    lines = {line.get_label(): line.get_xydata() for line in ax.lines}
    np.testing.assert_allclose(np.hypot(*lines["departure circle"].T), r1, rtol=1e-12)
    np.testing.assert_allclose(np.hypot(*lines["arrival circle"].T), r2, rtol=1e-12)
    transfer = lines["transfer"]
    # the ellipse with a focus at the centre and apsides r1, r2: p = 2 r1 r2 / (r1 + r2)
    r_p, r_a = min(r1, r2), max(r1, r2)
    e, p = (r_a - r_p) / (r_a + r_p), 2 * r_a * r_p / (r_a + r_p)
    r = np.hypot(*transfer.T)
    direction = np.array([1.0, 0.0]) if r2 > r1 else np.array([-1.0, 0.0])
    np.testing.assert_allclose(r, p / (1 + e * (transfer @ direction) / r), rtol=1e-12)
    # departure burn on +x at r1, arrival burn on -x at r2
    np.testing.assert_allclose(lines["periapsis" if r2 > r1 else "apoapsis"][0], [r1, 0.0],
                               atol=1e-9 * r1)
    np.testing.assert_allclose(lines["apoapsis" if r2 > r1 else "periapsis"][0], [-r2, 0.0],
                               atol=1e-9 * r2)
    assert (ax.get_xlabel(), ax.get_ylabel()) == ("x [km]", "y [km]")
    assert ax.get_legend() is None and len(ax.figure.legends) == 1
    assert _texts_outside(ax.figure) == []
