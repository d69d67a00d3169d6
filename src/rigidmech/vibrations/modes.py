"""Natural modes of a linear system with several degrees of freedom (book, ch. 21, 25.4,
27.5.2).

For :math:`M\\ddot q + C\\dot q + K q = F(t)` with M symmetric positive definite and K
symmetric, the natural modes solve :math:`(K - \\omega^2 M)\\,\\phi = 0`. The mode shapes are
orthogonal with respect to M and to K (:math:`\\phi_r^T M \\phi_s = 0`,
:math:`\\phi_r^T K \\phi_s = 0`, r ≠ s); in the modal coordinates :math:`q = \\Phi\\,\\eta`
the undamped equations uncouple into :math:`\\ddot\\eta_r + \\omega_r^2 \\eta_r =
\\phi_r^T F`.

:func:`natural_modes` gives them in closed form for two degrees of freedom with symbolic
entries, and with ``scipy.linalg.eigh`` (the generalised symmetric problem) for numbers.
"""

from __future__ import annotations

import numpy as np
import sympy as sp

from .._core.errors import ArgumentError

__all__ = ["Modes", "natural_modes", "harmonic_response_direct", "plot_frequency_response"]


def _square(matrix, name, n=None):
    if isinstance(matrix, sp.MatrixBase):
        shape = matrix.shape
    else:
        matrix = np.atleast_2d(np.asarray(matrix, dtype=float))
        shape = matrix.shape
    if len(shape) != 2 or shape[0] != shape[1] or (n is not None and shape[0] != n):
        want = f"{n}x{n}" if n is not None else "square"
        raise ArgumentError(f"`{name}` must be a {want} matrix; got shape {shape}.")
    return matrix


class Modes:
    """Natural frequencies and mode shapes of M q'' + K q = 0.

    Attributes
    ----------
    frequencies : tuple of sympy expressions, or ndarray (n,)
        Natural angular frequencies ω_r, increasing (numbers).
    shapes : sympy Matrix or ndarray (n, n)
        Mode shapes as columns. Numeric: normalised so that :math:`\\Phi^T M \\Phi = I`.
        Symbolic (2 dof): first component 1.
    mass, stiffness : the matrices M and K

    Examples
    --------
    >>> import numpy as np
    >>> modes = natural_modes(np.diag([1.0, 1.0]), [[2.0, -1.0], [-1.0, 2.0]])
    >>> np.round(modes.frequencies ** 2, 12).tolist()
    [1.0, 3.0]
    """

    __slots__ = ("frequencies", "shapes", "mass", "stiffness", "_symbolic")

    def __init__(self, frequencies, shapes, mass, stiffness, symbolic):
        self.frequencies = frequencies
        self.shapes = shapes
        self.mass = mass
        self.stiffness = stiffness
        self._symbolic = symbolic

    def __setattr__(self, name, value):
        if hasattr(self, name):
            raise AttributeError(f"Modes is immutable: cannot set `{name}`.")
        object.__setattr__(self, name, value)

    @property
    def n(self) -> int:
        """Number of degrees of freedom."""
        return len(self.frequencies)

    def modal_masses(self):
        """:math:`\\phi_r^T M \\phi_r` for each mode (all 1 for the numeric normalisation).

        Examples
        --------
        >>> import numpy as np
        >>> natural_modes(np.diag([2.0, 1.0]), np.diag([8.0, 1.0])).modal_masses().tolist()
        [1.0, 1.0]
        """
        P, M = self.shapes, self.mass
        if self._symbolic:
            return tuple(sp.simplify((P[:, r].T * M * P[:, r])[0]) for r in range(self.n))
        return np.einsum("ir,ij,jr->r", P, M, P)

    def modal_stiffnesses(self):
        """:math:`\\phi_r^T K \\phi_r` for each mode (:math:`\\omega_r^2` for the numeric
        normalisation).

        Examples
        --------
        >>> import numpy as np
        >>> natural_modes(np.eye(2), np.diag([4.0, 1.0])).modal_stiffnesses().tolist()
        [1.0, 4.0]
        """
        P, K = self.shapes, self.stiffness
        if self._symbolic:
            return tuple(sp.simplify((P[:, r].T * K * P[:, r])[0]) for r in range(self.n))
        return np.einsum("ir,ij,jr->r", P, K, P)

    def _numeric(self):
        if self._symbolic:
            raise ArgumentError(
                "this operation needs numeric modes; compute them from numeric M and K "
                "(substitute values first).")

    def modal_coordinates(self, q):
        """Modal coordinates :math:`\\eta = \\Phi^T M q` of displacements q (shape (n, ...)),
        so that :math:`q = \\Phi\\eta`.

        Examples
        --------
        >>> import numpy as np
        >>> modes = natural_modes(np.eye(2), [[2.0, -1.0], [-1.0, 2.0]])
        >>> eta = modes.modal_coordinates(np.array([1.0, 1.0]))
        >>> np.allclose(modes.shapes @ eta, [1.0, 1.0])
        True
        """
        self._numeric()
        return self.shapes.T @ self.mass @ np.asarray(q, dtype=float)

    def free_response(self, t, q0, u0=None):
        """Undamped free motion by modal superposition:
        :math:`q(t) = \\sum_r \\phi_r (a_r\\cos\\omega_r t + (b_r/\\omega_r)\\sin\\omega_r t)`
        with :math:`a = \\Phi^T M q_0`, :math:`b = \\Phi^T M \\dot q_0`.

        Returns
        -------
        ndarray, shape (n, len(t))

        Examples
        --------
        >>> import numpy as np
        >>> modes = natural_modes([[1.0]], [[4.0]])
        >>> np.allclose(modes.free_response([0.0, 1.0], [1.0]), [[1.0, np.cos(2.0)]])
        True
        """
        self._numeric()
        t = np.atleast_1d(np.asarray(t, dtype=float))
        a = self.modal_coordinates(q0)
        b = self.modal_coordinates(np.zeros(self.n) if u0 is None else u0)
        w = self.frequencies[:, None]
        wt = w * t[None, :]
        with np.errstate(divide="ignore", invalid="ignore"):
            sin_term = np.where(w > 0, np.sin(wt) / np.where(w > 0, w, 1.0), t[None, :])
        eta = a[:, None] * np.cos(wt) + b[:, None] * sin_term
        return self.shapes @ eta

    def harmonic_response(self, force, omega, damping_ratios=0.0):
        """Complex amplitudes of the steady response to :math:`\\Re(F e^{i\\omega t})` by
        modal superposition:

        .. math:: Q(\\omega) = \\sum_r \\frac{\\phi_r\\,\\phi_r^T F}
                  {\\omega_r^2 - \\omega^2 + 2 i \\zeta_r\\omega_r\\omega}

        exact for C = 0 and for modal (e.g. proportional) damping with ratios ζ_r.

        Parameters
        ----------
        force : array (n,)
        omega : float or array (m,)
        damping_ratios : float or array (n,)

        Returns
        -------
        ndarray complex, shape (n, m): amplitude ``abs``, phase lag ``-angle``.

        Examples
        --------
        >>> import numpy as np
        >>> modes = natural_modes([[1.0]], [[4.0]])
        >>> modes.harmonic_response([1.0], [1.0]).real.round(12).tolist()
        [[0.333333333333]]
        """
        self._numeric()
        F = np.asarray(force, dtype=float).reshape(self.n)
        w = np.atleast_1d(np.asarray(omega, dtype=float))
        z = np.broadcast_to(np.asarray(damping_ratios, dtype=float), (self.n,))
        wr = self.frequencies
        participation = self.shapes.T @ F
        den = (wr[:, None] ** 2 - w[None, :] ** 2 + 2j * z[:, None] * wr[:, None] * w[None, :])
        return self.shapes @ (participation[:, None] / den)

    def __repr__(self):
        freqs = (list(self.frequencies) if self._symbolic
                 else np.array2string(np.asarray(self.frequencies), precision=6))
        return f"Modes(n={self.n}, frequencies={freqs})"


def _symbolic_2dof(M, K):
    """Closed form for 2 dof: det(K - lam M) = a lam^2 + b lam + c = 0 with a = det M > 0,
    lam_{1,2} = (-b -+ sqrt(b^2 - 4ac)) / 2a (the smaller first)."""
    lam = sp.Dummy("lambda")
    coeffs = sp.Poly(sp.expand((K - lam * M).det()), lam).all_coeffs()
    if len(coeffs) != 3:
        raise ArgumentError(
            f"`mass` must be invertible; got det(M) = {sp.simplify(M.det())}.")
    a, b, c = coeffs
    root = sp.sqrt(sp.factor(b**2 - 4 * a * c))
    roots = [sp.simplify((-b - root) / (2 * a)), sp.simplify((-b + root) / (2 * a))]
    columns = []
    for r in roots:
        D = K - r * M
        if sp.simplify(D[0, 1]) != 0:
            col = [sp.S.One, sp.simplify(-D[0, 0] / D[0, 1])]
        elif sp.simplify(D[1, 1]) != 0:
            col = [sp.S.One, sp.simplify(-D[1, 0] / D[1, 1])]
        else:
            col = [sp.S.Zero, sp.S.One] if sp.simplify(D[0, 0]) != 0 or columns else [
                sp.S.One, sp.S.Zero]
        columns.append(col)
    freqs = tuple(sp.sqrt(r) for r in roots)
    shapes = sp.ImmutableMatrix(2, 2, lambda i, j: columns[j][i])
    return freqs, shapes


SYMMETRY_RTOL = 1e-10


def is_symmetric(X) -> bool:
    """Whether the numeric square matrix X is symmetric: max |X - X^T| <= 1e-10 max |X|,
    relative to its size so that the decision does not depend on the units (the one rule of
    :func:`natural_modes` and of :func:`rigidmech.vibrations.stability`).

    Examples
    --------
    >>> is_symmetric(np.array([[2e-15, -1e-15], [-1e-15, 2e-15]]))
    True
    >>> is_symmetric(np.array([[2e-15, -0.9e-15], [-1e-15, 2e-15]]))
    False
    """
    X = np.asarray(X, dtype=float)
    return bool(np.max(np.abs(X - X.T), initial=0.0)
                <= SYMMETRY_RTOL * np.max(np.abs(X), initial=0.0))


def natural_modes(mass, stiffness) -> Modes:
    """Natural frequencies and mode shapes of :math:`M\\ddot q + K q = 0` (ch. 27.5.2).

    Parameters
    ----------
    mass, stiffness : (n, n) arrays, or sympy matrices (2x2 for the closed form)
        Symmetric; M positive definite.

    Returns
    -------
    Modes

    Raises
    ------
    ArgumentError
        For non-square or mismatched matrices, a non-symmetric one, a symbolic system of more
        than 2 degrees of freedom, or (numbers) M not positive definite.

    Examples
    --------
    >>> import sympy as sp
    >>> k, m = sp.symbols("k m", positive=True)
    >>> modes = natural_modes(sp.Matrix([[m, 0], [0, m]]), sp.Matrix([[2*k, -k], [-k, 2*k]]))
    >>> modes.frequencies
    (sqrt(k)/sqrt(m), sqrt(3)*sqrt(k)/sqrt(m))
    >>> modes.shapes
    Matrix([
    [1,  1],
    [1, -1]])
    """
    symbolic = isinstance(mass, sp.MatrixBase) or isinstance(stiffness, sp.MatrixBase)
    if symbolic:
        M = sp.ImmutableMatrix(mass)
        K = sp.ImmutableMatrix(stiffness)
        _square(M, "mass")
        _square(K, "stiffness", M.shape[0])
        for X, name in ((M, "mass"), (K, "stiffness")):
            if any(sp.simplify(X[i, j] - X[j, i]) != 0 for i in range(X.shape[0])
                   for j in range(i)):
                raise ArgumentError(f"`{name}` must be symmetric; got {X.tolist()}.")
        if not all(x.is_number for x in list(M) + list(K)) or M.shape[0] <= 2:
            if M.shape[0] == 1:
                return Modes((sp.sqrt(sp.simplify(K[0, 0] / M[0, 0])),),
                             sp.ImmutableMatrix([[1]]), M, K, True)
            if M.shape[0] != 2:
                raise ArgumentError(
                    f"symbolic modes are given in closed form for 2 degrees of freedom; got "
                    f"{M.shape[0]}. Substitute numbers for the parameters.")
            freqs, shapes = _symbolic_2dof(M, K)
            return Modes(freqs, shapes, M, K, True)
        mass, stiffness = np.array(M.tolist(), dtype=float), np.array(K.tolist(), dtype=float)
    import scipy.linalg  # imported on use (slow import)

    M = _square(mass, "mass")
    K = _square(stiffness, "stiffness", M.shape[0])
    for X, name in ((M, "mass"), (K, "stiffness")):
        if not is_symmetric(X):
            raise ArgumentError(f"`{name}` must be symmetric; got {X.tolist()}.")
    try:
        lam, phi = scipy.linalg.eigh((K + K.T) / 2, (M + M.T) / 2)
    except np.linalg.LinAlgError as exc:
        raise ArgumentError(
            f"`mass` must be positive definite; scipy.linalg.eigh failed: {exc}.") from None
    scale = max(np.max(np.abs(lam)), 1e-300)
    lam = np.where(np.abs(lam) < 1e-12 * scale, 0.0, lam)
    if np.any(lam < 0):
        raise ArgumentError(
            f"`stiffness` must be positive semi-definite for natural modes (otherwise the "
            f"equilibrium is unstable); got the eigenvalues {lam.tolist()}.")
    # sign convention: the largest component of each shape is positive
    idx = np.argmax(np.abs(phi), axis=0)
    phi = phi * np.sign(phi[idx, np.arange(phi.shape[1])])
    return Modes(np.sqrt(lam), phi, M, K, False)


def harmonic_response_direct(mass, damping, stiffness, force, omega):
    """Complex amplitudes of the steady response of :math:`M\\ddot q + C\\dot q + K q =
    \\Re(F e^{i\\omega t})` by solving :math:`(K - \\omega^2 M + i\\omega C)\\,Q = F` at each
    frequency (any damping matrix).

    Returns
    -------
    ndarray complex, shape (n, m)

    Examples
    --------
    >>> harmonic_response_direct([[1.0]], [[0.0]], [[4.0]], [1.0], [1.0]).real.round(12).tolist()
    [[0.333333333333]]
    """
    M = _square(mass, "mass")
    n = M.shape[0]
    C = _square(damping, "damping", n)
    K = _square(stiffness, "stiffness", n)
    F = np.asarray(force, dtype=complex).reshape(n)
    w = np.atleast_1d(np.asarray(omega, dtype=float))
    out = np.empty((n, w.size), dtype=complex)
    for k, wk in enumerate(w):
        try:
            out[:, k] = np.linalg.solve(K - wk**2 * M + 1j * wk * C, F)
        except np.linalg.LinAlgError:
            raise ArgumentError(
                f"`omega` = {wk} is a natural frequency of the system without damping there "
                "(K - omega^2 M + i omega C is singular): the steady amplitude is infinite. "
                "Add damping or leave out that frequency.") from None
    return out


def plot_frequency_response(omega, response, *, labels=None, ax=None, path=None, log=True,
                            unit=None, degrees=False):
    """Bode-style plot: amplitude (top) and phase lag (bottom) against the angular
    frequency, on the conventions of :meth:`Simulation.plot
    <rigidmech.dynamics.Simulation.plot>` (ch. 21).

    The axes are labelled with their quantity and unit ("ω [rad/s]", "amplitude [m]",
    "phase lag [rad]"); a new figure has a constrained layout (no label is cut) and its
    legend outside the axes, on the right; on given axes the legend is placed to the right
    of the amplitude axes, off the data.

    Parameters
    ----------
    omega : array (m,)
        Angular frequencies, in rad/s.
    response : complex array (m,) or (n, m)
        Complex amplitudes (from :meth:`Modes.harmonic_response`,
        :func:`harmonic_response_direct` or :meth:`LinearSystem.frequency_response`).
    labels : list of str, optional
        One per row of ``response`` (default ``q1``, ``q2``, ... for several rows, none for
        one).
    ax : pair of matplotlib Axes, optional
        Amplitude and phase axes; default a new figure.
    path : str, optional
        Save the figure there (a new figure is then drawn off-screen).
    log : bool
        Logarithmic amplitude axis.
    unit : str, optional
        The unit of the amplitudes (``"m"``, ``"m/N"``): the amplitude axis reads
        ``amplitude [unit]``; plain ``amplitude`` when not given.
    degrees : bool
        Phase lag in degrees (``phase lag [deg]``) instead of radians.

    Returns
    -------
    (amplitude Axes, phase Axes)

    Examples
    --------
    >>> import numpy as np
    >>> w = np.linspace(0.1, 3.0, 50)
    >>> H = 1.0 / (1.0 - w**2 + 0.2j * w)
    >>> ax_amp, ax_phase = plot_frequency_response(w, H, path=None, ax=None)
    >>> ax_amp.get_ylabel(), ax_phase.get_ylabel(), ax_phase.get_xlabel()
    ('amplitude', 'phase lag [rad]', 'ω [rad/s]')
    >>> ax_amp, _ = plot_frequency_response(w, H, unit="m/N", degrees=True)
    >>> ax_amp.get_ylabel()
    'amplitude [m/N]'
    >>> import matplotlib.pyplot as plt; plt.close("all")
    """
    H = np.atleast_2d(np.asarray(response))
    w = np.asarray(omega, dtype=float)
    if H.shape[-1] != w.size:
        raise ArgumentError(
            f"`response` must have {w.size} values per row (one per frequency); got shape "
            f"{H.shape}.")
    if labels is not None and len(labels) != H.shape[0]:
        raise ArgumentError(f"`labels` must give {H.shape[0]} labels (one per row of "
                            f"`response`); got {len(labels)}.")
    if unit is not None and not (isinstance(unit, str) and unit):
        raise ArgumentError(f"`unit` must be a non-empty string such as 'm' or 'm/N'; got "
                            f"{unit!r}. Leave it out for a plain 'amplitude' label.")
    from ..dynamics._files import _axes  # the conventions of Simulation.plot

    own = ax is None
    if not own and (not isinstance(ax, (list, tuple, np.ndarray)) or len(ax) != 2):
        raise ArgumentError("`ax` must be a pair (amplitude Axes, phase Axes); got "
                            f"{ax!r}. Leave it out to get a new figure.")
    ax_amp, ax_phase = _axes(2, path, ax, (7, 5))
    scale = 180.0 / np.pi if degrees else 1.0
    for n, row in enumerate(H):
        label = labels[n] if labels is not None else (f"q{n + 1}" if H.shape[0] > 1 else None)
        ax_amp.plot(w, np.abs(row), label=label)
        ax_phase.plot(w, -scale * np.unwrap(np.angle(row)), label=label)
    if log:
        ax_amp.set_yscale("log")
    ax_amp.set_ylabel(f"amplitude [{unit}]" if unit else "amplitude")
    ax_phase.set_ylabel("phase lag [deg]" if degrees else "phase lag [rad]")
    ax_phase.set_xlabel("ω [rad/s]")
    for a in (ax_amp, ax_phase):
        a.grid(True, alpha=0.3)
    if H.shape[0] > 1 or labels is not None:
        if own:
            ax_amp.figure.legend(*ax_amp.get_legend_handles_labels(),
                                 loc="outside right upper")
        else:   # outside the amplitude axes, on their right (off the data)
            ax_amp.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0.0)
    if path is not None:
        ax_amp.figure.savefig(path, dpi=100)
    return ax_amp, ax_phase
