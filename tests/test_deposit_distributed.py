"""`simulate --scheduler`: slabs swept on a dask cluster give the grid the local run gives."""

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
    # Thin slabs so the part is split into several tiles (each with its own halo).
    monkeypatch.setattr(engine, "SLAB_BUDGET_BYTES", (1 << 20, 1 << 20))
    local, _ = deposit(tp, bead, 0.1)
    tiled, _ = deposit(tp, bead, 0.1, scheduler=dask_cluster)
    n_slabs = -(-local.block.shape[2] // max(1, (1 << 20) // (64 * local.block.shape[0] * local.block.shape[1] * 8
                                                               * engine.SLAB_BYTES_PER_VOXEL)))
    assert n_slabs >= 3
    for name in GRID_ARRAYS:
        assert np.array_equal(getattr(local, name), getattr(tiled, name)), name
    assert porosity(local).porosity_percent == porosity(tiled).porosity_percent > 0
