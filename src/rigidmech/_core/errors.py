"""The exception hierarchy of rigidmech.

Every error raised on purpose by rigidmech derives from :class:`RigidmechError`; the specific
errors also derive from the builtin that fits (``ValueError`` for a wrong value or shape,
``TypeError`` for a wrong type) so that callers can catch either.

Messages follow one rule: the argument in backticks, what was expected, what was received and,
where it helps, how to fix it.
"""

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
]


class RigidmechError(Exception):
    """Root of every error that rigidmech raises on purpose.

    Examples
    --------
    >>> issubclass(FrameError, RigidmechError)
    True
    """


class ArgumentError(RigidmechError, ValueError):
    """An argument has the right type but a wrong value or shape.

    Examples
    --------
    >>> isinstance(ArgumentError("`mass` must be >= 0; got -1."), ValueError)
    True
    """


class ArgumentTypeError(RigidmechError, TypeError):
    """An argument has the wrong type (a vector where a point is expected, ...).

    Examples
    --------
    >>> isinstance(ArgumentTypeError("`at` must be a Point; got Vector."), TypeError)
    True
    """


class FrameError(RigidmechError, ValueError):
    """Frames that do not belong together: no common root, a chain that does not compose.

    Examples
    --------
    >>> isinstance(FrameError("no common root"), ValueError)
    True
    """


class ConnectionError_(RigidmechError, ValueError):
    """A connection between bodies that cannot be set up or solved.

    (The trailing underscore avoids shadowing the builtin ``ConnectionError``.)

    Examples
    --------
    >>> isinstance(ConnectionError_("body connected twice"), ValueError)
    True
    """


class SingularMassMatrixError(RigidmechError, ArithmeticError):
    """The mass matrix cannot be inverted at the given state.

    Examples
    --------
    >>> issubclass(SingularMassMatrixError, ArithmeticError)
    True
    """


class NumericalError(RigidmechError, ArithmeticError):
    """A numerical computation produced non-finite values or could not proceed.

    Examples
    --------
    >>> issubclass(NumericalError, RigidmechError)
    True
    """


class CompilationError(RigidmechError, ValueError):
    """A symbolic expression cannot be compiled with the given arguments.

    Examples
    --------
    >>> issubclass(CompilationError, ValueError)
    True
    """


class SceneError(RigidmechError, ValueError):
    """An unknown scene name or scene option.

    Examples
    --------
    >>> issubclass(SceneError, ValueError)
    True
    """


class RigidmechWarning(UserWarning):
    """Root of the warnings that rigidmech issues on purpose.

    Examples
    --------
    >>> issubclass(SingularityWarning, RigidmechWarning)
    True
    """


class SingularityWarning(RigidmechWarning, RuntimeWarning):
    """A simulation came near the singular set of an orientation parametrisation (book,
    ch. 9.1.2): Euler angles near sin(theta) = 0, Cardan angles near cos(theta) = 0.

    There the mass matrix is nearly singular: the integration needs many small steps and
    loses accuracy. The message names the frame, the time and the distance, and suggests
    another sequence of rotations.

    Examples
    --------
    >>> issubclass(SingularityWarning, RuntimeWarning)
    True
    """


class HyperstaticWarning(RigidmechWarning, UserWarning):
    """A connection action was computed in a hyperstatic mounting (book, ch. 13.2, 14.2): some
    components of the action of a loop-closing joint are not determined by the fundamental
    principle (two coaxial pivots; a planar loop of spatial pivots, whose out-of-plane
    components are hyperstatic). They are taken zero in the closing joint, the tree joints
    carrying the load: one admissible split among infinitely many, which depends on the
    stiffness of the parts. The message names those unknowns (``<label>.<component>``, as
    ``System.hyperstatic_unknowns``); the other components are determined. After reading it,
    silence it with ``warnings.simplefilter("ignore", HyperstaticWarning)``.

    Examples
    --------
    >>> issubclass(HyperstaticWarning, UserWarning)
    True
    """
