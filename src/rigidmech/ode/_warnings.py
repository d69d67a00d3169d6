"""Warnings of :mod:`rigidmech.ode`."""

import os
import sys
import warnings

__all__ = ["StiffnessWarning", "stiffness_count"]


class StiffnessWarning(RuntimeWarning):
    """An explicit method detected that the problem has become stiff.

    Raised (as a warning) by ``"dopri5"``, ``"dop853"`` after Hairer's test (the estimate
    ``h |lambda|`` of the step times the dominant eigenvalue stays at the border of the
    stability domain for 15 checks) and by ``"adams"`` after the same count at orders 1-4;
    the integration goes on, but ``method="radau"`` would need far fewer steps.

    Examples
    --------
    >>> issubclass(StiffnessWarning, RuntimeWarning)
    True
    """


#: the package's folder: a warning is attributed to the first caller outside it
_PACKAGE = os.path.dirname(os.path.dirname(os.path.abspath(__file__))) + os.sep


def _user_stacklevel():
    """``stacklevel`` for :func:`warnings.warn` called from the caller of this function that
    names the first frame outside rigidmech (the user's call, direct or through ``solve``)."""
    frame = sys._getframe(1)
    level = 1
    while frame is not None and frame.f_code.co_filename.startswith(_PACKAGE):
        frame = frame.f_back
        level += 1
    return level


def stiffness_count(method, border, hlamb, t_new, iasti, nonsti, warned):
    """One check of Hairer's stiffness detection (codes DOPRI5/DOP853): 15 checks with
    ``h |lambda|`` beyond `border` (6 checks below in a row reset the count) warn once.

    Returns the updated ``(iasti, nonsti, warned)``. The warning points at the user's call
    (the first frame outside rigidmech).
    """
    if hlamb > border:
        iasti, nonsti = iasti + 1, 0
        if iasti == 15 and not warned:
            warned = True
            warnings.warn(
                f"The problem seems to have become stiff at t = {t_new:.6g} "
                f"(method {method!r}, h*|lambda| ~ {hlamb:.3g} for 15 checks): "
                "use method='radau'.",
                StiffnessWarning,
                stacklevel=_user_stacklevel(),
            )
    else:
        nonsti += 1
        if nonsti == 6:
            iasti = 0
    return iasti, nonsti, warned
