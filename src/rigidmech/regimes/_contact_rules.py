"""The guards and transitions of the regimes of a system with contacts for
:func:`~rigidmech.regimes.contact_motion` (book, ch. 13.1, 21.4, 23). Private: see
:mod:`rigidmech.regimes.contact_motion` for the rules it implements.
"""

from __future__ import annotations

import itertools

import numpy as np

from .._core.errors import ArgumentError
from ._contact_model import PARTS, _compose, _part, _slide, speeds_within
from .phased import Guard, Regime

#: relative size of a sliding velocity that counts as zero at an event located on one of its
#: components ("stops slipping" of a two-dimensional slip): the event's location leaves
#: about the solver's tolerance of the terms of the other component
STOPPED_AT_EVENT = 1e-7

#: relative slack of the cone: |T| <= f_s N (1 + CONE_SLACK) holds (the rounding of the
#: multipliers at a switch where the friction needed is exactly the limit)
CONE_SLACK = 1e-12


def within_cone(needed, limit):
    """Whether a friction (or couple) ``needed`` (its magnitude) is held by ``limit`` (f_s N,
    or the coefficient of a resistance times N): ``needed <= limit (1 + CONE_SLACK)``, the
    boundary included (ch. 13.1.2). One rule for every such decision of the regimes."""
    return needed <= limit * (1 + CONE_SLACK) + 1e-300


def presses(N, scale):
    """Whether a normal force ``N`` presses (or is zero): ``N >= -CONE_SLACK * scale``, with
    ``scale`` the magnitude of the terms of N (see ``_Model.normal_scales``): a lift equal to
    the weight up to rounding leaves N = -1e-15 of it, which is not a pull. One rule for every
    lift-off decision of the regimes (the start and the guard "lifts off").

    >>> presses(-1e-12, 1.0), presses(-2e-12, 1.0), presses(0.0, 0.0)
    (True, False, True)
    """
    return lift_margin(N, scale) >= 0


def lift_margin(N, scale):
    """The guard function of a lift-off: it crosses 0 downwards where :func:`presses` turns
    False."""
    return N + CONE_SLACK * scale


class _Rules:
    """The guards and transitions of every regime of a model."""

    def __init__(self, model):
        self.m = model
        self.directions = {}           # contact index -> slip direction at the phase start

    def forces(self, t, y, states):
        _, lam, layout = self.m.solve(t, y, states)
        return self.m.contact_forces(t, y, states, lam, layout)

    def margins(self, t, y, states, forces=None):
        """For each contact, its normal force as the lift-off rule sees it
        (:func:`lift_margin`): the friction limits use it too, so that a normal force within
        rounding of zero neither pulls nor lets go of a friction that is zero."""
        forces = self.forces(t, y, states) if forces is None else forces
        scales = self.m.normal_scales(t, y, states)
        return [lift_margin(N, scale) for (N, _), scale in zip(forces, scales, strict=True)]

    def _merge(self, k, old, new):
        """The state ``new`` of contact k (a sliding state), keeping the parts of its
        couples (held, by default, after an opening)."""
        kinds = self.m.contacts[k].couples
        if not kinds or new in ("open", "impact") or ", " in new:
            return new
        return _compose(new, [_part(old, kind) or PARTS[kind][2] for kind in kinds])

    def _with(self, states, k, state):
        return tuple(self._merge(i, s, state) if i == k else s for i, s in enumerate(states))

    def _with_all(self, states, ks, state):
        return tuple(self._merge(i, s, state) if i in ks else s for i, s in enumerate(states))

    def _with_part(self, states, k, kind, part):
        """``states`` with the part of the couple ``kind`` of contact k set to ``part``."""
        kinds = self.m.contacts[k].couples
        new = _compose(_slide(states[k]), [part if q == kind else _part(states[k], q)
                                           for q in kinds])
        return self._with(states, k, new)

    def couple(self, t, y, states, k, kind):
        """(N, M) of contact k in the regime ``states``, M its couple ``kind``; N as the
        lift-off rule sees it (:func:`lift_margin`), which the limit coefficient * N uses,
        as the friction limits do (:meth:`margins`); M from the raw multipliers."""
        _, lam, layout = self.m.solve(t, y, states)
        N = self.m.contact_forces(t, y, states, lam, layout)[k][0]
        scale = self.m.normal_scales(t, y, states)[k]
        return lift_margin(N, scale), self.m.couple(t, y, states, lam, layout, k, N, kind)

    def after_couple_stop(self, t, y, states, k, kind):
        """The states where the rate of the couple ``kind`` of contact k (its rolling or
        pivoting rotation) vanishes: held if the couple needed is within coefficient * N,
        else moving back against it (ch. 13.1.3)."""
        plus, minus, held = PARTS[kind]
        locked = self._with_part(states, k, kind, held)
        N, M = self.couple(t, self.m.project(t, y, locked), locked, k, kind)
        if within_cone(abs(M), self.m.contacts[k].couples[kind][1] * N):
            return locked
        return self._with_part(states, k, kind, plus if M < 0 else minus)

    def couple_guard(self, states, k, kind):
        c, m = self.m.contacts[k], self.m
        row, coefficient = c.couples[kind]
        plus, minus, held = PARTS[kind]
        verb = "rolling" if kind == "roll" else "spinning"
        if _part(states[k], kind) == held:
            def bound(t, y):
                N, M = self.couple(t, y, states, k, kind)
                return coefficient * N - abs(M)

            def to_move(t, y):
                M = self.couple(t, y, states, k, kind)[1]
                return m.regime_name(self._with_part(states, k, kind, plus if M < 0 else minus))
            return Guard(f"{c.name} starts {verb}", bound, target=to_move, direction=-1)
        sign = 1.0 if _part(states[k], kind) == plus else -1.0

        def rate(t, y):
            return sign * float(m.values(t, y)[row.c])
        return Guard(f"{c.name} stops {verb}", rate, direction=-1,
                     target=lambda t, y: m.regime_name(
                         self.after_couple_stop(t, y, states, k, kind)),
                     reset=lambda t, y: m.project(t, y, self._with_part(states, k, kind, held)))

    def couple_states(self, t, y, states, k, before=None):
        """The parts of the couples of contact k from their rates (at a start or a landing):
        moving if the rate is not zero, else held if coefficient * N holds it. ``before``:
        the values before the landing's impact (see :func:`speeds_within`)."""
        for kind, (row, _) in self.m.contacts[k].couples.items():
            vals = self.m.values(t, y)
            w = float(vals[row.c])
            if not self.m.speeds_zero(vals, [row], y, before):
                states = self._with_part(states, k, kind, PARTS[kind][0 if w > 0 else 1])
            else:
                states = self.after_couple_stop(t, y, states, k, kind)
        return states

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
        margins = self.margins(t, yp, stick, forces)
        T = sum(forces[j][1] for j in group)
        limit = sum(self.m.contacts[j].fs * margins[j] for j in group)
        if all(margins[j] >= 0 for j in group) and within_cone(float(np.linalg.norm(T)), limit):
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
        if c.couples:
            return self._sliding_guards(states, k, s) + [self.couple_guard(states, k, kind)
                                                         for kind in c.couples]
        return self._sliding_guards(states, k, s)

    def _sliding_guards(self, states, k, s):
        c, m = self.m.contacts[k], self.m
        name = m.regime_name

        def normal(t, y):
            return self.margins(t, y, states)[k]
        opened = None if c.gap is None else name(self._with(states, k, "open"))
        out = [Guard(f"{c.name} lifts off", normal, target=opened, direction=-1)]
        if s == "stick":
            def cone(t, y):            # of the contacts that stick with k, see after_stop
                group = m.group_of(m.values(t, y), states, k)
                forces = self.forces(t, y, states)
                margins = self.margins(t, y, states, forces)
                return sum(m.contacts[j].fs * margins[j] for j in group) - float(
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

        def stopped(t, y):  # located by the event, to its accuracy: STOPPED_AT_EVENT
            return bool(np.all(speeds_within(m, m.values(t, y), c.tangents, y,
                                             STOPPED_AT_EVENT)))

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
            before = np.array(m.values(t, y), dtype=object)
            return m.regime_name(self.closing_state(t, m.project(t, y, impact), states, k,
                                                    before))

        def reset(t, y):
            before = np.array(m.values(t, y), dtype=object)
            after = m.project(t, y, impact)
            return m.project(t, after, self.closing_state(t, after, states, k, before))

        return Guard(f"{c.name} lands", gap, target=target, direction=-1, reset=reset)

    def closing_state(self, t, y, states, k, before=None):
        """The states as contact k closes at (t, y) (normal velocity zero); ``before``: the
        values before the impact that closed it (see :func:`speeds_within`)."""
        c = self.m.contacts[k]
        if c.law is None:
            return self._with(states, k, "contact")
        vals = self.m.values(t, y)
        vs = c.sliding(vals)
        if not self.m.speeds_zero(vals, c.tangents, y, before):
            if len(c.tangents) == 1:
                out = self._with(states, k, "slip+" if vs[0] > 0 else "slip-")
            else:
                self.directions[k] = vs / float(np.linalg.norm(vs))
                out = self._with(states, k, "slip")
        else:
            out = self.after_stop(t, y, states, k)
        return self.couple_states(t, y, out, k, before) if c.couples else out

    def start(self, t, y):
        states = []
        for k, c in enumerate(self.m.contacts):
            vals = self.m.values(t, y)
            vs = c.sliding(vals)
            if c.gap is not None and not self.m.closed(vals, c):
                states.append("open")
            elif c.law is None:
                states.append("contact")
            elif not self.m.speeds_zero(vals, c.tangents, y):
                if len(c.tangents) == 1:
                    states.append("slip+" if vs[0] > 0 else "slip-")
                else:
                    self.directions[k] = vs / float(np.linalg.norm(vs))
                    states.append("slip")
            else:
                states.append("stick")
            if states[-1] != "open":          # the couples: moving or held
                parts = []
                for kind, (row, _) in c.couples.items():
                    w = float(vals[row.c])
                    moving = not self.m.speeds_zero(vals, [row], y)
                    parts.append(PARTS[kind][(0 if w > 0 else 1) if moving else 2])
                states[-1] = _compose(states[-1], parts)
        states = tuple(states)
        forces = self.forces(t, y, states)
        margins = self.margins(t, y, states, forces)
        for k, (c, (N, _)) in enumerate(zip(self.m.contacts, forces, strict=True)):
            if states[k] == "open":
                continue
            pulls = not margins[k] >= 0         # the rule of presses
            if pulls and c.gap is not None:
                states = self._with(states, k, "open")
            elif pulls:
                raise ArgumentError(
                    f"the contact {c.name} pulls at t = {t} (normal force N = {N:.6g} < 0): "
                    "it opens at once; start the bodies where the contact presses.")
            if _slide(states[k]) == "stick":  # the rule of after_stop, for the group
                group = self.m.group_of(self.m.values(t, y), states, k)
                total = sum(forces[j][1] for j in group)
                if not within_cone(float(np.linalg.norm(total)),
                                   sum(self.m.contacts[j].fs * margins[j] for j in group)):
                    states = self._slip_all(states, group, total)
        for k, c in enumerate(self.m.contacts):
            if c.couples and states[k] != "open":
                states = self.couple_states(t, y, states, k)
        return self.m.regime_name(states)
