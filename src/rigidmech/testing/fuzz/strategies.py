"""Hypothesis strategy of random mechanisms (test dependency: import this module only where
hypothesis is installed; ``import rigidmech`` and ``rigidmech.testing.fuzz`` never import it).

:func:`models` draws a :class:`~rigidmech.testing.fuzz.Model` with the same procedure as
:func:`~rigidmech.testing.fuzz.random_model` (:func:`~rigidmech.testing.fuzz.draw_model`),
its random choices read from hypothesis, so that a failing model shrinks to a minimal one:
fewer bodies, simpler joints (pivot first), offsets and angles towards zero, fewer actions.

Examples
--------
>>> from hypothesis import given, settings
>>> from rigidmech.testing.fuzz.strategies import models
>>> @settings(max_examples=3, derandomize=True, database=None)
... @given(models(max_bodies=2, actions=False))
... def check(model):
...     assert 1 <= len(model.bodies) <= 2
>>> check()
"""

from __future__ import annotations

import math

from hypothesis import strategies as st

from .generate import _GRID, draw_model

__all__ = ["HypothesisSource", "models"]


class HypothesisSource:
    """Random choices read from hypothesis' ``draw`` (see
    :func:`~rigidmech.testing.fuzz.draw_model`); integers shrink towards zero (or the bound
    nearest to it), so every choice shrinks to the simpler mechanism."""

    def __init__(self, draw):
        self._draw = draw

    def integer(self, lo, hi):
        """An integer in [lo, hi]."""
        return self._draw(st.integers(lo, hi))

    def real(self, lo, hi):
        """A multiple of 1/16 in [lo, hi]."""
        return self.integer(math.ceil(lo * _GRID), math.floor(hi * _GRID)) / _GRID

    def choice(self, seq):
        """One entry of ``seq`` (shrinks to the first)."""
        return seq[self.integer(0, len(seq) - 1)]

    def flag(self, p):
        """A boolean (shrinks to False; ``p`` is ignored: hypothesis chooses)."""
        return self._draw(st.booleans())


@st.composite
def _models(draw, options):
    return draw_model(HypothesisSource(draw), **options)


def models(**options):
    """Strategy of :class:`~rigidmech.testing.fuzz.Model` (options of
    :func:`~rigidmech.testing.fuzz.draw_model`)."""
    return _models(options)
