"""Numerical integration of ordinary differential equations (book, Part VI, ch. 26-27).

Purely numeric: this layer knows nothing of sympy or of mechanics, and imports no other
rigidmech layer but ``rigidmech._core``. Everything goes through one function,
:func:`solve`, which validates its arguments and dispatches to a registered method:

* fixed step: ``"euler"``, ``"heun"``, ``"midpoint"``, ``"rk4"``, ``"rk38"``, or any
  :class:`~rigidmech.ode.tableaux.ButcherTableau` (ch. 26.2);
* adaptive, with dense output, events and stiffness detection: ``"dopri5"`` (alias
  ``"rk45"``) and ``"dop853"``; and ``"bs32"`` (Bogacki-Shampine 3(2));
* extrapolation (Gragg-Bulirsch-Stoer, the book's Romberg idea, ch. 26.2.3): ``"gbs"``;
* multistep, adaptive in order and step (Adams PECE on backward differences, ch. 26.3):
  ``"adams"``;
* stiff: ``"radau"`` (Radau IIA, order 5);
* multistep (Adams) and geometric (symplectic, for ``q'' = a(t, q)``) methods of
  :mod:`rigidmech.ode.multistep` and :mod:`rigidmech.ode.geometric`.

A batch of initial states ``y0`` of shape ``(n, batch)`` is integrated in one call; the
embedded pairs give each trajectory its own step size (option ``stepping``, see
:mod:`rigidmech.ode._ensemble`).

The stability function of a Runge-Kutta tableau, its real stability interval and the order a
method shows on a problem with an exact solution are in :mod:`rigidmech.ode.stability`.

``methods()`` (or ``METHODS``) lists them all; :mod:`rigidmech.ode._registry` tells how a new
method plugs in.

Examples
--------
>>> import numpy as np
>>> from rigidmech import ode
>>> r = ode.solve(lambda t, y: -y, (0.0, 1.0), [1.0], method="dop853", rtol=1e-12, atol=0)
>>> float(r.y[0, -1])
0.36787944117...
"""

from . import stability, tableaux
from ._result import OdeResult
from ._warnings import StiffnessWarning
from .api import methods, solve
from .events import EventTracker, event
from .stability import observed_order, real_stability_interval, stability_function

__all__ = [
    "solve",
    "methods",
    "OdeResult",
    "StiffnessWarning",
    "tableaux",
    "stability",
    "stability_function",
    "real_stability_interval",
    "observed_order",
    "event",
    "EventTracker",
    "METHODS",
]


def __getattr__(name):
    if name == "METHODS":  # computed on access so that late registrations show up
        return tuple(methods())
    raise AttributeError(f"module 'rigidmech.ode' has no attribute {name!r}")


# --- methods: importing a module registers its methods with rigidmech.ode._registry ---------
from . import adaptive, extrapolation, radau, runge_kutta  # noqa: E402, F401, I001
# --- part B (multistep, geometric) adds its import line here ----------------------------------
from . import geometric, multistep  # noqa: E402, F401, I001
from . import adams, rkn  # noqa: E402, F401, I001
