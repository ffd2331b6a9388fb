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

The domain is swept in dense z slabs (with a halo of one band): each primitive visits only the
voxels of its bounding box, threads own disjoint x ranges, and each finished slab is cut into
8^3 blocks that the grid builder packs at once, so peak memory is the sparse grid plus one
slab (an eighth of the free memory, within ``SLAB_BUDGET_BYTES``).
"""

from __future__ import annotations

import time
from dataclasses import dataclass

import numpy as np
from numba import njit, prange

from ..defaults import BAND_VOXELS
from ..errors import DmdvoxError
from ..grid.build import GridBuilder
from ..grid.levelset import surface_memory
from ..grid.sparse import SparseGrid
from ..memory import available_memory, check_memory
from ..process.beads import ARC, CAP, SEGMENT, Beads
from ..process.profiles import RECT, profile_name
from ..tasks import map_tasks
from .primitives import arc_sdf, clipped_cap_sdf, section_sdf, segment_sdf

NEIGHBOURHOOD_VOXELS = 2  # reach of the inside-depth estimate from outside voxels
SEAM_VOXELS = 0.05  # faces closer than this touch (a seam): slicers round coordinates to a micron
DEPTH_STEPS = 64.0  # near_out and shallow in 1/64 of a voxel: 255 steps reach beyond the band
SLAB_BUDGET_BYTES = (256 * 2**20, 2 * 2**30)  # bounds; an eighth of the free memory in between
# sdf, arrival, nearest outside primitive, shallowest inside one, free nudges, two masks, core, gathered blocks
SLAB_BYTES_PER_VOXEL = 4 + 4 + 1 + 1 + 1 + 1 + 1 + 4 + 8

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
def _footprint_rows(kind, g0, g1, g2, g3, g4, g5, lx, ly, lz, length, x, reach, band, z_span, y_origin, voxel,
                    j0, j1):
    """Rows j of the column at ``x`` that a primitive's band can reach: a diagonal bead's
    bounding box is mostly empty, its footprint strip is not. (Only for beads standing up along
    +Z; a tilted bead's footprint is not a horizontal strip, and it visits its whole box.)"""
    if kind == CAP and abs(g5) >= 1.0 - 1e-12:
        dx = x - g0
        if abs(dx) > reach:
            return 1, 0
        half = np.sqrt(reach * reach - dx * dx)
        ylo, yhi = g1 - half, g1 + half
    elif kind == SEGMENT and length > 1e-12 and lz == 0.0:
        # |lateral| <= reach and -band <= along <= length + band; the lateral axis is
        # horizontal, along also moves with z (by at most |t_z| over the slab's z span).
        llo, lhi = _interval(-reach, reach, (x - g0) * lx - g1 * ly, ly)
        slack = abs(g5) * z_span
        alo, ahi = _interval(-band - slack, length + band + slack, (x - g0) * g3 - g1 * g4, g4)
        ylo, yhi = max(llo, alo), min(lhi, ahi)
    else:
        return j0, j1
    # Clamp before converting: float-to-int of an infinite bound is undefined.
    ja = int(np.ceil(min(max((ylo - y_origin) / voxel, j0), j1 + 1)))
    jb = int(np.floor(min(max((yhi - y_origin) / voxel, j0 - 1), j1)))
    return ja, jb


@njit(parallel=True, cache=True)
def _splat(prim_ids, kind, geom, t0, t1, lo, hi, code, n, voxel, origin, k0, band, sdf, arr, near_out, shallow,
           free):
    """Sweep primitives into a dense slab: per voxel the minimum distance and the arrival; also
    what tells real walls from seams (:func:`_finish_slab`), in 1/``DEPTH_STEPS`` of a voxel
    (uint8, saturating): the distance of the nearest primitive not containing the voxel
    (``near_out``), the depth in the shallowest one containing it (``shallow``) and, for a voxel
    on a face (within ``SEAM_VOXELS``), which of the six points that far from it along the axes
    no primitive contains (``free``, one bit each).

    Threads own disjoint x ranges, so writes never race; within a range primitives run in time
    order, so the first one covering a voxel sets its arrival, and a voxel already deeper
    than the band can change no more.
    """
    nx, ny, nz = sdf.shape
    eps = SEAM_VOXELS * voxel
    steps = DEPTH_STEPS / voxel
    n_chunks = nx  # one x column per task: its slice of the slab stays in cache for all primitives
    for c in prange(n_chunks):
        x_lo = c * nx // n_chunks
        x_hi = (c + 1) * nx // n_chunks
        for q in range(prim_ids.shape[0]):
            p = prim_ids[q]
            i0 = max(x_lo, int(np.ceil((lo[p, 0] - band - origin[0]) / voxel)))
            i1 = min(x_hi - 1, int(np.floor((hi[p, 0] + band - origin[0]) / voxel)))
            if i0 > i1:
                continue
            j0 = max(0, int(np.ceil((lo[p, 1] - band - origin[1]) / voxel)))
            j1 = min(ny - 1, int(np.floor((hi[p, 1] + band - origin[1]) / voxel)))
            l0 = max(0, int(np.ceil((lo[p, 2] - band - origin[2]) / voxel)) - k0)
            l1 = min(nz - 1, int(np.floor((hi[p, 2] + band - origin[2]) / voxel)) - k0)
            # Geometry in locals: loads from an array the loop also writes would not be hoisted.
            g0, g1, g2, g3, g4, g5, g6 = geom[p, 0], geom[p, 1], geom[p, 2], geom[p, 3], geom[p, 4], geom[p, 5], geom[p, 6]
            g7, g8, g9, g10, g11, g12 = geom[p, 7], geom[p, 8], geom[p, 9], geom[p, 10], geom[p, 11], geom[p, 12]
            w, h, foot = geom[p, _W], geom[p, _H], geom[p, _FOOT]
            kp = kind[p]
            ta = t0[p]
            dt = t1[p] - t0[p]
            reach = 0.5 * w + band
            z_span = (l1 - l0 + 1) * voxel
            for i in range(i0, i1 + 1):
                x = origin[0] + i * voxel
                ja, jb = _footprint_rows(kp, g0, g1, g2, g3, g4, g5, g9, g10, g11, g12, x, reach, band, z_span,
                                         origin[1], voxel, j0, j1)
                for j in range(ja, jb + 1):
                    y = origin[1] + j * voxel
                    for l in range(l0, l1 + 1):
                        if sdf[i, j, l] <= -band:
                            continue
                        z = origin[2] + (k0 + l) * voxel
                        d, f = _eval_scalars(kp, g0, g1, g2, g3, g4, g5, g6, g7, g8, g9, g10, g11, g12,
                                             x, y, z, code, w, h, n, foot)
                        if d < sdf[i, j, l]:
                            sdf[i, j, l] = d
                        q = np.uint8(min(abs(d) * steps, 255.0))
                        if d > 0.0:
                            if q < near_out[i, j, l]:
                                near_out[i, j, l] = q
                        elif q < shallow[i, j, l]:
                            shallow[i, j, l] = q
                        if d < -eps:
                            free[i, j, l] = 0
                        elif d <= eps and free[i, j, l] != 0:
                            # a face within eps: the sign at the six nudged points is not d's
                            for q in range(6):
                                if (free[i, j, l] >> q) & 1:
                                    e = eps if q & 1 else -eps
                                    dq, _ = _eval_scalars(kp, g0, g1, g2, g3, g4, g5, g6, g7, g8, g9, g10, g11, g12,
                                                          x + (e if q < 2 else 0.0), y + (e if 2 <= q < 4 else 0.0),
                                                          z + (e if q >= 4 else 0.0), code, w, h, n, foot)
                                    if dq <= 0.0:
                                        free[i, j, l] &= np.uint8(~(1 << q) & 63)
                        if d <= 0.0:
                            t = ta + f * dt
                            if t < arr[i, j, l]:
                                arr[i, j, l] = t


@njit(parallel=True, cache=True)
def _cut_below(sdf, floor_z, z0, voxel):
    """Intersect the slab's union with the half-space above the substrate (max of the two
    distances: exact sign, and exact on the bottom face the cut makes)."""
    nx, ny, nz = sdf.shape
    for i in prange(nx):
        for j in range(ny):
            for l in range(nz):
                below = floor_z - (z0 + l * voxel)
                if below > sdf[i, j, l]:
                    sdf[i, j, l] = below


@njit(cache=True)
def _dilate_plane_rows(plane, radius):
    """Dilate a 2-D boolean plane by ``radius`` along its first axis, in place, tracking per
    column the distance to the last set cell seen going forward and backward."""
    n, m = plane.shape
    far = radius + 1
    gap = np.empty(m, np.int64)
    grown = np.zeros((n, m), np.bool_)
    for direction in range(2):
        gap[:] = far
        for step in range(n):
            r = step if direction == 0 else n - 1 - step
            for c in range(m):
                gap[c] = 0 if plane[r, c] else min(gap[c] + 1, far)
                if gap[c] <= radius:
                    grown[r, c] = True
    plane[:, :] = grown


@njit(parallel=True, cache=True)
def _near_outside(sdf, radius, near):
    """``near``: within ``radius`` voxels (Chebyshev) of an outside voxel (sdf > 0).

    A separable box dilation; each pass tracks the distance to the last outside voxel seen
    going forward and backward, so the cost does not grow with the radius, and every pass runs
    along the array's contiguous axis or across whole contiguous rows.
    """
    nx, ny, nz = sdf.shape
    far = radius + 1
    # z (contiguous)
    for i in prange(nx):
        for j in range(ny):
            gap = far
            for l in range(nz):
                gap = 0 if sdf[i, j, l] > 0.0 else min(gap + 1, far)
                near[i, j, l] = gap <= radius
            gap = far
            for l in range(nz - 1, -1, -1):
                gap = 0 if sdf[i, j, l] > 0.0 else min(gap + 1, far)
                if gap <= radius:
                    near[i, j, l] = True
    # y, then x: whole rows of z stay contiguous; each thread owns one plane of the other axis
    for i in prange(nx):
        _dilate_plane_rows(near[i, :, :], radius)
    for j in prange(ny):
        _dilate_plane_rows(near[:, j, :], radius)


@njit(parallel=True, cache=True)
def _finish_slab(sdf, near, voxel, band, halo, reach, near_out, shallow, free, out):
    """Union distances for the slab's core (halo cut off).

    Outside, ``min`` over primitives is exact. Inside, it underestimates depth (0 on faces
    where beads merely touch), so: voxels farther than the band from any outside voxel are
    deep (-band); the others take the larger of their ``min`` depth and the estimate from
    the outside voxels around them (for outside q with exact distance d(q), the depth of p is
    |p - q| - d(q) along the nearest surface normal, exact at flat walls).
    """
    nx, ny, nz = out.shape
    for i in prange(nx):
        for j in range(ny):
            for l in range(nz):
                ls = l + halo
                raw = sdf[i, j, ls]
                if raw > 0.0:
                    out[i, j, l] = min(raw, band)
                    continue
                # Where the min depth is exact, keep it: a void thinner than a voxel, with no
                # outside voxel to estimate from, keeps its walls. On a face (within eps), it is
                # exact if some point eps away is in no primitive (a seam, faces back to back, is
                # covered all round). Deeper, if every primitive containing the voxel is as deep
                # (one, or overlapping beads' shared flat bottom) and no other one is as close:
                # their nearest face point is then outside the union.
                eps = SEAM_VOXELS * voxel
                if raw >= -eps:
                    exact = free[i, j, ls] != 0
                else:
                    # depths to 1/DEPTH_STEPS of a voxel, rounded down
                    step = voxel / DEPTH_STEPS
                    exact = (-raw - shallow[i, j, ls] * step <= eps + step
                             and near_out[i, j, ls] * step > eps - raw)
                if exact:
                    out[i, j, l] = -min(max(-raw, 1e-7 * voxel), band)
                    continue
                if not near[i, j, ls]:
                    out[i, j, l] = -band
                    continue
                depth = -raw
                if depth < band:
                    est = reach * voxel
                    for a in range(max(0, i - reach), min(nx, i + reach + 1)):
                        for b in range(max(0, j - reach), min(ny, j + reach + 1)):
                            for c in range(max(0, ls - reach), min(sdf.shape[2], ls + reach + 1)):
                                dq = sdf[a, b, c]
                                if dq > 0.0:
                                    dist = voxel * np.sqrt((a - i) ** 2 + (b - j) ** 2 + (c - ls) ** 2) - dq
                                    if dist < est:
                                        est = dist
                    depth = max(depth, est)
                # A voxel exactly on the surface stays inside: the sign follows the union.
                out[i, j, l] = -min(max(depth, 1e-7 * voxel), band)


@njit(parallel=True, cache=True)
def _block_slots(core, band):
    """Output slot of each block of the slab core; -1 for blocks wholly outside the band."""
    nbx, nby, nbz = core.shape[0] // 8, core.shape[1] // 8, core.shape[2] // 8
    keep = np.zeros(nbx * nby * nbz, np.int64)
    for bx in prange(nbx):
        for by in range(nby):
            for bz in range(nbz):
                block = core[8 * bx:8 * bx + 8, 8 * by:8 * by + 8, 8 * bz:8 * bz + 8]
                if block.min() < band:
                    keep[(bx * nby + by) * nbz + bz] = 1
    slots = np.cumsum(keep) - 1
    for k in range(keep.shape[0]):
        if keep[k] == 0:
            slots[k] = -1
    return slots


@njit(parallel=True, cache=True)
def _gather_blocks(core, arr, halo, slots, bz0, out_coords, out_sdf, out_arr):
    nby, nbz = core.shape[1] // 8, core.shape[2] // 8
    for k in prange(slots.shape[0]):
        m = slots[k]
        if m < 0:
            continue
        bx = k // (nby * nbz)
        by = (k // nbz) % nby
        bz = k % nbz
        out_coords[m, 0] = bx
        out_coords[m, 1] = by
        out_coords[m, 2] = bz0 + bz
        for a in range(8):
            for b in range(8):
                for c in range(8):
                    out_sdf[m, a, b, c] = core[8 * bx + a, 8 * by + b, 8 * bz + c]
                    out_arr[m, a, b, c] = arr[8 * bx + a, 8 * by + b, 8 * bz + c + halo]


@njit(parallel=True, cache=True)
def _union_min(kind, geom, points, code, n, out):
    for q in prange(points.shape[0]):
        best = np.inf
        for p in range(kind.shape[0]):
            d, _ = _eval(kind[p], geom[p], points[q, 0], points[q, 1], points[q, 2], code, n)
            best = min(best, d)
        out[q] = best


def union_distance(prims: Primitives, code: int, exponent: float, points: np.ndarray) -> np.ndarray:
    """``min`` over all primitives at each point: the deposit's exact distance outside it (a
    lower bound on depth inside). Brute force: for a few points far from the grid's band."""
    out = np.empty(len(points))
    _union_min(prims.kind, prims.geom, np.ascontiguousarray(points, np.float64), code, exponent, out)
    return out


@dataclass(frozen=True)
class Domain:
    voxel: float
    origin: np.ndarray  # world position of voxel index (0,0,0), on the voxel lattice
    block_shape: tuple[int, int, int]
    band: float


def make_domain(prims: Primitives, voxel: float, band: float, extra_bounds=None) -> Domain:
    """The block table around the primitives (and ``extra_bounds``, e.g. a CAD part)."""
    if len(prims) == 0:
        raise DmdvoxError("the toolpath deposits nothing (no deposit moves); check --dialect and the laser codes")
    pad = band + 2 * voxel
    lo = prims.lo.min(axis=0)
    hi = prims.hi.max(axis=0)
    if extra_bounds is not None:
        lo = np.minimum(lo, extra_bounds[0])
        hi = np.maximum(hi, extra_bounds[1])
    lo = lo - pad
    hi = hi + pad
    # Voxel centres sit on integer multiples of the voxel size, so every grid built on this
    # lattice (CAD, nozzle, fixtures) shares it exactly.
    i0 = np.floor(lo / voxel).astype(np.int64)
    i1 = np.ceil(hi / voxel).astype(np.int64)
    blocks = tuple(int(v) for v in -(-(i1 - i0 + 1) // 8))
    return Domain(voxel=voxel, origin=i0 * voxel, block_shape=blocks, band=band)


def estimate_memory(prims: Primitives, domain: Domain) -> int:
    """Bytes the grid and its construction need, from the bead surface area (an upper bound:
    surfaces shared by overlapping beads vanish in the union)."""
    g = prims.geom
    seg = prims.kind == SEGMENT
    arcs = prims.kind == ARC
    caps = prims.kind == CAP
    perimeter = g[:, _W] + 2 * (g[:, _H] + g[:, _FOOT])
    area = (np.sum(g[seg, 12] * perimeter[seg]) + np.sum(np.abs(g[arcs, 3] * g[arcs, 5]) * perimeter[arcs])
            + np.sum(np.pi * g[caps, _W] * (g[caps, _H] + g[caps, _FOOT])))
    nb = np.prod(domain.block_shape, dtype=np.float64)
    slab = min(SLAB_BUDGET_BYTES[1], nb * 512 * SLAB_BYTES_PER_VOXEL)
    return surface_memory(area, domain.voxel, domain.band, nb) + int(slab)


def plan_deposit(beads: Beads, voxel: float, *, max_memory: int | None = None,
                 extra_bounds=None, also_holds: dict[str, int] | None = None) -> tuple[Primitives, Domain]:
    """The primitives and the domain :func:`deposit` would sweep, after refusing (before any
    grid is allocated) a request that would not fit in ``max_memory`` beside what the caller
    ``also_holds`` (name -> bytes: a CAD part, the nozzle)."""
    check_voxel(voxel)
    prims = build_primitives(beads)
    domain = make_domain(prims, voxel, BAND_VOXELS * voxel, extra_bounds)
    check_memory({"deposit": estimate_memory(prims, domain), **(also_holds or {})}, voxel, max_memory)
    return prims, domain


def check_voxel(voxel: float) -> None:
    if not np.isfinite(voxel) or voxel <= 0:
        raise DmdvoxError(f"--voxel must be a positive number of mm, got {voxel}")


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


def deposit_beads(beads: Beads, voxel: float, *, max_memory: int | None = None, progress=None, extra_bounds=None,
                  scheduler: str | None = None,
                  also_holds: dict[str, int] | None = None) -> tuple[SparseGrid, dict]:
    """Sweep the bead elements into a sparse grid.

    Returns the grid and timings. ``progress(done, total)`` is called per slab of blocks.
    ``extra_bounds`` ``(lo, hi)`` widens the block table, so that another grid (a CAD part)
    built on the same lattice shares it block for block. With ``scheduler`` (a dask address)
    the z slabs are swept on the cluster's workers and merged here: the slabs carry their own
    halo of one band, so the grid is identical to the local one.
    """
    timings = {}
    t_start = time.perf_counter()
    prims, domain = plan_deposit(beads, voxel, max_memory=max_memory, extra_bounds=extra_bounds, also_holds=also_holds)
    band = domain.band
    timings["primitives_s"] = time.perf_counter() - t_start

    t = time.perf_counter()
    builder = GridBuilder(voxel, domain.origin, domain.block_shape, band)
    nbx, nby, nbz = domain.block_shape
    per_layer = 64 * nbx * nby * 8 * SLAB_BYTES_PER_VOXEL
    slab_budget = int(np.clip(available_memory() // 8, *SLAB_BUDGET_BYTES))
    layers_per_slab = int(max(1, min(nbz, slab_budget // per_layer)))
    slabs = [SlabTask(prims, beads.code, beads.exponent, domain, bz0, min(nbz, bz0 + layers_per_slab), beads.floor_z)
             for bz0 in range(0, nbz, layers_per_slab)]
    results = map_tasks(sweep_slab, slabs, scheduler=scheduler)
    for task, (coords, block_sdf, block_arr, slab_timings) in zip(slabs, results):
        builder.add_blocks(coords, block_sdf, block_arr)
        for key, value in slab_timings.items():
            timings[key] = timings.get(key, 0.0) + value
        if progress is not None:
            progress(task.bz1, nbz)
    grid = builder.finish(meta={"profile": profile_name(beads.code), "voxel_mm": voxel})
    timings["sweep_s"] = time.perf_counter() - t
    timings["domain_voxels"] = float(np.prod(domain.block_shape, dtype=np.float64) * 512)
    return grid, timings


@dataclass(frozen=True)
class SlabTask:
    """One z slab of blocks [bz0, bz1) of the domain: everything its sweep needs (picklable)."""

    prims: Primitives
    code: int
    exponent: float
    domain: Domain
    bz0: int
    bz1: int
    floor_z: float = -np.inf


def sweep_slab(task: SlabTask):
    """Sweep one slab (with a halo of one band above and below) and cut it into the blocks the
    grid keeps: ``(coords, sdf, arrival, timings)``. Pure: the same task gives the same bytes
    wherever it runs."""
    prims, domain = task.prims, task.domain
    voxel, band = domain.voxel, domain.band
    nbx, nby, _ = domain.block_shape
    nx, ny = 8 * nbx, 8 * nby
    halo = int(np.ceil(band / voxel))
    k0 = 8 * task.bz0 - halo
    nz = 8 * (task.bz1 - task.bz0) + 2 * halo
    prim_zlo = np.floor((prims.lo[:, 2] - band - domain.origin[2]) / voxel)
    prim_zhi = np.ceil((prims.hi[:, 2] + band - domain.origin[2]) / voxel)
    prim_ids = np.flatnonzero((prim_zhi >= k0) & (prim_zlo <= k0 + nz - 1)).astype(np.int64)
    timings = {}
    t_phase = time.perf_counter()
    sdf = np.full((nx, ny, nz), band, np.float32)
    arr = np.full((nx, ny, nz), np.inf, np.float32)
    near_out = np.full((nx, ny, nz), 255, np.uint8)
    shallow = np.full((nx, ny, nz), 255, np.uint8)
    free = np.full((nx, ny, nz), 63, np.uint8)
    _splat(prim_ids, prims.kind, prims.geom, prims.t0, prims.t1, prims.lo, prims.hi, task.code, task.exponent,
           voxel, domain.origin, k0, band, sdf, arr, near_out, shallow, free)
    if np.isfinite(task.floor_z):
        _cut_below(sdf, task.floor_z, domain.origin[2] + k0 * voxel, voxel)
    timings["splat_s"] = time.perf_counter() - t_phase
    t_phase = time.perf_counter()
    near = np.empty(sdf.shape, np.bool_)
    _near_outside(sdf, halo, near)
    core = np.empty((nx, ny, nz - 2 * halo), np.float32)
    _finish_slab(sdf, near, voxel, band, halo, NEIGHBOURHOOD_VOXELS, near_out, shallow, free, core)
    del sdf, near, near_out, shallow, free
    timings["band_s"] = time.perf_counter() - t_phase
    t_phase = time.perf_counter()
    slots = _block_slots(core, np.float32(band))
    m = int(slots.max()) + 1
    coords = np.empty((m, 3), np.int32)
    block_sdf = np.empty((m, 8, 8, 8), np.float32)
    block_arr = np.empty((m, 8, 8, 8), np.float32)
    _gather_blocks(core, arr, halo, slots, task.bz0, coords, block_sdf, block_arr)
    timings["pack_s"] = time.perf_counter() - t_phase
    return coords, block_sdf, block_arr, timings


__all__ = ["Primitives", "build_primitives", "plan_deposit", "deposit", "estimate_memory", "union_distance"]
