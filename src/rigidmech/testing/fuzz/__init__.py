"""A differential model fuzzer: random mechanisms built by rigidmech and by
sympy.physics.mechanics, their accelerations compared.

A model is plain immutable data (:class:`Model`, a tuple of :class:`BodySpec` and the
actions), drawn by :func:`random_model` from a ``numpy.random.Generator`` or, in the tests,
by the hypothesis strategy :func:`rigidmech.testing.fuzz.strategies.models` (a separate
module: hypothesis is a test dependency, never imported by ``import rigidmech``). Two
builders read the same description independently: :func:`to_rigidmech` (rigidmech's public
API) and :func:`to_sympy` (``KanesMethod``); :func:`compare` evaluates both at random states
and returns a :class:`Report`; :func:`compare_action` compares the action in one joint
(rigidmech's ``connection_components`` against Kane's auxiliary speeds, ``u_auxiliary``).
:mod:`rigidmech.testing.fuzz.transforms` gives the metamorphic transformations (Galilean
frame turned or moved, bodies connected in another order, units scaled).

The models are trees of the joints of :data:`JOINTS` (book, ch. 13.2.2), among them spheres
and discs rolling without slipping on a plane (:data:`ROLLING`, nonholonomic), optionally
with knife edges (:class:`KnifeSpec`, nonholonomic) and a joint closing a loop to the ground
(:class:`ClosureSpec`: spherical, or a pivot or a slider closing a planar loop).

Examples
--------
>>> import numpy as np
>>> from rigidmech.testing import fuzz
>>> model = fuzz.random_model(np.random.default_rng(7), max_bodies=2, max_dof=3)
>>> fuzz.compare(model, seed=1).ok
True
"""

from . import transforms
from .build_rigidmech import to_rigidmech
from .build_sympy import to_sympy
from .compare import RTOL, Report, compare, compare_action
from .description import (
    CLOSURES,
    JOINTS,
    ROLLING,
    BodySpec,
    ClosureSpec,
    DamperSpec,
    ForceSpec,
    KnifeSpec,
    Model,
    SpringSpec,
    TorqueSpec,
    TorsionalDamperSpec,
    coordinate_kinds,
    coordinate_names,
)
from .generate import NumpySource, draw_model, random_model

__all__ = ["JOINTS", "ROLLING", "CLOSURES", "KnifeSpec", "BodySpec", "SpringSpec",
           "DamperSpec", "TorqueSpec", "ForceSpec",
           "TorsionalDamperSpec", "ClosureSpec", "Model", "coordinate_names", "coordinate_kinds",
           "NumpySource", "draw_model", "random_model", "to_rigidmech", "to_sympy", "compare",
           "compare_action", "Report", "RTOL", "transforms"]
