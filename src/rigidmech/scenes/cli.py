"""The command line: ``python -m rigidmech run NAME`` and ``python -m rigidmech scenes``
(book, ch. 27).

``run`` prints the scene's title and book section, its equations of motion M(q) q'' = f,
integrates them, and prints the final state, the energy drift and the timings of each stage
(derive, compile, integrate, in ms, with the number of evaluations); ``--plot out.png`` writes a
figure (headless). ``scenes`` lists every scene ``run`` accepts (:func:`scene_names`, the one
list also shown by ``run --help`` and by the message for an unknown name). Without a NAME,
``run`` runs the default scene, ``double-pendulum``. The scenes with regime changes take the
same options but three, which they refuse with the reason (``--step``, ``--max-steps``,
``--pretty``); their ``--method`` must be adaptive.

Every option and the ``--plot`` path are checked before the run. Misuse (unknown scene,
parameter or method, malformed value, a non-positive value for a positive constant, wrong number
of initial values, a plot path in a missing folder or with an unknown extension) prints one line
``rigidmech: error: ...`` on stderr and exits with status 2; a failed integration prints one line
and exits with status 1 (after writing the ``--plot`` and ``--save`` outputs of the motion up to
the failure); Ctrl-C during the integration ends it with the samples computed so far, writes
the outputs, prints ``rigidmech: interrupted at t = ...`` and exits with status 130 (at any
other moment: ``rigidmech: interrupted``, status 130). Any other failure prints one line too;
``--debug`` shows its traceback instead. ``--save PATH`` writes the samples (``.npz`` or
``.csv``), ``--samples N`` sets their number, ``--max-steps N`` bounds the solver's steps,
``--progress/--no-progress`` shows or hides a progress bar on stderr (default: shown on a
terminal for runs longer than 2 s). ``--animate out.gif`` writes an animation of the bodies
moving (:func:`rigidmech.drawing.animate`, 60 images); the scenes with regime changes and the
bicycle (a linear analysis) cannot be drawn and are refused before the run.

``python -m rigidmech modes NAME`` (default ``double-pendulum``) linearises a scene about its
equilibrium q = 0 and prints M, K and the natural frequencies and mode shapes
(:func:`rigidmech.scenes.modes.scene_modes`); ``--param`` overrides as for ``run``. A scene
with no equilibrium at q = 0 is refused with one line (status 2).
"""

from __future__ import annotations

import argparse
import os
import re
import sys

from .. import ode
from .._core.errors import NumericalError, RigidmechError, SceneError
from .._core.version import __version__
from .bicycle_scene import BICYCLE_SCENE, run_bicycle
from .catalogue import catalogue, get, names
from .pipeline import check_plot_path, check_save_path, run
from .regime_scenes import regime_methods, regime_scene_names, regime_scenes, run_regime_scene

__all__ = ["main", "DEFAULT_SCENE", "scene_names", "COMMANDS"]

#: The scene ``python -m rigidmech run`` runs when no NAME is given.
DEFAULT_SCENE = "double-pendulum"


#: Number of images of ``run --animate``.
ANIMATION_FRAMES = 60

#: The commands, in the order of the usage line.
COMMANDS = ("run", "scenes", "modes")


def _all_scenes() -> tuple:
    """Every scene the command line runs, in listing order: the catalogue, then the scenes
    with regime changes. The one source of every listing (``scenes``, ``run --help``, the
    message for an unknown name)."""
    return catalogue() + regime_scenes() + (BICYCLE_SCENE,)


def scene_names() -> tuple:
    """The names of every scene ``python -m rigidmech run`` accepts, in listing order.

    Examples
    --------
    >>> names = scene_names()
    >>> names[0], "coulomb-oscillator" in names, len(names) == len(set(names))
    ('simple-pendulum', True, True)
    """
    return tuple(s.name for s in _all_scenes())


def _check_name(name):
    if name not in scene_names():
        raise SceneError(f"unknown scene {name!r}; known scenes: {', '.join(scene_names())} "
                         "(list them with `python -m rigidmech scenes`).")


class _UsageError(Exception):
    """Raised instead of argparse's print-usage-and-exit, to print one line."""


class _Parser(argparse.ArgumentParser):
    def error(self, message):
        raise _UsageError(message)


def _param(text):
    name, sep, value = text.partition("=")
    name = name.strip()
    if not sep or not name.isidentifier():
        raise argparse.ArgumentTypeError(
            f"expected NAME=VALUE (e.g. --param m=2); got {text!r}")
    try:
        number = float(value)
    except ValueError:
        raise argparse.ArgumentTypeError(
            f"the value of {name} must be a number; got {value!r}") from None
    return name, number


def _positive_int(text):
    try:
        value = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected a whole number >= 1; got {text!r}") from None
    if value < 1:
        raise argparse.ArgumentTypeError(f"expected a whole number >= 1; got {text!r}")
    return value


def _floats(text):
    try:
        return tuple(float(x) for x in text.split(","))
    except ValueError:
        raise argparse.ArgumentTypeError(
            f"expected comma-separated numbers such as 2.0,-0.2; got {text!r}") from None


def _join_negative_values(argv):
    """``--q0 -0.5,0.2`` -> ``--q0=-0.5,0.2``: argparse would take ``-0.5,0.2`` for an
    option."""
    out, i = [], 0
    while i < len(argv):
        a = argv[i]
        if (a in ("--q0", "--u0") and i + 1 < len(argv)
                and re.match(r"-[\d.]", argv[i + 1])):
            out.append(f"{a}={argv[i + 1]}")
            i += 2
        else:
            out.append(a)
            i += 1
    return out


def _parser():
    p = _Parser(prog="rigidmech", description="Mechanics of rigid bodies after J.-M. "
                "Berthelot's textbook: run the book's systems from the command line.")
    p.add_argument("--version", action="version", version=f"rigidmech {__version__}")
    sub = p.add_subparsers(dest="command", metavar="{" + ",".join(COMMANDS) + "}")
    sub.required = True
    r = sub.add_parser("run", help="derive, integrate and report a scene",
                       description="Derive the equations of motion of a scene, integrate them "
                       "and report the energy drift and the timings.")
    r.add_argument("name", nargs="?", default=DEFAULT_SCENE, metavar="NAME",
                   help=f"scene name (default {DEFAULT_SCENE}); one of {', '.join(scene_names())}")
    r.add_argument("--t-end", type=float, metavar="T", help="duration in seconds")
    r.add_argument("--method", metavar="M",
                   help=f"integration method, one of {', '.join(ode.methods())} (the scenes "
                   f"with regime changes: an adaptive one, {', '.join(regime_methods())})")
    r.add_argument("--rtol", type=float, metavar="R", help="relative tolerance")
    r.add_argument("--atol", type=float, metavar="A", help="absolute tolerance")
    r.add_argument("--step", type=float, metavar="H", help="step of a fixed-step method")
    r.add_argument("--param", type=_param, action="append", default=[], metavar="NAME=VALUE",
                   help="override a parameter, e.g. --param m=2 (repeatable)")
    r.add_argument("--q0", type=_floats, metavar="Q",
                   help="initial coordinates, comma-separated, e.g. --q0 2.0,-0.2")
    r.add_argument("--u0", type=_floats, metavar="U",
                   help="initial velocities q', comma-separated")
    r.add_argument("--plot", metavar="PATH", help="write a figure there (PNG, PDF, SVG...)")
    r.add_argument("--animate", metavar="PATH",
                   help="write an animation of the bodies moving there (GIF, through pillow)")
    r.add_argument("--save", metavar="PATH",
                   help="save the samples there (.npz or .csv, columns t, q, q')")
    r.add_argument("--samples", type=_positive_int, default=None, metavar="N",
                   help="number of evenly spaced output times (default 1001, at least 2)")
    r.add_argument("--max-steps", type=_positive_int, metavar="N",
                   help="largest number of solver steps (default 1000000)")
    r.add_argument("--progress", action=argparse.BooleanOptionalAction, default=None,
                   help="show a progress bar on runs longer than 2 s (default: only when "
                   "stderr is a terminal)")
    r.add_argument("--pretty", action="store_true",
                   help="print the equations with sympy's 2-D pretty printer")
    r.add_argument("--debug", action="store_true",
                   help="show the traceback of an unexpected failure")
    sub.add_parser("scenes", help="list the catalogue of ready-made systems",
                   description="List the catalogue of ready-made systems.")
    md = sub.add_parser("modes", help="natural frequencies and mode shapes about q = 0",
                        description="Linearise a scene about its equilibrium q = 0 and print "
                        "M, K and its natural frequencies and mode shapes.")
    md.add_argument("name", nargs="?", default=DEFAULT_SCENE, metavar="NAME",
                    help=f"scene name (default {DEFAULT_SCENE}); one of {', '.join(names())} "
                    "(the scenes with regime changes have no single linearisation)")
    md.add_argument("--param", type=_param, action="append", default=[], metavar="NAME=VALUE",
                    help="override a parameter, e.g. --param m=2 (repeatable)")
    md.add_argument("--debug", action="store_true",
                    help="show the traceback of an unexpected failure")
    return p


def _list_scenes(out):
    rows = [("name", "title", "book", "dof", "parameters")]
    for s in _all_scenes():
        params = " ".join(f"{n}={v:g}" for n, v in s.defaults.items())
        dof = s.dof if hasattr(s, "dof") else len(s.state)
        rows.append((s.name, s.title, s.section, str(dof), params))
    widths = [max(len(r[i]) for r in rows) for i in range(4)]
    for r in rows:
        print("  ".join(c.ljust(w) for c, w in zip(r[:4], widths, strict=True)) + "  " + r[4],
              file=out)


def _run(args, out):
    if args.plot is not None:
        check_plot_path(args.plot, "--plot")
    if args.save is not None:
        check_save_path(args.save, "--save")
    _check_name(args.name)  # unknown scene: fail before anything else
    if args.animate is not None:
        _check_animation(args.name, args.animate)
    if args.name == BICYCLE_SCENE.name:  # a linear analysis: no integration
        _run_bicycle(args, out)
        return
    if args.samples is None:
        args.samples = 1001
    if args.samples < 2:
        raise _UsageError(f"argument --samples: expected at least 2; got {args.samples}")
    if args.name in regime_scene_names():  # motions with regime changes print their phases
        _run_regimes(args, out)
        return
    get(args.name)
    params = {}
    for name, value in args.param:
        if name in params:
            raise SceneError(f"--param {name} given twice.")
        params[name] = value
    report = run(args.name, t_end=args.t_end, params=params, q0=args.q0, u0=args.u0,
                 method=args.method, rtol=args.rtol, atol=args.atol, step=args.step,
                 plot=args.plot, save=args.save, max_steps=args.max_steps,
                 progress=args.progress, n_output=args.samples, dense_output=False)
    print(report.summary(pretty=args.pretty), file=out)
    sim = report.simulation
    if args.animate is not None and sim.t.size > 0:
        _write_animation(sim, args.animate)
        print(f"animation: {args.animate}", file=out)
    if report.status == "interrupted":
        stop = sim.t.size > 1 and sim.t[-1] == sim.t_stop   # the state reached, kept
        raise _Interrupted(f"interrupted at t = {sim.t_stop:g} (the samples up to t = "
                           f"{sim.t[-2 if stop else -1]:g}"
                           f"{' and the state reached there' if stop else ''} are kept"
                           f"{_outputs(report)})")
    if report.status == "failed":
        raise NumericalError(report.message.rstrip(".")
                             + _outputs(report, "; partial output in "))


def _check_animation(name, path):
    """Refuse, before the run, an animation of a scene that cannot be drawn or a path that
    cannot be written."""
    if name == BICYCLE_SCENE.name or name in regime_scene_names():
        drawable = ", ".join(names())
        why = ("a linear analysis, with no motion to draw" if name == BICYCLE_SCENE.name
               else "a motion with regime changes, whose phases are not one system to draw")
        raise SceneError(f"--animate: scene {name!r} cannot be drawn ({why}); the scenes "
                         f"that can: {drawable}.")
    if not str(path).lower().endswith(".gif"):
        raise _UsageError(f"argument --animate: expected a path ending with .gif; got {path!r}")
    folder = os.path.dirname(os.path.abspath(path))
    if not os.path.isdir(folder):
        raise _UsageError(f"argument --animate: the folder {folder} does not exist")


def _write_animation(sim, path):
    # imported here, like the pipeline's plots: matplotlib's pyplot only when asked
    import matplotlib.pyplot as plt

    from ..drawing import animate

    anim = animate(sim, n_frames=ANIMATION_FRAMES, path=path)
    plt.close(anim._fig)


def _outputs(report, lead=", in "):
    paths = [p for p in (report.plot_path, report.save_path) if p is not None]
    return f"{lead}{' and '.join(paths)}" if paths else ""


class _Interrupted(Exception):
    """The run was interrupted; the partial outputs are written."""


#: Run options that do not apply to a scene with regime changes, and why.
_NOT_FOR_REGIMES = {
    "step": "its switches of regime are located by the events of an adaptive method, which "
            "chooses its steps",
    "max_steps": "it is integrated phase by phase, each phase by an adaptive method with its "
                 "own bound",
    "pretty": "each regime has its own equations; the summary prints the phases",
}


#: The run options of an integration, which the benchmark bicycle (a linear analysis) has not.
_INTEGRATION_OPTIONS = ("t_end", "method", "rtol", "atol", "step", "q0", "u0", "plot", "save",
                        "samples", "max_steps", "progress", "pretty")


def _run_bicycle(args, out):
    for option in _INTEGRATION_OPTIONS:
        if getattr(args, option) not in (None, False):
            raise SceneError(f"--{option.replace('_', '-')} is not an option of the scene "
                             f"{args.name!r}: it is a linear analysis about the straight "
                             "upright run (matrices and critical speeds), with no "
                             "integration; only --param applies.")
    print(run_bicycle(_params(args)).summary(), file=out)


def _params(args):
    params = {}
    for name, value in args.param:
        if name in params:
            raise SceneError(f"--param {name} given twice.")
        params[name] = value
    return params


def _run_regimes(args, out):
    for option, why in _NOT_FOR_REGIMES.items():
        if getattr(args, option) not in (None, False):
            raise SceneError(f"--{option.replace('_', '-')} is not an option of the regime "
                             f"scene {args.name!r}: {why}.")
    if args.method is not None and args.method not in regime_methods():
        raise SceneError(f"--method is not an option of the regime scene {args.name!r} with "
                         f"{args.method!r}: its switches of regime are located by the events "
                         f"of an adaptive method; one of {', '.join(regime_methods())}.")
    params = {}
    for name, value in args.param:
        if name in params:
            raise SceneError(f"--param {name} given twice.")
        params[name] = value
    report = run_regime_scene(args.name, t_end=args.t_end, params=params, q0=args.q0,
                              u0=args.u0, plot=args.plot, save=args.save, method=args.method,
                              rtol=args.rtol, atol=args.atol, n_output=args.samples,
                              progress=args.progress)
    print(report.summary(), file=out)


def _modes(args, out):
    from .modes import scene_modes  # imported on use: the vibrations layer

    _check_name(args.name)
    if args.name == BICYCLE_SCENE.name:
        raise SceneError(f"scene {args.name!r} is a linear analysis itself (its eigenvalues "
                         "against the speed): run it with `python -m rigidmech run "
                         f"{args.name}`.")
    if args.name in regime_scene_names():
        raise SceneError(f"scene {args.name!r} changes regime along its motion (phases "
                         "integrated one by one): it has no single set of equations to "
                         "linearise about q = 0.")
    params = {}
    for name, value in args.param:
        if name in params:
            raise SceneError(f"--param {name} given twice.")
        params[name] = value
    print(scene_modes(args.name, params=params).summary(), file=out)


def main(argv=None) -> int:
    """Run the command line with ``argv`` (default ``sys.argv[1:]``); return the exit status.

    Examples
    --------
    >>> main(["scenes"])                                  # doctest: +ELLIPSIS
    name  ...
    simple-pendulum  ...
    0
    """
    out, err = sys.stdout, sys.stderr
    argv = sys.argv[1:] if argv is None else list(argv)
    debug = "--debug" in argv
    try:
        args = _parser().parse_args(_join_negative_values(argv))
        if args.command == "scenes":
            _list_scenes(out)
        elif args.command == "modes":
            _modes(args, out)
        else:
            _run(args, out)
    except SystemExit as exc:  # --help, --version
        return exc.code if isinstance(exc.code, int) else 0
    except KeyboardInterrupt:
        print("rigidmech: interrupted", file=err)
        return 130
    except _Interrupted as exc:
        print(f"rigidmech: {exc}", file=err)
        return 130
    except _UsageError as exc:
        print(f"rigidmech: error: {exc}", file=err)
        return 2
    except NumericalError as exc:
        print(f"rigidmech: integration failed: {exc}", file=err)
        return 1
    except RigidmechError as exc:
        print(f"rigidmech: error: {exc}", file=err)
        return 2
    except Exception as exc:
        if debug:
            raise
        print(f"rigidmech: internal error: {type(exc).__name__}: {exc} (run again with "
              "--debug for the traceback)", file=err)
        return 1
    return 0
