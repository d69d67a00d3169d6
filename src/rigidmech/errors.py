"""The errors that rigidmech raises on purpose, for callers to catch.

Every one derives from :class:`RigidmechError`; the specific errors also derive from the
builtin that fits (``ValueError`` for a wrong value or shape, ``TypeError`` for a wrong type,
``ArithmeticError`` for a mass matrix that cannot be inverted), so ``except ValueError`` keeps
working. Messages name the argument in backticks, say what was expected and what was received.

The classes are defined in ``rigidmech._core.errors`` (the lowest layer, so that every layer can
raise them); this module is their public home.

Examples
--------
>>> import rigidmech as rm
>>> from rigidmech.errors import ArgumentError, RigidmechError
>>> try:
...     rm.Body("b", frame=rm.Frame("R0"), mass=-1)
... except ArgumentError as error:
...     print(isinstance(error, RigidmechError), isinstance(error, ValueError))
True True
"""

from ._core.errors import (
    ArgumentError,
    ArgumentTypeError,
    CompilationError,
    ConnectionError_,
    FrameError,
    HyperstaticWarning,
    NumericalError,
    RigidmechError,
    RigidmechWarning,
    SceneError,
    SingularityWarning,
    SingularMassMatrixError,
)

__all__ = [
    "RigidmechError",
    "ArgumentError",
    "ArgumentTypeError",
    "FrameError",
    "ConnectionError_",
    "SingularMassMatrixError",
    "NumericalError",
    "CompilationError",
    "SceneError",
    "RigidmechWarning",
    "SingularityWarning",
    "HyperstaticWarning",
]
