"""Zero isosurface of a :class:`SparseGrid` as a closed, outward-facing triangle mesh.

The grid is exported to an in-memory OpenVDB level set and meshed with
``convertToPolygons(0, 0)``: one pass over the active voxels that shares vertices between
neighbouring cells, so the mesh is watertight by index. The export uses index space (identity
transform) and vertices are mapped to world in float64, so OpenVDB's float32 points lose
precision relative to the table size only, never to the part's distance from the world origin.

Measured on a spherical shell (R 20 / 12 mm at 0.1 mm, 4.1 M active voxels, 2.05 M
triangles): export + convertToPolygons 0.37 s; scikit-image ``marching_cubes`` on the same
box as one dense array 0.73 s (plus a dense 72 M-voxel array). Per-block marching cubes would
need neighbour padding, a Python loop over blocks and a vertex weld afterwards, so OpenVDB it is.

OpenVDB winds faces inward (normals into the solid); faces are reversed here and its quads
split along the (0, 2) diagonal, so normals point out of the deposit.
"""

from __future__ import annotations

import numba as nb
import numpy as np

from .sparse import SparseGrid, value_at
from .vdbio import to_openvdb


def surface_mesh(grid: SparseGrid) -> tuple[np.ndarray, np.ndarray]:
    """(vertices (n, 3) float64 world mm, triangles (m, 3) int64) of the sdf = 0 surface."""
    sdf_vdb, _ = to_openvdb(grid, world=False, arrival=False)
    points, tris, quads = sdf_vdb.convertToPolygons(0.0, 0.0)
    vertices = grid.origin + np.asarray(points, np.float64) * grid.voxel
    tris = np.asarray(tris, np.int64).reshape(-1, 3)
    quads = np.asarray(quads, np.int64).reshape(-1, 4)
    triangles = np.concatenate([
        tris[:, ::-1],
        quads[:, [0, 2, 1]],
        quads[:, [0, 3, 2]],
    ])
    return vertices, np.ascontiguousarray(triangles)


def surface_arrival(grid: SparseGrid, vertices: np.ndarray) -> np.ndarray:
    """Arrival time at surface points: that of the nearest inside voxel (the nearest, not the
    earliest, so a layer's surface does not take the time of the layer below where the two meet).

    The 8 voxels around a point usually hold one. They hold none where the zero crossing sits on
    a voxel centre whose value is a hair above zero (two faces that meet to within rounding, such
    as a layer step of 0.30000000000000004 mm): the mesher puts the vertex on that outside voxel,
    and the inside one lies a voxel further. Those points look a ring further out, then the next,
    up to the band, where an inside voxel always is."""
    idx = np.ascontiguousarray(grid.world_to_index(np.asarray(vertices, np.float64).reshape(-1, 3)))
    arrival = np.empty(len(idx))
    max_ring = max(2, int(np.ceil(grid.band / grid.voxel)) + 1)
    _nearest_inside_arrival(idx, max_ring, grid.view(), arrival)
    return arrival


@nb.njit(cache=True, parallel=True)
def _nearest_inside_arrival(idx, max_ring, g, out):
    """Per point (continuous index coordinates), the arrival of the nearest voxel with one in
    the smallest ring that holds any (ring 1: the cell's 8 corners; ring r: the (2r)^3 voxels
    around it), the first in (x, y, z) order among equally near; +inf when none does."""
    for p in nb.prange(idx.shape[0]):
        x, y, z = idx[p, 0], idx[p, 1], idx[p, 2]
        i0, j0, k0 = int(np.floor(x)), int(np.floor(y)), int(np.floor(z))
        out[p] = np.inf
        for ring in range(1, max_ring + 1):
            best = np.inf
            found = np.inf
            for a in range(2 * ring):
                for b in range(2 * ring):
                    for c in range(2 * ring):
                        i, j, k = i0 + a - (ring - 1), j0 + b - (ring - 1), k0 + c - (ring - 1)
                        t = value_at(g, i, j, k, False)
                        if np.isfinite(t):
                            d2 = (i - x) ** 2 + (j - y) ** 2 + (k - z) ** 2
                            if d2 < best:
                                best = d2
                                found = t
            if np.isfinite(found):
                out[p] = found
                break
