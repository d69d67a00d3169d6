"""Equations handed to and from sympy.physics.mechanics (kane_form, from_sympy_mechanics): the
same equations both ways, the energy of a Lagrangian, and the refusals named."""

import pytest
import sympy as sp
from sympy.physics import mechanics as me

import rigidmech as rm
from rigidmech import models
from rigidmech.dynamics import from_sympy_mechanics, kane_form
from rigidmech.errors import ArgumentError, ArgumentTypeError

q = me.dynamicsymbols("q")
u = me.dynamicsymbols("u")
m, g, L = sp.symbols("m g L", positive=True)


def _pendulum_point():
    N = me.ReferenceFrame("N")
    O = me.Point("O")
    O.set_vel(N, 0)
    P = O.locatenew("P", L * (sp.cos(q) * N.x + sp.sin(q) * N.y))
    return N, O, P


def _lagrange():
    N, O, P = _pendulum_point()
    P.set_vel(N, P.pos_from(O).dt(N))
    bob = me.Particle("bob", P, m)
    bob.potential_energy = -m * g * L * sp.cos(q)
    lm = me.LagrangesMethod(me.Lagrangian(N, bob), [q])
    return lm


def _kane(kd):
    N, O, P = _pendulum_point()
    kane = me.KanesMethod(N, q_ind=[q], u_ind=[u], kd_eqs=[kd])
    P.set_vel(N, me.msubs(P.pos_from(O).dt(N), kane.kindiffdict()))
    kane.kanes_equations([me.Particle("bob", P, m)], [(P, m * g * N.x)])
    return kane


def test_lagrange_and_kane_give_the_same_equations_as_the_closed_form():
    lm = _lagrange()
    lm.form_lagranges_equations()
    for eqs in (from_sympy_mechanics(lm), from_sympy_mechanics(_kane(q.diff() - u))):
        assert eqs.coordinates == (q,)
        assert sp.simplify(eqs.accelerations()[0] + g / L * sp.sin(q)) == 0


def test_energy_of_a_lagrangian_is_T_plus_V_and_conserved():
    lm = _lagrange()
    lm.form_lagranges_equations()
    eqs = from_sympy_mechanics(lm)
    T_plus_V = m * L**2 * q.diff(rm.t)**2 / 2 - m * g * L * sp.cos(q)
    assert sp.simplify(eqs.energy - T_plus_V) == 0
    sim = eqs.simulate(t=(0.0, 3.0), q0=[1.0], u0=[0.0], rtol=1e-11, atol=1e-12, m=1.0, g=9.81,
                       L=1.0)
    assert sim.energy_drift() < 1e-8


def test_kane_form_of_a_model_matches_kanes_method():
    model = models.compound_pendulum()
    eqs = model.system.equations_of_motion()
    (c,) = model.coordinates
    w = me.dynamicsymbols("w")
    MF, FF = kane_form(eqs, speeds=[w])
    assert MF.shape == (2, 2) and MF[0, 0] == 1 and MF[0, 1] == 0
    assert FF[0] == w and MF[1, 1] == eqs.mass_matrix[0, 0]
    assert sp.simplify(FF[1] - eqs.forcing[0].subs(c.diff(rm.t), w)) == 0
    MF2, FF2 = kane_form(eqs)
    assert FF2[0] == c.diff(rm.t)


def test_refusals_are_named():
    with pytest.raises(ArgumentError, match="call form_lagranges_equations"):
        from_sympy_mechanics(_lagrange())
    with pytest.raises(ArgumentError, match=r"the speeds must be the rates of the coordinates"):
        from_sympy_mechanics(_kane(q.diff() - 2 * u))
    N, O, P = _pendulum_point()
    with pytest.raises(ArgumentError, match="call kanes_equations"):
        from_sympy_mechanics(me.KanesMethod(N, q_ind=[q], u_ind=[u], kd_eqs=[q.diff() - u]))
    with pytest.raises(ArgumentTypeError, match="`method` must be a LagrangesMethod or a "
                                                "KanesMethod"):
        from_sympy_mechanics("lagrange")
    disc = models.rolling_disc().system.equations_of_motion()
    with pytest.raises(ArgumentError, match="`eqs` has constraints"):
        kane_form(disc)
    eqs = models.compound_pendulum().system.equations_of_motion()
    with pytest.raises(ArgumentError, match=r"`speeds` must give 1 speeds"):
        kane_form(eqs, speeds=[u, q])
    with pytest.raises(ArgumentTypeError, match="`eqs` must be an EquationsOfMotion"):
        kane_form(None)
