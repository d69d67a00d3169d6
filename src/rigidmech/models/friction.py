"""Equilibria with friction (book, ch. 13.1.2, 14.4): problems of statics, built as a
:class:`~rigidmech.statics.Statics` rather than a system of dynamics.

* :func:`ladder`: a uniform ladder against a wall, with Coulomb friction at both ends (ch.
  14.4.1): hyperstatic of degree 1 while it holds; its limiting angle is
  tan(alpha_min) = (1 - f1 f2) / (2 f1).
"""

from __future__ import annotations

import sympy as sp

from .._core.errors import ArgumentError, ArgumentTypeError
from ..actions import ContactLaws, Coulomb
from ..actions import gravity as _gravity_field
from ..kinetics import Body
from ..statics import Statics
from ..vectors import Frame, constants
from ._model import Model

__all__ = ["ladder"]


def _law(value, name):
    """Coulomb's law of coefficient ``value``, a refusal naming ``name`` otherwise."""
    try:
        return Coulomb(value)
    except (ArgumentError, ArgumentTypeError) as exc:   # the same kind, named by `name`
        raise type(exc)(f"`{name}` must be a friction coefficient, a number >= 0; got "
                            f"{value!r}. Pass e.g. {name}=0.4.") from exc


def ladder(f1=0.4, f2=0.3) -> Model:
    """A uniform ladder AB of length L and weight m g leaning against a vertical wall at the
    angle alpha with the ground, its foot A on the ground (Coulomb friction ``f1``), its top
    B against the wall (``f2``) (book, ch. 14.4.1; contact laws ch. 13.1.2).

    Conventions: R0 has ``i`` horizontal, away from the wall (the wall is the plane x = 0)
    and ``j`` up (the ground is y = 0): A = (L cos alpha, 0), B = (0, L sin alpha), G the
    middle of AB. The ground acts at A by N_A j + T_A i, the wall at B by N_B i + T_B j
    (normals into the ladder); gravity is ``-g j``. Statics leaves one unknown free
    (hyperstatic of degree 1); at the limit both contacts slide, T_A = -f1 N_A and
    T_B = f2 N_B, N_A = m g / (1 + f1 f2) and tan(alpha_min) = (1 - f1 f2) / (2 f1).

    Parameters
    ----------
    f1, f2 : number, default 0.4 and 0.3
        Static friction coefficients at the foot (ground) and at the top (wall).

    Returns
    -------
    Model
        system: the :class:`~rigidmech.statics.Statics` (contacts labelled ``"A"`` and
        ``"B"``); no coordinates; constants (m, g, L, alpha); frames (R0,); bodies
        (ladder,); points (A, B, G).

    Examples
    --------
    >>> import math
    >>> from rigidmech import models
    >>> lad = models.ladder(0.4, 0.3)
    >>> alpha = lad.constant("alpha")
    >>> limit = lad.system.limit(alpha, (1.4, 0.05), values={"m": 10, "g": 9.81, "L": 4})
    >>> round(limit.value, 9) == round(math.atan((1 - 0.4 * 0.3) / (2 * 0.4)), 9)
    True
    """
    ground, wall = _law(f1, "f1"), _law(f2, "f2")
    alpha = sp.Symbol("alpha", positive=True)
    m, g, L = constants("m g L", positive=True)
    R0 = Frame("R0")
    A = R0.point("A", L * sp.cos(alpha), 0, 0)
    B = R0.point("B", 0, L * sp.sin(alpha), 0)
    G = R0.point("G", L * sp.cos(alpha) / 2, L * sp.sin(alpha) / 2, 0)
    body = Body("ladder", frame=R0, mass=m, centre=G)
    statics = Statics(R0)
    statics.connect(R0, body, ContactLaws(at=A, normal=R0.j, tangent=R0.i,
                                          friction=ground), label="A")
    statics.connect(R0, body, ContactLaws(at=B, normal=R0.i, tangent=R0.j,
                                          friction=wall), label="B")
    statics.act(_gravity_field(-g * R0.j))
    return Model(statics, (), (m, g, L, alpha), (R0,), (body,), (A, B, G))
