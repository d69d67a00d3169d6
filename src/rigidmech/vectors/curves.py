"""Parametrised curves: arc length, Frenet trihedron, curvature, torsion (book, ch. 4).

A :class:`Curve` is the position r(s) of a point, relative to a frame, as a function of a
parameter s (ch. 4.1). Derivatives with respect to s are taken relative to that frame. With
the curvilinear abscissa sigma (``ds/dsigma = 1/|r'|``, ch. 4.2) the book defines the unit
tangent T, the principal normal N, the binormal B = T ^ N, the curvature kappa = 1/rho and
the torsion tau by the Frenet formulas (ch. 4.3-4.4)

.. math:: \\frac{d\\mathbf{T}}{d\\sigma} = \\kappa\\,\\mathbf{N}, \\qquad
          \\frac{d\\mathbf{N}}{d\\sigma} = -\\kappa\\,\\mathbf{T} + \\tau\\,\\mathbf{B}, \\qquad
          \\frac{d\\mathbf{B}}{d\\sigma} = -\\tau\\,\\mathbf{N},

computed for any parameter by ``kappa = |r' ^ r''| / |r'|^3`` and
``tau = (r', r'', r''') / |r' ^ r''|^2``. With this sign convention a right-handed helix has a
positive torsion. :func:`frenet_numeric` does the same for a curve known by samples.

Where r' = 0 the point is singular (no tangent): rigidmech raises an error instead of returning
nan. Where the curvature is zero (a straight line, an inflection point) N, B and the torsion are
undefined: asking for them raises an error; T and the curvature (0) are returned.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
import sympy as sp

from .._core.errors import ArgumentError, ArgumentTypeError
from .._core.symbolic import is_identically_zero
from .points import Point
from .vector import Vector, _check_frame

__all__ = ["Curve", "FrenetTrihedron", "FrenetSamples", "frenet_numeric"]


class FrenetTrihedron(NamedTuple):
    """The Frenet trihedron at a point of a curve, with the curvature and the torsion
    (ch. 4.4). Unpacks as ``T, N, B, kappa, tau``.

    Examples
    --------
    >>> import sympy as sp
    >>> from rigidmech.vectors import Frame
    >>> s = sp.Symbol("s", real=True)
    >>> R0 = Frame("R0")
    >>> T, N, B, kappa, tau = Curve(R0.vector(sp.cos(s), sp.sin(s), 0), s, R0).frenet(at=0)
    >>> N, kappa, tau
    (-R0.i, 1, 0)
    """

    tangent: Vector
    normal: Vector
    binormal: Vector
    curvature: sp.Expr
    torsion: sp.Expr


class Curve:
    """A curve r(s), parametrised by ``parameter``, relative to ``frame`` (ch. 4.1).

    Parameters
    ----------
    position : Point or Vector
        The current point M(s), or its position vector O M(s) from the origin of ``frame``.
    parameter : sympy.Symbol
        The parameter s (may be the time :data:`rigidmech.vectors.t`).
    frame : Frame
        The frame relative to which the curve is described and derivatives are taken; the
        vectors returned use its basis.

    Notes
    -----
    Every method takes ``at=None``: without it the result is a symbolic expression of the
    parameter (simplified); with a value it is the result at that parameter, computed from
    the derivatives at that value (so that a removable 0/0 is not created by simplification).
    A singular point is detected exactly at ``at``; symbolically only when the velocity is
    identically zero.

    Examples
    --------
    >>> import sympy as sp
    >>> from rigidmech.vectors import Frame
    >>> s = sp.Symbol("s", real=True)
    >>> a, b = sp.symbols("a b", positive=True)
    >>> R0 = Frame("R0")
    >>> helix = Curve(R0.vector(a * sp.cos(s), a * sp.sin(s), b * s), s, R0)
    >>> helix.curvature(), helix.torsion()
    (a/(a**2 + b**2), b/(a**2 + b**2))
    >>> helix.arc_length(0, 2 * sp.pi)
    2*pi*sqrt(a**2 + b**2)
    """

    __slots__ = ("_frame", "_parameter", "_r", "_derivs", "_position")

    def __init__(self, position, parameter, frame):
        _check_frame(frame, "frame")
        if isinstance(position, Point):
            if position.root != frame.root:
                raise ArgumentError(
                    f"`position` must be a point of the tree of {frame.name}; got point "
                    f"{position.name} of the tree rooted at {position.root.name}."
                )
            position = position - frame.origin
        if not isinstance(position, Vector):
            raise ArgumentTypeError(
                f"`position` must be a Point or a Vector; got {type(position).__name__}."
            )
        if not isinstance(parameter, sp.Symbol):
            raise ArgumentTypeError(
                f"`parameter` must be a sympy Symbol; got {type(parameter).__name__} "
                f"{parameter!r}."
            )
        self._frame = frame
        self._parameter = parameter
        self._position = position
        r = position.components(frame)
        self._r = r
        d1 = r.diff(parameter)
        d2 = d1.diff(parameter)
        self._derivs = (d1, d2, d2.diff(parameter))

    @property
    def parameter(self) -> sp.Symbol:
        """The parameter s."""
        return self._parameter

    @property
    def frame(self):
        """The frame relative to which the curve is described."""
        return self._frame

    def _vec(self, comps) -> Vector:
        # Numbers (a value of the parameter was given) are left in sympy's canonical form:
        # simplify costs ~0.1 s per algebraic number and seldom shortens them.
        return Vector.from_components(
            self._frame, [c if c.is_number else sp.simplify(c) for c in comps])

    def _at(self, at, upto=3):
        ds = self._derivs[:upto]
        if at is None:
            return ds
        value = sp.sympify(at)
        return tuple(d.subs(self._parameter, value) for d in ds)

    def _where(self, at):
        return f"{self._parameter} = {at}" if at is not None else "every parameter value"

    def _speed2(self, at):
        (d1,) = self._at(at, 1)
        v2 = sp.simplify(d1.dot(d1))
        if is_identically_zero(v2):
            raise ArgumentError(
                f"singular point: the velocity dr/d{self._parameter} is zero at "
                f"{self._where(at)}, so the curve has no tangent there; `at` must be a "
                "regular point."
            )
        return v2

    def _binormal_data(self, at):
        d1, d2, _ = self._at(at)
        self._speed2(at)
        c = d1.cross(d2)
        c2 = sp.simplify(c.dot(c))
        if is_identically_zero(c2):
            raise ArgumentError(
                f"the principal normal, the binormal and the torsion are undefined where the "
                f"curvature is zero; got zero curvature at {self._where(at)} (straight line "
                "or inflection point)."
            )
        return c, c2

    def position(self, at=None) -> Vector:
        """Position vector O M(s) in the basis of the frame.

        Examples
        --------
        >>> import sympy as sp
        >>> from rigidmech.vectors import Frame
        >>> s = sp.Symbol("s", real=True); R0 = Frame("R0")
        >>> Curve(R0.vector(s, s**2, 0), s, R0).position(at=2)
        2*R0.i + 4*R0.j
        """
        r = self._r if at is None else self._r.subs(self._parameter, sp.sympify(at))
        return self._vec(r)

    def velocity(self, at=None) -> Vector:
        """The derivative dr/ds relative to the frame (not normalised).

        Examples
        --------
        >>> import sympy as sp
        >>> from rigidmech.vectors import Frame
        >>> s = sp.Symbol("s", real=True); R0 = Frame("R0")
        >>> Curve(R0.vector(s, s**2, 0), s, R0).velocity()
        R0.i + 2*s*R0.j
        """
        return self._vec(self._at(at, 1)[0])

    def speed(self, at=None) -> sp.Expr:
        """``|dr/ds|``, the derivative of the curvilinear abscissa dsigma/ds (ch. 4.2).

        Examples
        --------
        >>> import sympy as sp
        >>> from rigidmech.vectors import Frame
        >>> s = sp.Symbol("s", real=True); R0 = Frame("R0")
        >>> Curve(R0.vector(3 * s, 4 * s, 0), s, R0).speed()
        5
        """
        (d1,) = self._at(at, 1)
        return sp.sqrt(sp.simplify(d1.dot(d1)))

    def arc_length(self, start, end, *, method: str = "auto"):
        """Length of the arc between the parameter values ``start`` and ``end`` (ch. 4.2).

        Parameters
        ----------
        start, end : number or sympy expression
        method : {"auto", "symbolic", "numeric"}
            "symbolic": sympy's integral, possibly unevaluated (``sympy.Integral``);
            "numeric": :func:`scipy.integrate.quad` of the speed (needs numeric bounds and no
            symbol but the parameter), returned as a ``sympy.Float``; "auto": symbolic, with
            the numeric fallback when sympy leaves the integral unevaluated and the data are
            numeric. sympy may take seconds on a hard integrand: ask "numeric" for speed.

        Returns
        -------
        sympy expression
            Signed: negative when ``end < start``.

        Examples
        --------
        >>> import sympy as sp
        >>> from rigidmech.vectors import Frame
        >>> s = sp.Symbol("s", real=True); R0 = Frame("R0")
        >>> Curve(R0.vector(s, sp.sin(s), 0), s, R0).arc_length(0, 1, method="numeric")
        1.31144249821555
        """
        if method not in ("auto", "symbolic", "numeric"):
            raise ArgumentError(
                f"`method` must be 'auto', 'symbolic' or 'numeric'; got {method!r}."
            )
        start, end = sp.sympify(start), sp.sympify(end)
        speed = self.speed()
        s = self._parameter
        if method != "numeric":
            try:
                value = sp.integrate(speed, (s, start, end))
            except (NotImplementedError, sp.PolynomialError, ValueError):  # sympy gave up
                value = sp.Integral(speed, (s, start, end))
            if not value.has(sp.Integral):
                return sp.simplify(value)
            if method == "symbolic":
                return value
        numeric = (speed.free_symbols <= {s} and not speed.atoms(sp.core.function.AppliedUndef)
                   and start.is_number and end.is_number)
        if not numeric:
            if method == "auto":
                return sp.Integral(speed, (s, start, end))
            raise ArgumentError(
                "`method='numeric'` needs numeric bounds and a speed depending on the parameter "
                f"only; got the speed {speed} between {start} and {end}: substitute values first."
            )
        # Imported on use: scipy.integrate costs about 0.7 s to import.
        from scipy.integrate import quad

        f = sp.lambdify(s, speed, "math")
        value, _ = quad(f, float(start), float(end), limit=200, epsabs=1e-13, epsrel=1e-12)
        return sp.Float(value)

    def curvilinear_abscissa(self, origin=0):
        """The curvilinear abscissa sigma(s) = integral from ``origin`` to s of ``|r'|`` (ch. 4.2).

        Returns a sympy expression of the parameter (an unevaluated ``Integral`` when sympy
        cannot integrate the speed).

        Examples
        --------
        >>> import sympy as sp
        >>> from rigidmech.vectors import Frame
        >>> s = sp.Symbol("s", real=True); R0 = Frame("R0")
        >>> Curve(R0.vector(2 * sp.cos(s), 2 * sp.sin(s), 0), s, R0).curvilinear_abscissa()
        2*s
        """
        u = sp.Dummy("u", real=True)
        speed = self.speed().subs(self._parameter, u)
        return sp.simplify(sp.integrate(speed, (u, sp.sympify(origin), self._parameter)))

    def tangent(self, at=None) -> Vector:
        """The unit tangent ``T = r' / |r'|`` (ch. 4.3).

        Examples
        --------
        >>> import sympy as sp
        >>> from rigidmech.vectors import Frame
        >>> s = sp.Symbol("s", real=True); R0 = Frame("R0")
        >>> Curve(R0.vector(3 * s, 4 * s, 0), s, R0).tangent()
        3/5*R0.i + 4/5*R0.j
        """
        v2 = self._speed2(at)
        (d1,) = self._at(at, 1)
        return self._vec(d1 / sp.sqrt(v2))

    def curvature(self, at=None) -> sp.Expr:
        """Curvature ``kappa = |r' ^ r''| / |r'|^3`` (ch. 4.3); 0 on a straight line.

        Examples
        --------
        >>> import sympy as sp
        >>> from rigidmech.vectors import Frame
        >>> s = sp.Symbol("s", real=True); R0 = Frame("R0")
        >>> Curve(R0.vector(s, s**2, 0), s, R0).curvature(at=0)
        2
        """
        v2 = self._speed2(at)
        d1, d2 = self._at(at, 2)
        c = d1.cross(d2)
        return sp.simplify(sp.sqrt(sp.simplify(c.dot(c))) / v2 ** sp.Rational(3, 2))

    def radius_of_curvature(self, at=None) -> sp.Expr:
        """Radius of curvature rho = 1 / kappa (ch. 4.3).

        Raises
        ------
        ArgumentError
            Where the curvature is zero (the radius is infinite).

        Examples
        --------
        >>> import sympy as sp
        >>> from rigidmech.vectors import Frame
        >>> s = sp.Symbol("s", real=True); R0 = Frame("R0")
        >>> Curve(R0.vector(3 * sp.cos(s), 3 * sp.sin(s), 0), s, R0).radius_of_curvature()
        3
        """
        _, c2 = self._binormal_data(at)
        return sp.simplify(1 / self.curvature(at))

    def binormal(self, at=None) -> Vector:
        """The binormal ``B = r' ^ r'' / |r' ^ r''| = T ^ N`` (ch. 4.4).

        Examples
        --------
        >>> import sympy as sp
        >>> from rigidmech.vectors import Frame
        >>> s = sp.Symbol("s", real=True); R0 = Frame("R0")
        >>> Curve(R0.vector(sp.cos(s), sp.sin(s), 0), s, R0).binormal()
        R0.k
        """
        c, c2 = self._binormal_data(at)
        return self._vec(c / sp.sqrt(c2))

    def normal(self, at=None) -> Vector:
        """The principal normal N = B ^ T, directed towards the centre of curvature (ch. 4.3).

        Raises
        ------
        ArgumentError
            Where the curvature is zero: N is undefined there.

        Examples
        --------
        >>> import sympy as sp
        >>> from rigidmech.vectors import Frame
        >>> s = sp.Symbol("s", real=True); R0 = Frame("R0")
        >>> Curve(R0.vector(sp.cos(s), sp.sin(s), 0), s, R0).normal()
        -cos(s)*R0.i - sin(s)*R0.j
        """
        c, c2 = self._binormal_data(at)
        (d1,) = self._at(at, 1)
        v2 = self._speed2(at)
        return self._vec(c.cross(d1) / sp.sqrt(c2 * v2))

    def torsion(self, at=None) -> sp.Expr:
        """Torsion ``tau = (r', r'', r''') / |r' ^ r''|^2`` (ch. 4.4); positive for a right-handed
        helix.

        Examples
        --------
        >>> import sympy as sp
        >>> from rigidmech.vectors import Frame
        >>> s = sp.Symbol("s", real=True); R0 = Frame("R0")
        >>> Curve(R0.vector(s, s**2, s**3), s, R0).torsion(at=0)
        3
        """
        c, c2 = self._binormal_data(at)
        _, _, d3 = self._at(at)
        return sp.simplify(c.dot(d3) / c2)

    def frenet(self, at=None) -> FrenetTrihedron:
        """The Frenet trihedron (T, N, B) with the curvature and the torsion (ch. 4.4).

        Examples
        --------
        >>> import sympy as sp
        >>> from rigidmech.vectors import Frame
        >>> s = sp.Symbol("s", real=True); R0 = Frame("R0")
        >>> Curve(R0.vector(sp.cos(s), sp.sin(s), s), s, R0).frenet(at=0).binormal
        -sqrt(2)/2*R0.j + sqrt(2)/2*R0.k
        """
        return FrenetTrihedron(self.tangent(at), self.normal(at), self.binormal(at),
                               self.curvature(at), self.torsion(at))

    def __repr__(self):
        return f"Curve({self._position!r}, {self._parameter}, {self._frame.name})"


class FrenetSamples(NamedTuple):
    """Frenet trihedra of a sampled curve (see :func:`frenet_numeric`); read-only arrays.

    Examples
    --------
    >>> FrenetSamples._fields
    ('tangent', 'normal', 'binormal', 'curvature', 'torsion', 'speed')
    """

    tangent: np.ndarray  #: (n, 3) unit tangents
    normal: np.ndarray  #: (n, 3) principal normals (nan where straight, if allowed)
    binormal: np.ndarray  #: (n, 3) binormals
    curvature: np.ndarray  #: (n,)
    torsion: np.ndarray  #: (n,)
    speed: np.ndarray  #: (n,) ``|dr/ds|``


def _readonly(a):
    a = np.array(a, dtype=float)
    a.setflags(write=False)
    return a


def frenet_numeric(points, params, *, method: str = "spline", straight: str = "raise",
                   curvature_atol=None) -> FrenetSamples:
    """Frenet trihedra, curvature and torsion of a curve known by samples (ch. 4.4).

    Parameters
    ----------
    points : array_like, shape (n, 3)
        Cartesian coordinates r(s_k) of the samples in one reference system.
    params : array_like, shape (n,)
        Strictly increasing parameter values s_k (any spacing).
    method : {"spline", "finite_differences"}
        "spline": derivatives of a not-a-knot :class:`scipy.interpolate.CubicSpline` through
        the samples (n >= 4); "finite_differences": :func:`numpy.gradient` applied one, two
        and three times, second order inside and at the ends (n >= 3).
    straight : {"raise", "nan"}
        What to do where the curvature is zero (below ``curvature_atol``): raise an
        ArgumentError naming the samples, or put nan in the normal, the binormal and the
        torsion there.
    curvature_atol : float, optional
        Curvature below which a sample counts as straight; default 1e-8 / L, with L the
        largest extent of the points.

    Returns
    -------
    FrenetSamples

    Raises
    ------
    ArgumentError
        On malformed input, at a singular sample (zero velocity) and at straight samples
        when ``straight="raise"``.

    Notes
    -----
    Accuracy measured on the helix r = (cos s, sin s, s/2) sampled with a uniform step h on
    [0, 2 pi] (kappa = 0.8, tau = 0.4; see tests/vectors/test_curves.py,
    ``test_numeric_accuracy``): maximum errors with n = 101 and 401 samples (h = 0.063 and
    0.016):

    ==================  ==================  ==================  ==================
    method              tangent             curvature           torsion
    ==================  ==================  ==================  ==================
    spline, inside      3e-8, 1e-10 (h^4)   3e-4, 2e-5 (h^2)    3e-4, 2e-5 (h^2)
    spline, ends        4e-5, 6e-7 (h^3)    2e-3, 1e-4 (h^2)    2e-3, 2e-4 (h^2)
    differences, in     2e-4, 1e-5 (h^2)    2e-4, 1e-5 (h^2)    2e-4, 1e-5 (h^2)
    differences, ends   5e-4, 3e-5 (h^2)    2e-3, 1e-4 (h^2)    0.25 (no convergence)
    ==================  ==================  ==================  ==================

    "Inside" excludes the first and last 10 % of the samples. With finite differences the
    torsion is wrong at the first and last three samples (the third derivative comes from
    three nested one-sided differences there): drop them. Prefer the spline for smooth data;
    finite differences are local (a noisy sample spoils only its neighbours).

    Examples
    --------
    >>> import numpy as np
    >>> s = np.linspace(0, 2 * np.pi, 201)
    >>> pts = np.column_stack([np.cos(s), np.sin(s), 0.5 * s])
    >>> res = frenet_numeric(pts, s)
    >>> bool(np.allclose(res.curvature[50:150], 0.8, rtol=1e-4))
    True
    """
    if method not in ("spline", "finite_differences"):
        raise ArgumentError(
            f"`method` must be 'spline' or 'finite_differences'; got {method!r}."
        )
    if straight not in ("raise", "nan"):
        raise ArgumentError(f"`straight` must be 'raise' or 'nan'; got {straight!r}.")
    try:
        pts = np.asarray(points, dtype=float)
        s = np.asarray(params, dtype=float)
    except (TypeError, ValueError) as exc:
        raise ArgumentTypeError("`points` and `params` must be numeric arrays.") from exc
    if pts.ndim != 2 or pts.shape[1] != 3:
        raise ArgumentError(f"`points` must have shape (n, 3); got {pts.shape}.")
    need = 4 if method == "spline" else 3
    if s.shape != (pts.shape[0],) or pts.shape[0] < need:
        raise ArgumentError(
            f"`params` must have shape (n,) matching `points` with n >= {need} for "
            f"method={method!r}; got params {s.shape} and points {pts.shape}."
        )
    if not (np.all(np.isfinite(pts)) and np.all(np.isfinite(s))):
        raise ArgumentError("`points` and `params` must be finite; got nan or inf.")
    if np.any(np.diff(s) <= 0):
        raise ArgumentError("`params` must be strictly increasing; got a non-increasing step.")
    if method == "spline":
        from scipy.interpolate import CubicSpline  # imported on use (slow import)

        spline = CubicSpline(s, pts, axis=0)
        d1, d2, d3 = spline(s, 1), spline(s, 2), spline(s, 3)
    else:
        d1 = np.gradient(pts, s, axis=0, edge_order=2)
        d2 = np.gradient(d1, s, axis=0, edge_order=2)
        d3 = np.gradient(d2, s, axis=0, edge_order=2)
    speed = np.linalg.norm(d1, axis=1)
    extent = float(np.max(np.ptp(pts, axis=0)))
    singular = np.flatnonzero(speed <= 1e-12 * max(float(speed.max()), 1e-300))
    if extent == 0.0 or singular.size:
        where = singular[:5].tolist() if singular.size else "all"
        raise ArgumentError(
            f"singular point: the velocity dr/ds is zero at samples {where}; the tangent is "
            "undefined there. `points` must describe a regular curve."
        )
    c = np.cross(d1, d2)
    cn = np.linalg.norm(c, axis=1)
    curvature = cn / speed**3
    atol = 1e-8 / extent if curvature_atol is None else float(curvature_atol)
    flat = curvature <= atol
    if flat.any() and straight == "raise":
        raise ArgumentError(
            f"the principal normal is undefined where the curvature is zero; got curvature "
            f"<= {atol:.3g} at samples {np.flatnonzero(flat)[:5].tolist()}"
            f"{' ...' if flat.sum() > 5 else ''}; pass straight='nan' to get nan there."
        )
    T = d1 / speed[:, None]
    with np.errstate(invalid="ignore", divide="ignore"):
        B = np.where(flat[:, None], np.nan, c / cn[:, None])
        torsion = np.where(flat, np.nan, np.einsum("ij,ij->i", c, d3) / cn**2)
    N = np.cross(B, T)
    return FrenetSamples(_readonly(T), _readonly(N), _readonly(B), _readonly(curvature),
                         _readonly(torsion), _readonly(speed))
