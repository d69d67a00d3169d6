"""The benchmark bicycle: the linearised Whipple bicycle of Meijaard, Papadopoulos, Ruina and
Schwab (2007, Proc. R. Soc. A 463, 1955-1982), a scene that is a linear analysis (book,
ch. 25.3.3: parameters linked by rolling conditions; ch. 21.3, 27.5: motions about a
reference state).

``python -m rigidmech run benchmark-bicycle`` builds :func:`rigidmech.models.whipple_bicycle`
with the paper's 25 parameters (its symbols, the defaults its benchmark values, overridden by
``--param``) and g, linearises it about the straight upright run at the forward speed v
(:func:`rigidmech.vibrations.linearize`, the pitch eliminated, independent rates phi', delta',
theta_R'), and prints the paper's matrices of M q'' + v C1 q' + (g K0 + v^2 K2) q = 0 on
q = (roll phi, steer delta) -- in the paper's sign convention (y right, z down: the steer
angle changes sign) -- and the weave and capsize speeds, where the real part of an eigenvalue
of the motion crosses zero (found by :func:`scipy.optimize.brentq` on the largest real part
of the eigenvalues; the bicycle runs itself straight between them). The derivation and the
linearisation take a few tens of seconds.

Examples
--------
>>> BICYCLE_SCENE.name, BICYCLE_SCENE.defaults["w"], BICYCLE_SCENE.defaults["g"]
('benchmark-bicycle', 1.02, 9.81)
>>> len(BICYCLE_SCENE.parameters)
26
"""

from __future__ import annotations

import time

import numpy as np

from .. import models
from .._core.errors import SceneError
from .pipeline import _finite

__all__ = ["BicycleScene", "BicycleReport", "BICYCLE_SCENE", "run_bicycle", "critical_speeds"]

_MEANINGS = {
    "w": "wheelbase, m", "c": "trail, m", "lam": "steer axis tilt, rad",
    "rR": "rear wheel radius, m", "mR": "rear wheel mass, kg",
    "IRxx": "rear wheel inertia about its diameter, kg m^2",
    "IRyy": "rear wheel inertia about its axle, kg m^2",
    "xB": "rear frame mass centre, forward, m", "zB": "rear frame mass centre, down, m",
    "mB": "rear frame mass, kg", "IBxx": "rear frame inertia, kg m^2",
    "IByy": "rear frame inertia, kg m^2", "IBzz": "rear frame inertia, kg m^2",
    "IBxz": "rear frame product of inertia, kg m^2",
    "xH": "front frame mass centre, forward, m", "zH": "front frame mass centre, down, m",
    "mH": "front frame mass, kg", "IHxx": "front frame inertia, kg m^2",
    "IHyy": "front frame inertia, kg m^2", "IHzz": "front frame inertia, kg m^2",
    "IHxz": "front frame product of inertia, kg m^2",
    "rF": "front wheel radius, m", "mF": "front wheel mass, kg",
    "IFxx": "front wheel inertia about its diameter, kg m^2",
    "IFyy": "front wheel inertia about its axle, kg m^2",
}

#: The paper's sign convention: q_paper = S q (the steer angle changes sign).
_S = np.diag([1.0, -1.0])


class BicycleScene:
    """The benchmark bicycle as a scene: name, title, section, the paper's 25 parameters and
    g with their defaults and meanings.

    Examples
    --------
    >>> BICYCLE_SCENE.parameters[0]
    ('w', 1.02, 'wheelbase, m')
    """

    name = "benchmark-bicycle"
    title = "Benchmark bicycle (Meijaard et al. 2007): weave and capsize speeds"
    section = "ch. 25.3.3, 27.5"
    dof = 3
    notes = ("linearised about the straight upright run at speed v; q = (roll phi, steer "
             "delta) in the paper's convention; no integration.")

    @property
    def parameters(self) -> tuple:
        """(symbol, default, meaning) of the paper's 25 parameters, then g."""
        out = tuple((k, float(v), _MEANINGS[k]) for k, v in models.BENCHMARK_BICYCLE.items())
        return out + (("g", 9.81, "gravity, m/s^2"),)

    @property
    def defaults(self) -> dict:
        """Default parameter values, a fresh dict."""
        return {n: v for n, v, _ in self.parameters}

    def __repr__(self):
        return f"BicycleScene({self.name!r}, section={self.section!r})"


BICYCLE_SCENE = BicycleScene()


class BicycleReport:
    """What :func:`run_bicycle` found: the parameters, the matrices M, C1, K0, K2 (paper's
    convention), the weave and capsize speeds (m/s, None if not found in 0.1-20 m/s) and the
    wall time.

    Examples
    --------
    >>> rep = BicycleReport({"g": 9.81}, *(np.eye(2),) * 4, 4.29, 6.02, 1.0)
    >>> print(rep.summary().splitlines()[-3])
    weave speed   4.29 m/s (the weave oscillation stops growing above it)
    """

    __slots__ = ("parameters", "M", "C1", "K0", "K2", "weave", "capsize", "seconds")

    def __init__(self, parameters, M, C1, K0, K2, weave, capsize, seconds):
        self.parameters, self.M, self.C1, self.K0, self.K2 = parameters, M, C1, K0, K2
        self.weave, self.capsize, self.seconds = weave, capsize, seconds

    def summary(self) -> str:
        """Lines for a terminal."""
        sc = BICYCLE_SCENE
        params = ", ".join(f"{k}={v:g}" for k, v in self.parameters.items())

        def matrix(name, X):
            rows = [" ".join(f"{x:14.8f}" for x in row) for row in X]
            return [f"{name} =", *("  " + r for r in rows)]

        def speed(v):
            return "not found in 0.1 .. 20 m/s" if v is None else f"{v:.6g} m/s"

        return "\n".join([
            f"{sc.title} ({sc.name}, book {sc.section})",
            f"parameters: {params}",
            "M q'' + v C1 q' + (g K0 + v^2 K2) q = 0, q = (phi roll, delta steer), the paper's "
            "signs:",
            *matrix("M", self.M), *matrix("C1", self.C1), *matrix("K0", self.K0),
            *matrix("K2", self.K2),
            f"weave speed   {speed(self.weave)} (the weave oscillation stops growing above it)",
            f"capsize speed {speed(self.capsize)} (the capsize mode grows above it)",
            f"derived, linearised and solved in {self.seconds:.1f} s",
        ])

    def __str__(self):
        return self.summary()


def _state_matrix(M, C1, K0, K2, g, v):
    Mi = np.linalg.inv(M)
    return np.block([[np.zeros((2, 2)), np.eye(2)],
                     [-Mi @ (g * K0 + v**2 * K2), -v * Mi @ C1]])


def critical_speeds(M, C1, K0, K2, g, v_max=20.0):
    """The weave and capsize speeds of M q'' + v C1 q' + (g K0 + v^2 K2) q = 0: the lower and
    upper ends of the first interval of speeds where every eigenvalue has a negative real
    part (:func:`rigidmech.vibrations.stability_changes` without margin, ``tol=0``: Brent's
    method on the largest real part, bracketed on a grid of step 0.1 m/s from 0.1 to
    ``v_max``); None where no crossing is found.

    Examples
    --------
    >>> M = np.eye(2); C1 = np.zeros((2, 2)); K0 = -np.eye(2); K2 = np.eye(2)
    >>> C1[0, 0] = C1[1, 1] = 1.0     # stable once v^2 > g
    >>> w, c = critical_speeds(M, C1, K0, K2, g=4.0)
    >>> round(w, 10), c
    (2.0, None)
    """
    from ..vibrations import stability_changes  # the library's finder, without margin

    def exponents(v):
        return np.linalg.eigvals(_state_matrix(M, C1, K0, K2, g, v))

    grid = np.arange(0.1, v_max + 1e-9, 0.1)
    changes = stability_changes(exponents, None, grid, tol=0.0)
    weave = next((c.value for c in changes if c.becomes == "stable"), None)
    capsize = None if weave is None else next(
        (c.value for c in changes if c.value > weave and c.becomes == "unstable"), None)
    return weave, capsize


def run_bicycle(params=None) -> BicycleReport:
    """Derive, linearise and analyse the benchmark bicycle (see the module's description).

    Raises
    ------
    SceneError
        A name that is not one of the parameters, a value that is not finite.
    """
    import sympy as sp

    from ..vibrations import linearize  # imported on use: the vibrations layer

    values = BICYCLE_SCENE.defaults
    for key, v in (params or {}).items():
        if key not in values:
            raise SceneError(f"scene 'benchmark-bicycle' has no parameter {key!r}; its "
                             f"parameters are {', '.join(values)} (the paper's symbols).")
        values[key] = _finite(v, f"parameter `{key}`")
    start = time.perf_counter()
    given = {k: v for k, v in (params or {}).items() if k != "g"}
    g = values["g"]
    model = models.whipple_bicycle(**given)
    eqs = model.system.equations_of_motion()
    v = sp.Symbol("v")
    rR = models.BENCHMARK_BICYCLE["rR"] if "rR" not in given else sp.Rational(str(given["rR"]))
    lin = linearize(eqs, velocities={"theta_R": v / rR}, parameters={"g": g},
                    independent=["phi", "delta", "theta_R"], simplify=False)
    M, C1, K1, _ = lin.numeric(v=1.0)
    K0 = lin.numeric(v=0.0)[2]
    M, C1, K0, K2 = (_S @ X[:2, :2] @ _S for X in (M, C1, K0 / g, K1 - K0))
    weave, capsize = critical_speeds(M, C1, K0, K2, g)
    return BicycleReport(values, M, C1, K0, K2, weave, capsize, time.perf_counter() - start)
