"""The heavy top of rigidmech.models against Lagrange's equations written by hand."""

import sympy as sp

from rigidmech import models


def test_heavy_top_mass_matrix_and_gravity_torque():
    # T = [(A + m l^2)(theta'^2 + psi'^2 sin^2 theta) + C (phi' + psi' cos theta)^2] / 2,
    # V = m g l cos(theta): at rest f = (0, m g l sin(theta), 0)
    model = models.heavy_top()
    psi, theta, phi = model.coordinates
    m, g, l, A, C = model.constants
    eqs = model.system.equations_of_motion()
    B = A + m * l**2
    c, s = sp.cos(theta), sp.sin(theta)
    M = sp.Matrix([[B * s**2 + C * c**2, 0, C * c], [0, B, 0], [C * c, 0, C]])
    assert sp.simplify(eqs.mass_matrix - M) == sp.zeros(3, 3)
    rest = eqs.forcing.subs({q.diff(): 0 for q in model.coordinates})
    assert sp.simplify(rest - sp.Matrix([0, m * g * l * s, 0])) == sp.zeros(3, 1)
