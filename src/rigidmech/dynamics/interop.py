"""Equations of motion handed to and from ``sympy.physics.mechanics`` (book, ch. 20.2, 25).

rigidmech writes the equations as M(q) q'' = f(q, q', t) with the coordinates q(t) (functions of
sympy's own time symbol, so that ``dynamicsymbols`` are coordinates as they are). Kane's method
in sympy writes them on generalised speeds u with kinematic equations q' = u; with u = q' the two
are the same equations:

* :func:`kane_form` gives ``(mass_matrix_full, forcing_full)`` of the first-order form in
  ``KanesMethod``'s layout, states (q, u): [[I, 0], [0, M]] (q', u')ᵀ = (u, f)ᵀ;
* :func:`from_sympy_mechanics` makes an :class:`~rigidmech.dynamics.EquationsOfMotion` of a
  ``LagrangesMethod`` or of a ``KanesMethod`` whose speeds are the rates of the coordinates
  (u_i = q_i'), so that rigidmech compiles, simulates, linearises and analyses them.
"""

from __future__ import annotations

import sympy as sp

from .._core.errors import ArgumentError, ArgumentTypeError
from ..vectors import t as _t
from .equations import EquationsOfMotion

__all__ = ["kane_form", "from_sympy_mechanics"]


def kane_form(eqs, speeds=None):
    """``(mass_matrix_full, forcing_full)`` of ``eqs`` in the layout of sympy's
    ``KanesMethod``: states (q, u) with u = q', [[I, 0], [0, M]] and (u, f) (ch. 20.2).

    Parameters
    ----------
    eqs : EquationsOfMotion
        Without constraints (for constraints, reduce them first: ``eqs.reduced()``).
    speeds : sequence of functions of t, optional
        The names of the speeds u(t) (``dynamicsymbols``) written in place of q'(t); default
        q'(t) itself.

    Returns
    -------
    (sympy.ImmutableMatrix (2n, 2n), sympy.ImmutableMatrix (2n, 1))

    Examples
    --------
    >>> import sympy as sp
    >>> from sympy.physics.mechanics import dynamicsymbols
    >>> import rigidmech as rm
    >>> x, u = dynamicsymbols("x u"); k, m = sp.symbols("k m")
    >>> eqs = rm.EquationsOfMotion(coordinates=(x,), mass_matrix=sp.Matrix([[m]]),
    ...                            forcing=sp.Matrix([[-k * x]]))
    >>> kane_form(eqs, speeds=[u])
    (Matrix([
    [1, 0],
    [0, m]]), Matrix([
    [    u(t)],
    [-k*x(t)]]))
    """
    if not isinstance(eqs, EquationsOfMotion):
        raise ArgumentTypeError(f"`eqs` must be an EquationsOfMotion; got "
                                f"{type(eqs).__name__}.")
    if eqs.constraints is not None and len(eqs.constraints) > 0:
        raise ArgumentError("`eqs` has constraints: KanesMethod's full form on independent "
                            "speeds needs them eliminated; use eqs.reduced() (its "
                            "mass_matrix and forcing) instead.")
    n = len(eqs.coordinates)
    rates = [c.diff(_t) if c.has(_t) else u for c, u in zip(eqs.coordinates, eqs.u,
                                                           strict=True)]
    M, f = eqs.mass_matrix, eqs.forcing
    if speeds is not None:
        speeds = list(speeds)
        if len(speeds) != n:
            raise ArgumentError(f"`speeds` must give {n} speeds (one per coordinate); got "
                                f"{len(speeds)}.")
        rule = dict(zip(rates, speeds, strict=True))
        M, f = M.subs(rule), f.subs(rule)
        rates = speeds
    full_M = sp.diag(sp.eye(n), M)
    full_f = sp.Matrix.vstack(sp.Matrix(rates), f)
    return sp.ImmutableMatrix(full_M), sp.ImmutableMatrix(full_f)


def from_sympy_mechanics(method) -> EquationsOfMotion:
    """The :class:`~rigidmech.dynamics.EquationsOfMotion` of a ``LagrangesMethod`` or a
    ``KanesMethod`` of ``sympy.physics.mechanics`` whose equations are formed (ch. 25).

    Parameters
    ----------
    method : LagrangesMethod or KanesMethod
        A ``LagrangesMethod`` without constraint equations, or a ``KanesMethod`` whose
        kinematic equations make each speed the rate of a coordinate (u_i = q_i'), without
        dependent speeds.

    Returns
    -------
    EquationsOfMotion
        M(q) q'' = f(q, q', t) on ``method.q`` (the dynamicsymbols, as they are); from a
        ``LagrangesMethod`` without loads, with the energy sum q' dL/dq' - L (= T + V) for
        the energy drift of its simulations.

    Raises
    ------
    ArgumentError
        Equations not formed yet, constraints, or speeds that are not the rates of the
        coordinates.

    Examples
    --------
    >>> import sympy as sp
    >>> from sympy.physics import mechanics as me
    >>> q = me.dynamicsymbols("q"); m, g, L = sp.symbols("m g L", positive=True)
    >>> N = me.ReferenceFrame("N"); O = me.Point("O"); O.set_vel(N, 0)
    >>> P = O.locatenew("P", L * (sp.cos(q) * N.x + sp.sin(q) * N.y))
    >>> P.set_vel(N, P.pos_from(O).dt(N))
    >>> bob = me.Particle("bob", P, m); bob.potential_energy = -m * g * L * sp.cos(q)
    >>> lm = me.LagrangesMethod(me.Lagrangian(N, bob), [q]); _ = lm.form_lagranges_equations()
    >>> eqs = from_sympy_mechanics(lm)
    >>> eqs.accelerations(simplify=True)
    Matrix([[-g*sin(q(t))/L]])
    """
    from sympy.physics import mechanics as me  # imported on use (slow import)

    if isinstance(method, me.LagrangesMethod):
        if getattr(method, "_m_cd", None) is not None and method._m_cd.shape[0] > 0:
            raise ArgumentError("`method` has constraint equations (LagrangesMethod with "
                                "`hol_coneqs` or `nonhol_coneqs`): not supported; write the "
                                "system with rigidmech's connections instead.")
        try:
            M, f = method.mass_matrix, method.forcing
        except (AttributeError, ValueError, TypeError):
            M = None
        if M is None or getattr(method, "eom", None) is None:
            raise ArgumentError("`method` must have its equations formed: call "
                                "form_lagranges_equations() first.")
        energy = None
        if not method._forcelist:
            # Jacobi's integral sum q' dL/dq' - L: T + V for a Lagrangian T - V with T
            # quadratic in the rates (no load: the energy a simulation follows)
            lag = method._L[0]
            energy = sum(q.diff(_t) * lag.diff(q.diff(_t)) for q in method.q) - lag
        return EquationsOfMotion(coordinates=tuple(method.q), mass_matrix=M, forcing=f,
                                 energy=energy)
    if isinstance(method, me.KanesMethod):
        if getattr(method, "_fr", None) is None:
            raise ArgumentError("`method` must have its equations formed: call "
                                "kanes_equations(bodies, loads) first.")
        if len(method.u) != len(method.q) or len(getattr(method, "_udep", ())) > 0:
            raise ArgumentError("`method` has dependent speeds or a number of speeds other "
                                "than of coordinates: only u_i = q_i' is supported.")
        kd = method.kindiffdict()
        rule = {}
        for q, u in zip(method.q, method.u, strict=True):
            if sp.simplify(kd.get(q.diff(_t), sp.nan) - u) != 0:
                raise ArgumentError(f"the speeds must be the rates of the coordinates "
                                    f"(u_i = q_i'); the kinematic equations give {q.diff(_t)} "
                                    f"= {kd.get(q.diff(_t))}.")
            rule[u.diff(_t)] = q.diff(_t, 2)
            rule[u] = q.diff(_t)
        M = method.mass_matrix.subs(rule)
        f = method.forcing.subs(rule)
        return EquationsOfMotion(coordinates=tuple(method.q), mass_matrix=M, forcing=f)
    raise ArgumentTypeError(f"`method` must be a LagrangesMethod or a KanesMethod of "
                            f"sympy.physics.mechanics; got {type(method).__name__}.")
