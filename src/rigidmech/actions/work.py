"""Work of a force along a path and of an action along a motion; conservative fields and
their potential energy (book, ch. 11.3, 18.3).

The work of a force F along the path C of its point of application, parametrised by s from
s0 to s1, and the work of an action along a motion between t0 and t1 (the integral of its
power, the comoment of the action torsor with the kinematic torsor, ch. 11.3.1) are

.. math::
    W_C(\\mathbf{F}) = \\int_{s_0}^{s_1} \\mathbf{F}\\cdot\\frac{d\\mathbf{r}}{ds}\\,ds,
    \\qquad
    W_{t_0\\to t_1} = \\int_{t_0}^{t_1} \\{\\mathcal{F}\\}\\cdot\\{\\mathcal{V}\\}\\,dt .

A force field F(x, y, z) is conservative when its curl is zero (on a simply connected
domain); then F = -grad E_p, E_p being the potential energy, defined up to a constant
(ch. 11.3.3), and the work along any path is E_p(start) - E_p(end).
"""

from __future__ import annotations

import sympy as sp

from .._core.errors import ArgumentError, ArgumentTypeError
from ..kinematics import Solid, kinematic_torsor
from ..torsors import Torsor
from ..vectors import Curve, Frame, Point, Vector, t
from .actions import Action

__all__ = ["work_along_path", "power_of", "work_along_motion", "curl", "is_conservative",
           "potential_energy_of"]


def _integrate(expr, var, a, b, method):
    if method not in ("auto", "symbolic", "numeric"):
        raise ArgumentError(f"`method` must be 'auto', 'symbolic' or 'numeric'; got {method!r}.")
    a, b = sp.sympify(a), sp.sympify(b)
    if method != "numeric":
        try:
            value = sp.integrate(expr, (var, a, b))
        except (NotImplementedError, sp.PolynomialError, ValueError):  # sympy gave up
            value = sp.Integral(expr, (var, a, b))
        if not value.has(sp.Integral):
            return sp.simplify(value)
        if method == "symbolic":
            return value
    numeric = (expr.free_symbols <= {var} and not expr.atoms(sp.core.function.AppliedUndef)
               and a.is_number and b.is_number)
    if not numeric:
        if method == "auto":
            return sp.Integral(expr, (var, a, b))
        raise ArgumentError(
            "`method='numeric'` needs numeric bounds and an integrand depending on the "
            f"integration variable only; got {expr} between {a} and {b}: substitute values.")
    # Imported on use: scipy.integrate costs about 0.7 s to import.
    from scipy.integrate import quad

    f = sp.lambdify(var, expr, "math")
    value, _ = quad(f, float(a), float(b), limit=200, epsabs=1e-13, epsrel=1e-12)
    return sp.Float(value)


def _check_variables(variables):
    try:
        v = tuple(variables)
    except TypeError as exc:
        raise ArgumentTypeError(
            f"`variables` must be the 3 symbols (x, y, z); got {variables!r}.") from exc
    if len(v) != 3 or not all(isinstance(x, sp.Symbol) for x in v):
        raise ArgumentTypeError(f"`variables` must be the 3 symbols (x, y, z); got {variables!r}.")
    return v


def _field_components(field, frame, variables):
    if not isinstance(field, Vector):
        raise ArgumentTypeError(f"`field` must be a Vector; got {type(field).__name__}.")
    if not isinstance(frame, Frame):
        raise ArgumentTypeError(f"`frame` must be a Frame; got {type(frame).__name__}.")
    return field.components(frame), _check_variables(variables)


def work_along_path(force: Vector, path, start, end, *, variables=None, method="auto",
                    parameter=None, frame=None):
    """The work of ``force`` along ``path`` between the parameter values ``start`` and ``end``
    (ch. 11.3.4).

    Parameters
    ----------
    force : Vector
        The force; its components may depend on the path's parameter s (a friction force
        -f T, say) and on the coordinates ``variables`` (a field F(x, y, z)), which are
        replaced by those of the current point.
    path : Curve or Point
        The path r(s) of the point of application, relative to ``path.frame``; or a Point
        whose position depends on ``parameter``, described relative to ``frame``.
    start, end : number or sympy expression
    variables : (x, y, z) sympy Symbols, optional
        The Cartesian coordinates in ``path.frame`` that ``force`` uses, if any.
    method : {"auto", "symbolic", "numeric"}
        As for :meth:`Curve.arc_length <rigidmech.vectors.Curve.arc_length>`.
    parameter : sympy.Symbol, optional
        With a Point ``path``: its parameter (the time :data:`rigidmech.t`, say).
    frame : Frame, optional
        With a Point ``path``: the reference of the path.

    Examples
    --------
    Gravity -m g k along a helix: only the drop in height counts.

    >>> import sympy as sp
    >>> from rigidmech import Frame, Curve
    >>> s = sp.Symbol("s", real=True); m, g, a, b = sp.symbols("m g a b", positive=True)
    >>> R0 = Frame("R0")
    >>> helix = Curve(R0.vector(a * sp.cos(s), a * sp.sin(s), b * s), s, R0)
    >>> work_along_path(-m * g * R0.k, helix, 0, 2 * sp.pi)
    -2*pi*b*g*m
    """
    if isinstance(path, Point):
        if parameter is None or frame is None:
            raise ArgumentTypeError(
                f"`parameter` and `frame` are needed with the Point {path.name} as `path`.")
        path = Curve(path, parameter, frame)
    if not isinstance(path, Curve):
        raise ArgumentTypeError(
            f"`path` must be a Curve or a Point; got "
            f"{type(path).__name__}.")
    if not isinstance(force, Vector):
        raise ArgumentTypeError(f"`force` must be a Vector; got {type(force).__name__}.")
    s = path.parameter
    F = force.components(path.frame)
    if variables is not None:
        x = _check_variables(variables)
        r = path.position().components(path.frame)
        F = F.xreplace(dict(zip(x, r, strict=True)))
    integrand = sp.simplify(F.dot(path.velocity().components(path.frame)))
    return _integrate(integrand, s, start, end, method)


def power_of(action: Action, solids, *, relative_to: Frame) -> sp.Expr:
    """The power of ``action`` on ``solids`` relative to ``relative_to``: the sum of the
    comoments of its torsors with the kinematic torsors of the solids they act on
    (ch. 11.3.1).

    Examples
    --------
    >>> import rigidmech as rm
    >>> q = rm.coordinates("q"); C = rm.constants("C")
    >>> R0 = rm.Frame("R0"); S = rm.Solid("S", frame=R0.rotated("R1", about=R0.k, angle=q))
    >>> power_of(rm.Couple(on=S, moment=C * R0.k), [S], relative_to=R0)
    C*Derivative(q(t), t)
    """
    if not isinstance(action, Action):
        raise ArgumentTypeError(f"`action` must be an Action; got {type(action).__name__}.")
    if not isinstance(relative_to, Frame):
        raise ArgumentTypeError(
            f"`relative_to` must be a Frame; got {type(relative_to).__name__}.")
    solids = list(solids)
    total = sp.S.Zero
    for solid, torsor in action.contributions(solids):
        if not isinstance(solid, Solid):
            raise ArgumentTypeError(f"the action returned {solid!r}, not a Solid.")
        V = kinematic_torsor(solid.frame, relative_to=relative_to, at=torsor.point,
                             anchor=solid.anchor)
        total += torsor.comoment(V)
    return total


def work_along_motion(action, motion, *, start, end, trajectory=None, relative_to=None,
                      method="auto"):
    """The work of an action along a motion between the times ``start`` and ``end``: the
    integral of its power (ch. 11.3.4, 18.3).

    Parameters
    ----------
    action : Torsor or Action
        An action torsor, with ``motion`` the kinematic torsor of the solid it acts on; or an
        :class:`Action`, with ``motion`` the list of solids and ``relative_to`` the reference.
    motion : Torsor or list of Solid
    start, end : number or sympy expression
        The times t0 and t1.
    trajectory : dict, optional
        The motion as explicit functions of time, ``{q(t): expression of t}``; the power is
        written with them (derivatives included) before integration.
    relative_to : Frame, optional
        Needed with an :class:`Action`.
    method : {"auto", "symbolic", "numeric"}

    Examples
    --------
    A couple C k0 on a body turning at the constant rate w does C w T in the time T:

    >>> import rigidmech as rm
    >>> q = rm.coordinates("q"); C, w, T = rm.constants("C w T", positive=True)
    >>> R0 = rm.Frame("R0"); R1 = R0.rotated("R1", about=R0.k, angle=q)
    >>> V = rm.kinematic_torsor(R1, relative_to=R0, at=R0.origin)
    >>> work_along_motion(rm.couple(C * R0.k, R0.origin), V, start=0, end=T,
    ...                   trajectory={q: w * rm.t})
    C*T*w
    """
    if isinstance(action, Torsor):
        if not isinstance(motion, Torsor):
            raise ArgumentTypeError(
                f"`motion` must be the kinematic torsor of the solid; got "
                f"{type(motion).__name__}.")
        p = action.comoment(motion)
    elif isinstance(action, Action):
        if relative_to is None:
            raise ArgumentTypeError("`relative_to` is needed with an Action: the reference "
                                    "of the motion.")
        p = power_of(action, motion, relative_to=relative_to)
    else:
        raise ArgumentTypeError(
            f"`action` must be a Torsor or an Action; got {type(action).__name__}.")
    if trajectory is not None:
        if not isinstance(trajectory, dict):
            raise ArgumentTypeError(
                f"`trajectory` must be a dict {{q(t): expression}}; got "
                f"{type(trajectory).__name__}.")
        p = p.subs({q: sp.sympify(e) for q, e in trajectory.items()}).doit()
    return _integrate(sp.simplify(p), t, start, end, method)


def curl(field: Vector, frame: Frame, variables) -> sp.ImmutableMatrix:
    """The curl of a field F(x, y, z) given in ``frame`` with the coordinates ``variables``,
    as components in ``frame``.

    Examples
    --------
    >>> import sympy as sp
    >>> from rigidmech import Frame
    >>> x, y, z = sp.symbols("x y z", real=True); R0 = Frame("R0")
    >>> curl(R0.vector(-y, x, 0), R0, (x, y, z)).T
    Matrix([[0, 0, 2]])
    """
    F, (x, y, z) = _field_components(field, frame, variables)
    return sp.ImmutableMatrix([
        sp.diff(F[2], y) - sp.diff(F[1], z),
        sp.diff(F[0], z) - sp.diff(F[2], x),
        sp.diff(F[1], x) - sp.diff(F[0], y),
    ])


def is_conservative(field: Vector, frame: Frame, variables) -> bool:
    """Whether the curl of the field simplifies to zero (ch. 11.3.3).

    Examples
    --------
    >>> import sympy as sp
    >>> from rigidmech import Frame
    >>> x, y, z = sp.symbols("x y z", real=True); R0 = Frame("R0")
    >>> is_conservative(R0.vector(x, y, z), R0, (x, y, z))
    True
    """
    return all(sp.simplify(c) == 0 for c in curl(field, frame, variables))


def potential_energy_of(field: Vector, frame: Frame, variables, *, reference=(0, 0, 0)):
    """The potential energy E_p(x, y, z) of a conservative force field, F = -grad E_p,
    with E_p(reference) = 0 (ch. 11.3.3).

    Computed as minus the work along the straight segment from ``reference`` to (x, y, z)
    (valid on a domain star-shaped about ``reference``), and checked: -grad E_p must give back
    the field.

    Raises
    ------
    ArgumentError
        If the field is not conservative (its curl is given in the message).

    Examples
    --------
    >>> import sympy as sp
    >>> from rigidmech import Frame
    >>> x, y, z = sp.symbols("x y z", real=True); k = sp.Symbol("k", positive=True)
    >>> R0 = Frame("R0")
    >>> potential_energy_of(-k * R0.vector(x, y, z), R0, (x, y, z))
    k*(x**2 + y**2 + z**2)/2
    """
    F, (x, y, z) = _field_components(field, frame, variables)
    c = [sp.simplify(e) for e in curl(field, frame, variables)]
    if any(e != 0 for e in c):
        raise ArgumentError(
            f"`field` must be conservative (zero curl) to have a potential energy; got curl "
            f"{tuple(c)} in {frame.name}.")
    ref = [sp.sympify(v) for v in reference]
    d = [v - r0 for v, r0 in zip((x, y, z), ref, strict=True)]
    lam = sp.Dummy("lambda", positive=True)
    on_segment = {v: r0 + lam * dv for v, r0, dv in zip((x, y, z), ref, d, strict=True)}
    integrand = sp.simplify(sum(F[n].xreplace(on_segment) * d[n] for n in range(3)))
    w = sp.integrate(integrand, (lam, 0, 1))
    Ep = sp.simplify(-w)
    residual = [sp.simplify(F[n] + sp.diff(Ep, v)) for n, v in enumerate((x, y, z))]
    if any(e != 0 for e in residual):
        raise ArgumentError(
            f"could not verify the potential energy {Ep} of `field` (-grad E_p - F = "
            f"{tuple(residual)}); the field may be singular on the segment from `reference` "
            f"{tuple(reference)}: choose another reference point.")
    return Ep

