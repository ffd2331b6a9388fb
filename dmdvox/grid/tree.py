"""Block hierarchy of a :class:`SparseGrid`, the skeleton of the collision octree.

Level 0 has one node per block: occupancy ``EMPTY`` (outside tile or untouched), ``PARTIAL``
(leaf) or ``FULL`` (inside tile), and the earliest arrival time of material in the block
(+inf when empty; a leaf's minimum over its per-voxel and octant values, i.e. over all its
inside voxels; a tile's minimum octant). Level
k+1 merges 2x2x2 children: EMPTY if all children are, FULL if all are, else PARTIAL, and the
minimum of the children's arrival. A level with an odd size is padded with EMPTY / +inf
nodes (space beyond the table is empty), so any table shape reduces to a single root.

A collision query at time t descends only into nodes with ``min_arrival <= t`` and, for
PARTIAL nodes, down to the leaves; FULL nodes are solid boxes at any depth.
"""

from __future__ import annotations

from dataclasses import dataclass

import numba as nb
import numpy as np

from .sparse import SparseGrid

EMPTY = np.uint8(0)
PARTIAL = np.uint8(1)
FULL = np.uint8(2)


@dataclass(frozen=True, eq=False)
class TreeLevel:
    """Nodes of one level; node (i, j, k) of level k covers blocks ``2^k * (i, j, k)`` onward."""

    occupancy: np.ndarray  # (nx, ny, nz) uint8 EMPTY / PARTIAL / FULL
    min_arrival: np.ndarray  # (nx, ny, nz) float32 seconds, +inf when empty


@dataclass(frozen=True, eq=False)
class BlockTree:
    """Levels from blocks (``levels[0]``) up to a single root node (``levels[-1]``)."""

    levels: tuple[TreeLevel, ...]
    voxel: float
    origin: np.ndarray  # (3,) float64, the grid's

    def node_bounds(self, level: int, ijk: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """World-space (min, max) corners of nodes (n, 3) of ``level``: the cells of their voxels."""
        span = 8 * 2**level
        lo = np.asarray(ijk, np.float64) * span
        corner = self.origin - 0.5 * self.voxel
        return corner + lo * self.voxel, corner + (lo + span) * self.voxel


@nb.njit(cache=True, parallel=True)
def _leaf_min(arr_offset, arrival, leaf_octant_arrival):
    n = arr_offset.shape[0] - 1
    out = np.full(n, np.inf, np.float32)
    for leaf in nb.prange(n):
        a = np.float32(np.inf)
        for q in range(arr_offset[leaf], arr_offset[leaf + 1]):
            a = min(a, arrival[q])
        for ox in range(2):
            for oy in range(2):
                for oz in range(2):
                    a = min(a, leaf_octant_arrival[leaf, ox, oy, oz])
        out[leaf] = a
    return out


@nb.njit(cache=True, parallel=True)
def _merge(occ, arr):
    nx, ny, nz = occ.shape
    mx, my, mz = (nx + 1) // 2, (ny + 1) // 2, (nz + 1) // 2
    out_occ = np.empty((mx, my, mz), np.uint8)
    out_arr = np.empty((mx, my, mz), np.float32)
    for n in nb.prange(mx * my * mz):
        i = n // (my * mz)
        j = (n // mz) % my
        k = n % mz
        n_empty = 0
        n_full = 0
        a = np.float32(np.inf)
        for di in range(2):
            for dj in range(2):
                for dk in range(2):
                    ci, cj, ck = 2 * i + di, 2 * j + dj, 2 * k + dk
                    if ci >= nx or cj >= ny or ck >= nz:
                        n_empty += 1
                        continue
                    o = occ[ci, cj, ck]
                    if o == 0:
                        n_empty += 1
                    elif o == 2:
                        n_full += 1
                    a = min(a, arr[ci, cj, ck])
        out_occ[i, j, k] = 0 if n_empty == 8 else (2 if n_full == 8 else 1)
        out_arr[i, j, k] = a
    return out_occ, out_arr


def block_tree(grid: SparseGrid) -> BlockTree:
    """Build the block hierarchy of ``grid`` (see module docstring)."""
    occ = np.zeros(grid.block.shape, np.uint8)
    arr = np.full(grid.block.shape, np.inf, np.float32)
    lc, tc = grid.leaf_coord, grid.tile_coord
    occ[lc[:, 0], lc[:, 1], lc[:, 2]] = PARTIAL
    arr[lc[:, 0], lc[:, 1], lc[:, 2]] = _leaf_min(grid.arr_offset, grid.arrival, grid.leaf_octant_arrival)
    occ[tc[:, 0], tc[:, 1], tc[:, 2]] = FULL
    arr[tc[:, 0], tc[:, 1], tc[:, 2]] = grid.tile_arrival.reshape(-1, 8).min(axis=1)
    levels = [TreeLevel(occ, arr)]
    while max(levels[-1].occupancy.shape) > 1:
        levels.append(TreeLevel(*_merge(levels[-1].occupancy, levels[-1].min_arrival)))
    return BlockTree(levels=tuple(levels), voxel=grid.voxel, origin=grid.origin.copy())
