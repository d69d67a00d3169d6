"""Functions of slow-to-import modules, imported on their first call (import cost).

``import scipy.linalg`` alone takes about 0.4 s and ``scipy.optimize`` 0.3 s, as long as
``import sympy`` itself; most sessions that ``import rigidmech`` never call them. A module
whose hot path calls such a function at every step (LAPACK in :mod:`rigidmech._core.compile`)
binds a stand-in at import instead of the function, with the usual names::

    _dgetrf, _dposv = lazy_functions(globals(), "scipy.linalg.lapack", "dgetrf", "dposv")

The first call of either stand-in imports the module and rebinds every stand-in of the batch
in that module's namespace to the real function, so later calls cost nothing extra. Where
the call is not hot, the import simply moves into the function, with a comment saying why
(``# lazy: import cost (see docs/performance)``). A module written against a package's
subpackages (``scipy.linalg.qr(...)``) binds ``scipy = lazy_package("scipy")`` instead of
``import scipy.linalg``: ``scipy.linalg`` is imported on first access. Hand-rolled:
:class:`importlib.util.LazyLoader` makes a whole module lazy but not a ``from module import
name`` binding, which is what these modules hold.

Examples
--------
>>> namespace = {}
>>> (sqrt,) = lazy_functions(namespace, "math", "sqrt")
>>> namespace["sqrt"] = sqrt
>>> sqrt
<function math.sqrt, imported on first call>
>>> sqrt(4.0), namespace["sqrt"]
(2.0, <built-in function sqrt>)
"""

from __future__ import annotations

import importlib

__all__ = ["lazy_functions", "lazy_package"]


class _LazyFunction:
    """Stand-in for ``module.name``: imports it when first called (see the module notes)."""

    __slots__ = ("_batch", "_function", "_module", "_name", "_namespace")

    def __init__(self, namespace, module, name, batch):
        self._namespace, self._module, self._name, self._batch = namespace, module, name, batch
        self._function = None

    def _load(self):
        if self._function is None:
            module = importlib.import_module(self._module)
            for stand_in in self._batch:
                stand_in._function = getattr(module, stand_in._name)
            # rebind the names of the batch in the caller's namespace: no stand-in on later calls
            for key, value in list(self._namespace.items()):
                if isinstance(value, _LazyFunction) and value in self._batch:
                    self._namespace[key] = value._function
        return self._function

    def __call__(self, *args, **kwargs):
        return self._load()(*args, **kwargs)

    def __repr__(self):
        return f"<function {self._module}.{self._name}, imported on first call>"


def lazy_functions(namespace, module, *names):
    """Stand-ins for ``module.<name>`` for each name, imported on the first call of any.

    Parameters
    ----------
    namespace : dict
        The ``globals()`` of the calling module, where the first call rebinds every name
        bound to one of these stand-ins to the real function.
    module : str
        Dotted name of the module to import.
    *names : str
        Names of functions in ``module``.

    Returns
    -------
    tuple
        One callable stand-in per name, in order.

    Examples
    --------
    >>> ns = {}
    >>> ns["floor"], ns["ceil"] = lazy_functions(ns, "math", "floor", "ceil")
    >>> ns["floor"](2.5), ns["ceil"]
    (2, <built-in function ceil>)
    """
    batch = []
    batch.extend(_LazyFunction(namespace, module, name, batch) for name in names)
    return tuple(batch)


class _LazyPackage:
    """Stand-in for package ``name``: ``.sub`` imports ``name.sub`` on first access."""

    def __init__(self, name):
        self._name = name

    def __getattr__(self, attr):  # only called until the attribute is cached below
        if attr.startswith("__"):
            raise AttributeError(attr)
        value = importlib.import_module(f"{self._name}.{attr}")
        setattr(self, attr, value)
        return value

    def __repr__(self):
        return f"<package {self._name!r}, subpackages imported on first access>"


def lazy_package(name):
    """Stand-in for package ``name`` whose subpackages are imported on first access.

    Parameters
    ----------
    name : str
        Dotted name of a package (``"scipy"``); attributes of the stand-in are its
        subpackages only (``scipy.linalg``), each imported when first read.

    Returns
    -------
    object
        The stand-in, to bind under the package's usual name.

    Examples
    --------
    >>> xml = lazy_package("xml")
    >>> xml.dom.__name__
    'xml.dom'
    """
    return _LazyPackage(name)
