"""The void search of :mod:`enclosure` tile by tile: slabs of block columns (x) searched as
separate tasks (on a cluster's workers), merged through a small boundary graph.

Everything the search does per voxel but the two connected-component labellings reaches a
bounded distance: the classes read a voxel around, the clearance beyond the band reaches
``s/2 + 2`` voxels, the reach from the exterior ``R`` (and its direct lookups as far again).
So a tile searched together with a halo of whole block columns sees, in its core, the voxels
the whole grid's search sees, and only the components need the other tiles:

1. *Exterior centres.* Per tile, the ball centres of its core are labelled (6-connected, open
   whole tiles as one node each, the table's boundary as the exterior node). Each tile hands
   back its two x faces (per voxel: its component, exterior, or none) and the voxels of the
   components not already exterior within the tile (internal cavities and those that reach
   across a face: few). The client joins the faces' label pairs by union-find: which of those
   components reach the exterior through the other tiles.
2. *Reach and voids.* Per tile again (same halo widened by the reach), the exterior centres
   are those of step 1 (every centre but the enclosed components' voxels), the reach runs as
   in :func:`enclosure.enclosed_voids`, and the enclosed voxels of the core are labelled and
   joined across faces the same way. The components that never meet the exterior are the
   voids; the tiles hand back their voxels' empty fractions, and the client sums them in the
   whole grid's work-block order, so volumes, centroids and the numbering are the local
   search's to the bit.

Without a bead width (no channel rule) the reach is unlimited: no halo bounds it, and the
search runs on the whole grid (:func:`tiled_voids` says so by running it).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numba as nb
import numpy as np

from ..tasks import cluster_threads, map_tasks
from . import enclosure as enc
from .enclosure import Voids
from .sparse import BLOCK, BLOCK_VOXELS, SparseGrid

TILES_PER_THREAD = 2  # tiles per worker thread (as the sweep's chunks)
_NONE = -1  # face / label entry: no member voxel
_EXT = -2  # face entry: a component exterior within its tile


def halo_blocks(r_vox: float, reach_vox: float, band_vox: float) -> tuple[int, int]:
    """Block columns each side of a tile's core for the two steps (module docstring): step 1's
    classes exact in the core (the outside tiles the rule sees within ``rings`` of a leaf, a
    voxel of neighbours, the clearance's ``s/2 + 3``), step 2's as far again as two reaches
    (a path of the reach from a voxel reached directly, itself ``R`` from its centre)."""
    rings = max(0, int(math.ceil((r_vox - 0.5) / 8.0))) if r_vox > band_vox - 1e-6 else 0
    first = max(1, rings) + int(math.ceil((r_vox + 3.0) / BLOCK))
    return first, first + int(math.ceil((2.0 * reach_vox + 3.0) / BLOCK))


@dataclass(frozen=True, eq=False)
class VoidTile:
    """One task: the grid's blocks ``lo <= bx < hi`` in the whole table (the rest outside
    tiles), the core ``bx0 <= bx < bx1``; step 2 also carries the enclosed centres around it
    (``enclosed_coord`` blocks with ``enclosed_mask`` voxels, ``enclosed_tiles`` whole tiles)."""

    grid: SparseGrid
    bx0: int
    bx1: int
    zp: float
    r_vox: float
    reach_vox: float
    band_vox: float
    enclosed_coord: np.ndarray | None = None
    enclosed_mask: np.ndarray | None = None
    enclosed_tiles: np.ndarray | None = None


@dataclass(frozen=True, eq=False)
class TileComponents:
    """A tile's components not exterior within it: ``n`` of them; ``lower`` / ``upper`` its x
    faces (``(ny*8, nz*8)`` int32: component, ``_EXT`` or ``_NONE``; None at the table's edge);
    ``coord`` / ``label`` its core blocks holding their voxels (per voxel a component or -1),
    ``leaf`` whether each is a leaf; ``tiles`` / ``tile_label`` whole tiles in them; step 2 adds
    ``frac`` (empty fractions) and ``centre`` (ball centres) of those blocks."""

    n: int
    lower: np.ndarray | None
    upper: np.ndarray | None
    coord: np.ndarray
    label: np.ndarray
    leaf: np.ndarray
    tiles: np.ndarray
    tile_label: np.ndarray
    frac: np.ndarray | None = None
    centre: np.ndarray | None = None


def _prepared(task: VoidTile):
    grid = task.grid
    wid, wcoord, tile_open = enc._work_blocks(grid, task.zp, task.r_vox, task.band_vox)
    n_work = wcoord.shape[0]
    state = np.empty((n_work, BLOCK_VOXELS), np.uint8)
    dep = np.empty((n_work, BLOCK_VOXELS), np.float32)
    packed = (grid.view(), 1.0 / grid.voxel, task.band_vox, task.zp)
    enc._classify(wcoord, *packed, task.r_vox, state, dep)
    if task.r_vox > task.band_vox - 1e-6:
        enc._extend_clearance(wid, wcoord, state, dep, task.band_vox, task.r_vox, grid.n_leaf, False)
    return wid, wcoord, tile_open, state, dep, packed


def _core_components(task: VoidTile, wid, wcoord, member, tile_member, n_leaf, packed=None, state=None):
    """Label the members of the core (module docstring) and hand back what the merge needs."""
    nx, ny, nz = wid.shape
    nblk = wid.size
    bx0, bx1 = task.bx0, task.bx1
    core = np.flatnonzero((wcoord[:, 0] >= bx0) & (wcoord[:, 0] < bx1))
    # the core alone: blocks beyond it are neither work blocks nor member tiles, so nothing
    # joins through them and only the table's own boundary is the exterior node
    wid_core = np.full(wid.shape, -1, np.int32)
    wid_core[bx0:bx1] = wid[bx0:bx1]
    renumber = np.full(wcoord.shape[0], -1, np.int32)
    renumber[core] = np.arange(core.size, dtype=np.int32)
    work = wid_core >= 0
    wid_core[work] = renumber[wid_core[work]]
    tm = np.zeros(wid.shape, bool)
    tm[bx0:bx1] = tile_member.reshape(wid.shape)[bx0:bx1]
    tm = tm.reshape(-1)
    labels, counts = enc._label_blocks(np.ascontiguousarray(member[core]))
    comp_off = np.zeros(core.size + 1, np.int64)
    np.cumsum(counts, out=comp_off[1:])
    root = enc._connect(wid_core, tm, np.ascontiguousarray(wcoord[core]), labels, comp_off)
    ext = root[nblk]
    tile_nodes = np.flatnonzero(tm & (wid_core.reshape(-1) == -1))
    nodes = np.concatenate([tile_nodes, nblk + 1 + np.arange(comp_off[-1])])
    roots = root[nodes]
    mine = roots != ext
    kept, local = np.unique(roots[mine], return_inverse=True)
    node_label = np.full(nodes.size, _EXT, np.int64)
    node_label[mine] = local
    n_tile = tile_nodes.size
    tile_label = node_label[:n_tile]
    comp_label = node_label[n_tile:]
    # per core block and voxel: component, _EXT or _NONE
    block_label = np.full(labels.shape, _NONE, np.int64)
    has = labels != enc._NO_LABEL
    block_label[has] = comp_label[(comp_off[:-1, None] + labels.astype(np.int64))[has]]

    def face(bx, layer):
        if bx < 0 or bx >= nx:
            return None
        out = np.full((ny, nz, BLOCK, BLOCK), _NONE, np.int32)
        at = np.flatnonzero(wcoord[core, 0] == bx)
        out[wcoord[core[at], 1], wcoord[core[at], 2]] = block_label[at].reshape(-1, BLOCK, BLOCK, BLOCK)[:, layer]
        tiles = tile_nodes[tile_nodes // (ny * nz) == bx]
        out[(tiles // nz) % ny, tiles % nz] = node_label[np.searchsorted(tile_nodes, tiles)][:, None, None]
        return out.transpose(0, 2, 1, 3).reshape(ny * BLOCK, nz * BLOCK)

    lower = face(bx0, 0) if bx0 > 0 else None
    upper = face(bx1 - 1, BLOCK - 1) if bx1 < nx else None
    block_label[block_label == _EXT] = _NONE
    held = np.flatnonzero(np.any(block_label >= 0, axis=1))
    works = core[held]
    open_tiles = tile_label >= 0
    out = TileComponents(
        n=int(kept.size), lower=lower, upper=upper, coord=wcoord[works].astype(np.int32),
        label=block_label[held].astype(np.int32), leaf=works < n_leaf, tiles=tile_nodes[open_tiles],
        tile_label=tile_label[open_tiles].astype(np.int32))
    if packed is None:
        return out
    frac = enc._fractions(works.astype(np.int64), wcoord, *packed)
    centre = (state[works] & enc.CLASS_MASK) == enc.CENTRE
    return TileComponents(**{**out.__dict__, "frac": frac, "centre": centre})


def exterior_step(task: VoidTile) -> TileComponents:
    """Step 1 on one tile: its ball centres' components (module docstring)."""
    wid, wcoord, tile_open, state, _, _ = _prepared(task)
    return _core_components(task, wid, wcoord, state == enc.CENTRE, tile_open, task.grid.n_leaf)


def void_step(task: VoidTile) -> TileComponents:
    """Step 2 on one tile: the reach from the exterior and the enclosed voxels' components."""
    wid, wcoord, tile_open, state, dep, packed = _prepared(task)
    centre = (state & enc.CLASS_MASK) == enc.CENTRE
    state[centre] |= enc.EXTERIOR
    if task.enclosed_coord is not None and task.enclosed_coord.shape[0]:
        at = wid[tuple(task.enclosed_coord.T)]
        ok = at >= 0
        rows = at[ok]
        state[rows] &= np.where(task.enclosed_mask[ok], ~enc.EXTERIOR, 0xFF).astype(np.uint8)
    tile_ext = tile_open.copy()
    if task.enclosed_tiles is not None:
        tile_ext[task.enclosed_tiles] = False
    enc._reach(wid, wcoord, state, dep, tile_open, tile_ext, task.zp, task.r_vox, task.reach_vox, task.band_vox,
               False)
    del dep
    member = enc._enclosed_members(state)
    return _core_components(task, wid, wcoord, member, tile_open & ~tile_ext, task.grid.n_leaf, packed, state)


def _merge(parts: list[TileComponents]) -> tuple[np.ndarray, list[np.ndarray]]:
    """Union-find over the tiles' components joined across their faces: per tile, whether each
    of its components meets the exterior, and the global component of each."""
    offset = np.zeros(len(parts) + 1, np.int64)
    np.cumsum([p.n for p in parts], out=offset[1:])
    pairs = [np.zeros((0, 2), np.int64)]
    for t in range(len(parts) - 1):
        a, b = parts[t].upper, parts[t + 1].lower
        both = (a != _NONE) & (b != _NONE)
        na = np.where(a[both] == _EXT, 0, 1 + offset[t] + a[both])
        nb_ = np.where(b[both] == _EXT, 0, 1 + offset[t + 1] + b[both])
        if na.size:
            pairs.append(np.unique(np.stack([na, nb_], axis=1), axis=0))
    root = _union_pairs(int(offset[-1]) + 1, np.concatenate(pairs))
    return root, [root[1 + offset[t]:1 + offset[t + 1]] for t in range(len(parts))]


@nb.njit(cache=True)
def _union_pairs(n, pairs):
    parent = np.arange(n)
    for q in range(pairs.shape[0]):
        enc._union(parent, pairs[q, 0], pairs[q, 1])
    for x in range(n):
        parent[x] = enc._find(parent, x)
    return parent


@nb.njit(cache=True)
def _void_stats(tile_lin, tile_void, coord, void, frac, centre, n_void, shape):
    """:func:`enclosure._void_stats` over the merged tiles' voxels, given in the whole grid's
    order (whole tiles by linear index, then work blocks: leaves, then outside tiles, each by
    linear index): the same sums in the same order. Voids are numbered at their first node
    in that order, as :func:`enclosure._number` numbers them."""
    ny, nz = shape[1], shape[2]
    number = np.full(n_void, -1, np.int64)
    n = 0
    vol = np.zeros(n_void)
    csum = np.zeros((n_void, 3))
    lo = np.full((n_void, 3), np.iinfo(np.int64).max, np.int64)
    hi = np.full((n_void, 3), np.iinfo(np.int64).min, np.int64)
    count = np.zeros(n_void, np.int64)
    wide = np.zeros(n_void, np.bool_)
    for t in range(tile_lin.shape[0]):
        g = tile_void[t]
        if number[g] < 0:
            number[g] = n
            n += 1
        p = number[g]
        lin = tile_lin[t]
        bx, by, bz = lin // (ny * nz), (lin // nz) % ny, lin % nz
        enc._add_whole_tile(p, bx, by, bz, vol, csum, lo, hi, count, wide)
    for i in range(coord.shape[0]):
        for v in range(BLOCK_VOXELS):
            g = void[i, v]
            if g < 0:
                continue
            if number[g] < 0:
                number[g] = n
                n += 1
            p = number[g]
            if centre[i, v]:
                wide[p] = True
            f = frac[i, v]
            if f <= enc._MIN_PARTIAL:
                continue
            enc._add_voxel(p, f, coord[i], v, vol, csum, lo, hi, count)
    return number, vol, csum, lo, hi, count, wide


def plan_tiles(grid: SparseGrid, n_tiles: int) -> list[tuple[int, int]]:
    """Core x ranges ``(bx0, bx1)``: ``n_tiles`` runs of block columns with about equal leaves
    (the work follows the part), at most one per column."""
    nx = grid.block.shape[0]
    per_column = np.bincount(grid.leaf_coord[:, 0], minlength=nx).astype(np.float64) + 1.0
    cut = np.searchsorted(np.cumsum(per_column), per_column.sum() * np.arange(1, n_tiles) / n_tiles, side="right")
    edges = np.unique(np.concatenate([[0], np.clip(cut, 1, nx - 1), [nx]]))
    return [(int(a), int(b)) for a, b in zip(edges[:-1], edges[1:])]


def _slab(grid: SparseGrid, lo: int, hi: int) -> SparseGrid:
    """The blocks ``lo <= bx < hi`` in the whole table (the others outside tiles)."""
    return grid.crop_x(lo, hi).widened(grid.origin, grid.block_shape)


def tiled_voids(grid: SparseGrid, plate_z: float | None = None, bead_width: float | None = None, *,
                tiles: int | None = None, scheduler: str | None = None, processes: int | None = 0) -> Voids:
    """:func:`enclosure.enclosed_voids` (same arguments, the same voids to the bit) searched in
    x tiles (module docstring): ``tiles`` of them (default: ``TILES_PER_THREAD`` per thread of
    the cluster at ``scheduler``, else one per process), run as :func:`tasks.map_tasks` runs
    tasks. Without a bead width the whole grid is searched at once."""
    if bead_width is None:
        return enc.enclosed_voids(grid, plate_z=plate_z)
    v = float(grid.voxel)
    if plate_z is None:
        plate_z = enc.lowest_deposit_z(grid)
    plate_z = float(plate_z)
    zp = (plate_z - grid.origin[2]) / v if np.isfinite(plate_z) else -np.inf
    channel = enc.CHANNEL_FRACTION * float(bead_width)
    if not (math.isfinite(channel) and channel >= 0):
        raise ValueError(f"bead width must be a non-negative length, got {bead_width!r}")
    if channel == 0:
        return enc.enclosed_voids(grid, plate_z=plate_z, bead_width=bead_width)
    r_vox = 0.5 * channel / v
    band_vox = float(np.float32(grid.band)) / v
    reach_vox = max(channel / v, 0.5 * channel / v + enc.REACH_SLACK_VOXELS)
    if tiles is None:
        tiles = TILES_PER_THREAD * (cluster_threads(scheduler) if scheduler else max(1, processes or 1))
    cores = plan_tiles(grid, tiles)
    nx = grid.block.shape[0]
    h1, h2 = halo_blocks(r_vox, reach_vox, band_vox)
    settings = dict(zp=zp, r_vox=r_vox, reach_vox=reach_vox, band_vox=band_vox)

    def step1():
        for a, b in cores:
            yield VoidTile(_slab(grid, max(0, a - h1), min(nx, b + h1)), a, b, **settings)

    first = list(map_tasks(exterior_step, step1(), scheduler=scheduler, processes=processes, total=len(cores)))
    root, per_tile = _merge(first)
    # the enclosed centres each step-2 tile needs: those of every core its slab overlaps
    enclosed = []
    for part, comp_root in zip(first, per_tile):
        inner = comp_root != root[0]
        mask = (part.label >= 0) & inner[np.maximum(part.label, 0)]
        rows = np.any(mask, axis=1)
        enclosed.append((part.coord[rows], mask[rows], part.tiles[inner[part.tile_label]]))
    del first

    def step2():
        for a, b in cores:
            lo, hi = max(0, a - h2), min(nx, b + h2)
            near = [e for (c0, c1), e in zip(cores, enclosed) if c0 < hi and c1 > lo]
            yield VoidTile(_slab(grid, lo, hi), a, b, **settings,
                           enclosed_coord=np.concatenate([e[0] for e in near]).reshape(-1, 3),
                           enclosed_mask=np.concatenate([e[1] for e in near]).reshape(-1, BLOCK_VOXELS),
                           enclosed_tiles=np.concatenate([e[2] for e in near]).astype(np.int64))

    second = list(map_tasks(void_step, step2(), scheduler=scheduler, processes=processes, total=len(cores)))
    return _voids(grid, second, plate_z, channel, reach_vox)


def _voids(grid: SparseGrid, parts: list[TileComponents], plate_z: float, channel: float, reach_vox: float) -> Voids:
    v = float(grid.voxel)
    shape = np.array(grid.block_shape, np.int64)
    root, per_tile = _merge(parts)
    ext = root[0]
    # global void ids: the roots that never meet the exterior
    roots = np.concatenate(per_tile) if per_tile else np.zeros(0, np.int64)
    void_roots = np.unique(roots[roots != ext])
    n_void = void_roots.size

    def void_of(comp_root, labels):
        r = comp_root[np.maximum(labels, 0)]
        g = np.searchsorted(void_roots, r)
        return np.where((labels >= 0) & (r != ext), g, -1)

    tile_lin = np.concatenate([p.tiles for p in parts] + [np.zeros(0, np.int64)]).astype(np.int64)
    tile_void = np.concatenate([void_of(c, p.tile_label) for p, c in zip(parts, per_tile)] + [np.zeros(0, np.int64)])
    keep = tile_void >= 0
    tile_lin, tile_void = tile_lin[keep], tile_void[keep]
    order = np.argsort(tile_lin, kind="stable")
    tile_lin, tile_void = tile_lin[order], tile_void[order]
    coord = np.concatenate([p.coord for p in parts]).reshape(-1, 3).astype(np.int64)
    void = np.concatenate([void_of(c, p.label) for p, c in zip(parts, per_tile)]).reshape(-1, BLOCK_VOXELS)
    frac = np.concatenate([p.frac for p in parts]).reshape(-1, BLOCK_VOXELS)
    centre = np.concatenate([p.centre for p in parts]).reshape(-1, BLOCK_VOXELS)
    leaf = np.concatenate([p.leaf for p in parts])
    rows = np.flatnonzero(np.any(void >= 0, axis=1))
    lin = (coord[rows, 0] * shape[1] + coord[rows, 1]) * shape[2] + coord[rows, 2]
    rows = rows[np.lexsort((lin, ~leaf[rows]))]  # the whole grid's work-block order
    coord, void, frac, centre = coord[rows], void[rows], frac[rows], centre[rows]
    # the stats come indexed by the local search's void numbers (``number``: of each global id)
    number, vol, csum, lo, hi, count, wide = _void_stats(tile_lin, tile_void, coord, void, frac, centre, n_void, shape)
    floor = enc.speck_floor(v, channel)
    speck = vol * v**3 < floor
    order, remap = enc.pore_order(vol, lo, speck)
    local = np.where(void >= 0, number[np.maximum(void, 0)], -1)
    block_label = np.where((local >= 0) & (frac > enc._MIN_PARTIAL), remap[np.maximum(local, 0)], -1).astype(np.int32)
    block_fraction = np.where(block_label >= 0, frac, 0.0).astype(np.float32)
    keep_blocks = np.any(block_label >= 0, axis=1)
    tile_label = remap[number[tile_void]]
    tiles = tile_lin[tile_label >= 0]
    tile_label = tile_label[tile_label >= 0]
    return enc.voids_of(grid, plate_z, channel, reach_vox, floor, order, (vol, csum, lo, hi, count, wide, speck),
                        coord[keep_blocks], block_label[keep_blocks], block_fraction[keep_blocks], tiles, tile_label)
