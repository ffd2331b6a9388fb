"""The comparison's kernels on two sparse grids of one lattice: block by block, never a box.

The deposit and the CAD part are :class:`~dmdvox.grid.sparse.SparseGrid` on the same voxel
lattice and block table. Every kernel here walks a list of blocks (the union of the two trees'
non-outside blocks, or the CAD's leaves) and decodes at most a block and its faces at a time,
so memory follows the active voxels and the tiles, not the bounding box:

* :func:`block_sums`: per block and per voxel plane along z, the CAD's, the void's and the
  overbuild's sub-voxel volume (in voxels), and the largest distance from a void (overbuild)
  voxel to the deposit (CAD) within that grid's band, flagged where a voxel lies beyond it;
* :func:`crossings`: the CAD surface where it crosses the lattice's edges, the deposit's SDF
  interpolated along those edges, and area weights (see :mod:`.sampling`);
* :func:`block_labels`: the label of every voxel of a block, for the outputs.

Occupancy is ``clamp(0.5 - sdf / voxel, 0, 1)`` per voxel for the CAD; for the deposit, the
material the void analysis counts (:func:`dmdvox.grid.enclosure.cell_empty`: a gap thinner
than a voxel, which the engine keeps, weighs its thickness, not a quarter voxel). Void is
``max(0, f_cad - f_dep)``, overbuild ``max(0, f_dep - f_cad)``.
"""

from __future__ import annotations

import numpy as np
from numba import njit, prange

from ..grid.enclosure import cell_empty
from ..grid.sparse import BLOCK_VOXELS, OUTSIDE, block_sdf_into, sdf_at

LABEL_OUTSIDE = 0
LABEL_BOTH = 1
LABEL_VOID = 2
LABEL_OVERBUILD = 3
LABEL_PORE = 4
LABEL_NAMES = {LABEL_OUTSIDE: "outside both", LABEL_BOTH: "inside both", LABEL_VOID: "void (CAD only)",
               LABEL_OVERBUILD: "overbuild (deposit only)", LABEL_PORE: "pore"}


def union_blocks(dep_block: np.ndarray, cad_block: np.ndarray) -> np.ndarray:
    """(m, 3) int64 coordinates of the blocks where either grid is not outside, in linear order."""
    return np.argwhere((dep_block != OUTSIDE) | (cad_block != OUTSIDE)).astype(np.int64)


@njit(cache=True)
def _low_share(g, i, j, k, q, cut):
    """Of a voxel's part ``q`` (a fraction of its cell) lying on ``g``'s outside, the share below
    ``cut`` (a height in the voxel, 0..1). A surface across the voxel (mostly horizontal) leaves
    that part at the bottom when the solid is above and at the top when it is below; a steeper
    surface spreads it over the voxel's height."""
    gx = np.float64(sdf_at(g, i + 1, j, k) - sdf_at(g, i - 1, j, k))
    gy = np.float64(sdf_at(g, i, j + 1, k) - sdf_at(g, i, j - 1, k))
    gz = np.float64(sdf_at(g, i, j, k + 1) - sdf_at(g, i, j, k - 1))
    if gz * gz < gx * gx + gy * gy:
        return cut
    if gz < 0.0:  # the solid lies above: its outside part at the bottom
        return min(1.0, cut / q)
    return max(0.0, 1.0 - (1.0 - cut) / q)


@njit(parallel=True, cache=True)
def block_sums(dep, cad, blocks, voxel, plane_cut):
    """Per block, for each of its z planes: the CAD's volume, and the void's and the
    overbuild's, each split at the layer boundary the plane may hold (``plane_cut[z]``: its
    height in the plane, 0..1 from the plane's bottom; -1: none): (8, 5) columns CAD, void
    below, void above, overbuild below, overbuild above, in voxels. Also the largest underfill
    (overbuild) depth within the deposit's (CAD's) band, and whether a void (overbuild) voxel
    lies at or beyond that band, where the depth must be measured otherwise.

    Depth at a voxel: at a void voxel centre (inside the CAD, outside the deposit) the deposit's
    SDF there; in a voxel only partly void (a surface crossing it) the thickness of its void
    part, ``(f_cad - f_dep) * voxel`` (the gap between the two surfaces where they run
    parallel through it). So a positive void volume always comes with a positive depth."""
    m = blocks.shape[0]
    sums = np.zeros((m, 8, 5))
    under = np.zeros(m)
    over = np.zeros(m)
    far_under = np.zeros(m, np.bool_)
    far_over = np.zeros(m, np.bool_)
    inv = 1.0 / voxel
    dep_edge = np.float64(dep.band) * (1.0 - 1e-6)
    cad_edge = np.float64(cad.band) * (1.0 - 1e-6)
    for b in prange(m):
        bx, by, bz = blocks[b, 0], blocks[b, 1], blocks[b, 2]
        dv = dep.block[bx, by, bz]
        cv = cad.block[bx, by, bz]
        if dv <= -2 and cv <= -2:  # both solid: CAD volume only
            for lz in range(8):
                sums[b, lz, 0] = 64.0
            continue
        d8 = np.empty(BLOCK_VOXELS, np.float32)
        c8 = np.empty(BLOCK_VOXELS, np.float32)
        block_sdf_into(dep, bx, by, bz, d8)
        block_sdf_into(cad, bx, by, bz, c8)
        for v in range(BLOCK_VOXELS):
            d = np.float64(d8[v])
            c = np.float64(c8[v])
            lz = v & 7
            i, j, k = 8 * bx + (v >> 6), 8 * by + ((v >> 3) & 7), 8 * bz + lz
            # a centre half a voxel or more from the surface is all one side (as cell_empty
            # says too); only the cells the surface crosses need their neighbours
            sd = d * inv
            fd = 0.0 if sd >= 0.5 else 1.0 if sd <= -0.5 else 1.0 - cell_empty(dep, i, j, k, inv)
            fc = min(1.0, max(0.0, 0.5 - c * inv))
            sums[b, lz, 0] += fc
            cut = plane_cut[k]
            if fc > fd:
                q = fc - fd
                low = 1.0 if cut < 0.0 else _low_share(dep, i, j, k, q, cut)
                sums[b, lz, 1] += q * low
                sums[b, lz, 2] += q * (1.0 - low)
                if c < 0.0 and d >= 0.0:
                    under[b] = max(under[b], d)
                    if d >= dep_edge:
                        far_under[b] = True
                else:
                    under[b] = max(under[b], q * voxel)
            elif fd > fc:
                q = fd - fc
                low = 1.0 if cut < 0.0 else _low_share(cad, i, j, k, q, cut)
                sums[b, lz, 3] += q * low
                sums[b, lz, 4] += q * (1.0 - low)
                if d < 0.0 and c >= 0.0:
                    over[b] = max(over[b], c)
                    if c >= cad_edge:
                        far_over[b] = True
                else:
                    over[b] = max(over[b], q * voxel)
    return sums, under, over, far_under, far_over


@njit(cache=True)
def _gradient(g, i, j, k):
    return (0.5 * (sdf_at(g, i + 1, j, k) - sdf_at(g, i - 1, j, k)),
            0.5 * (sdf_at(g, i, j + 1, k) - sdf_at(g, i, j - 1, k)),
            0.5 * (sdf_at(g, i, j, k + 1) - sdf_at(g, i, j, k - 1)))


@njit(parallel=True, cache=True)
def crossings(surface, other, leaf_coord):
    """Points (index space) where ``surface`` crosses zero along lattice edges starting in its
    leaves (a crossing lies in the surface grid's narrow band, so in a leaf), ``other``
    interpolated there, and area weights (:mod:`.sampling`)."""
    n_leaf = leaf_coord.shape[0]
    dummy_points = np.empty((0, 3))
    dummy = np.empty(0)
    counts = np.zeros(n_leaf, np.int64)
    for leaf in prange(n_leaf):
        counts[leaf] = _crossings_at(surface, other, leaf_coord, leaf, dummy_points, dummy, dummy, 0, False)
    starts = np.zeros(n_leaf + 1, np.int64)
    for leaf in range(n_leaf):
        starts[leaf + 1] = starts[leaf] + counts[leaf]
    points = np.empty((starts[n_leaf], 3))
    values = np.empty(starts[n_leaf])
    weights = np.empty(starts[n_leaf])
    for leaf in prange(n_leaf):
        _crossings_at(surface, other, leaf_coord, leaf, points, values, weights, starts[leaf], True)
    return points, values, weights


@njit(cache=True)
def _crossings_at(surface, other, leaf_coord, leaf, out_points, out_values, out_weights, start, write):
    n = start
    bx, by, bz = leaf_coord[leaf, 0], leaf_coord[leaf, 1], leaf_coord[leaf, 2]
    # the leaf decoded once, with the first plane of its three upper neighbours: a rank lookup
    # per edge end costs four times as much
    local = np.empty((9, 9, 9), np.float32)
    flat = np.empty(BLOCK_VOXELS, np.float32)
    block_sdf_into(surface, bx, by, bz, flat)
    for v in range(BLOCK_VOXELS):
        local[v >> 6, (v >> 3) & 7, v & 7] = flat[v]
    for p in range(8):
        for q in range(8):
            local[8, p, q] = sdf_at(surface, 8 * bx + 8, 8 * by + p, 8 * bz + q)
            local[p, 8, q] = sdf_at(surface, 8 * bx + p, 8 * by + 8, 8 * bz + q)
            local[p, q, 8] = sdf_at(surface, 8 * bx + p, 8 * by + q, 8 * bz + 8)
    for v in range(BLOCK_VOXELS):
        li, lj, lk = v >> 6, (v >> 3) & 7, v & 7
        i = 8 * bx + li
        j = 8 * by + lj
        k = 8 * bz + lk
        a = np.float64(local[li, lj, lk])
        for axis in range(3):
            bi, bj, bk = i, j, k
            if axis == 0:
                bi += 1
                b = np.float64(local[li + 1, lj, lk])
            elif axis == 1:
                bj += 1
                b = np.float64(local[li, lj + 1, lk])
            else:
                bk += 1
                b = np.float64(local[li, lj, lk + 1])
            if (a < 0.0) == (b < 0.0):
                continue
            if write:
                t = a / (a - b)
                out_points[n, 0] = i + t * (bi - i)
                out_points[n, 1] = j + t * (bj - j)
                out_points[n, 2] = k + t * (bk - k)
                oa = np.float64(sdf_at(other, i, j, k))
                ob = np.float64(sdf_at(other, bi, bj, bk))
                out_values[n] = oa + t * (ob - oa)
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
def block_labels(dep, cad, blocks, pore):
    """(m, 512) uint8 labels of the blocks' voxels (v order); ``pore`` flags, per block and
    voxel, the enclosed voids' voxels (those whose centre lies outside the deposit are pore)."""
    m = blocks.shape[0]
    out = np.empty((m, BLOCK_VOXELS), np.uint8)
    for b in prange(m):
        d8 = np.empty(BLOCK_VOXELS, np.float32)
        c8 = np.empty(BLOCK_VOXELS, np.float32)
        block_sdf_into(dep, blocks[b, 0], blocks[b, 1], blocks[b, 2], d8)
        block_sdf_into(cad, blocks[b, 0], blocks[b, 1], blocks[b, 2], c8)
        for v in range(BLOCK_VOXELS):
            din = d8[v] < 0.0
            cin = c8[v] < 0.0
            if pore[b, v] and not din:
                out[b, v] = LABEL_PORE
            elif din and cin:
                out[b, v] = LABEL_BOTH
            elif cin:
                out[b, v] = LABEL_VOID
            elif din:
                out[b, v] = LABEL_OVERBUILD
            else:
                out[b, v] = LABEL_OUTSIDE
    return out
