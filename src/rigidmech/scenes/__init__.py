"""Ready-made systems from the book, the run pipeline and the command line (book, ch. 27).

* :mod:`~rigidmech.scenes.catalogue`: immutable :class:`Scene` descriptions of systems the book
  studies (compound pendulum, double pendulum, pendulum on a slide, mass on a spring), each with
  its parameters, default state and a builder of the :class:`~rigidmech.dynamics.System`;
* :mod:`~rigidmech.scenes.pipeline`: :func:`run` derives, compiles and integrates a scene,
  follows its energy and times each stage (:class:`RunReport`);
* :mod:`~rigidmech.scenes.cli`: ``python -m rigidmech run NAME`` and ``python -m rigidmech
  scenes``.
* :mod:`~rigidmech.scenes.space_scenes`: a satellite, a probe between the Earth and the Moon,
  the Foucault pendulum (ch. 19, 24, 27), in the catalogue too;
* :mod:`~rigidmech.scenes.machine_scenes`: a block on an incline, a cart-pendulum, a triple
  pendulum, the four-bar, the slider-crank, a wheel on an incline, the heavy top, a gyroscope
  (ch. 20-25, 27), built from :mod:`rigidmech.models`, in the catalogue too;
* :mod:`~rigidmech.scenes.modes`: the natural modes of a scene about q = 0
  (``python -m rigidmech modes NAME``).

Examples
--------
>>> from rigidmech import scenes
>>> scenes.names()[:4]
('simple-pendulum', 'double-pendulum', 'slider-pendulum', 'spring-mass')
>>> rep = scenes.run("double-pendulum", t_end=0.5)
>>> rep.scene.section, rep.energy_drift < 1e-8
('ch. 25.4.3, 27.5', True)
"""

from .catalogue import Built, Parameter, Scene, catalogue, get, names
from .pipeline import RunReport, check_plot_path, equations_text, plot_simulation, run

__all__ = ["Scene", "Parameter", "Built", "catalogue", "get", "names", "RunReport", "run",
           "equations_text", "plot_simulation", "check_plot_path"]
from .pipeline import check_save_path  # noqa: E402

__all__ += ["check_save_path"]
from .modes import SceneModes, scene_modes  # noqa: E402

__all__ += ["SceneModes", "scene_modes"]
