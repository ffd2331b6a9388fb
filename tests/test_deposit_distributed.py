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
