"""The figure of a Kepler orbit (book, ch. 8.2): the conic in its plane, the attracting
centre at a focus, the apsides, on the conventions of the library's other plots (axes
labelled with a name and a unit, equal aspect, a constrained layout so that no label is cut,
the legend off the data).

The points of the curve are computed from the polar equation r = p / (1 + e cos nu) (and,
on the far side of an ellipse, its form with the eccentric anomaly), so the drawing is the
conic of :meth:`Orbit.radius_at <rigidmech.kinematics.orbits.Orbit.radius_at>` to
rounding. matplotlib is imported only when a figure is drawn.
"""

from __future__ import annotations

import math
import numbers

import numpy as np

from .._core.errors import ArgumentError

__all__: list[str] = []


def in_xy_plane(normal) -> bool:
    """True when the orbit's plane is z = 0 (its normal along z to 1e-14, the rounding of a
    unit vector): the one rule of :attr:`Orbit.argument_of_periapsis` and of the figure."""
    return bool(np.linalg.norm(np.cross([0.0, 0.0, 1.0], normal)) < 1e-14)


def _anomalies(orbit, points, extent):
    """The true anomalies drawn, and for an ellipse the eccentric anomalies they come from:
    a closed ellipse (uniform in the eccentric anomaly, which spreads the points along the
    curve also when e is close to 1), or the open branch of a parabola or hyperbola up to the
    distance extent * periapsis (uniform in nu; E None)."""
    e = orbit.eccentricity
    if orbit.is_bound:
        E = np.linspace(-math.pi, math.pi, points)
        # tan(nu/2) = sqrt((1+e)/(1-e)) tan(E/2), written with atan2 so that e -> 1 (where
        # sqrt(1 - e) may round to 0) gives nu = +-pi, not a division by zero
        nu = 2 * np.arctan2(math.sqrt(1 + e) * np.sin(E / 2),
                            math.sqrt(max(1 - e, 0.0)) * np.cos(E / 2))
        return nu, E
    r_max = extent * orbit.periapsis
    # r = r_max at cos nu = (p / r_max - 1) / e, which lies in (-1/e, 1): inside the asymptotes
    c = (orbit.semi_latus_rectum / r_max - 1) / e
    nu_max = math.acos(min(1.0, max(-1.0, c)))
    return np.linspace(-nu_max, nu_max, points), None


def conic_points(orbit, points=200, extent=10.0):
    """The drawn curve: an array (points, 3) of positions on the conic, from the centre.

    r = p / (1 + e cos nu) where cos nu >= 0 (the denominator is >= 1 there); on the far
    side of an ellipse, where 1 + e cos nu loses its digits when e is close to 1, the same
    distance written with the eccentric anomaly, r = a (1 - e cos E) (ch. 8.2), whose factor
    is >= 1 there.

    Examples
    --------
    >>> from rigidmech.kinematics.orbits import Orbit
    >>> o = Orbit([1.0, 0, 0], [0, 1.2, 0], mu=1.0)
    >>> xyz = conic_points(o, points=5)
    >>> np.round(xyz[:, 0], 6).tolist()
    [-2.571429, -0.785714, 1.0, -0.785714, -2.571429]
    """
    nu, E = _anomalies(orbit, points, extent)
    p, e = orbit.semi_latus_rectum, orbit.eccentricity
    cos_nu = np.cos(nu)
    near = cos_nu >= 0
    r = np.empty_like(nu)
    r[near] = p / (1 + e * cos_nu[near])         # den >= 1
    if E is not None:
        r[~near] = orbit.semi_major_axis * (1 - e * np.cos(E[~near]))
    else:
        r[~near] = p / (1 + e * cos_nu[~near])   # den >= p / r_max > 0 on the branch
    P, Q = orbit.periapsis_direction, np.cross(orbit.normal, orbit.periapsis_direction)
    return (r * cos_nu)[:, None] * P + (r * np.sin(nu))[:, None] * Q


def _basis(orbit):
    """The axes of the drawing: x and y for an orbit in the plane z = 0, else the perifocal
    axes xi (towards the periapsis) and eta (90 degrees ahead in the sense of motion)."""
    if in_xy_plane(orbit.normal):
        return np.eye(3)[0], np.eye(3)[1], ("x", "y")
    P = orbit.periapsis_direction
    return P, np.cross(orbit.normal, P), ("ξ", "η")


def _check(points, extent, unit):
    if isinstance(points, bool) or not isinstance(points, numbers.Integral) or points < 3:
        raise ArgumentError(f"`points` must be an integer >= 3 (points on the curve); got "
                            f"{points!r}.")
    if not (isinstance(extent, numbers.Real) and math.isfinite(extent) and extent > 1):
        raise ArgumentError(f"`extent` must be a finite number > 1 (the open branch is drawn "
                            f"out to extent * periapsis); got {extent!r}.")
    if unit is not None and not (isinstance(unit, str) and unit):
        raise ArgumentError(f"`unit` must be a non-empty string such as 'km'; got {unit!r}. "
                            "Leave it out for plain 'x', 'y' labels.")


def _new_axes(path):
    """A new figure in a constrained layout (labels never cut): off-screen when a path is
    given, pyplot's otherwise."""
    if path is not None:
        from matplotlib.figure import Figure  # imported on use (slow import)

        fig = Figure(figsize=(6.5, 5), layout="constrained")
    else:
        import matplotlib.pyplot as plt  # imported on use (slow import)

        fig = plt.figure(figsize=(6.5, 5), layout="constrained")
    return fig.add_subplot()


def _draw(orbit, ax, *, points, focus, apsides, extent, label, basis, **style):
    e1, e2, _ = basis
    xyz = conic_points(orbit, points, extent)
    text = label if label is not None else f"{orbit.kind}, e = {orbit.eccentricity:.4g}"
    ax.plot(xyz @ e1, xyz @ e2, label=text, **style)
    if focus:
        ax.plot([0.0], [0.0], "k+", markersize=10, linestyle="none", label="centre")
    if apsides and orbit.kind != "circle":         # a circle has no apsides
        peri = orbit.periapsis * orbit.periapsis_direction
        ax.plot([peri @ e1], [peri @ e2], "v", color="C3", linestyle="none",
                label="periapsis")
        if orbit.is_bound:
            apo = -orbit.apoapsis * orbit.periapsis_direction
            ax.plot([apo @ e1], [apo @ e2], "^", color="C2", linestyle="none",
                    label="apoapsis")


def _finish(ax, own, basis, unit, path):
    """Equal aspect, labels with the unit, the legend off the data, the file."""
    ax.set_aspect("equal", adjustable="datalim")
    suffix = f" [{unit}]" if unit else ""
    ax.set_xlabel(basis[2][0] + suffix)
    ax.set_ylabel(basis[2][1] + suffix)
    ax.grid(True, alpha=0.3)
    if own:
        ax.figure.legend(*ax.get_legend_handles_labels(), loc="outside right upper")
    else:   # outside the axes, on their right (off the data)
        ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0.0)
    if path is not None:
        ax.figure.savefig(path, dpi=100)
    return ax


def plot_orbit(orbit, ax=None, *, points=200, focus=True, apsides=True, path=None,
               unit=None, extent=10.0, label=None):
    """The body of :meth:`Orbit.plot <rigidmech.kinematics.orbits.Orbit.plot>`.

    Examples
    --------
    >>> import matplotlib.pyplot as plt
    >>> from rigidmech.kinematics.orbits import Orbit
    >>> ax = plot_orbit(Orbit([1.0, 0, 0], [0, 1.0, 0], mu=1.0), unit="AU")
    >>> ax.get_xlabel(), ax.get_ylabel()
    ('x [AU]', 'y [AU]')
    >>> plt.close("all")
    """
    _check(points, extent, unit)
    own = ax is None
    if own:
        ax = _new_axes(path)
    basis = _basis(orbit)
    _draw(orbit, ax, points=points, focus=focus, apsides=apsides, extent=extent, label=label,
          basis=basis)
    return _finish(ax, own, basis, unit, path)


def plot_transfer(transfer, ax=None, *, points=200, path=None, unit=None):
    """The body of :meth:`HohmannTransfer.plot <rigidmech.kinematics.kepler.HohmannTransfer.plot>`:
    the departure and arrival circles and the transfer ellipse, its apsides on them, the
    departure on the x axis.

    Examples
    --------
    >>> import matplotlib.pyplot as plt
    >>> from rigidmech.kinematics.kepler import HohmannTransfer
    >>> ax = plot_transfer(HohmannTransfer(1.0, 1.0, 4.0))
    >>> [line.get_label() for line in ax.lines]
    ['departure circle', 'centre', 'arrival circle', 'transfer', 'periapsis', 'apoapsis']
    >>> plt.close("all")
    """
    from .orbits import Orbit  # orbits imports kepler: the class only on demand

    _check(points, 10.0, unit)
    own = ax is None
    if own:
        ax = _new_axes(path)
    mu, r1, r2 = transfer.mu, transfer.r1, transfer.r2
    sign = 1.0 if r2 >= r1 else -1.0             # the departure point on +x
    ellipse = Orbit.from_apsides(min(r1, r2), max(r1, r2), mu=mu,
                                 argument_of_periapsis=0.0 if r2 >= r1 else math.pi)
    basis = _basis(ellipse)
    for orbit, text, focus in (
            (Orbit([r1, 0.0, 0.0], [0.0, sign * math.sqrt(mu / r1), 0.0], mu=mu),
             "departure circle", True),
            (Orbit([r2, 0.0, 0.0], [0.0, sign * math.sqrt(mu / r2), 0.0], mu=mu),
             "arrival circle", False)):
        _draw(orbit, ax, points=points, focus=focus, apsides=False, extent=10.0, label=text,
              basis=basis, color="0.5", linestyle=":" if focus else "--")
    _draw(ellipse, ax, points=points, focus=False, apsides=True, extent=10.0,
          label="transfer", basis=basis, color="C0")
    return _finish(ax, own, basis, unit, path)
