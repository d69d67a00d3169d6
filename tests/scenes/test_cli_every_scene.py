"""Every scene runs from the command line (in process, a short time), every listing of the
scenes is the same list, and every run option is accepted or refused with its reason."""

import re

import numpy as np
import pytest

from rigidmech import scenes
from rigidmech.scenes import cli
from rigidmech.scenes.regime_scenes import regime_scene_names

ALL = cli.scene_names()


def test_at_least_sixteen_scenes_covering_the_book():
    assert len(ALL) >= 16 and len(set(ALL)) == len(ALL)
    for name in ("heavy-top", "gyroscope", "four-bar", "block-on-incline", "cart-pendulum",
                 "satellite"):
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


@pytest.mark.parametrize("name", ALL)
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
