"""The README's example runs as written (with the plot sent to a temporary file)."""

import pathlib
import re

import sympy as sp

README = pathlib.Path(__file__).resolve().parents[1] / "README.md"


def test_readme_example_runs(tmp_path, monkeypatch):
    code = re.search(r"```python\n(.*?)```", README.read_text(), re.S).group(1)
    monkeypatch.chdir(tmp_path)
    namespace = {}
    exec(compile(code, str(README), "exec"), namespace)  # noqa: S102 - our own README
    q1, q2 = namespace["eqs"].q
    m, L = namespace["m"], namespace["L"]
    expected = m * L**2 * sp.Matrix([[sp.Rational(4, 3), sp.cos(q1 - q2) / 2],
                                     [sp.cos(q1 - q2) / 2, sp.Rational(1, 3)]])
    assert sp.simplify(namespace["eqs"].mass_matrix - expected) == sp.zeros(2, 2)
    assert namespace["sim"].energy_drift() < 1e-7  # dop853 at rtol 1e-10 over 10 s
    assert (tmp_path / "pendulum.png").stat().st_size > 1000


def test_readme_keeps_exactly_two_setup_commands():
    text = README.read_text()
    block = text.split("## Set up on a fresh machine", 1)[1].split("```", 2)[1]
    lines = [ln for ln in block.splitlines() if ln.strip()]
    assert lines == [
        'python -m pip install -e . && python -m rigidmech run double-pendulum',
        'python -m pip install -e ".[test]" && python -m pytest -n auto',
    ]


def test_ci_runs_the_readmes_test_command():
    # .ci/run installs and tests the way the README says (kept in sync by hand, checked here)
    ci = (README.parent / ".ci" / "run").read_text()
    assert 'python -m pip install -e ".[test]"\n' in ci
    assert 'run_stage check "pytest" python -m pytest -n auto\n' in ci
