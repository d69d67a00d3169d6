"""The run pipeline of a scene: derive, compile, integrate, check the energy, plot (book,
ch. 27.2).

:func:`run` takes a :class:`~rigidmech.scenes.Scene` (or its name), overrides of its defaults,
and goes through the main path of data of rigidmech: the builder assembles the system, the
fundamental principle gives M(q) q'' = f (``derive``), the right-hand side is compiled once
(``compile``), a solver of :mod:`rigidmech.ode` integrates it (``integrate``) and the total
mechanical energy is followed along the motion (``energy``). Each stage is timed and the whole
is returned as an immutable :class:`RunReport`.
"""

from __future__ import annotations

import math
import os
import re
import time
from types import MappingProxyType

import sympy as sp

from .. import ode
from .._core.errors import SceneError
from ..dynamics import EquationsOfMotion, Simulation
from .catalogue import Scene, get

__all__ = ["RunReport", "run", "equations_text", "plot_simulation", "check_plot_path"]
__all__ += ["check_save_path"]


def equations_text(eqs: EquationsOfMotion, *, pretty: bool = False) -> str:
    """The equations of motion M(q) q'' = f as readable text, one line per equation.

    Parameters
    ----------
    eqs : EquationsOfMotion
    pretty : bool
        Use sympy's 2-D pretty printer (unicode) instead of one-line ``str`` forms.

    Examples
    --------
    >>> from rigidmech import scenes
    >>> eqs = scenes.get("simple-pendulum").build().system.equations_of_motion()
    >>> print(equations_text(eqs))
    (L**2*m/3)*theta_ddot = -L*g*m*sin(theta)/2
    """
    # q(t), q'(t) printed q, q_dot (reading only)
    display = eqs.display_rule()
    M, f = eqs.mass_matrix.xreplace(display), eqs.forcing.xreplace(display)
    acc = [sp.Symbol(name + "_ddot", real=True) for name in eqs.names]
    n = len(acc)
    if pretty:  # dotted letters in 2-D: theta1_dot -> thetadot1, shown with a dot above
        names = [re.fullmatch(r"(.*?)(\d*)", name).groups() for name in eqs.names]
        rule = {display[u]: sp.Symbol(f"{a}dot{d}", real=True)
                for u, (a, d) in zip(eqs.u, names, strict=True)}
        acc = [sp.Symbol(f"{a}ddot{d}", real=True) for a, d in names]
        M, f = M.xreplace(rule), f.xreplace(rule)
        lhs = sp.MatMul(M, sp.Matrix(acc), evaluate=False)
        return sp.pretty(sp.Eq(lhs, f, evaluate=False), use_unicode=True, wrap_line=False)
    lines = []
    for i in range(n):
        terms = [f"({sp.sstr(M[i, j])})*{acc[j]}" for j in range(n) if M[i, j] != 0]
        lines.append(f"{' + '.join(terms) or '0'} = {sp.sstr(f[i])}")
    return "\n".join(lines)


class RunReport:
    """The outcome of :func:`run`: what was integrated, how long each stage took, and the
    result.

    Examples
    --------
    >>> from rigidmech import scenes
    >>> report = scenes.run("simple-pendulum", t_end=1.0)
    >>> report.energy_drift < 1e-8
    True

    Attributes
    ----------
    scene : Scene
    parameters : mapping str -> float
        The parameter values used (defaults with the overrides).
    q0, u0 : tuple of float
        The initial state used.
    t_end, method, rtol, atol, step
        The integration settings used.
    equations : EquationsOfMotion
    simulation : Simulation
    timings : mapping str -> float
        Wall times in seconds of ``derive`` (build and fundamental principle), ``compile``
        (right-hand side), ``integrate`` and ``energy`` (energy derived, compiled and evaluated
        along the motion).
    nfev, nsteps : int
        Evaluations of the right-hand side and steps of the solver.
    energy_drift : float or None
        ``max |E(t) - E(0)| / scale`` along the motion (the scale of
        :meth:`Simulation.energy_scale`; None without a potential energy, or when T + V is
        not conserved by an exact motion: explicit time dependence, dampers; see
        :meth:`Simulation.energy_not_conserved`).
    final_q, final_u : tuple of float
        State at ``t_end``.
    plot_path : str or None
        Where the plot was written.
    status, message : str
        How the run ended (:attr:`Simulation.status`) and why; the final state is the last
        sample computed.
    save_path : str or None
        Where the samples were saved (:meth:`Simulation.save`).
    """

    __slots__ = ("scene", "parameters", "q0", "u0", "t_end", "method", "rtol", "atol", "step",
                 "equations", "simulation", "timings", "nfev", "nsteps", "energy_drift",
                 "final_q", "final_u", "plot_path", "status", "message", "save_path")

    def __init__(self, **fields):
        for name in self.__slots__:
            object.__setattr__(self, name, fields[name])

    def __setattr__(self, name, value):
        raise AttributeError(f"RunReport is immutable; cannot set {name!r}.")

    def equations_text(self, *, pretty: bool = False) -> str:
        """The equations of motion as text (see :func:`equations_text`)."""
        return equations_text(self.equations, pretty=pretty)

    def summary(self, *, pretty: bool = False) -> str:
        """Several lines for a terminal: scene, equations, settings, energy drift, timings,
        and the notes of the simulation (values given for constants that dropped out of the
        equations, ignored)."""
        sc = self.scene
        coords = ", ".join(sc.coordinates)
        params = ", ".join(f"{k}={v:g}" for k, v in self.parameters.items())
        tol = (f"step={self.step:g}" if self.step is not None
               else f"rtol={self.rtol:g}, atol={self.atol:g}")
        ms = {k: 1e3 * v for k, v in self.timings.items()}
        drift = "n/a (no potential energy, or one that depends on time)" if (
            self.energy_drift is None) else (
            f"{self.energy_drift:.3e}")
        lines = [
            f"{sc.title} ({sc.name}, book {sc.section})",
            f"parameters of situation q = ({coords}); {params}",
            "equations of motion M(q) q'' = f(q, q', t):",
            *("  " + line for line in self.equations_text(pretty=pretty).splitlines()),
            f"integrated t in [0, {self.t_end:g}] with {self.method} ({tol}) from "
            f"q0 = {list(self.q0)}, u0 = {list(self.u0)}",
            *([f"the run ended early ({self.status}): {self.message}"]
              if self.status not in ("finished", "event") else []),
            f"final state: q = {[float(f'{x:.10g}') for x in self.final_q]}, "
            f"q' = {[float(f'{x:.10g}') for x in self.final_u]}"
            + ("" if self.status == "finished" else f" at t = {self.simulation.t[-1]:g}"),
            f"energy drift: {drift}",
            f"timings: derive {ms['derive']:.1f} ms, compile {ms['compile']:.1f} ms, "
            f"integrate {ms['integrate']:.1f} ms ({self.nfev} evaluations, {self.nsteps} "
            f"steps), energy {ms['energy']:.1f} ms",
        ]
        lines.extend(f"note: {note}" for note in self.simulation.notes)
        if self.plot_path is not None:
            lines.append(f"plot written to {self.plot_path}")
        if self.save_path is not None:
            lines.append(f"samples saved to {self.save_path}")
        return "\n".join(lines)

    def __str__(self):
        return self.summary()

    def __repr__(self):
        return (f"RunReport(scene={self.scene.name!r}, t_end={self.t_end:g}, "
                f"method={self.method!r}, nfev={self.nfev}, energy_drift={self.energy_drift!r})")


def _finite(value, what):
    try:
        x = float(value)
    except (TypeError, ValueError):
        raise SceneError(f"{what} must be a number; got {value!r}.") from None
    if not math.isfinite(x):
        raise SceneError(f"{what} must be finite; got {value!r}.")
    return x


def _state(values, default, n, what, scene):
    if values is None:
        return default
    try:
        values = tuple(values)
    except TypeError:
        raise SceneError(
            f"`{what}` must be a sequence of {n} numbers; got {values!r}.") from None
    if len(values) != n:
        raise SceneError(
            f"`{what}` must give {n} values for scene {scene.name!r} (one per coordinate "
            f"{', '.join(scene.coordinates)}); got {len(values)}: {list(values)}.")
    return tuple(_finite(v, f"`{what}` entry {i}") for i, v in enumerate(values))


def check_plot_path(path, argument="plot") -> str:
    """Check, before a run, that a figure can be written at ``path``: its folder exists and
    its extension is a file type matplotlib writes. Returns the path as a string.

    Parameters
    ----------
    path : str or path-like
    argument : str
        The name of the argument in the error message (``"--plot"`` on the command line).

    Raises
    ------
    SceneError
        No extension, an unknown extension, or a folder that does not exist.

    Examples
    --------
    >>> check_plot_path("pendulum.png")
    'pendulum.png'
    >>> check_plot_path("pendulum.xyz")                        # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    rigidmech._core.errors.SceneError: `plot`: unknown file type '.xyz'; one of ...
    """
    from matplotlib.backend_bases import FigureCanvasBase

    name = f"`{argument}`" if not argument.startswith("-") else argument
    text = str(path)
    folder, base = os.path.split(text)
    stem, ext = os.path.splitext(base)
    types = sorted(FigureCanvasBase.get_supported_filetypes())
    if not base or not ext:
        raise SceneError(f"{name}: {text!r} has no file extension; give one of "
                         f"{', '.join('.' + e for e in types)} (e.g. {text}.png).")
    if ext[1:].lower() not in types:
        raise SceneError(f"{name}: unknown file type {ext!r}; one of "
                         f"{', '.join('.' + e for e in types)}.")
    if folder and not os.path.isdir(folder):
        raise SceneError(f"{name}: the folder {folder!r} does not exist; create it first.")
    return text


def check_save_path(path, argument="save") -> str:
    """Check, before a run, that the samples can be saved at ``path``: a ``.npz`` or ``.csv``
    extension, an existing folder. Returns the path as a string.

    Examples
    --------
    >>> check_save_path("run.csv")
    'run.csv'
    >>> check_save_path("run.txt")
    Traceback (most recent call last):
    ...
    rigidmech._core.errors.SceneError: `save`: unknown file type '.txt'; one of .npz, .csv.
    """
    name = f"`{argument}`" if not argument.startswith("-") else argument
    text = str(path)
    folder, base = os.path.split(text)
    ext = os.path.splitext(base)[1]
    if ext.lower() not in (".npz", ".csv"):
        raise SceneError(f"{name}: unknown file type {ext or 'none'!r}; one of .npz, .csv.")
    if folder and not os.path.isdir(folder):
        raise SceneError(f"{name}: the folder {folder!r} does not exist; create it first.")
    return text


def _positive(values, built):
    """Values of constants declared positive (``rm.constants(..., positive=True)``) must
    be > 0: a negative mass or length gives equations with no physical meaning."""
    eqs = built.system.equations_of_motion()
    for symbol in eqs.parameters:
        name = str(symbol)
        if symbol.is_positive and name in values and not values[name] > 0:
            raise SceneError(f"parameter `{name}` must be > 0 (the scene declares it "
                             f"positive); got {values[name]:g}.")


def _method(method, step):
    known = ode.methods()
    if not isinstance(method, str) or method not in known:
        raise SceneError(f"unknown method {method!r}; known methods: {', '.join(known)}.")
    fixed = method in ode.methods("fixed") + ode.methods("second_order")
    if fixed and step is None:
        raise SceneError(f"method {method!r} has a fixed step: give `step` (--step).")
    if not fixed and step is not None:
        raise SceneError(f"`step` is only for fixed-step methods; {method!r} is adaptive.")
    if step is not None:
        step = _finite(step, "`step`")
        if step <= 0:
            raise SceneError(f"`step` must be > 0; got {step:g}.")
    return step


def run(scene, *, t_end=None, params=None, q0=None, u0=None, method=None, rtol=None,
        atol=None, step=None, n_output=1001, plot=None, save=None, max_steps=None,
        progress=None, dense_output=True) -> RunReport:
    """Derive, compile and integrate a scene; follow its energy; optionally plot it.

    Parameters
    ----------
    scene : Scene or str
        A scene of the catalogue or its name.
    t_end : float, optional
        Duration (default: the scene's).
    params : mapping str -> float, optional
        Overrides of the scene's parameter values (``{"m": 2, "L": 0.5}``).
    q0, u0 : sequence of float, optional
        Initial state (default: the scene's).
    method, rtol, atol : optional
        Integration method of :func:`rigidmech.ode.solve` and tolerances (default: the
        scene's). Fixed-step methods need ``step``.
    n_output : int
        Number of evenly spaced output times.
    plot : str or path-like, optional
        Write a figure (coordinates and relative energy error against time) there; works
        without a display (matplotlib's Agg canvas, no pyplot). The path is checked before
        the run (:func:`check_plot_path`).
    save : str or path-like, optional
        Save the samples there (``.npz`` or ``.csv``, :meth:`Simulation.save`); checked
        before the run (:func:`check_save_path`).
    max_steps : int, optional
        Largest number of steps of the solver (default 10^6).
    progress : None, bool or callable
        As for :meth:`EquationsOfMotion.simulate` (default: a bar on a terminal only).
    dense_output : bool
        Keep the solver's continuous solution (``report.simulation.result.sol``), default
        True; its memory grows with the number of steps: turn it off for long runs (the
        command line does), memory then follows the ``n_output`` samples.

    Returns
    -------
    RunReport
        Also for a run that fails or is interrupted: it holds the samples computed so far
        (plotted and saved if asked), see ``status`` and ``message``.

    Raises
    ------
    SceneError
        Unknown scene, parameter or method; malformed values; a value <= 0 for a constant
        the scene declares positive; wrong length of ``q0``/``u0``; a plot path that cannot
        be written; a method for q'' = a(t, q) on equations that depend on q'.

    Examples
    --------
    >>> from rigidmech import scenes
    >>> rep = scenes.run("simple-pendulum", t_end=1.0, params={"L": 0.5})
    >>> rep.parameters["L"], rep.energy_drift < 1e-8
    (0.5, True)
    >>> scenes.run("simple-pendulum", params={"l": 1})
    Traceback (most recent call last):
    ...
    rigidmech._core.errors.SceneError: unknown parameter 'l' for scene 'simple-pendulum'; ...
    """
    scene = get(scene)
    if not isinstance(scene, Scene):  # pragma: no cover - get() guarantees it
        raise SceneError(f"`scene` must be a Scene or a name; got {scene!r}.")
    values = scene.defaults
    for name, value in dict(params or {}).items():
        if name not in values:
            raise SceneError(
                f"unknown parameter {name!r} for scene {scene.name!r}; its parameters are "
                f"{', '.join(values)}.")
        values[name] = _finite(value, f"parameter `{name}`")
    n = scene.dof
    q0 = _state(q0, scene.q0, n, "q0", scene)
    u0 = _state(u0, scene.u0, n, "u0", scene)
    t_end = scene.t_end if t_end is None else _finite(t_end, "`t_end`")
    if t_end <= 0:
        raise SceneError(f"`t_end` must be > 0; got {t_end:g}.")
    method = scene.method if method is None else method
    step = _method(method, step)
    rtol = scene.rtol if rtol is None else _finite(rtol, "`rtol`")
    atol = scene.atol if atol is None else _finite(atol, "`atol`")
    if step is None and not (rtol > 0 and atol >= 0):
        raise SceneError(f"`rtol` must be > 0 and `atol` >= 0; got rtol={rtol:g}, "
                         f"atol={atol:g}.")
    if plot is not None:
        check_plot_path(plot)
    if save is not None:
        check_save_path(save)
    if max_steps is not None and (isinstance(max_steps, bool) or not isinstance(
            max_steps, int) or max_steps < 1):
        raise SceneError(f"`max_steps` must be an integer >= 1; got {max_steps!r}.")
    if step is not None and step > t_end:
        raise SceneError(f"`step` = {step:g} exceeds the duration `t_end` = {t_end:g}.")

    timings = {}
    start = time.perf_counter()
    built = scene.build()
    eqs = built.system.equations_of_motion()
    timings["derive"] = time.perf_counter() - start
    _positive(values, built)
    if method in ode.methods("second_order") + ode.methods("adaptive_second_order") and any(
            eqs.forcing.has(u) or eqs.mass_matrix.has(u) for u in eqs.u):
        raise SceneError(
            f"method {method!r} integrates q'' = a(t, q) only; the equations of scene "
            f"{scene.name!r} depend on q' too: choose another method.")
    start = time.perf_counter()
    eqs.rhs(**values)  # compiles once; simulate() reuses the compiled function
    timings["compile"] = time.perf_counter() - start
    sim = eqs.simulate(t=(0.0, t_end), q0=q0, u0=u0, method=method, rtol=rtol, atol=atol,
                       step=step, n_output=n_output, params=values, progress=progress,
                       dense_output=dense_output,
                       **({"max_steps": max_steps} if max_steps is not None else {}))
    timings["integrate"] = sim.elapsed
    start = time.perf_counter()
    drift = (sim.energy_drift() if eqs.energy is not None and sim.t.size
             and sim.energy_not_conserved() is None else None)
    timings["energy"] = time.perf_counter() - start
    plot_path = None
    if plot is not None:
        plot_path = str(plot)
        plot_simulation(sim, plot_path, title=f"{scene.title} ({scene.section})",
                        units=scene.units, time_unit=scene.time_unit)
    save_path = sim.save(save, units=scene.units) if save is not None else None
    return RunReport(
        scene=scene, parameters=MappingProxyType(values), q0=q0, u0=u0, t_end=t_end,
        method=method, rtol=rtol, atol=atol, step=step, equations=eqs, simulation=sim,
        timings=MappingProxyType(timings), nfev=int(sim.result.nfev),
        nsteps=int(getattr(sim.result, "nsteps", 0) or 0), energy_drift=drift,
        final_q=tuple(float(x) for x in sim.q[:, -1]),
        final_u=tuple(float(x) for x in sim.u[:, -1]), plot_path=plot_path,
        status=sim.status, message=sim.message, save_path=save_path)


def plot_simulation(sim: Simulation, path, *, title=None, units=None, degrees=False,
                    time_unit="s"):
    """Write a figure of the coordinates (one panel each, labelled with its name and unit,
    see :meth:`Simulation.plot <rigidmech.dynamics.Simulation.plot>`) and of the relative
    energy error against time. Returns the figure.

    Uses :class:`matplotlib.figure.Figure` directly (Agg canvas, no pyplot state) with
    constrained layout (no label cut): works headless and leaves the user's matplotlib
    backend alone.

    Examples
    --------
    >>> import os, tempfile
    >>> from rigidmech import scenes
    >>> report = scenes.run("spring-mass", t_end=1.0)
    >>> path = os.path.join(tempfile.mkdtemp(), "spring.png")
    >>> fig = plot_simulation(report.simulation, path, units={"x": "m"})
    >>> os.path.getsize(path) > 1000, [a.get_ylabel() for a in fig.axes][0]
    (True, '$x$ [m]')
    """
    from matplotlib.figure import Figure

    n = len(sim.names)
    has_energy = sim.equations is not None and sim.equations.energy is not None
    fig = Figure(figsize=(7, 1.4 + 1.6 * (n + has_energy)), layout="constrained")
    axes = fig.subplots(n + has_energy, 1, sharex=True, squeeze=False)[:, 0]
    sim.plot(ax=list(axes[:n]), units=units, degrees=degrees)
    if has_energy:
        e = sim.energy()
        scale = sim.energy_scale() or 1.0
        axes[-1].plot(sim.t, (e - e[0]) / scale)
        axes[-1].set_ylabel("$(E - E_0)$ / scale")
        axes[-1].grid(True, alpha=0.3)
    for a in axes[:-1]:
        a.set_xlabel("")
    axes[-1].set_xlabel(f"t [{time_unit}]")
    if title:
        fig.suptitle(title)
    fig.savefig(path, dpi=100)
    return fig
