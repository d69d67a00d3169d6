"""The command line checks every option and output path before the run, and reports every
failure in one line (issue: a run that never loses work).

Each test here failed on the command line before these checks: a bad ``--plot`` path was found
only after the whole run (with a traceback, or a message naming a file it did not write), there
was no ``--version``, ``--param m=-1`` was accepted for a positive constant, and
``--method verlet`` was refused on the spring-mass scene with a wrong reason.
"""

import os
import signal
import subprocess
import sys
import time

import pytest

import rigidmech
from rigidmech import scenes
from rigidmech._core.errors import SceneError
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
    started: one line on stderr, exit status 130, no traceback."""
    env = dict(os.environ, PYTHONUNBUFFERED="1")
    proc = subprocess.Popen(
        [sys.executable, "-m", "rigidmech", "run", "double-pendulum", "--t-end", "1e6"],
        cwd=tmp_path, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=env)
    time.sleep(6.0)  # import, derive, compile and be integrating
    proc.send_signal(signal.SIGINT)
    out, err = proc.communicate(timeout=60)
    assert proc.returncode == 130, (out, err)
    assert "Traceback" not in err
    assert err.strip().splitlines()[-1] == "rigidmech: interrupted"
