"""Exact Euclidean distance transform (numba), for distances beyond a narrow band.

Felzenszwalb and Huttenlocher's separable algorithm: the squared distance to the nearest
``True`` voxel is the lower envelope of parabolas, computed one axis at a time. Each pass runs
in parallel over the lines of that axis; the result is exact (not a chamfer estimate).
"""

from __future__ import annotations

import numpy as np
from numba import njit, prange

_FAR = 1e20


@njit(cache=True)
def _envelope_1d(f, out, v, z):
    """Squared distances along one line: out[q] = min_p (q - p)^2 + f[p]."""
    n = f.shape[0]
    k = 0
    v[0] = 0
    z[0] = -np.inf
    z[1] = np.inf
    for q in range(1, n):
        while True:
            p = v[k]
            s = ((f[q] + q * q) - (f[p] + p * p)) / (2.0 * q - 2.0 * p)
            if s <= z[k] and k > 0:
                k -= 1
            else:
                break
        k += 1
        v[k] = q
        z[k] = s
        z[k + 1] = np.inf
    k = 0
    for q in range(n):
        while z[k + 1] < q:
            k += 1
        p = v[k]
        out[q] = (q - p) * (q - p) + f[p]


@njit(cache=True)
def _line_buffers(n):
    """Scratch for :func:`_envelope_1d` on lines of ``n`` voxels: values, result, vertices, bounds."""
    return np.empty(n), np.empty(n), np.empty(n, np.int64), np.empty(n + 1)


@njit(cache=True)
def _envelope_plane(plane):
    """:func:`_envelope_1d` along the first axis of a 2-D plane, column by column, in place."""
    n, m = plane.shape
    f, out, v, z = _line_buffers(n)
    for c in range(m):
        f[:] = plane[:, c]
        _envelope_1d(f, out, v, z)
        plane[:, c] = out


@njit(parallel=True, cache=True)
def _edt_zy(target_sdf):
    """The first two passes (along z, then y) of the squared EDT to the voxels where
    ``target_sdf < 0``, in float32 (squared integer distances are exact below 2^24)."""
    nx, ny, nz = target_sdf.shape
    d = np.empty((nx, ny, nz), np.float32)
    for i in prange(nx):
        f, out, v, z = _line_buffers(nz)
        for j in range(ny):
            for l in range(nz):
                f[l] = 0.0 if target_sdf[i, j, l] < 0.0 else _FAR
            _envelope_1d(f, out, v, z)
            for l in range(nz):
                d[i, j, l] = out[l]
        _envelope_plane(d[i, :, :])
    return d


def max_squared_distance(target_sdf: np.ndarray, region_sdf: np.ndarray, band: float) -> float:
    """Largest squared distance (voxels^2) from a voxel inside ``region_sdf`` and at least
    ``band`` outside ``target_sdf`` to the nearest voxel inside ``target_sdf``; 0 when there is
    none. The last EDT pass (along x) is fused with the maximum, so the full transform is never
    stored. (Two kernels called from here: a cached kernel calling another parallel one can
    crash when loaded from numba's cache.)"""
    return float(_max_along_x(_edt_zy(target_sdf), target_sdf, region_sdf, np.float32(band)))


@njit(parallel=True, cache=True)
def _max_along_x(d, target_sdf, region_sdf, band):
    nx, ny, nz = target_sdf.shape
    best = np.zeros(ny)
    for j in prange(ny):
        f, out, v, z = _line_buffers(nx)
        for l in range(nz):
            wanted = False
            for i in range(nx):
                if region_sdf[i, j, l] < 0.0 and target_sdf[i, j, l] >= band:
                    wanted = True
                    break
            if not wanted:
                continue
            for i in range(nx):
                f[i] = d[i, j, l]
            _envelope_1d(f, out, v, z)
            for i in range(nx):
                if region_sdf[i, j, l] < 0.0 and target_sdf[i, j, l] >= band:
                    best[j] = max(best[j], out[i])
    return best.max()
