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
def _envelope_plane(plane):
    """:func:`_envelope_1d` along the first axis of a 2-D plane, column by column, in place."""
    n, m = plane.shape
    f = np.empty(n)
    out = np.empty(n)
    v = np.empty(n, np.int64)
    z = np.empty(n + 1)
    for c in range(m):
        f[:] = plane[:, c]
        _envelope_1d(f, out, v, z)
        plane[:, c] = out


@njit(parallel=True, cache=True)
def squared_edt(target):
    """Squared distance (in voxels^2) from every voxel to the nearest ``True`` voxel."""
    nx, ny, nz = target.shape
    d = np.empty((nx, ny, nz), np.float64)
    for i in prange(nx):
        f = np.empty(nz)
        out = np.empty(nz)
        v = np.empty(nz, np.int64)
        z = np.empty(nz + 1)
        for j in range(ny):
            for l in range(nz):
                f[l] = 0.0 if target[i, j, l] else _FAR
            _envelope_1d(f, out, v, z)
            d[i, j, :] = out
    # y, then x: each thread owns one plane of the other axis and runs along its columns
    for i in prange(nx):
        _envelope_plane(d[i, :, :])
    for j in prange(ny):
        _envelope_plane(d[:, j, :])
    return d
