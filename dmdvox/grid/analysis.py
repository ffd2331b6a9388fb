"""Deposit volume and enclosed pores of a :class:`SparseGrid`.

Sub-voxel occupancy
    A voxel is counted as ``clamp(0.5 - sdf / voxel, 0, 1)`` full: the fraction of its cell
    below a plane at the stored distance. It is exact for grid-aligned planes (a face through
    voxel centres gives 0.5 to each centre voxel, so CAD faces at round coordinates are not
    biased) and second-order accurate for curved surfaces. Inactive voxels are exactly 0 or 1.

Pores
    Outside space is split into nodes: one node per outside tile (untouched blocks included,
    512 voxels at once) and, per leaf, one node per 6-connected component of its outside
    voxels (labelled in parallel, leaf by leaf, into a temporary uint16 label per leaf voxel:
    1 KB per leaf, about half the grid's own size). A sequential union-find then joins nodes
    across block faces (tile-tile, tile-leaf, leaf-leaf voxel pairs) and to an exterior node:
    space beyond the block table is exterior, so anything reaching the table's boundary is not
    a pore. Components other than the exterior's are pores.

    A pore's volume uses the same fractions as :func:`volume`: each of its outside voxels gives
    its outside fraction, and each inside voxel whose cell is partly empty gives its outside
    fraction to the component of its first outside face neighbour (order -x, +x, -y, +y, -z,
    +z). Deposit volume + pore volumes + exterior volume therefore add up to the table volume
    (up to inside voxels with no outside face neighbour, whose small remainder is dropped).
    Pore statistics are accumulated sequentially over the few leaves that touch a pore, so
    results do not depend on the thread count.
"""

from __future__ import annotations

from dataclasses import dataclass

import numba as nb
import numpy as np

from .sparse import BLOCK_VOXELS, OUTSIDE, SparseGrid, bit_is_set

_NO_LABEL = np.uint16(0xFFFF)


@nb.njit(cache=True, parallel=True)
def _leaf_fill(leaf_active, leaf_inside, sdf_offset, sdf, inv_voxel):
    """Per leaf: the sum of inside fractions, in voxels (one leaf per iteration: deterministic)."""
    n = leaf_active.shape[0]
    out = np.zeros(n, np.float64)
    for leaf in nb.prange(n):
        k = sdf_offset[leaf]
        act = leaf_active[leaf]
        ins = leaf_inside[leaf]
        acc = 0.0
        for v in range(BLOCK_VOXELS):
            if bit_is_set(act, v):
                acc += min(max(0.5 - np.float64(sdf[k]) * inv_voxel, 0.0), 1.0)
                k += 1
            elif bit_is_set(ins, v):
                acc += 1.0
        out[leaf] = acc
    return out


def volume(grid: SparseGrid) -> float:
    """Deposit volume in mm^3 from the sub-voxel occupancy of every voxel (module docstring)."""
    per_leaf = _leaf_fill(grid.leaf_active, grid.leaf_inside, grid.sdf_offset, grid.sdf, 1.0 / grid.voxel)
    voxels = float(np.sum(per_leaf)) + BLOCK_VOXELS * grid.n_tile
    return voxels * grid.voxel**3


@dataclass(frozen=True, eq=False)
class Pore:
    """One enclosed cavity. ``bbox_mm`` is (2, 3): min and max corners of its outside voxel cells."""

    volume_mm3: float
    centroid_mm: np.ndarray  # (3,) float64
    bbox_mm: np.ndarray  # (2, 3) float64
    equivalent_diameter_mm: float


@dataclass(frozen=True, eq=False)
class Porosity:
    """Pores sorted by descending volume, and the porosity of the deposit."""

    pores: tuple[Pore, ...]
    deposit_volume_mm3: float
    pore_volume_mm3: float
    porosity_percent: float  # 100 * pore / (deposit + pore)


@nb.njit(cache=True, inline="always")
def _find(parent, x):
    root = x
    while parent[root] != root:
        root = parent[root]
    while parent[x] != root:
        nxt = parent[x]
        parent[x] = root
        x = nxt
    return root


@nb.njit(cache=True, inline="always")
def _union(parent, a, b):
    ra = _find(parent, a)
    rb = _find(parent, b)
    # the smaller id becomes the root, so roots do not depend on the order of unions
    if ra < rb:
        parent[rb] = ra
    elif rb < ra:
        parent[ra] = rb


@nb.njit(cache=True, parallel=True)
def _label_leaves(leaf_inside):
    """6-connected components of each leaf's outside voxels: labels (n_leaf, 512), counts."""
    n = leaf_inside.shape[0]
    labels = np.empty((n, BLOCK_VOXELS), np.uint16)
    counts = np.zeros(n, np.int64)
    for leaf in nb.prange(n):
        ins = leaf_inside[leaf]
        parent = np.empty(BLOCK_VOXELS, np.int64)
        for v in range(BLOCK_VOXELS):
            parent[v] = v
        for v in range(BLOCK_VOXELS):
            if bit_is_set(ins, v):
                continue
            if (v >> 6) > 0 and not bit_is_set(ins, v - 64):
                _union(parent, v, v - 64)
            if ((v >> 3) & 7) > 0 and not bit_is_set(ins, v - 8):
                _union(parent, v, v - 8)
            if (v & 7) > 0 and not bit_is_set(ins, v - 1):
                _union(parent, v, v - 1)
        lab = labels[leaf]
        c = 0
        for v in range(BLOCK_VOXELS):
            if bit_is_set(ins, v):
                lab[v] = _NO_LABEL
            else:
                r = _find(parent, v)
                if r == v:
                    lab[v] = c
                    c += 1
                else:
                    lab[v] = lab[r]  # r < v, so it is already labelled
        counts[leaf] = c
    return labels, counts


@nb.njit(cache=True, inline="always")
def _face_voxel(axis, layer, a, b):
    """Local index of the voxel at ``layer`` along ``axis`` and (a, b) on the other two axes."""
    if axis == 0:
        return layer * 64 + a * 8 + b
    if axis == 1:
        return a * 64 + layer * 8 + b
    return a * 64 + b * 8 + layer


@nb.njit(cache=True)
def _connect(block, leaf_coord, labels, comp_off):
    """Union-find over outside nodes; returns the fully compressed root of every node.

    Nodes: blocks by linear index (only outside tiles are ever joined), the exterior node
    ``nb``, then leaf components ``nb + 1 + comp_off[leaf] + label``.
    """
    nx, ny, nz = block.shape
    nblk = nx * ny * nz
    ext = nblk
    base = nblk + 1
    parent = np.arange(base + comp_off[-1])
    for bx in range(nx):
        for by in range(ny):
            for bz in range(nz):
                if block[bx, by, bz] != OUTSIDE:
                    continue
                b = (bx * ny + by) * nz + bz
                if bx == 0 or by == 0 or bz == 0 or bx == nx - 1 or by == ny - 1 or bz == nz - 1:
                    _union(parent, b, ext)
                if bx + 1 < nx and block[bx + 1, by, bz] == OUTSIDE:
                    _union(parent, b, b + ny * nz)
                if by + 1 < ny and block[bx, by + 1, bz] == OUTSIDE:
                    _union(parent, b, b + nz)
                if bz + 1 < nz and block[bx, by, bz + 1] == OUTSIDE:
                    _union(parent, b, b + 1)
    dims = np.array([nx, ny, nz])
    nbr = np.empty(3, np.int64)
    for leaf in range(leaf_coord.shape[0]):
        lab = labels[leaf]
        node0 = base + comp_off[leaf]
        for axis in range(3):
            for side in range(2):
                for q in range(3):
                    nbr[q] = leaf_coord[leaf, q]
                nbr[axis] += 1 if side == 1 else -1
                layer = 7 if side == 1 else 0
                if nbr[axis] < 0 or nbr[axis] >= dims[axis]:
                    target = ext
                else:
                    val = block[nbr[0], nbr[1], nbr[2]]
                    if val == OUTSIDE:
                        target = (nbr[0] * ny + nbr[1]) * nz + nbr[2]
                    elif val >= 0 and side == 1:
                        # leaf-leaf faces are joined once, from the lower leaf
                        other = labels[val]
                        node1 = base + comp_off[val]
                        for a in range(8):
                            for b in range(8):
                                la = lab[_face_voxel(axis, 7, a, b)]
                                lb = other[_face_voxel(axis, 0, a, b)]
                                if la != _NO_LABEL and lb != _NO_LABEL:
                                    _union(parent, node0 + la, node1 + lb)
                        continue
                    else:
                        continue
                for a in range(8):
                    for b in range(8):
                        la = lab[_face_voxel(axis, layer, a, b)]
                        if la != _NO_LABEL:
                            _union(parent, node0 + la, target)
    for x in range(parent.shape[0]):
        parent[x] = _find(parent, x)
    return parent


@nb.njit(cache=True)
def _number_pores(block, root, comp_off):
    """Pore id per node (-1: exterior or not an outside node), numbered by first node."""
    nblk = block.size
    ext_root = root[nblk]
    flat = block.reshape(nblk)
    pore_of_root = np.full(root.shape[0], -1, np.int64)
    pid = np.full(root.shape[0], -1, np.int64)
    n = 0
    for x in range(root.shape[0]):
        if x < nblk and flat[x] != OUTSIDE:
            continue
        r = root[x]
        if r == ext_root:
            continue
        if pore_of_root[r] < 0:
            pore_of_root[r] = n
            n += 1
        pid[x] = pore_of_root[r]
    return pid, n


@nb.njit(cache=True, parallel=True)
def _leaves_near_pores(block, leaf_coord, comp_off, counts, pid):
    """Leaves that own a pore component or touch a pore node across a face."""
    nx, ny, nz = block.shape
    base = block.size + 1
    n = leaf_coord.shape[0]
    own = np.zeros(n, np.bool_)
    for leaf in nb.prange(n):
        for c in range(counts[leaf]):
            if pid[base + comp_off[leaf] + c] >= 0:
                own[leaf] = True
    flag = own.copy()
    for leaf in nb.prange(n):
        if flag[leaf]:
            continue
        for axis in range(3):
            for step in (-1, 1):
                c = leaf_coord[leaf].astype(np.int64)
                c[axis] += step
                if c[0] < 0 or c[1] < 0 or c[2] < 0 or c[0] >= nx or c[1] >= ny or c[2] >= nz:
                    continue
                val = block[c[0], c[1], c[2]]
                if val >= 0 and own[val]:
                    flag[leaf] = True
                elif val == OUTSIDE and pid[(c[0] * ny + c[1]) * nz + c[2]] >= 0:
                    flag[leaf] = True
    return flag


@nb.njit(cache=True)
def _pore_stats(block, leaf_coord, leaf_active, leaf_inside, sdf_offset, sdf, labels, comp_off, pid, n_pore, leaves,
                inv_voxel):
    """Per pore: volume (voxels), weighted index sums, index bbox; sequential for determinism."""
    nx, ny, nz = block.shape
    base = block.size + 1
    vol = np.zeros(n_pore, np.float64)
    csum = np.zeros((n_pore, 3), np.float64)
    lo = np.full((n_pore, 3), np.iinfo(np.int64).max, np.int64)
    hi = np.full((n_pore, 3), np.iinfo(np.int64).min, np.int64)
    for bx in range(nx):
        for by in range(ny):
            for bz in range(nz):
                if block[bx, by, bz] != OUTSIDE:
                    continue
                p = pid[(bx * ny + by) * nz + bz]
                if p < 0:
                    continue
                vol[p] += BLOCK_VOXELS
                csum[p, 0] += BLOCK_VOXELS * (8.0 * bx + 3.5)
                csum[p, 1] += BLOCK_VOXELS * (8.0 * by + 3.5)
                csum[p, 2] += BLOCK_VOXELS * (8.0 * bz + 3.5)
                g = (8 * bx, 8 * by, 8 * bz)
                for q in range(3):
                    lo[p, q] = min(lo[p, q], g[q])
                    hi[p, q] = max(hi[p, q], g[q] + 7)
    ijk = np.empty(3, np.int64)
    nijk = np.empty(3, np.int64)
    for leaf in leaves:
        act = leaf_active[leaf]
        ins = leaf_inside[leaf]
        lab = labels[leaf]
        k = sdf_offset[leaf]
        for v in range(BLOCK_VOXELS):
            is_act = bit_is_set(act, v)
            s = np.float64(sdf[k]) if is_act else 0.0
            if is_act:
                k += 1
            ijk[0] = 8 * leaf_coord[leaf, 0] + (v >> 6)
            ijk[1] = 8 * leaf_coord[leaf, 1] + ((v >> 3) & 7)
            ijk[2] = 8 * leaf_coord[leaf, 2] + (v & 7)
            if not bit_is_set(ins, v):
                p = pid[base + comp_off[leaf] + lab[v]]
                if p < 0:
                    continue
                f = min(max(0.5 + s * inv_voxel, 0.0), 1.0) if is_act else 1.0
                for q in range(3):
                    lo[p, q] = min(lo[p, q], ijk[q])
                    hi[p, q] = max(hi[p, q], ijk[q])
            else:
                if not is_act:
                    continue
                f = 0.5 + s * inv_voxel
                if f <= 0.0:
                    continue
                p = -1
                for d in range(6):
                    axis = d >> 1
                    for q in range(3):
                        nijk[q] = ijk[q]
                    nijk[axis] += 1 if (d & 1) else -1
                    bi, bj, bk = nijk[0] >> 3, nijk[1] >> 3, nijk[2] >> 3
                    if nijk[0] < 0 or nijk[1] < 0 or nijk[2] < 0 or bi >= nx or bj >= ny or bk >= nz:
                        break  # the exterior
                    val = block[bi, bj, bk]
                    if val == OUTSIDE:
                        p = pid[(bi * ny + bj) * nz + bk]
                        break
                    if val >= 0:
                        nv = (nijk[0] & 7) * 64 + (nijk[1] & 7) * 8 + (nijk[2] & 7)
                        if not bit_is_set(leaf_inside[val], nv):
                            p = pid[base + comp_off[val] + labels[val, nv]]
                            break
                if p < 0:
                    continue
            vol[p] += f
            for q in range(3):
                csum[p, q] += f * ijk[q]
    return vol, csum, lo, hi


def porosity(grid: SparseGrid) -> Porosity:
    """Enclosed pores (6-connected outside space not reaching the table boundary) and porosity."""
    labels, counts = _label_leaves(grid.leaf_inside)
    comp_off = np.zeros(grid.n_leaf + 1, np.int64)
    np.cumsum(counts, out=comp_off[1:])
    root = _connect(grid.block, grid.leaf_coord, labels, comp_off)
    pid, n_pore = _number_pores(grid.block, root, comp_off)
    deposit = volume(grid)
    if n_pore == 0:
        return Porosity(pores=(), deposit_volume_mm3=deposit, pore_volume_mm3=0.0, porosity_percent=0.0)
    leaves = np.flatnonzero(_leaves_near_pores(grid.block, grid.leaf_coord, comp_off, counts, pid))
    vol, csum, lo, hi = _pore_stats(
        grid.block, grid.leaf_coord, grid.leaf_active, grid.leaf_inside, grid.sdf_offset, grid.sdf,
        labels, comp_off, pid, n_pore, leaves, 1.0 / grid.voxel,
    )
    v3 = grid.voxel**3
    centroid = grid.index_to_world(csum / vol[:, None])
    lo_w = grid.index_to_world(lo) - 0.5 * grid.voxel
    hi_w = grid.index_to_world(hi) + 0.5 * grid.voxel
    # descending volume; ties broken by bbox corner so the order never depends on node numbering
    order = np.lexsort((lo[:, 2], lo[:, 1], lo[:, 0], -vol))
    pores = tuple(
        Pore(
            volume_mm3=float(vol[p] * v3),
            centroid_mm=centroid[p],
            bbox_mm=np.stack([lo_w[p], hi_w[p]]),
            equivalent_diameter_mm=float((6.0 * vol[p] * v3 / np.pi) ** (1.0 / 3.0)),
        )
        for p in order
    )
    pore_volume = float(np.sum(vol) * v3)
    return Porosity(
        pores=pores,
        deposit_volume_mm3=deposit,
        pore_volume_mm3=pore_volume,
        porosity_percent=100.0 * pore_volume / (deposit + pore_volume),
    )


def pores(grid: SparseGrid) -> list[Pore]:
    """Enclosed pores sorted by descending volume (see :func:`porosity`)."""
    return list(porosity(grid).pores)


@nb.njit(cache=True)
def _inside_index_bounds(block, leaf_coord, leaf_inside):
    lo = np.full(3, np.iinfo(np.int64).max, np.int64)
    hi = np.full(3, np.iinfo(np.int64).min, np.int64)
    nx, ny, nz = block.shape
    for bx in range(nx):
        for by in range(ny):
            for bz in range(nz):
                if block[bx, by, bz] <= -2:  # inside tile: all of it
                    base = (8 * bx, 8 * by, 8 * bz)
                    for q in range(3):
                        lo[q] = min(lo[q], base[q])
                        hi[q] = max(hi[q], base[q] + 7)
    for leaf in range(leaf_coord.shape[0]):
        for v in range(512):
            if bit_is_set(leaf_inside[leaf], v):
                ijk = (8 * leaf_coord[leaf, 0] + (v >> 6), 8 * leaf_coord[leaf, 1] + ((v >> 3) & 7),
                       8 * leaf_coord[leaf, 2] + (v & 7))
                for q in range(3):
                    lo[q] = min(lo[q], ijk[q])
                    hi[q] = max(hi[q], ijk[q])
    return lo, hi


def deposit_bbox(grid: SparseGrid) -> np.ndarray:
    """``[[xmin,ymin,zmin],[xmax,ymax,zmax]]`` of the inside voxels' cells (to a voxel)."""
    lo, hi = _inside_index_bounds(grid.block, grid.leaf_coord, grid.leaf_inside)
    if lo[0] > hi[0]:
        return np.zeros((2, 3))
    return np.stack([grid.index_to_world(lo) - 0.5 * grid.voxel, grid.index_to_world(hi) + 0.5 * grid.voxel])
