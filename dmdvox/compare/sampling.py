"""Surface samples and interpolation on dense SDF arrays (index space: voxel (i, j, k) at i, j, k).

The deviation statistics sample the CAD surface where it crosses the lattice's edges: every edge
between two voxels whose CAD SDF changes sign holds one surface point, found by linear
interpolation of the SDF along the edge, and along that same edge the deposit's SDF is
interpolated too (the trilinear value there). A surface with unit normal n crosses
(|nx| + |ny| + |nz|) / voxel² edges per unit area, so each sample is weighted by
1 / (|nx| + |ny| + |nz|) to give area-uniform statistics without building a mesh.
"""

from __future__ import annotations

import numpy as np
from numba import njit, prange


@njit(cache=True)
def _gradient(sdf, i, j, k):
    """Central differences (one-sided at the array's faces), as a tuple: no allocation per call."""
    nx, ny, nz = sdf.shape
    i0, i1 = max(i - 1, 0), min(i + 1, nx - 1)
    j0, j1 = max(j - 1, 0), min(j + 1, ny - 1)
    k0, k1 = max(k - 1, 0), min(k + 1, nz - 1)
    return ((sdf[i1, j, k] - sdf[i0, j, k]) / max(i1 - i0, 1),
            (sdf[i, j1, k] - sdf[i, j0, k]) / max(j1 - j0, 1),
            (sdf[i, j, k1] - sdf[i, j, k0]) / max(k1 - k0, 1))


@njit(cache=True)
def _slice_crossings(surface, other, i, out_points, out_values, out_weights, start, write):
    """Edge crossings of ``surface``'s zero level from the voxels of x slice ``i`` to their +x,
    +y and +z neighbours; counts them, and writes them from ``start`` when ``write``."""
    nx, ny, nz = surface.shape
    n = start
    for j in range(ny):
        for k in range(nz):
            a = surface[i, j, k]
            for axis in range(3):
                bi, bj, bk = i, j, k
                if axis == 0:
                    bi += 1
                elif axis == 1:
                    bj += 1
                else:
                    bk += 1
                if bi >= nx or bj >= ny or bk >= nz:
                    continue
                b = surface[bi, bj, bk]
                if (a < 0.0) == (b < 0.0):
                    continue
                if write:
                    t = a / (a - b)
                    out_points[n, 0] = i + t * (bi - i)
                    out_points[n, 1] = j + t * (bj - j)
                    out_points[n, 2] = k + t * (bk - k)
                    out_values[n] = other[i, j, k] + t * (other[bi, bj, bk] - other[i, j, k])
                    ga = _gradient(surface, i, j, k)
                    gb = _gradient(surface, bi, bj, bk)
                    gx = (1.0 - t) * ga[0] + t * gb[0]
                    gy = (1.0 - t) * ga[1] + t * gb[1]
                    gz = (1.0 - t) * ga[2] + t * gb[2]
                    manhattan = abs(gx) + abs(gy) + abs(gz)
                    out_weights[n] = np.sqrt(gx * gx + gy * gy + gz * gz) / manhattan if manhattan > 0 else 1.0
                n += 1
    return n - start


@njit(parallel=True, cache=True)
def edge_crossings(surface, other):
    """Points (index space) where ``surface`` crosses zero along lattice edges, ``other``
    interpolated there, and area weights (module docstring)."""
    nx = surface.shape[0]
    dummy_points = np.empty((0, 3))
    dummy = np.empty(0)
    counts = np.zeros(nx, np.int64)
    for i in prange(nx):
        counts[i] = _slice_crossings(surface, other, np.int64(i), dummy_points, dummy, dummy, 0, False)
    starts = np.zeros(nx + 1, np.int64)
    for i in range(nx):
        starts[i + 1] = starts[i] + counts[i]
    points = np.empty((starts[nx], 3))
    values = np.empty(starts[nx])
    weights = np.empty(starts[nx])
    for i in prange(nx):
        _slice_crossings(surface, other, np.int64(i), points, values, weights, starts[i], True)
    return points, values, weights


@njit(parallel=True, cache=True)
def trilinear(sdf, index_points, outside):
    """``sdf`` trilinearly interpolated at index-space points; ``outside`` beyond the array."""
    nx, ny, nz = sdf.shape
    n = index_points.shape[0]
    out = np.empty(n)
    for p in prange(n):
        x, y, z = index_points[p, 0], index_points[p, 1], index_points[p, 2]
        if not (0.0 <= x <= nx - 1 and 0.0 <= y <= ny - 1 and 0.0 <= z <= nz - 1):
            out[p] = outside
            continue
        i, j, k = min(np.int64(x), nx - 2), min(np.int64(y), ny - 2), min(np.int64(z), nz - 2)
        tx, ty, tz = x - i, y - j, z - k
        value = 0.0
        for di in range(2):
            wx = tx if di else 1.0 - tx
            for dj in range(2):
                wy = ty if dj else 1.0 - ty
                for dk in range(2):
                    wz = tz if dk else 1.0 - tz
                    value += wx * wy * wz * sdf[i + di, j + dj, k + dk]
        out[p] = value
    return out


def weighted_stats(values: np.ndarray, weights: np.ndarray | None = None) -> dict:
    """Mean, RMS and the 95th percentile of |value|, each weighted (weights default to 1)."""
    values = np.asarray(values, np.float64)
    if values.size == 0:
        return {"mean": 0.0, "rms": 0.0, "p95": 0.0}
    w = np.ones_like(values) if weights is None else np.asarray(weights, np.float64)
    total = w.sum()
    order = np.argsort(np.abs(values), kind="stable")
    cumulative = np.cumsum(w[order])
    p95 = float(np.abs(values[order[min(np.searchsorted(cumulative, 0.95 * total), values.size - 1)]]))
    return {"mean": float(np.dot(w, values) / total), "rms": float(np.sqrt(np.dot(w, values**2) / total)),
            "p95": p95}
