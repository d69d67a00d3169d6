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

**Rolling and pivoting resistance.** A contact given ``rolling=RollingResistance(delta)``
(planar rolling: the rolling rotation omega_r along one tangent) or
``pivoting=PivotingResistance(eta)`` (the spin omega_n about the normal) has a part in its
state for each couple (ch. 13.1.3): ``rolls+`` / ``rolls-`` (the couple
``-delta N sign(omega_r)`` acts with N: the generalised force of the contact gains
``-delta sign(omega_r) A_r^T N``, A_r the row of omega_r) or ``locked`` (omega_r = 0 is a
condition, its multiplier the couple M_r, which must stay within ``|M_r| <= delta N``; beyond
it the body rolls against M_r); likewise ``spins+`` / ``spins-`` / ``no spin`` with eta.
Regimes are then named ``"stick, rolls+"``, ``"slip+, locked"``, ``"stick, no spin"``, ...
and :meth:`ContactMotion.rolling_couples` and :meth:`ContactMotion.pivoting_couples` give the
couples.

Where a normal force N would become negative (guard "lifts off") the contact opens. Negative
means below -1e-12 times the magnitude of the terms of N (the weight, a lift, ...: the terms
of the generalised forces carried through the solve for the multipliers), so that a lift equal
to the weight up to rounding (N = -1e-15 of it) neither pulls at the start nor lifts off; the
friction limits f_s N use the same N + 1e-12 x scale. If the
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

import math

import numpy as np

from .._core.errors import ArgumentError, ArgumentTypeError, ConnectionError_, NumericalError
from ..dynamics import System
from ._contact_model import _Model
from ._contact_rules import _Rules
from .phased import PhasedMotion, integrate_phases

__all__ = ["contact_motion", "ContactMotion"]


class ContactMotion(PhasedMotion):
    """The phases of a system with contacts (see :func:`contact_motion`), with the contact
    actions along the motion.

    Examples
    --------
    See :func:`contact_motion`.
    """

    __slots__ = ("_model",)

    def __init__(self, phases, model, *, status="finished", message="", regimes=None):
        super().__init__(phases, status=status, message=message, regimes=regimes)
        self._model = model

    def accelerations(self, time):
        """The accelerations q'' at ``time`` (a number or an array of times), from the
        equations of the regime of the phase then (at a switching instant, the phase that
        ends there, as :meth:`contact_actions`): shape (n,) or (n, len(time)), in the order
        of the system's coordinates (ch. 21.4, 23). The last half of
        :meth:`~rigidmech.regimes.PhasedMotion.derivative`.

        Examples
        --------
        A block on a plane inclined by alpha (x down the slope), friction f = 0.2, thrown
        up the slope: it decelerates at g (sin alpha + f cos alpha), stops, then slides back
        at g (sin alpha - f cos alpha) (tan alpha > f).

        >>> import math, rigidmech as rm
        >>> from rigidmech.actions import Coulomb, FrictionContact
        >>> from rigidmech.kinematics import ContactKinematics
        >>> x, y = rm.coordinates("x y"); alpha, f, g = 0.5, 0.2, 9.81
        >>> R0 = rm.Frame("R0"); G = R0.point("G", x, y, 0); Rb = R0.translated("Rb", G)
        >>> s = rm.System(galilean=R0)
        >>> s.connect(R0, rm.Body("block", frame=Rb, mass=1, centre=G), FrictionContact(
        ...     ContactKinematics(Rb, R0, at=R0.point("I", x, y, 0), normal=R0.j),
        ...     friction=Coulomb(f)))
        >>> s.act(rm.gravity(g * (math.sin(alpha) * R0.i - math.cos(alpha) * R0.j)))
        >>> m = contact_motion(s, 2.0, {"x": 0.0, "y": 0.0}, {"x": -3.0, "y": 0.0})
        >>> m.regimes
        ('slip-', 'slip+')
        >>> a_up, a_down = m.accelerations([0.1, 1.5])[0]
        >>> bool(abs(a_up - g * (math.sin(alpha) + f * math.cos(alpha))) < 1e-9)
        True
        >>> bool(abs(a_down - g * (math.sin(alpha) - f * math.cos(alpha))) < 1e-9)
        True
        """
        return self.derivative(time)[self._model.n:]

    def evaluate(self, expr, time):
        """An expression of the motion at ``time`` (a number or an array of times): of t,
        the coordinates q(t), their rates and their accelerations q''(t) (those of the
        regime of the phase then, :meth:`accelerations`) and the constants given to
        :func:`contact_motion` (ch. 21.4, 23). The forces of the contacts are not symbols
        of the system: :meth:`contact_actions` gives them.

        Examples
        --------
        A block pushed along a rough floor (f = 0.25) slows down at f g: m x'' is the
        friction force, -f m g while it slides.

        >>> import rigidmech as rm
        >>> from rigidmech.actions import Coulomb, FrictionContact
        >>> from rigidmech.kinematics import ContactKinematics
        >>> x, y = rm.coordinates("x y"); m = rm.constants("m", positive=True)
        >>> R0 = rm.Frame("R0"); G = R0.point("G", x, y, 0); Rb = R0.translated("Rb", G)
        >>> s = rm.System(galilean=R0)
        >>> s.connect(R0, rm.Body("block", frame=Rb, mass=m, centre=G), FrictionContact(
        ...     ContactKinematics(Rb, R0, at=R0.point("I", x, y, 0), normal=R0.j),
        ...     friction=Coulomb(0.25)))
        >>> s.act(rm.gravity(-9.81 * R0.j))
        >>> motion = contact_motion(s, 1.0, {"x": 0, "y": 0}, {"x": 2.0, "y": 0}, m=2.0)
        >>> motion.evaluate(m * x.diff(rm.t, 2), [0.1, 0.5]).round(9).tolist()
        [-4.905, -4.905]
        """
        import sympy as sp

        from ..vectors import t as time_symbol

        model = self._model
        q_s, u_s, a_s, rule = model.system.symbols()
        try:
            e = sp.sympify(expr).xreplace(rule)
        except (sp.SympifyError, TypeError):
            raise ArgumentTypeError(f"`expr` must be a sympy expression of the motion; got "
                                    f"{type(expr).__name__}.") from None
        left = e.atoms(sp.Derivative) | e.atoms(sp.core.function.AppliedUndef)
        if left:
            raise ArgumentError(
                f"`expr` contains {', '.join(sorted(map(str, left)))}, which is neither a "
                "coordinate of the system nor one of its first two derivatives.")
        constants = sorted(e.free_symbols - set(q_s) - set(u_s) - set(a_s) - {time_symbol},
                           key=lambda c: c.name)
        missing = [c.name for c in constants if c.name not in model.params]
        if missing:
            raise ArgumentError(f"`expr` depends on {missing}, which the motion has no value "
                                "for; give them to contact_motion().")
        f = sp.lambdify([time_symbol, list(q_s), list(u_s), list(a_s), *constants], e,
                        "numpy")
        values = [float(model.params[c.name]) for c in constants]
        ts = np.atleast_1d(np.asarray(time, dtype=float))
        y, acc, n = self(ts).reshape(-1, ts.size), self.accelerations(ts), model.n
        acc = acc.reshape(n, ts.size)
        out = np.array([float(f(t, y[:n, i], y[n:, i], acc[:, i], *values))
                        for i, t in enumerate(ts)])
        return out[0] if np.ndim(time) == 0 else out

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
        return self._couples(time, "roll")

    def pivoting_couples(self, time) -> dict:
        """The pivoting couple of each contact with a pivoting resistance at ``time``:
        ``{name: (N, M_p, omega_n)}``, M_p and omega_n the components of the couple and of
        the rotation on the normal; while it spins ``M_p = -eta N sign(omega_n)``, while it
        does not ``|M_p| <= eta N``."""
        return self._couples(time, "spin")

    def _couples(self, time, kind):
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
                         model.couple(time, y, states, lam, rows, i, forces[i][0], kind),
                         float(vals[c.couples[kind][0].c]))
                for i, c in enumerate(model.contacts) if kind in c.couples}


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
                   max_phases: int = 10_000, stabilization=None, progress=None,
                   **params) -> ContactMotion:
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
    progress : None, bool or callable
        As :meth:`EquationsOfMotion.simulate`'s, over the whole run: None (default) a bar on
        stderr for runs longer than 2 s when stderr is a terminal, True the bar, False
        nothing, a callable ``progress(t)`` called about every 0.1 s (returning False stops
        the run).
    **params
        Values of the constants (by name).

    Returns
    -------
    ContactMotion
        Its ``status``: "finished", or "interrupted" (Ctrl-C or the progress callback), the
        phases finished and the one under way up to the time reached kept. Regimes named
        ``stick``, ``slip+``, ``slip-``, ``slip``, ``contact``, ``open`` (one contact;
        followed by ``, rolls+``, ``, rolls-`` or ``, locked`` with a rolling
        resistance, ``, spins+``, ``, spins-`` or ``, no spin`` with a pivoting one), or
        ``"I: stick; J: slip+"`` (several, by the names of their points).

    Raises
    ------
    ConnectionError\\_
        A system without contact, or a contact whose coordinates forbid the motions the
        regimes need (or a rolling resistance on a rolling that is not planar).
    NumericalError
        A regime whose contact conditions stay dependent (hyperstatic normal forces), or a
        failed phase (the error's ``motion`` then holds the phases computed until the
        failure, as a ContactMotion with status "failed").
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
        if c.gap is not None and not model.closed(vals, c):
            continue                                 # starts open
        vn = float(vals[c.normal.c])
        if not model.speeds_zero(vals, [c.normal], y0):   # the rule on the constraints
            raise ArgumentError(f"`u0` separates the contact {c.name}: its normal velocity is "
                                f"{vn:.6g} at t0 (it must be 0).")
    rules = _Rules(model)
    try:
        motion = integrate_phases(rules.regimes(), rules.start, span, y0, method=method,
                                  rtol=rtol, atol=atol, max_step=max_step,
                                  max_phases=max_phases, progress=progress)
    except NumericalError as exc:  # the phases computed until the failure, with actions
        done = getattr(exc, "motion", None)
        if done is not None:
            exc.motion = ContactMotion(done.phases, model, status=done.status,
                                       message=done.message, regimes=done._regimes)
        raise
    return ContactMotion(motion.phases, model, status=motion.status, message=motion.message,
                         regimes=motion._regimes)
