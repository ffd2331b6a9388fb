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
