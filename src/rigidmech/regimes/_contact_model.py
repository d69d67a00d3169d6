"""The numeric model of a system with contacts for :func:`~rigidmech.regimes.contact_motion`
(book, ch. 13.1, 21.4, 23): its mass matrix, forces and the rows of its conditions compiled
once, and the solve of one regime (q'' and the multipliers: contact forces and couples).
Private: see :mod:`rigidmech.regimes.contact_motion` for the rules it implements.
"""

from __future__ import annotations

import numpy as np
import sympy as sp

from .._core.errors import ArgumentError, ArgumentTypeError, ConnectionError_, NumericalError
from .._core.rules import ON_CONSTRAINTS, magnitude, numeric_rank, on_constraints
from ..vectors import t as time_symbol


def speeds_within(model, vals, rows, y, tol, before=None):
    """For each row, whether its velocity is at most ``tol`` of the magnitude of its terms
    (:func:`~rigidmech._core.rules.magnitude`) at the evaluated ``vals`` (see
    :meth:`_Model.speeds_zero`); ``y`` is the state they were evaluated at. ``before``: the
    values before an impact that led to ``vals`` (its projection leaves the rounding of the
    velocities it removed: the larger magnitude counts)."""
    v = np.array([float(vals[r.c]) for r in rows])
    index = [model._speed_terms + (r.c - 2) // 4 for r in rows]
    scale = np.array([float(vals[i]) for i in index])
    if before is not None:
        scale = np.maximum(scale, [float(before[i]) for i in index])
    return np.abs(v) <= tol * scale

# the parts of a contact's state for its resisting couples: moving one way or the other, or
# held (the couple is then a multiplier bounded by coefficient * N)
PARTS = {"roll": ("rolls+", "rolls-", "locked"), "spin": ("spins+", "spins-", "no spin")}
ROLLING = PARTS["roll"]


def _slide(state):
    """The sliding part of a contact's state ("stick, rolls+" -> "stick")."""
    return state.split(", ", 1)[0]


def _part(state, kind):
    """The part of a contact's state for the couple ``kind`` ("roll", "spin"), or None."""
    return next((p for p in state.split(", ")[1:] if p in PARTS[kind]), None)


def _roll(state):
    """The rolling part of a contact's state, or None."""
    return _part(state, "roll")


def _compose(slide, parts):
    """A contact's state from its sliding part and its couples' parts."""
    return ", ".join([slide, *(p for p in parts if p)])


class _Row:
    """One constraint velocity c(q, q', t) = J(q, t) q' + ..., numerically."""

    __slots__ = ("J", "h", "c", "p")

    def __init__(self, J, h, c, p):
        self.J, self.h, self.c, self.p = J, h, c, p      # p: the position residual, or 0


class _Contact:
    """A contact's numeric rows: the normal one and 1 or 2 tangential ones."""

    __slots__ = ("name", "law", "normal", "tangents", "fs", "fk", "gap", "couples")

    def __init__(self, name, law, normal, tangents, gap=None, couples=None):
        self.name, self.law, self.normal, self.tangents = name, law, normal, tangents
        self.gap = gap                        # index of the gap in the evaluated list
        # kind ("roll", "spin") -> [row, coefficient]: the resisting couples
        self.couples = dict(couples or {})
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
        for kind in self.couples:
            out = tuple(f"{a}, {b}" for a in out for b in PARTS[kind])
        return out + (("open",) if self.gap is not None else ())

    def sliding(self, vals):
        return np.array([vals[r.c] for r in self.tangents])


class _Model:
    """The numeric pieces of a system with contacts: M, f, the rows, and the regime solve."""

    def __init__(self, system, params, stabilization=(0.0, 0.0)):
        self.alpha, self.beta = stabilization
        self.system, self.params = system, dict(params)   # for ContactMotion.evaluate
        eqs = system.equations_of_motion(open_contacts=True)
        qs = system.coordinates
        n = len(qs)
        q_sym, u_sym, a_sym, rule = system.symbols()
        self.n = n
        exprs = [sp.Matrix(eqs.mass_matrix).xreplace(rule), sp.Matrix(eqs.forcing).xreplace(rule)]
        # the magnitudes of the terms of each generalised force (weight, lift, ...): the
        # force scale against which a normal force is told from rounding (see force_scales)
        self._forcing_terms = sp.Matrix([sum((sp.Abs(a) for a in sp.Add.make_args(e)), sp.S.Zero)
                                         for e in exprs[1]])
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
            couples = {}
            if getattr(contact, "rolling", None) is not None:
                couples["roll"] = self._rolling_row(row, kin, contact, name, child, rule)
            if getattr(contact, "pivoting", None) is not None:
                couples["spin"] = [row(kin.rotation.dot(kin.normal)),
                                   self._coefficient(contact.pivoting, name, "pivoting")]
            gap = None
            if contact.gap is not None:
                gaps.append(contact.gap.xreplace(rule))
                gap = len(gaps) - 1
            self.contacts.append(_Contact(name, contact.friction, normal, tang, gap, couples))
        self._compile(exprs, rows, q_sym, u_sym, params, gaps)
        for c in self.contacts:
            c.normal = self._rows[c.normal]
            c.tangents = [self._rows[i] for i in c.tangents]
            for pair in c.couples.values():
                pair[0] = self._rows[pair[0]]
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
        return [row(w.dot(comps[0][0])), _Model._coefficient(contact.rolling, name, "rolling")]

    @staticmethod
    def _coefficient(law, name, what):
        try:
            return float(law.coefficient)
        except TypeError:
            raise ArgumentError(f"the {what}-resistance coefficient of contact {name} must be "
                                f"a number to integrate; got {law!r}.") from None

    def _compile(self, exprs, rows, q_sym, u_sym, params, gaps):
        flat = [*exprs, *[e for J, h, c, p in rows for e in (sp.Matrix([J]), h, c, p)],
                *gaps, self._forcing_terms, *(magnitude(g) for g in gaps),
                *(magnitude(c) for _, _, c, _ in rows)]
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
        self._terms = 2 + 4 * len(rows) + len(gaps)
        self._gap_terms = self._terms + 1 - (2 + 4 * len(rows))  # gap index -> its terms
        self._speed_terms = self._terms + 1 + len(gaps)     # + row number: its c's terms
        self._n = n
        self._memo = (None, None)
        self._saddle_memo = (None, None, None)

    def closed(self, vals, contact) -> bool:
        """Whether ``contact`` (with a gap) is closed at the evaluated ``vals``: its gap is
        at most 0 or zero by the rule on the constraints (at most ON_CONSTRAINTS of the
        magnitude of its terms, :func:`~rigidmech._core.rules.on_constraints`)."""
        g = float(vals[contact.gap])
        return g <= 0 or bool(on_constraints([g], [float(vals[contact.gap + self._gap_terms])])[0])

    def speeds_zero(self, vals, rows, y, before=None) -> bool:
        """Whether the velocities of ``rows`` (a sliding velocity, a rolling or spinning
        rate, a normal velocity) are zero at the state ``y``: each at most ON_CONSTRAINTS of
        the magnitude of its terms, sum_j |J_j q'_j| + |the rest| (the rule on the
        velocity constraints, :func:`~rigidmech._core.rules.on_constraints`)."""
        return bool(np.all(speeds_within(self, vals, rows, y, ON_CONSTRAINTS, before)))

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
            s = _slide(full)
            if s == "open":
                continue
            Jn = np.asarray(vals[c.normal.J], dtype=float).reshape(-1)
            force = Jn.copy()
            for kind, (r, coefficient) in c.couples.items():
                part = _part(full, kind)
                if part in PARTS[kind][:2]:         # the couple -coefficient N sign(rate)
                    sign = 1.0 if part == PARTS[kind][0] else -1.0
                    force -= coefficient * sign * np.asarray(vals[r.J], dtype=float).reshape(-1)
            if s.startswith("slip"):
                direction = self._slip_direction(s, c.sliding(vals))
                for d, r in zip(direction, c.tangents, strict=True):
                    force -= c.fk * d * np.asarray(vals[r.J], dtype=float).reshape(-1)
            out.append(("N", k, c.normal, force))
            if s == "stick" and lead[k] == k:      # the group's total, once
                for i, r in enumerate(c.tangents):
                    J = np.asarray(vals[r.J], dtype=float).reshape(-1)
                    out.append(("T", (k, i), r, J))
            for kind, (r, _) in c.couples.items():
                if _part(full, kind) == PARTS[kind][2]:
                    out.append(("M", (k, kind), r,
                                np.asarray(vals[r.J], dtype=float).reshape(-1)))
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
        _, _, layout, x = self._solved(t, vals, states)
        return x[:n].copy(), x[n:].copy(), list(layout)

    def _solved(self, t, vals, states):
        """(K, rhs, layout, x = K^-1 rhs) of the regime ``states`` at the evaluated ``vals``,
        kept for the last pair: the right-hand side, the contact forces and the scales of the
        normal forces at one state (an event check after a step) form and solve the regime
        once (the rank check on its conditions included)."""
        memo, states = self._saddle_memo, tuple(states)
        if memo[0] is vals and memo[1] == states:     # ``vals`` held here: its id is not reused
            return memo[2]
        K, rhs, layout = self._saddle(t, vals, states)
        out = (K, rhs, tuple(layout), np.linalg.solve(K, rhs))
        self._saddle_memo = (vals, states, out)
        return out

    def _saddle(self, t, vals, states):
        """The matrix K = [[M, -G^T], [A, 0]] and right-hand side [f, bias] of the regime
        (K = M alone without rows), and the row layout."""
        n = self.n
        M = np.atleast_2d(np.asarray(vals[0], dtype=float))
        f = np.asarray(vals[1], dtype=float).reshape(-1)
        rows = self.rows(vals, states)
        layout = [(kind, key) for kind, key, _, _ in rows]
        m = len(rows)
        if m == 0:
            return M, f, layout
        A = np.array([np.asarray(vals[r.J], dtype=float).reshape(-1) for _, _, r, _ in rows])
        K = np.zeros((n + m, n + m))
        K[:n, :n] = M
        K[:n, n:] = -np.array([g for _, _, _, g in rows]).T
        K[n:, :n] = A
        rhs = np.concatenate([f, [self.bias(vals, r) for _, _, r, _ in rows]])
        if numeric_rank(A) < m:  # the one rank rule (rigidmech._core.rules)
            raise NumericalError(
                f"the regime {self.regime_name(states)} is hyperstatic at t = {t}: its contact "
                "conditions are not independent, so their multipliers (the contact forces) "
                "are not determined (e.g. a table standing on four legs: its normal forces).")
        return K, rhs, layout

    def normal_scales(self, t, y, states):
        """For each contact, the magnitude of the terms of its normal force N (0 when open):
        N is row i of K^-1 [f, bias], a sum of K^-1_ij times the terms of f_j (the weight, a
        lift, ...) and bias_j, so its terms add up to at most sum_j |K^-1_ij| (sum of |terms
        of f_j|, |bias_j|). A normal force that small relative to them is their rounding."""
        vals = self.values(t, y)
        K, rhs, layout, _ = self._solved(t, vals, states)
        terms = np.asarray(vals[self._terms], dtype=float).reshape(-1)
        size = np.concatenate([terms, np.abs(rhs[self.n:])])
        x = np.abs(np.linalg.inv(K)) @ size
        out = [0.0] * len(self.contacts)
        for i, (kind, key) in enumerate(layout):
            if kind == "N":
                out[key] = float(x[self.n + i])
        return out

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

    def couple(self, t, y, states, lam, layout, k, N, kind="roll"):
        """The couple ``kind`` ("roll", "spin") of contact k: its component on the rolling
        axis, or on the normal."""
        part = _part(states[k], kind)
        if part == PARTS[kind][2]:
            return next(float(lam[i]) for i, (what, key) in enumerate(layout)
                        if what == "M" and key == (k, kind))
        if part in PARTS[kind][:2]:
            coefficient = self.contacts[k].couples[kind][1]
            return -coefficient * N * (1.0 if part == PARTS[kind][0] else -1.0)
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
