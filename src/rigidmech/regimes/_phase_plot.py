"""The figure of a motion phase by phase (book, ch. 21.4, 23, 24), on the conventions of
:meth:`Simulation.plot <rigidmech.dynamics.Simulation.plot>`: its helpers (the stacked panels
in a constrained layout, the axis labels with units) are the same functions.
"""

from __future__ import annotations

import numpy as np

from .._core.errors import ArgumentError

__all__: list[str] = []


def plot_phases(motion, ax, *, components, names, units, degrees, path, samples, component,
                label):
    """The body of :meth:`PhasedMotion.plot <rigidmech.regimes.phased.PhasedMotion.plot>`.

    Examples
    --------
    >>> import matplotlib.pyplot as plt
    >>> from rigidmech.regimes import Regime, integrate_phases
    >>> m = integrate_phases([Regime("rest")], "rest", (0.0, 1.0), [1.0])
    >>> [a.get_ylabel() for a in plot_phases(m, None, components=None, names=None,
    ...     units=None, degrees=False, path=None, samples=5, component=None, label=None)]
    ['$y[0]$']
    >>> plt.close("all")
    """
    from matplotlib.patches import Patch  # the plotting backend only on demand

    from ..dynamics._files import _axes, _label  # the conventions of Simulation.plot

    size = len(motion._phases[0].y_start)
    names = motion.names if names is None else tuple(map(str, names))
    if len(names) != size:
        raise ArgumentError(f"`names` must give {size} names (one per state component); "
                            f"got {len(names)}.")
    if component is not None:
        components = [component]
    chosen = list(range(size)) if components is None else [
        names.index(c) if isinstance(c, str) and c in names else c for c in components]
    if not chosen or any(not isinstance(i, int | np.integer) or not 0 <= i < size
                         for i in chosen):
        raise ArgumentError(f"`components` must give indices below {size} or names among "
                            f"{', '.join(names)}; got {components!r}.")
    units = dict(units or {})
    unknown = sorted(set(units) - set(names))
    if unknown:
        raise ArgumentError(f"`units` names {unknown}, which is not a state component; "
                            f"the components are {', '.join(names)}.")
    own = ax is None
    axes = _axes(len(chosen), path, ax, (7, 1.4 + 1.6 * len(chosen)))
    import matplotlib.pyplot as plt  # the colour cycle

    cycle = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    colours = {}
    for p in motion._phases:
        colours.setdefault(p.regime, cycle[len(colours) % len(cycle)])
    for a, i in zip(axes, chosen, strict=True):
        unit = units.get(names[i])
        scale = 1.0
        if degrees and unit in ("rad", "rad/s"):
            scale, unit = 180.0 / np.pi, unit.replace("rad", "deg")
        for p in motion._phases:
            ts = (np.linspace(p.start, p.end, samples) if p.end > p.start
                  else np.array([p.start]))
            a.plot(ts, scale * p.solution.sol(ts)[i], color=colours[p.regime])
            a.axvspan(p.start, p.end, color=colours[p.regime], alpha=0.12, lw=0)
        for s in motion.switch_times:
            a.axvline(s, color="0.6", linestyle=":", linewidth=0.8)
        a.set_ylabel(label if label is not None else _label(names[i], unit))
        a.grid(True, alpha=0.3)
    axes[-1].set_xlabel("t [s]")
    handles = [Patch(color=c, alpha=0.5, label=r) for r, c in colours.items()]
    if own:
        axes[0].figure.legend(handles=handles, title="regime", loc="outside upper center",
                              ncols=min(len(handles), 4))
    else:
        axes[0].legend(handles=handles, title="regime", loc="best")
    if path is not None:
        axes[0].figure.savefig(path, dpi=100)
    return tuple(axes)
