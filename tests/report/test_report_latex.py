"""The report's LaTeX compiles with pdflatex (Debian's texlive-latex-base and
texlive-latex-recommended; CI installs them, see .ci/run), and its other forms (fragment,
Jupyter, .tex file) are what they say.

Without pdflatex the compiling tests skip on a developer's machine, and fail in CI (CI set):
a test that CI cannot run must not pass silently there.
"""

import contextlib
import os
import re
import shutil
import subprocess

import pytest
import sympy as sp

import rigidmech as rm
from rigidmech import models, report
from rigidmech.errors import ArgumentError, ArgumentTypeError

pytestmark = pytest.mark.filterwarnings("error")


def pdflatex():
    exe = shutil.which("pdflatex")
    if exe is None:
        message = ("pdflatex is not installed (Debian: apt-get install texlive-latex-base "
                   "texlive-latex-recommended)")
        if os.environ.get("CI"):
            pytest.fail(message + "; CI must compile the report")
        pytest.skip(message)
    return exe


def compile_tex(path):
    proc = subprocess.run(
        [pdflatex(), "-interaction=nonstopmode", "-halt-on-error", path.name],
        cwd=path.parent, capture_output=True, text=True, timeout=300, stdin=subprocess.DEVNULL)
    assert proc.returncode == 0, proc.stdout[-3000:]
    pdf = path.with_suffix(".pdf")
    assert pdf.exists() and pdf.stat().st_size > 0
    return pdf


@pytest.fixture(scope="module")
def pendulum_report(double_pendulum_report):
    return double_pendulum_report


@pytest.fixture(scope="module")
def disc_report():
    # long expressions named, closure conditions and multipliers: every kind of line
    return report.derivation(models.rolling_disc(), route="lagrange", simplify=False)


def test_double_pendulum_report_compiles(pendulum_report, tmp_path):
    path = pendulum_report.write(tmp_path / "double_pendulum.tex")
    assert path == tmp_path / "double_pendulum.tex"
    compile_tex(path)


def test_rolling_disc_report_with_named_expressions_compiles(disc_report, tmp_path):
    assert disc_report.named
    compile_tex(disc_report.write(tmp_path / "rolling disc_1.tex"))


def test_the_fragment_compiles_inside_a_document_with_amsmath(pendulum_report, tmp_path):
    fragment = pendulum_report.to_latex(standalone=False)
    assert r"\documentclass" not in fragment and r"\begin{document}" not in fragment
    path = tmp_path / "host.tex"
    path.write_text("\\documentclass{article}\n\\usepackage{amsmath}\n\\begin{document}\n"
                    + fragment + "\\end{document}\n", encoding="utf-8")
    compile_tex(path)


def test_the_document_uses_only_packages_of_texlive_latex_base(pendulum_report):
    document = pendulum_report.to_latex()
    used = {line.split("{")[1].rstrip("}") for line in document.splitlines()
            if line.startswith(r"\usepackage")}
    assert used == set(report.LATEX_PACKAGES) == {"amsmath", "geometry"}
    assert r"\begin{bmatrix}" in document    # the mass matrix, amsmath's bmatrix


def test_jupyter_latex_is_one_aligned_display(pendulum_report):
    tex = pendulum_report._repr_latex_()
    assert tex.startswith("$$\\begin{aligned}") and tex.endswith("\\end{aligned}$$")
    assert tex.count("$$") == 2
    assert r"\textbf{8. Equations of motion (ch. 20.2, 25.1.4)}" in tex


def test_write_refuses_another_suffix(pendulum_report, tmp_path):
    with pytest.raises(ArgumentError, match=r"`path` must name a \.tex file; got .*report\.txt"):
        pendulum_report.write(tmp_path / "report.txt")
    with pytest.raises(ArgumentTypeError, match="`path` must be a str or a path; got int"):
        pendulum_report.write(3)


def test_without_pdflatex_the_compile_test_skips_locally_and_fails_in_ci(monkeypatch):
    monkeypatch.setattr(shutil, "which", lambda name: None)
    monkeypatch.setenv("CI", "true")
    with pytest.raises(pytest.fail.Exception, match="CI must compile the report"):
        pdflatex()
    monkeypatch.delenv("CI")
    with pytest.raises(pytest.skip.Exception, match="pdflatex is not installed"):
        pdflatex()


def test_names_with_latex_special_characters_compile(tmp_path):
    # a body, points and actions whose names hold _ and # (two forces: Force#1, Force#2)
    x = rm.coordinates("x")
    m, k, F = rm.constants("m k F", positive=True)
    R0 = rm.Frame("R0")
    P = R0.point("P_1", x, 0, 0)
    body = rm.Body("block_&_co", frame=R0.translated("R_b", P), mass=m, centre=P)
    s = rm.System(galilean=R0)
    s.connect(R0, body, rm.joints.Prismatic(at=P, axis=R0.i), label="s_1")
    s.act(rm.Force(on=body, vector=F * R0.i, at=P))
    s.act(rm.Force(on=body, vector=-F / 2 * R0.i, at=P))
    s.act(rm.Spring(k, 0, a=R0.origin, b=P, on_b=body))
    got = report.derivation(s)
    text = got.to_text()
    assert "{A(Force#1 -> block_&_co)}" in text and "{A(Force#2 -> block_&_co)}" in text
    assert "unknowns X_s_1, Y_s_1, L_s_1, M_s_1, N_s_1" in text
    compile_tex(got.write(tmp_path / "names.tex"))


_ARGUMENTS = {"n_link_pendulum": (3,), "spherical_chain": (2,), "four_bar_chain": (1,),
              "wheel_on_incline": (sp.Symbol("alpha"),), "sleigh_on_incline": (sp.Symbol("beta"),)}
_WITH_CONTACTS = ("sliding_ball", "eccentric_disc")   # refused: their equations follow regimes
_STATICS = ("ladder",)                                 # a problem of statics: no equations


@pytest.mark.slow
@pytest.mark.parametrize("name", [n for n in models.names()
                                  if n not in _WITH_CONTACTS + _STATICS])
def test_every_catalogue_model_gives_a_report_that_compiles(name, tmp_path):
    model = models.get(name).build(*_ARGUMENTS.get(name, ()))
    hyperstatic = model.system.hyperstatic_unknowns()  # planar loops of spatial pivots
    with (pytest.warns(rm.errors.HyperstaticWarning, match=re.escape(", ".join(hyperstatic)))
          if hyperstatic else contextlib.nullcontext()):
        got = report.derivation(model, simplify=False)
    assert got.equations.mass_matrix == model.system.equations_of_motion().mass_matrix
    compile_tex(got.write(tmp_path / f"{name}.tex"))
