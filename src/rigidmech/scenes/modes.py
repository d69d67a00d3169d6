"""Natural modes of a scene about its equilibrium q = 0: ``python -m rigidmech modes NAME``
(book, ch. 21.3, 25.4, 27.5.2).

:func:`scene_modes` builds a scene of the catalogue, checks that q = 0, q' = 0 is an
equilibrium of its equations of motion (f(0, 0) = 0 for the scene's parameter values),
linearises them there with :func:`rigidmech.vibrations.linearize` (M and K kept symbolic in
the parameters) and computes the natural frequencies and mode shapes with the parameter values
(:func:`rigidmech.vibrations.natural_modes`). The result is an immutable :class:`SceneModes`
whose :meth:`~SceneModes.summary` is what the command line prints.

A scene is refused with a :class:`~rigidmech._core.errors.SceneError` when q = 0 is not an
equilibrium (f(0, 0) not zero or not finite), when its equations depend on the time
explicitly (a moving reference: no fixed equilibrium), or when the equilibrium is unstable (K
not positive semi-definite: no natural modes).
"""

from __future__ import annotations

import math
from types import MappingProxyType

import numpy as np
import sympy as sp

from .._core.errors import RigidmechError, SceneError
from ..vectors import t as _time
from ..vibrations import linearize, natural_modes
from .catalogue import Scene, get

__all__ = ["SceneModes", "scene_modes"]


class SceneModes:
    """The natural modes of a scene about q = 0 (ch. 25.4, 27.5.2).

    Attributes
    ----------
    scene : Scene
    parameters : mapping str -> float
        The parameter values used for the frequencies.
    linear : rigidmech.vibrations.LinearSystem
        M, C, K symbolic in the parameters.
    frequencies : ndarray (n,)
        Natural angular frequencies, rad/s, increasing (0 for a free coordinate).
    shapes : ndarray (n, n)
        Mode shapes as columns, scaled so that their largest component is 1.

    Examples
    --------
    >>> sm = scene_modes("spring-mass", params={"k": 9.0})
    >>> sm.frequencies.tolist()
    [3.0]
    """

    __slots__ = ("scene", "parameters", "linear", "frequencies", "shapes")

    def __init__(self, scene, parameters, linear, frequencies, shapes):
        object.__setattr__(self, "scene", scene)
        object.__setattr__(self, "parameters", MappingProxyType(dict(parameters)))
        object.__setattr__(self, "linear", linear)
        object.__setattr__(self, "frequencies", frequencies)
        object.__setattr__(self, "shapes", shapes)

    def __setattr__(self, name, value):
        raise AttributeError(f"SceneModes is immutable: cannot set `{name}`.")

    def summary(self) -> str:
        """The report printed by ``python -m rigidmech modes``.

        Examples
        --------
        >>> print(scene_modes("simple-pendulum").summary())      # doctest: +ELLIPSIS
        Compound pendulum: a uniform rod on a pivot (simple-pendulum, book ch. 22.2.1)
        parameters: m=1, L=1, g=9.81
        equilibrium: theta = 0, with q' = 0
        linearised equations M q'' + C q' + K q = 0 about it:
          M = [[L**2*m/3]]
          C = 0
          K = [[L*g*m/2]]
        natural frequencies and mode shapes (columns, largest component 1):
          mode 1: omega = 3.83601 rad/s (f = 0.610521 Hz, period 1.63795 s); theta: 1
        """
        sc, lin = self.scene, self.linear
        names = list(lin.about)
        lines = [f"{sc.title} ({sc.name}, book {sc.section})",
                 "parameters: " + ", ".join(f"{k}={v:g}" for k, v in self.parameters.items()),
                 "equilibrium: " + ", ".join(f"{n} = 0" for n in names) + ", with q' = 0",
                 "linearised equations M q'' + C q' + K q = 0 about it:",
                 f"  M = {sp.sstr(lin.M.tolist())}",
                 f"  C = {'0' if lin.C.is_zero_matrix else sp.sstr(lin.C.tolist())}",
                 f"  K = {sp.sstr(lin.K.tolist())}"]
        if not lin.C.is_zero_matrix:
            lines.append("  (the damping C is left out of the natural modes)")
        lines.append("natural frequencies and mode shapes (columns, largest component 1):")
        for r, w in enumerate(self.frequencies):
            shape = ", ".join(f"{n}: {self.shapes[i, r]:.6g}" for i, n in enumerate(names))
            if w > 0:
                head = (f"omega = {w:.6g} rad/s (f = {w / (2 * math.pi):.6g} Hz, period "
                        f"{2 * math.pi / w:.6g} s)")
            else:
                head = "omega = 0 (a free motion, no restoring stiffness)"
            lines.append(f"  mode {r + 1}: {head}; {shape}")
        return "\n".join(lines)

    def __str__(self):
        return self.summary()

    def __repr__(self):
        return (f"SceneModes({self.scene.name!r}, frequencies="
                f"{np.round(self.frequencies, 6).tolist()})")


def _finite_number(x):
    try:
        value = complex(x)
    except (TypeError, ValueError):
        return None
    return value if math.isfinite(value.real) and math.isfinite(value.imag) else None


def scene_modes(scene, *, params=None) -> SceneModes:
    """Linearise a scene about q = 0 and compute its natural modes (ch. 25.4, 27.5.2).

    Parameters
    ----------
    scene : Scene or str
        A scene of the catalogue or its name.
    params : mapping str -> float, optional
        Overrides of the scene's parameter values, as for :func:`rigidmech.scenes.run`.

    Returns
    -------
    SceneModes

    Raises
    ------
    SceneError
        Unknown scene or parameter, a non-finite value, a value <= 0 for a positive constant;
        a scene whose equations have no equilibrium at q = 0 (f(0, 0) not zero), depend on
        the time explicitly, or whose equilibrium at q = 0 is unstable.

    Examples
    --------
    Two uniform rods of length L (ch. 25.4.3): ω² = (g/L)(3 ∓ 6/√7)

    >>> sm = scene_modes("double-pendulum")
    >>> sm.frequencies.round(4).tolist()
    [2.6801, 7.1887]
    >>> scene_modes("double-pendulum", params={"L": -1})
    Traceback (most recent call last):
    ...
    rigidmech._core.errors.SceneError: parameter `L` must be > 0 ...
    """
    scene = get(scene)
    if not isinstance(scene, Scene):  # pragma: no cover - get() guarantees it
        raise SceneError(f"`scene` must be a Scene or a name; got {scene!r}.")
    values = scene.defaults
    for name, value in dict(params or {}).items():
        if name not in values:
            raise SceneError(
                f"unknown parameter {name!r} for scene {scene.name!r}; its parameters are "
                f"{', '.join(values)}.")
        try:
            number = float(value)
        except (TypeError, ValueError):
            raise SceneError(f"parameter `{name}` must be a number; got {value!r}.") from None
        if not math.isfinite(number):
            raise SceneError(f"parameter `{name}` must be finite; got {value!r}.")
        values[name] = number
    eqs = scene.build().system.equations_of_motion()
    symbols = {str(s): s for s in eqs.parameters}
    for name, value in values.items():
        s = symbols.get(name)
        if s is not None and s.is_positive and not value > 0:
            raise SceneError(f"parameter `{name}` must be > 0 (the scene declares it "
                             f"positive); got {value:g}.")
    plain = {u: sp.Dummy() for u in eqs.u}
    plain |= {q: sp.Dummy() for q in eqs.q}
    M_plain = eqs.mass_matrix.subs(plain)
    f_plain = eqs.forcing.subs(plain)
    if M_plain.has(_time) or f_plain.has(_time):
        raise SceneError(
            f"scene {scene.name!r} has equations that depend on the time t explicitly (a "
            "moving reference or a prescribed motion): it has no fixed equilibrium at q = 0 "
            "to linearise about.")
    subs = {symbols[k]: v for k, v in values.items() if k in symbols}
    zero = {d: 0 for d in plain.values()}
    f0 = [_finite_number(e.xreplace(subs).xreplace(zero).evalf()) for e in f_plain]
    scale = max([abs(x) for x in f0 if x is not None] + [0.0])
    if any(x is None for x in f0) or scale > 1e-9:
        shown = ", ".join("not finite" if x is None else f"{x.real:.6g}" for x in f0)
        raise SceneError(
            f"scene {scene.name!r} has no equilibrium at q = 0 (q' = 0): there f(0, 0) = "
            f"[{shown}] (its coordinates are {', '.join(scene.coordinates)}); `modes` "
            "linearises about q = 0 only.")
    try:
        lin = linearize(eqs, about=[0] * scene.dof)
        M, _, K, _ = lin.numeric(**values)
        modes = natural_modes(M, K)
    except RigidmechError as exc:
        raise SceneError(f"scene {scene.name!r}: no natural modes about q = 0: "
                         f"{exc}") from None
    shapes = np.array(modes.shapes, dtype=float)
    shapes = shapes / shapes[np.argmax(np.abs(shapes), axis=0), np.arange(shapes.shape[1])]
    used = {k: v for k, v in values.items()}
    return SceneModes(scene, used, lin, np.asarray(modes.frequencies, dtype=float), shapes)
