"""A closed triangle mesh as a :class:`SparseGrid` on a given lattice (CAD parts, nozzles, fixtures).

OpenVDB's ``createLevelSetFromPolygons`` builds the narrow-band level set in the lattice's index
space (vertices mapped by ``(x - origin) / voxel``, unit voxels): the two lattices coincide voxel
for voxel, and float32 stays precise however far the part is from the machine origin. Its
interior comes flood-filled (``-background``), so copying the level set's active box slab by
slab into the grid builder gives leaves along the surface and inside tiles in the interior; a
slab holds at most ``SLAB_VOXELS`` voxels whatever the part's size.
"""

from __future__ import annotations

import math

import numba as nb
import numpy as np

from .build import GridBuilder
from .sparse import SparseGrid

SLAB_VOXELS = 1 << 24  # 64 MB of float32 per dense slab


def surface_memory(area: float, voxel: float, band: float, n_blocks: float) -> int:
    """Bytes a narrow-band grid around a surface of ``area`` mm^2 needs, with its block table of
    ``n_blocks`` blocks (the grid and the working copies of its construction)."""
    active = area / (voxel * voxel) * (2 * band / voxel)
    leaves = active / 200.0
    grid = active * 6.5 + leaves * 160 + n_blocks * 4
    return int(grid * 1.5 + n_blocks * 8)


def mesh_area(vertices: np.ndarray, triangles: np.ndarray) -> float:
    """The area of a triangle mesh (mm^2)."""
    return float(_mesh_area(np.ascontiguousarray(vertices, np.float64), np.ascontiguousarray(triangles, np.int64)))


@nb.njit(cache=True)
def _mesh_area(vertices, triangles):
    # straight from the indexed mesh: numpy would build an (m, 3, 3) corner array and the
    # temporaries of its cross product (seconds on the 8.6 M triangles of a 100 mm part)
    total = 0.0
    for t in range(triangles.shape[0]):
        a, b, c = triangles[t, 0], triangles[t, 1], triangles[t, 2]
        ux, uy, uz = vertices[b, 0] - vertices[a, 0], vertices[b, 1] - vertices[a, 1], vertices[b, 2] - vertices[a, 2]
        vx, vy, vz = vertices[c, 0] - vertices[a, 0], vertices[c, 1] - vertices[a, 1], vertices[c, 2] - vertices[a, 2]
        total += 0.5 * math.sqrt((uy * vz - uz * vy) ** 2 + (uz * vx - ux * vz) ** 2 + (ux * vy - uy * vx) ** 2)
    return total


def index_level_set(vertices: np.ndarray, triangles: np.ndarray, voxel: float, origin, half_width_voxels: float):
    """The mesh as an OpenVDB FloatGrid in the lattice's index space (voxel (0, 0, 0) at
    ``origin``, unit voxels, values in voxels)."""
    from ..vdb import openvdb

    index_vertices = (np.asarray(vertices, np.float64) - np.asarray(origin, np.float64)) / voxel
    return openvdb.FloatGrid.createLevelSetFromPolygons(
        np.ascontiguousarray(index_vertices), triangles=np.ascontiguousarray(triangles, np.int32),
        transform=openvdb.createLinearTransform(1.0), halfWidth=float(half_width_voxels))


def mesh_grid(vertices: np.ndarray, triangles: np.ndarray, voxel: float, origin, block_shape, band: float,
              meta: dict | None = None) -> SparseGrid:
    """The mesh as a sparse SDF on the lattice ``(origin, voxel)`` with ``block_shape`` blocks
    (a band of ``band`` mm); arrival 0 inside: the part is there from the start."""
    level_set = index_level_set(vertices, triangles, voxel, origin, band / voxel)
    builder = GridBuilder(voxel, origin, block_shape, band)
    if level_set.activeVoxelCount():
        (imin, jmin, kmin), (imax, jmax, kmax) = level_set.evalActiveVoxelBoundingBox()
        shape = np.array(block_shape)
        lo = np.clip(np.floor_divide([imin, jmin, kmin], 8), 0, shape)
        hi = np.clip(np.floor_divide([imax, jmax, kmax], 8) + 1, 0, shape)
        ny, nz = int(hi[1] - lo[1]), int(hi[2] - lo[2])
        step = max(1, SLAB_VOXELS // max(1, 512 * ny * nz))
        for x0 in range(int(lo[0]), int(hi[0]), step):
            x1 = min(int(hi[0]), x0 + step)
            sdf = np.empty((8 * (x1 - x0), 8 * ny, 8 * nz), np.float32)
            level_set.copyToArray(sdf, (8 * x0, 8 * int(lo[1]), 8 * int(lo[2])))
            builder.add_static(sdf, voxel, (x0, int(lo[1]), int(lo[2])))
    return builder.finish(meta or {})


def like_grid(vertices: np.ndarray, triangles: np.ndarray, like: SparseGrid, meta: dict | None = None) -> SparseGrid:
    """The mesh on ``like``'s lattice, block table and band (a CAD part beside a deposit)."""
    return mesh_grid(vertices, triangles, like.voxel, like.origin, like.block.shape, like.band, meta)
