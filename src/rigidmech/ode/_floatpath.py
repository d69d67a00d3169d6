"""Plain-float kernels of the explicit Runge-Kutta pairs, for small systems.

For a handful of equations, numpy's per-call overhead (about 1-3 us for a tiny ``@``) dwarfs
the arithmetic: a step of DOP853 makes some 90 small array operations. Here the stages are
combined in plain Python floats by a function *generated once per tableau* (the coefficients
inlined, zero terms dropped), and ``fun`` still receives a fresh ndarray at every call. Used
by :mod:`~rigidmech.ode.adaptive` for a single trajectory with ``n <= FLOAT_PATH_MAX_N``; the
code is unrolled over the stages and over the components.
"""

from __future__ import annotations

import numpy as np

__all__ = ["FLOAT_PATH_MAX_N", "make_unrolled_stepper"]

#: Largest system size for which the plain-float kernel is used (measured crossover with the
#: numpy path: about 16 equations for DOP853 on a 2-core machine).
FLOAT_PATH_MAX_N = 12


def _combo(coeffs, names):
    terms = [f"{float(a)!r}*{k}" for a, k in zip(coeffs, names, strict=True) if a != 0.0]
    return " + ".join(terms) if terms else "0.0"


def _compile(name, lines):
    src = "\n".join(lines)
    namespace = {"_arr": np.array, "_tolist": np.ndarray.tolist}
    exec(compile(src, f"<rigidmech.ode {name} float kernel>", "exec"), namespace)  # noqa: S102
    return namespace[f"step_{name}"]


def make_unrolled_stepper(name, A, b, c, s, errors, n, norm=False):
    """Generate ``step(fun, t, y, k0, h) -> (y_new, ks, y_last_stage, *error_vectors)``.

    With ``errors=None`` the step of a fixed-step method is generated instead:
    ``step(fun, t, y, k0, h) -> y_new``, without the evaluation at ``(t + h, y_new)``.

    With ``norm=True`` the step is ``step(fun, t, y, k0, h, rtol, atols)`` and returns, in
    place of each error vector ``e``, its weighted sum of squares
    ``sum((e_j / (atol_j + rtol max(|y_j|, |y_new_j|)))**2)`` (`atols`: list of `n` floats),
    so that the adaptive driver needs no loop over the components.

    Parameters
    ----------
    name : str
        Used in the generated function's name.
    A, b, c : ndarray
        Tableau of the ``s`` stages (``b`` has ``s`` entries).
    s : int
        Number of stages before the FSAL evaluation ``f(t + h, y_new)``.
    errors : list of ndarray, shape (s + 1,)
        Weight vectors whose combinations of the ``s + 1`` stages are returned (unscaled).
    n : int
        Number of equations.

    Returns
    -------
    callable
        ``y`` and ``k0`` are lists of floats; ``ks`` is the tuple of the ``s + 1`` stage lists.

    Examples
    --------
    >>> import numpy as np
    >>> step = make_unrolled_stepper("euler", np.zeros((1, 1)), np.ones(1), np.zeros(1), 1,
    ...                              [np.array([-1.0, 1.0])], 1)
    >>> step(lambda t, y: -y, 0.0, [1.0], [-1.0], 0.1)[0]
    [0.9]
    >>> make_unrolled_stepper("euler", np.zeros((1, 1)), np.ones(1), np.zeros(1), 1, None,
    ...                       1)(lambda t, y: -y, 0.0, [1.0], [-1.0], 0.1)
    [0.9]
    >>> step = make_unrolled_stepper("euler", np.zeros((1, 1)), np.ones(1), np.zeros(1), 1,
    ...                              [np.array([-1.0, 1.0])], 1, norm=True)
    >>> out = step(lambda t, y: -y, 0.0, [1.0], [-1.0], 0.1, 0.1, [0.01])
    >>> out[0], round(out[3], 12)  # e = -k0 + k1 = 0.1; scale = 0.01 + 0.1 * 1.0
    ([0.9], 0.826446280992)
    """
    if norm:
        lines = [f"def step_{name}_{n}n(fun, t, y, k0, h, rtol, atols):"]
    else:
        lines = [f"def step_{name}_{n}(fun, t, y, k0, h):"]
    comps = range(n)
    lines.append(f"    {', '.join(f'y_{j}' for j in comps)}, = y")
    lines.append(f"    {', '.join(f'k0_{j}' for j in comps)}, = k0")

    def combo(coeffs, stage_count, j):
        return _combo(coeffs[:stage_count], [f"k{i}_{j}" for i in range(stage_count)])

    last = "y"
    for i in range(1, s):
        elems = ", ".join(f"y_{j} + h*({combo(A[i], i, j)})" for j in comps)
        lines.append(f"    ys = [{elems}]")
        lines.append(f"    k{i} = _tolist(fun(t + {float(c[i])!r}*h, _arr(ys)))")
        lines.append(f"    {', '.join(f'k{i}_{j}' for j in comps)}, = k{i}")
        last = "ys"
    for j in comps:
        lines.append(f"    yn_{j} = y_{j} + h*({combo(b, s, j)})")
    lines.append(f"    yn = [{', '.join(f'yn_{j}' for j in comps)}]")
    if errors is None:
        lines.append("    return yn")
        return _compile(f"{name}_{n}", lines)
    lines.append(f"    k{s} = _tolist(fun(t + h, _arr(yn)))")
    lines.append(f"    {', '.join(f'k{s}_{j}' for j in comps)}, = k{s}")
    outs = []
    if norm:
        lines.append(f"    {', '.join(f'at_{j}' for j in comps)}, = atols")
        for e_idx in range(len(errors)):
            lines.append(f"    s{e_idx} = 0.0")
        for j in comps:
            lines.append(f"    a = abs(y_{j})")
            lines.append(f"    b = abs(yn_{j})")
            lines.append(f"    sc = at_{j} + rtol*(a if a > b else b)")
            for e_idx, e in enumerate(errors):
                lines.append(f"    w = ({combo(e, s + 1, j)}) / sc")
                lines.append(f"    s{e_idx} += w*w")
        outs = [f"s{e_idx}" for e_idx in range(len(errors))]
    else:
        for e_idx, e in enumerate(errors):
            elems = ", ".join(combo(e, s + 1, j) for j in comps)
            lines.append(f"    e{e_idx} = [{elems}]")
            outs.append(f"e{e_idx}")
    lines.append(f"    return yn, ({', '.join(f'k{i}' for i in range(s + 1))},), {last}, "
                 f"{', '.join(outs)}")
    return _compile(f"{name}_{n}{'n' if norm else ''}", lines)
