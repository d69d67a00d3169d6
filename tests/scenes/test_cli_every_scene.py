"""Every scene runs from the command line (in process, a short time), every listing of the
scenes is the same list, and every run option is accepted or refused with its reason."""

import re

import numpy as np
import pytest

from rigidmech import scenes
from rigidmech.scenes import cli
from rigidmech.scenes.bicycle_scene import critical_speeds
from rigidmech.scenes.regime_scenes import regime_scene_names

ALL = cli.scene_names()
BICYCLE = "benchmark-bicycle"   # a linear analysis of ~40 s: its own tests below

# Meijaard et al. (2007), the benchmark matrices of the paper (eq. (A 3)-(A 5) values)
M_PAPER = np.array([[80.81722, 2.31941332208709], [2.31941332208709, 0.29784188199686]])
C1_PAPER = np.array([[0.0, 33.86641391492494], [-0.85035641456978, 1.68540397397560]])
K0_PAPER = np.array([[-80.95, -2.59951685249872], [-2.59951685249872, -0.80329488458618]])
K2_PAPER = np.array([[0.0, 76.59734589573222], [0.0, 2.65431523794604]])


def test_at_least_sixteen_scenes_covering_the_book():
    assert len(ALL) >= 16 and len(set(ALL)) == len(ALL)
    for name in ("heavy-top", "gyroscope", "four-bar", "block-on-incline", "cart-pendulum",
                 "satellite", BICYCLE):
        assert name in ALL


def test_usage_lists_every_command(capsys):
    assert cli.main(["--help"]) == 0
    usage = capsys.readouterr().out
    assert usage.splitlines()[0] == "usage: rigidmech [-h] [--version] {run,scenes,modes} ..."
    for command in ("run", "scenes", "modes"):
        assert re.search(rf"^ +{command} +\w", usage, re.M), command   # each with its help
    assert cli.COMMANDS == ("run", "scenes", "modes")


def test_every_listing_is_the_same_list(capsys):
    assert cli.main(["scenes"]) == 0
    listed = tuple(line.split()[0] for line in capsys.readouterr().out.splitlines()[1:])
    assert listed == ALL
    assert cli.main(["run", "--help"]) == 0
    # argparse wraps lines after hyphens: join them back
    helptext = " ".join(capsys.readouterr().out.split()).replace("- ", "-")
    in_help = re.search(r"one of (.*?)(?: --| options)", helptext).group(1)
    assert tuple(n.strip() for n in in_help.split(",")) == ALL
    assert cli.main(["run", "no-such-scene"]) == 2
    err = capsys.readouterr().err
    known = re.search(r"known scenes: (.*?) \(list", err).group(1)
    assert tuple(n.strip() for n in known.split(",")) == ALL


@pytest.mark.parametrize("name", [n for n in ALL if n != BICYCLE])
def test_every_scene_runs_from_the_command_line(name, capsys, tmp_path):
    if name in regime_scene_names():
        t_end = "0.5"
    else:
        t_end = str(min(scenes.get(name).t_end, 0.5))
    save = tmp_path / "out.csv"
    argv = ["run", name, "--t-end", t_end, "--samples", "11", "--save", str(save)]
    assert cli.main(argv) == 0, capsys.readouterr().err
    out = capsys.readouterr().out
    assert f"({name}, book ch. " in out
    assert save.exists() and save.stat().st_size > 0
    assert cli.main([*argv, "--method", "dopri5"]) == 0, capsys.readouterr().err


@pytest.mark.parametrize("name", regime_scene_names())
def test_regime_scenes_accept_the_run_options_or_say_why(name, capsys, tmp_path):
    path = tmp_path / "m.npz"
    assert cli.main(["run", name, "--t-end", "1", "--method", "bs32", "--rtol", "1e-9",
                     "--atol", "1e-11", "--samples", "5", "--save", str(path)]) == 0
    out = capsys.readouterr().out
    assert "(bs32, phase by phase)" in out and f"samples saved to {path}" in out
    with np.load(path) as data:
        assert data["t"].shape == (5,) and data["y"].shape[1] == 5
        assert data["t"][0] == 0.0 and data["t"][-1] == 1.0
    for extra, why in ((["--method", "rk4"], "adaptive method"),
                       (["--step", "0.01"], "adaptive method"),
                       (["--max-steps", "10"], "phase by phase"),
                       (["--pretty"], "its own equations")):
        assert cli.main(["run", name, *extra]) == 2
        err = capsys.readouterr().err.strip()
        assert err.startswith(f"rigidmech: error: {extra[0]} is not an option of the regime "
                              f"scene {name!r}") and why in err and "\n" not in err


@pytest.mark.parametrize("option", [["--t-end", "1"], ["--method", "rk4"], ["--save", "b.npz"],
                                    ["--plot", "b.png"], ["--samples", "5"], ["--q0", "0.1"],
                                    ["--pretty"]])
def test_benchmark_bicycle_says_why_integration_options_do_not_apply(option, capsys):
    assert cli.main(["run", BICYCLE, *option]) == 2
    err = capsys.readouterr().err.strip()
    assert err == (f"rigidmech: error: {option[0]} is not an option of the scene {BICYCLE!r}: "
                   "it is a linear analysis about the straight upright run (matrices and "
                   "critical speeds), with no integration; only --param applies.")


def test_critical_speeds_of_the_papers_matrices():
    """The paper's weave and capsize speeds, 4.292 and 6.024 m/s (its Table 2, to 4 digits)
    from its own matrices, against an independent root finding on the 4 x 4 state matrix."""
    weave, capsize = critical_speeds(M_PAPER, C1_PAPER, K0_PAPER, K2_PAPER, 9.81)
    assert weave == pytest.approx(4.2924, abs=5e-4) and capsize == pytest.approx(6.0243, abs=5e-4)
    # the paper's speeds to all the digits it gives (Meijaard et al. 2007, from its matrices
    # above at g = 9.81): v_w = 4.29238253634111, v_c = 6.02426201538837 m/s
    assert abs(weave - 4.29238253634111) < 1e-10 and abs(capsize - 6.02426201538837) < 1e-10
    Mi = np.linalg.inv(M_PAPER)

    def eig(v):
        A = np.block([[np.zeros((2, 2)), np.eye(2)],
                      [-Mi @ (9.81 * K0_PAPER + v**2 * K2_PAPER), -v * Mi @ C1_PAPER]])
        return np.linalg.eigvals(A)

    # the weave pair (complex) crosses at the weave speed, a real one at the capsize speed
    for v, complex_pair in ((weave, True), (capsize, False)):
        ev = eig(v)
        crossing = ev[np.argmax(ev.real)]
        assert abs(crossing.real) < 1e-8 and (abs(crossing.imag) > 1e-3) == complex_pair
    assert eig(weave - 1e-3).real.max() > 0 > eig(weave + 1e-3).real.max()
    assert eig(capsize - 1e-3).real.max() < 0 < eig(capsize + 1e-3).real.max()


@pytest.mark.slow
def test_benchmark_bicycle_from_the_command_line(capsys):
    """Derived and linearised from the System (~40 s): the paper's matrices and speeds."""
    assert cli.main(["run", BICYCLE]) == 0
    out = capsys.readouterr().out
    numbers = {}
    lines = out.splitlines()
    for name in ("M", "C1", "K0", "K2"):
        i = lines.index(f"{name} =")
        numbers[name] = np.array([[float(x) for x in lines[i + k].split()] for k in (1, 2)])
    for name, paper in (("M", M_PAPER), ("C1", C1_PAPER), ("K0", K0_PAPER), ("K2", K2_PAPER)):
        np.testing.assert_allclose(numbers[name], paper, rtol=1e-7, atol=1e-8)
    weave = float(re.search(r"weave speed +([\d.]+) m/s", out).group(1))
    capsize = float(re.search(r"capsize speed ([\d.]+) m/s", out).group(1))
    assert weave == pytest.approx(4.2924, abs=5e-4) and capsize == pytest.approx(6.0243, abs=5e-4)


def test_modes_of_the_benchmark_bicycle_points_to_run(capsys):
    assert cli.main(["modes", BICYCLE]) == 2
    assert capsys.readouterr().err.strip() == (
        f"rigidmech: error: scene {BICYCLE!r} is a linear analysis itself (its eigenvalues "
        f"against the speed): run it with `python -m rigidmech run {BICYCLE}`.")
