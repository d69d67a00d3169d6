"""Sweeps over parameters and initial states (rigidmech.sweeps): a grid sweep equals single
calls, Dask equals in-process bit for bit for the same chunks, failures keep the finished
chunks, bad input is refused before anything is computed."""

import numpy as np
import pytest
import sympy as sp

import rigidmech as rm
from rigidmech import vibrations
from rigidmech.sweeps import WORKER_CONFIG, ClusterError, Labelled, grid, points, sweep


def two_mass_pendulum():
    """Point masses m1, m2 on massless rods of length l, absolute angles q1, q2 from the
    downward vertical (the classical closed form)."""
    q1, q2 = rm.coordinates("q1 q2")
    t = sp.Symbol("t")
    m1, m2, l, g = sp.symbols("m1 m2 l g", positive=True)
    c, s = sp.cos(q1 - q2), sp.sin(q1 - q2)
    M = sp.ImmutableMatrix([[(m1 + m2) * l**2, m2 * l**2 * c], [m2 * l**2 * c, m2 * l**2]])
    f = sp.ImmutableMatrix([
        -m2 * l**2 * s * q2.diff(t)**2 - (m1 + m2) * g * l * sp.sin(q1),
        m2 * l**2 * s * q1.diff(t)**2 - m2 * g * l * sp.sin(q2)])
    return rm.EquationsOfMotion(coordinates=(q1, q2), mass_matrix=M, forcing=f)


@pytest.fixture(scope="module")
def eqs():
    return two_mass_pendulum()


FIXED = {"m1": 1.0, "l": 1.0, "g": 9.81}


def test_grid_sweep_equals_single_simulate_calls(eqs):
    over = grid(m2=[0.5, 1.0, 2.0], q1=[0.2, 0.8])
    r = sweep(eqs, over, t=(0.0, 2.0), chunk_size=4, rtol=1e-10, atol=1e-12, **FIXED)
    assert r.complete and r.values.dims == ("m2", "q1", "state")
    for m2 in over.axes["m2"]:
        for q1 in over.axes["q1"]:
            sim = eqs.simulate(t=(0.0, 2.0), q0={"q1": q1}, n_output=2, rtol=1e-10,
                               atol=1e-12, progress=False, m2=m2, **FIXED)
            single = np.concatenate((sim.q[:, -1], sim.u[:, -1]))
            got = np.asarray(r.values.sel(m2=m2, q1=q1).values)
            np.testing.assert_allclose(got, single, rtol=0, atol=1e-7)


def test_samples_at_times_equal_single_calls_and_numpy_labels(eqs):
    times = np.linspace(0.0, 1.0, 5)
    over = points(m2=[1.0, 3.0], q2=[0.3, -0.4], q1_dot=[0.0, 1.0])
    r = sweep(eqs, over, quantity="samples", t=(0.0, 1.0), times=times, labels="numpy",
              rtol=1e-10, atol=1e-12, **FIXED)
    assert isinstance(r.values, Labelled)
    assert r.values.dims == ("point", "time", "state") and r.values.shape == (2, 5, 4)
    for k in range(2):
        sim = eqs.simulate(t=(0.0, 1.0), q0={"q2": over.columns["q2"][k]},
                           u0={"q1": over.columns["q1_dot"][k]}, t_eval=times, rtol=1e-10,
                           atol=1e-12, progress=False, m2=over.columns["m2"][k], **FIXED)
        np.testing.assert_allclose(r.values.values[k], np.vstack((sim.q, sim.u)).T, atol=1e-7)


def test_eigenvalue_sweep_equals_single_calls_and_closed_form():
    x, v, k, c, m = sp.symbols("x x_dot k c m")
    eqs = rm.EquationsOfMotion(coordinates=(x,), q=(x,), u=(v,),
                               mass_matrix=sp.ImmutableMatrix([[m]]),
                               forcing=sp.ImmutableMatrix([[-k * x - c * v]]))
    lin = vibrations.linearize(eqs)
    r = sweep(lin, grid(k=[1.0, 4.0, 9.0], c=[0.0, 0.5]), quantity="eigenvalues", m=1.0)
    assert r.values.dims == ("k", "c", "eigenvalue")
    for kk in (1.0, 4.0, 9.0):
        for cc in (0.0, 0.5):
            single = np.sort_complex(lin.eigenvalues(k=kk, c=cc, m=1.0))
            got = np.asarray(r.values.sel(k=kk, c=cc).values)
            np.testing.assert_array_equal(got, single)
            # closed form: -c/2 -+ i sqrt(k - c^2/4)
            w = np.sqrt(kk - cc**2 / 4)
            np.testing.assert_allclose(got, [-cc / 2 - 1j * w, -cc / 2 + 1j * w], atol=1e-12)


def test_a_failing_chunk_keeps_the_finished_ones(eqs):
    # m2 = 0 makes the mass matrix singular: that chunk fails, the other two finish
    over = points(m2=[1.0, 2.0, 0.0, 1.5, 0.5, 2.5], q1=[0.1] * 6)
    r = sweep(eqs, over, t=(0.0, 0.5), chunk_size=2, labels="numpy", **FIXED)
    assert not r.complete
    [fail] = r.failed
    assert (fail.index, fail.start, fail.stop) == (1, 2, 4)
    assert "SingularMassMatrixError" in fail.message or "singular" in fail.message
    vals = r.values.values
    assert np.all(np.isnan(vals[2:4])) and np.all(np.isfinite(vals[[0, 1, 4, 5]]))
    alone = sweep(eqs, points(m2=[1.0, 2.0], q1=[0.1, 0.1]), t=(0.0, 0.5), chunk_size=2,
                  labels="numpy", **FIXED)
    np.testing.assert_array_equal(vals[:2], alone.values.values)


def test_a_progress_callback_stops_and_keeps_the_chunks_done():
    seen = []

    def progress(done, total):
        seen.append((done, total))
        return done < 2

    r = sweep(lambda v, rng: 2 * v["x"], points(x=np.arange(10.0)), chunk_size=3,
              progress=progress, labels="numpy")
    assert seen == [(1, 4), (2, 4)]
    assert [(f.index, f.error) for f in r.failed] == [(2, None), (3, None)]
    np.testing.assert_array_equal(r.values.values[:6], 2 * np.arange(6.0))
    assert np.all(np.isnan(r.values.values[6:]))


def test_per_chunk_generators_come_from_seedsequence_spawn():
    r = sweep(lambda v, rng: rng.random(len(v["x"])), points(x=np.zeros(7)), chunk_size=3,
              seed=42, labels="numpy")
    children = np.random.SeedSequence(42).spawn(3)
    expected = np.concatenate([np.random.default_rng(s).random(n)
                               for s, n in zip(children, (3, 3, 1), strict=True)])
    np.testing.assert_array_equal(r.values.values, expected)
    assert r.seed == 42


def test_bad_input_is_refused_before_computing(eqs):
    with pytest.raises(rm.errors.ArgumentError, match=r"`points` must have one length"):
        points(m2=[1.0, 2.0], q1=[0.1])
    with pytest.raises(rm.errors.ArgumentError, match=r"`k` is not used by the equations"):
        sweep(eqs, grid(k=[1.0, 2.0]), m2=1.0, **FIXED)
    with pytest.raises(rm.errors.ArgumentError, match=r"missing values for \['m2'\]"):
        sweep(eqs, grid(q1=[1.0, 2.0]), **FIXED)
    with pytest.raises(rm.errors.ArgumentError, match=r"both swept and given"):
        sweep(eqs, grid(m2=[1.0]), m2=1.0, **FIXED)
    with pytest.raises(rm.errors.ArgumentTypeError, match=r"`over` must be grid"):
        sweep(eqs, {"m2": [1.0]}, **FIXED)
    with pytest.raises(rm.errors.ArgumentError, match=r"`backend` must be one of"):
        sweep(eqs, grid(m2=[1.0]), backend="spark", **FIXED)
    with pytest.raises(rm.errors.ArgumentError, match=r"`chunk_size` must be a positive"):
        sweep(eqs, grid(m2=[1.0]), chunk_size=0, **FIXED)
    with pytest.raises(rm.errors.ArgumentError, match=r"needs `times`"):
        sweep(eqs, grid(m2=[1.0]), quantity="samples", **FIXED)
    with pytest.raises(rm.errors.ArgumentError, match=r"values of `m2` must be a non-empty"):
        grid(m2=[[1.0, 2.0]])


def test_chunk_size_one_and_exactly_the_size_give_one_and_n_chunks():
    # the boundary of the chunking: size == chunk_size is one chunk, size + 1 is two
    for size, chunk, n in ((4, 4, 1), (5, 4, 2), (3, 4, 1), (4, 1, 4)):
        calls = []

        def f(v, rng, calls=calls):
            calls.append(len(v["x"]))
            return v["x"]

        sweep(f, points(x=np.arange(size)), chunk_size=chunk, labels="numpy")
        assert len(calls) == n and sum(calls) == size


def test_unreachable_scheduler_is_a_clear_error(eqs):
    pytest.importorskip("distributed")
    with pytest.raises(ClusterError, match=r"cannot reach the Dask scheduler at `address`"):
        sweep(eqs, grid(m2=[1.0]), backend="dask", address="tcp://127.0.0.1:1", timeout=1,
              **FIXED)
    with pytest.raises(rm.errors.ArgumentError, match=r"needs `client`"):
        sweep(eqs, grid(m2=[1.0]), backend="dask", **FIXED)


@pytest.fixture(scope="module")
def client():
    distributed = pytest.importorskip("distributed")
    import dask
    with dask.config.set(WORKER_CONFIG), \
            distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                     dashboard_address=":0") as cluster, \
            distributed.Client(cluster, set_as_default=False) as c:
        yield c


def test_workers_started_under_worker_config_keep_malloc_defaults_and_no_profiler(client):
    # dask's nanny sets MALLOC_TRIM_THRESHOLD_ in its workers (glibc then maps and unmaps
    # every large array: a page fault per page, the worker's CPU a point up by a third on the
    # sweep benchmark) and samples their stacks every 10 ms; WORKER_CONFIG undoes both
    import os

    import dask
    seen = client.run(lambda: (os.environ.get("MALLOC_TRIM_THRESHOLD_"),
                               dask.config.get("distributed.worker.profile.enabled")))
    assert len(seen) == 2 and set(seen.values()) == {(None, False)}


def test_dask_equals_inprocess_bit_for_bit(eqs, client):
    over = grid(m2=np.linspace(0.5, 2.0, 10), q1=np.linspace(0.1, 1.5, 10))
    args = dict(t=(0.0, 1.0), chunk_size=17, rtol=1e-8, atol=1e-10, **FIXED)
    here = sweep(eqs, over, **args)
    there = sweep(eqs, over, backend="dask", client=client, **args)
    assert here.complete and there.complete
    np.testing.assert_array_equal(np.asarray(there.values.values),
                                  np.asarray(here.values.values))
    noisy = dict(chunk_size=3, seed=7, labels="numpy")
    f = lambda v, rng: v["x"] + rng.standard_normal(len(v["x"]))  # noqa: E731
    np.testing.assert_array_equal(
        sweep(f, points(x=np.arange(10.0)), backend="dask", client=client, **noisy).values.values,
        sweep(f, points(x=np.arange(10.0)), **noisy).values.values)


def test_dask_keeps_the_finished_chunks_when_one_fails(eqs, client):
    over = points(m2=[1.0, 2.0, 0.0, 1.5], q1=[0.1] * 4)
    r = sweep(eqs, over, t=(0.0, 0.5), chunk_size=2, backend="dask", client=client,
              labels="numpy", **FIXED)
    assert [f.index for f in r.failed] == [1]
    assert np.all(np.isfinite(r.values.values[:2])) and np.all(np.isnan(r.values.values[2:]))


def test_without_dask_the_inprocess_backend_works_and_dask_is_a_clear_error(eqs, monkeypatch):
    import sys
    monkeypatch.setitem(sys.modules, "distributed", None)   # import distributed fails
    r = sweep(lambda v, rng: v["x"], points(x=[1.0, 2.0]), labels="numpy")
    assert r.values.values.tolist() == [1.0, 2.0]
    with pytest.raises(rm.errors.ArgumentError, match=r"pip install rigidmech\[distributed\]"):
        sweep(eqs, grid(m2=[1.0]), backend="dask", address="tcp://127.0.0.1:1", **FIXED)


def test_xarray_labels_of_a_grid_and_of_points(eqs):
    xr = pytest.importorskip("xarray")
    r = sweep(eqs, grid(m2=[1.0, 2.0], q1=[0.1, 0.2, 0.3]), t=(0.0, 0.1), labels="xarray",
              **FIXED)
    assert isinstance(r.values, xr.DataArray)
    assert r.values.dims == ("m2", "q1", "state")
    assert r.values.coords["state"].values.tolist() == ["q1", "q2", "q1_dot", "q2_dot"]
    assert r.values.coords["q1"].values.tolist() == [0.1, 0.2, 0.3]
    p = sweep(eqs, points(m2=[1.0, 2.0], q1=[0.2, 0.3]), t=(0.0, 0.1), **FIXED)
    assert p.values.dims == ("point", "state")
    assert p.values.coords["m2"].values.tolist() == [1.0, 2.0]
    np.testing.assert_array_equal(p.values.values[0], r.values.sel(m2=1.0, q1=0.2).values)


def test_the_direct_batched_call_gives_the_checked_calls_numbers_bit_for_bit(eqs, monkeypatch):
    # the chunk's task calls the generated batched code directly; with that path switched off
    # every call goes through the compiled solve's argument checks: the same function on the
    # same arrays, so the same numbers to the last bit
    from rigidmech.dynamics import _compiled
    over = grid(m2=[0.5, 1.0, 2.0], q1=[0.2, 0.8, 1.4])
    args = dict(t=(0.0, 1.0), chunk_size=4, rtol=1e-9, atol=1e-11, labels="numpy", **FIXED)
    calls = []
    direct = _compiled.batched_first_order

    def spy(solve, n):
        found = direct(solve, n)
        calls.append(found is not None)
        return found

    monkeypatch.setattr(_compiled, "batched_first_order", spy)
    fast = sweep(eqs, over, **args).values.values
    assert calls and all(calls)
    monkeypatch.setattr(_compiled, "batched_first_order", lambda solve, n: None)
    checked = sweep(eqs, over, **args).values.values
    np.testing.assert_array_equal(fast, checked)
