"""Ready-made systems from the book, as immutable scene descriptions (book, ch. 21-27).

A :class:`Scene` names a system of the book, the chapter where the book studies it, its
parameters with default values, a default initial state, duration and integration method, and a
builder that assembles the :class:`~rigidmech.dynamics.System` the book's way (frames, bodies,
connections, actions). Building is cheap and symbolic; numbers come only when the scene is run
(:func:`rigidmech.scenes.run`).

Conventions shared by the catalogue: the Galilean reference is R0 = (O; i, j, k), the gravity
field is ``g * R0.i`` (``i`` points **down**), motions are planar in (i, j) and angles are
measured from the downward vertical ``i`` about ``k``.
"""

from __future__ import annotations

from typing import NamedTuple

from .. import inertia, models
from .._core.errors import SceneError
from ..actions import Pivot, Prismatic, Spring, gravity
from ..dynamics import System
from ..kinetics import Body
from ..vectors import Frame, constants, coordinates

__all__ = ["Scene", "Parameter", "Built", "get", "catalogue", "names"]


class Parameter(NamedTuple):
    """A constant of a scene: its symbol name, default value and meaning.

    Examples
    --------
    >>> from rigidmech import scenes
    >>> scenes.get("simple-pendulum").parameters[0].name
    'm'
    """

    name: str
    default: float
    meaning: str


class Built(NamedTuple):
    """What a scene's builder returns: the system and its bodies (in connection order).

    Examples
    --------
    >>> from rigidmech import scenes
    >>> built = scenes.get("double-pendulum").build()
    >>> [b.name for b in built.bodies]
    ['bar1', 'bar2']
    """

    system: System
    bodies: tuple


class Scene:
    """An immutable description of a ready-made system of the book.

    Parameters
    ----------
    name : str
        Identifier used on the command line (``"double-pendulum"``).
    title : str
        One-line human title.
    section : str
        Where the book studies the system (``"ch. 22.2.1"``).
    coordinates : tuple of str
        Names of the parameters of situation, in the order of the equations.
    parameters : tuple of Parameter
        Constants with their default values.
    q0, u0 : tuple of float
        Default initial state (u0 = q0' defaults to zeros).
    t_end : float
        Default duration, seconds.
    method, rtol, atol
        Default integration method and tolerances (see :func:`rigidmech.ode.solve`).
    builder : callable
        ``builder() -> Built``: assembles the system in symbol form.
    notes : str
        Conventions worth knowing (which angles, which axis points down).
    units : dict, optional
        Units of coordinates by name, for the plots and the saved columns (the angles of
        rotation of the bodies' frames are in rad without saying so).
    time_unit : str
        Unit of time of the plots (default ``"s"``).

    Examples
    --------
    >>> from rigidmech import scenes
    >>> sc = scenes.get("simple-pendulum")
    >>> sc.section, sc.dof, sc.defaults
    ('ch. 22.2.1', 1, {'m': 1.0, 'L': 1.0, 'g': 9.81})
    >>> sc.build().system.equations_of_motion().mass_matrix
    Matrix([[L**2*m/3]])
    """

    __slots__ = ("_name", "_title", "_section", "_coordinates", "_parameters", "_q0", "_u0",
                 "_t_end", "_method", "_rtol", "_atol", "_builder", "_notes", "_units",
                 "_time_unit")

    def __init__(self, name, title, section, *, coordinates, parameters, q0, builder,
                 u0=None, t_end=10.0, method="dop853", rtol=1e-10, atol=1e-12, notes="",
                 units=None, time_unit="s"):
        self._name, self._title, self._section = str(name), str(title), str(section)
        self._coordinates = tuple(coordinates)
        self._parameters = tuple(Parameter(*p) for p in parameters)
        n = len(self._coordinates)
        self._q0 = tuple(float(x) for x in q0)
        self._u0 = tuple(float(x) for x in (u0 if u0 is not None else [0.0] * n))
        if len(self._q0) != n or len(self._u0) != n:
            raise SceneError(
                f"scene {name!r}: `q0` and `u0` must give {n} values (one per coordinate "
                f"{list(self._coordinates)}); got {len(self._q0)} and {len(self._u0)}.")
        self._t_end, self._method = float(t_end), str(method)
        self._rtol, self._atol = float(rtol), float(atol)
        self._builder, self._notes = builder, str(notes)
        self._units, self._time_unit = dict(units or {}), str(time_unit)
        unknown = sorted(set(self._units) - set(self._coordinates))
        if unknown:
            raise SceneError(f"scene {name!r}: `units` names {unknown}, which is not a "
                             f"coordinate; the coordinates are {list(self._coordinates)}.")

    name = property(lambda self: self._name, doc="Identifier (command-line name).")
    title = property(lambda self: self._title, doc="One-line title.")
    section = property(lambda self: self._section, doc="Section of the book.")
    coordinates = property(lambda self: self._coordinates,
                           doc="Names of the parameters of situation.")
    parameters = property(lambda self: self._parameters, doc="Constants and their defaults.")
    q0 = property(lambda self: self._q0, doc="Default initial q.")
    u0 = property(lambda self: self._u0, doc="Default initial q'.")
    t_end = property(lambda self: self._t_end, doc="Default duration.")
    method = property(lambda self: self._method, doc="Default integration method.")
    rtol = property(lambda self: self._rtol, doc="Default relative tolerance.")
    atol = property(lambda self: self._atol, doc="Default absolute tolerance.")
    notes = property(lambda self: self._notes, doc="Conventions of the scene.")

    time_unit = property(lambda self: self._time_unit, doc="Unit of time of the plots.")

    @property
    def units(self) -> dict:
        """Units of coordinates by name (a fresh dict), e.g. ``{"x": "m"}``."""
        return dict(self._units)

    @property
    def dof(self) -> int:
        """Number of degrees of freedom (parameters of situation)."""
        return len(self._coordinates)

    @property
    def defaults(self) -> dict:
        """Default parameter values, a fresh dict ``{name: value}``."""
        return {p.name: float(p.default) for p in self._parameters}

    def build(self) -> Built:
        """Assemble the system in symbol form (frames, bodies, connections, actions)."""
        return self._builder()

    def __eq__(self, other):
        return isinstance(other, Scene) and other._name == self._name

    def __hash__(self):
        return hash(("Scene", self._name))

    def __repr__(self):
        return f"Scene({self._name!r}, title={self._title!r}, section={self._section!r})"


# -- builders ------------------------------------------------------------------------------
def _rod_on_pivot(name, frame, at, m, L):
    """A uniform rod of length L hanging from ``at`` along ``frame.i``."""
    G = at.moved("G" + name[-1] if name[-1].isdigit() else "G", L / 2 * frame.i)
    return Body(name, frame=frame, mass=m, centre=G,
                inertia=inertia.rod(m, L, axis=frame.i, centre=G))


def _simple_pendulum() -> Built:
    model = models.compound_pendulum()
    return Built(model.system, model.bodies)


def _double_pendulum() -> Built:
    model = models.double_pendulum()
    return Built(model.system, model.bodies)


def _slider_pendulum() -> Built:
    x, theta = coordinates("x theta")
    M, m, L, g = constants("M m L g", positive=True)
    R0 = Frame("R0")
    P = R0.point("P", 0, x, 0)                        # the block slides along the horizontal j
    Rb = R0.translated("Rb", P)
    R1 = Rb.rotated("R1", about=R0.k, angle=theta)
    block = Body("block", frame=Rb, mass=M, centre=P)
    rod = _rod_on_pivot("rod", R1, P, m, L)
    system = System(galilean=R0)
    system.connect(R0, block, Prismatic(at=P, axis=R0.j))
    system.connect(block, rod, Pivot(at=P, axis=R0.k))
    system.act(gravity(g * R0.i))
    return Built(system, (block, rod))


def _spring_mass() -> Built:
    x = coordinates("x")
    m, k, l0 = constants("m k l0", positive=True)
    R0 = Frame("R0")
    P = R0.point("P", l0 + x, 0, 0)                   # x: elongation of the spring
    Rb = R0.translated("Rb", P)
    mass = Body("mass", frame=Rb, mass=m, centre=P)
    system = System(galilean=R0)
    system.connect(R0, mass, Prismatic(at=P, axis=R0.i))
    system.act(Spring(k, l0, a=R0.origin, b=P, on_b=mass))
    return Built(system, (mass,))


_SCENES = (
    Scene("simple-pendulum", "Compound pendulum: a uniform rod on a pivot", "ch. 22.2.1",
          coordinates=("theta",),
          parameters=(("m", 1.0, "mass of the rod"), ("L", 1.0, "length of the rod"),
                      ("g", 9.81, "gravity")),
          q0=(1.0,), t_end=10.0, builder=_simple_pendulum,
          notes="theta: angle of the rod from the downward vertical."),
    Scene("double-pendulum", "Double pendulum of two uniform rods", "ch. 25.4.3, 27.5",
          coordinates=("theta1", "theta2"),
          parameters=(("m", 1.0, "mass of each rod"), ("L", 1.0, "length of each rod"),
                      ("g", 9.81, "gravity")),
          q0=(2.0, -0.2), t_end=10.0, builder=_double_pendulum,
          notes="theta1, theta2: absolute angles of the rods from the downward vertical "
                "(the book also uses the relative angle theta2 - theta1)."),
    Scene("slider-pendulum", "A rod pendulum hanging from a block on a frictionless slide",
          "ch. 24.3",
          coordinates=("x", "theta"),
          parameters=(("M", 2.0, "mass of the block"), ("m", 1.0, "mass of the rod"),
                      ("L", 1.0, "length of the rod"), ("g", 9.81, "gravity")),
          q0=(0.0, 1.0), t_end=10.0, builder=_slider_pendulum, units={"x": "m"},
          notes="x: position of the block along the horizontal j; theta: angle of the rod "
                "from the downward vertical."),
    Scene("spring-mass", "One-degree-of-freedom vibration: a mass on a spring", "ch. 21.2.2",
          coordinates=("x",),
          parameters=(("m", 1.0, "mass"), ("k", 4.0, "stiffness of the spring"),
                      ("l0", 1.0, "free length of the spring")),
          q0=(0.5,), t_end=10.0, builder=_spring_mass, units={"x": "m"},
          notes="x: elongation of the spring (x > -l0); free vibration at sqrt(k/m)."),
)
_BY_NAME = {s.name: s for s in _SCENES}


def names() -> tuple:
    """Names of the scenes of the catalogue, in catalogue order.

    Examples
    --------
    >>> names()                                        # doctest: +NORMALIZE_WHITESPACE
    ('simple-pendulum', 'double-pendulum', 'slider-pendulum', 'spring-mass', 'satellite',
     'moon-probe', 'foucault-pendulum', 'wagon-pendulum', 'block-on-incline', 'cart-pendulum',
     'triple-pendulum', 'four-bar', 'slider-crank', 'wheel-on-incline', 'heavy-top',
     'gyroscope')
    """
    return tuple(_BY_NAME)


def catalogue() -> tuple:
    """All the scenes of the catalogue.

    Examples
    --------
    >>> [s.dof for s in catalogue()]
    [1, 2, 2, 1, 2, 2, 2, 1, 1, 2, 3, 3, 3, 2, 3, 3]
    """
    return _SCENES


def get(name) -> Scene:
    """The scene called ``name`` (a Scene passes through).

    Raises
    ------
    SceneError
        If no scene has that name; the message lists the known names.

    Examples
    --------
    >>> get("double-pendulum").title
    'Double pendulum of two uniform rods'
    >>> get("quadruple-pendulum")
    Traceback (most recent call last):
    ...
    rigidmech._core.errors.SceneError: unknown scene 'quadruple-pendulum'; known scenes: ...
    """
    if isinstance(name, Scene):
        return name
    if not isinstance(name, str) or name not in _BY_NAME:
        raise SceneError(
            f"unknown scene {name!r}; known scenes: {', '.join(_BY_NAME)} "
            "(list them with `python -m rigidmech scenes`).")
    return _BY_NAME[name]


# -- the Earth and space (ch. 8, 19, 24, 27): appended to the catalogue ----------------------
from .space_scenes import SPACE_SCENES  # noqa: E402  (the module uses Scene and Built above)

_SCENES += SPACE_SCENES
_BY_NAME.update((s.name, s) for s in SPACE_SCENES)

# -- solids, machines and tops (ch. 20-25, 27), from rigidmech.models: appended too ---------
from .machine_scenes import MACHINE_SCENES  # noqa: E402  (the module uses Scene and Built)

_SCENES += MACHINE_SCENES
_BY_NAME.update((s.name, s) for s in MACHINE_SCENES)
