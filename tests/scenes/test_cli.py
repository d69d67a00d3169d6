"""Tests of the command line ``python -m rigidmech`` (rigidmech.scenes.cli)."""

import subprocess
import sys

import pytest

from rigidmech import __main__ as entry
from rigidmech.scenes import cli


def test_entry_point_main_exists():
    # pyproject.toml: rigidmech = "rigidmech.__main__:main"
    assert entry.main is cli.main


def test_scenes_lists_the_catalogue(capsys):
    assert cli.main(["scenes"]) == 0
    out = capsys.readouterr().out.splitlines()
    assert out[0].split() == ["name", "title", "book", "dof", "parameters"]
    rows = {line.split()[0]: line for line in out[1:]}
    assert set(rows) == {"simple-pendulum", "double-pendulum", "slider-pendulum", "spring-mass",
                         "coulomb-oscillator", "rolling-cylinder",
                         "satellite", "moon-probe", "foucault-pendulum", "wagon-pendulum",
                         "block-on-incline", "cart-pendulum", "triple-pendulum", "four-bar",
                         "slider-crank", "wheel-on-incline", "heavy-top", "gyroscope",
                         "benchmark-bicycle"}
    assert " 2 " in rows["rolling-cylinder"] and "fs=0.12 fk=0.1" in rows["coulomb-oscillator"]
    assert "ch. 22.2.1" in rows["simple-pendulum"] and "m=1 L=1 g=9.81" in rows["simple-pendulum"]
    assert " 2 " in rows["double-pendulum"] and "M=2 m=1 L=1 g=9.81" in rows["slider-pendulum"]


def test_run_defaults_to_the_double_pendulum(capsys):
    assert cli.main(["run", "--t-end", "0.2"]) == 0
    out = capsys.readouterr().out
    assert out.startswith("Double pendulum of two uniform rods (double-pendulum, book ch. "
                          "25.4.3, 27.5)")
    assert "equations of motion M(q) q'' = f(q, q', t):" in out
    assert "(4*L**2*m/3)*theta1_ddot" in out
    assert "energy drift: " in out
    assert "timings: derive " in out and " ms, compile " in out and " evaluations" in out


def test_run_with_every_option_and_a_plot(capsys, tmp_path):
    path = tmp_path / "pendulum.png"
    argv = ["run", "simple-pendulum", "--t-end", "0.5", "--method", "dopri5", "--rtol", "1e-9",
            "--atol", "1e-11", "--param", "m=2", "--param", "L=0.5", "--q0", "-0.3",
            "--u0", "0.1", "--plot", str(path), "--pretty"]
    assert cli.main(argv) == 0
    out = capsys.readouterr().out
    assert "m=2, L=0.5, g=9.81" in out
    assert "with dopri5 (rtol=1e-09, atol=1e-11) from q0 = [-0.3], u0 = [0.1]" in out
    assert f"plot written to {path}" in out
    assert path.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_run_fixed_step(capsys):
    assert cli.main(["run", "spring-mass", "--method", "rk4", "--step", "0.01",
                     "--t-end", "0.1"]) == 0
    assert "with rk4 (step=0.01)" in capsys.readouterr().out


@pytest.mark.parametrize(
    ("argv", "match"),
    [
        pytest.param(["run", "quadruple-pendulum"], "unknown scene 'quadruple-pendulum'; known "
                     "scenes: simple-pendulum, double-pendulum", id="scene"),
        pytest.param(["run", "--param", "l=2"], "unknown parameter 'l' for scene "
                     "'double-pendulum'; its parameters are m, L, g.", id="param-name"),
        pytest.param(["run", "--param", "m"], "argument --param: expected NAME=VALUE "
                     "(e.g. --param m=2); got 'm'", id="param-form"),
        pytest.param(["run", "--param", "m=heavy"], "argument --param: the value of m must be "
                     "a number; got 'heavy'", id="param-value"),
        pytest.param(["run", "--param", "m=1", "--param", "m=2"], "--param m given twice",
                     id="param-twice"),
        pytest.param(["run", "--q0", "1"], "`q0` must give 2 values for scene "
                     "'double-pendulum' (one per coordinate theta1, theta2); got 1", id="q0-len"),
        pytest.param(["run", "--q0", "1,x"], "argument --q0: expected comma-separated numbers "
                     "such as 2.0,-0.2; got '1,x'", id="q0-value"),
        pytest.param(["run", "--u0", "nan,0"], "`u0` entry 0 must be finite; got nan",
                     id="u0-nan"),
        pytest.param(["run", "--method", "rk99"], "unknown method 'rk99'; known methods: ",
                     id="method"),
        pytest.param(["run", "--method", "rk4"], "method 'rk4' has a fixed step: give `step` "
                     "(--step).", id="fixed-no-step"),
        pytest.param(["run", "--t-end", "soon"], "argument --t-end: invalid float value: "
                     "'soon'", id="t-end-value"),
        pytest.param(["run", "--t-end", "-1"], "`t_end` must be > 0; got -1", id="t-end-sign"),
        pytest.param(["fly"], "argument {run,scenes,modes}: invalid choice: 'fly'", id="command"),
        pytest.param([], "the following arguments are required: {run,scenes,modes}",
                     id="no-command"),
    ],
)
def test_misuse_prints_one_line_and_exits_2(capsys, argv, match):
    assert cli.main(argv) == 2
    captured = capsys.readouterr()
    assert captured.out == ""
    lines = captured.err.splitlines()
    assert len(lines) == 1, captured.err
    assert lines[0].startswith("rigidmech: error: ")
    assert match in lines[0]
    assert "Traceback" not in captured.err


def test_negative_initial_values_need_no_equals_sign(capsys):
    assert cli.main(["run", "--q0", "-0.5,0.2", "--t-end", "0.05"]) == 0
    assert "q0 = [-0.5, 0.2]" in capsys.readouterr().out


def test_help_exits_0(capsys):
    assert cli.main(["run", "--help"]) == 0
    assert "--t-end T" in capsys.readouterr().out


def test_python_m_rigidmech_in_a_subprocess():
    proc = subprocess.run([sys.executable, "-m", "rigidmech", "run", "double-pendulum",
                           "--t-end", "1"], capture_output=True, text=True, timeout=120)
    assert proc.returncode == 0, proc.stderr
    assert proc.stdout.startswith("Double pendulum of two uniform rods")
    assert "energy drift: " in proc.stdout
