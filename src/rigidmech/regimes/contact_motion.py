"""Motion of a :class:`~rigidmech.dynamics.System` with one-sided contacts and dry friction,
regime by regime (book, ch. 13.1, 21.4, 23).

A system holds :class:`~rigidmech.actions.FrictionContact` connections (``system.connect(S1,
S2, FrictionContact(...))``). Its equations of motion change with the state of each
contact, and :func:`contact_motion` derives them itself from the system, for each regime:

* **stick** (for a wheel: rolls without slipping): the contact is a constraint, the velocity
  of sliding v(I in S2/S1) = 0 and its normal component; the normal force N and the
  tangential force T are the Lagrange multipliers of these conditions (M q'' = f + A^T lambda).
  The phase ends where the friction needed exceeds the cone, ``|T| = f_s N``: the contact
  then slips, in the direction opposite to T;
* **slip** (``slip+`` / ``slip-`` along the one tangent t of a plane contact, ``slip`` for a
  contact with two tangents): only the normal condition is kept, and the friction
  ``T = -f_k N v_s/|v_s|`` acts with its multiplier N: the generalised force of the contact is
  ``(A_n - f_k (v_s/|v_s|) . A_t)^T N``. The phase ends where the sliding velocity vanishes; the
  contact then sticks if the friction needed to stick lies inside the cone
  (``|T| <= f_s N``), otherwise it slips back;
* a frictionless contact (``friction=None``) keeps only its normal condition (regime
  ``contact``).

**Contacts that stick together.** A rigid body sticking on a plane at two points (a box on a
floor) has the same sliding velocity at both: their tangential conditions coincide, and the
fundamental principle, which gives only the resultant and the moment of the actions on a
rigid body (ch. 14.2), determines the total T_A + T_B of their tangential forces but not its
split (the stick regime is hyperstatic in the tangential direction, ch. 13.2.5), while the
normal forces and the motion stay determined. Such contacts share one tangential condition,
whose multiplier is the total; as for a single contact (ch. 13.1.2), sticking holds while the
total lies within the sum of the limits, ``|T_A + T_B| <= f_s,A N_A + f_s,B N_B``, the
textbook treatment of a body on a plane with both contacts sticking. When it leaves it, they
slip together against it; when their common sliding velocity vanishes, they stick together
if the total needed lies within the sum of the limits. ``contact_actions`` reports the total
split in proportion to the limits f_s N (each contact then uses the same fraction of its
cone). A contact whose normal force reaches 0 lifts off (a box tipping about its other
corner). Conditions that stay dependent after this merge (a table on four legs, whose normal
forces are not determined) are refused as hyperstatic.

**Rolling resistance.** A contact given ``rolling=RollingResistance(delta)`` (planar rolling:
the rolling rotation omega_r along one tangent) has a second part in its state (ch. 13.1.3):
``rolls+`` / ``rolls-`` (the couple ``-delta N sign(omega_r)`` acts with N: the generalised
force of the contact gains ``-delta sign(omega_r) A_r^T N``, A_r the row of omega_r) or
``locked`` (omega_r = 0 is a condition, its multiplier the couple M_r, which must stay within
``|M_r| <= delta N``; beyond it the body rolls against M_r). Regimes are then named
``"stick, rolls+"``, ``"slip+, locked"``, ... and :meth:`ContactMotion.rolling_couples` gives
the couples.

Where a normal force N would become negative (guard "lifts off") the contact opens: if the
contact has a ``gap`` (the distance between the surfaces), the motion goes on with the contact
**open** (no condition, no action) until the gap closes again (guard "lands": a perfectly
plastic impact sets the normal relative velocity to zero, in the metric of the mass matrix, and
the contact sticks or slips from there); without a gap the motion **stops** there. The impact
is frictionless (no tangential impulse). The phases come back as a :class:`ContactMotion` (a
:class:`~rigidmech.regimes.PhasedMotion` that also gives the contact actions).

The conditions of each regime are enforced at the acceleration level; with
``stabilization=(alpha, beta)`` :func:`contact_motion` adds Baumgarte's correction, as a
:class:`~rigidmech.dynamics.System` does for its closures (the gap is the position residual
of a normal condition).

The state is y = (q, q'), q the system's coordinates. The coordinates of each body in contact
must leave the contact free in the normal direction (N is a multiplier) and in the
tangential ones (T is a multiplier while sticking).
"""

from __future__ import annotations

import itertools
import math

import numpy as np
import sympy as sp

from .._core.errors import ArgumentError, ArgumentTypeError, ConnectionError_, NumericalError
from ..dynamics import System
from ..vectors import t as time_symbol
from .phased import Guard, PhasedMotion, Regime, integrate_phases

__all__ = ["contact_motion", "ContactMotion"]


class ContactMotion(PhasedMotion):
    """The phases of a system with contacts (see :func:`contact_motion`), with the contact
    actions along the motion.

    Examples
    --------
    See :func:`contact_motion`.
    """

    __slots__ = ("_model",)

    def __init__(self, phases, model):
        super().__init__(phases)
        self._model = model

    @property
    def contacts(self) -> tuple:
        """The names of the contacts (their points), in the system's order."""
        return tuple(c.name for c in self._model.contacts)

    def contact_actions(self, time) -> dict:
        """The action of each contact at ``time`` in the regime of the phase then:
        ``{name: (N, T, v_s)}`` with N the normal force, T the tangential force and v_s the
        sliding velocity, both as arrays of their components on the contact's tangents
        (t1 or (t1, t2), see :meth:`ContactKinematics.tangents`).

        At a switching instant the phase that ends there is used.
        """
        time = float(time)
        ends = np.array([p.end for p in self.phases])
        k = min(int(np.searchsorted(ends, time, side="left")), len(self.phases) - 1)
        phase = self.phases[k]
        y = phase.solution.sol(time)
        states = self._model.states_of(phase.regime)
        _, lam, rows = self._model.solve(time, y, states)
        out = {}
        for c, (N, T) in zip(self._model.contacts,
                             self._model.contact_forces(time, y, states, lam, rows),
                             strict=True):
            out[c.name] = (N, T, c.sliding(self._model.values(time, y)))
        return out

    def rolling_couples(self, time) -> dict:
        """The rolling couple of each contact with a rolling resistance at ``time``:
        ``{name: (N, M_r, omega_r)}``, M_r and omega_r the components of the couple and of the
        rolling rotation on the rolling axis (the tangent along which omega_r lies); while
        it rolls ``M_r = -delta N sign(omega_r)``, while it does not ``|M_r| <= delta N``.
        At a switching instant the phase that ends there is used."""
        time = float(time)
        ends = np.array([p.end for p in self.phases])
        k = min(int(np.searchsorted(ends, time, side="left")), len(self.phases) - 1)
        phase = self.phases[k]
        y = phase.solution.sol(time)
        model = self._model
        states = model.states_of(phase.regime)
        _, lam, rows = model.solve(time, y, states)
        forces = model.contact_forces(time, y, states, lam, rows)
        vals = model.values(time, y)
        return {c.name: (forces[i][0],
                         model.rolling_couple(time, y, states, lam, rows, i, forces[i][0]),
                         float(vals[c.roll.c]))
                for i, c in enumerate(model.contacts) if c.roll is not None}


ROLLING = ("rolls+", "rolls-", "locked")


def _slide(state):
    """The sliding part of a contact's state ("stick, rolls+" -> "stick")."""
    return state.split(", ", 1)[0]


def _roll(state):
    """The rolling part of a contact's state, or None."""
    return state.split(", ", 1)[1] if ", " in state else None


class _Row:
    """One constraint velocity c(q, q', t) = J(q, t) q' + ..., numerically."""

    __slots__ = ("J", "h", "c", "p")

    def __init__(self, J, h, c, p):
        self.J, self.h, self.c, self.p = J, h, c, p      # p: the position residual, or 0


class _Contact:
    """A contact's numeric rows: the normal one and 1 or 2 tangential ones."""

    __slots__ = ("name", "law", "normal", "tangents", "fs", "fk", "gap", "roll", "delta")

    def __init__(self, name, law, normal, tangents, gap=None, roll=None, delta=0.0):
        self.name, self.law, self.normal, self.tangents = name, law, normal, tangents
        self.gap = gap                        # index of the gap in the evaluated list
        self.roll, self.delta = roll, delta   # the rolling row and delta, with a rolling law
        if law is not None:
            try:
                self.fs, self.fk = float(law.static), float(law.kinetic)
            except TypeError:
                raise ArgumentError(
                    f"the friction coefficients of contact {name} must be numbers to integrate; "
                    f"got {law!r}.") from None
        else:
            self.fs = self.fk = 0.0

    @property
    def states(self):
        if self.law is None:
            out = ("contact",)
        else:
            out = ("stick", "slip+", "slip-") if len(self.tangents) == 1 else ("stick", "slip")
        if self.roll is not None:
            out = tuple(f"{a}, {b}" for a in out for b in ROLLING)
        return out + (("open",) if self.gap is not None else ())

    def sliding(self, vals):
        return np.array([vals[r.c] for r in self.tangents])


class _Model:
    """The numeric pieces of a system with contacts: M, f, the rows, and the regime solve."""

    def __init__(self, system, params, stabilization=(0.0, 0.0)):
        self.alpha, self.beta = stabilization
        eqs = system.equations_of_motion(open_contacts=True)
        qs = system.coordinates
        n = len(qs)
        q_sym, u_sym, a_sym, rule = system.symbols()
        self.n = n
        exprs = [sp.Matrix(eqs.mass_matrix).xreplace(rule), sp.Matrix(eqs.forcing).xreplace(rule)]
        self.closures = []
        self.contacts = []
        rows, gaps = [], []

        def row(c, position=None):
            c = sp.sympify(c).xreplace(rule)
            J = [sp.diff(c, u) for u in u_sym]
            h = sum((sp.diff(c, q) * u for q, u in zip(q_sym, u_sym, strict=True)),
                    sp.S.Zero) + sp.diff(c, time_symbol)
            p = sp.S.Zero if position is None else sp.sympify(position).xreplace(rule)
            rows.append((J, h, c, p))
            return len(rows) - 1

        for _label, velocity, position in system.closure_conditions():
            self.closures.append(row(velocity, position))
        for k, (_, child, contact) in enumerate(system.contacts):
            kin = contact.contact
            name = kin.point.name if kin.point.name not in [c.name for c in self.contacts] \
                else f"{kin.point.name}{k + 1}"
            v = kin.sliding_velocity
            t1, t2 = kin.tangents()
            vn = sp.simplify(v.dot(kin.normal).xreplace(rule))
            if vn == 0:
                raise ConnectionError_(
                    f"the contact {name} of {child.name} leaves no normal motion: the "
                    f"coordinates {list(qs)} keep the contact closed, so its normal force is "
                    "not a multiplier. Give the body a coordinate along the normal (e.g. its "
                    "height) and start it on the contact.")
            comps = [sp.simplify(v.dot(e).xreplace(rule)) for e in (t1, t2)]
            tangential = [c for c in comps if c != 0]
            if contact.friction is not None and not tangential:
                raise ConnectionError_(
                    f"the contact {name} of {child.name} cannot slip: its coordinates allow "
                    "no sliding velocity, so friction has no regime to switch between.")
            normal = row(v.dot(kin.normal), contact.gap)    # the gap: its position residual
            tang = [row(v.dot(e)) for e, c in zip((t1, t2), comps, strict=True) if c != 0]
            roll, delta = None, 0.0
            if getattr(contact, "rolling", None) is not None:
                roll, delta = self._rolling_row(row, kin, contact, name, child, rule)
            gap = None
            if contact.gap is not None:
                gaps.append(contact.gap.xreplace(rule))
                gap = len(gaps) - 1
            self.contacts.append(_Contact(name, contact.friction, normal, tang, gap, roll,
                                          delta))
        self._compile(exprs, rows, q_sym, u_sym, params, gaps)
        for c in self.contacts:
            c.normal = self._rows[c.normal]
            c.tangents = [self._rows[i] for i in c.tangents]
            if c.roll is not None:
                c.roll = self._rows[c.roll]
            if c.gap is not None:                 # gaps come after the rows
                c.gap = 2 + 4 * len(rows) + c.gap
        self.closures = [self._rows[i] for i in self.closures]

    @staticmethod
    def _rolling_row(row, kin, contact, name, child, rule):
        """The row of the rolling rotation (one tangential component) and delta."""
        w = kin.rolling
        comps = [(e, sp.simplify(w.dot(e).xreplace(rule))) for e in kin.tangents()]
        comps = [(e, c) for e, c in comps if c != 0]
        if len(comps) != 1:
            raise ConnectionError_(
                f"the rolling resistance of contact {name} of {child.name} needs a planar "
                f"rolling, the rolling rotation along one tangent; got {len(comps)} "
                "tangential components of the rolling rotation.")
        try:
            delta = float(contact.rolling.coefficient)
        except TypeError:
            raise ArgumentError(f"the rolling-resistance coefficient of contact {name} must "
                                f"be a number to integrate; got {contact.rolling!r}.") from None
        return row(w.dot(comps[0][0])), delta

    def _compile(self, exprs, rows, q_sym, u_sym, params, gaps):
        flat = [*exprs, *[e for J, h, c, p in rows for e in (sp.Matrix([J]), h, c, p)],
                *gaps]
        free = set()
        for e in flat:
            free |= sp.sympify(e).free_symbols
        constants = sorted(free - set(q_sym) - set(u_sym) - {time_symbol}, key=lambda s: s.name)
        missing = [s.name for s in constants if s.name not in params]
        if missing:
            raise ArgumentError(f"missing values for the parameters {missing}; pass them as "
                                f"keywords, e.g. {missing[0]}=1.0.")
        unknown = sorted(set(params) - {s.name for s in constants})
        if unknown:
            raise ArgumentError(f"unknown parameters {unknown}; the equations depend on "
                                f"{[s.name for s in constants]}.")
        values = {}
        for s in constants:
            try:
                values[s] = float(params[s.name])
            except (TypeError, ValueError):
                raise ArgumentTypeError(f"the value of parameter `{s.name}` must be a real "
                                        f"number; got {params[s.name]!r}.") from None
        flat = [sp.sympify(e).xreplace(values) for e in flat]
        fn = sp.lambdify((time_symbol, *q_sym, *u_sym), flat, modules="numpy", cse=True)
        n = self.n
        self._fn = fn
        # indices into the evaluated list [M, f, J_0, h_0, c_0, p_0, J_1, ...]
        self._rows = [_Row(*(2 + 4 * i + j for j in range(4))) for i in range(len(rows))]
        self._n = n
        self._memo = (None, None)

    def values(self, t, y):
        key = (float(t), np.asarray(y, dtype=float).tobytes())
        if self._memo[0] != key:
            self._memo = (key, self._fn(t, *y[: self._n], *y[self._n:]))
        return self._memo[1]

    # -- one regime ---------------------------------------------------------------------
    def states_of(self, regime):
        if len(self.contacts) == 1:
            return (regime,)
        return tuple(part.split(": ", 1)[1] for part in regime.split("; "))

    def regime_name(self, states):
        if len(self.contacts) == 1:
            return states[0]
        return "; ".join(f"{c.name}: {s}" for c, s in zip(self.contacts, states, strict=True))

    # -- contacts whose tangential rows coincide ----------------------------------------
    def coincide(self, vals, j, k) -> bool:
        """Whether contacts j and k have the same tangential rows (J and h): the same
        sliding velocity as a function of q', e.g. two corners of a body on a plane."""
        cj, ck = self.contacts[j], self.contacts[k]
        if len(cj.tangents) != len(ck.tangents):
            return False
        for rj, rk in zip(cj.tangents, ck.tangents, strict=True):
            Jj = np.asarray(vals[rj.J], dtype=float).reshape(-1)
            Jk = np.asarray(vals[rk.J], dtype=float).reshape(-1)
            hj, hk = float(vals[rj.h]), float(vals[rk.h])
            scale = max(1.0, float(np.abs(Jj).max()), float(np.abs(Jk).max()))
            if float(np.abs(Jj - Jk).max()) > 1e-9 * scale or \
                    abs(hj - hk) > 1e-9 * max(1.0, abs(hj), abs(hk)):
                return False
        return True

    def group_of(self, vals, states, k, among=("stick",)) -> list:
        """Contact k and the contacts in a state of ``among`` whose tangential rows coincide
        with k's (they stick or slip together)."""
        return [j for j in range(len(self.contacts))
                if j == k or (_slide(states[j]) in among and self.coincide(vals, j, k))]

    def leads(self, vals, states) -> dict:
        """For each sticking contact, the first sticking contact of its group: the one whose
        tangential rows stand for the group (their multipliers are the group's total)."""
        lead = {}
        sticking = [k for k, s in enumerate(states) if _slide(s) == "stick"]
        for k in sticking:
            lead[k] = next((lead[j] for j in sticking if j < k and self.coincide(vals, j, k)),
                           k)
        return lead

    def rows(self, vals, states, lead=None):
        """The conditions of the regime ``states``: [(kind, key, row, force row)]."""
        lead = self.leads(vals, states) if lead is None else lead
        out = []
        for r in self.closures:
            J = np.asarray(vals[r.J], dtype=float).reshape(-1)
            out.append(("closure", None, r, J))
        for k, (c, full) in enumerate(zip(self.contacts, states, strict=True)):
            s, rolling = _slide(full), _roll(full)
            if s == "open":
                continue
            Jn = np.asarray(vals[c.normal.J], dtype=float).reshape(-1)
            force = Jn.copy()
            if rolling in ("rolls+", "rolls-"):      # the couple -delta N sign(omega_r)
                sign = 1.0 if rolling == "rolls+" else -1.0
                force -= c.delta * sign * np.asarray(vals[c.roll.J], dtype=float).reshape(-1)
            if s.startswith("slip"):
                direction = self._slip_direction(s, c.sliding(vals))
                for d, r in zip(direction, c.tangents, strict=True):
                    force -= c.fk * d * np.asarray(vals[r.J], dtype=float).reshape(-1)
            out.append(("N", k, c.normal, force))
            if s == "stick" and lead[k] == k:      # the group's total, once
                for i, r in enumerate(c.tangents):
                    J = np.asarray(vals[r.J], dtype=float).reshape(-1)
                    out.append(("T", (k, i), r, J))
            if rolling == "locked":
                out.append(("M", k, c.roll, np.asarray(vals[c.roll.J], dtype=float).reshape(-1)))
        return out

    def bias(self, vals, r):
        """The right-hand side of a condition at the acceleration level, with Baumgarte's
        correction: -h - 2 alpha c - beta^2 p (c the velocity residual, p the position
        residual where the condition has one), as the compiled equations of a System."""
        out = -float(vals[r.h])
        if self.alpha:
            out -= 2.0 * self.alpha * float(vals[r.c])
        if self.beta:
            out -= self.beta ** 2 * float(vals[r.p])
        return out

    def solve(self, t, y, states, vals=None):
        """(q'', multipliers, row layout) of the regime ``states`` at (t, y).

        Contacts that stick with coincident tangential rows (a body on a plane at two
        points) share one set of tangential conditions: its multipliers are the total of
        their tangential forces, which is determined while its split is not.
        """
        n = self.n
        vals = self.values(t, y) if vals is None else vals
        M = np.atleast_2d(np.asarray(vals[0], dtype=float))
        f = np.asarray(vals[1], dtype=float).reshape(-1)
        rows = self.rows(vals, states)
        layout = [(kind, key) for kind, key, _, _ in rows]
        m = len(rows)
        if m == 0:
            return np.linalg.solve(M, f), np.zeros(0), layout
        A = np.array([np.asarray(vals[r.J], dtype=float).reshape(-1) for _, _, r, _ in rows])
        K = np.zeros((n + m, n + m))
        K[:n, :n] = M
        K[:n, n:] = -np.array([g for _, _, _, g in rows]).T
        K[n:, :n] = A
        rhs = np.concatenate([f, [self.bias(vals, r) for _, _, r, _ in rows]])
        if np.linalg.matrix_rank(A, tol=1e-10 * max(1.0, float(np.abs(A).max()))) < m:
            raise NumericalError(
                f"the regime {self.regime_name(states)} is hyperstatic at t = {t}: its contact "
                "conditions are not independent, so their multipliers (the contact forces) "
                "are not determined (e.g. a table standing on four legs: its normal forces).")
        x = np.linalg.solve(K, rhs)
        return x[:n], x[n:], layout

    @staticmethod
    def _slip_direction(state, vs):
        if state == "slip+":
            return np.array([1.0])
        if state == "slip-":
            return np.array([-1.0])
        norm = float(np.linalg.norm(vs))
        return vs / norm if norm > 0 else np.zeros_like(vs)

    def contact_forces(self, t, y, states, lam, layout):
        """[(N, T components on the tangents)] for each contact.

        The total tangential force of contacts sticking together (see :meth:`solve`) is
        split in proportion to their limits f_s N: each then uses the same fraction of its
        friction cone, so each leaves its cone exactly when the total leaves the sum of the
        limits.
        """
        vals = self.values(t, y)
        lead = self.leads(vals, states)
        Ns = []
        for k, s in enumerate(states):
            Ns.append(0.0 if _slide(s) == "open" else next(
                float(lam[i]) for i, (kind, key) in enumerate(layout)
                if kind == "N" and key == k))
        out = []
        for k, (c, s) in enumerate(zip(self.contacts, states, strict=True)):
            N, s = Ns[k], _slide(s)
            if s == "stick":
                total = np.array([lam[i] for i, (kind, key) in enumerate(layout)
                                  if kind == "T" and key[0] == lead[k]], dtype=float)
                members = [j for j in lead if lead[j] == lead[k]]
                limits = [self.contacts[j].fs * max(Ns[j], 0.0) for j in members]
                share = (c.fs * max(N, 0.0) / sum(limits) if sum(limits) > 0
                         else 1.0 / len(members))
                T = share * total
            elif s.startswith("slip"):
                T = -c.fk * N * self._slip_direction(s, c.sliding(vals))
            else:
                T = np.zeros(len(c.tangents))
            out.append((N, T))
        return out

    def rolling_couple(self, t, y, states, lam, layout, k, N):
        """The rolling couple of contact k (its component on the rolling axis)."""
        c, rolling = self.contacts[k], _roll(states[k])
        if rolling == "locked":
            return next(float(lam[i]) for i, (kind, key) in enumerate(layout)
                        if kind == "M" and key == k)
        if rolling in ("rolls+", "rolls-"):
            return -c.delta * N * (1.0 if rolling == "rolls+" else -1.0)
        return 0.0

    def project(self, t, y, states):
        """y with q' projected (in the metric of M) onto the conditions of ``states``."""
        n = self.n
        vals = self.values(t, y)
        M = np.atleast_2d(np.asarray(vals[0], dtype=float))
        rows = [r for _, _, r, _ in self.rows(vals, states)]
        if not rows:
            return np.array(y, dtype=float)
        A = np.array([np.asarray(vals[r.J], dtype=float).reshape(-1) for r in rows])
        c = np.array([float(vals[r.c]) for r in rows])
        u = np.array(y[n:], dtype=float)
        Minv_At = np.linalg.solve(M, A.T)
        u = u - Minv_At @ np.linalg.solve(A @ Minv_At, c)
        return np.concatenate([np.asarray(y[:n], dtype=float), u])


def _state_vector(values, coordinates, what):
    names = [q.func.__name__ for q in coordinates]
    if values is None:
        return np.zeros(len(names))
    if isinstance(values, dict):
        out = []
        by_name = {(k if isinstance(k, str) else getattr(getattr(k, "func", None), "__name__",
                                                          str(k))): v for k, v in values.items()}
        unknown = sorted(set(by_name) - set(names))
        if unknown:
            raise ArgumentError(f"`{what}` names unknown coordinates {unknown}; the "
                                f"coordinates are {names}.")
        for n in names:
            out.append(by_name.get(n, 0.0))
        values = out
    try:
        arr = np.array(values, dtype=float).reshape(-1)
    except (TypeError, ValueError):
        raise ArgumentTypeError(f"`{what}` must be numbers (a dict by coordinate or a "
                                f"sequence in the order {names}); got {values!r}.") from None
    if arr.size != len(names) or not np.all(np.isfinite(arr)):
        raise ArgumentError(f"`{what}` must hold {len(names)} finite values, for {names}; got "
                            f"{values!r}.")
    return arr


class _Rules:
    """The guards and transitions of every regime of a model."""

    def __init__(self, model):
        self.m = model
        self.directions = {}           # contact index -> slip direction at the phase start

    def forces(self, t, y, states):
        _, lam, layout = self.m.solve(t, y, states)
        return self.m.contact_forces(t, y, states, lam, layout)

    def _merge(self, k, old, new):
        """The state ``new`` of contact k (a sliding state), keeping its rolling part."""
        if self.m.contacts[k].roll is None or new in ("open", "impact") or \
                _roll(new) is not None:
            return new
        return f"{new}, {_roll(old) or 'locked'}"

    def _with(self, states, k, state):
        return tuple(self._merge(i, s, state) if i == k else s for i, s in enumerate(states))

    def _with_all(self, states, ks, state):
        return tuple(self._merge(i, s, state) if i in ks else s for i, s in enumerate(states))

    def _with_roll(self, states, k, rolling):
        return self._with(states, k, f"{_slide(states[k])}, {rolling}")

    def couple(self, t, y, states, k):
        """(N, M_r) of contact k in the regime ``states``."""
        _, lam, layout = self.m.solve(t, y, states)
        N = self.m.contact_forces(t, y, states, lam, layout)[k][0]
        return N, self.m.rolling_couple(t, y, states, lam, layout, k, N)

    def after_roll_stop(self, t, y, states, k):
        """The states where the rolling rotation of contact k vanishes: it stays without
        rolling if the couple needed is within delta N, else it rolls back against it."""
        locked = self._with_roll(states, k, "locked")
        N, M = self.couple(t, self.m.project(t, y, locked), locked, k)
        if abs(M) <= self.m.contacts[k].delta * N * (1 + 1e-12) + 1e-300:
            return locked
        return self._with_roll(states, k, "rolls+" if M < 0 else "rolls-")

    def roll_guard(self, states, k):
        c, m, rolling = self.m.contacts[k], self.m, _roll(states[k])
        if rolling == "locked":
            def bound(t, y):
                N, M = self.couple(t, y, states, k)
                return c.delta * N - abs(M)

            def to_roll(t, y):
                M = self.couple(t, y, states, k)[1]
                return m.regime_name(self._with_roll(states, k, "rolls+" if M < 0 else
                                                     "rolls-"))
            return Guard(f"{c.name} starts rolling", bound, target=to_roll, direction=-1)
        sign = 1.0 if rolling == "rolls+" else -1.0

        def rate(t, y):
            return sign * float(m.values(t, y)[c.roll.c])
        return Guard(f"{c.name} stops rolling", rate, direction=-1,
                     target=lambda t, y: m.regime_name(self.after_roll_stop(t, y, states, k)),
                     reset=lambda t, y: m.project(t, y, self._with_roll(states, k, "locked")))

    def rolling_state(self, t, y, states, k):
        """The rolling part of contact k from its rolling rotation (at a start or a
        landing): rolls+/- if it rolls, else locked if delta N holds it."""
        c = self.m.contacts[k]
        w = float(self.m.values(t, y)[c.roll.c])
        if abs(w) > 1e-12 * (float(np.linalg.norm(y[self.m.n:])) + 1):
            return self._with_roll(states, k, "rolls+" if w > 0 else "rolls-")
        return self.after_roll_stop(t, y, states, k)

    def _slip_all(self, states, group, T):
        """``states`` with every contact of ``group`` slipping against the total T."""
        new = self.slip_state(group[0], T)
        for j in group[1:]:
            if group[0] in self.directions:
                self.directions[j] = self.directions[group[0]]
        return self._with_all(states, group, new)

    def stop_group(self, t, y, states, k):
        """Contact k and those that stick or slip with it (coincident tangential rows)."""
        among = ("stick",) if states[k] == "open" else ("stick", _slide(states[k]))
        return self.m.group_of(self.m.values(t, y), states, k, among)

    def after_stop(self, t, y, states, k):
        """The states where the sliding velocity of contact k vanishes: k (and the contacts
        that slide with it) stick if the friction needed lies inside the cone, i.e. within
        the sum of the limits f_s N for contacts that stick together (ch. 13.1.2)."""
        group = self.stop_group(t, y, states, k)
        stick = self._with_all(states, group, "stick")
        yp = self.m.project(t, y, stick)
        forces = self.forces(t, yp, stick)
        Ns = [forces[j][0] for j in group]
        T = sum(forces[j][1] for j in group)
        limit = sum(self.m.contacts[j].fs * forces[j][0] for j in group)
        if min(Ns) >= 0 and float(np.linalg.norm(T)) <= limit * (1 + 1e-12) + 1e-300:
            return stick
        return self._slip_all(states, group, T)

    def slip_state(self, k, T):
        """The slip that a needed friction T cannot hold: opposite to T."""
        if len(self.m.contacts[k].tangents) == 1:
            return "slip+" if T[0] < 0 else "slip-"
        self.directions[k] = -T / float(np.linalg.norm(T))
        return "slip"

    def regimes(self):
        out = []
        for states in itertools.product(*(c.states for c in self.m.contacts)):
            guards = []
            for k, s in enumerate(states):
                guards.extend(self.guards(states, k, s))
            out.append(Regime(self.m.regime_name(states), self.rhs(states), guards))
        return out

    def rhs(self, states):
        n = self.m.n

        def rhs(t, y):
            a, _, _ = self.m.solve(t, y, states)
            return np.concatenate([y[n:], a])
        return rhs

    def guards(self, states, k, s):
        c = self.m.contacts[k]
        s = _slide(s)
        if s == "open":
            return [self._landing_guard(states, k)]
        if c.roll is not None:
            return self._sliding_guards(states, k, s) + [self.roll_guard(states, k)]
        return self._sliding_guards(states, k, s)

    def _sliding_guards(self, states, k, s):
        c, m = self.m.contacts[k], self.m
        name = m.regime_name

        def normal(t, y):
            return self.forces(t, y, states)[k][0]
        opened = None if c.gap is None else name(self._with(states, k, "open"))
        out = [Guard(f"{c.name} lifts off", normal, target=opened, direction=-1)]
        if s == "stick":
            def cone(t, y):            # of the contacts that stick with k, see after_stop
                group = m.group_of(m.values(t, y), states, k)
                forces = self.forces(t, y, states)
                return sum(m.contacts[j].fs * forces[j][0] for j in group) - float(
                    np.linalg.norm(sum(forces[j][1] for j in group)))

            def to_slip(t, y):
                group = m.group_of(m.values(t, y), states, k)
                forces = self.forces(t, y, states)
                return name(self._slip_all(states, group, sum(forces[j][1] for j in group)))
            out.append(Guard(f"{c.name} starts slipping", cone, target=to_slip, direction=-1))
        elif s in ("slip+", "slip-"):
            sign = 1.0 if s == "slip+" else -1.0
            row = c.tangents[0]

            def speed(t, y):
                return sign * float(m.values(t, y)[row.c])
            out.append(Guard(f"{c.name} stops slipping", speed, direction=-1,
                             target=lambda t, y: name(self.after_stop(t, y, states, k)),
                             reset=lambda t, y: m.project(t, y, self._with_all(
                                 states, self.stop_group(t, y, states, k), "stick"))))
        elif s == "slip":
            out.append(self._slip2_guard(states, k))
        return out

    def _slip2_guard(self, states, k):
        c, m = self.m.contacts[k], self.m

        def along(t, y):
            return float(c.sliding(m.values(t, y)) @ self.directions[k])

        def stopped(t, y):
            vs = c.sliding(m.values(t, y))
            scale = float(np.linalg.norm(y[m.n:])) + 1e-300
            return float(np.linalg.norm(vs)) <= 1e-7 * scale

        def target(t, y):
            if stopped(t, y):
                return m.regime_name(self.after_stop(t, y, states, k))
            return m.regime_name(states)

        def reset(t, y):
            if stopped(t, y):
                return m.project(t, y, self._with_all(states, self.stop_group(t, y, states, k),
                                                      "stick"))
            vs = c.sliding(m.values(t, y))
            self.directions[k] = vs / float(np.linalg.norm(vs))
            return y
        return Guard(f"{c.name} stops slipping", along, target=target, direction=-1,
                     reset=reset)

    def _landing_guard(self, states, k):
        """The open contact k closes: a perfectly plastic impact, then stick or slip."""
        c, m = self.m.contacts[k], self.m
        impact = self._with(states, k, "impact")  # the normal condition of k, no tangent

        def gap(t, y):
            return float(m.values(t, y)[c.gap])

        def target(t, y):
            return m.regime_name(self.closing_state(t, m.project(t, y, impact), states, k))

        def reset(t, y):
            after = m.project(t, y, impact)
            return m.project(t, after, self.closing_state(t, after, states, k))

        return Guard(f"{c.name} lands", gap, target=target, direction=-1, reset=reset)

    def closing_state(self, t, y, states, k):
        """The states as contact k closes at (t, y) (normal velocity zero)."""
        c = self.m.contacts[k]
        if c.law is None:
            return self._with(states, k, "contact")
        vs = c.sliding(self.m.values(t, y))
        if float(np.linalg.norm(vs)) > 1e-12 * (float(np.linalg.norm(y[self.m.n:])) + 1):
            if len(c.tangents) == 1:
                out = self._with(states, k, "slip+" if vs[0] > 0 else "slip-")
            else:
                self.directions[k] = vs / float(np.linalg.norm(vs))
                out = self._with(states, k, "slip")
        else:
            out = self.after_stop(t, y, states, k)
        return out if c.roll is None else self.rolling_state(t, y, out, k)

    def start(self, t, y):
        states = []
        for k, c in enumerate(self.m.contacts):
            vs = c.sliding(self.m.values(t, y))
            if c.gap is not None and self.m.values(t, y)[c.gap] > 1e-12:
                states.append("open")
            elif c.law is None:
                states.append("contact")
            elif float(np.linalg.norm(vs)) > 1e-12 * (float(np.linalg.norm(y[self.m.n:])) + 1):
                if len(c.tangents) == 1:
                    states.append("slip+" if vs[0] > 0 else "slip-")
                else:
                    self.directions[k] = vs / float(np.linalg.norm(vs))
                    states.append("slip")
            else:
                states.append("stick")
            if c.roll is not None and states[-1] != "open":
                w = float(self.m.values(t, y)[c.roll.c])
                moving = abs(w) > 1e-12 * (float(np.linalg.norm(y[self.m.n:])) + 1)
                states[-1] += ", " + (("rolls+" if w > 0 else "rolls-") if moving else "locked")
        states = tuple(states)
        forces = self.forces(t, y, states)
        for k, (c, (N, T)) in enumerate(zip(self.m.contacts, forces, strict=True)):
            if states[k] == "open":
                continue
            if N < 0 and c.gap is not None:
                states = self._with(states, k, "open")
            elif N < 0:
                raise ArgumentError(
                    f"the contact {c.name} pulls at t = {t} (normal force N = {N:.6g} < 0): "
                    "it opens at once; start the bodies where the contact presses.")
            if _slide(states[k]) == "stick" and float(np.linalg.norm(T)) > c.fs * N:
                group = self.m.group_of(self.m.values(t, y), states, k)
                states = self._slip_all(states, group, sum(forces[j][1] for j in group))
        for k, c in enumerate(self.m.contacts):
            if c.roll is not None and states[k] != "open":
                states = self.rolling_state(t, y, self._with(states, k, states[k]), k)
        return self.m.regime_name(states)


def _stabilization(value):
    if value is None:
        return 0.0, 0.0
    try:
        alpha, beta = (float(v) for v in value)
    except (TypeError, ValueError):
        raise ArgumentError(f"`stabilization` must be a pair (alpha, beta) of numbers >= 0; "
                            f"got {value!r}.") from None
    if not all(math.isfinite(v) and v >= 0 for v in (alpha, beta)):
        raise ArgumentError(f"`stabilization` must be a pair (alpha, beta) of numbers >= 0; "
                            f"got {value!r}.")
    return alpha, beta


def contact_motion(system, t_span, q0, u0=None, *, method: str = "dop853",
                   rtol: float = 1e-10, atol: float = 1e-12, max_step: float = math.inf,
                   max_phases: int = 10_000, stabilization=None, **params) -> ContactMotion:
    """Integrate a system with one-sided contacts and dry friction phase by phase, each
    regime's equations derived from the system (ch. 13.1, 21.4, 23).

    Parameters
    ----------
    system : System
        With at least one :class:`~rigidmech.actions.FrictionContact`.
    t_span : float or (float, float)
        End time (from 0) or (start, end).
    q0, u0 : dict or sequence
        Initial coordinates and rates (by name or q(t), or in the order of
        ``system.coordinates``); the contacts must be closed at q0 and u0 must not
        separate them (v(I) . n = 0).
    method, rtol, atol, max_step, max_phases
        Passed to :func:`~rigidmech.regimes.integrate_phases`.
    stabilization : (alpha, beta), optional
        Baumgarte's coefficients (in 1/time) for the conditions of each regime (closures,
        contacts' normal conditions, sticking and non-rolling conditions): the condition
        c' = 0 at the acceleration level becomes c' + 2 alpha c + beta^2 p = 0, with c the
        velocity residual and p the position residual where the condition has one (a
        contact's ``gap``, a closure's position), so that the integration does not drift off
        the conditions, as ``System(stabilization=...)`` does for its closures. Default
        None: (0, 0), the conditions at the acceleration level only. A Runge-Kutta method
        keeps a condition that is linear in the coordinates and rates (a cylinder on a
        plane) to round-off without it, where the correction would only add the
        integration error; it pays for nonlinear conditions (a body rocking on a corner or
        an eccentric disk) over long runs.
    **params
        Values of the constants (by name).

    Returns
    -------
    ContactMotion
        Regimes named ``stick``, ``slip+``, ``slip-``, ``slip``, ``contact``, ``open`` (one
        contact; followed by ``, rolls+``, ``, rolls-`` or ``, locked`` with a rolling
        resistance), or ``"I: stick; J: slip+"`` (several, by the names of their points).

    Raises
    ------
    ConnectionError\\_
        A system without contact, or a contact whose coordinates forbid the motions the
        regimes need (or a rolling resistance on a rolling that is not planar).
    NumericalError
        A regime whose contact conditions stay dependent (hyperstatic normal forces).
    ArgumentError
        Missing or unknown parameters, bad initial values, a contact that pulls at t0 or a
        normal velocity at t0.

    Examples
    --------
    A block of mass m on a spring (zero free length) on a rough floor, released at x = 1:

    >>> import rigidmech as rm
    >>> from rigidmech.actions import Coulomb, FrictionContact, Spring
    >>> from rigidmech.kinematics import ContactKinematics
    >>> x, y = rm.coordinates("x y")
    >>> R0 = rm.Frame("R0"); G = R0.point("G", x, y, 0); R1 = R0.translated("R1", G)
    >>> block = rm.Body("block", frame=R1, mass=1, centre=G)
    >>> s = rm.System(galilean=R0)
    >>> s.connect(R0, block, FrictionContact(ContactKinematics(
    ...     R1, R0, at=R0.point("I", x, y, 0), normal=R0.j), friction=Coulomb(0.15)))
    >>> s.act(rm.gravity(-R0.j))
    >>> s.act(Spring(1, 0, a=R0.origin, b=G, on_b=block))
    >>> m = contact_motion(s, 20.0, {"x": 1.0, "y": 0.0}, rtol=1e-12)
    >>> m.regimes                       # half-cycles of pi, amplitude -0.3 each
    ('slip-', 'slip+', 'slip-', 'stick')
    >>> round(m.phases[-1].start, 9), round(m.phases[-1].y_start[0], 9)
    (9.424777961, -0.1)
    >>> N, T, v_s = m.contact_actions(1.0)["I"]      # sliding back: T = +f_k N
    >>> float(N), T.round(12), bool(v_s[0] < 0)
    (1.0, array([0.15]), True)
    """
    if not isinstance(system, System):
        raise ArgumentTypeError(f"`system` must be a System; got {type(system).__name__}.")
    if not system.contacts:
        raise ConnectionError_("the system has no FrictionContact: simulate its "
                               "equations_of_motion() instead.")
    try:
        span = (0.0, float(t_span)) if np.ndim(t_span) == 0 else tuple(float(v) for v in t_span)
    except (TypeError, ValueError):
        raise ArgumentError(f"`t_span` must be an end time or a pair of times; got "
                            f"{t_span!r}.") from None
    model = _Model(system, params, _stabilization(stabilization))
    coords = system.coordinates
    y0 = np.concatenate([_state_vector(q0, coords, "q0"), _state_vector(u0, coords, "u0")])
    vals = model.values(span[0], y0)
    for c in model.contacts:
        if c.gap is not None and float(vals[c.gap]) > 1e-12:
            continue                                 # starts open
        vn = float(vals[c.normal.c])
        if abs(vn) > 1e-9 * (1.0 + float(np.linalg.norm(y0[model.n:]))):
            raise ArgumentError(f"`u0` separates the contact {c.name}: its normal velocity is "
                                f"{vn:.6g} at t0 (it must be 0).")
    rules = _Rules(model)
    motion = integrate_phases(rules.regimes(), rules.start, span, y0, method=method,
                              rtol=rtol, atol=atol, max_step=max_step, max_phases=max_phases)
    return ContactMotion(motion.phases, model)
