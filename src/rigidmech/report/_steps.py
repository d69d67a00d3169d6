"""The steps of a derivation report, each gathered from the library's own results (book,
ch. 9, 11, 13, 16, 18, 20, 25).

:class:`StepsWriter` reads a :class:`~rigidmech.dynamics.System` and appends the steps, each
``(title, section, intro, lines)`` with lines ``(label, value, note)``: ``label`` a
:class:`~rigidmech.report._display.Words`, ``value`` the library's value written with q(t)
(the report shows it later) and the raw results in :attr:`StepsWriter.results`.

The partial kinematic torsors and the actions' contributions are those the equations of
motion were assembled from: :meth:`System.partial_kinematic_torsors
<rigidmech.dynamics.System.partial_kinematic_torsors>` and :meth:`System.action_contributions
<rigidmech.dynamics.System.action_contributions>`, cached by the system (the report reads
them rather than computing them again another way).

Examples
--------
>>> from rigidmech import models
>>> pendulum = models.compound_pendulum()
>>> w = StepsWriter(pendulum.system, {"bar": pendulum.point("O_R0")})
>>> w.kinematics()
>>> w.steps[0][0], w.steps[0][3][0][0].text
('Kinematic torsors', '{V(bar/R0)}')
"""

from __future__ import annotations

import sympy as sp

from ..kinetics import Body
from ..vectors import t
from ._display import Relation, Words, tex_name, tex_text

__all__ = ["StepsWriter"]


def _sym_tex(name):
    """A frame's or a point's name as sympy prints a symbol of that name (R0 -> R_{0})."""
    return sp.latex(sp.Symbol(name))


def _as_argument(solid):
    """A solid as :meth:`System.connection_action` takes it: a Body, or the Galilean frame
    for the ground."""
    return solid if isinstance(solid, Body) else solid.frame


class StepsWriter:
    """Gathers the steps of a report of ``system`` (see the module).

    Parameters
    ----------
    system : System
    points : dict
        Body name -> the point of its kinematic torsor.
    """

    def __init__(self, system, points):
        self.system = system
        self.points = points
        self.R = system.reference
        self.q = system.coordinates
        q_plain = system.symbols()[0]
        self.q_text = [q.name for q in q_plain]
        self.q_tex = [sp.latex(q) for q in q_plain]
        self.steps = []
        self.results = {"points": dict(points), "kinematic": {}, "kinetic": {}, "dynamic": {},
                        "kinetic_energy": {}, "partial": {}, "actions": {}}
        self._names = self._action_names()
        # the labels of the linking connections (closure rows are labelled "<label>.<row>")
        self.linking = {label.rsplit(".", 1)[0] for label, _, _ in system.closure_conditions()}
        c = system.constraints()
        self.linked = None if c is None else \
            sp.ImmutableMatrix(c.jacobian.T * sp.Matrix(system.multiplier_symbols()))

    # -- names ------------------------------------------------------------------------
    def _action_names(self):
        kinds = [type(a).__name__ for a in self.system.actions]
        seen = {}
        names = {}
        for a, kind in zip(self.system.actions, kinds, strict=True):
            seen[kind] = seen.get(kind, 0) + 1
            names[id(a)] = kind if kinds.count(kind) == 1 else f"{kind}#{seen[kind]}"
        return names

    def _torsor(self, letter, body, index=None):
        R = self.R.name
        sub_t = "" if index is None else f"_{self.q_text[index]}"
        sub_x = "" if index is None else f"_{{{self.q_tex[index]}}}"
        text = f"{{{letter}{sub_t}({body}/{R})}}"
        tex = rf"\{{\mathcal{{{letter}}}{sub_x}({tex_name(body)}/{_sym_tex(R)})\}}"
        return Words(text, tex)

    @staticmethod
    def _action(source, target):
        text = f"{{A({source} -> {target})}}"
        tex = rf"\{{\mathcal{{A}}({tex_name(source)} \to {tex_name(target)})\}}"
        return Words(text, tex)

    def _add(self, title, section, intro, lines):
        self.steps.append((title, section, intro, lines))

    # -- 1. parameters of situation ---------------------------------------------------
    def situation(self):
        s, R = self.system, self.R
        kind = "Galilean" if R is s.galilean else f"moving; Galilean {s.galilean.name}"
        lines = [(None, Words(f"reference {R.name} ({kind})",
                              rf"\text{{reference }} {_sym_tex(R.name)}"
                              rf"\text{{ ({tex_text(kind)})}}"), ""),
                 (Words("q", "q"), sp.Tuple(*self.q),
                  f"{len(self.q)} parameter{'' if len(self.q) == 1 else 's'} of situation"),
                 (Words("constants", r"\text{constants}"), sp.Tuple(*s.parameters), "")]
        O = R.origin
        for b in s.bodies:
            lines.append((Words(f"frame of {b.name}", rf"\text{{frame of }}{tex_name(b.name)}"),
                          Words(repr(b.frame), rf"\texttt{{{tex_text(repr(b.frame))}}}"),
                          ""))
            G = b.centre
            lines.append((Words(f"vec({O.name} {G.name})",
                                rf"\overrightarrow{{{_sym_tex(O.name)}{_sym_tex(G.name)}}}"),
                          G - O, f"mass centre of {b.name}"))
            if b.mass is not None:
                lines.append((Words(f"m({b.name})", rf"m({tex_name(b.name)})"), b.mass, ""))
            if b.inertia is not None:
                basis = b.inertia.frame.name
                lines.append((Words(f"J_{G.name} in the basis of {basis}",
                                    rf"\mathcal{{J}}_{{{_sym_tex(G.name)}}}"),
                              b.inertia.matrix, f"operator of inertia, basis {basis}"))
        self._add("Parameters of situation", "ch. 9.1, 15, 21.1.2",
                  "The coordinates, the constants and the bodies.", lines)
        rows = s.closure_conditions()
        if rows:
            lines = []
            for label, velocity, position in rows:
                tex_label = tex_name(label)
                if position is not None:
                    lines.append((Words(f"Phi_{label}", rf"\Phi_{{{tex_label}}}"),
                                  Relation(position, 0), "closure condition"))
                lines.append((Words(f"Phi'_{label}", rf"\dot\Phi_{{{tex_label}}}"),
                              Relation(velocity, 0), "condition on the velocities"))
            lines.append((Words("lambda", r"\lambda"), sp.Tuple(*s.multiplier_symbols()),
                          "Lagrange multipliers, one per condition"))
            lines += [(None, None, note) for note in self._hyperstatic_notes()]
            self._add("Linked parameters", "ch. 25.3.3",
                      f"{len(rows)} conditions link the {len(self.q)} parameters; each has a "
                      "Lagrange multiplier.", lines)

    def _hyperstatic(self, label):
        """The names of the hyperstatic unknowns of the closing joint ``label``
        (:meth:`System.hyperstatic_unknowns
        <rigidmech.dynamics.System.hyperstatic_unknowns>`, ``<label>.<component>``)."""
        return tuple(n for n in self.system.hyperstatic_unknowns()
                     if n.rsplit(".", 1)[0] == label)

    def _hyperstatic_notes(self):
        """One note per loop-closing joint with hyperstatic unknowns: the components the
        equations do not determine, taken zero as the connection actions take them (their
        HyperstaticWarning says the same, ch. 14.2)."""
        tree = {id(k) for k in self.system.mechanism.tree_links()}
        notes = []
        for link in self.system.mechanism.links:
            names = () if id(link) in tree else self._hyperstatic(link.label)
            if names:
                notes.append(f"hyperstatic unknowns {', '.join(names)}: components of the "
                             f"action of the loop-closing joint {link.label} that the "
                             "equations do not determine; taken zero (the tree joints carry "
                             "the load, ch. 14.2)")
        return notes

    # -- 2. kinematics ----------------------------------------------------------------
    def kinematics(self):
        lines = []
        for b in self.system.bodies:
            P = self.points[b.name]
            V = b.kinematic_torsor(relative_to=self.R, at=P)
            self.results["kinematic"][b.name] = V
            lines.append((self._torsor("V", b.name), V, ""))
        self._add("Kinematic torsors", "ch. 9.2.4", "", lines)

    # -- 3. kinetics ------------------------------------------------------------------
    def kinetics(self):
        lines = []
        R = self.R
        for b in self.system.bodies:
            if not b.mass:
                lines.append((None, None, f"{b.name} is massless: no kinetic torsor"))
                continue
            C, D, E = b.kinetic_torsor(R), b.dynamic_torsor(R), b.kinetic_energy(R)
            self.results["kinetic"][b.name] = C
            self.results["dynamic"][b.name] = D
            self.results["kinetic_energy"][b.name] = E
            lines += [(self._torsor("C", b.name), C, ""),
                      (self._torsor("D", b.name), D, ""),
                      (Words(f"E_k({b.name}/{R.name})",
                             rf"E_k({tex_name(b.name)}/{_sym_tex(R.name)})"), E, "")]
        T = self.system.kinetic_energy()
        self.results["kinetic_energy_total"] = T
        lines.append((Words("T", "T"), T, "kinetic energy of the set"))
        self._add("Kinetic and dynamic torsors", "ch. 16.1.2, 16.2.2, 16.3",
                  "At the mass centres.", lines)

    # -- 4. actions -------------------------------------------------------------------
    def actions(self):
        s = self.system
        lines = []
        for solid, torsor, action in s.action_contributions():
            name = self._names[id(action)]
            label = self._action(name, solid.name)
            self.results["actions"][f"{name} -> {solid.name}"] = torsor
            lines.append((label, torsor, "given"))
        tree = {id(k) for k in s.mechanism.tree_links()}
        for link in s.mechanism.links:
            first, second, conn = link.first, link.second, link.connection
            key = f"{first.name} -> {second.name} ({link.label})"
            kind = type(conn).__name__
            if id(link) not in tree:
                # a loop-closing connection: its action is sum lambda_i e_i (ch. 25.3.3)
                A = s.connection_action(_as_argument(first), _as_argument(second),
                                        label=link.label)
                note = f"{kind} {link.label}, closes a loop: its multipliers"
                hyperstatic = self._hyperstatic(link.label)
                if hyperstatic:
                    note += f"; hyperstatic {', '.join(hyperstatic)} taken zero"
            elif hasattr(conn, "action_torsor"):
                A, unknowns = conn.action_torsor(link.label)
                note = f"{kind} {link.label}: unknowns {', '.join(map(str, unknowns))}"
                if link.label in self.linking:
                    note += "; linking: in the equations through its multipliers"
            else:
                lines.append((None, None, f"{kind} {link.label}: no action torsor shown"))
                continue
            self.results["actions"][key] = A
            lines.append((self._action(first.name, second.name), A, note))
        self._add("Action torsors", "ch. 11, 13.2",
                  "The given actions, and the connections' actions with their unknowns.", lines)

    # -- 5. partial kinematic torsors, power coefficients --------------------------------
    def _partial(self, solid, point, i):
        return self.system.partial_kinematic_torsors(solid, point)[i]

    def partials(self):
        s = self.system
        lines = []
        for b in s.bodies:
            P = self.points[b.name]
            parts = tuple(self._partial(b, P, i) for i in range(len(self.q)))
            self.results["partial"][b.name] = parts
            lines += [(self._torsor("V", b.name, index=i), V, "") for i, V in enumerate(parts)]
        self._add("Partial kinematic torsors", "ch. 25.1.2",
                  "{V_i(S/R)} = d{V(S/R)}/dq_i' for each parameter q_i.", lines)
        lines = []
        for solid, torsor, action in s.action_contributions():
            name = self._names[id(action)]
            for i, qt in enumerate(self.q_text):
                Q = torsor.comoment(self._partial(solid, torsor.point, i))
                lines.append((Words(f"Q_{qt}({name} -> {solid.name})",
                                    rf"Q_{{{self.q_tex[i]}}}({tex_name(name)} \to "
                                    rf"{tex_name(solid.name)})"), Q, ""))
        Q = s.generalized_forces()
        self.results["power_coefficients"] = Q
        lines.append((Words("Q", "Q"), Q, "power coefficients of the given actions"))
        ground = s.mechanism.solids[0]
        for link in s.mechanism.tree_links():
            if link.label in self.linking:
                continue   # its power is that of its multipliers, A^T lambda
            A = self.results["actions"].get(f"{link.first.name} -> {link.second.name} "
                                            f"({link.label})")
            if A is None:
                continue
            for i, qt in enumerate(self.q_text):
                P = A.point
                power = A.comoment(self._partial(link.second, P, i))
                if link.first is not ground:
                    power -= A.comoment(self._partial(link.first, P, i))
                lines.append((Words(f"Q_{qt}(connection {link.label})",
                                    rf"Q_{{{self.q_tex[i]}}}(\text{{connection }}"
                                    rf"{tex_name(link.label)})"), power,
                              "perfect connection: zero (ch. 25.1.4)"))
        if self.linked is not None:
            lines.append((Words("A^T lambda", r"A^{T}\lambda"), self.linked,
                          "power coefficients of the linking connections"))
        self._add("Power coefficients", "ch. 25.1.3, 25.1.4",
                  "Q_i = {A}.{V_i}, the comoment of each action with the partial kinematic "
                  "torsor of the body it acts on.", lines)

    # -- 6. the route -----------------------------------------------------------------
    def _linked(self, i):
        return 0 if self.linked is None else self.linked[i]

    def principle(self):
        s, R = self.system, self.R
        lines = []
        for b in s.bodies:
            terms = [self._action(self._names[id(a)], b.name)
                     for solid, _, a in s.action_contributions() if solid is b]
            for link in s.mechanism.links:
                if link.second is b:
                    terms.append(self._action(link.first.name, b.name))
                elif link.first is b:
                    terms.append(self._action(link.second.name, b.name))
            rhs = Words(" + ".join(w.text for w in terms) or "0",
                        " + ".join(w.latex for w in terms) or "0")
            lines.append((self._torsor("D", b.name), rhs, "isolated body"))
        for i, qt in enumerate(self.q_text):
            total = []
            for b in s.bodies:
                if not b.mass:
                    continue
                D = self.results["dynamic"][b.name]
                term = D.comoment(self.results["partial"][b.name][i])
                total.append(term)
                lines.append((Words(f"{{D({b.name}/{R.name})}}.{{V_{qt}({b.name}/{R.name})}}",
                                    self._torsor("D", b.name).latex + r"\cdot"
                                    + self._torsor("V", b.name, index=i).latex), term, ""))
            rhs = self.results["power_coefficients"][i] + self._linked(i)
            lines.append((Words(f"({qt})", rf"({self.q_tex[i]})"),
                          Relation(sp.Add(*total), rhs), "summed over the set"))
        self._add("Fundamental principle", "ch. 18.1, 25.1.4",
                  "{D(S/R)} = {A(ext -> S)} for each body, projected on its partial kinematic "
                  "torsors and summed over the set: the perfect connections drop out.", lines)

    def lagrange(self):
        T = self.results["kinetic_energy_total"]
        lines = []
        self.results["momenta"] = []
        for i, (q, qt) in enumerate(zip(self.q, self.q_text, strict=True)):
            rate = q.diff(t)
            p = sp.diff(T, rate)
            self.results["momenta"].append(p)
            dp, dq = sp.diff(p, t), sp.diff(T, q)
            tq = self.q_tex[i]
            lines += [(Words(f"dT/d{qt}'", rf"\frac{{\partial T}}{{\partial \dot{{{tq}}}}}"),
                       p, ""),
                      (Words(f"d/dt(dT/d{qt}')", rf"\frac{{d}}{{dt}}\frac{{\partial T}}"
                             rf"{{\partial \dot{{{tq}}}}}"), dp, ""),
                      (Words(f"dT/d{qt}", rf"\frac{{\partial T}}{{\partial {tq}}}"), dq, ""),
                      (Words(f"({qt})", rf"({tq})"),
                       Relation(dp - dq, self.results["power_coefficients"][i]
                                + self._linked(i)), "")]
        self.results["momenta"] = tuple(self.results["momenta"])
        self._add("Lagrange's equations", "ch. 25.3.2",
                  "d/dt(dT/dq_i') - dT/dq_i = Q_i for each parameter q_i.", lines)

    # -- 7. equations -----------------------------------------------------------------
    def equations(self, eqs):
        self.results["equations"] = eqs
        M, f = eqs.mass_matrix, eqs.forcing
        n = len(self.q)
        acc = [q.diff(t, 2) for q in self.q]
        lines = [(Words("M(q)", "M(q)"), M, "mass matrix"),
                 (Words("f(q, q', t)", r"f(q, \dot q, t)"), f, "")]
        for i in range(n):
            lhs = sp.Add(*[M[i, j] * acc[j] for j in range(n)])
            lines.append((Words(f"({self.q_text[i]})", rf"({self.q_tex[i]})"),
                          Relation(lhs, f[i] + self._linked(i), termwise=True), ""))
        self._add("Equations of motion", "ch. 20.2, 25.1.4",
                  "M(q) q'' = f(q, q', t)" + ("" if self.linked is None else " + A^T lambda"),
                  lines)

