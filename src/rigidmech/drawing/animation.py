"""The bodies of a system moving along a simulated motion: :func:`animate` (book, ch. 27).

The motion is shown at the simulation's samples nearest to evenly spaced times
(:func:`sample_motion`), the system is drawn at each one with :func:`~rigidmech.drawing.draw`
in one fixed box, and the frames make a matplotlib ``FuncAnimation``, written as a GIF
through pillow (or any format matplotlib's writers know).
"""

from __future__ import annotations

import os

import matplotlib.pyplot as plt
import numpy as np
from matplotlib.animation import FuncAnimation, PillowWriter

from .._core.errors import ArgumentError, ArgumentTypeError
from .bodies import View, is_3d
from .placement import Placer
from .system import _symbol_size, azimuth_of, draw, limits_of

__all__ = ["animate", "sample_motion"]


def _simulation_parts(sim, system):
    t = getattr(sim, "t", None)
    q = getattr(sim, "q", None)
    if t is None or q is None or not hasattr(sim, "parameters"):
        raise ArgumentTypeError(
            f"`sim` must be a Simulation (what EquationsOfMotion.simulate returns); got "
            f"{type(sim).__name__}.")
    if system is None:
        eqs = getattr(sim, "equations", None)
        system = getattr(eqs, "system", None) if eqs is not None else None
        if system is None:
            raise ArgumentError(
                "`system` must be given: this simulation does not know the system its "
                "equations come from (equations built by hand, or loaded from a file). Pass "
                "animate(sim, system=...).")
    if len(np.asarray(t)) < 1:
        raise ArgumentError("`sim` has no samples to animate.")
    return np.asarray(t, dtype=float), np.asarray(q, dtype=float), system


def sample_motion(sim, n_frames):
    """(times, coordinates) of ``n_frames`` images along a simulation: the samples of the
    simulation nearest to evenly spaced times over it (the states the solver computed, on
    the constraints to its tolerance; no interpolation). Coordinates: shape (n, n_frames).

    Examples
    --------
    >>> import sympy as sp, rigidmech as rm
    >>> x = rm.coordinates("x")
    >>> eqs = rm.EquationsOfMotion(coordinates=(x,), mass_matrix=sp.ImmutableMatrix([[1]]),
    ...                            forcing=sp.ImmutableMatrix([[0]]))
    >>> sim = eqs.simulate(t=(0, 2), q0=[0.0], u0=[1.0], n_output=5)
    >>> times, q = sample_motion(sim, 3)
    >>> times.tolist(), q.round(9).tolist()
    ([0.0, 1.0, 2.0], [[0.0, 1.0, 2.0]])
    """
    if isinstance(n_frames, bool) or not isinstance(n_frames, int | np.integer) or n_frames < 1:
        raise ArgumentError(f"`n_frames` must be a whole number >= 1; got {n_frames!r}.")
    t, q = np.asarray(sim.t, dtype=float), np.atleast_2d(np.asarray(sim.q, dtype=float))
    wanted = np.linspace(t[0], t[-1], int(n_frames))
    right = np.clip(np.searchsorted(t, wanted), 1, len(t) - 1) if len(t) > 1 else \
        np.zeros(len(wanted), dtype=int)
    left = np.maximum(right - 1, 0)
    nearest = np.where(np.abs(t[left] - wanted) <= np.abs(t[right] - wanted), left, right)
    return t[nearest], q[:, nearest]


def _coordinates_in_order(sim, placer, q):
    """Rows of ``q`` (in the simulation's order) in the order of the placer's coordinates."""
    names = list(getattr(sim, "names", ()))
    wanted = [str(c.func) for c in placer.coordinates]
    if names and sorted(names) == sorted(wanted):
        return q[[names.index(n) for n in wanted]]
    if q.shape[0] != len(wanted):
        raise ArgumentError(
            f"`sim` has {q.shape[0]} coordinates; the system has {len(wanted)} "
            f"({', '.join(wanted)}). Animate a simulation of this system.")
    return q


def animate(sim, system=None, *, params=None, n_frames=40, fps=None, path=None, ax=None,
            dim=None, frames=False, labels=False, trace=(), figsize=None, title=True):
    """Animate the bodies of a system along a simulated motion (ch. 27).

    Parameters
    ----------
    sim : Simulation
        The motion (:meth:`EquationsOfMotion.simulate`).
    system : System or Model, optional
        Default: the system the simulated equations were derived from.
    params : dict, optional
        Values of the constants; default the values the simulation was run with.
    n_frames : int, default 40
        Number of images, at the samples nearest to evenly spaced times (simulate with
        ``n_output`` at least this).
    fps : float, optional
        Images per second; default so that the animation lasts as long as the motion (at
        most 30, at least 2).
    path : str, optional
        Write the animation there (``.gif`` through pillow; another extension with the
        matplotlib writer that knows it).
    ax : matplotlib Axes, optional
        Axes to draw on (3D for a spatial system); default a new figure.
    dim, frames, labels, figsize
        As for :func:`~rigidmech.drawing.draw`.
    trace : sequence of Point or str
        Points whose path is drawn as the motion goes (a coupler point of a four-bar).
    title : bool, default True
        Show the time above the drawing.

    Returns
    -------
    matplotlib.animation.FuncAnimation
        Its ``placements`` attribute holds the :class:`Placement` of each image.

    Raises
    ------
    ArgumentError
        If the simulation does not know its system and none is given, or for a bad
        ``n_frames`` or ``path``.

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> from rigidmech import models
    >>> eqs = models.double_pendulum().system.equations_of_motion()
    >>> sim = eqs.simulate(t=(0, 1), q0=[1.0, 0.5], m=1.0, L=1.0, g=9.81)
    >>> anim = animate(sim, n_frames=3)
    >>> len(anim.placements)
    3
    >>> html = anim.to_jshtml()                 # render it (or anim.save("out.gif"))
    >>> import matplotlib.pyplot as plt; plt.close(anim._fig)
    """
    t, _, system = _simulation_parts(sim, system)
    if params is None:
        placer_params = _known(system, sim.parameters)
    else:
        placer_params = params
    placer = Placer(system, placer_params, points=[p for p in trace if not isinstance(p, str)])
    times, q = sample_motion(sim, n_frames)
    q = _coordinates_in_order(sim, placer, q)
    placements = [placer.at(q[:, n], times[n]) for n in range(len(times))]
    view = View.of(placements[0], dim)
    if ax is None:
        fig = plt.figure(figsize=figsize or ((5, 5) if view.dim == 3 else (5, 4)))
        ax = fig.add_subplot(projection="3d" if view.dim == 3 else None)
    elif (view.dim == 3) != is_3d(ax):
        raise ArgumentError(f"`ax` must be {'3D' if view.dim == 3 else '2D'} axes for this "
                            f"system; got {'3D' if is_3d(ax) else '2D'} axes.")
    fig = ax.figure
    size = _symbol_size(placements[0], view)
    box = limits_of(placements, view, size)
    azim = azimuth_of(placements, view) if view.dim == 3 else None
    paths = [np.array([view.project(p.point(x)) for p in placements]) for x in trace]

    def frame(n):
        ax.cla()
        draw(system, q[:, n], t=times[n], ax=ax, frames=frames, labels=labels,
             dim=view.dim, limits=box, azim=azim, placer=placer)
        for path_xy in paths:
            ax.plot(*path_xy[:n + 1].T, color="0.35", lw=1.0, ls="--")
        if title:
            ax.set_title(f"t = {times[n]:.2f}")
        return []

    duration = float(times[-1] - times[0])
    if fps is None:
        fps = min(30.0, max(2.0, len(times) / duration)) if duration > 0 else 10.0
    anim = FuncAnimation(fig, frame, frames=len(times), interval=1000.0 / fps, blit=False)
    anim.placements = tuple(placements)
    anim.fps = fps
    if path is not None:
        save_animation(anim, path, fps=fps)
    return anim


def _known(system, values):
    """The values whose names are constants of the system (a simulation also keeps inputs
    and constants that dropped out)."""
    names = {s.name for s in system.parameters}
    return {k: v for k, v in values.items()
            if (k.name if hasattr(k, "name") else str(k)) in names}


def save_animation(anim, path, *, fps=None) -> str:
    """Write an animation; ``.gif`` through pillow. Returns the path.

    Raises
    ------
    ArgumentError
        If the folder of ``path`` does not exist.

    Examples
    --------
    >>> import os, tempfile, matplotlib
    >>> matplotlib.use("Agg")
    >>> from rigidmech import models
    >>> eqs = models.compound_pendulum().system.equations_of_motion()
    >>> sim = eqs.simulate(t=(0, 1), q0=[1.0], m=1.0, L=1.0, g=9.81)
    >>> anim = animate(sim, n_frames=2)
    >>> with tempfile.TemporaryDirectory() as folder:
    ...     path = save_animation(anim, os.path.join(folder, "pendulum.gif"))
    ...     os.path.getsize(path) > 0
    True
    >>> import matplotlib.pyplot as plt; plt.close(anim._fig)
    """
    path = os.fspath(path)
    folder = os.path.dirname(os.path.abspath(path))
    if not os.path.isdir(folder):
        raise ArgumentError(f"`path` is in a folder that does not exist: {folder}.")
    fps = fps if fps is not None else getattr(anim, "fps", 10.0)
    if path.lower().endswith(".gif"):
        anim.save(path, writer=PillowWriter(fps=fps), dpi=80)
    else:
        anim.save(path, fps=fps, dpi=80)
    return path
