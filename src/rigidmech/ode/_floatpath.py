"""The one generator of plain-float kernels of :mod:`rigidmech.ode`, for small systems.

For a handful of equations, numpy's per-call overhead (about 1-3 us for a tiny ``@``) dwarfs
the arithmetic: a step of DOP853 makes some 90 small array operations. Here the stages are
combined in plain Python floats by a function *generated once per tableau* (the coefficients
inlined, zero terms dropped), and ``fun`` still receives a fresh ndarray at every call. Used
by :mod:`~rigidmech.ode.adaptive` for a single trajectory with ``n <= FLOAT_PATH_MAX_N``; the
code is unrolled over the stages and over the components.

Every generated function of the layer comes from here, through one compiler
(:func:`compile_function`) and one cache (:func:`cached`): the explicit Runge-Kutta steps
(:func:`make_unrolled_stepper`, fixed-step and embedded pairs, from a Butcher tableau), the
Runge-Kutta-Nystrom steps (:func:`make_rkn_stepper`, from an RKN pair's coefficients) and
Gragg's midpoint substeps of the extrapolation method (:func:`make_midpoint`); the Adams run
hands its source to :func:`compile_function` and :func:`cached`.
"""

from __future__ import annotations

import math

import numpy as np

from ._loop import StepResult

__all__ = ["FLOAT_PATH_MAX_N", "make_unrolled_stepper", "make_fixed_advance", "make_pair_step",
           "error_norm", "ERROR_NORM_LINES", "make_rkn_stepper", "make_midpoint",
           "compile_function", "cached"]

#: Largest system size for which the plain-float kernel is used (measured crossover with the
#: numpy path: about 16 equations for DOP853 on a 2-core machine).
FLOAT_PATH_MAX_N = 12


def _combo(coeffs, names):
    terms = [f"{float(a)!r}*{k}" for a, k in zip(coeffs, names, strict=True) if a != 0.0]
    return " + ".join(terms) if terms else "0.0"


_CACHE: dict = {}


def cached(key, build):
    """The kernel of `key`, built once by ``build()`` (the one cache of generated code)."""
    fn = _CACHE.get(key)
    if fn is None:
        fn = _CACHE[key] = build()
    return fn


def compile_function(lines, name, label, namespace=None):
    """Compile the source `lines` and return its function `name` (the one ``exec`` of ode).

    The namespace holds ``_arr`` (:func:`numpy.array`), ``_tolist`` and `namespace`.

    Examples
    --------
    >>> compile_function(["def f(x):", "    return _arr([x]).tolist()"], "f", "doc")(2.0)
    [2.0]
    """
    ns = {"_arr": np.array, "_tolist": np.ndarray.tolist, **(namespace or {})}
    exec(compile("\n".join(lines), f"<rigidmech.ode {label}>", "exec"), ns)  # noqa: S102
    return ns[name]


def _compile(name, lines):
    return compile_function(lines, f"step_{name}", f"{name} float kernel")


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
    lines = _unrolled_lines(name, A, b, c, s, errors, n, norm)
    return _compile(f"{name}_{n}{'n' if norm and errors is not None else ''}", lines)


def make_fixed_advance(name, A, b, c, s, n):
    """The step of a fixed-step tableau for `n` equations, as a factory bound once per run.

    ``bind(fun, y, k0) -> advance(t, h)``: ``advance`` makes one step from the state it keeps
    (`y`, a list of floats; `k0`, ``f(t, y)`` already evaluated, or None) and returns
    ``(y_new, None)``, the form :func:`rigidmech.ode._fixed.fixed_loop` expects: the stage
    ``f(t, y)`` and the whole step in one generated function (no Python frame around it).

    Examples
    --------
    >>> import numpy as np
    >>> bind = make_fixed_advance("euler", np.zeros((1, 1)), np.ones(1), np.zeros(1), 1, 1)
    >>> advance = bind(lambda t, y: -y, [1.0], None)
    >>> advance(0.0, 0.1), advance(0.1, 0.1)[0]
    (([0.9], None), [0.81])
    """
    body = _unrolled_lines(name, A, b, c, s, None, n, False)
    lines = ["def make(fun, y, k0):", "    def advance(t, h):", "        nonlocal y, k0",
             "        if k0 is None:", "            k0 = _tolist(fun(t, _arr(y)))"]
    lines += ["    " + line for line in body[1:-1]]
    lines += ["        y = yn", "        k0 = None", "        return yn, None",
              "    return advance"]
    return cached(("fixed-advance", name, A.tobytes(), b.tobytes(), c.tobytes(), n),
                  lambda: compile_function(lines, "make", f"{name} fixed step n={n}"))


#: The error norm of an embedded pair from the weighted sums of squares ``s0`` (and ``s1``) of
#: its error vectors over ``n`` components, as source: Hairer's RMS norm for one error vector;
#: for two, DOP853's combination of its 5th- and 3rd-order estimates (Hairer's code:
#: ``err5**2 / sqrt(err5**2 + 0.01 err3**2)``; a nan stays nan, so that the step is rejected).
#: The one definition of the formulas: compiled into the generated steps
#: (:func:`make_pair_step`) and into :func:`error_norm` for the numpy path.
ERROR_NORM_LINES = {
    1: ("err = {h_abs}*_sqrt(s0/{n})",),
    2: ("den = s0 + 0.01*s1",
        "err = {h_abs}*s0/_sqrt(den*{n}) if den > 0 else (0.0 if den == 0 else den)"),
}


def error_norm(m):
    """``norm(h_abs, s0, s1, n) -> err``: :data:`ERROR_NORM_LINES` for `m` error vectors as a
    function (`s1` unused for one).

    Examples
    --------
    >>> error_norm(2)(0.5, 4.0, 0.0, 1), error_norm(1)(0.5, 4.0, None, 1)
    (1.0, 1.0)
    """
    return cached(("error-norm", m), lambda: compile_function(
        ["def norm(h_abs, s0, s1, n):"]
        + ["    " + line.format(n="n", h_abs="h_abs") for line in ERROR_NORM_LINES[m]]
        + ["    return err"], "norm", f"error norm of {m} vectors", {"_sqrt": math.sqrt}))


def make_pair_step(name, A, b, c, s, errors, n):
    """The step of an embedded pair for `n` equations, as a factory bound once per run.

    ``bind(fun, rtol, atols)`` returns ``step(t, y, k0, h) -> StepResult(y_new, k_last, err,
    (ks, y_last_stage))`` with the error norm of the pair computed inside (Hairer's RMS norm
    for one error vector, DOP853's combination for two): the whole attempt of the loop's
    plain-float stepper in one generated function (no Python frame around it).

    Examples
    --------
    >>> import numpy as np
    >>> bind = make_pair_step("euler", np.zeros((1, 1)), np.ones(1), np.zeros(1), 1,
    ...                       [np.array([-1.0, 1.0])], 1)
    >>> r = bind(lambda t, y: -y, 0.1, [0.01])(0.0, [1.0], [-1.0], 0.1)
    >>> r.y, round(r.error, 12)  # h * sqrt(0.826446280992 / 1)
    ([0.9], 0.090909090909)
    """
    return cached(("pair-step", name, n), lambda: compile_function(
        _pair_step_lines(name, A, b, c, s, errors, n), "make", f"{name} pair step n={n}",
        {"_new": tuple.__new__, "_SR": StepResult, "_sqrt": math.sqrt}))


def _pair_step_lines(name, A, b, c, s, errors, n):
    body = _unrolled_lines(name, A, b, c, s, errors, n, True)
    comps = range(n)
    lines = ["def make(fun, rtol, atols):"]
    lines.append(f"    {', '.join(f'at_{j}' for j in comps)}, = atols")
    lines.append("    def step(t, y, k0, h):")
    ret = body[-1]
    for line in body[1:-1]:
        if line.strip().startswith("at_0") and line.endswith("= atols"):
            continue
        lines.append("    " + line)
    lines += ["        " + line.format(n=n, h_abs="abs(h)")
              for line in ERROR_NORM_LINES[len(errors)]]
    ks, last = ret.split("return yn, ", 1)[1].rsplit(", s0", 1)[0].rsplit(", ", 1)
    lines.append(f"        return _new(_SR, (yn, k{s}, err, ({ks}, {last})))")
    lines.append("    return step")
    return lines


def _unrolled_lines(name, A, b, c, s, errors, n, norm):
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
        return lines
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
    return lines


def _rkn_source(pair, d, unrolled):
    """Generate ``step(fun, t, q, v, k1, h, rtol, aq, av, control)``.

    Returns ``(q1, v1, k_last, err2)`` where ``err2`` is the sum over the ``2 d`` components of
    the squared scaled error (0.0 when ``control`` is false). With `unrolled`, ``q``, ``v`` and
    the stages are lists of floats; otherwise 1-D ndarrays.
    """
    co = pair.floats()
    s = pair.stages
    dq = [x - y for x, y in zip(co["bbar"], co["bbar_hat"], strict=True)]
    dv = [x - y for x, y in zip(co["b"], co["b_hat"], strict=True)]
    idx = [f"[{j}]" for j in range(d)] if unrolled else [""]

    def vec(fmt):
        parts = [fmt(j) for j in idx]
        return "[" + ", ".join(parts) + "]" if unrolled else parts[0]

    def ks(i, j):
        return [f"k{m + 1}{j}" for m in range(i)]

    L = ["def step(fun, t, q, v, k1, h, rtol, aq, av, control):", "    h2 = h * h"]
    conv = ".tolist()" if unrolled else ".copy()"
    nk = s - 1 if pair.fsal else s  # stages entering q1 and v1 before the end-point call
    for i in range(1, nk):
        ci = co["c"][i]
        row = co["abar"][i][:i]

        def stage(j, i=i, ci=ci, row=row):
            return f"q{j} + {ci!r}*h*v{j} + h2*(" + _rcombo(row, ks(i, j)) + ")"

        L.append("    Q = " + vec(stage))
        L.append(f"    k{i + 1} = _asarray(fun(t + {ci!r}*h, _arr(Q)), dtype=float){conv}")
    wq, wv = co["bbar"][:nk], co["b"][:nk]
    L.append("    q1 = " + vec(lambda j: f"q{j} + h*v{j} + h2*(" + _rcombo(wq, ks(nk, j)) + ")"))
    L.append("    v1 = " + vec(lambda j: f"v{j} + h*(" + _rcombo(wv, ks(nk, j)) + ")"))
    # the acceleration at (t + h, q1): the last stage (FSAL) or the next step's first
    end = f"k{s}" if pair.fsal else "knext"
    L.append(f"    {end} = _asarray(fun(t + h, _arr(q1)), dtype=float){conv}")
    if pair.fsal:
        bs = co["b"][s - 1]
        if bs != 0.0:  # with FSAL the last stage may weigh in the velocity update
            L.append("    v1 = " + vec(lambda j: f"v1{j} + h*{bs!r}*k{s}{j}"))
    L.append("    if not control:")
    L.append(f"        return q1, v1, {end}, 0.0")
    L.append("    eq = " + vec(lambda j: "h2*(" + _rcombo(dq, ks(s, j)) + ")"))
    L.append("    ev = " + vec(lambda j: "h*(" + _rcombo(dv, ks(s, j)) + ")"))
    if unrolled:
        terms = []
        for j in range(d):
            terms.append(f"(eq[{j}]/(aq[{j}] + rtol*max(abs(q[{j}]), abs(q1[{j}]))))**2")
            terms.append(f"(ev[{j}]/(av[{j}] + rtol*max(abs(v[{j}]), abs(v1[{j}]))))**2")
        L.append("    err2 = " + " + ".join(terms))
    else:
        L.append("    sq = eq / (aq + rtol*_max(_abs(q), _abs(q1)))")
        L.append("    sv = ev / (av + rtol*_max(_abs(v), _abs(v1)))")
        L.append("    err2 = float(sq @ sq + sv @ sv)")
    L.append(f"    return q1, v1, {end}, err2")
    return L


def make_rkn_stepper(pair, d, unrolled):
    """The step of the Runge-Kutta-Nystrom `pair` for `d` positions (generated once).

    ``step(fun, t, q, v, k1, h, rtol, aq, av, control) -> (q1, v1, k_last, err2)`` where
    ``err2`` is the sum over the ``2 d`` components of the squared scaled error (0.0 when
    ``control`` is false). With `unrolled`, ``q``, ``v`` and the stages are lists of floats;
    otherwise 1-D ndarrays (one function for every `d`).

    Examples
    --------
    >>> from rigidmech.ode.rkn import DPRKN6
    >>> step = make_rkn_stepper(DPRKN6, 1, True)
    >>> q1, v1, a1, _ = step(lambda t, q: -q, 0.0, [1.0], [0.0], [-1.0], 0.1, 0.0, None,
    ...                      None, False)
    >>> bool(abs(q1[0] - np.cos(0.1)) < 1e-12)
    True
    """
    key = ("rkn", pair.name, d if unrolled else -1)
    return cached(key, lambda: compile_function(
        _rkn_source(pair, d, unrolled), "step", f"{pair.name} kernel d={d}",
        {"_arr": np.array, "_asarray": np.asarray, "_max": np.maximum, "_abs": np.abs}))


def _rcombo(coeffs, names):
    terms = [f"{a!r}*{k}" for a, k in zip(coeffs, names, strict=False) if a != 0.0]
    return " + ".join(terms) if terms else "0.0"


def make_midpoint(n):
    """Gragg's midpoint rule on `n` plain floats, unrolled over the components (cached).

    ``mid(fun, t, y, f0, hs, nj)`` makes `nj` substeps of `hs` from the lists `y`, `f0` and
    returns the final list; `fun` receives a fresh ndarray at every substep.

    Examples
    --------
    >>> mid = make_midpoint(1)
    >>> mid(lambda t, y: -y, 0.0, [1.0], [-1.0], 0.5, 2)  # y1 = 0.5, y2 = 1 - 1 * 0.5
    [0.5]
    """
    def build():
        c = range(n)
        p_ = ", ".join(f"p{j}" for j in c)
        q_ = ", ".join(f"q{j}" for j in c)
        lines = [
            "def mid(fun, t, y, f0, hs, nj):",
            f"    {p_}, = y",
            f"    {', '.join(f'f{j}' for j in c)}, = f0",
            *(f"    q{j} = p{j} + hs*f{j}" for j in c),
            "    h2 = hs + hs",
            "    for i in range(1, nj):",
            f"        {', '.join(f'f{j}' for j in c)}, = _tolist(fun(t + i*hs, _arr([{q_}])))",
            f"        {p_}, {q_} = {q_}, {', '.join(f'p{j} + h2*f{j}' for j in c)}",
            f"    return [{q_}]",
        ]
        return compile_function(lines, "mid", f"gbs midpoint {n}")

    return cached(("gbs-midpoint", n), build)
