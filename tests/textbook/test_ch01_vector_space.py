"""Textbook-style exercises of chapter 1 (the vector space), with rigidmech.vectors.basis.

Conventions (book, ch. 1): (i, j, k) is the direct orthonormal basis of the frame R0; in an
arbitrary basis (e1, e2, e3) a vector is u = u^1 e1 + u^2 e2 + u^3 e3 (contravariant
components), the metric is g_ij = e_i . e_j and (u, v, w) = u . (v ^ w) is the mixed product.
Expected values are worked out by hand in each case's comment.
"""

import pytest
import sympy as sp

from rigidmech.vectors import Frame, constants, mixed
from rigidmech.vectors.basis import Basis, double_cross, linear_dependence, linearly_independent

R0 = Frame("R0")
i, j, k = R0.basis
V = R0.vector
SKEW = Basis(i, i + j, i + j + k)  # e1 = i, e2 = i + j, e3 = i + j + k


def rotated_basis_matrix():
    th = constants("theta")
    R1 = R0.rotated("R1", about=k, angle=th)
    return sp.simplify(Basis.of(R0).change_of_basis_matrix(Basis.of(R1)))


CASES = [
    # 1.2.2: (1, 2, 3), (4, 5, 6), (7, 8, 9): the third is 2 * second - first.
    pytest.param(lambda: linear_dependence(V(1, 2, 3), V(4, 5, 6), V(7, 8, 9)), (1, -2, 1),
                 id="1.2.2-dependent-family"),
    # 1.2.2: (1, 1, 0), (0, 1, 1), (1, 0, 1): determinant 2, independent.
    pytest.param(lambda: linearly_independent(V(1, 1, 0), V(0, 1, 1), V(1, 0, 1)), True,
                 id="1.2.2-independent-family"),
    # 1.2.4: u = 2i + 3j + 4k = u^1 e1 + u^2 e2 + u^3 e3: u^3 = 4, u^2 + u^3 = 3, u^1 + u^2 +
    # u^3 = 2, so (u^1, u^2, u^3) = (-1, -1, 4).
    pytest.param(lambda: tuple(SKEW.components_of(V(2, 3, 4))), (-1, -1, 4),
                 id="1.2.4-components-in-skew-basis"),
    # 1.3.3: metric of (i, i + j, i + j + k): g_ij = min(i, j).
    pytest.param(lambda: SKEW.metric, sp.Matrix([[1, 1, 1], [1, 2, 2], [1, 2, 3]]),
                 id="1.3.3-metric"),
    # 1.3.3: u = e1 + e2 (= 2i + j), v = e3 (= i + j + k): g_13 + g_23 = 1 + 2 = 3 = u . v.
    pytest.param(lambda: SKEW.dot((1, 1, 0), (0, 0, 1)), 3, id="1.3.3-scalar-product"),
    # 1.3.2: |3i + 4j + 12k| = 13.
    pytest.param(lambda: V(3, 4, 12).magnitude(), 13, id="1.3.2-norm"),
    # 1.4.2: e1 ^ e2 = i ^ (i + j) = k = e3 - e2: components (0, -1, 1).
    pytest.param(lambda: tuple(SKEW.cross((1, 0, 0), (0, 1, 0))), (0, -1, 1),
                 id="1.4.2-vector-product-in-skew-basis"),
    # 1.4.3: (j, i, k) is an inverse basis (mixed product -1).
    pytest.param(lambda: Basis(j, i, k).is_direct, False, id="1.4.3-inverse-basis"),
    # 1.4.5: (u, v, w) = det [[1, 2, 3], [0, 1, 4], [5, 6, 0]] = -24 + 40 - 15 = 1.
    pytest.param(lambda: mixed(V(1, 2, 3), V(0, 1, 4), V(5, 6, 0)), 1, id="1.4.5-mixed-product"),
    # 1.4.6: i ^ (j ^ (i + j)) = i ^ (-k) = j; by the formula (i.(i+j)) j - (i.j)(i+j) = j.
    pytest.param(lambda: double_cross(i, j, i + j), j, id="1.4.6-double-vector-product"),
    # 1.4: area of the parallelogram built on 2i and i + 3j: |2i ^ (i + 3j)| = |6k| = 6.
    pytest.param(lambda: (2 * i).cross(i + 3 * j).magnitude(), 6, id="1.4-parallelogram-area"),
    # 1.5.2: rotation by theta about k: columns are i1 = (c, s, 0), j1 = (-s, c, 0), k1 = k.
    pytest.param(rotated_basis_matrix,
                 sp.Matrix([[sp.cos(constants("theta")), -sp.sin(constants("theta")), 0],
                            [sp.sin(constants("theta")), sp.cos(constants("theta")), 0],
                            [0, 0, 1]]),
                 id="1.5.2-basis-change-rotation"),
]


@pytest.mark.parametrize(("compute", "expected"), CASES)
def test_chapter_1(compute, expected):
    got = compute()
    if isinstance(expected, sp.MatrixBase):
        assert sp.simplify(sp.Matrix(got) - expected) == sp.zeros(*expected.shape)
    elif isinstance(expected, tuple):
        assert tuple(got) == expected
    elif isinstance(expected, bool):
        assert got is expected
    else:
        assert got == expected
