"""Scenes with regime changes on the command line: ``python -m rigidmech run
coulomb-oscillator`` and ``... run rolling-cylinder`` print the phases."""

import math

import pytest

from rigidmech._core.errors import SceneError
from rigidmech.scenes import cli
from rigidmech.scenes.regime_scenes import regime_scene_names, run_regime_scene


def test_coulomb_oscillator_prints_its_phases(capsys):
    # defaults m=1, k=4, N=2, fs=0.12, fk=0.1, x0=1: turning points 1 - 0.1 n, stop when
    # |x| <= fs N / k = 0.06, i.e. after 10 half-cycles of pi/2: 11 phases, at rest at 5 pi
    assert cli.main(["run", "coulomb-oscillator"]) == 0
    out = capsys.readouterr().out
    assert out.startswith("Mass on a spring with dry friction: stick-slip (coulomb-oscillator, "
                          "book ch. 21.4)")
    assert "phases (11):" in out
    lines = [ln.split() for ln in out.splitlines() if ln.startswith("  ") and ln.split()[0]
             .isdigit()]
    assert [ln[1] for ln in lines] == ["slide-", "slide+"] * 5 + ["stick"]
    assert math.isclose(float(lines[-1][2]), 5 * math.pi, rel_tol=1e-9)


def test_rolling_cylinder_slips_then_rolls(capsys):
    assert cli.main(["run", "rolling-cylinder", "--t-end", "1.5"]) == 0
    out = capsys.readouterr().out
    assert "phases (2):" in out and "slipping+" in out and "rolling" in out
    # above the threshold tan(alpha) > 3 fs it never rolls
    assert cli.main(["run", "rolling-cylinder", "--param", "alpha=0.7"]) == 0
    assert "phases (1):" in capsys.readouterr().out


def test_options_plot_and_errors(capsys, tmp_path):
    path = tmp_path / "stick.png"
    assert cli.main(["run", "coulomb-oscillator", "--q0", "-0.5", "--u0", "0.2",
                     "--param", "fk=0.05", "--plot", str(path)]) == 0
    assert path.stat().st_size > 0
    capsys.readouterr()
    assert cli.main(["run", "coulomb-oscillator", "--param", "mu=1"]) == 2
    assert "has no parameter 'mu'" in capsys.readouterr().err
    assert cli.main(["run", "rolling-cylinder", "--method", "rk4"]) == 2
    assert "--method is not an option" in capsys.readouterr().err
    with pytest.raises(SceneError, match=r"`q0` and `u0` must give 2 values"):
        run_regime_scene("rolling-cylinder", q0=[0.0])
    with pytest.raises(SceneError, match=r"unknown regime scene"):
        run_regime_scene("pendulum")
    assert regime_scene_names() == ("coulomb-oscillator", "rolling-cylinder")
