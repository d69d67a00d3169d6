"""A catalogue of the models of the book, one builder per model (book, ch. 13, 22-25).

Each builder assembles a :class:`~rigidmech.dynamics.System` the book's way (frames,
bodies, connections, actions) and returns a :class:`Model`: the system and its handles
(coordinates, constants, frames, bodies, points). The scenes, the tests, the benchmarks and
the examples import these builders rather than building their own copies.

* :mod:`~rigidmech.models.chains`: compound pendulum, double pendulum (rods or point
  masses), n-link pendulum, pendulum on a cart;
* :mod:`~rigidmech.models.loops`: four-bar, chain of four-bars, slider-crank;
* :mod:`~rigidmech.models.incline`: a block sliding down a smooth incline;
* :mod:`~rigidmech.models.rolling`: rolling disc, wheel on an incline, ball on a driven
  turntable;
* :mod:`~rigidmech.models.knife`: the Chaplygin sleigh (flat, inclined, on a turntable);
* :mod:`~rigidmech.models.contacts`: a ball sliding then rolling, an eccentric disc rocking;
* :mod:`~rigidmech.models.tops`: the symmetric heavy top on a ball joint;
* :mod:`~rigidmech.models.bicycle`: the Whipple bicycle (Meijaard et al. 2007);
* :mod:`~rigidmech.models.friction`: a ladder against a wall with friction at both ends, a
  problem of statics (its ``system`` is a :class:`~rigidmech.statics.Statics`).

Examples
--------
>>> from rigidmech import models
>>> models.names()[:3]
('compound_pendulum', 'double_pendulum', 'point_mass_double_pendulum')
>>> models.get("four_bar").section
'ch. 13.2, 25.3.3'
"""

from __future__ import annotations

from typing import NamedTuple

from .._core.errors import ArgumentError
from ._model import Model
from .bicycle import BENCHMARK_BICYCLE, whipple_bicycle
from .chains import (
    cart_pendulum,
    compound_pendulum,
    double_pendulum,
    n_link_pendulum,
    point_mass_double_pendulum,
    spherical_chain,
)
from .contacts import eccentric_disc, sliding_ball
from .friction import ladder
from .incline import block_on_incline
from .knife import sleigh, sleigh_on_incline, sleigh_on_turntable
from .loops import CHAIN_COUPLER, FOUR_BAR_LENGTHS, four_bar, four_bar_chain, slider_crank
from .rolling import ball_on_turntable, rolling_disc, wheel_on_incline
from .tops import heavy_top

__all__ = ["Model", "Entry", "catalogue", "names", "get",
           "compound_pendulum", "double_pendulum", "point_mass_double_pendulum", "n_link_pendulum",
           "spherical_chain", "cart_pendulum",
           "four_bar", "four_bar_chain", "slider_crank", "FOUR_BAR_LENGTHS", "CHAIN_COUPLER",
           "block_on_incline", "rolling_disc", "wheel_on_incline", "ball_on_turntable",
           "sleigh", "sleigh_on_incline", "sleigh_on_turntable",
           "sliding_ball", "eccentric_disc", "heavy_top",
           "whipple_bicycle", "BENCHMARK_BICYCLE", "ladder"]


class Entry(NamedTuple):
    """One line of the catalogue: a builder's name, the book's section, its family (the
    module) and the builder itself.

    Examples
    --------
    >>> from rigidmech import models
    >>> entry = models.get("rolling_disc")
    >>> entry.family, entry.build().coordinates[:2]
    ('rolling', (x(t), y(t)))
    """

    name: str
    section: str
    family: str
    build: object


_ENTRIES = tuple(Entry(f.__name__, section, f.__module__.rsplit(".", 1)[-1], f) for f, section in (
    (compound_pendulum, "ch. 22.2.1"),
    (double_pendulum, "ch. 25.4.3, 27.5"),
    (point_mass_double_pendulum, "ch. 25.4.3, 27.5.2"),
    (n_link_pendulum, "ch. 25.3"),
    (spherical_chain, "ch. 9.4.4, 25.3"),
    (cart_pendulum, "ch. 21, 24.3"),
    (four_bar, "ch. 13.2, 25.3.3"),
    (four_bar_chain, "ch. 25.3.3"),
    (slider_crank, "ch. 13.2, 25.3.3"),
    (block_on_incline, "ch. 23.2.5, 27.4"),
    (rolling_disc, "ch. 10.1, 13.1"),
    (wheel_on_incline, "ch. 23.4"),
    (ball_on_turntable, "ch. 10.1, 13.1, 17.1, 25.3.3"),
    (sleigh, "ch. 13.1, 25.3.3"),
    (sleigh_on_incline, "ch. 13.1, 25.3.3"),
    (sleigh_on_turntable, "ch. 13.1, 25.3.3"),
    (sliding_ball, "ch. 13.1.2"),
    (eccentric_disc, "ch. 13.1, 23.4"),
    (heavy_top, "ch. 9.4.4, 20"),
    (whipple_bicycle, "ch. 13.1, 25.3.3"),
    (ladder, "ch. 14.4.1"),
))
_BY_NAME = {e.name: e for e in _ENTRIES}


def catalogue() -> tuple:
    """Every builder of the catalogue as an :class:`Entry`, in catalogue order.

    Examples
    --------
    >>> from rigidmech import models
    >>> sorted({e.family for e in models.catalogue()})
    ['bicycle', 'chains', 'contacts', 'friction', 'incline', 'knife', 'loops', 'rolling', 'tops']
    """
    return _ENTRIES


def names() -> tuple:
    """The builders' names, in catalogue order.

    Examples
    --------
    >>> from rigidmech import models
    >>> len(models.names())
    21
    """
    return tuple(_BY_NAME)


def get(name) -> Entry:
    """The :class:`Entry` called ``name``.

    Raises
    ------
    ArgumentError
        If no builder has that name; the message lists the known names.

    Examples
    --------
    >>> from rigidmech import models
    >>> models.get("sleigh").build().bodies[0].name
    'sleigh'
    """
    if not isinstance(name, str) or name not in _BY_NAME:
        raise ArgumentError(f"`name` must be one of the catalogue's models ({', '.join(_BY_NAME)});"
                            f" got {name!r}. List them with rigidmech.models.names().")
    return _BY_NAME[name]
