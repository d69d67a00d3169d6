"""plot_frequency_response on the conventions of Simulation.plot (Agg backend): axes labelled
with quantity and unit ("ω [rad/s]", "amplitude [unit]", "phase lag [rad]" or "[deg]"), a
constrained layout, the legend off the data, no label cut, the old call kept working."""


import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402
from numpy.testing import assert_allclose  # noqa: E402
from plot_checks import texts_outside as _texts_outside  # noqa: E402

from rigidmech.errors import ArgumentError  # noqa: E402
from rigidmech.vibrations import harmonic_response_direct, plot_frequency_response  # noqa: E402


@pytest.fixture(autouse=True)
def _close_figures():
    yield
    plt.close("all")


def _two_dof():
    w = np.linspace(0.1, 3.0, 120)
    M, C, K = np.eye(2), 0.05 * np.eye(2), [[2.0, -1.0], [-1.0, 2.0]]
    return w, harmonic_response_direct(M, C, K, [1.0, 0.0], w)


def test_labels_carry_the_quantity_and_its_unit():
    w, H = _two_dof()
    ax_amp, ax_phase = plot_frequency_response(w, H, unit="m/N")
    assert ax_amp.get_ylabel() == "amplitude [m/N]"
    assert ax_phase.get_ylabel() == "phase lag [rad]"
    assert ax_phase.get_xlabel() == "ω [rad/s]"
    ax_amp, _ = plot_frequency_response(w, H)              # unit unknown: plain
    assert ax_amp.get_ylabel() == "amplitude"


def test_degrees_scale_the_phase_and_its_label():
    w, H = _two_dof()
    _, ax_phase = plot_frequency_response(w, H, degrees=True)
    assert ax_phase.get_ylabel() == "phase lag [deg]"
    assert_allclose(ax_phase.lines[1].get_ydata(), -np.degrees(np.unwrap(np.angle(H[1]))),
                    rtol=1e-14)


def test_a_new_figure_is_constrained_with_its_legend_outside_and_nothing_cut(tmp_path):
    w, H = _two_dof()
    ax_amp, ax_phase = plot_frequency_response(w, H, unit="m/N", path=tmp_path / "frf.png")
    fig = ax_amp.figure
    assert fig.get_layout_engine().__class__.__name__ == "ConstrainedLayoutEngine"
    assert ax_amp.get_legend() is None and len(fig.legends) == 1   # a figure legend
    assert [t.get_text() for t in fig.legends[0].get_texts()] == ["q1", "q2"]
    assert _texts_outside(fig) == []
    renderer = fig.canvas.get_renderer()
    legend = fig.legends[0].get_window_extent(renderer)
    for a in (ax_amp, ax_phase):                  # the legend covers no axes (no data)
        assert not legend.overlaps(a.get_window_extent(renderer))
    assert (tmp_path / "frf.png").stat().st_size > 0


def test_given_axes_get_the_legend_beside_them():
    w, H = _two_dof()
    fig, axes = plt.subplots(2, 1, sharex=True, layout="constrained")
    out = plot_frequency_response(w, H, labels=["x1", "x2"], ax=axes)
    assert out == (axes[0], axes[1])
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    legend = axes[0].get_legend().get_window_extent(renderer)
    assert legend.x0 >= axes[0].get_window_extent(renderer).x1    # right of the data
    assert _texts_outside(fig) == []


@pytest.mark.parametrize("kwargs, match", [
    ({"labels": ["only one"]}, "`labels` must give 2 labels"),
    ({"unit": ""}, "`unit` must be a non-empty string"),
    ({"ax": "not axes"}, "`ax` must be a pair"),
])
def test_bad_arguments_are_named(kwargs, match):
    w, H = _two_dof()
    with pytest.raises(ArgumentError, match=match):
        plot_frequency_response(w, H, **kwargs)
