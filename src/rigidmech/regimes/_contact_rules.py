"""The guards and transitions of the regimes of a system with contacts for
:func:`~rigidmech.regimes.contact_motion` (book, ch. 13.1, 21.4, 23). Private: see
:mod:`rigidmech.regimes.contact_motion` for the rules it implements.
"""

from __future__ import annotations

import itertools

import numpy as np

from .._core.errors import ArgumentError
from ._contact_model import _roll, _slide
from .phased import Guard, Regime


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
