"""Why a run of a system stopped, named in the mechanics' words (book, ch. 11.2, 21.3, 27):
a spring or damper whose ends meet. Its force k (l - l0) AB / l, or c l' AB / l, has no
direction where l = 0 (0/0): the right-hand side is not finite there, and the solver can only
say so by component. Evaluated on the failure path only (no cost to a run that succeeds).

Examples
--------
>>> import rigidmech as rm
>>> x = rm.coordinates("x")
>>> R0 = rm.Frame("R0"); P = R0.point("P", x, 0, 0)
>>> s = rm.System(galilean=R0)
>>> s.add(rm.Body("block", frame=R0.translated("R1", P), mass=1, centre=P))
>>> s.act(rm.Spring(4, 1, a=R0.origin, b=P, on_b=s.bodies[0]))
>>> eqs = s.equations_of_motion()
>>> meeting_ends(eqs, 0.5, [0.0, 1.0], {})[:60]
' The ends O_R0 and P of the Spring (stiffness 4, free length'
"""

from __future__ import annotations

import math

import sympy as sp

from .._core.symbolic import is_exactly_zero
from ..actions import Damper, Spring
from ..actions.actions import _coincide
from ..vectors import t as _t

__all__ = ["meeting_ends"]


def _describe(action):
    if isinstance(action, Spring):
        return f"Spring (stiffness {action._k}, free length {action.free_length})"
    return f"Damper (damping {action.damping})"


def meeting_ends(eqs, t, y, values) -> str:
    """A sentence naming each spring (of free length > 0) and damper of ``eqs``'s system
    whose ends meet (length exactly 0, or not finite) in the state ``y`` = (q, q') at ``t``;
    '' if none (or no system). ``values``: the run's values of the constants by name."""
    system = getattr(eqs, "_system", None)
    if system is None:
        return ""
    n = len(eqs.coordinates)
    rule = {q: sp.Float(float(v)) for q, v in zip(eqs.coordinates, list(y)[:n], strict=True)}
    out = []
    for action in system.actions:
        if not isinstance(action, Spring | Damper):
            continue
        if isinstance(action, Spring) and is_exactly_zero(sp.sympify(action.free_length)):
            continue  # k AB: no direction needed
        a, b = action.ends
        if _coincide(a, b):  # at all times: no force (damper) or refused (spring)
            continue
        ab = (b - a).components(a.root).xreplace(rule)
        consts = {c: float(values[c.name]) for c in ab.free_symbols
                  if getattr(c, "name", None) in values and not callable(values[c.name])}
        try:
            length = float(sp.sqrt(sum(c**2 for c in ab.subs(consts).subs(_t, t))))
        except (TypeError, ValueError):  # a value not known: cannot tell
            continue
        if not (math.isfinite(length) and length > 0):
            out.append(f" The ends {a.name} and {b.name} of the {_describe(action)} meet at "
                       f"t = {float(t)!r} (length {length}): the direction AB / l of its force "
                       "is undefined there (0/0). Attach the ends at points that cannot meet, "
                       "or start from a state where they are apart.")
    return "".join(out)
