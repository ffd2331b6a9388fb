"""The deposit engine: a toolpath's beads swept into a :class:`~dmdvox.grid.sparse.SparseGrid`.

Every deposit row becomes one primitive (a straight extrusion, or an exact G17 arc), and every
row end and vertex gets a cap (the profile revolved about the vertical axis through it), so
joints are round at any corner angle. The deposit is the union of the primitives:

* sign is decided by the union (inside iff some primitive contains the voxel centre);
* the stored distance is ``min`` of the primitives' exact distances, clamped to the band. It is
  exact outside and on the surface; inside, ``min`` underestimates depth and is 0 on faces
  where beads merely touch, so voxels at such seams are probed (six axis directions at growing
  radii) and given the depth at which the union still covers all probes;
* arrival time is the earliest time a primitive covers the voxel: primitives are sorted in
  time, so the first one that contains the voxel gives it.

Blocks (8^3 voxels) are filled in parallel batches and packed by the grid builder as they
come, so peak memory is the final grid plus one batch.
"""

from __future__ import annotations

import os
import time
from dataclasses import dataclass

import numpy as np
from numba import njit, prange

from ..errors import DmdvoxError, ResourceError
from ..grid.build import GridBuilder
from ..grid.sparse import SparseGrid
from ..toolpath.geometry import linearized
from ..toolpath.model import Toolpath
from .primitives import arc_sdf, cap_sdf, segment_sdf
from .profiles import BeadProfile

SEGMENT = 0
CAP = 1
ARC = 2

BAND_VOXELS = 3.0
BATCH_BLOCKS = 4096
DEFAULT_VOXELS_PER_WIDTH = 20.0  # w/voxel: closed-form volumes within 1 % (tests)


@dataclass(frozen=True)
class Primitives:
    """Bead solids in time order. ``geom``: segment a(3) b(3); cap c(3); arc c(3) r theta0 sweep."""

    kind: np.ndarray  # (n,) uint8
    geom: np.ndarray  # (n, 6) float64
    t0: np.ndarray  # (n,) float64
    t1: np.ndarray  # (n,) float64
    lo: np.ndarray  # (n, 3) float64 bounding box of the solid
    hi: np.ndarray  # (n, 3)

    def __len__(self) -> int:
        return int(self.kind.shape[0])


def _exact_arc_rows(tp: Toolpath) -> np.ndarray:
    """Arc table indices drawn as exact arc beads: horizontal (G17), no helix, no spiral."""
    rows = tp.arcs.segment
    flat = np.abs(tp.end[rows, 2] - tp.start[rows, 2]) < 1e-9
    round_ = np.abs(tp.arcs.r_end - tp.arcs.r_start) < 1e-9
    return np.flatnonzero((tp.arcs.normal_axis == 2) & flat & round_ & tp.deposit[rows])


def build_primitives(tp: Toolpath, profile: BeadProfile, chord_tolerance: float) -> Primitives:
    """Primitives for the deposit rows of ``tp`` (bead-bottom coordinates)."""
    z_shift = -profile.height if tp.z_is_layer_top else 0.0
    exact = _exact_arc_rows(tp)
    exact_rows = tp.arcs.segment[exact]
    rest_mask = tp.deposit.copy()
    rest_mask[exact_rows] = False
    lines = linearized(tp.select(rest_mask), chord_tolerance)
    shift = np.array([0.0, 0.0, z_shift])
    half = profile.width / 2
    h = profile.height

    a = lines.start + shift
    b = lines.end + shift
    seg_geom = np.concatenate([a, b], axis=1)
    seg_lo = np.minimum(a, b) - [half, half, 0.0]
    seg_hi = np.maximum(a, b) + [half, half, h]

    # Arcs
    centre = tp.arcs.centre[exact] + shift
    start = tp.start[exact_rows] + shift
    radius = tp.arcs.r_start[exact]
    theta0 = np.arctan2(start[:, 1] - centre[:, 1], start[:, 0] - centre[:, 0])
    arc_geom = np.column_stack([centre, radius, theta0, tp.arcs.sweep[exact]])
    reach = (radius + half)[:, None]
    arc_lo = centre - np.column_stack([reach, reach, np.zeros_like(reach)])
    arc_hi = centre + np.column_stack([reach, reach, np.full_like(reach, h)])
    arc_end = tp.end[exact_rows] + shift

    # Caps at every piece's start and end; a start that continues the previous piece's end at
    # the same time is the same cap.
    piece_start = np.concatenate([a, start])
    piece_end = np.concatenate([b, arc_end])
    piece_t0 = np.concatenate([lines.t_start, tp.t_start[exact_rows]])
    piece_t1 = np.concatenate([lines.t_end, tp.t_end[exact_rows]])
    order = np.argsort(piece_t0, kind="stable")
    ps, pe, pt0, pt1 = piece_start[order], piece_end[order], piece_t0[order], piece_t1[order]
    continues = np.zeros(len(order), bool)
    if len(order) > 1:
        continues[1:] = np.all(ps[1:] == pe[:-1], axis=1) & (pt0[1:] == pt1[:-1])
    cap_pts = np.concatenate([ps[~continues], pe])
    cap_t = np.concatenate([pt0[~continues], pt1])
    cap_geom = np.column_stack([cap_pts, np.zeros((len(cap_pts), 3))])

    kind = np.concatenate([np.full(len(a), SEGMENT, np.uint8), np.full(len(exact), ARC, np.uint8),
                           np.full(len(cap_pts), CAP, np.uint8)])
    geom = np.concatenate([seg_geom, arc_geom, cap_geom])
    t0 = np.concatenate([lines.t_start, tp.t_start[exact_rows], cap_t])
    t1 = np.concatenate([lines.t_end, tp.t_end[exact_rows], cap_t])
    lo = np.concatenate([seg_lo, arc_lo, cap_pts - [half, half, 0.0]])
    hi = np.concatenate([seg_hi, arc_hi, cap_pts + [half, half, h]])
    # Time order: a cap at a vertex sits after the row that ends there and before the next.
    order = np.lexsort((t1, t0))
    return Primitives(kind=kind[order], geom=np.ascontiguousarray(geom[order]), t0=t0[order], t1=t1[order],
                      lo=lo[order], hi=hi[order])


@njit(cache=True)
def _eval(kind, g, x, y, z, code, w, h, n):
    if kind == SEGMENT:
        return segment_sdf(x, y, z, g[0], g[1], g[2], g[3], g[4], g[5], code, w, h, n)
    if kind == CAP:
        return cap_sdf(x, y, z, g[0], g[1], g[2], code, w, h, n)
    return arc_sdf(x, y, z, g[0], g[1], g[2], g[3], g[4], g[5], code, w, h, n)


@njit(cache=True)
def _covered(cand, nc, kind, geom, x, y, z, code, w, h, n):
    for c in range(nc):
        p = cand[c]
        d, _ = _eval(kind[p], geom[p], x, y, z, code, w, h, n)
        if d <= 0.0:
            return True
    return False


@njit(parallel=True, cache=True)
def _fill_blocks(coords, ptr, prim_ids, kind, geom, t0, t1, code, w, h, n, voxel, origin, band,
                 out_sdf, out_arr):
    m = coords.shape[0]
    half_diag = voxel * 3.5 * np.sqrt(3.0)
    steps = int(band / (0.5 * voxel))
    for bi in prange(m):
        bx = origin[0] + voxel * 8 * coords[bi, 0]
        by = origin[1] + voxel * 8 * coords[bi, 1]
        bz = origin[2] + voxel * 8 * coords[bi, 2]
        cx = bx + 3.5 * voxel
        cy = by + 3.5 * voxel
        cz = bz + 3.5 * voxel
        count = ptr[bi + 1] - ptr[bi]
        cand = np.empty(count, np.int64)
        nc = 0
        for k in range(ptr[bi], ptr[bi + 1]):
            p = prim_ids[k]
            d, _ = _eval(kind[p], geom[p], cx, cy, cz, code, w, h, n)
            # Distances are 1-Lipschitz: a primitive this far from the centre cannot reach
            # the band of any voxel in the block. Order (time) is kept.
            if d < half_diag + band:
                cand[nc] = p
                nc += 1
        for lx in range(8):
            x = bx + lx * voxel
            for ly in range(8):
                y = by + ly * voxel
                for lz in range(8):
                    z = bz + lz * voxel
                    best = band
                    arrival = np.inf
                    for c in range(nc):
                        p = cand[c]
                        d, f = _eval(kind[p], geom[p], x, y, z, code, w, h, n)
                        if d < best:
                            best = d
                        if d <= 0.0 and arrival == np.inf:
                            arrival = t0[p] + f * (t1[p] - t0[p])
                        if best <= -band and arrival < np.inf:
                            break
                    if best < -band:
                        best = -band
                    if arrival < np.inf and best > -0.5 * voxel:
                        # Inside, near zero: a true surface, or a seam between touching beads.
                        depth = 0.0
                        for s in range(1, steps + 1):
                            r = 0.5 * voxel * s
                            if (_covered(cand, nc, kind, geom, x + r, y, z, code, w, h, n)
                                    and _covered(cand, nc, kind, geom, x - r, y, z, code, w, h, n)
                                    and _covered(cand, nc, kind, geom, x, y + r, z, code, w, h, n)
                                    and _covered(cand, nc, kind, geom, x, y - r, z, code, w, h, n)
                                    and _covered(cand, nc, kind, geom, x, y, z + r, code, w, h, n)
                                    and _covered(cand, nc, kind, geom, x, y, z - r, code, w, h, n)):
                                depth = r
                            else:
                                break
                        if depth > 0.0:
                            best = min(best, -depth)
                    if arrival < np.inf and best >= 0.0:
                        # On the surface exactly: keep it inside so the sign follows the union.
                        best = -1e-7 * voxel
                    out_sdf[bi, lx, ly, lz] = best
                    out_arr[bi, lx, ly, lz] = arrival


@njit(cache=True)
def _count_pairs(lo_b, hi_b):
    total = 0
    for p in range(lo_b.shape[0]):
        total += (hi_b[p, 0] - lo_b[p, 0] + 1) * (hi_b[p, 1] - lo_b[p, 1] + 1) * (hi_b[p, 2] - lo_b[p, 2] + 1)
    return total


@njit(cache=True)
def _pairs(lo_b, hi_b, shape, out_block, out_prim):
    k = 0
    for p in range(lo_b.shape[0]):
        for i in range(lo_b[p, 0], hi_b[p, 0] + 1):
            for j in range(lo_b[p, 1], hi_b[p, 1] + 1):
                for l in range(lo_b[p, 2], hi_b[p, 2] + 1):
                    out_block[k] = (i * shape[1] + j) * shape[2] + l
                    out_prim[k] = p
                    k += 1


@dataclass(frozen=True)
class Domain:
    voxel: float
    origin: np.ndarray  # world position of voxel index (0,0,0), on the voxel lattice
    block_shape: tuple[int, int, int]
    band: float


def make_domain(prims: Primitives, voxel: float, band: float) -> Domain:
    if len(prims) == 0:
        raise DmdvoxError("the toolpath deposits nothing (no deposit moves); check --dialect and the laser codes")
    pad = band + 2 * voxel
    lo = prims.lo.min(axis=0) - pad
    hi = prims.hi.max(axis=0) + pad
    # Voxel centres sit on integer multiples of the voxel size, so every grid built on this
    # lattice (CAD, nozzle, fixtures) shares it exactly.
    i0 = np.floor(lo / voxel).astype(np.int64)
    i1 = np.ceil(hi / voxel).astype(np.int64)
    blocks = tuple(int(v) for v in -(-(i1 - i0 + 1) // 8))
    return Domain(voxel=voxel, origin=i0 * voxel, block_shape=blocks, band=band)


def estimate_memory(prims: Primitives, profile: BeadProfile, domain: Domain) -> int:
    """Bytes the grid and its construction need, from the bead surface area (an upper bound:
    surfaces shared by overlapping beads vanish in the union)."""
    seg = prims.kind == SEGMENT
    length = np.linalg.norm(prims.geom[seg, 3:] - prims.geom[seg, :3], axis=1).sum()
    arcs = prims.kind == ARC
    length += np.sum(np.abs(prims.geom[arcs, 3] * prims.geom[arcs, 5]))
    perimeter = profile.width + 2 * profile.height
    area = length * perimeter + np.count_nonzero(prims.kind == CAP) * np.pi * profile.width * profile.height
    v = domain.voxel
    active = area / (v * v) * (2 * domain.band / v)
    leaves = active / 200.0
    nb = np.prod(domain.block_shape, dtype=np.float64)
    grid = active * 6.5 + leaves * 160 + nb * 4
    batch = BATCH_BLOCKS * 512 * 8 * 2
    return int(grid * 1.5 + batch + nb * 8)


def available_memory() -> int:
    try:
        with open("/proc/meminfo") as fh:
            for line in fh:
                if line.startswith("MemAvailable:"):
                    return int(line.split()[1]) * 1024
    except OSError:
        pass
    return int(os.sysconf("SC_PAGE_SIZE") * os.sysconf("SC_PHYS_PAGES"))


def check_memory(estimate: int, voxel: float, limit: int | None) -> None:
    budget = limit if limit is not None else int(available_memory() * 0.8)
    if estimate <= budget:
        return
    # Active voxels scale as 1/voxel^2 (surface area times a band of fixed voxel count).
    suggested = voxel * np.sqrt(estimate / budget) * 1.1
    raise ResourceError(
        f"--voxel {voxel:g}: the grid needs about {estimate / 2**30:.1f} GiB but {budget / 2**30:.1f} GiB is "
        f"available; use --voxel {np.ceil(suggested * 1000) / 1000:g} or larger (or raise --max-memory)"
    )


def deposit(tp: Toolpath, profile: BeadProfile, voxel: float, *, until: float | None = None,
            max_memory: int | None = None, chord_tolerance: float | None = None,
            progress=None) -> tuple[SparseGrid, dict]:
    """Sweep the deposit rows of ``tp`` (up to ``until`` seconds) into a sparse grid.

    Returns the grid and timings. ``progress(done_blocks, total_blocks)`` is called per batch.
    """
    if not np.isfinite(voxel) or voxel <= 0:
        raise DmdvoxError(f"--voxel must be a positive number of mm, got {voxel}")
    timings = {}
    t_start = time.perf_counter()
    if until is not None:
        tp = tp.until(until)
    band = BAND_VOXELS * voxel
    chord = chord_tolerance if chord_tolerance is not None else min(0.01, voxel / 4)
    prims = build_primitives(tp, profile, chord)
    domain = make_domain(prims, voxel, band)
    check_memory(estimate_memory(prims, profile, domain), voxel, max_memory)
    timings["primitives_s"] = time.perf_counter() - t_start

    t = time.perf_counter()
    shape = np.array(domain.block_shape, np.int64)
    block_size = 8 * voxel
    lo_b = np.floor((prims.lo - band - domain.origin) / block_size).astype(np.int64)
    hi_b = np.floor((prims.hi + band - domain.origin) / block_size).astype(np.int64)
    lo_b = np.clip(lo_b, 0, shape - 1)
    hi_b = np.clip(hi_b, 0, shape - 1)
    total = _count_pairs(lo_b, hi_b)
    pair_block = np.empty(total, np.int64)
    pair_prim = np.empty(total, np.int64)
    _pairs(lo_b, hi_b, shape, pair_block, pair_prim)
    order = np.lexsort((pair_prim, pair_block))
    pair_block = pair_block[order]
    pair_prim = pair_prim[order]
    blocks, first = np.unique(pair_block, return_index=True)
    ptr = np.append(first, total).astype(np.int64)
    coords = np.stack(np.unravel_index(blocks, domain.block_shape), axis=1).astype(np.int64)
    timings["binning_s"] = time.perf_counter() - t

    t = time.perf_counter()
    builder = GridBuilder(voxel, domain.origin, domain.block_shape, band)
    n_blocks = len(blocks)
    for s in range(0, n_blocks, BATCH_BLOCKS):
        e = min(n_blocks, s + BATCH_BLOCKS)
        sdf = np.empty((e - s, 8, 8, 8), np.float32)
        arr = np.empty((e - s, 8, 8, 8), np.float32)
        _fill_blocks(coords[s:e], ptr[s:e + 1] - ptr[s], pair_prim[ptr[s]:ptr[e]], prims.kind, prims.geom,
                     prims.t0, prims.t1, profile.code, profile.width, profile.height, profile.exponent,
                     voxel, domain.origin, band, sdf, arr)
        builder.add_blocks(coords[s:e].astype(np.int32), sdf, arr)
        if progress is not None:
            progress(e, n_blocks)
    grid = builder.finish(meta={"profile": profile.name, "width_mm": profile.width, "height_mm": profile.height,
                                "voxel_mm": voxel, "source": tp.source})
    timings["sweep_s"] = time.perf_counter() - t
    timings["domain_voxels"] = float(np.prod(domain.block_shape, dtype=np.float64) * 512)
    return grid, timings


def default_voxel(profile: BeadProfile) -> float:
    """A voxel that resolves the bead: width/20, but at least 4 voxels over the height."""
    return float(min(profile.width / DEFAULT_VOXELS_PER_WIDTH, profile.height / 4))


__all__ = ["Primitives", "build_primitives", "deposit", "default_voxel", "estimate_memory", "check_memory"]
