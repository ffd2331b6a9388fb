"""The deposit engine: a toolpath's beads swept into a :class:`~dmdvox.grid.sparse.SparseGrid`.

The beads come from :mod:`dmdvox.process.beads`: straight extrusions and exact G17 arcs of a
cross-section (each element its own width, height and foot), and caps (the section revolved
about the bead's up axis) at every joint and end, so joints are round at any corner angle. The
deposit is the union of these primitives:

* sign is decided by the union (inside iff some primitive contains the voxel centre);
* outside, the stored distance is ``min`` of the primitives' exact distances: exact. Inside,
  ``min`` underestimates depth and is 0 on faces where beads merely touch, so inside voxels
  farther than the band from any outside voxel are deep (the tiles), and the others take the
  larger of their ``min`` depth and an estimate from the exact distances of the outside voxels
  around them; no internal surfaces survive at seams. Except where the ``min`` depth is exact:
  all the primitives containing the voxel are equally deep there and none other is as close, so
  the nearest face point is on the union's boundary (a void thinner than a voxel, with no
  outside voxel to estimate from, keeps its walls: porosity converges with the voxel);
* arrival time is the earliest time a primitive covers the voxel.

Work and memory follow the primitives' block footprint, not the part's bounding box:

* Classification, one block layer at a time: each primitive tests its distance at the centre of
  every block in its reach against the block's half-diagonal plus the band. Blocks it may reach
  get it in their list (a count pass and a fill pass, then a stable counting sort: each list
  stays in time order, so arrival stays the earliest covering time); a list ends at the first
  primitive that covers the block deeper than the band (the voxels skip every later one). A
  block whose first primitive covers it so is an inside tile with no voxel work: its octant
  arrival comes from the octant corners (a segment's arrival is monotone along its axis).
* The other listed blocks are swept voxel by voxel, in parallel over blocks, exactly as a dense
  sweep would: the same primitives, order, reach and early exit.
* The inside-depth correction needs the voxels up to the band (plus ``NEIGHBOURHOOD_VOXELS``)
  around each voxel: the 26 neighbouring blocks. Layers are swept bottom to top and each is
  finished once the layer above it is swept, so a chunk holds three layers of swept blocks.
* The table is cut into chunks (x ranges of whole block layers, with a halo of one block each
  side), each a picklable task that classifies, sweeps and finishes its blocks and returns them
  packed (leaves, and inside tiles as coordinates with their arrival). Chunks run here or on a
  dask cluster; the grid is the same bytes either way.

Before any voxel work, :func:`plan_deposit` classifies the whole table (or, for a request too
large to classify in seconds, a coarser lattice, scaled) and estimates the memory from it: the
leaves and tiles it predicts, a chunk's working layers, the block tables and the primitives.
"""

from __future__ import annotations

import dataclasses
import time
from dataclasses import dataclass

import numpy as np
from numba import njit, prange

from ..defaults import BAND_VOXELS
from ..errors import DmdvoxError, ParameterError
from ..grid.build import GridBuilder, octant_min, pack_blocks
from ..grid.sparse import BLOCK, SparseGrid
from ..memory import after_sweep, check_memory
from ..process.beads import ARC, CAP, SEGMENT, Beads
from ..process.profiles import RECT, profile_name
from ..tasks import cluster_threads, map_tasks
from .primitives import arc_sdf, clipped_cap_sdf, section_sdf, segment_sdf

NEIGHBOURHOOD_VOXELS = 2  # reach of the inside-depth estimate from outside voxels
SEAM_VOXELS = 0.05  # faces closer than this touch (a seam): slicers round coordinates to a micron
DEPTH_STEPS = 64.0  # near_out and shallow in 1/64 of a voxel: 255 steps reach beyond the band
# A primitive is left out of a block only if it stays this much beyond the band everywhere in it:
# beyond the seam tolerance and a depth step (the exact-depth test compares the nearest outside
# primitive, rounded down to a step, with up to the band plus the tolerance), with float32 storage
# and profile distances found by iteration (to ~1e-9 of the bead) far below the rest.
CLASSIFY_MARGIN_VOXELS = SEAM_VOXELS + 1.0 / DEPTH_STEPS + 1e-3
# per swept block: sdf, arrival (float32), nearest outside primitive, shallowest inside one, free
# nudges (uint8), outside bits; the finished value and the copies packed leaves are made from
SWEPT_BLOCK_BYTES = 512 * (4 + 4 + 1 + 1 + 1) + 64
FINISHED_BLOCK_BYTES = 512 * (4 + 4 + 4)
WINDOW_BYTES = 384 * 2**20  # a chunk's three swept layers: wider layers split the table along x
CHUNK_OUTPUT_BYTES = 512 * 2**20  # packed blocks one chunk returns (its share of the grid)
# On a cluster the chunks are cut smaller, CLUSTER_CHUNKS_PER_THREAD per worker thread, so that
# every worker gets work, but never below this (a few million voxels' blocks: below, a task's
# start and its transfer cost more than the split saves)
MIN_CLUSTER_CHUNK_BYTES = 16 * 2**20
CLUSTER_CHUNKS_PER_THREAD = 2
# (primitive, block) centre tests the exact classification may make before a request is
# refused; beyond, a coarser lattice with at most COARSE_PAIRS of them estimates it first
EXACT_PAIRS = 2e8
COARSE_PAIRS = 4e6
# Grid bytes per predicted leaf (masks, coordinates, offsets, octants: 188 B; ~300 active voxels
# of 4 B sdf and ~150 inside ones of 4 B arrival) and per inside tile (octants, table, id).
LEAF_BYTES = 188 + 300 * 4 + 150 * 4
TILE_BYTES = 32 + 12
PRIMITIVE_BYTES = 8 * (16 + 2 + 6) + 1 + 8 * 6  # geom, times, bounds, kind, block ranges

# geom columns: segment a(3) t(3) v(3) l(3) length (its frame, see segment_frame); cap c(3) u(3) and its
# two cut normals (3 + 3, zero: no cut);
# arc c(3) radius theta0 sweep; then every element's width, height and foot
GEOM_WIDTH = 16
_W, _H, _FOOT = 13, 14, 15


@dataclass(frozen=True)
class Primitives:
    """Bead solids in time order: ``geom`` (n, GEOM_WIDTH) as laid out above, and the bounding
    box of each solid."""

    kind: np.ndarray  # (n,) uint8 SEGMENT, CAP, ARC
    geom: np.ndarray  # (n, GEOM_WIDTH) float64
    t0: np.ndarray  # (n,) float64
    t1: np.ndarray  # (n,) float64
    lo: np.ndarray  # (n, 3) float64 bounding box of the solid
    hi: np.ndarray  # (n, 3)

    def __len__(self) -> int:
        return int(self.kind.shape[0])


def build_primitives(beads: Beads) -> Primitives:
    """The engine's form of the bead elements: segment frames and bounding boxes."""
    m = len(beads)
    geom = np.zeros((m, GEOM_WIDTH))
    geom[:, :3] = beads.p0
    geom[:, _W] = beads.width
    geom[:, _H] = beads.height
    geom[:, _FOOT] = beads.foot
    seg = np.flatnonzero(beads.kind == SEGMENT)
    frames = np.zeros((seg.size, 10))
    _frames(beads.p0[seg], beads.p1[seg], beads.up[seg], frames)
    geom[seg, 3:13] = frames
    cap = np.flatnonzero(beads.kind == CAP)
    geom[cap, 3:6] = beads.up[cap]
    geom[cap, 6:12] = beads.clip[cap]
    arc = np.flatnonzero(beads.kind == ARC)
    geom[arc, 3:6] = beads.p1[arc]
    lo, hi = _bounds(beads.kind, geom)
    return Primitives(kind=beads.kind, geom=np.ascontiguousarray(geom), t0=beads.t0, t1=beads.t1, lo=lo, hi=hi)


@njit(cache=True)
def _bounds(kind, geom):
    """Bounding boxes: a segment's section corners at both ends, a cap's disc at its bottom and
    top along its axis, an arc's ring."""
    m = kind.shape[0]
    lo = np.empty((m, 3))
    hi = np.empty((m, 3))
    for k in range(m):
        half = 0.5 * geom[k, _W]
        top = geom[k, _H]
        bottom = -geom[k, _FOOT]
        for a in range(3):
            lo[k, a] = np.inf
            hi[k, a] = -np.inf
        if kind[k] == SEGMENT:
            length = geom[k, 12]
            for end in range(2):
                for side in (-half, half):
                    for up in (bottom, top):
                        for a in range(3):
                            x = geom[k, a] + end * length * geom[k, 3 + a] + up * geom[k, 6 + a] + side * geom[k, 9 + a]
                            lo[k, a] = min(lo[k, a], x)
                            hi[k, a] = max(hi[k, a], x)
        elif kind[k] == CAP:
            for a in range(3):
                u = geom[k, 3 + a]
                spread = half * np.sqrt(max(0.0, 1.0 - u * u))
                lo[k, a] = geom[k, a] + min(bottom * u, top * u) - spread
                hi[k, a] = geom[k, a] + max(bottom * u, top * u) + spread
        else:
            reach = geom[k, 3] + half
            for a in range(2):
                lo[k, a] = geom[k, a] - reach
                hi[k, a] = geom[k, a] + reach
            lo[k, 2] = geom[k, 2] + bottom
            hi[k, 2] = geom[k, 2] + top
    return lo, hi


_VERTICAL = 0.999  # as in primitives.segment_sdf: segments nearly along the up axis have no section frame


@njit(cache=True)
def segment_frame(ax, ay, az, bx, by, bz, ux, uy, uz):
    """Travel t, section up v (the bead's up axis u made perpendicular to t), lateral l = t x v,
    and length of a segment. Nearly along u (and for zero length), v is u itself.

    The sweep evaluates each segment at ~10^5 voxels; computing its frame once (rather than
    per voxel inside :func:`primitives.segment_sdf`) halves the cost of the rect bead.
    """
    dx = bx - ax
    dy = by - ay
    dz = bz - az
    length = np.sqrt(dx * dx + dy * dy + dz * dz)
    if length == 0.0:
        return 0.0, 0.0, 0.0, ux, uy, uz, 0.0, 0.0, 0.0, 0.0
    tx = dx / length
    ty = dy / length
    tz = dz / length
    tu = tx * ux + ty * uy + tz * uz
    if abs(tu) > _VERTICAL:
        return tx, ty, tz, ux, uy, uz, 0.0, 0.0, 0.0, length
    un = np.sqrt(1.0 - tu * tu)
    vx = (ux - tu * tx) / un
    vy = (uy - tu * ty) / un
    vz = (uz - tu * tz) / un
    return tx, ty, tz, vx, vy, vz, ty * vz - tz * vy, tz * vx - tx * vz, tx * vy - ty * vx, length


@njit(cache=True, inline="always")
def segment_sdf_framed(px, py, pz, ax, ay, az, tx, ty, tz, vx, vy, vz, lx, ly, lz, length, code, w, h, n, foot):
    """:func:`primitives.segment_sdf` given the frame; ``frac`` only where it matters (inside)."""
    if length == 0.0 or abs(tx * vx + ty * vy + tz * vz) > _VERTICAL:
        return segment_sdf(px, py, pz, ax, ay, az, ax + tx * length, ay + ty * length, az + tz * length,
                           vx, vy, vz, code, w, h, n, foot)
    wx = px - ax
    wy = py - ay
    wz = pz - az
    along = wx * tx + wy * ty + wz * tz
    lateral = wx * lx + wy * ly + wz * lz
    up = wx * vx + wy * vy + wz * vz
    s_out = abs(along - 0.5 * length) - 0.5 * length
    if code == RECT:
        # The extruded rectangle (and its foot) is a box: one square root.
        q0 = abs(lateral) - 0.5 * w
        q1 = abs(up - 0.5 * (h - foot)) - 0.5 * (h + foot)
        d = np.sqrt(max(q0, 0.0) ** 2 + max(q1, 0.0) ** 2 + max(s_out, 0.0) ** 2) + min(max(q0, q1, s_out), 0.0)
    else:
        q0 = section_sdf(code, w, h, n, foot, lateral, up)
        d = min(max(q0, s_out), 0.0) + np.sqrt(max(q0, 0.0) ** 2 + max(s_out, 0.0) ** 2)
    frac = min(1.0, max(0.0, along / length)) if d <= 0.0 else 0.0
    return d, frac


@njit(cache=True)
def _frames(a, b, up, out):
    for k in range(a.shape[0]):
        frame = segment_frame(a[k, 0], a[k, 1], a[k, 2], b[k, 0], b[k, 1], b[k, 2], up[k, 0], up[k, 1], up[k, 2])
        for q in range(10):
            out[k, q] = frame[q]


@njit(cache=True, inline="always")
def _eval_scalars(kind, g0, g1, g2, g3, g4, g5, g6, g7, g8, g9, g10, g11, g12, x, y, z, code, w, h, n, foot):
    if kind == SEGMENT:
        return segment_sdf_framed(x, y, z, g0, g1, g2, g3, g4, g5, g6, g7, g8, g9, g10, g11, g12, code, w, h, n,
                                  foot)
    if kind == CAP:
        return clipped_cap_sdf(x, y, z, g0, g1, g2, g3, g4, g5, g6, g7, g8, g9, g10, g11, code, w, h, n, foot)
    return arc_sdf(x, y, z, g0, g1, g2, g3, g4, g5, code, w, h, n, foot)


@njit(cache=True)
def _eval(kind, g, x, y, z, code, n):
    return _eval_scalars(kind, g[0], g[1], g[2], g[3], g[4], g[5], g[6], g[7], g[8], g[9], g[10], g[11], g[12],
                         x, y, z, code, g[_W], g[_H], n, g[_FOOT])


@njit(cache=True)
def _interval(lo, hi, offset, slope):
    """y-interval where lo <= offset + slope * y <= hi."""
    if abs(slope) < 1e-12:
        if lo <= offset <= hi:
            return -np.inf, np.inf
        return np.inf, -np.inf
    a = (lo - offset) / slope
    b = (hi - offset) / slope
    return min(a, b), max(a, b)


@njit(cache=True)
def _footprint_rows(kind, g0, g1, g2, g3, g4, g5, lx, ly, lz, length, x, reach, band, z_lo, z_hi, y_origin,
                    voxel, j0, j1):
    """Rows j of the column at ``x`` (voxel centres at heights ``z_lo .. z_hi``) that a
    primitive's band can reach: a diagonal bead's bounding box is mostly empty, its footprint
    strip is not. (Only for beads standing up along +Z; a tilted bead's footprint is not a
    horizontal strip, and it visits its whole box.)"""
    if kind == CAP and abs(g5) >= 1.0 - 1e-12:
        dx = x - g0
        if abs(dx) > reach:
            return 1, 0
        half = np.sqrt(reach * reach - dx * dx)
        ylo, yhi = g1 - half, g1 + half
    elif kind == SEGMENT and length > 1e-12 and lz == 0.0:
        # |lateral| <= reach and -band <= along <= length + band; the lateral axis is
        # horizontal, along also moves with z by (z - a_z) t_z over the heights swept.
        llo, lhi = _interval(-reach, reach, (x - g0) * lx - g1 * ly, ly)
        rise_lo = (z_lo - g2) * g5
        rise_hi = (z_hi - g2) * g5
        alo, ahi = _interval(-band - max(rise_lo, rise_hi), length + band - min(rise_lo, rise_hi),
                             (x - g0) * g3 - g1 * g4, g4)
        ylo, yhi = max(llo, alo), min(lhi, ahi)
    else:
        return j0, j1
    # Clamp before converting: float-to-int of an infinite bound is undefined.
    ja = int(np.ceil(min(max((ylo - y_origin) / voxel, j0), j1 + 1)))
    jb = int(np.floor(min(max((yhi - y_origin) / voxel, j0 - 1), j1)))
    return ja, jb


@njit(cache=True)
def _reach_ranges(lo, hi, band, origin, voxel, nb):
    """Per primitive, the voxels its band can reach along each axis (``ranges[p, a]``, first
    and last index, as the sweep computes them) and the blocks holding them, clipped to the
    table (``blocks[p, a]``; empty when first > last)."""
    m = lo.shape[0]
    ranges = np.empty((m, 3, 2), np.int64)
    blocks = np.empty((m, 3, 2), np.int64)
    for p in range(m):
        for a in range(3):
            i0 = int(np.ceil((lo[p, a] - band - origin[a]) / voxel))
            i1 = int(np.floor((hi[p, a] + band - origin[a]) / voxel))
            ranges[p, a, 0] = i0
            ranges[p, a, 1] = i1
            blocks[p, a, 0] = max(0, i0 // 8)
            blocks[p, a, 1] = min(nb[a] - 1, i1 // 8)
    return ranges, blocks


@njit(cache=True)
def _layer_lists(blocks, x0, x1, z0, z1):
    """The primitives whose blocks meet x range [x0, x1) in each block layer of [z0, z1), in
    time order: ``ids[start[z - z0]:start[z - z0 + 1]]``."""
    count = np.zeros(z1 - z0 + 1, np.int64)
    for p in range(blocks.shape[0]):
        if blocks[p, 0, 0] > min(blocks[p, 0, 1], x1 - 1) or blocks[p, 0, 1] < x0 or blocks[p, 1, 0] > blocks[p, 1, 1]:
            continue
        for z in range(max(blocks[p, 2, 0], z0), min(blocks[p, 2, 1], z1 - 1) + 1):
            count[z - z0 + 1] += 1
    start = np.cumsum(count)
    ids = np.empty(start[-1], np.int64)
    fill = start[:-1].copy()
    for p in range(blocks.shape[0]):
        if blocks[p, 0, 0] > min(blocks[p, 0, 1], x1 - 1) or blocks[p, 0, 1] < x0 or blocks[p, 1, 0] > blocks[p, 1, 1]:
            continue
        for z in range(max(blocks[p, 2, 0], z0), min(blocks[p, 2, 1], z1 - 1) + 1):
            ids[fill[z - z0]] = p
            fill[z - z0] += 1
    return start, ids


@njit(cache=True)
def _centre(b, origin, voxel):
    return origin + (8 * b + 3.5) * voxel


@njit(parallel=True, cache=True)
def _classify_layer(ids, kind, geom, code, n, blocks, bz, x0, x1, ny, origin, voxel, band, floor_z):
    """The blocks of layer ``bz`` (x in [x0, x1), every y) that the primitives ``ids`` (in time
    order) may reach.

    A primitive may reach a block if its distance at the block centre is within the block's
    half-diagonal plus the band (and the margin): distances are 1-Lipschitz (exact outside,
    exact or a max of exact ones inside), so beyond that it stays beyond the band at every
    voxel, where it changes nothing. It covers the block deeper than the band if its distance
    there is below minus as much (segments and caps: their inside distances are exact; an arc
    narrower than its bead only bounds its depth).

    Returns, per reached block m: its window index ``xy_of[m]`` (``(x - x0) * ny + y``), its
    primitive list ``prims[start[m]:end[m]]`` (time order, cut after the first primitive
    covering the block deeper than the band), ``tile[m]`` (that primitive is the first, a
    segment or a cap, and the block is above the substrate's cut: an inside tile) and the least
    centre distance ``u[m]``; and the number of (primitive, block) pairs.
    """
    wn = (x1 - x0) * ny
    half_diagonal = 3.5 * voxel * np.sqrt(3.0)
    margin = CLASSIFY_MARGIN_VOXELS * voxel
    near = half_diagonal + band + margin
    cz = _centre(bz, origin[2], voxel)
    above_cut = origin[2] + 8 * bz * voxel >= floor_z + band + margin
    m_ids = ids.shape[0]
    count = np.zeros(m_ids + 1, np.int64)
    for q in prange(m_ids):
        p = ids[q]
        c = 0
        for bx in range(max(blocks[p, 0, 0], x0), min(blocks[p, 0, 1], x1 - 1) + 1):
            cx = _centre(bx, origin[0], voxel)
            for by in range(blocks[p, 1, 0], blocks[p, 1, 1] + 1):
                d, _ = _eval(kind[p], geom[p], cx, _centre(by, origin[1], voxel), cz, code, n)
                if d <= near:
                    c += 1
        count[q + 1] = c
    offset = np.cumsum(count)
    pair_xy = np.empty(offset[-1], np.int64)
    pair_d = np.empty(offset[-1], np.float64)
    for q in prange(m_ids):
        p = ids[q]
        k = offset[q]
        for bx in range(max(blocks[p, 0, 0], x0), min(blocks[p, 0, 1], x1 - 1) + 1):
            cx = _centre(bx, origin[0], voxel)
            for by in range(blocks[p, 1, 0], blocks[p, 1, 1] + 1):
                d, _ = _eval(kind[p], geom[p], cx, _centre(by, origin[1], voxel), cz, code, n)
                if d <= near:
                    pair_xy[k] = (bx - x0) * ny + by
                    pair_d[k] = d
                    k += 1
    # counting sort by block, stable: each block's list stays in time order
    per_block = np.zeros(wn, np.int64)
    for k in range(offset[-1]):
        per_block[pair_xy[k]] += 1
    slot = np.full(wn, -1, np.int32)
    m = 0
    for xy in range(wn):
        if per_block[xy] > 0:
            slot[xy] = m
            m += 1
    xy_of = np.empty(m, np.int64)
    start = np.zeros(m + 1, np.int64)
    for xy in range(wn):
        if slot[xy] >= 0:
            xy_of[slot[xy]] = xy
            start[slot[xy] + 1] = per_block[xy]
    start = np.cumsum(start)
    fill = start[:-1].copy()
    prims = np.empty(offset[-1], np.int64)
    dist = np.empty(offset[-1], np.float64)
    for q in range(m_ids):
        for k in range(offset[q], offset[q + 1]):
            s = slot[pair_xy[k]]
            prims[fill[s]] = ids[q]
            dist[fill[s]] = pair_d[k]
            fill[s] += 1
    end = np.empty(m, np.int64)
    tile = np.zeros(m, np.bool_)
    u = np.empty(m, np.float64)
    for s in prange(m):
        end[s] = start[s + 1]
        u[s] = np.inf
        for k in range(start[s], start[s + 1]):
            u[s] = min(u[s], dist[k])
            if end[s] == start[s + 1] and dist[k] <= -near and kind[prims[k]] != ARC:
                end[s] = k + 1
                tile[s] = k == start[s] and above_cut
    return xy_of, start, end, prims, tile, u, offset[-1]


@njit(parallel=True, cache=True)
def _sweep_blocks(todo, xy_of, start, end, prims, bz, x0, ny, kind, geom, t0, t1, ranges, code, n, voxel, origin,
                  band, floor_z, sdf, arr, near_out, shallow, free, outside):
    """Sweep the listed primitives into blocks ``todo`` of one layer: per voxel the minimum
    distance and the arrival; also what tells real walls from seams (:func:`_finish_blocks`), in
    1/``DEPTH_STEPS`` of a voxel (uint8, saturating): the distance of the nearest primitive not
    containing the voxel (``near_out``), the depth in the shallowest one containing it
    (``shallow``) and, for a voxel on a face (within ``SEAM_VOXELS``), which of the six points
    that far from it along the axes no primitive contains (``free``, one bit each). Then the
    substrate's cut, and ``outside`` (per (x, y) of the block, one bit per z) for the
    neighbours' finish.

    Threads own blocks, so writes never race; within a block primitives run in time order, so
    the first one covering a voxel sets its arrival, and a voxel already deeper than the band
    can change no more. Each primitive visits the voxels of its reach and footprint rows, as a
    dense sweep of the whole table would.
    """
    eps = SEAM_VOXELS * voxel
    steps = DEPTH_STEPS / voxel
    for s in prange(todo.shape[0]):
        m = todo[s]
        bx = x0 + xy_of[m] // ny
        by = xy_of[m] % ny
        xa, ya, za = 8 * bx, 8 * by, 8 * bz
        sdf[s] = band
        arr[s] = np.inf
        near_out[s] = 255
        shallow[s] = 255
        free[s] = 63
        for q in range(start[m], end[m]):
            p = prims[q]
            i0 = max(xa, ranges[p, 0, 0])
            i1 = min(xa + 7, ranges[p, 0, 1])
            j0 = max(ya, ranges[p, 1, 0])
            j1 = min(ya + 7, ranges[p, 1, 1])
            l0 = max(za, ranges[p, 2, 0])
            l1 = min(za + 7, ranges[p, 2, 1])
            if i0 > i1 or j0 > j1 or l0 > l1:
                continue
            # Geometry in locals: loads from an array the loop also writes would not be hoisted.
            g0, g1, g2, g3, g4, g5, g6 = geom[p, 0], geom[p, 1], geom[p, 2], geom[p, 3], geom[p, 4], geom[p, 5], geom[p, 6]
            g7, g8, g9, g10, g11, g12 = geom[p, 7], geom[p, 8], geom[p, 9], geom[p, 10], geom[p, 11], geom[p, 12]
            w, h, foot = geom[p, _W], geom[p, _H], geom[p, _FOOT]
            kp = kind[p]
            ta = t0[p]
            dt = t1[p] - t0[p]
            reach = 0.5 * w + band
            z_lo = origin[2] + l0 * voxel
            z_hi = origin[2] + l1 * voxel
            for i in range(i0, i1 + 1):
                x = origin[0] + i * voxel
                ja, jb = _footprint_rows(kp, g0, g1, g2, g3, g4, g5, g9, g10, g11, g12, x, reach, band, z_lo, z_hi,
                                         origin[1], voxel, j0, j1)
                a = i - xa
                for j in range(ja, jb + 1):
                    y = origin[1] + j * voxel
                    b = j - ya
                    for l in range(l0, l1 + 1):
                        c = l - za
                        if sdf[s, a, b, c] <= -band:
                            continue
                        z = origin[2] + l * voxel
                        d, f = _eval_scalars(kp, g0, g1, g2, g3, g4, g5, g6, g7, g8, g9, g10, g11, g12,
                                             x, y, z, code, w, h, n, foot)
                        if d < sdf[s, a, b, c]:
                            sdf[s, a, b, c] = d
                        q = np.uint8(min(abs(d) * steps, 255.0))
                        if d > 0.0:
                            if q < near_out[s, a, b, c]:
                                near_out[s, a, b, c] = q
                        elif q < shallow[s, a, b, c]:
                            shallow[s, a, b, c] = q
                        if d < -eps:
                            free[s, a, b, c] = 0
                        elif d <= eps and free[s, a, b, c] != 0:
                            # a face within eps: the sign at the six nudged points is not d's
                            for e6 in range(6):
                                if (free[s, a, b, c] >> e6) & 1:
                                    e = eps if e6 & 1 else -eps
                                    dq, _ = _eval_scalars(kp, g0, g1, g2, g3, g4, g5, g6, g7, g8, g9, g10, g11, g12,
                                                          x + (e if e6 < 2 else 0.0), y + (e if 2 <= e6 < 4 else 0.0),
                                                          z + (e if e6 >= 4 else 0.0), code, w, h, n, foot)
                                    if dq <= 0.0:
                                        free[s, a, b, c] &= np.uint8(~(1 << e6) & 63)
                        if d <= 0.0:
                            t = ta + f * dt
                            if t < arr[s, a, b, c]:
                                arr[s, a, b, c] = t
        for a in range(8):
            for b in range(8):
                bits = 0
                for c in range(8):
                    if floor_z > -np.inf:
                        # the union cut by the half-space above the substrate (max of the two
                        # distances: exact sign, and exact on the bottom face the cut makes)
                        below = floor_z - (origin[2] + (za + c) * voxel)
                        if below > sdf[s, a, b, c]:
                            sdf[s, a, b, c] = below
                    if sdf[s, a, b, c] > 0.0:
                        bits |= 1 << c
                outside[s, a, b] = bits


@njit(parallel=True, cache=True)
def _tile_arrival(todo, xy_of, start, prims, bz, x0, ny, kind, geom, t0, t1, code, n, voxel, origin, out):
    """Octant arrival minima of inside tiles whose first primitive covers them deeper than the
    band: every voxel's arrival is that primitive's. A cap's is its start time; a segment's
    grows with the projection on its axis, which is monotone in each voxel index even as
    computed in floating point, so each octant's least is at one of its 8 corners."""
    for s in prange(todo.shape[0]):
        m = todo[s]
        p = prims[start[m]]
        bx = x0 + xy_of[m] // ny
        by = xy_of[m] % ny
        dt = t1[p] - t0[p]
        for ox in range(2):
            for oy in range(2):
                for oz in range(2):
                    least = np.float32(np.inf)
                    for cx in range(2):
                        x = origin[0] + (8 * bx + 4 * ox + 3 * cx) * voxel
                        for cy in range(2):
                            y = origin[1] + (8 * by + 4 * oy + 3 * cy) * voxel
                            for cz in range(2):
                                z = origin[2] + (8 * bz + 4 * oz + 3 * cz) * voxel
                                _, f = _eval(kind[p], geom[p], x, y, z, code, n)
                                least = min(least, np.float32(t0[p] + f * dt))
                    out[s, ox, oy, oz] = least


@njit(cache=True)
def _gather_outside(grown, slot, outside, wx, wy, nwx, ny, shift):
    """OR one layer's outside bits of the 3 x 3 blocks around (wx, wy) into ``grown`` (24 x 24
    columns, z bits shifted by ``shift``); True if any is set. Blocks no primitive reaches are
    all outside; tiles and blocks beyond the table have no outside voxel."""
    found = False
    for dx in range(3):
        x = wx + dx - 1
        if x < 0 or x >= nwx:
            continue
        for dy in range(3):
            y = wy + dy - 1
            if y < 0 or y >= ny:
                continue
            s = slot[x * ny + y]
            if s == _TILE:
                continue
            found = True
            for a in range(8):
                for b in range(8):
                    bits = np.uint32(255) if s == _NONE else np.uint32(outside[s, a, b])
                    grown[8 * dx + a, 8 * dy + b] |= bits << np.uint32(shift)
    return found


@njit(cache=True)
def _near_outside(wx, wy, nwx, ny, slot_b, slot_c, slot_t, out_b, out_c, out_t, radius, near):
    """``near[a, b]``: bit c set if voxel (a, b, c) of the block at (wx, wy) is within ``radius``
    voxels (Chebyshev, at most 8) of an outside voxel (sdf > 0); False if none is. A separable
    box dilation of the outside bits of the 27 blocks around it, z as shifts of bit columns."""
    grown = np.zeros((24, 24), np.uint32)
    found = _gather_outside(grown, slot_b, out_b, wx, wy, nwx, ny, 0)
    found |= _gather_outside(grown, slot_c, out_c, wx, wy, nwx, ny, 8)
    found |= _gather_outside(grown, slot_t, out_t, wx, wy, nwx, ny, 16)
    if not found:
        return False
    for a in range(24):
        for b in range(24):
            col = grown[a, b]
            dil = col
            for r in range(1, radius + 1):
                dil |= (col << np.uint32(r)) | (col >> np.uint32(r))
            grown[a, b] = dil
    rows = np.zeros((24, 8), np.uint32)
    for a in range(24):
        for b in range(8):
            for r in range(8 + b - radius, 8 + b + radius + 1):
                rows[a, b] |= grown[a, r]
    for a in range(8):
        for b in range(8):
            acc = np.uint32(0)
            for r in range(8 + a - radius, 8 + a + radius + 1):
                acc |= rows[r, b]
            near[a, b] = (acc >> np.uint32(8)) & np.uint32(255)
    return True


@njit(cache=True)
def _gather_raw(window, wx, wy, nwx, ny, slot_b, slot_c, slot_t, sdf_b, sdf_c, sdf_t, bz, origin_z, voxel, band,
                floor_z, reach):
    """Union distances (before the correction) of the voxels within ``reach`` of the block at
    (wx, wy): a swept block's, the band cut by the substrate where no primitive reaches, and
    -band (no outside voxel) in tiles and beyond the table."""
    size = 8 + 2 * reach
    band32 = np.float32(band)
    for a in range(size):
        dx = (a - reach + 8) // 8 - 1
        x = wx + dx
        la = a - reach - 8 * dx
        for b in range(size):
            dy = (b - reach + 8) // 8 - 1
            y = wy + dy
            lb = b - reach - 8 * dy
            for c in range(size):
                dz = (c - reach + 8) // 8 - 1
                lc = c - reach - 8 * dz
                if x < 0 or x >= nwx or y < 0 or y >= ny:
                    window[a, b, c] = -band32
                    continue
                slot = slot_b if dz < 0 else slot_c if dz == 0 else slot_t
                s = slot[x * ny + y]
                if s >= 0:
                    window[a, b, c] = (sdf_b if dz < 0 else sdf_c if dz == 0 else sdf_t)[s, la, lb, lc]
                elif s == _TILE:
                    window[a, b, c] = -band32
                else:
                    window[a, b, c] = band32
                    below = floor_z - (origin_z + (8 * (bz + dz) + lc) * voxel)
                    if below > window[a, b, c]:
                        window[a, b, c] = below


@njit(parallel=True, cache=True)
def _finish_blocks(todo, xy_of_swept, nwx, ny, slot_b, slot_c, slot_t, sdf_b, sdf_c, sdf_t, out_b, out_c, out_t,
                   near_out, shallow, free, bz, origin_z, voxel, band, floor_z, radius, reach, out, verdict):
    """Union distances of the swept blocks ``todo`` of the middle layer (``_b``, ``_c``, ``_t``:
    the layers below, at and above it; ``slot`` maps a window block to its swept slot, ``_NONE``
    or ``_TILE``).

    Outside, ``min`` over primitives is exact. Inside, it underestimates depth (0 on faces
    where beads merely touch), so: voxels farther than the band from any outside voxel are
    deep (-band); the others take the larger of their ``min`` depth and the estimate from
    the outside voxels around them (for outside q with exact distance d(q), the depth of p is
    |p - q| - d(q) along the nearest surface normal, exact at flat walls).

    ``verdict``: 0 every voxel outside beyond the band (dropped), 2 every voxel inside beyond
    it (an inside tile), 1 a leaf.
    """
    band32 = np.float32(band)
    eps = SEAM_VOXELS * voxel
    step = voxel / DEPTH_STEPS
    size = 8 + 2 * reach
    for t in prange(todo.shape[0]):
        s = todo[t]
        wx = xy_of_swept[s] // ny
        wy = xy_of_swept[s] % ny
        pending = False
        for a in range(8):
            for b in range(8):
                for c in range(8):
                    raw = sdf_c[s, a, b, c]
                    if raw > 0.0:
                        out[t, a, b, c] = min(raw, band)
                        continue
                    # Where the min depth is exact, keep it: a void thinner than a voxel, with no
                    # outside voxel to estimate from, keeps its walls. On a face (within eps), it is
                    # exact if some point eps away is in no primitive (a seam, faces back to back, is
                    # covered all round). Deeper, if every primitive containing the voxel is as deep
                    # (one, or overlapping beads' shared flat bottom) and no other one is as close:
                    # their nearest face point is then outside the union.
                    if raw >= -eps:
                        exact = free[s, a, b, c] != 0
                    else:
                        # depths to 1/DEPTH_STEPS of a voxel, rounded down
                        exact = (-raw - shallow[s, a, b, c] * step <= eps + step
                                 and near_out[s, a, b, c] * step > eps - raw)
                    if exact:
                        out[t, a, b, c] = -min(max(-raw, 1e-7 * voxel), band)
                        continue
                    out[t, a, b, c] = np.nan
                    pending = True
        if pending:
            near = np.zeros((8, 8), np.uint32)
            _near_outside(wx, wy, nwx, ny, slot_b, slot_c, slot_t, out_b, out_c, out_t, radius, near)
            window = np.empty((size, size, size), np.float32)
            gathered = False
            for a in range(8):
                for b in range(8):
                    for c in range(8):
                        if not np.isnan(out[t, a, b, c]):
                            continue
                        if not (near[a, b] >> np.uint32(c)) & np.uint32(1):
                            out[t, a, b, c] = -band
                            continue
                        raw = sdf_c[s, a, b, c]
                        depth = -raw
                        if depth < band:
                            if not gathered:
                                _gather_raw(window, wx, wy, nwx, ny, slot_b, slot_c, slot_t, sdf_b, sdf_c, sdf_t, bz,
                                            origin_z, voxel, band, floor_z, reach)
                                gathered = True
                            est = reach * voxel
                            for da in range(-reach, reach + 1):
                                for db in range(-reach, reach + 1):
                                    for dc in range(-reach, reach + 1):
                                        dq = window[a + reach + da, b + reach + db, c + reach + dc]
                                        if dq > 0.0:
                                            dist = voxel * np.sqrt(da ** 2 + db ** 2 + dc ** 2) - dq
                                            if dist < est:
                                                est = dist
                            depth = max(depth, est)
                        # A voxel exactly on the surface stays inside: the sign follows the union.
                        out[t, a, b, c] = -min(max(depth, 1e-7 * voxel), band)
        all_out = True
        all_in = True
        for a in range(8):
            for b in range(8):
                for c in range(8):
                    v = out[t, a, b, c]
                    if v < band32:
                        all_out = False
                    if not (v < 0 and v <= -band32):
                        all_in = False
        verdict[t] = 0 if all_out else 2 if all_in else 1


@njit(cache=True, inline="always")
def _box_distance2(lo, hi, p, x, y, z):
    gx = max(lo[p, 0] - x, 0.0, x - hi[p, 0])
    gy = max(lo[p, 1] - y, 0.0, y - hi[p, 1])
    gz = max(lo[p, 2] - z, 0.0, z - hi[p, 2])
    return gx * gx + gy * gy + gz * gz


@njit(parallel=True, cache=True)
def _union_min(kind, geom, lo, hi, points, code, n, out):
    """The least SDF over the primitives at each point. A primitive lies in its box, so its
    distance is at least the box's: those boxes farther than the best value so far are skipped,
    which leaves the minimum as it is; the primitive with the nearest box goes first."""
    m = kind.shape[0]
    for q in prange(points.shape[0]):
        x, y, z = points[q, 0], points[q, 1], points[q, 2]
        first = 0
        nearest = np.inf
        for p in range(m):
            b2 = _box_distance2(lo, hi, p, x, y, z)
            if b2 < nearest:
                nearest = b2
                first = p
        best, _ = _eval(kind[first], geom[first], x, y, z, code, n)
        for p in range(m):
            b2 = _box_distance2(lo, hi, p, x, y, z)
            # outside a box by b the primitive's distance is >= b; inside one it may be < 0
            if p == first or (b2 > 0.0 and (best <= 0.0 or b2 >= best * best)):
                continue
            d, _ = _eval(kind[p], geom[p], x, y, z, code, n)
            best = min(best, d)
        out[q] = best


def union_distance(prims: Primitives, code: int, exponent: float, points: np.ndarray) -> np.ndarray:
    """``min`` over all primitives at each point: the deposit's exact distance outside it (a
    lower bound on depth inside). Brute force with box pruning: for a few points far from the
    grid's band."""
    out = np.empty(len(points))
    _union_min(prims.kind, prims.geom, prims.lo, prims.hi, np.ascontiguousarray(points, np.float64), code, exponent,
               out)
    return out


_NONE = -1  # in a layer's slot table: a block no primitive reaches (all outside)
_TILE = -2  # an inside tile, or a block beyond the table: no outside voxel


@dataclass(frozen=True)
class Domain:
    voxel: float
    origin: np.ndarray  # world position of voxel index (0,0,0), on the voxel lattice
    block_shape: tuple[int, int, int]
    band: float

    def widened(self, bounds) -> "Domain":
        """This table grown by whole blocks to hold ``bounds`` ``(lo, hi)`` (e.g. a CAD part)
        with the same margin: its own blocks stay where they are, so a grid swept on it is the
        same grid as one swept here (:meth:`SparseGrid.widened`)."""
        pad = self.band + 2 * self.voxel
        i0 = np.rint(self.origin / self.voxel).astype(np.int64)
        end = i0 + BLOCK * np.asarray(self.block_shape, np.int64) - 1
        e0 = np.floor((np.asarray(bounds[0], np.float64) - pad) / self.voxel).astype(np.int64)
        e1 = np.ceil((np.asarray(bounds[1], np.float64) + pad) / self.voxel).astype(np.int64)
        below = np.maximum(-(-(i0 - e0) // BLOCK), 0)
        above = np.maximum(-(-(e1 - end) // BLOCK), 0)
        blocks = np.asarray(self.block_shape, np.int64) + below + above
        return Domain(self.voxel, (i0 - BLOCK * below) * self.voxel, tuple(int(n) for n in blocks), self.band)


def make_domain(prims: Primitives, voxel: float, band: float, extra_bounds=None) -> Domain:
    """The block table around the primitives, widened by whole blocks to ``extra_bounds``
    (:meth:`Domain.widened`)."""
    if len(prims) == 0:
        raise DmdvoxError("the toolpath deposits nothing (no deposit moves); check --dialect and the laser codes")
    pad = band + 2 * voxel
    # Voxel centres sit on integer multiples of the voxel size, so every grid built on this
    # lattice (CAD, nozzle, fixtures) shares it exactly.
    i0 = np.floor((prims.lo.min(axis=0) - pad) / voxel).astype(np.int64)
    i1 = np.ceil((prims.hi.max(axis=0) + pad) / voxel).astype(np.int64)
    domain = Domain(voxel, i0 * voxel, tuple(int(n) for n in -(-(i1 - i0 + 1) // BLOCK)), band)
    return domain if extra_bounds is None else domain.widened(extra_bounds)


@dataclass(frozen=True)
class Footprint:
    """The blocks the primitives reach, per block layer and x column of blocks: swept voxel by
    voxel, inside tiles of a single primitive, and (from the union's sign at the block centres)
    the leaves and tiles the sweep will leave; the (primitive, block) pairs per layer. From a
    coarser lattice ``scale`` times the voxel, the counts are that lattice's."""

    swept: np.ndarray  # (nbz, nbx) int64
    leaves: np.ndarray  # (nbz, nbx) int64 predicted
    tiles: np.ndarray  # (nbz, nbx) int64 predicted, single-primitive tiles among them
    pairs: np.ndarray  # (nbz,) int64
    scale: int = 1

    def output_bytes(self) -> np.ndarray:
        """Packed bytes a chunk returns, per layer and column."""
        return self.leaves * LEAF_BYTES + self.tiles * TILE_BYTES


@njit(cache=True)
def _survey_counts(xy_of, tile, u_b, u_c, u_t, ny, swept, leaves, tiles):
    """Count one layer's reached blocks by x column: swept ones, and predicted leaves and tiles.
    A swept block is predicted a tile if the union contains the centres of all 27 blocks around
    it (``u``: the least centre distance, +inf where nothing reaches, -inf in a tile)."""
    nx = u_c.shape[0]
    for m in range(xy_of.shape[0]):
        bx = xy_of[m] // ny
        by = xy_of[m] % ny
        if tile[m]:
            tiles[bx] += 1
            continue
        swept[bx] += 1
        inside = True
        for x in range(bx - 1, bx + 2):
            for y in range(by - 1, by + 2):
                if x < 0 or x >= nx or y < 0 or y >= ny:
                    inside = False
                    continue
                if not (u_b[x, y] < 0.0 and u_c[x, y] < 0.0 and u_t[x, y] < 0.0):
                    inside = False
        if inside:
            tiles[bx] += 1
        else:
            leaves[bx] += 1


def _survey(prims: Primitives, domain: Domain, code: int, exponent: float, floor_z: float) -> Footprint:
    """Classify every block layer of the table (no voxel work) and count its blocks."""
    nbx, nby, nbz = domain.block_shape
    blocks = _reach_ranges(prims.lo, prims.hi, domain.band, domain.origin, domain.voxel,
                           np.array(domain.block_shape, np.int64))[1]
    start, ids = _layer_lists(blocks, 0, nbx, 0, nbz)
    swept = np.zeros((nbz, nbx), np.int64)
    leaves = np.zeros((nbz, nbx), np.int64)
    tiles = np.zeros((nbz, nbx), np.int64)
    pairs = np.zeros(nbz, np.int64)
    far = np.full((nbx, nby), np.inf)

    def classify(bz):
        if bz >= nbz:
            return None, far
        xy_of, _, _, _, tile, u, n_pairs = _classify_layer(
            ids[start[bz]:start[bz + 1]], prims.kind, prims.geom, code, exponent, blocks, bz, 0, nbx, nby,
            domain.origin, domain.voxel, domain.band, floor_z)
        pairs[bz] = n_pairs
        table = np.full(nbx * nby, np.inf)
        table[xy_of] = np.where(tile, -np.inf, u)
        return (xy_of, tile), table.reshape(nbx, nby)

    below = far
    current, u_c = classify(0)
    for bz in range(nbz):
        above, u_t = classify(bz + 1)
        _survey_counts(current[0], current[1], below, u_c, u_t, nby, swept[bz], leaves[bz], tiles[bz])
        below, (current, u_c) = u_c, (above, u_t)
    return Footprint(swept=swept, leaves=leaves, tiles=tiles, pairs=pairs)


def _pairs_bound(prims: Primitives, voxel: float, band: float) -> float:
    """(primitive, block) pairs within the primitives' reach boxes: what classifying costs."""
    extent = (prims.hi - prims.lo + 2 * band) / (8 * voxel) + 2
    return float(np.prod(extent, axis=1).sum())


@dataclass(frozen=True)
class DepositPlan:
    """What :func:`deposit_beads` sweeps: the primitives, the block table and their footprint."""

    prims: Primitives
    domain: Domain
    footprint: Footprint
    memory_bytes: int = 0  # the run's estimated peak the memory check passed


def _window_blocks() -> int:
    return WINDOW_BYTES // (3 * SWEPT_BLOCK_BYTES)


def estimate_memory(prims: Primitives, domain: Domain, footprint: Footprint) -> int:
    """Bytes the deposit holds at its peak, from its footprint: the grid (predicted leaves and
    tiles; the leaves' values twice, the finished grid beside the batches it is placed from,
    whose memory the allocator keeps), a chunk's three swept layers and the layer it finishes,
    one layer's classification, the block tables (the grid's, the builder's and the finish's)
    and the primitives (and a chunk's copy of them)."""
    k = footprint.scale
    n_blocks = float(np.prod(domain.block_shape, dtype=np.float64))
    leaves = float(footprint.leaves.sum()) * k * k
    tiles = float(footprint.tiles.sum()) * k ** 3
    grid = leaves * (2 * LEAF_BYTES - 188) + tiles * TILE_BYTES + n_blocks * (4 + 1 + 8)
    # a chunk's window: a layer's swept blocks over the columns it spans (halo included)
    if k == 1:
        nbx = footprint.swept.shape[1]
        layer = max(float(footprint.swept[:, max(0, x0 - 1):min(nbx, x1 + 1)].sum(axis=1).max())
                    for x0, x1 in _x_ranges(footprint.swept))
    else:
        layer = min(float(footprint.swept.sum(axis=1).max()) * k * k, _window_blocks())
    window = layer * (3 * SWEPT_BLOCK_BYTES + FINISHED_BLOCK_BYTES)
    classify = float(footprint.pairs.max()) * k * k * 40 + domain.block_shape[0] * domain.block_shape[1] * 40.0
    return int(grid + window + classify + 2 * len(prims) * PRIMITIVE_BYTES)


def run_memory(prims: Primitives, domain: Domain, footprint: Footprint, steps=()) -> dict[str, int]:
    """What the run holds at its peak for its deposit (``{"deposit": bytes}``): the sweep's
    (:func:`estimate_memory`) and what the ``steps`` after it (:data:`~dmdvox.memory.AFTER_SWEEP`)
    hold beside the grid."""
    leaves = float(footprint.leaves.sum()) * footprint.scale ** 2
    return {"deposit": estimate_memory(prims, domain, footprint) + after_sweep(leaves, steps)}


def plan_deposit(beads: Beads, voxel: float, *, max_memory: int | None = None,
                 extra_bounds=None, also_holds: dict[str, int] | None = None, steps=()) -> DepositPlan:
    """The primitives, the block table and the footprint :func:`deposit_beads` would sweep,
    after refusing (before any grid is allocated) a request that would not fit in
    ``max_memory`` beside what the caller ``also_holds`` (name -> bytes: a CAD part, the nozzle)
    and what the ``steps`` it takes after the sweep hold (``"porosity"``, ``"outputs"``).

    A request whose classification alone would take long (more than ``EXACT_PAIRS`` block
    tests) is first estimated on a lattice coarse enough to classify in a moment, scaled back
    (leaves with the square of the ratio, tiles with its cube), so that a request of billions
    of voxels is refused in seconds."""
    check_voxel(voxel)
    prims = build_primitives(beads)
    band = BAND_VOXELS * voxel
    domain = make_domain(prims, voxel, band, extra_bounds)
    holds = also_holds or {}
    bound = _pairs_bound(prims, voxel, band)
    n_blocks = float(np.prod(domain.block_shape, dtype=np.float64))
    if bound > EXACT_PAIRS or n_blocks > EXACT_PAIRS:
        scale = 2
        while _pairs_bound(prims, voxel * scale, band * scale) > COARSE_PAIRS or n_blocks / scale ** 3 > COARSE_PAIRS:
            scale *= 2
        coarse = make_domain(prims, voxel * scale, band * scale)
        footprint = _survey(prims, coarse, beads.code, beads.exponent, beads.floor_z)
        footprint = dataclasses.replace(footprint, scale=scale)
        check_memory({**run_memory(prims, domain, footprint, steps), **holds}, voxel, max_memory)
    footprint = _survey(prims, domain, beads.code, beads.exponent, beads.floor_z)
    parts = {**run_memory(prims, domain, footprint, steps), **holds}
    check_memory(parts, voxel, max_memory)
    return DepositPlan(prims=prims, domain=domain, footprint=footprint, memory_bytes=int(sum(parts.values())))


def check_voxel(voxel: float) -> None:
    if not np.isfinite(voxel) or voxel <= 0:
        raise ParameterError(f"{{voxel}} must be a positive number of mm, got {voxel}", "voxel")


def deposit(tp, profile, voxel: float, *, until: float | None = None, max_memory: int | None = None,
            chord_tolerance: float | None = None, progress=None, extra_bounds=None,
            scheduler: str | None = None) -> tuple[SparseGrid, dict]:
    """The fixed bead ``profile`` along ``tp`` as timed (the callers not yet on process plans)."""
    from ..process.plan import check_chords, fixed_beads
    from ..process.plan import chord_tolerance as default_chord

    check_voxel(voxel)
    chord = default_chord(voxel) if chord_tolerance is None else chord_tolerance
    check_chords(tp, chord, max_memory)
    beads = fixed_beads(tp, profile, chord)
    if until is not None:
        beads = beads.until(until)
    return deposit_beads(beads, voxel, max_memory=max_memory, progress=progress, extra_bounds=extra_bounds,
                         scheduler=scheduler)


@dataclass(frozen=True)
class BlockChunk:
    """Block layers [bz0, bz1) of the block columns [bx0, bx1) of the table: everything its
    sweep needs (picklable), with the primitives that reach it or its halo (one block around)
    in time order."""

    prims: Primitives
    code: int
    exponent: float
    domain: Domain
    bx0: int
    bx1: int
    bz0: int
    bz1: int
    floor_z: float = -np.inf


def _x_ranges(swept: np.ndarray) -> list[tuple[int, int]]:
    """Block column ranges whose swept blocks in any layer, with a halo column each side, fit
    the window (at least one column each)."""
    nbx = swept.shape[1]
    column = swept.max(axis=0)
    window = _window_blocks()
    out = []
    x0 = 0
    while x0 < nbx:
        x1 = x0 + 1
        while x1 < nbx and column[max(0, x0 - 1):min(nbx, x1 + 2)].sum() <= window:
            x1 += 1
        out.append((x0, x1))
        x0 = x1
    return out


def _chunk_ranges(footprint: Footprint, min_chunks: int = 1) -> list[tuple[int, int, int, int]]:
    """(bx0, bx1, bz0, bz1) of each chunk: x ranges whose layers' swept blocks (with the halo
    columns) fit the window, each cut into runs of layers whose packed output fits
    ``CHUNK_OUTPUT_BYTES``, or a ``min_chunks``-th of the whole output when that is smaller
    (never below ``MIN_CLUSTER_CHUNK_BYTES``); layers no primitive reaches are left out."""
    swept = footprint.swept
    output = footprint.output_bytes()
    cap = CHUNK_OUTPUT_BYTES
    if min_chunks > 1:
        cap = min(cap, max(MIN_CLUSTER_CHUNK_BYTES, int(output.sum()) // min_chunks))
    reached = (swept + footprint.tiles) > 0
    chunks = []
    for x0, x1 in _x_ranges(swept):
        layers = np.flatnonzero(reached[:, x0:x1].any(axis=1))
        if layers.size:
            per_layer = output[:, x0:x1].sum(axis=1)
            z0 = int(layers[0])
            held = 0
            for z in range(int(layers[0]), int(layers[-1]) + 1):
                if z > z0 and held + per_layer[z] > cap:
                    chunks.append((x0, x1, z0, z))
                    z0, held = z, 0
                held += per_layer[z]
            chunks.append((x0, x1, z0, int(layers[-1]) + 1))
    return chunks


def plan_chunks(plan: DepositPlan, beads: Beads, min_chunks: int = 1) -> list[BlockChunk]:
    """The deposit's tasks, each with the primitives that reach its blocks or their halo; at
    least ``min_chunks`` of them where the output allows (:func:`_chunk_ranges`)."""
    prims, domain = plan.prims, plan.domain
    blocks = _reach_ranges(prims.lo, prims.hi, domain.band, domain.origin, domain.voxel,
                           np.array(domain.block_shape, np.int64))[1]
    chunks = []
    for bx0, bx1, bz0, bz1 in _chunk_ranges(plan.footprint, min_chunks):
        mine = np.flatnonzero((blocks[:, 0, 0] <= bx1) & (blocks[:, 0, 1] >= bx0 - 1) & (blocks[:, 2, 0] <= bz1)
                              & (blocks[:, 2, 1] >= bz0 - 1) & (blocks[:, 1, 0] <= blocks[:, 1, 1]))
        subset = Primitives(kind=prims.kind[mine], geom=prims.geom[mine], t0=prims.t0[mine], t1=prims.t1[mine],
                            lo=prims.lo[mine], hi=prims.hi[mine])
        chunks.append(BlockChunk(subset, beads.code, beads.exponent, domain, bx0, bx1, bz0, bz1, beads.floor_z))
    return chunks


@dataclass
class _Layer:
    """One swept block layer of a chunk's window."""

    slot: np.ndarray  # (window blocks,) int32: swept slot, _NONE or _TILE
    xy: np.ndarray  # (swept,) window index of each swept block
    sdf: np.ndarray  # (swept, 8, 8, 8) float32, before the correction
    arr: np.ndarray
    near_out: np.ndarray  # uint8, as free
    shallow: np.ndarray
    free: np.ndarray
    outside: np.ndarray  # (swept, 8, 8) uint8 z bits
    tile_xy: np.ndarray  # window index of the chunk's single-primitive tiles
    tile_arr: np.ndarray  # (tiles, 2, 2, 2) float32

    @staticmethod
    def absent(n_window: int) -> "_Layer":
        """Beyond the table: no voxel, none outside."""
        empty = np.zeros((0, 8, 8, 8), np.float32)
        steps = np.zeros((0, 8, 8, 8), np.uint8)
        return _Layer(np.full(n_window, _TILE, np.int32), np.zeros(0, np.int64), empty, empty, steps, steps, steps,
                      np.zeros((0, 8, 8), np.uint8), np.zeros(0, np.int64), np.zeros((0, 2, 2, 2), np.float32))


def sweep_chunk(task: BlockChunk):
    """Classify, sweep and finish one chunk, layer by layer from the bottom (each layer is
    finished once the one above it is swept: three swept layers at a time), and pack its
    blocks: ``(parts, timings)``, a :class:`~dmdvox.grid.build.PackedBlocks` per layer. Pure:
    the same task gives the same bytes wherever it runs."""
    prims, domain = task.prims, task.domain
    voxel, band, origin = domain.voxel, domain.band, domain.origin
    nbx, nby, nbz = domain.block_shape
    radius = int(np.ceil(band / voxel))  # of the near-outside test: the band, in whole voxels
    wx0, wx1 = max(0, task.bx0 - 1), min(nbx, task.bx1 + 1)
    n_window = (wx1 - wx0) * nby
    z_first, z_last = max(0, task.bz0 - 1), min(nbz, task.bz1 + 1)
    ranges, blocks = _reach_ranges(prims.lo, prims.hi, band, origin, voxel, np.array(domain.block_shape, np.int64))
    start, ids = _layer_lists(blocks, wx0, wx1, z_first, z_last)
    timings = {"classify_s": 0.0, "splat_s": 0.0, "band_s": 0.0, "pack_s": 0.0, "swept_blocks": 0.0}

    def in_core(xy):
        x = xy // nby + wx0
        return (x >= task.bx0) & (x < task.bx1)

    def coords(xy, bz):
        return np.stack([xy // nby + wx0, xy % nby, np.full(xy.shape, bz)], axis=1).astype(np.int32)

    def sweep(bz):
        t = time.perf_counter()
        listed = ids[start[bz - z_first]:start[bz - z_first + 1]]
        xy_of, first, end, listed_prims, tile, _, _ = _classify_layer(
            listed, prims.kind, prims.geom, task.code, task.exponent, blocks, bz, wx0, wx1, nby, origin, voxel,
            band, task.floor_z)
        todo = np.flatnonzero(~tile)
        tiles = np.flatnonzero(tile)
        timings["classify_s"] += time.perf_counter() - t
        t = time.perf_counter()
        n = todo.size
        sdf = np.empty((n, 8, 8, 8), np.float32)
        arr = np.empty((n, 8, 8, 8), np.float32)
        near_out = np.empty((n, 8, 8, 8), np.uint8)
        shallow = np.empty((n, 8, 8, 8), np.uint8)
        free = np.empty((n, 8, 8, 8), np.uint8)
        outside = np.empty((n, 8, 8), np.uint8)
        _sweep_blocks(todo, xy_of, first, end, listed_prims, bz, wx0, nby, prims.kind, prims.geom, prims.t0,
                      prims.t1, ranges, task.code, task.exponent, voxel, origin, band, task.floor_z, sdf, arr,
                      near_out, shallow, free, outside)
        slot = np.full(n_window, _NONE, np.int32)
        slot[xy_of[todo]] = np.arange(n, dtype=np.int32)
        slot[xy_of[tiles]] = _TILE
        if task.bz0 <= bz < task.bz1:
            tiles = tiles[in_core(xy_of[tiles])]
        else:
            tiles = tiles[:0]
        tile_arr = np.empty((tiles.size, 2, 2, 2), np.float32)
        _tile_arrival(tiles, xy_of, first, listed_prims, bz, wx0, nby, prims.kind, prims.geom, prims.t0, prims.t1,
                      task.code, task.exponent, voxel, origin, tile_arr)
        timings["splat_s"] += time.perf_counter() - t
        timings["swept_blocks"] += n
        return _Layer(slot, xy_of[todo], sdf, arr, near_out, shallow, free, outside, xy_of[tiles], tile_arr)

    def finish(bz, below, layer, above):
        t = time.perf_counter()
        todo = np.flatnonzero(in_core(layer.xy))
        out = np.empty((todo.size, 8, 8, 8), np.float32)
        verdict = np.empty(todo.size, np.int8)
        _finish_blocks(todo, layer.xy, wx1 - wx0, nby, below.slot, layer.slot, above.slot, below.sdf, layer.sdf,
                       above.sdf, below.outside, layer.outside, above.outside, layer.near_out, layer.shallow,
                       layer.free, bz, origin[2], voxel, band, task.floor_z, radius, NEIGHBOURHOOD_VOXELS, out,
                       verdict)
        timings["band_s"] += time.perf_counter() - t
        t = time.perf_counter()
        leaves = np.flatnonzero(verdict == 1)
        tiles = np.flatnonzero(verdict == 2)
        packed = pack_blocks(coords(layer.xy[todo[leaves]], bz), out[leaves], layer.arr[todo[leaves]], band)
        part = dataclasses.replace(
            packed,
            tile_coord=np.concatenate([packed.tile_coord, coords(layer.xy[todo[tiles]], bz),
                                       coords(layer.tile_xy, bz)]),
            tile_arr=np.concatenate([packed.tile_arr, octant_min(layer.arr, todo[tiles]), layer.tile_arr]))
        timings["pack_s"] += time.perf_counter() - t
        return part

    absent = _Layer.absent(n_window)
    swept = {}
    parts = []
    for bz in range(z_first, z_last):
        swept[bz] = sweep(bz)
        mid = bz - 1
        if task.bz0 <= mid < task.bz1:
            parts.append(finish(mid, swept.pop(mid - 1, absent), swept[mid], swept[bz]))
    if task.bz1 == nbz:  # the table's top layer has no layer above to wait for
        parts.append(finish(nbz - 1, swept.get(nbz - 2, absent), swept[nbz - 1], absent))
    return parts, timings


def deposit_beads(beads: Beads, voxel: float, *, max_memory: int | None = None, progress=None, extra_bounds=None,
                  scheduler: str | None = None,
                  also_holds: dict[str, int] | None = None, steps=()) -> tuple[SparseGrid, dict]:
    """Sweep the bead elements into a sparse grid.

    Returns the grid and timings (with ``memory_estimate_bytes``: the peak the memory check
    estimated, the ``steps`` the caller takes after the sweep included, see :func:`plan_deposit`). ``progress(done, total)`` is called per chunk of blocks.
    ``extra_bounds`` ``(lo, hi)`` widens the block table, so that another grid (a CAD part)
    built on the same lattice shares it block for block. With ``scheduler`` (a dask address)
    the chunks are swept on the cluster's workers and merged here as they arrive: the chunks
    carry their own halo of one block, so the grid is identical to the local one (which runs
    the same chunks here, one after the other).
    """
    timings = {}
    t_start = time.perf_counter()
    plan = plan_deposit(beads, voxel, max_memory=max_memory, extra_bounds=extra_bounds, also_holds=also_holds,
                        steps=steps)
    domain = plan.domain
    timings["primitives_s"] = time.perf_counter() - t_start
    timings["memory_estimate_bytes"] = float(plan.memory_bytes)

    t = time.perf_counter()
    builder = GridBuilder(voxel, domain.origin, domain.block_shape, domain.band)
    # on a cluster, chunks for every worker (the grid does not depend on the cut)
    min_chunks = CLUSTER_CHUNKS_PER_THREAD * cluster_threads(scheduler) if scheduler else 1
    chunks = plan_chunks(plan, beads, min_chunks)
    parts = []
    for done, (parts, chunk_timings) in enumerate(map_tasks(sweep_chunk, chunks, scheduler=scheduler), 1):
        for part in parts:
            builder.add_packed(part)
        for key, value in chunk_timings.items():
            timings[key] = timings.get(key, 0.0) + value
        if progress is not None:
            progress(done, len(chunks))
    del parts  # the builder holds the blocks; it releases each batch as it places it
    grid = builder.finish(meta={"profile": profile_name(beads.code), "voxel_mm": voxel})
    timings["sweep_s"] = time.perf_counter() - t
    timings["domain_voxels"] = float(np.prod(domain.block_shape, dtype=np.float64) * 512)
    timings["chunks"] = float(len(chunks))
    return grid, timings


__all__ = ["Primitives", "build_primitives", "plan_deposit", "deposit", "deposit_beads", "estimate_memory",
           "run_memory", "union_distance"]
