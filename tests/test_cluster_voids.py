"""The void search in x tiles (grid/tilelabels.py), merged through the boundary graph, finds the
whole grid's voids to the bit: on the void-search part (a pore, cavities behind a narrow and a
wide channel, crevices, an open fin) and on a long bar whose pore and channels cross many tiles,
in this process and on a two-worker dask cluster (issue 26, "Work that spreads")."""

from __future__ import annotations

import math

import numpy as np
import pytest

from dmdvox.grid.build import grid_from_dense
from dmdvox.grid.enclosure import enclosed_voids
from dmdvox.grid.tilelabels import halo_blocks, plan_tiles, tiled_voids

from .test_void_search import BEAD, VOXEL, assert_same_voids, ball, box, rod_y


def rod_x(X, Y, Z, y, z, r, x0, x1):
    """A cylinder along x from x0 to x1."""
    return np.maximum(np.sqrt((Y - y) ** 2 + (Z - z) ** 2) - r, np.maximum(x0 - X, X - x1))


def bar(X, Y, Z):
    solid = box(X, Y, Z, (0.5, 0.5, 0.0), (19.5, 4.5, 2.4))
    cavity = rod_x(X, Y, Z, 1.8, 1.2, 0.4, 3.0, 15.0)  # a sealed pore 12 mm long
    cavity = np.minimum(cavity, ball(X, Y, Z, (5.0, 3.3, 1.2), 0.5))  # behind a narrow channel to x = 0.5
    cavity = np.minimum(cavity, rod_x(X, Y, Z, 3.3, 1.2, 0.15, -5.0, 5.0))
    cavity = np.minimum(cavity, rod_x(X, Y, Z, 3.3, 1.2, 0.45, 10.0, 25.0))  # a wide channel open at x = 19.5
    cavity = np.minimum(cavity, rod_y(X, Y, Z, 17.0, 2.0, 0.1, 1.0, 2.0))  # a sliver: a speck or two
    return np.maximum(solid, -cavity)


def dense_grid(shape_fn, n, lo):
    X, Y, Z = np.meshgrid(*[lo[a] + VOXEL * np.arange(n[a]) for a in range(3)], indexing="ij")
    sdf = np.clip(shape_fn(X, Y, Z), -3 * VOXEL, 3 * VOXEL).astype(np.float32)
    arrival = np.where(sdf < 0, 10.0 + Z, np.inf).astype(np.float32)
    return grid_from_dense(sdf, arrival, VOXEL, np.asarray(lo, float), 3 * VOXEL)


@pytest.fixture(scope="module")
def long_bar():
    return dense_grid(bar, (208, 56, 32), (-0.15, -0.15, -0.35))


def test_the_halo_covers_the_reach():
    # s = 0.625 mm at 0.1 mm: centres 3.125 voxels clear, reach 6.25 voxels
    r_vox, reach_vox = 0.5 * 0.25 * BEAD / VOXEL, 0.25 * BEAD / VOXEL
    first, second = halo_blocks(r_vox, reach_vox, 3.0)
    assert 8 * first >= 8 + r_vox + 3  # a ring of outside tiles, a voxel of neighbours, the clearance
    assert 8 * second - 8 * first >= 2 * reach_vox
    assert (first, second) == (2, 4)


def test_tiles_follow_the_part(long_bar):
    cores = plan_tiles(long_bar, 5)
    assert len(cores) == 5 and cores[0][0] == 0 and cores[-1][1] == long_bar.block_shape[0]
    assert all(a < b for a, b in cores) and all(b == c for (_, b), (c, _) in zip(cores[:-1], cores[1:]))


def test_long_bar_pore_and_channels_across_tiles(long_bar):
    whole = enclosed_voids(long_bar, bead_width=BEAD)
    pores = whole.volume_mm3[~whole.speck]
    # the sealed rod and the ball behind the narrow channel are pores; the wide channel's is open
    assert whole.n_pores == 2
    rod = math.pi * 0.4**2 * 12.0
    assert pores[0] == pytest.approx(rod, rel=0.05)
    assert 4 / 3 * math.pi * 0.5**3 * 0.95 < pores[1] < 4 / 3 * math.pi * 0.5**3 + math.pi * 0.15**2 * 4.5
    # the pore spans most of the tiles' cores: its components meet across their faces
    cores = plan_tiles(long_bar, 7)
    x0, x1 = (whole.bbox_mm[0, :, 0] - long_bar.origin[0]) / (8 * VOXEL)
    assert sum(1 for a, b in cores if a < x1 and b > x0) >= 4
    for tiles in (2, 7, 26):
        assert_same_voids(whole, tiled_voids(long_bar, bead_width=BEAD, tiles=tiles))
    for kwargs in ({"bead_width": BEAD, "plate_z": -np.inf}, {"bead_width": 1.0}, {"bead_width": None}):
        assert_same_voids(enclosed_voids(long_bar, **kwargs), tiled_voids(long_bar, tiles=7, **kwargs))


def test_void_search_part_in_tiles():
    from .test_void_search import part

    grid = dense_grid(part, (64, 48, 40), (-0.15, -0.15, -0.35))
    whole = enclosed_voids(grid, bead_width=BEAD)
    assert whole.n_pores == 2
    for tiles in (2, 3, 8):
        assert_same_voids(whole, tiled_voids(grid, bead_width=BEAD, tiles=tiles))


def test_tiled_voids_on_a_cluster(long_bar, dask_cluster):
    from distributed import Client

    def executed(dask_worker):
        return dask_worker.state.executed_count

    with Client(dask_cluster, timeout=30) as client:
        before = client.run(executed)
        voids = tiled_voids(long_bar, bead_width=BEAD, scheduler=dask_cluster)
        after = client.run(executed)
    assert len(before) == 2 and all(after[w] > before[w] for w in before), (before, after)
    assert_same_voids(enclosed_voids(long_bar, bead_width=BEAD), voids)
