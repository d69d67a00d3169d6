"""Animations along a simulated motion (rigidmech.drawing.animate) and ``run --animate``."""

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt
import numpy as np
import pytest
import sympy as sp
from numpy.testing import assert_allclose
from PIL import Image

import rigidmech as rm
from rigidmech import models
from rigidmech.drawing import animate, sample_motion
from rigidmech.errors import ArgumentError, ArgumentTypeError
from rigidmech.scenes.cli import main


@pytest.fixture(autouse=True)
def close_figures():
    yield
    plt.close("all")


@pytest.fixture(scope="module")
def pendulum_run():
    eqs = models.double_pendulum().system.equations_of_motion()
    return eqs.simulate(t=(0, 1), q0=[1.0, 0.5], m=1.0, L=1.0, g=9.81)


def test_gif_of_a_few_frames(tmp_path, pendulum_run):
    path = tmp_path / "pendulum.gif"
    anim = animate(pendulum_run, n_frames=4, path=path)
    with Image.open(path) as gif:
        assert gif.format == "GIF" and gif.n_frames == 4
    # the images are the samples nearest to 0, 1/3, 2/3, 1 (1001 samples: within 0.5 ms)
    times, q = sample_motion(pendulum_run, 4)
    assert_allclose(times, [0, 1 / 3, 2 / 3, 1], atol=5e-4)
    assert set(times) <= set(pendulum_run.t)
    A = [p.point("A") for p in anim.placements]
    assert_allclose(A, np.c_[np.cos(q[0]), np.sin(q[0]), 0 * q[0]], atol=1e-12)


def test_animation_in_3d(tmp_path):
    eqs = models.heavy_top().system.equations_of_motion()
    sim = eqs.simulate(t=(0, 0.5), q0=[0.0, 0.5, 0.0], u0=[0.0, 0.0, 20.0], m=1.0, g=9.81,
                       l=1.0, A=1.0, C=0.5)
    anim = animate(sim, n_frames=3, path=tmp_path / "top.gif")
    assert anim._fig.axes[0].name == "3d"
    with Image.open(tmp_path / "top.gif") as gif:
        assert gif.n_frames == 3


def test_a_simulation_without_its_system_needs_one(pendulum_run):
    x = rm.coordinates("x")
    eqs = rm.EquationsOfMotion(coordinates=(x,), mass_matrix=sp.ImmutableMatrix([[1]]),
                               forcing=sp.ImmutableMatrix([[0]]))
    sim = eqs.simulate(t=(0, 1), q0=[0.0])
    with pytest.raises(ArgumentError, match=r"`system` must be given: this simulation does "
                                            r"not know the system"):
        animate(sim)


@pytest.mark.parametrize("n", [0, 2.5, True])
def test_number_of_frames_checked(pendulum_run, n):
    with pytest.raises(ArgumentError, match="`n_frames` must be a whole number >= 1"):
        animate(pendulum_run, n_frames=n)


def test_not_a_simulation():
    with pytest.raises(ArgumentTypeError, match="`sim` must be a Simulation"):
        animate([1, 2, 3])


def test_command_line_writes_the_gif(tmp_path, capsys):
    path = tmp_path / "pendulum.gif"
    assert main(["run", "simple-pendulum", "--t-end", "0.5", "--animate", str(path)]) == 0
    assert f"animation: {path}" in capsys.readouterr().out
    with Image.open(path) as gif:
        assert gif.n_frames == 60


@pytest.mark.parametrize("argv, match", [
    pytest.param(["run", "coulomb-oscillator", "--animate", "{tmp}/x.gif"],
                 "--animate: scene 'coulomb-oscillator' cannot be drawn", id="regimes"),
    pytest.param(["run", "benchmark-bicycle", "--animate", "{tmp}/x.gif"],
                 "--animate: scene 'benchmark-bicycle' cannot be drawn", id="bicycle"),
    pytest.param(["run", "four-bar", "--animate", "{tmp}/x.png"],
                 "expected a path ending with .gif", id="not-gif"),
    pytest.param(["run", "four-bar", "--animate", "{tmp}/missing/x.gif"],
                 "does not exist", id="no-folder"),
])
def test_command_line_refuses_before_the_run(tmp_path, capsys, argv, match):
    argv = [a.replace("{tmp}", str(tmp_path)) for a in argv]
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert match in err and err.count("\n") == 1
    assert not list(tmp_path.iterdir())
