"""The value every builder of :mod:`rigidmech.models` returns (book, ch. 20: a system of the
book is its frames, bodies, connections and actions)."""

from __future__ import annotations

from typing import NamedTuple

from .._core.errors import ArgumentError

__all__ = ["Model"]


def _named(items, name, kind):
    for item in items:
        if getattr(item, "name", None) == name:
            return item
    known = ", ".join(repr(getattr(x, "name", x)) for x in items)
    raise ArgumentError(f"`name` must name one of the model's {kind}s ({known}); got {name!r}.")


class Model(NamedTuple):
    """A built model: the system and the handles a user needs, all immutable tuples.

    Attributes
    ----------
    system : System or Statics
        The assembled :class:`~rigidmech.dynamics.System` (symbol form); for a problem of
        statics (:func:`rigidmech.models.ladder`), the :class:`~rigidmech.statics.Statics`.
    coordinates : tuple
        The parameters of situation, in the order of the equations.
    constants : tuple
        The symbols of the model's parameters left symbolic (masses, lengths, g, ...).
    frames : tuple
        The frames, the Galilean reference R0 first.
    bodies : tuple
        The bodies, in connection order.
    points : tuple
        Points worth naming (joint centres, contact points, loop points).
    connections : tuple
        Connections a user may query (a knife edge, a contact), empty for most models.

    Examples
    --------
    >>> from rigidmech import models
    >>> pendulum = models.compound_pendulum()
    >>> pendulum.frame("R1").name, pendulum.constant("L")
    ('R1', L)
    >>> pendulum.body("bar").mass
    m
    """

    system: object
    coordinates: tuple
    constants: tuple
    frames: tuple
    bodies: tuple
    points: tuple = ()
    connections: tuple = ()

    def frame(self, name):
        """The frame called ``name`` (an :class:`~rigidmech.errors.ArgumentError` lists the
        known names otherwise)."""
        return _named(self.frames, name, "frame")

    def body(self, name):
        """The body called ``name``."""
        return _named(self.bodies, name, "body")

    def point(self, name):
        """The point called ``name``."""
        return _named(self.points, name, "point")

    def constant(self, name):
        """The constant (symbol) called ``name``."""
        return _named(self.constants, name, "constant")
