"""Ready-made motions with dry friction, run phase by phase (book, ch. 21.4, 23).

Each :class:`RegimeScene` poses a system from bodies (a :class:`~rigidmech.dynamics.System`
with a :class:`~rigidmech.actions.FrictionContact`), its parameters with default values and
its default initial state and duration; :func:`run_regime_scene` integrates it with
:func:`rigidmech.regimes.contact_motion`, which derives the regimes from the system, and
returns a :class:`RegimeReport` whose summary prints the phases (regime, start, end, what ended
each). ``python -m rigidmech run coulomb-oscillator`` and ``python -m rigidmech run
rolling-cylinder`` print these summaries. (The same motions written regime by regime are
:func:`rigidmech.regimes.coulomb_oscillator` and :func:`rigidmech.regimes.cylinder_on_incline`;
the tests check that both give the same phases.)
"""

from __future__ import annotations

import math
import time
from functools import lru_cache

import sympy as sp

from .. import ode
from .._core.errors import SceneError
from ..actions import Coulomb, FrictionContact, Spring, gravity
from ..dynamics import System
from ..inertia import disk
from ..kinematics import ContactKinematics
from ..kinetics import Body
from ..regimes import PhasedMotion, contact_motion
from ..vectors import Frame, coordinates
from .pipeline import _finite, check_plot_path, check_save_path

__all__ = ["RegimeScene", "RegimeReport", "regime_scenes", "regime_scene_names",
           "run_regime_scene", "regime_methods", "save_motion"]


@lru_cache(maxsize=8)
def _oscillator_system(fs, fk):
    """A block (centre (x, y)) on the floor y = 0, a spring of zero free length from the
    origin, the weight -m g j: the normal force is m g."""
    x, y = coordinates("x y")
    m, k, g = sp.symbols("m k g", positive=True)
    R0 = Frame("R0")
    G = R0.point("G", x, y, 0)
    R1 = R0.translated("R1", G)
    block = Body("block", frame=R1, mass=m, centre=G)
    system = System(galilean=R0)
    system.connect(R0, block, FrictionContact(ContactKinematics(
        R1, R0, at=R0.point("I", x, y, 0), normal=R0.j), friction=Coulomb(fs, fk)))
    system.act(gravity(-g * R0.j))
    system.act(Spring(k, 0, a=R0.origin, b=G, on_b=block))
    return system


@lru_cache(maxsize=8)
def _cylinder_system(fs, fk):
    """A solid cylinder (centre (x, y), rotation theta, x' = r theta' when rolling) on the
    incline y = 0 of angle alpha, x down the slope."""
    x, y, th = coordinates("x y theta")
    m, r, g, alpha = sp.symbols("m r g alpha", positive=True)
    R0 = Frame("R0")
    C = R0.point("C", x, y, 0)
    R1 = R0.rotated("R1", about=R0.k, angle=-th, origin=C)
    cylinder = Body("cylinder", frame=R1, mass=m, centre=C,
                    inertia=disk(m, r, axis=R1.k, centre=C))
    system = System(galilean=R0)
    system.connect(R0, cylinder, FrictionContact(ContactKinematics(
        R1, R0, at=R0.point("I", x, y - r, 0), normal=R0.j), friction=Coulomb(fs, fk)))
    system.act(gravity(g * (sp.sin(alpha) * R0.i - sp.cos(alpha) * R0.j)))
    return system


def _law(p):
    Coulomb(p["fs"], p["fk"])                 # refuses a negative or inconsistent coefficient
    return p["fs"], p["fk"]


def _positive(p, *names):
    bad = [f"{n}={p[n]:g}" for n in names if not p[n] > 0]
    if bad:
        raise SceneError(f"parameters {', '.join(names)} must be > 0; got {', '.join(bad)}.")


def _oscillator(p, q0, u0, t_end, **solver):
    _positive(p, "m", "k", "N")
    return contact_motion(_oscillator_system(*_law(p)), t_end, {"x": q0[0], "y": 0.0},
                          {"x": u0[0]}, **solver, m=p["m"], k=p["k"], g=p["N"] / p["m"])


def _cylinder(p, q0, u0, t_end, **solver):
    _positive(p, "r", "g")
    return contact_motion(_cylinder_system(*_law(p)), t_end,
                          {"x": q0[0], "y": p["r"], "theta": q0[1]},
                          {"x": u0[0], "theta": u0[1]}, **solver, m=1.0, r=p["r"],
                          g=p["g"], alpha=p["alpha"])


#: Default solver of the regime scenes: an adaptive method, whose events locate the switches.
DEFAULT_METHOD, DEFAULT_RTOL, DEFAULT_ATOL = "dop853", 1e-12, 1e-12


def regime_methods() -> tuple:
    """The integration methods a regime scene accepts: the adaptive ones of
    :mod:`rigidmech.ode` (their events locate the switches of regime on the dense output).

    Examples
    --------
    >>> "dop853" in regime_methods(), "rk4" in regime_methods()
    (True, False)
    """
    return tuple(ode.methods("adaptive"))


class RegimeScene:
    """A motion with regime changes from the book, with its defaults.

    Examples
    --------
    >>> sc = regime_scenes()[0]
    >>> sc.name, sc.section
    ('coulomb-oscillator', 'ch. 21.4')
    """

    __slots__ = ("_name", "_title", "_section", "_parameters", "_state", "_q0", "_u0",
                 "_t_end", "_runner", "_notes", "_layout")

    def __init__(self, name, title, section, *, parameters, state, q0, u0, t_end, runner,
                 notes="", layout=None):
        self._name, self._title, self._section = name, title, section
        self._layout = tuple(layout) if layout is not None else tuple(
            n for q in state for n in (q, f"{q}_dot"))
        self._parameters = tuple(parameters)
        self._state, self._q0, self._u0 = tuple(state), tuple(q0), tuple(u0)
        self._t_end, self._runner, self._notes = float(t_end), runner, notes

    name = property(lambda self: self._name, doc="Command-line name.")
    title = property(lambda self: self._title, doc="One-line title.")
    section = property(lambda self: self._section, doc="Section of the book.")
    parameters = property(lambda self: self._parameters,
                          doc="(name, default, meaning) of each parameter.")
    notes = property(lambda self: self._notes, doc="Conventions of the scene.")
    state = property(lambda self: self._state,
                     doc="Names of the coordinates given by q0 and u0.")
    layout = property(lambda self: self._layout,
                      doc="Names of the components of the integrated state y.")

    @property
    def defaults(self) -> dict:
        """Default parameter values."""
        return {n: float(v) for n, v, _ in self._parameters}

    def __repr__(self):
        return f"RegimeScene({self._name!r}, section={self._section!r})"


_SCENES = (
    RegimeScene(
        "coulomb-oscillator", "Mass on a spring with dry friction: stick-slip", "ch. 21.4",
        parameters=(("m", 1.0, "mass"), ("k", 4.0, "stiffness"), ("N", 2.0, "normal force"),
                    ("fs", 0.12, "static friction coefficient"),
                    ("fk", 0.1, "kinetic friction coefficient")),
        state=("x",), q0=(1.0,), u0=(0.0,), t_end=20.0, runner=_oscillator,
        layout=("x", "y", "x_dot", "y_dot"),
        notes="x: elongation of the spring, y: height of the block on the floor (0 while in "
              "contact); the amplitude drops by 4 fk N / k per cycle."),
    RegimeScene(
        "rolling-cylinder", "Solid cylinder on a rough incline: rolling or slipping", "ch. 23",
        parameters=(("r", 0.1, "radius"), ("alpha", math.atan(0.3), "angle of the incline"),
                    ("g", 9.81, "gravity"), ("fs", 0.2, "static friction coefficient"),
                    ("fk", 0.15, "kinetic friction coefficient")),
        state=("x", "theta"), q0=(0.0, 0.0), u0=(2.0, 0.0), t_end=2.0, runner=_cylinder,
        layout=("x", "y", "theta", "x_dot", "y_dot", "theta_dot"),
        notes="x down the slope, y the height of the centre (r while in contact), theta the "
              "rotation; launched sliding (u0 = x', theta'), it slips, then rolls (sticks) if "
              "tan(alpha) <= 3 fs."),
)
_BY_NAME = {s.name: s for s in _SCENES}


def regime_scenes() -> tuple:
    """The scenes with regime changes.

    Examples
    --------
    >>> [s.name for s in regime_scenes()]
    ['coulomb-oscillator', 'rolling-cylinder']
    """
    return _SCENES


def regime_scene_names() -> tuple:
    """Their names.

    Examples
    --------
    >>> regime_scene_names()
    ('coulomb-oscillator', 'rolling-cylinder')
    """
    return tuple(_BY_NAME)


class RegimeReport:
    """The outcome of :func:`run_regime_scene`: the scene, the values used, the motion and
    the wall time.

    Examples
    --------
    >>> rep = run_regime_scene("coulomb-oscillator")
    >>> rep.motion.regimes[-1]
    'stick'
    """

    __slots__ = ("scene", "parameters", "q0", "u0", "t_end", "motion", "seconds", "save_path",
                 "plot_path", "method")

    def __init__(self, scene, parameters, q0, u0, t_end, motion: PhasedMotion, seconds,
                 save_path=None, plot_path=None, method=DEFAULT_METHOD):
        self.scene, self.parameters, self.q0, self.u0 = scene, parameters, q0, u0
        self.t_end, self.motion, self.seconds = t_end, motion, seconds
        self.save_path, self.plot_path, self.method = save_path, plot_path, method

    def summary(self) -> str:
        """Lines for a terminal: scene, parameters, the table of phases, the final state.

        Examples
        --------
        >>> print(run_regime_scene("coulomb-oscillator", t_end=2.0).summary())
        ... # doctest: +ELLIPSIS
        Mass on a spring with dry friction: stick-slip (coulomb-oscillator, book ch. 21.4)
        state y = (x, y, x_dot, y_dot); m=1, k=4, N=2, fs=0.12, fk=0.1
        initial q0 = [1.0], u0 = [0.0], t = 0 .. 2
        phases (2):
          phase  regime  start        end          ended by
          1      slip-   0            1.570796327  I stops slipping
          2      slip+   1.570796327  2            -
        final state at t = 2: [...] (slip+)
        integrated in ... ms (dop853, phase by phase)
        """
        sc = self.scene
        params = ", ".join(f"{k}={v:g}" for k, v in self.parameters.items())
        last = self.motion.phases[-1]
        final = ", ".join(f"{v:.10g}" for v in last.y_end)
        return "\n".join([
            f"{sc.title} ({sc.name}, book {sc.section})",
            f"state y = ({', '.join(sc.layout)}); {params}",
            f"initial q0 = {list(self.q0)}, u0 = {list(self.u0)}, t = 0 .. {self.t_end:g}",
            f"phases ({len(self.motion.phases)}):",
            *("  " + line for line in self.motion.table().splitlines()),
            f"final state at t = {last.end:g}: [{final}] ({last.regime})",
            f"integrated in {1e3 * self.seconds:.1f} ms ({self.method}, phase by phase)",
            *([f"samples saved to {self.save_path}"] if self.save_path else []),
            *([f"plot written to {self.plot_path}"] if self.plot_path else []),
        ])

    def __str__(self):
        return self.summary()


def run_regime_scene(name, *, t_end=None, params=None, q0=None, u0=None, plot=None,
                     save=None, method=None, rtol=None, atol=None, n_output=1001,
                     progress=None) -> RegimeReport:
    """Run the scene ``name`` phase by phase; ``plot`` writes a figure of the first state
    component there, ``save`` the samples (:func:`save_motion`).

    ``method`` (default ``dop853``) must be adaptive (:func:`regime_methods`): the switches of
    regime are located by its events; ``rtol`` and ``atol`` default to 1e-12. ``n_output``
    evenly spaced samples are saved.

    Raises
    ------
    SceneError
        Unknown scene, parameter or method, wrong number of initial values, a path that
        cannot be written.

    Examples
    --------
    >>> print(run_regime_scene("rolling-cylinder").summary())     # doctest: +ELLIPSIS
    Solid cylinder on a rough incline: rolling or slipping (rolling-cylinder, book ch. 23)
    ...
      1      slip+   0 ...
      2      stick   ...
    >>> run_regime_scene("rolling-cylinder", method="rk4")        # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    rigidmech._core.errors.SceneError: `method` of a regime scene must be adaptive ...
    """
    if name not in _BY_NAME:
        raise SceneError(f"unknown regime scene {name!r}; known: {', '.join(_BY_NAME)}.")
    sc = _BY_NAME[name]
    values = sc.defaults
    for key, v in (params or {}).items():
        if key not in values:
            raise SceneError(f"scene {name!r} has no parameter {key!r}; its parameters are "
                             f"{', '.join(values)}.")
        values[key] = _finite(v, f"parameter `{key}`")
    n = len(sc._state)
    q0 = sc._q0 if q0 is None else tuple(_finite(x, "`q0` entry") for x in q0)
    u0 = sc._u0 if u0 is None else tuple(_finite(x, "`u0` entry") for x in u0)
    if len(q0) != n or len(u0) != n:
        raise SceneError(f"scene {name!r}: `q0` and `u0` must give {n} values "
                         f"({', '.join(sc._state)}); got {len(q0)} and {len(u0)}.")
    t_end = sc._t_end if t_end is None else _finite(t_end, "`t_end`")
    if t_end <= 0:
        raise SceneError(f"`t_end` must be > 0; got {t_end:g}.")
    method = DEFAULT_METHOD if method is None else method
    if method not in regime_methods():
        raise SceneError(f"`method` of a regime scene must be adaptive (its events locate the "
                         f"switches of regime): one of {', '.join(regime_methods())}; got "
                         f"{method!r}.")
    rtol = DEFAULT_RTOL if rtol is None else _finite(rtol, "`rtol`")
    atol = DEFAULT_ATOL if atol is None else _finite(atol, "`atol`")
    if not (rtol > 0 and atol >= 0):
        raise SceneError(f"`rtol` must be > 0 and `atol` >= 0; got rtol={rtol:g}, "
                         f"atol={atol:g}.")
    if plot is not None:
        check_plot_path(plot)
    if save is not None:
        check_save_path(save)
    start = time.perf_counter()
    motion = sc._runner(values, q0, u0, t_end, method=method, rtol=rtol, atol=atol,
                        progress=progress)
    seconds = time.perf_counter() - start
    if plot is not None:
        from matplotlib.figure import Figure  # plotting only on demand

        fig = Figure(figsize=(7, 3.5), layout="constrained")
        ax = fig.add_subplot()
        motion.plot(ax, component=0, label=sc._state[0])
        ax.set_xlabel("t [s]")
        ax.set_ylabel(sc._state[0])
        fig.savefig(plot)
    save_path = None if save is None else save_motion(motion, save, sc.layout, n_output)
    return RegimeReport(sc, values, q0, u0, t_end, motion, seconds, save_path,
                        None if plot is None else str(plot), method)


def save_motion(motion: PhasedMotion, path, names, n_output=1001) -> str:
    """Write ``n_output`` evenly spaced samples of a phased motion to ``path``: ``.npz``
    (arrays ``t``, ``y``, ``regime``, ``names``) or ``.csv`` (columns ``t [s]``, the state
    components ``names``, ``regime``). Returns the path.

    Examples
    --------
    >>> import os, tempfile
    >>> rep = run_regime_scene("coulomb-oscillator", t_end=2.0)
    >>> path = save_motion(rep.motion, os.path.join(tempfile.mkdtemp(), "osc.csv"),
    ...                    rep.scene.layout, 5)
    >>> with open(path) as fh:
    ...     fh.readline().strip()
    't [s],x,y,x_dot,y_dot,regime'
    """
    import csv
    import os

    import numpy as np

    text = os.fspath(path)
    t0, t1 = motion.phases[0].start, motion.phases[-1].end
    t = np.linspace(t0, t1, int(n_output))
    y = motion(t)
    ends = np.array([p.end for p in motion.phases])
    k = np.minimum(np.searchsorted(ends, t, side="left"), len(ends) - 1)
    regimes = np.array([motion.phases[i].regime for i in k])
    if text.lower().endswith(".npz"):
        np.savez(text, t=t, y=y, regime=regimes, names=np.array(list(names)))
    else:
        with open(text, "w", newline="") as fh:
            w = csv.writer(fh)
            w.writerow(["t [s]", *names, "regime"])
            for j in range(t.size):
                w.writerow([repr(float(t[j])), *(repr(float(v)) for v in y[:, j]), regimes[j]])
    return text
