"""Free-body diagrams along a motion (book, ch. 18.2) and the errors of bad input.

The compound pendulum of the catalogue (a rod of mass m, length L on a pivot at O, gravity
g R0.i): along its motion the pivot's action, from the fundamental principle, is the one
Simulation.connection_action gives at each sample, and the arrows of all the instants are
drawn to one scale.
"""

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
import pytest
from matplotlib.animation import FuncAnimation

import rigidmech as rm
from rigidmech import models
from rigidmech.actions import ContactLaws, Force
from rigidmech.drawing import free_body_diagram, free_body_motion
from rigidmech.drawing.fbd import NEGLIGIBLE
from rigidmech.errors import ArgumentError, ArgumentTypeError

PARAMS = {"m": 1.0, "L": 1.0, "g": 9.81}


@pytest.fixture(autouse=True)
def _close():
    yield
    plt.close("all")


@pytest.fixture(scope="module")
def swing():
    pend = models.compound_pendulum()
    sim = pend.system.equations_of_motion().simulate(t=(0, 1), q0=[1.0], n_output=11,
                                                     **PARAMS)
    return pend, sim


def test_values_at_the_instants_are_the_simulations(swing):
    pend, sim = swing
    motion = free_body_motion(sim, pend.bodies[0], times=[0.0, 0.5, 1.0])
    assert motion.times.tolist() == [0.0, 0.5, 1.0]
    R0 = pend.frames[0]
    N = sim.connection_action(R0, pend.bodies[0], basis=R0)
    for k, acts in zip((0, 5, 10), motion.actions, strict=True):
        joint, weight = acts
        assert np.allclose(joint.force, [N["X"][k], N["Y"][k], N["Z"][k]], rtol=1e-12)
        assert [c.name for c in joint.components] == ["X_1", "Y_1", "Z_1", "L_1", "M_1"]
        assert joint.components[0].value == pytest.approx(N["X"][k], rel=1e-12)
        assert np.allclose(weight.force, [9.81, 0, 0])


def test_one_scale_for_the_whole_motion(swing):
    pend, sim = swing
    motion = free_body_motion(sim, pend.bodies[0], times=[0.0, 0.5, 1.0])
    biggest = max(np.linalg.norm(a.force) for acts in motion.actions for a in acts)
    fig = motion.plot()
    lengths = []
    for ax, acts in zip(fig.axes, motion.actions, strict=True):
        texts = [t.get_text() for t in ax.texts]
        assert any(t.startswith("X_1 = ") for t in texts)
        patches = [p for p in ax.patches if type(p).__name__ == "FancyArrowPatch"]
        assert len(patches) >= 2
        lengths.append(np.linalg.norm(acts[0].force) / motion.scale)
    assert motion.scale == pytest.approx(biggest / (0.45 * motion._length), rel=1e-12)
    # the same force would be the same length at every instant: lengths are force / scale
    assert np.allclose(lengths, [np.linalg.norm(a[0].force) / motion.scale
                                 for a in motion.actions])
    assert fig.axes[-1].texts[-1].get_text().startswith("force scale: ")


def test_frame_function_drives_an_animation(swing, tmp_path):
    pend, sim = swing
    motion = free_body_motion(sim, pend.bodies[0])
    assert len(motion.times) == 4
    fig, ax = plt.subplots()
    limits = []

    def frame(i):
        arts = motion.frame(ax, i)
        limits.append((ax.get_xlim(), ax.get_ylim()))
        return arts

    anim = FuncAnimation(fig, frame, frames=len(motion.times), blit=False)
    path = tmp_path / "fbd.gif"
    anim.save(path, writer="pillow", fps=4)
    assert path.stat().st_size > 0
    assert all(lim == limits[0] for lim in limits)        # fixed limits over the motion


def test_bad_times_and_instants(swing):
    pend, sim = swing
    with pytest.raises(ArgumentError, match=r"`times` must lie in the simulated span \[0, 1\]"):
        free_body_motion(sim, pend.bodies[0], times=[0.5, 2.0])
    with pytest.raises(ArgumentError, match="`times` must hold at least one instant"):
        free_body_motion(sim, pend.bodies[0], times=[])
    motion = free_body_motion(sim, pend.bodies[0], times=[0.0])
    with pytest.raises(ArgumentError, match=r"`instant` must be in \[0, 0\]"):
        motion.draw(3)
    with pytest.raises(ArgumentTypeError, match="`instant` must be an index"):
        motion.draw(0.5)
    with pytest.raises(ArgumentTypeError, match="`simulation` must be a Simulation"):
        free_body_motion("run", pend.bodies[0])


def box_on_floor():
    R0 = rm.Frame("R0")
    box = rm.Body("box", frame=R0)
    st = rm.statics.Statics(R0)
    st.connect(R0, box, ContactLaws(at=R0.origin, normal=R0.j), label="A")
    st.act(Force(on=box, vector=-10 * R0.j, at=R0.point("G", 0, 1, 0)))
    return st, box


def test_errors_name_the_argument():
    st, box = box_on_floor()
    other = rm.Body("other", frame=st.reference)
    with pytest.raises(ArgumentTypeError, match="`system` must be a System .or a Model., a "
                                                 "Mechanism or a Statics; got str"):
        free_body_diagram("system", box)
    with pytest.raises(ArgumentError, match=r"`bodies` must be bodies of the system \['box'\]"):
        free_body_diagram(st, other)
    with pytest.raises(ArgumentError, match="`bodies` must name at least one body"):
        free_body_diagram(st, [])
    with pytest.raises(ArgumentError, match="`dim` must be 2, 3 or None"):
        free_body_diagram(st, box, dim=4)
    with pytest.raises(ArgumentError, match="`scale` must be a finite number > 0"):
        free_body_diagram(st, box, scale=-1.0)
    with pytest.raises(ArgumentTypeError, match="`scale` must be a number"):
        free_body_diagram(st, box, scale="big")
    with pytest.raises(ArgumentError, match=r"`values`: 'X_A' is no unknown"):
        free_body_diagram(st, box, values={"X_A": 1.0})
    with pytest.raises(ArgumentTypeError, match="`equilibrium` must be an Equilibrium"):
        free_body_diagram(st, box, equilibrium={"N_A": 1.0})
    fig = plt.figure()
    with pytest.raises(ArgumentError, match="`ax` must be a 2D Axes"):
        free_body_diagram(st, box, ax=fig.add_subplot(projection="3d"))


def test_state_errors_name_the_argument():
    pend = models.compound_pendulum()
    with pytest.raises(ArgumentError, match=r"`q` must hold 1 values, one per coordinate"):
        free_body_diagram(pend.system, pend.bodies[0], q=[0.1, 0.2], params=PARAMS)
    with pytest.raises(ArgumentError, match=r"`q`: \['phi'\] name no coordinate"):
        free_body_diagram(pend.system, pend.bodies[0], q={"phi": 0.1}, params=PARAMS)
    with pytest.raises(ArgumentError, match="`params` must give"):
        free_body_diagram(pend.system, pend.bodies[0], q=[0.1], params={"m": 1.0})


@pytest.mark.parametrize(("factor", "drawn"), [(0.5, False), (1.0, False), (2.0, True)])
def test_noise_sized_moments_are_not_drawn(factor, drawn):
    """A moment at most NEGLIGIBLE * scale * length^2 is rounding noise: no couple."""
    st, box = box_on_floor()
    R0 = st.reference
    eq = st.solve()
    d0 = free_body_diagram(st, box, equilibrium=eq)
    moment = factor * NEGLIGIBLE * d0.scale * 1.0**2        # the diagram's length is 1
    st.act(rm.actions.Couple(on=box, moment=moment * R0.k))
    d = free_body_diagram(st, box, equilibrium=eq, scale=d0.scale)
    assert (len(d.couples) == 1) is drawn


@pytest.mark.parametrize(("given", "error", "match"), [
    ({"q": "abc"}, ArgumentTypeError, "`q` must be a sequence of numbers"),
    ({"q": [np.nan]}, ArgumentError, "`q` must be a finite real number; got nan"),
    ({"q": [1j]}, ArgumentError, "`q` must be a finite real number"),
    ({"q": [0.1], "u": "x"}, ArgumentTypeError, "`u` must be a sequence of numbers"),
    ({"q": [0.1], "params": [1, 2]}, ArgumentTypeError, "`params` must be a dict"),
    ({"q": [0.1], "params": {**PARAMS, "m": "x"}}, ArgumentError, r"`params\['m'\]` must be "
                                                                   "a number"),
    ({"q": [0.1], "params": {**PARAMS, "m": np.nan}}, ArgumentError,
     r"`params\['m'\]` must be a finite real number"),
    ({"q": [0.1], "t": "now"}, ArgumentTypeError, "`t` must be a number"),
    ({"q": [0.1], "values": {"X_1": np.nan}}, ArgumentError,
     r"`values\['X_1'\]` must be a finite real number"),
    ({"q": [0.1], "values": [1]}, ArgumentTypeError, "`values` must be a dict"),
    ({"q": [0.1], "ax": "ax"}, ArgumentTypeError, "`ax` must be a matplotlib Axes"),
])
def test_junk_gets_an_error_naming_the_argument(given, error, match):
    pend = models.compound_pendulum()
    with pytest.raises(error, match=match):
        free_body_diagram(pend.system, pend.bodies[0], **{"params": PARAMS, **given})
