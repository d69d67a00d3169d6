"""Linearisation of constrained equations of motion: closed loops and rolling (book, ch. 25.3,
25.4).

The equations M q'' = f + A^T λ, A q'' = b are first reduced to the independent speeds
u = q'_I, :math:`M_r u' = f_r(q, u)` (:mod:`rigidmech.dynamics.reduced`: multipliers and
dependent rates eliminated), then linearised about a reference state (q*, u*) with u'* = 0:

* the dependent parameters of the **holonomic** constraints follow the independent ones to
  first order, :math:`\\Phi_q\\,\\delta q = 0`, so
  :math:`\\delta q_H = G\\,\\delta q_I,\\ G = -\\Phi_{q_H}^{-1}\\Phi_{q_I}`, and
  :math:`K = -(\\partial f_r/\\partial q_I + \\partial f_r/\\partial q_H\\, G)`;
* the dependent parameters of the **nonholonomic** constraints (the position of a rolling
  disc's contact point) are not functions of the others; the reduced equations must not
  depend on them at the reference state (they do not when the system is invariant under
  their change, as a disc on a horizontal plane under a translation) and they leave the
  linear system;
* :math:`C = -\\partial f_r/\\partial u`, :math:`B = \\partial f_r/\\partial w`, M = M_r(q*).

The result is M δq_I'' + C δq_I' + K δq_I = B δw on the independent parameters. The reference
state must satisfy the constraints (Φ(q*) = 0, A q'* + a = 0) and be an equilibrium or a
steady motion: f_r(q*, u*) = 0 and, the coordinates moving at the rates q'*, the rate of
change of f_r along the motion, :math:`(\\partial f_r/\\partial q)\\, q'^*`, is zero too.
"""

from __future__ import annotations

import numpy as np
import sympy as sp

from .._core.errors import ArgumentError
from .._core.symbolic import is_identically_zero, xreplace_shared
from ._jet import values_and_jacobian

__all__ = ["linearize_constrained"]


def _vanishes(x, tol):
    x = sp.sympify(x)
    if x.is_number:
        return abs(complex(x)) <= tol
    return is_identically_zero(x)


def _rates(velocities, eqs, red, norm):
    """(given rates by index): a dict by coordinate or a full sequence of n values, or a
    sequence of the n - m independent rates."""
    n = len(eqs.coordinates)
    if velocities is None:
        return {}
    if isinstance(velocities, dict):
        return {norm.index(k): sp.sympify(v) for k, v in velocities.items()}
    values = list(velocities) if not isinstance(velocities, sp.Basic | int | float) \
        else [velocities]
    if len(values) == n:
        return {k: sp.sympify(v) for k, v in enumerate(values)}
    if len(values) == len(red.independent):
        return {eqs.coordinates.index(c): sp.sympify(v)
                for c, v in zip(red.independent, values, strict=True)}
    raise ArgumentError(
        f"`velocities` must give {n} rates (or the {len(red.independent)} independent ones "
        f"{[str(c) for c in red.independent]}, or a dict by coordinate); got "
        f"{len(values)}: {velocities!r}.")


def _holonomic_split(phi_q, dep):
    """Dependent parameters that the holonomic rows fix: p columns of Φ_q (n columns) among
    ``dep`` with an invertible block at the point (greedy, in order)."""
    p = phi_q.shape[0]
    if p == 0:
        return []
    if p == len(dep):
        return list(dep)
    rng = np.random.default_rng(7)
    sub = {s: sp.Float(v) for s, v in zip(sorted(phi_q.free_symbols, key=str),
                                          rng.uniform(0.3, 1.3, len(phi_q.free_symbols)),
                                          strict=True)}
    num = np.array(phi_q.xreplace(sub).evalf().tolist(), dtype=complex).real
    chosen = []
    for j in dep:
        if np.linalg.matrix_rank(num[:, chosen + [j]], tol=1e-9) == len(chosen) + 1:
            chosen.append(j)
        if len(chosen) == p:
            return chosen
    raise ArgumentError(
        "the holonomic constraints cannot be solved for dependent parameters at the "
        "reference state (their Jacobian is rank deficient there): a locked or singular "
        "configuration of the loop.")


def _reference(eqs, red, norm, about, velocities, values_of):
    """q*, the rates q'* (dependent ones computed from the constraints) and the velocity
    residual of the rates the user gave for dependent parameters."""
    n = len(eqs.coordinates)
    q_s, uI, uD, _, _, _ = red.plain
    q_star = values_of(about, norm, "about")
    given = _rates(velocities, eqs, red, norm)
    ind = [eqs.coordinates.index(c) for c in red.independent]
    dep = [eqs.coordinates.index(c) for c in red.dependent]
    u_star = {uI[r]: given.get(j, sp.S.Zero) for r, j in enumerate(ind)}
    point = dict(zip(q_s, q_star, strict=True)) | u_star
    rates = [None] * n
    for r, j in enumerate(ind):
        rates[j] = u_star[uI[r]]
    for r, j in enumerate(dep):
        rates[j] = uD[r].xreplace(point)
    return q_star, rates, given, point, ind, dep


def _check_constraints(eqs, red, point, rates, given, tol):
    c = eqs.constraints
    q_s, u_s, _, rule, _, _ = eqs._symbolic()
    memo = {}
    names = eqs.names
    pos = [p for p in c.position]
    phi_rows = [k for k, p in enumerate(pos) if p is not None]
    phi = xreplace_shared([pos[k] for k in phi_rows], rule, memo)
    phi_val = [sp.sympify(e).xreplace(point) for e in phi]
    bad = [(c.labels[k], v) for k, v in zip(phi_rows, phi_val, strict=True)
           if not _vanishes(v, tol)]
    about = {names[j]: point[q] for j, q in enumerate(q_s)}
    if bad:
        raise ArgumentError(
            f"`about` violates the constraints: the residual Φ(q*) = "
            f"{', '.join(f'{lab}: {v}' for lab, v in bad)} is not 0 at q* = {about}. Give "
            "a configuration on the loop (solve its closure for the dependent parameters).")
    wrong = []
    for j, v in given.items():
        if not _vanishes(sp.sympify(v) - rates[j], tol):
            wrong.append(f"{names[j]}' = {v} (the constraints give {rates[j]})")
    if wrong:
        vel = xreplace_shared(list(c.velocity), rule, {})
        full = point | dict(zip(u_s, [sp.sympify(given.get(j, rates[j]))
                                      for j in range(len(q_s))], strict=True))
        res = [sp.sympify(e).xreplace(full) for e in vel]
        raise ArgumentError(
            f"`velocities` violate the constraints: residual A q'* + a = {res} "
            f"({'; '.join(wrong)}) at q* = {about}. Give only the independent rates "
            f"{[str(x) for x in red.independent]}: the others follow.")
    return phi, phi_rows


def linearize_constrained(eqs, about, velocities, w, w_star, extra, *, check, tol,
                          independent, values_of, normalise):
    """Linearise constrained equations (see the module); arguments as
    :func:`rigidmech.vibrations.linearize`. Returns the pieces of the LinearSystem."""
    red = eqs.reduced(independent)
    norm = normalise(eqs)
    q_s, uI, uD, _, Mr, fr = red.plain
    n, k = len(q_s), len(uI)
    q_star, rates, given, point, ind, dep = _reference(eqs, red, norm, about, velocities,
                                                      values_of)
    point |= dict(zip(w, w_star, strict=True)) | extra
    phi, phi_rows = _check_constraints(eqs, red, point, rates, given, tol) if check else \
        (None, None)
    if phi is None:
        c = eqs.constraints
        rule = eqs._symbolic()[3]
        phi = xreplace_shared([p for p in c.position if p is not None], rule, {})
    variables = list(q_s) + list(uI) + list(w)
    vals, jac = values_and_jacobian(list(fr) + list(phi), point, variables)
    f_val, J = vals[:k], sp.Matrix(jac[:k])
    phi_q = sp.Matrix(len(phi), n, lambda i, j: jac[k + i][j]) if phi else sp.zeros(0, n)
    M0 = sp.ImmutableMatrix(k, k, values_and_jacobian(list(Mr), point, [])[0])
    names = eqs.names
    about_named = dict(zip(names, q_star, strict=True))
    vel_named = dict(zip(names, rates, strict=True))
    if check:
        drift = J[:, :n] * sp.Matrix(rates)
        res = [sp.simplify(r) if not sp.sympify(r).is_number else r for r in f_val]
        res_rate = [sp.simplify(r) if not r.is_number else r for r in drift]
        if not all(_vanishes(r, tol) for r in res + res_rate):
            moving = any(not _vanishes(r, 0.0) for r in rates)
            kind = "a steady motion" if moving else "an equilibrium"
            raise ArgumentError(
                f"`about` is not {kind} of the reduced equations (u'* = 0 needs f_r = 0 "
                f"and d f_r/dt = 0 along the motion): residual f_r(q*, u*) = {res}, its rate "
                f"(df_r/dq) q'* = {res_rate}, at q* = {about_named}, q'* = {vel_named}.")
    hol = _holonomic_split(phi_q, dep)
    rest = [j for j in range(n) if j not in hol]
    Jq = J[:, :n]
    if hol:
        G = -phi_q[:, hol].LUsolve(phi_q[:, rest])
        Kq = Jq[:, rest] + Jq[:, hol] * G
    else:
        Kq = Jq[:, rest]
    free = [j for j in rest if j not in ind]
    for col, j in enumerate(rest):
        if j in free and not all(_vanishes(Kq[i, col], tol) for i in range(k)):
            raise ArgumentError(
                f"the reduced equations depend on {names[j]} at the reference state, a "
                f"parameter whose rate is fixed by a nonholonomic constraint: it cannot be "
                f"left out of the linear system on the independent parameters "
                f"{[str(c) for c in red.independent]}. Linearise about a state where they "
                "are invariant under its change, or choose other `independent` ones.")
    order = [rest.index(j) for j in ind]
    K = -Kq[:, order]
    C = -J[:, n:n + k]
    B = J[:, n + k:]
    return red, M0, C, K, B, about_named, vel_named
