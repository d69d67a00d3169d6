"""Constraints between the parameters of situation: closed loops, rolling, gears (book,
ch. 13.2, 20, 25.3).

When the parameters q of a set of bodies are **linked** (the book's *paramètres liés*, ch.
25.3) by m relations, holonomic Φ(q, t) = 0 (the closure of a loop, a wheel rolling on a
line, two gears in mesh) or not, A(q, t) q' + a(q, t) = 0 (a disc rolling on a plane, a knife
edge), the equations of motion carry the unknown actions of the linking connections. With
perfect connections these actions do no work in any motion the constraints allow, so they
enter as :math:`A^T \\lambda` with m Lagrange multipliers λ:

.. math::
    M(q)\\, q'' = f(q, q', t) + A^T \\lambda,\\qquad
    A\\, q'' = b(q, q', t) = -\\dot A\\, q' - \\dot a

(the second line is the time derivative of the velocity constraints: the index-1 form; for
a holonomic constraint A = Φ_q and a = Φ_t). Numbers come from the augmented linear system

.. math:: \\begin{pmatrix} M & A^T \\\\ A & 0 \\end{pmatrix}
          \\begin{pmatrix} q'' \\\\ -\\lambda \\end{pmatrix} =
          \\begin{pmatrix} f \\\\ b \\end{pmatrix},

solved by LU at each evaluation (a singular matrix, redundant constraints or a locked
configuration, is reported). The integration drifts off Φ = 0 (only q'' satisfies the
constraints); the compiled right-hand side controls the drift with **Baumgarte's
stabilisation**, b - 2 α c - β² Φ in place of b (c = A q' + a, the velocity residual): the
residuals obey c' + 2 α c + β² Φ = 0, a damped oscillator, critically damped for α = β.

**Why multipliers rather than eliminating the dependent parameters.** Elimination (ch.
25.3.2) needs the dependent parameters as explicit functions of the independent ones, which a
four-bar or a slider-crank has only with square roots and branch choices (and a nonholonomic
constraint never has); the multipliers keep every parameter, need only derivatives of the
constraints, give the constraint actions (λ) for free, and a nonholonomic constraint enters
exactly the same way (A q' + a = 0 with no Φ). The price is a larger linear system (n + m
unknowns instead of n - m) and the drift control.
"""

from __future__ import annotations

import sympy as sp

from .._core.errors import ArgumentError
from ..vectors import partial_derivative, t, time_derivative

__all__ = ["Constraints"]


class Constraints:
    """m constraints between the parameters of situation, ready for the equations of motion.

    Parameters
    ----------
    coordinates : tuple of q(t)
    rows : sequence of (label, velocity, position)
        For each constraint: a name (the connection it comes from), the velocity form
        c(q, q', t) = A q' + a (linear in the q'), and the position form Φ(q, t) with
        dΦ/dt = c, or None for a nonholonomic constraint.
    stabilization : (alpha, beta)
        Baumgarte's coefficients (in 1/time) used by the compiled right-hand side.

    Examples
    --------
    A particle on the circle x² + y² = 1:

    >>> import rigidmech as rm
    >>> x, y = rm.coordinates("x y")
    >>> phi = x**2 + y**2 - 1
    >>> c = Constraints((x, y), [("circle", phi.diff(rm.t), phi)])
    >>> c.jacobian
    Matrix([[2*x(t), 2*y(t)]])
    >>> c.bias
    Matrix([[-2*Derivative(x(t), t)**2 - 2*Derivative(y(t), t)**2]])
    """

    __slots__ = ("_coordinates", "_labels", "_velocity", "_position", "_A", "_b",
                 "_stabilization", "_stabilized")

    def __init__(self, coordinates, rows, stabilization=(5.0, 5.0)):
        self._coordinates = tuple(coordinates)
        rows = tuple(rows)
        self._labels = tuple(str(r[0]) for r in rows)
        self._velocity = tuple(sp.sympify(r[1]) for r in rows)
        self._position = tuple(None if r[2] is None else sp.sympify(r[2]) for r in rows)
        # c is linear in q': A = dc/dq' and b = -dc/dt with q'' = 0, both taken
        # structurally on q(t) (no substitution of plain symbols, no sympy diff)
        rates = [sp.Derivative(q, t) for q in self._coordinates]
        coords = set(self._coordinates)
        no_acc = {sp.Derivative(q, (t, 2)): 0 for q in self._coordinates}
        A, b = [], []
        for label, c in zip(self._labels, self._velocity, strict=True):
            if any(d.variable_count != ((t, 1),) for d in c.atoms(sp.Derivative)):
                raise ArgumentError(
                    f"constraint {label}: the velocity form must hold first derivatives "
                    f"of the coordinates only; got {c}.")
            stray = [f for f in c.atoms(sp.core.function.AppliedUndef) if f.args == (t,)
                     and f not in coords]
            if stray:
                raise ArgumentError(
                    f"constraint {label} depends on {stray[0]}, which is not a coordinate of "
                    f"the system {tuple(self._coordinates)}: build the points of the "
                    "connection on the bodies' frames.")
            row = [partial_derivative(c, u) for u in rates]
            if any(a.has(*rates) for a in row):
                raise ArgumentError(
                    f"constraint {label}: the velocity form must be linear in the rates; got "
                    f"{c}.")
            A.append(row)
            b.append(-time_derivative(c).xreplace(no_acc))
        m, n = len(rows), len(self._coordinates)
        self._A = sp.ImmutableMatrix(m, n, [x for r in A for x in r])
        self._b = sp.ImmutableMatrix(m, 1, b)
        alpha, beta = stabilization
        self._stabilization = (float(alpha), float(beta))
        self._stabilized = None

    @property
    def coordinates(self) -> tuple:
        """The parameters of situation."""
        return self._coordinates

    @property
    def labels(self) -> tuple:
        """The name of each constraint (its connection and component)."""
        return self._labels

    @property
    def velocity(self) -> tuple:
        """c_i(q, q', t) = A_i q' + a_i: the velocity constraints, which must vanish."""
        return self._velocity

    @property
    def position(self) -> tuple:
        """Φ_i(q, t), or None for a nonholonomic constraint."""
        return self._position

    @property
    def jacobian(self) -> sp.ImmutableMatrix:
        """A(q, t), m x n: the coefficients of the rates (Φ_q for a holonomic row)."""
        return self._A

    @property
    def bias(self) -> sp.ImmutableMatrix:
        """b(q, q', t) with A q'' = b: the acceleration form of the constraints."""
        return self._b

    @property
    def holonomic(self) -> bool:
        """True when every constraint has a position form."""
        return all(p is not None for p in self._position)

    @property
    def stabilization(self) -> tuple:
        """Baumgarte's (alpha, beta)."""
        return self._stabilization

    def stabilized_bias(self) -> sp.ImmutableMatrix:
        """b - 2 alpha c - beta^2 Φ (Φ = 0 for a nonholonomic row): what the compiled
        right-hand side uses."""
        if self._stabilized is None:
            alpha, beta = self._stabilization
            out = []
            for bi, ci, pi in zip(self._b, self._velocity, self._position, strict=True):
                # the Float coefficients kept in front of c and Φ (an evaluated
                # Float * Add is distributed over every term: slow, and no gain)
                terms = [bi]
                if alpha:
                    terms.append(sp.Mul(sp.Float(-2 * alpha), ci, evaluate=False))
                if pi is not None and beta:
                    terms.append(sp.Mul(sp.Float(-beta**2), pi, evaluate=False))
                out.append(sp.Add(*terms, evaluate=False) if len(terms) > 1 else bi)
            self._stabilized = sp.ImmutableMatrix(len(out), 1, out)
        return self._stabilized

    def __len__(self):
        return len(self._labels)

    def __repr__(self):
        return f"Constraints({len(self)} rows: {', '.join(self._labels)})"
