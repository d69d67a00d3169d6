"""A :class:`~rigidmech.dynamics.Simulation` saved, loaded and plotted (book, ch. 27).

Functions called by the methods of :class:`~rigidmech.dynamics.Simulation` that carry the
documentation: ``.npz`` files (arrays, names, parameters, status, event times) and ``.csv``
files (a header line of comments with the status and the parameters, then the columns with
their units where known), read back without the equations; a plot of the parameters of
situation against time (matplotlib, imported on use).

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

__all__ = ["columns", "load", "plot", "save", "units_of"]


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
    if ext == ".npz":
        np.savez(text, t=sim.t, q=sim.q, u=sim.u, meta=np.array(json.dumps(meta)),
                 **{f"t_events_{i}": np.asarray(te) for i, te in enumerate(sim._t_events)})
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
        events = []
    else:
        raise ArgumentError(f"`path` must end in .npz or .csv; got {text!r}.")
    return cls(None, None, meta["parameters"], meta.get("elapsed", 0.0), meta["notes"],
               status=meta["status"], message=meta["message"], names=meta["names"], t=t,
               y=y, t_events=events, method=meta.get("method"), t_stop=meta.get("t_stop"))


def plot(sim, path, ax):
    """Plot the parameters of situation against time (see :meth:`Simulation.plot
    <rigidmech.dynamics.Simulation.plot>`)."""
    if ax is None:
        if path is not None:
            from matplotlib.figure import Figure  # imported on use (slow import)

            ax = Figure(figsize=(7, 4)).subplots()
        else:
            import matplotlib.pyplot as plt  # imported on use (slow import)

            ax = plt.subplots(figsize=(7, 4))[1]
    for i, name in enumerate(sim._names):
        ax.plot(sim.t, sim.q[i], label=f"${sp.latex(sp.Symbol(name))}$")
    ax.set_xlabel("t")
    ax.set_ylabel("parameters of situation")
    ax.legend()
    ax.grid(True, alpha=0.3)
    if path is not None:
        ax.figure.tight_layout()
        ax.figure.savefig(path, dpi=100)
    return ax
