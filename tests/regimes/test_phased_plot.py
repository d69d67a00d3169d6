"""PhasedMotion.plot on the conventions of Simulation.plot (Agg backend): one panel per state
component labelled with its name and unit, degrees on demand, the phases shaded in their
regime's colour and named in a legend off the data, no label cut, a tuple of Axes."""

import math

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402
from matplotlib.figure import Figure  # noqa: E402
from plot_checks import texts_outside as _texts_outside  # noqa: E402

from rigidmech.actions.contact_laws import Coulomb  # noqa: E402
from rigidmech.errors import ArgumentError  # noqa: E402
from rigidmech.regimes import Guard, Regime, integrate_phases  # noqa: E402
from rigidmech.regimes.friction import coulomb_oscillator  # noqa: E402


@pytest.fixture(autouse=True)
def _close_figures():
    yield
    plt.close("all")


def _oscillator():
    # x(0) = 1, slides back and forth, sticks at x = -0.1 after 3 pi (4 phases)
    return coulomb_oscillator(mass=1.0, stiffness=1.0, friction=Coulomb(0.15),
                              normal_force=1.0, x0=1.0, t_end=12.0)


def test_one_panel_per_component_with_name_and_unit_and_regimes_named():
    m = _oscillator()
    axes = m.plot(names=("x", "x'"), units={"x": "m", "x'": "m/s"})
    assert isinstance(axes, tuple) and len(axes) == 2 and axes[0] is not axes[1]
    assert [a.get_ylabel() for a in axes] == ["$x$ [m]", "$x'$ [m/s]"]
    assert axes[-1].get_xlabel() == "t [s]"
    fig = axes[0].figure
    assert fig.get_layout_engine() is not None                  # constrained layout
    # every phase drawn in its regime's colour, and shaded
    lines = axes[0].get_lines()
    phase_lines = [ln for ln in lines if ln.get_linestyle() == "-"]
    assert len(phase_lines) == len(m.phases)
    first = phase_lines[0]
    t0 = first.get_xdata()
    np.testing.assert_allclose(first.get_ydata(), m(t0)[0], atol=1e-9)
    assert len(axes[0].patches) == len(m.phases)                # the shaded spans
    # the regimes in one legend, above the panels: no legend on the data
    assert [leg for a in axes if (leg := a.get_legend()) is not None] == []
    (legend,) = fig.legends
    assert sorted(t.get_text() for t in legend.get_texts()) == sorted(set(m.regimes))
    # switching instants dotted
    dotted = [ln for ln in lines if ln.get_linestyle() == ":"]
    assert [ln.get_xdata()[0] for ln in dotted] == pytest.approx(list(m.switch_times))
    assert _texts_outside(fig) == []


def test_legend_does_not_cover_the_data():
    m = _oscillator()
    axes = m.plot(names=("x", "x'"))
    fig = axes[0].figure
    fig.canvas.draw()
    box = fig.legends[0].get_window_extent(fig.canvas.get_renderer())
    for a in axes:
        assert box.y0 >= a.get_window_extent().y1 - 0.5


def test_a_chosen_component_by_name_and_degrees():
    # a regime in rad: the angle theta' = 1 rad/s for 1 s, then rest
    turn = Regime("turn", lambda t, y: np.array([1.0]),
                  [Guard("stops", lambda t, y: y[0] - 1.0, target="rest")])
    m = integrate_phases([turn, Regime("rest")], "turn", (0.0, 2.0), [0.0])
    (ax,) = m.plot(names=("theta",), units={"theta": "rad"}, components=["theta"],
                   degrees=True)
    assert ax.get_ylabel() == "$\\theta$ [deg]"
    assert np.max(ax.get_lines()[0].get_ydata()) == pytest.approx(math.degrees(1.0))


def test_given_axes_saved_figure_and_the_former_interface(tmp_path):
    m = _oscillator()
    fig = Figure(figsize=(6, 3), layout="constrained")
    ax = fig.add_subplot()
    (got,) = m.plot(ax, component=1, label="v [m/s]")
    assert got is ax and ax.get_ylabel() == "v [m/s]"
    axes = m.plot(path=tmp_path / "phases.png", names=("x", "x'"))
    assert (tmp_path / "phases.png").stat().st_size > 1000
    assert _texts_outside(axes[0].figure) == []


def test_bad_arguments_are_named():
    m = _oscillator()
    with pytest.raises(ArgumentError, match=r"`names` must give 2 names"):
        m.plot(names=("x",))
    with pytest.raises(ArgumentError, match=r"`components` must give indices below 2 or "
                                            r"names among x, x'; got \['z'\]"):
        m.plot(names=("x", "x'"), components=["z"])
    with pytest.raises(ArgumentError, match=r"`units` names \['z'\]"):
        m.plot(names=("x", "x'"), units={"z": "m"})
    _, ax = plt.subplots()
    with pytest.raises(ArgumentError, match=r"`ax` must give 2 Axes \(one per panel\); got 1"):
        m.plot(ax=ax)
