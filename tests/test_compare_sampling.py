"""Surface samples on sparse grids: edge crossings with area weights (dmdvox.comparison.blocks),
trilinear sampling (dmdvox.grid.sparse), weighted statistics (dmdvox.comparison.sampling), the
block-by-block depth search (dmdvox.comparison.depth)."""

import math

import numpy as np
import pytest

from dmdvox.comparison.blocks import crossings
from dmdvox.comparison.sampling import weighted_stats
from dmdvox.grid.build import grid_from_dense


def _sparse(sdf: np.ndarray, voxel: float = 0.1):
    """A dense field as a sparse grid (band 3 voxels) whose index (0, 0, 0) is its voxel (0, 0, 0)."""
    band = 3 * voxel
    return grid_from_dense(np.clip(sdf, -band, band).astype(np.float32), np.zeros_like(sdf, np.float32), voxel,
                           np.zeros(3), band)


def edge_crossings(surface: np.ndarray, other: np.ndarray):
    s, o = _sparse(surface), _sparse(other)
    return crossings(s.view(), o.view(), s.leaf_coord.astype(np.int64))


def _sphere_sdf(n: int, voxel: float, radius: float, centre=(0.013, -0.021, 0.007)) -> np.ndarray:
    axis = (np.arange(n) - (n - 1) / 2) * voxel
    x, y, z = np.meshgrid(axis - centre[0], axis - centre[1], axis - centre[2], indexing="ij")
    return (np.sqrt(x * x + y * y + z * z) - radius).astype(np.float32)


def test_weighted_crossings_measure_the_area_of_a_sphere():
    voxel, radius = 0.1, 3.0
    sdf = _sphere_sdf(80, voxel, radius)
    points, values, weights = edge_crossings(sdf, sdf)
    # every crossing stands for voxel^2 / (|nx| + |ny| + |nz|) of surface
    assert voxel**2 * weights.sum() == pytest.approx(4 * math.pi * radius**2, rel=0.01)
    # unweighted, the count over-represents the diagonal directions by up to sqrt(3)
    assert voxel**2 * len(weights) > 1.3 * 4 * math.pi * radius**2
    assert np.all((weights > 1 / math.sqrt(3) - 1e-6) & (weights <= 1.0 + 1e-6))
    centre = (np.array(sdf.shape) - 1) / 2
    r = np.linalg.norm((points - centre) * voxel - (0.013, -0.021, 0.007), axis=1)
    assert np.max(np.abs(r - radius)) < 0.01 * voxel * 10  # linear interpolation of a smooth SDF
    assert np.max(np.abs(values)) < 1e-2 * voxel * 10  # the surface's own SDF there is ~0


def test_other_field_is_interpolated_at_the_crossings():
    voxel = 0.1
    cad = _sphere_sdf(80, voxel, 3.0)
    deposit = _sphere_sdf(80, voxel, 3.25)  # everywhere 0.25 mm outside the CAD sphere
    _, values, weights = edge_crossings(cad, deposit)
    stats = weighted_stats(-values, weights)  # + = excess material, as compare signs it
    assert stats["mean"] == pytest.approx(0.25, abs=2e-3)
    assert stats["rms"] == pytest.approx(0.25, abs=2e-3)
    assert stats["p95"] == pytest.approx(0.25, abs=3e-3)


def test_trilinear_is_exact_on_a_linear_field():
    i, j, k = np.meshgrid(np.arange(24), np.arange(16), np.arange(24), indexing="ij")
    voxel = 0.1
    field = (0.005 * i - 0.0025 * j + 0.00125 * k - 0.05).astype(np.float32)  # |values| < the band
    grid = _sparse(field, voxel)
    rng = np.random.default_rng(7)
    points = rng.uniform([0, 0, 0], [23, 15, 23], (1000, 3))
    expected = 0.005 * points[:, 0] - 0.0025 * points[:, 1] + 0.00125 * points[:, 2] - 0.05
    assert np.allclose(grid.trilinear(grid.index_to_world(points)), expected, atol=1e-6)


def test_weighted_stats_closed_forms():
    values = np.array([-1.0, 2.0, 3.0])
    weights = np.array([1.0, 1.0, 2.0])
    stats = weighted_stats(values, weights)
    assert stats["mean"] == pytest.approx((-1 + 2 + 6) / 4)
    assert stats["rms"] == pytest.approx(math.sqrt((1 + 4 + 18) / 4))
    assert stats["p95"] == 3.0  # half the weight sits at |3|
    assert weighted_stats(np.arange(1.0, 101.0))["p95"] == 95.0
    assert weighted_stats(np.zeros(0)) == {"mean": 0.0, "rms": 0.0, "p95": 0.0}


def test_deepest_point_matches_a_brute_force_search():
    """The branch-and-bound depth search gives the farthest region voxel from a target, exactly
    as measuring every voxel does."""
    from dmdvox.comparison.depth import deepest

    voxel = 0.1
    n = 48
    axis = np.arange(n) * voxel
    x, y, z = np.meshgrid(axis, axis, axis, indexing="ij")
    centre = np.array([1.2, 2.3, 2.0])
    target = np.sqrt((x - centre[0]) ** 2 + (y - centre[1]) ** 2 + (z - centre[2]) ** 2) - 0.4  # a ball
    region = np.maximum(np.abs(x - 2.4) - 1.9, np.maximum(np.abs(y - 2.4) - 1.9, np.abs(z - 2.4) - 1.9))  # a box
    t, r = _sparse(target, voxel), _sparse(region, voxel)
    blocks = np.argwhere(np.ones(t.block.shape, bool)).astype(np.int64)

    def distance(points):
        return np.linalg.norm(points - centre, axis=1) - 0.4

    far = (region < 0) & (target >= 3 * voxel * (1 - 1e-6))
    expected = distance(np.stack([x[far], y[far], z[far]], 1)).max()
    assert deepest(r.view(), t.view(), blocks, np.zeros(3), voxel, distance, 0.0) == pytest.approx(expected, abs=1e-9)
