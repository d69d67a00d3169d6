"""The command line checks every option and output path before the run, and reports every
failure in one line (issue: a run that never loses work).

Each test here failed on the command line before these checks: a bad ``--plot`` path was found
only after the whole run (with a traceback, or a message naming a file it did not write), there
was no ``--version``, ``--param m=-1`` was accepted for a positive constant, and
``--method verlet`` was refused on the spring-mass scene with a wrong reason.
"""

import os
import re
import signal
import subprocess
import sys
import time

import numpy as np
import pytest

import rigidmech
from rigidmech import scenes
from rigidmech._core.errors import SceneError
from rigidmech.dynamics import load_simulation
from rigidmech.scenes import cli


def _main(argv, capsys):
    code = cli.main(argv)
    captured = capsys.readouterr()
    return code, captured.out, captured.err


def test_version(capsys):
    code, out, err = _main(["--version"], capsys)
    assert code == 0
    assert out.strip() == f"rigidmech {rigidmech.__version__}"


@pytest.mark.parametrize(
    ("name", "match"),
    [
        pytest.param(os.path.join("no-such-folder", "out.png"),
                     r"--plot: the folder .*no-such-folder.* does not exist", id="missing-folder"),
        pytest.param("out.xyz", r"--plot: unknown file type '\.xyz'; one of .*png", id="bad-ext"),
        pytest.param("out", r"--plot: 'out' has no file extension", id="no-ext"),
    ],
)
def test_plot_path_is_checked_before_the_run(name, match, capsys, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    started = []
    monkeypatch.setattr(cli, "run", lambda *a, **k: started.append(1))
    code, out, err = _main(["run", "spring-mass", "--plot", name], capsys)
    assert code == 2
    assert not started, "the run started before the plot path was checked"
    assert len(err.strip().splitlines()) == 1
    import re
    assert re.search(match, err), err
    assert "Traceback" not in err


def test_plot_path_checked_by_the_api_too(tmp_path):
    with pytest.raises(SceneError, match=r"`plot`: the folder .* does not exist"):
        scenes.run("spring-mass", t_end=0.1, plot=tmp_path / "missing" / "x.png")


@pytest.mark.parametrize("value", ["-1", "0"])
def test_positive_parameter_refused(value, capsys):
    code, out, err = _main(["run", "simple-pendulum", "--param", f"m={value}"], capsys)
    assert code == 2
    assert f"parameter `m` must be > 0 (the scene declares it positive); got {float(value):g}" \
        in err


def test_positive_parameter_refused_by_the_api():
    with pytest.raises(SceneError, match=r"parameter `L` must be > 0"):
        scenes.run("double-pendulum", t_end=0.1, params={"L": -2.0})


def test_verlet_accepted_where_the_equations_do_not_depend_on_velocities(capsys):
    # The spring-mass equations are m x'' = -k x: no q' in them, so a method for
    # q'' = a(t, q) applies (it was refused, saying the equations depend on q').
    code, out, err = _main(["run", "spring-mass", "--method", "verlet", "--step", "0.001",
                            "--t-end", "1"], capsys)
    assert code == 0, err
    assert "with verlet (step=0.001)" in out
    # closed form x = 0.5 cos(2 t) (m = 1, k = 4, x0 = 0.5, x0' = 0); Stormer-Verlet is of
    # order 2, error ~ h^2 w^3 t / 24 ~ 3e-7 here
    final = out.split("final state: q = [")[1].split("]")[0]
    import math
    assert abs(float(final) - 0.5 * math.cos(2.0)) < 1e-5


def test_verlet_refused_with_the_right_reason(capsys):
    code, out, err = _main(["run", "double-pendulum", "--method", "verlet", "--step", "0.01"],
                           capsys)
    assert code == 2
    assert "depend on q'" in err and "verlet" in err


def test_unexpected_error_is_one_line_without_debug(capsys, monkeypatch):
    def boom(*args, **kwargs):
        raise RuntimeError("something broke")

    monkeypatch.setattr(cli, "run", boom)
    code, out, err = _main(["run", "spring-mass"], capsys)
    assert code == 1
    assert err.strip() == ("rigidmech: internal error: RuntimeError: something broke "
                           "(run again with --debug for the traceback)")


def test_debug_shows_the_traceback(capsys, monkeypatch):
    def boom(*args, **kwargs):
        raise RuntimeError("something broke")

    monkeypatch.setattr(cli, "run", boom)
    with pytest.raises(RuntimeError, match="something broke"):
        cli.main(["run", "spring-mass", "--debug"])


def test_keyboard_interrupt_is_one_line(capsys, monkeypatch):
    def interrupted(*args, **kwargs):
        raise KeyboardInterrupt

    monkeypatch.setattr(cli, "run", interrupted)
    code, out, err = _main(["run", "spring-mass"], capsys)
    assert code == 130
    assert err.strip() == "rigidmech: interrupted"


@pytest.mark.slow
def test_sigint_to_a_long_run_ends_with_one_line(tmp_path):
    """A real Ctrl-C (SIGINT) sent to ``python -m rigidmech run ... --t-end 1e6`` after it
    started: one line on stderr naming the time reached, exit status 130, no traceback, and
    the partial output written (the samples computed so far and the state reached, status
    "interrupted")."""
    env = dict(os.environ, PYTHONUNBUFFERED="1")
    proc = subprocess.Popen(
        [sys.executable, "-m", "rigidmech", "run", "double-pendulum", "--t-end", "1e6",
         "--samples", "100001", "--save", "out.csv", "--plot", "out.png"],
        cwd=tmp_path, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=env)
    time.sleep(10.0)  # import, derive, compile and be integrating (a loaded machine: slow)
    proc.send_signal(signal.SIGINT)
    out, err = proc.communicate(timeout=120)
    assert proc.returncode == 130, (out, err)
    assert "Traceback" not in err
    lines = err.strip().splitlines()
    assert len(lines) == 1, err
    found = re.fullmatch(r"rigidmech: interrupted at t = (\S+) \(the samples up to t = (\S+) "
                         r"and the state reached there are kept, in out\.png and out\.csv\)",
                         lines[0])
    assert found, lines[0]
    t_reached, t_sample = float(found.group(1)), float(found.group(2))
    assert 10 < t_reached < 1e6 and t_reached - 10 <= t_sample <= t_reached
    assert (tmp_path / "out.png").stat().st_size > 1000
    sim = load_simulation(tmp_path / "out.csv")
    assert sim.status == "interrupted"
    assert sim.names == ("theta1", "theta2")
    assert sim.t[0] == 0.0 and sim.t[-2] == pytest.approx(t_sample, rel=1e-5)
    assert np.allclose(np.diff(sim.t[:-1]), 10.0)  # 1e6 / (100001 - 1)
    assert sim.t_stop == pytest.approx(t_reached, rel=1e-5)
    assert sim.t[-1] == sim.t_stop  # the state reached, after the samples (issue 19)
    assert sim.q[:, 0].tolist() == [2.0, -0.2]  # the scene's initial state


def test_save_path_is_checked_before_the_run(capsys, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    started = []
    monkeypatch.setattr(cli, "run", lambda *a, **k: started.append(1))
    for name, match in [("out.txt", r"--save: unknown file type '\.txt'; one of \.npz, \.csv"),
                        (os.path.join("missing", "o.csv"),
                         r"--save: the folder .*missing.* does not exist")]:
        code, out, err = _main(["run", "spring-mass", "--save", name], capsys)
        assert code == 2 and not started
        assert re.search(match, err) and len(err.strip().splitlines()) == 1, err


@pytest.mark.parametrize("value", ["0", "-3", "2.5", "many"])
def test_max_steps_must_be_a_positive_integer(value, capsys):
    code, out, err = _main(["run", "spring-mass", "--max-steps", value], capsys)
    assert code == 2
    assert f"expected a whole number >= 1; got '{value}'" in err


def test_max_steps_reached_keeps_the_partial_output(capsys, tmp_path):
    path = tmp_path / "run.npz"
    code, out, err = _main(["run", "spring-mass", "--max-steps", "20", "--save", str(path)],
                           capsys)
    assert code == 1
    lines = err.strip().splitlines()
    assert len(lines) == 1
    assert lines[0].startswith("rigidmech: integration failed: The maximum number of steps "
                               "`max_steps` = 20 was reached at t = ")
    assert lines[0].endswith(f"; partial output in {path}")
    sim = load_simulation(path)
    assert sim.status == "failed" and 0 < sim.t[-1] < 10
    # spring-mass: x = 0.5 cos(2 t) (m = 1, k = 4)
    assert np.allclose(sim.q[0], 0.5 * np.cos(2 * sim.t), atol=1e-8)


def test_progress_options(capsys):
    for flag in ("--progress", "--no-progress"):
        code, out, err = _main(["run", "spring-mass", "--t-end", "0.5", flag], capsys)
        assert code == 0, err


def test_step_larger_than_the_duration_is_refused(capsys):
    code, out, err = _main(["run", "spring-mass", "--method", "rk4", "--step", "2",
                            "--t-end", "1"], capsys)
    assert code == 2
    assert "`step` = 2 exceeds the duration `t_end` = 1" in err
