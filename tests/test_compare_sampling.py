"""Surface samples on dense SDFs: edge crossings with area weights, trilinear sampling, weighted
statistics (dmdvox.compare.sampling)."""

import math

import numpy as np
import pytest

from dmdvox.compare.sampling import edge_crossings, trilinear, weighted_stats


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


def test_trilinear_is_exact_on_a_linear_field_and_flags_outside_points():
    i, j, k = np.meshgrid(np.arange(8), np.arange(16), np.arange(24), indexing="ij")
    field = (0.5 * i - 0.25 * j + 0.125 * k + 1.0).astype(np.float32)
    rng = np.random.default_rng(7)
    points = rng.uniform([0, 0, 0], [7, 15, 23], (1000, 3))
    expected = 0.5 * points[:, 0] - 0.25 * points[:, 1] + 0.125 * points[:, 2] + 1.0
    assert np.allclose(trilinear(field, points, 99.0), expected, atol=1e-5)
    corners = np.array([[0.0, 0.0, 0.0], [7.0, 15.0, 23.0], [7.5, 1.0, 1.0], [-0.1, 1.0, 1.0]])
    assert np.allclose(trilinear(field, corners, 99.0), [1.0, 0.5 * 7 - 0.25 * 15 + 0.125 * 23 + 1.0, 99.0, 99.0])


def test_weighted_stats_closed_forms():
    values = np.array([-1.0, 2.0, 3.0])
    weights = np.array([1.0, 1.0, 2.0])
    stats = weighted_stats(values, weights)
    assert stats["mean"] == pytest.approx((-1 + 2 + 6) / 4)
    assert stats["rms"] == pytest.approx(math.sqrt((1 + 4 + 18) / 4))
    assert stats["p95"] == 3.0  # half the weight sits at |3|
    assert weighted_stats(np.arange(1.0, 101.0))["p95"] == 95.0
    assert weighted_stats(np.zeros(0)) == {"mean": 0.0, "rms": 0.0, "p95": 0.0}


def test_max_squared_distance_matches_scipy_edt():
    """The fused EDT maximum against scipy's exact transform, on random solids and regions."""
    from scipy import ndimage

    from dmdvox.compare.edt import max_squared_distance

    rng = np.random.default_rng(11)
    for shape in ((17, 23, 9), (40, 8, 31)):
        target = rng.random(shape) < 0.02
        target_sdf = np.where(target, -1.0, 1.0).astype(np.float32)
        # "far" voxels: give a random half the clamped value, the rest a small distance
        target_sdf[~target & (rng.random(shape) < 0.5)] = 3.0
        region_sdf = np.where(rng.random(shape) < 0.3, -1.0, 1.0).astype(np.float32)
        squared = ndimage.distance_transform_edt(~target) ** 2
        selected = (region_sdf < 0) & (target_sdf >= 3.0)
        assert max_squared_distance(target_sdf, region_sdf, 3.0) == pytest.approx(squared[selected].max(), abs=1e-6)
    empty = np.ones((8, 8, 8), np.float32)
    assert max_squared_distance(-empty, empty, 3.0) == 0.0
