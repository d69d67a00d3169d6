"""The derivation report as a value: its steps, their lines, and its forms (plain text, LaTeX
document or fragment, Jupyter, a ``.tex`` file).

A :class:`Derivation` is made by :func:`rigidmech.report.derivation`; it holds the library's
own results (torsors, energies, equations, written with q(t)) for a program or a test to use,
and their shown form (plain symbols, long expressions named) for a reader.

Examples
--------
>>> from rigidmech import models, report
>>> rep = report.derivation(models.compound_pendulum())
>>> [s.title for s in rep.steps][:3]
['Parameters of situation', 'Kinematic torsors', 'Kinetic and dynamic torsors']
>>> print(rep.steps[1].to_text())
2. Kinematic torsors (ch. 9.2.4)
   {V(bar/R0)} = {theta_dot k_R1 ; 0}_O_R0
"""

from __future__ import annotations

import os
from pathlib import Path
from types import MappingProxyType
from typing import NamedTuple

from .._core.errors import ArgumentError, ArgumentTypeError
from ._display import tex_text

__all__ = ["Line", "Step", "Derivation", "LATEX_PACKAGES"]

#: The LaTeX packages a report's document loads (all in Debian's texlive-latex-base).
LATEX_PACKAGES = ("amsmath", "geometry")


class Line(NamedTuple):
    """One shown line of a step: ``label = value`` in plain text and in LaTeX (math mode),
    and a note (either may be empty: a note alone).

    Examples
    --------
    >>> from rigidmech import models, report
    >>> line = report.derivation(models.compound_pendulum()).steps[1].lines[0]
    >>> line.text
    '{V(bar/R0)} = {theta_dot k_R1 ; 0}_O_R0'
    >>> line.latex.startswith(r"\\{\\mathcal{V}(\\mathrm{bar}/R_{0})\\} =")
    True
    """

    text: str
    latex: str
    note: str = ""


class Step(NamedTuple):
    """One step of the derivation, the book's way: a title, the book's section, a sentence
    that says what is done, and its lines (text and LaTeX already rendered).

    Examples
    --------
    >>> Step(1, "Parameters of situation", "ch. 9.1", "", ()).heading
    '1. Parameters of situation (ch. 9.1)'
    """

    number: int
    title: str
    section: str
    intro: str
    lines: tuple   # of Line

    @property
    def heading(self) -> str:
        """``"n. Title (ch. x)"``."""
        return f"{self.number}. {self.title} ({self.section})"

    def to_text(self) -> str:
        """The step in plain text."""
        out = [self.heading]
        if self.intro:
            out.append("   " + self.intro)
        for text, _, note in self.lines:
            if text:
                out.append("   " + text + (f"   [{note}]" if note else ""))
            elif note:
                out.append("   " + note)
        return "\n".join(out)

    def to_latex(self) -> str:
        """The step as a LaTeX fragment (a starred subsection, one display per line)."""
        out = [rf"\subsection*{{{self.number}. {tex_text(self.title)} "
               rf"\normalfont\small({tex_text(self.section)})}}"]
        if self.intro:
            out.append(tex_text(self.intro))
        for _, tex, note in self.lines:
            if tex and note:
                out.append(rf"\[ {tex} \qquad \text{{\small ({tex_text(note)})}} \]")
            elif tex:
                out.append(rf"\[ {tex} \]")
            elif note:
                out.append(rf"\noindent{{\small {tex_text(note)}}}")
        return "\n".join(out)


class Derivation:
    """A system's equations of motion derived step by step, the book's way (ch. 9, 16, 18,
    25): an immutable value made by :func:`rigidmech.report.derivation`.

    Attributes
    ----------
    route : str
        ``"principle"`` (the fundamental principle projected on the partial kinematic
        torsors) or ``"lagrange"`` (Lagrange's equations).
    steps : tuple of Step
    named : tuple of (Symbol, expression)
        The names given to long expressions and their definitions (plain symbols).
    results : mapping
        The library's own results shown by the steps, written with q(t): ``"points"``,
        ``"kinematic"``, ``"kinetic"``, ``"dynamic"``, ``"kinetic_energy"`` (body name ->
        value), ``"partial"`` (body name -> tuple of torsors, one per coordinate),
        ``"actions"`` (label -> torsor), ``"kinetic_energy_total"`` (T of the set),
        ``"power_coefficients"``, ``"equations"`` and, on Lagrange's route, ``"momenta"``
        (dT/dq_i', one per coordinate).

    Examples
    --------
    >>> from rigidmech import models, report
    >>> rep = report.derivation(models.compound_pendulum(), route="lagrange")
    >>> rep.route, rep.equations.mass_matrix
    ('lagrange', Matrix([[L**2*m/3]]))
    >>> rep.kinetic_energy
    L**2*m*Derivative(theta(t), t)**2/6
    """

    __slots__ = ("_route", "_steps", "_named", "_results", "_title", "_named_lines")

    def __init__(self, *, route, steps, named, named_lines, results, title):
        self._route = route
        self._steps = tuple(steps)
        self._named = tuple(named)
        self._named_lines = tuple(named_lines)
        self._results = MappingProxyType(dict(results))
        self._title = title

    route = property(lambda self: self._route, doc="``'principle'`` or ``'lagrange'``.")
    steps = property(lambda self: self._steps, doc="The steps, a tuple of :class:`Step`.")
    named = property(lambda self: self._named,
                     doc="The named expressions: (symbol, definition) pairs.")
    results = property(lambda self: self._results,
                       doc="The library's results shown by the steps (a read-only mapping).")
    title = property(lambda self: self._title, doc="The report's title.")

    # -- the library's results, for programs and tests ------------------------------------
    def kinematic_torsor(self, body):
        """{V(S/R)} of ``body`` (a Body or its name) at the report's point for it (ch. 9.2.4).

        Examples
        --------
        >>> from rigidmech import models, report
        >>> rep = report.derivation(models.compound_pendulum(), simplify=False)
        >>> rep.kinematic_torsor("bar")
        KinematicTorsor(V(R1/R0): rotation=Derivative(theta(t), t)*R1.k, velocity=0, at=O_R0)
        >>> rep.partial_kinematic_torsors("bar")
        (Torsor(resultant=R1.k, moment=0, at=O_R0),)
        """
        return self._get("kinematic", body)

    def partial_kinematic_torsors(self, body) -> tuple:
        """The partial kinematic torsors {V_i(S/R)} of ``body``, one per coordinate, at the
        same point as :meth:`kinematic_torsor` (ch. 25.1.2)."""
        return self._get("partial", body)

    def kinetic_torsor(self, body):
        """{C(S/R)} of ``body`` at its mass centre (ch. 16.1.2).

        Examples
        --------
        >>> from rigidmech import models, report
        >>> rep = report.derivation(models.compound_pendulum(), simplify=False)
        >>> rep.kinetic_torsor("bar").moment
        L**2*m*Derivative(theta(t), t)/12*R1.k
        >>> rep.dynamic_torsor("bar").moment_at(rep.kinematic_torsor("bar").point)
        L**2*m*Derivative(theta(t), (t, 2))/3*R1.k
        """
        return self._get("kinetic", body)

    def dynamic_torsor(self, body):
        """{D(S/R)} of ``body`` at its mass centre (ch. 16.2.2)."""
        return self._get("dynamic", body)

    @property
    def kinetic_energy(self):
        """The kinetic energy T of the set of bodies (ch. 16.3.3)."""
        return self._results["kinetic_energy_total"]

    @property
    def action_torsors(self):
        """The action torsors shown, by label: the given actions (``"Gravity -> bar"``) and
        the connections' (``"R0 -> bar (1)"``, with their unknowns or multipliers).

        Examples
        --------
        >>> from rigidmech import models, report
        >>> rep = report.derivation(models.compound_pendulum(), simplify=False)
        >>> list(rep.action_torsors)
        ['Gravity -> bar', 'R0 -> bar (1)']
        >>> rep.action_torsors["R0 -> bar (1)"].moment
        L_1*R0.i + M_1*R0.j
        >>> rep.power_coefficients
        Matrix([[-L*g*m*sin(theta(t))/2]])
        """
        return self._results["actions"]

    @property
    def power_coefficients(self):
        """Q_i of the given actions (ch. 25.1.3), a column."""
        return self._results["power_coefficients"]

    @property
    def equations(self):
        """The equations of motion of the route, an
        :class:`~rigidmech.dynamics.EquationsOfMotion`."""
        return self._results["equations"]

    def _get(self, kind, body):
        name = getattr(body, "name", body)
        if name not in self._results["points"]:
            known = ", ".join(self._results["points"])
            raise ArgumentError(f"`body` must be a body of the report ({known}); got {body!r}.")
        if name not in self._results[kind]:
            raise ArgumentError(f"`body` {name} is massless: it has no {kind} torsor. Give it a "
                                "mass, or ask for another body.")
        return self._results[kind][name]

    # -- forms ----------------------------------------------------------------------------
    def to_text(self) -> str:
        """The report in plain text (also ``str(report)``).

        Examples
        --------
        >>> from rigidmech import models, report
        >>> text = report.derivation(models.compound_pendulum()).to_text()
        >>> print(text[text.index("8. Equations"):])
        8. Equations of motion (ch. 20.2, 25.1.4)
           M(q) q'' = f(q, q', t)
           M(q) = [[L**2*m/3]]   [mass matrix]
           f(q, q', t) = [[-L*g*m*sin(theta)/2]]
           (theta)  L**2*m*theta_ddot/3 = -L*g*m*sin(theta)/2
        <BLANKLINE>
        """
        parts = [f"{self._title}\n{'=' * len(self._title)}"]
        parts += [s.to_text() for s in self._steps]
        if self._named_lines:
            parts.append("Named expressions")
            parts += ["   " + text for text, _ in self._named_lines]
        return "\n\n".join(parts) + "\n"

    __str__ = to_text

    def to_latex(self, *, standalone: bool = True) -> str:
        """The report in LaTeX: a complete document (``standalone=True``, compiles with
        pdflatex and the packages of :data:`LATEX_PACKAGES`) or a fragment to include in
        one that loads amsmath (``standalone=False``).

        Examples
        --------
        >>> from rigidmech import models, report
        >>> rep = report.derivation(models.compound_pendulum(), simplify=False)
        >>> document = rep.to_latex()
        >>> [line.split("{")[1] for line in document.splitlines()[:3]]
        ['article}', 'amsmath}', 'geometry}']
        >>> "documentclass" in rep.to_latex(standalone=False)
        False
        """
        body = [s.to_latex() for s in self._steps]
        if self._named_lines:
            body.append(r"\subsection*{Named expressions}")
            body += [rf"\[ {tex} \]" for _, tex in self._named_lines]
        fragment = "\n\n".join(body) + "\n"
        if not standalone:
            return fragment
        return (
            "\\documentclass[11pt]{article}\n"
            "\\usepackage{amsmath}\n"
            "\\usepackage[margin=2cm]{geometry}\n"
            "\\allowdisplaybreaks\n"
            f"\\title{{{tex_text(self._title)}}}\n\\date{{}}\n"
            "\\begin{document}\n\\maketitle\n\n"
            f"{fragment}\n\\end{{document}}\n")

    def _repr_latex_(self):
        """Jupyter: the steps in one ``aligned`` display (MathJax renders it)."""
        rows = []
        for s in self._steps:
            rows.append(rf"&\textbf{{{_mj(s.heading)}}}")
            rows += [f"&{tex}" for _, tex, _ in s.lines if tex]
        if self._named_lines:
            rows.append(r"&\textbf{Named expressions}")
            rows += [f"&{tex}" for _, tex in self._named_lines]
        return "$$\\begin{aligned}\n" + " \\\\\n".join(rows) + "\n\\end{aligned}$$"

    def write(self, path) -> Path:
        """Write the LaTeX document to ``path`` (a ``.tex`` file); returns the path.

        Raises
        ------
        ArgumentError
            If ``path`` does not end with ``.tex``.

        Examples
        --------
        >>> import tempfile, pathlib
        >>> from rigidmech import models, report
        >>> rep = report.derivation(models.compound_pendulum(), simplify=False)
        >>> with tempfile.TemporaryDirectory() as tmp:
        ...     path = rep.write(pathlib.Path(tmp) / "pendulum.tex")
        ...     path.name, "documentclass" in path.read_text()
        ('pendulum.tex', True)
        """
        if not isinstance(path, (str, os.PathLike)):
            raise ArgumentTypeError(f"`path` must be a str or a path; got {type(path).__name__}.")
        path = Path(path)
        if path.suffix != ".tex":
            raise ArgumentError(
                f"`path` must name a .tex file; got {str(path)!r}. Pass e.g. "
                f"{str(path.with_suffix('.tex'))!r}.")
        path.write_text(self.to_latex(standalone=True), encoding="utf-8")
        return path

    def __repr__(self):
        return (f"Derivation(route={self._route!r}, steps={len(self._steps)}, "
                f"named={len(self._named)})")


def _mj(text):
    """Text for MathJax's ``\\textbf``: braces and underscores escaped."""
    return text.replace("{", r"\{").replace("}", r"\}").replace("_", r"\_")
