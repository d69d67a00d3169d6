"""Free-body diagrams along a motion: the actions on an isolated set at chosen instants of a
:class:`~rigidmech.dynamics.Simulation`, their arrows drawn to one force scale for the whole
motion with its key (book, ch. 18.2: the connection actions from the fundamental principle
at each state).

Examples
--------
A pendulum swinging from 1 rad: the action of the pivot and the weight at three instants.

>>> import matplotlib
>>> matplotlib.use("Agg")
>>> import rigidmech as rm
>>> from rigidmech import models
>>> pend = models.compound_pendulum()
>>> sim = pend.system.equations_of_motion().simulate(
...     t=(0, 1), q0=[1.0], m=1.0, L=1.0, g=9.81, n_output=11)
>>> motion = free_body_motion(sim, pend.bodies[0], times=[0.0, 0.5, 1.0])
>>> fig = motion.plot()
>>> len(fig.axes), motion.times.tolist()
(3, [0.0, 0.5, 1.0])
>>> import matplotlib.pyplot as plt; plt.close("all")
"""

from __future__ import annotations

import numpy as np

from .._core.errors import ArgumentError, ArgumentTypeError
from ._fbd_sources import Source, motion_numbers, plan
from .fbd import (
    FreeBodyDiagram,
    _axes,
    _check_scale,
    _default_scale,
    _draw_bodies,
    _extent,
    _limits,
    _view,
    draw_actions,
    rotated,
)
from .fbd_actions import _build
from .placement import Placer

__all__ = ["FreeBodyMotion", "free_body_motion"]


class FreeBodyMotion:
    """The free-body diagram of a set of bodies at chosen instants of a motion, with one
    force scale (see :func:`free_body_motion`).

    Attributes
    ----------
    times : numpy.ndarray
        The instants drawn (sample times of the simulation).
    actions : tuple of tuple of ExternalAction
        The actions at each instant.
    scale : float or None
        Force per unit of length, the same at every instant.
    dim : int
        2 or 3.
    view : View
        How the reference's coordinates map to the axes (that of the first instant).
    """

    def __init__(self, times, actions, scale, view, length, unit, placements, bodies):
        self.times = np.asarray(times, dtype=float)
        self.actions = tuple(actions)
        self.scale, self.view, self._length, self._unit = scale, view, length, unit
        self.dim = view.dim
        self._placements, self._bodies = tuple(placements), tuple(bodies)
        seen = [rotated(acts, view.rows) for acts in self.actions]
        self._points = [a.point for acts in seen for a in acts] + _tips(
            seen, scale, length) + [view.rows @ c for p in self._placements
                                    for c in p.extent()]
        self._box = self._whole_box()

    def _whole_box(self):
        """The limits of every instant (bodies drawn by their shapes on a scratch figure):
        the same at every frame of an animation."""
        from matplotlib.figure import Figure

        ax = Figure().add_subplot(projection="3d" if self.dim == 3 else None)
        for k, acts in enumerate(self.actions):
            _draw_bodies(ax, self._bodies, self._placements[k], self.view, acts,
                         self._length)
        return _limits(ax, self._points, self.dim, self._length)

    def _instant(self, instant):
        if isinstance(instant, bool) or not isinstance(instant, int | np.integer):
            raise ArgumentTypeError(
                f"`instant` must be an index into times (an int); got {instant!r}.")
        if not -len(self.times) <= instant < len(self.times):
            raise ArgumentError(
                f"`instant` must be in [0, {len(self.times) - 1}] (one of the "
                f"{len(self.times)} times); got {instant}.")
        return int(instant)

    def draw(self, instant: int = 0, *, ax=None, key: bool = True,
             show_values: bool = True) -> FreeBodyDiagram:
        """Draw the diagram at ``times[instant]`` on ``ax`` (a new figure by default), with
        the limits of the whole motion.

        Examples
        --------
        See the module.
        """
        k = self._instant(instant)
        ax = _axes(ax, self.dim)
        acts = self.actions[k]
        drawn = _draw_bodies(ax, self._bodies, self._placements[k], self.view, acts,
                             self._length)
        d = draw_actions(ax, acts, dim=self.dim, scale=self.scale, length=self._length,
                         show_values=show_values, key=False, unit=self._unit, view=self.view)
        d.bodies = drawn
        _limits(ax, list(self._box), self.dim, 0.0, with_data=False)
        if key and self.scale is not None:
            from .arrows import scale_key

            d.key, _ = scale_key(ax, self.scale, 0.25 * self._length, dim=self.dim,
                                 unit=self._unit)
        ax.set_title(f"t = {self.times[k]:.3g}", fontsize=9)
        return d

    def frame(self, ax, instant: int) -> list:
        """Clear ``ax`` and draw ``times[instant]``: the function of an animation frame
        (``FuncAnimation(fig, lambda i: motion.frame(ax, i), frames=len(motion.times))``).
        Returns the artists drawn.

        Examples
        --------
        >>> import matplotlib
        >>> matplotlib.use("Agg")
        >>> import matplotlib.pyplot as plt
        >>> from rigidmech import models
        >>> pend = models.compound_pendulum()
        >>> sim = pend.system.equations_of_motion().simulate(
        ...     t=(0, 1), q0=[1.0], m=1.0, L=1.0, g=9.81, n_output=5)
        >>> motion = free_body_motion(sim, pend.bodies[0])
        >>> fig, ax = plt.subplots()
        >>> len(motion.frame(ax, 2)) > 0
        True
        >>> plt.close(fig)
        """
        ax.clear()
        d = self.draw(instant, ax=ax)
        return ([a.artist for a in d.arrows] + [x for _, arts in d.couples for x in arts]
                + list(d.labels) + list(d.key))

    def plot(self, *, ncols: int | None = None):
        """All the instants side by side in one figure, to one scale.

        Examples
        --------
        See the module.
        """
        import matplotlib.pyplot as plt

        n = len(self.times)
        ncols = min(n, 4) if ncols is None else int(ncols)
        nrows = -(-n // ncols)
        kw = {"projection": "3d"} if self.dim == 3 else {}
        fig = plt.figure(figsize=(3.2 * ncols, 3.2 * nrows), layout="constrained")
        for k in range(n):
            self.draw(k, ax=fig.add_subplot(nrows, ncols, k + 1, **kw), key=k == n - 1)
        return fig


def _tips(actions_sets, scale, length):
    out = []
    for acts in actions_sets:
        for a in acts:
            if a.force is not None and scale:
                out.append(a.point + a.force / scale)
    return out


def free_body_motion(simulation, bodies, *, times=None, system=None, dim=None, scale=None,
                     unit: str = "N") -> FreeBodyMotion:
    """The free-body diagram of ``bodies`` along ``simulation`` at ``times`` (ch. 18.2).

    Parameters
    ----------
    simulation : Simulation
        A motion of a :class:`~rigidmech.dynamics.System`'s equations.
    bodies : Body or sequence of Body
        The isolated set.
    times : sequence of float, optional
        The instants, within the simulated span; each is drawn at the sample nearest to it.
        Default: four instants evenly spread over the samples.
    system : System, optional
        The system the equations were derived from (default: the one they remember).
    dim : {2, 3, None}
        As for :func:`free_body_diagram`, decided on all the instants.
    scale : float, optional
        Force per unit of length; default the largest known force of the whole motion drawn
        0.45 times the size of the diagram.
    unit : str
        The unit of force written in the key.

    Returns
    -------
    FreeBodyMotion

    Examples
    --------
    See the module.
    """
    eqs = getattr(simulation, "equations", None)
    if not hasattr(simulation, "evaluate") or not hasattr(simulation, "t"):
        raise ArgumentTypeError(
            f"`simulation` must be a Simulation; got {type(simulation).__name__}.")
    if system is None:
        system = getattr(eqs, "system", None)
        if system is None:
            raise ArgumentError("`system` is needed: these equations were not derived by "
                                "System.equations_of_motion(); pass system=... .")
    source = Source(system, bodies)
    if source.dynamics is None:
        raise ArgumentTypeError(
            f"`system` must be the dynamics System of the simulation; got "
            f"{type(system).__name__}.")
    items = plan(source, dynamic=True)
    numbers, link_numbers = motion_numbers(simulation, source, items)
    indices = _indices(simulation.t, times)
    actions = [_build(items, lambda e, k=k: numbers(e, k),
                      lambda it, k=k: link_numbers(it, k)) for k in indices]
    placer = Placer(source.dynamics, simulation.parameters)
    placements = [placer.at(simulation.q[:, k], simulation.t[k]) for k in indices]
    views = [_view(p, acts, dim) for p, acts in zip(placements, actions, strict=True)]
    view = views[0][0]
    if any(v.dim == 3 for v, _ in views) and view.dim == 2:
        view = _view(placements[0], actions[0], 3)[0]
    length = max(_extent(acts, p) for p, acts in zip(placements, actions, strict=True))
    scale = _check_scale(scale)
    if scale is None:
        scale = _default_scale(actions, length)
    return FreeBodyMotion(simulation.t[indices], actions, scale, view, length, unit,
                          placements, source.bodies)


def _indices(t, times):
    t = np.asarray(t, dtype=float)
    if times is None:
        return np.unique(np.linspace(0, t.size - 1, min(4, t.size)).round().astype(int))
    try:
        wanted = np.asarray(times, dtype=float).reshape(-1)
    except (TypeError, ValueError):
        raise ArgumentTypeError(f"`times` must be a sequence of numbers; got {times!r}.") \
            from None
    if wanted.size == 0:
        raise ArgumentError("`times` must hold at least one instant; got none.")
    span = t[-1] - t[0]
    bad = wanted[(wanted < t[0] - 1e-9 * span) | (wanted > t[-1] + 1e-9 * span)
                 | ~np.isfinite(wanted)]
    if bad.size:
        raise ArgumentError(
            f"`times` must lie in the simulated span [{t[0]:g}, {t[-1]:g}]; got "
            f"{bad.tolist()}.")
    return np.abs(t[None, :] - wanted[:, None]).argmin(axis=1)
