"""Warnings of :mod:`rigidmech.ode`."""

__all__ = ["StiffnessWarning"]


class StiffnessWarning(RuntimeWarning):
    """An explicit method detected that the problem has become stiff.

    Raised (as a warning) by ``"dopri5"``, ``"dop853"`` after Hairer's test (the estimate
    ``h |lambda|`` of the step times the dominant eigenvalue stays at the border of the
    stability domain for 15 checks); the integration goes on, but ``method="radau"`` would need
    far fewer steps.

    Examples
    --------
    >>> issubclass(StiffnessWarning, RuntimeWarning)
    True
    """
