"""Image conventions of the plots a reader expects (Agg backend): one panel per coordinate
labelled with its name and unit, phase portraits and energy one call away, no label cut
(every text inside the figure), no legend over the data; the Hohmann example fixed."""

import pathlib
import runpy

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402
from plot_checks import texts_outside as _texts_outside  # noqa: E402

import rigidmech as rm  # noqa: E402
from rigidmech import scenes  # noqa: E402
from rigidmech.errors import ArgumentError  # noqa: E402

EXAMPLES = pathlib.Path(__file__).resolve().parents[2] / "examples"


@pytest.fixture(autouse=True)
def _close_figures():
    yield
    plt.close("all")


def _polar_mass():
    """A point mass in polar coordinates about a centre of attraction (the Hohmann case of
    the issue): r a length in km, phi the angle of a body's frame, in rad."""
    r, phi = rm.coordinates("r phi")
    mu = rm.constants("mu", positive=True)
    R0 = rm.Frame("R0")
    R1 = R0.rotated("R1", about=R0.k, angle=phi)
    P = R0.origin.moved("P", r * R1.i)
    s = rm.System(galilean=R0)
    s.add(rm.Body("sat", frame=R1.translated("Rs", P), mass=1, centre=P))
    s.act(rm.Force(on=s.bodies[0], vector=-mu / r**2 * R1.i, at=P))
    eqs = s.equations_of_motion()
    return eqs.simulate(t=(0, 5000.0), q0=[7000.0, 0.0], u0=[0.0, 8.0 / 7000.0],
                        params={"mu": 398600.4418}, n_output=201)


def test_one_panel_per_coordinate_with_name_and_unit():
    sim = _polar_mass()
    axes = sim.plot(units={"r": "km"})
    assert len(axes) == 2 and axes[0] is not axes[1]
    assert [a.get_ylabel() for a in axes] == ["$r$ [km]", "$\\phi$ [rad]"]
    assert axes[-1].get_xlabel() == "t [s]"
    np.testing.assert_array_equal(axes[1].lines[0].get_ydata(), sim.q[1])   # phi on its own
    assert axes[0].get_legend() is None and _texts_outside(axes[0].figure) == []


def test_a_chosen_subset_and_degrees():
    sim = _polar_mass()
    (ax,) = sim.plot(coordinates=["phi"], degrees=True)
    assert ax.get_ylabel() == "$\\phi$ [deg]"
    np.testing.assert_allclose(ax.lines[0].get_ydata(), np.degrees(sim.q[1]))
    (ax,) = sim.plot(coordinates="r", degrees=True)      # not an angle: unchanged, no unit
    assert ax.get_ylabel() == "$r$"
    np.testing.assert_array_equal(ax.lines[0].get_ydata(), sim.q[0])


def test_phase_portrait_and_energy_are_one_call_away():
    sim = scenes.run("slider-pendulum", t_end=2.0, n_output=101).simulation
    axes = sim.plot(kind="phase", units={"x": "m"})
    assert [(a.get_xlabel(), a.get_ylabel()) for a in axes] == [
        ("$x$ [m]", "$x'$ [m/s]"), ("$\\theta$ [rad]", "$\\theta'$ [rad/s]")]
    np.testing.assert_array_equal(axes[1].lines[0].get_xdata(), sim.q[1])
    np.testing.assert_array_equal(axes[1].lines[0].get_ydata(), sim.u[1])
    assert _texts_outside(axes[0].figure) == []
    axes = sim.plot(kind="energy")
    np.testing.assert_allclose(axes[0].lines[0].get_ydata(), sim.energy())
    assert axes[-1].get_xlabel() == "t [s]" and _texts_outside(axes[0].figure) == []


def test_saved_figure_and_scene_figure_have_no_label_cut(tmp_path):
    sim = scenes.run("triple-pendulum", t_end=0.5, n_output=51).simulation
    axes = sim.plot(tmp_path / "sim.png")
    assert (tmp_path / "sim.png").stat().st_size > 1000 and _texts_outside(axes[0].figure) == []
    rep = scenes.run("satellite", t_end=600.0, n_output=51, plot=tmp_path / "sat.png")
    fig = scenes.plot_simulation(rep.simulation, tmp_path / "sat2.png",
                                 title=rep.scene.title, units=rep.scene.units)
    assert [a.get_ylabel() for a in fig.axes][:2] == ["$x$ [km]", "$y$ [km]"]
    assert _texts_outside(fig) == []


def test_bad_arguments_are_named():
    sim = _polar_mass()
    with pytest.raises(ArgumentError, match=r"`coordinates` must name coordinates among r, "
                                            r"phi; got 'theta'"):
        sim.plot(coordinates="theta")
    with pytest.raises(ArgumentError, match=r"`kind` must be one of time, phase, energy; "
                                            r"got 'bode'"):
        sim.plot(kind="bode")
    _, ax = plt.subplots()
    with pytest.raises(ArgumentError, match=r"`ax` must give 2 Axes \(one per panel\); got 1"):
        sim.plot(ax=ax)
    with pytest.raises(ArgumentError, match=r"`coordinates` does not apply to kind='energy'"):
        sim.plot(kind="energy", coordinates="r")


def test_hohmann_example_keeps_its_labels_and_legend_off_the_orbits(monkeypatch):
    monkeypatch.setattr(plt, "show", lambda *a, **k: None)
    runpy.run_path(str(EXAMPLES / "plot_ch27_hohmann_transfer.py"), run_name="__main__")
    fig = plt.gcf()
    assert _texts_outside(fig) == []
    ax = fig.axes[0]
    legend = ax.get_legend()
    box = legend.get_window_extent(fig.canvas.get_renderer())
    for line in ax.lines:
        xy = ax.transData.transform(np.column_stack([line.get_xdata(), line.get_ydata()]))
        inside = ((xy[:, 0] > box.x0) & (xy[:, 0] < box.x1) & (xy[:, 1] > box.y0)
                  & (xy[:, 1] < box.y1))
        assert not inside.any(), f"the legend covers {line.get_label()!r}"


def test_a_scene_in_other_units_says_so(tmp_path):
    rep = scenes.run("moon-probe", t_end=0.5, n_output=51)
    sc = rep.scene
    fig = scenes.plot_simulation(rep.simulation, tmp_path / "probe.png", units=sc.units,
                                 time_unit=sc.time_unit)
    assert [a.get_ylabel() for a in fig.axes][:2] == ["$x$ [D]", "$y$ [D]"]
    assert fig.axes[-1].get_xlabel() == "t [4.34 days]" and _texts_outside(fig) == []
