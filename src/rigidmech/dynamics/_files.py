"""A :class:`~rigidmech.dynamics.Simulation` saved, loaded and plotted (book, ch. 27).

Functions called by the methods of :class:`~rigidmech.dynamics.Simulation` that carry the
documentation: ``.npz`` files (arrays, names, parameters, status, event times and states)
and ``.csv`` files (a header line of comments with the status and the parameters, then the
columns with their units where known), read back without the equations; plots of the parameters of
situation against time (one panel per coordinate, labelled with its name and unit), of their
phase portraits and of the energy (matplotlib, imported on use).

Examples
--------
>>> import rigidmech as rm
>>> psi, x = rm.coordinates("psi x")
>>> R0 = rm.Frame("R0"); R1 = R0.rotated("R1", about=R0.k, angle=psi)
>>> s = rm.System(galilean=R0)
>>> s.add(rm.Body("b", frame=R1, mass=1, inertia=rm.InertiaOperator.from_products(1, 1, 1,
...                                                                             frame=R1)))
>>> P = R0.point("P", x, 1, 0)
>>> s.add(rm.Body("c", frame=R0.translated("R2", P), mass=1, centre=P))
>>> sim = s.equations_of_motion().simulate(t=(0, 1), q0=[0.0, 0.0], n_output=2)
>>> sim.status, units_of(sim, {"x": "m"})
('finished', {'psi': 'rad', 'x': 'm'})
"""

from __future__ import annotations

import csv
import json
import os

import numpy as np
import sympy as sp

from .._core.errors import ArgumentError

__all__ = ["columns", "load", "plot", "save", "units_of", "PLOT_KINDS"]


def columns(sim):
    """The names of the columns of the samples: t, the coordinates, their rates."""
    names = list(sim._names)
    return ["t", *names, *(f"{n}_dot" for n in names)]


def units_of(sim, units):
    """The unit of each coordinate: `units` (by name) first, else rad for an angle of
    rotation of a body's frame (or of a frame it is built from), else None."""
    units = dict(units or {})
    unknown = sorted(set(units) - set(sim._names))
    if unknown:
        raise ArgumentError(f"`units` names {unknown}, which is not a coordinate; the "
                            f"coordinates are {', '.join(sim._names)}.")
    angles = set()
    system = getattr(sim._eqs, "system", None) if sim._eqs is not None else None
    for body in (system.bodies if system is not None else ()):
        frame = body.frame
        while frame is not None:
            angles.add(str(frame.angle))
            frame = frame.parent
    coords = sim._eqs.coordinates if sim._eqs is not None else ()
    out = {}
    for name, c in zip(sim._names, coords or sim._names, strict=False):
        out[name] = units.get(name, "rad" if str(c) in angles else None)
    for name in sim._names:
        out.setdefault(name, units.get(name))
    return out


def save(sim, path, units):
    """Write the samples of ``sim`` to ``path`` (see :meth:`Simulation.save
    <rigidmech.dynamics.Simulation.save>`)."""
    text = os.fspath(path)
    ext = os.path.splitext(text)[1].lower()
    if ext not in (".npz", ".csv"):
        raise ArgumentError(f"`path` must end in .npz or .csv; got {text!r}.")
    params = {k: (float(v) if not callable(v) else repr(v)) for k, v in sim._params.items()}
    meta = {"names": list(sim._names), "parameters": params, "status": sim.status,
            "message": sim.message, "method": sim._method, "elapsed": sim.elapsed,
            "t_stop": sim._t_stop,
            "notes": list(sim.notes)}
    if sim._given is not None:  # the initial state as given (before an assembly moved it)
        meta["q0_given"], meta["u0_given"] = (g.tolist() for g in sim._given)
    if ext == ".npz":
        np.savez(text, t=sim.t, q=sim.q, u=sim.u, meta=np.array(json.dumps(meta)),
                 **{f"t_events_{i}": np.asarray(te) for i, te in enumerate(sim._t_events)},
                 **{f"y_events_{i}": np.asarray(ye) for i, ye in enumerate(sim._y_events or ())})
    else:
        unit = units_of(sim, units)
        header = ["t [s]"] + [n + (f" [{unit[n]}]" if unit[n] else "") for n in sim._names]
        header += [f"{n}_dot" + (f" [{unit[n]}/s]" if unit[n] else "") for n in sim._names]
        with open(text, "w", newline="") as fh:
            fh.write("# rigidmech simulation " + json.dumps(meta) + "\n")
            w = csv.writer(fh)
            w.writerow(header)
            data = np.vstack([sim.t, sim.q, sim.u]).T
            for row in data:
                w.writerow([repr(float(x)) for x in row])
    return text


def load(cls, path):
    """A ``cls`` read from a file written by :func:`save` (see :meth:`Simulation.load
    <rigidmech.dynamics.Simulation.load>`)."""
    text = os.fspath(path)
    ext = os.path.splitext(text)[1].lower()
    if ext == ".npz":
        with np.load(text) as data:
            meta = json.loads(str(data["meta"]))
            t, y = data["t"], np.vstack([data["q"], data["u"]])
            events = [data[k] for k in sorted(
                (k for k in data.files if k.startswith("t_events_")),
                key=lambda k: int(k.rsplit("_", 1)[1]))]
            keys = [f"y_events_{i}" for i in range(len(events))]
            states = ([data[k] for k in keys] if all(k in data.files for k in keys)
                      else None)  # None: a file written before the states were saved
    elif ext == ".csv":
        with open(text, newline="") as fh:
            first = fh.readline()
            prefix = "# rigidmech simulation "
            if not first.startswith(prefix):
                raise ArgumentError(f"`path` {text!r} is not a CSV file written by "
                                    "Simulation.save (no rigidmech header line).")
            meta = json.loads(first[len(prefix):])
            rows = list(csv.reader(fh))[1:]
        data = np.array(rows, dtype=float).reshape(len(rows), -1)
        t, y = data[:, 0], data[:, 1:].T
        events, states = [], None
    else:
        raise ArgumentError(f"`path` must end in .npz or .csv; got {text!r}.")
    given = ((meta["q0_given"], meta["u0_given"]) if meta.get("q0_given") is not None
             else None)  # files written before q0_given was saved have none
    return cls(None, None, meta["parameters"], meta.get("elapsed", 0.0), meta["notes"],
               status=meta["status"], message=meta["message"], names=meta["names"], t=t,
               y=y, t_events=events, method=meta.get("method"), t_stop=meta.get("t_stop"),
               y_events=states, given=given)


#: The kinds of figure of :meth:`Simulation.plot <rigidmech.dynamics.Simulation.plot>`.
PLOT_KINDS = ("time", "phase", "energy")


def _selected(sim, coordinates):
    """The names of the coordinates to draw: all, or the chosen ones in the order given."""
    if coordinates is None:
        return list(sim._names)
    chosen = [coordinates] if isinstance(coordinates, str) else [str(c) for c in coordinates]
    unknown = [c for c in chosen if c not in sim._names]
    if unknown or not chosen:
        raise ArgumentError(f"`coordinates` must name coordinates among "
                            f"{', '.join(sim._names)}; got {coordinates!r}.")
    return chosen


def _axes(n, path, ax, figsize):
    """``n`` stacked axes: those given (one Axes or a sequence of n), else a new figure with
    constrained layout (labels are never cut): off-screen when a path is given, pyplot's
    otherwise."""
    if ax is not None:
        axes = list(ax) if isinstance(ax, (list, tuple, np.ndarray)) else [ax]
        if len(axes) != n:
            raise ArgumentError(f"`ax` must give {n} Axes (one per panel); got {len(axes)}. "
                                "Leave `ax` out to get a new figure, or choose the panels "
                                "with `coordinates=`.")
        return axes
    if path is not None:
        from matplotlib.figure import Figure  # imported on use (slow import)

        fig = Figure(figsize=figsize, layout="constrained")
    else:
        import matplotlib.pyplot as plt  # imported on use (slow import)

        fig = plt.figure(figsize=figsize, layout="constrained")
    return list(np.atleast_1d(fig.subplots(n, 1, sharex=(n > 1), squeeze=False)[:, 0]))


def _label(name, unit, rate=False):
    text = f"${sp.latex(sp.Symbol(name))}$"
    if rate:
        text = f"${sp.latex(sp.Symbol(name))}'$"
    if unit:
        text += f" [{unit}/s]" if rate else f" [{unit}]"
    return text


def plot(sim, path, ax, *, coordinates=None, kind="time", degrees=False, units=None):
    """Plot a simulation (see :meth:`Simulation.plot <rigidmech.dynamics.Simulation.plot>`):
    one panel per coordinate, each labelled with its name and unit. Returns the Axes as a
    tuple."""
    if kind not in PLOT_KINDS:
        raise ArgumentError(f"`kind` must be one of {', '.join(PLOT_KINDS)}; got {kind!r}.")
    if kind == "energy":
        if coordinates is not None:
            raise ArgumentError("`coordinates` does not apply to kind='energy' (the energy "
                                "of the whole system is drawn); leave it out.")
        e = np.asarray(sim.energy(), dtype=float)
        scale = sim.energy_scale() or 1.0
        axes = _axes(2, path, ax, (7, 4.5))
        axes[0].plot(sim.t, e)
        axes[0].set_ylabel("$E = T + V$")
        axes[1].plot(sim.t, (e - e[0]) / scale)
        axes[1].set_ylabel("$(E - E_0)$ / scale")
        axes[0].set_title(f"energy (scale {scale:.4g}: the larger of T0 + |V0| and max T)",
                          fontsize="medium")
    else:
        names = _selected(sim, coordinates)
        unit_of = units_of(sim, units)
        index = {n: i for i, n in enumerate(sim._names)}
        n = len(names)
        if kind == "time":
            axes = _axes(n, path, ax, (7, 1.0 + 1.6 * n))
        else:
            axes = _axes(n, path, ax, (4.5, 0.6 + 3.4 * n))
        for a, name in zip(axes, names, strict=True):
            q, u, unit = sim.q[index[name]], sim.u[index[name]], unit_of[name]
            if degrees and unit == "rad":
                q, u, unit = np.degrees(q), np.degrees(u), "deg"
            if kind == "time":
                a.plot(sim.t, q)
                a.set_ylabel(_label(name, unit))
            else:
                a.plot(q, u)
                a.plot(q[:1], u[:1], "o", color="tab:green")   # the start
                a.set_xlabel(_label(name, unit))
                a.set_ylabel(_label(name, unit, rate=True))
    for a in axes:
        a.grid(True, alpha=0.3)
    if kind != "phase":
        axes[-1].set_xlabel("t [s]")
    if path is not None:
        axes[0].figure.savefig(path, dpi=100)
    return tuple(axes)
