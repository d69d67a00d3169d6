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
    assert [ln[1] for ln in lines] == ["slip-", "slip+"] * 5 + ["stick"]
    assert math.isclose(float(lines[-1][2]), 5 * math.pi, rel_tol=1e-9)


def test_rolling_cylinder_slips_then_rolls(capsys):
    assert cli.main(["run", "rolling-cylinder", "--t-end", "1.5"]) == 0
    out = capsys.readouterr().out
    assert "phases (2):" in out and "slip+" in out and "stick" in out
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


def test_regime_scenes_are_posed_from_bodies_and_match_the_hand_written_regimes():
    """The scenes run the System route (rigidmech.regimes.contact_motion); the regimes written
    by hand give the same phases."""
    from rigidmech.actions import Coulomb
    from rigidmech.regimes import coulomb_oscillator, cylinder_on_incline

    osc = run_regime_scene("coulomb-oscillator").motion
    hand = coulomb_oscillator(mass=1.0, stiffness=4.0, normal_force=2.0,
                              friction=Coulomb(0.12, 0.1), x0=1.0, t_end=20.0)
    assert len(osc.phases) == len(hand.phases)
    assert max(abs(a - b) for a, b in zip(osc.switch_times, hand.switch_times,
                                          strict=True)) < 1e-9
    cyl = run_regime_scene("rolling-cylinder").motion
    hand = cylinder_on_incline(radius=0.1, angle=math.atan(0.3), friction=Coulomb(0.2, 0.15),
                               v0=2.0, t_end=2.0)
    assert cyl.regimes == ("slip+", "stick") and hand.regimes == ("slipping+", "rolling")
    assert abs(cyl.switch_times[0] - hand.switch_times[0]) < 1e-9


def test_regime_scene_parameters_are_checked():
    with pytest.raises(SceneError, match=r"parameters m, k, N must be > 0; got N=-1"):
        run_regime_scene("coulomb-oscillator", params={"N": -1.0})
    with pytest.raises(SceneError, match=r"parameters r, g must be > 0; got r=0"):
        run_regime_scene("rolling-cylinder", params={"r": 0.0})
