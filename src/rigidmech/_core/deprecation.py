"""Deprecated aliases of renamed public names, resolved by a module ``__getattr__``
(PEP 562) that warns with :class:`DeprecationWarning` and returns the new object.

Examples
--------
>>> import warnings
>>> getattr_ = deprecated_aliases("pkg", {"old": ("pkg.new", 42)})
>>> with warnings.catch_warnings(record=True) as w:
...     warnings.simplefilter("always")
...     value = getattr_("old")
>>> value, str(w[0].message)
(42, '`pkg.old` is deprecated: use `pkg.new` (the same object under a clearer name).')
"""

from __future__ import annotations

import warnings

__all__ = ["deprecated_aliases"]


def deprecated_aliases(module: str, aliases: dict):
    """A module ``__getattr__`` for ``aliases`` = {old name: (new dotted name, object)}."""

    def __getattr__(name):
        if name in aliases:
            new, obj = aliases[name]
            warnings.warn(f"`{module}.{name}` is deprecated: use `{new}` (the same object "
                          "under a clearer name).", DeprecationWarning, stacklevel=2)
            return obj
        raise AttributeError(f"module {module!r} has no attribute {name!r}")

    return __getattr__
