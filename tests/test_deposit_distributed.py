"""`simulate --scheduler`: chunks swept on a dask cluster give the grid the local run gives."""

import numpy as np

from dmdvox.deposit import engine
from dmdvox.deposit.engine import deposit
from dmdvox.process.profiles import BeadProfile
from dmdvox.grid.analysis import porosity
from dmdvox.toolpath import read_gcode

from .conftest import DATA

GRID_ARRAYS = ("block", "leaf_coord", "leaf_active", "leaf_inside", "sdf_offset", "sdf", "arr_offset", "arrival",
               "leaf_octant_arrival", "tile_arrival")


def test_tiled_simulate_equals_local(dask_cluster, monkeypatch):
    tp = read_gcode(DATA / "prusa_block_20.gcode")
    bead = BeadProfile("rect", 0.6, 0.3)
    whole, _ = deposit(tp, bead, 0.1)
    # Small windows and outputs so the part is split along x and z (each chunk with its own halo).
    monkeypatch.setattr(engine, "WINDOW_BYTES", 3 * engine.SWEPT_BLOCK_BYTES * 200)
    monkeypatch.setattr(engine, "CHUNK_OUTPUT_BYTES", 256 << 10)
    chunks = []
    plan_chunks = engine.plan_chunks
    monkeypatch.setattr(engine, "plan_chunks", lambda *args: chunks.append(plan_chunks(*args)) or chunks[-1])
    local, _ = deposit(tp, bead, 0.1)
    tiled, timings = deposit(tp, bead, 0.1, scheduler=dask_cluster)
    assert len({(c.bx0, c.bx1) for c in chunks[-1]}) >= 2 and len({(c.bz0, c.bz1) for c in chunks[-1]}) >= 2
    assert timings["chunks"] == len(chunks[-1]) >= 4
    for name in GRID_ARRAYS:
        assert np.array_equal(getattr(whole, name), getattr(local, name)), name
        assert np.array_equal(getattr(local, name), getattr(tiled, name)), name
    assert porosity(local).porosity_percent == porosity(tiled).porosity_percent > 0


def test_a_cluster_gets_a_chunk_for_every_worker(dask_cluster, monkeypatch):
    # On a cluster the sweep is cut into chunks for every worker thread (two per thread), never
    # below MIN_CLUSTER_CHUNK_BYTES: that floor shrunk so that this small part stands in for one
    # of a few million voxels. Both single-thread workers of the fixture sweep a share, and the
    # grid is the local one's.
    from distributed import Client

    tp = read_gcode(DATA / "prusa_block_20.gcode")
    bead = BeadProfile("rect", 0.6, 0.3)
    local, local_timings = deposit(tp, bead, 0.1)
    assert local_timings["chunks"] == 1  # here the part is one chunk
    monkeypatch.setattr(engine, "MIN_CLUSTER_CHUNK_BYTES", 64 << 10)
    def executed(dask_worker):
        return dask_worker.state.executed_count

    with Client(dask_cluster, timeout=30) as client:
        before = client.run(executed)
        assert len(before) == 2
        tiled, timings = deposit(tp, bead, 0.1, scheduler=dask_cluster)
        after = client.run(executed)
    assert timings["chunks"] >= engine.CLUSTER_CHUNKS_PER_THREAD * len(before)
    assert all(after[w] > before[w] for w in before), (before, after)
    for name in GRID_ARRAYS:
        assert np.array_equal(getattr(local, name), getattr(tiled, name)), name


def simulate_json(*extra) -> dict:
    import contextlib
    import io
    import json

    from dmdvox import cli

    out = io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(io.StringIO()):
        code = cli.main(["simulate", str(DATA / "prusa_block_20.gcode"), "--width", "0.6", "--voxel", "0.1", "--json",
                         *extra])
    assert code == 0
    result = json.loads(out.getvalue())
    del result["timings_s"]
    return result


def test_simulate_on_a_cluster_prints_the_local_json(dask_cluster, monkeypatch):
    # the sweep's chunks and the void search's tiles both spread over the two workers; the JSON,
    # pores and porosity included, is the local run's
    from distributed import Client, get_task_stream

    monkeypatch.setattr(engine, "MIN_CLUSTER_CHUNK_BYTES", 64 << 10)
    local = simulate_json()
    with Client(dask_cluster, timeout=30) as client, get_task_stream(client) as stream:
        remote = simulate_json("--scheduler", dask_cluster)
    assert remote == local
    assert local["pore_count"] > 0 and local["porosity_percent"] > 0
    by_kind = {}
    for task in stream.data:
        by_kind.setdefault(task["key"].split("-")[0], set()).add(task["worker"])
    assert {k: len(by_kind.get(k, ())) for k in ("sweep_chunk", "exterior_step", "void_step")} == \
        {"sweep_chunk": 2, "exterior_step": 2, "void_step": 2}, by_kind
