"""Numba kernels of the collision engine: SAT box tests, tree descent, voxel-level distance.

Two bodies meet in every query: the *target* (an obstacle: the part, a fixture) whose tree is
descended in its own frame, and the *probe* (the nozzle, a moved scene object) posed in the
target's frame by a rotation ``R`` (probe axes as columns) and a translation ``T``.

Descent: a target node is kept only if it holds material at time ``t`` (occupancy not EMPTY,
``min_arrival <= t``) and its box, grown by ``reach``, overlaps some probe node box that holds
material (an OBB once posed; :func:`probe_near` descends the probe's tree for one). Target
level-0 blocks that survive are tested voxel by voxel.

Voxel level: at every inside voxel centre ``p`` of the target whose material has arrived,
``d(p) = s_probe(p) + s_target(p)``. ``s_target(p) <= 0`` is the depth of ``p`` in the target, so
the ball of radius ``-s_target(p)`` around ``p`` is target material, and ``s_probe(p)`` is the
distance from ``p`` to the probe (negative inside). ``d(p) < 0`` therefore proves an overlap
(the ball reaches into the probe) and ``d(p) >= 0`` bounds the gap from above: the minimum over
the voxels is the clearance (negative: the penetration depth), to within about a voxel. A probe
wholly inside the target is caught too: the target's deep voxels inside the probe give
``d < 0``. Clamped SDF values keep the test sound: a clamped target depth (-band) is shallower
than the truth, and probe samples that touch the probe's clamp (+band) are skipped, so the
probe band must exceed the target band plus the reach (the callers build it so).

Only target voxels *inside* the material are used: they carry arrival times, so the test is
exact in time per voxel (octant minima for voxels deeper than the band, which is conservative),
whereas outside voxels cannot tell which bead their distance refers to.

Poses along a path (:func:`query_poses`) use four things that leave every value unchanged:
conservative advancement (a pose out of reach certifies a margin within which the following
poses are out of reach too, see :func:`_descend`), shared descents near an obstacle (one
descent with a grown reach lists the block pairs of the next poses, :func:`_collect`), the
previous pose's value as a first cut (:func:`query`), and, with the tool axis fixed (R the
identity), per-axis tables and tighter bounds in :func:`eval_block` and three-comparison SAT
tests (:func:`aligned_thresholds`). A rotated probe (five-axis poses, :func:`query_poses_rotated`)
takes the general path: SAT on the six face normals from thresholds precomputed per rotation
(:func:`general_thresholds`), and in :func:`eval_block` bounds per block, octant, 2^3 group and
voxel from per-block coordinate tables before any trilinear sample, whose values are computed
exactly as :func:`probe_sdf` does (the aligned path's, bit for bit, at R = I).

Bodies are passed as one named structure, :data:`BodyView` (see
:meth:`dmdvox.collision.bodies.Body.kernel_args`): the octree's occupancy, minimum arrival and
level tables, the grid's arrays as :data:`~dmdvox.grid.sparse.GridView` names them, ``geo``
float64 ``[origin x, y, z, voxel, band, largest sample]`` (the band, or an active value above
it), ``rank_prefix`` (n_leaf, 8) int64, the number of
active voxels of a leaf before each 64-bit word, and ``node_box`` (nodes above level 0, 6)
float64, the box of each node's material (centre, half extents; see
:func:`dmdvox.collision.bodies._node_boxes`).
"""

from __future__ import annotations

from collections import namedtuple

import numba as nb
import numpy as np

from ..grid.sparse import OUTSIDE, popcount64

BodyView = namedtuple("BodyView", ["occupancy", "min_arrival", "level_offset", "level_shape", "block",
                                   "leaf_active", "leaf_inside", "sdf_offset", "sdf", "arr_offset", "arrival",
                                   "leaf_octant_arrival", "tile_arrival", "geo", "rank_prefix", "node_box"])

_U1 = np.uint64(1)
_LOW32 = np.uint64(0xFFFFFFFF)
_OCTANT_BITS = np.uint64(0x0F0F0F0F)  # ly 0-3, lz 0-3 of a leaf mask word
_GROUP_BITS = np.uint64(0x0303)  # ly 0-1, lz 0-1
_HIGH32 = np.uint64(0xFFFFFFFF00000000)
SQRT3 = np.sqrt(3.0)
SAT_EPS = 1e-9  # added to |R|: keeps the cross-product axes robust when two edges are parallel
BOX_PAD_MM = 1e-9  # added to the half extents of the material boxes (BodyView.node_box)
STACK_PER_LEVEL = 8
# Conservative advancement (query_poses): poses within ADVANCE_WINDOW_MM of a certifying pose
# may be skipped (a longer window only makes arrival times later); ADVANCE_TOL_MM absorbs the
# rounding of the SAT terms (mm-scale coordinates, float64) at the poses a margin covers.
ADVANCE_WINDOW_MM = 8.0
ADVANCE_TOL_MM = 1e-6
LIPSCHITZ_EPS = 0.01  # voxels: the float32 samples are 1-Lipschitz up to their rounding
HINT_SLOPE = 1.5  # query_poses: d of the previous pose + this times the step hints at d
# query_poses near an obstacle (R = I): one descent, with the reach grown by SHARE_MM, lists
# the block pairs of every pose within SHARE_MM (at most SHARE_CAP pairs)
SHARE_MM = 0.5
SHARE_CAP = 1 << 16
POSE_CHUNK = 512
STRIPES = 16


@nb.njit(cache=True, inline="always")
def sat_disjoint(tx, ty, tz, ea0, ea1, ea2, eb0, eb1, eb2, R, AbsR):
    """Separating-axis test of box A (half extents ``ea``, axes = the frame's) and box B
    (half extents ``eb``, axes = columns of ``R``, centre offset ``t`` from A's, in A's frame).

    True when one of the 6 face normals separates them (Gottschalk's OBB test without its 9
    edge cross products; ``AbsR = |R| + eps``, hoisted by the caller since R is fixed per pose).
    Conservative: a pair only the cross axes separate is kept and split further, which costs
    less on the node pairs of a descent (nearly all apart on a face normal or overlapping) than
    testing 9 more axes on every one.
    """
    # A's face normals
    if abs(tx) > ea0 + eb0 * AbsR[0, 0] + eb1 * AbsR[0, 1] + eb2 * AbsR[0, 2]:
        return True
    if abs(ty) > ea1 + eb0 * AbsR[1, 0] + eb1 * AbsR[1, 1] + eb2 * AbsR[1, 2]:
        return True
    if abs(tz) > ea2 + eb0 * AbsR[2, 0] + eb1 * AbsR[2, 1] + eb2 * AbsR[2, 2]:
        return True
    # B's face normals
    for j in range(3):
        eb = eb0 if j == 0 else (eb1 if j == 1 else eb2)
        ra = ea0 * AbsR[0, j] + ea1 * AbsR[1, j] + ea2 * AbsR[2, j]
        if abs(tx * R[0, j] + ty * R[1, j] + tz * R[2, j]) > ra + eb:
            return True
    return False


@nb.njit(cache=True)
def aligned_thresholds(ea, eb, AbsR, out):
    """Per axis k, the smallest separating-axis threshold whose axis is k when R is the identity
    (cubes: ``ea``, ``eb`` isotropic), written to ``out`` (3,).

    With R = I every one of Gottschalk's 15 tests (:func:`sat_disjoint`'s six face normals and
    the nine edge cross products, each a valid separating axis) reads ``|t_k| > threshold`` for
    some k (the B faces and the cross axes repeat A's faces, or vanish and never separate):
    ``|t_k| > out[k]`` for some k decides them all at 3 comparisons.
    """
    for k in range(3):
        out[k] = ea + eb * AbsR[k, 0] + eb * AbsR[k, 1] + eb * AbsR[k, 2]
    for j in range(3):
        out[j] = min(out[j], ea * AbsR[0, j] + ea * AbsR[1, j] + ea * AbsR[2, j] + eb)
    for i in range(3):
        i1 = (i + 1) % 3
        i2 = (i + 2) % 3
        for j in range(3):
            if j == i:
                continue
            j1 = (j + 1) % 3
            j2 = (j + 2) % 3
            threshold = (ea * AbsR[i2, j] + ea * AbsR[i1, j]) + (eb * AbsR[i, j2] + eb * AbsR[i, j1])
            # the axis e_i x e_j: |t_i2| when j == i1, |t_i1| when j == i2
            k = i2 if j == i1 else i1
            out[k] = min(out[k], threshold)


@nb.njit(cache=True, inline="always")
def _corner(block, act, ins, sdf_offset, sdf, prefix, band, i, j, k):
    """Probe SDF at an integer index; +band (the clamp) outside its table.

    A one-popcount rank (per-word prefix counts) on explicit arrays: this runs 8 times per
    target voxel, where the generic ``leaf_value`` (views, a rank loop) costs ~100x more.
    """
    bi, bj, bk = i >> 3, j >> 3, k >> 3
    if i < 0 or j < 0 or k < 0 or bi >= block.shape[0] or bj >= block.shape[1] or bk >= block.shape[2]:
        return band
    val = block[bi, bj, bk]
    if val >= 0:
        v = (i & 7) * 64 + (j & 7) * 8 + (k & 7)
        w = v >> 6
        b = np.uint64(v & 63)
        m = act[val, w]
        if (m >> b) & _U1:
            return sdf[sdf_offset[val] + prefix[val, w] + popcount64(m & ((_U1 << b) - _U1))]
        if (ins[val, w] >> b) & _U1:
            return -band
        return band
    if val == OUTSIDE:
        return band
    return -band


@nb.njit(cache=True, inline="always")
def _nearest(block, act, ins, sdf_offset, sdf, prefix, origin, h, band, qx, qy, qz):
    """Probe SDF at the voxel centre nearest a probe-frame point (one lookup; clamped)."""
    return _corner(block, act, ins, sdf_offset, sdf, prefix, band, np.int64(np.floor((qx - origin[0]) / h + 0.5)),
                   np.int64(np.floor((qy - origin[1]) / h + 0.5)), np.int64(np.floor((qz - origin[2]) / h + 0.5)))


@nb.njit(cache=True, inline="always")
def _trilinear(block, act, ins, sdf_offset, sdf, prefix, band, i0, j0, k0, tx, ty, tz):
    """Trilinear probe SDF in cell (i0, j0, k0) at fractions (tx, ty, tz); +inf where any corner
    is clamped at +band (the distance there is unknown beyond the band, see module docstring)."""
    if i0 < 0 or j0 < 0 or k0 < 0 or i0 + 1 >= 8 * block.shape[0] or j0 + 1 >= 8 * block.shape[1] \
            or k0 + 1 >= 8 * block.shape[2]:
        return np.inf
    acc = 0.0
    for c in range(8):
        di, dj, dk = c >> 2, (c >> 1) & 1, c & 1
        v = _corner(block, act, ins, sdf_offset, sdf, prefix, band, i0 + di, j0 + dj, k0 + dk)
        if v >= band:
            return np.inf
        w = (tx if di else 1.0 - tx) * (ty if dj else 1.0 - ty) * (tz if dk else 1.0 - tz)
        acc += w * v
    return acc


@nb.njit(cache=True)
def probe_sdf(block, act, ins, sdf_offset, sdf, prefix, origin, h, band, qx, qy, qz):
    """Trilinear probe SDF at a probe-frame point (see :func:`_trilinear`)."""
    ux = (qx - origin[0]) / h
    uy = (qy - origin[1]) / h
    uz = (qz - origin[2]) / h
    fx, fy, fz = np.floor(ux), np.floor(uy), np.floor(uz)
    return _trilinear(block, act, ins, sdf_offset, sdf, prefix, band, np.int64(fx), np.int64(fy), np.int64(fz),
                      ux - fx, uy - fy, uz - fz)


@nb.njit(cache=True)
def eval_block(g_block, g_act, g_ins, g_sdf_offset, g_sdf, g_arr_offset, g_arrival, g_leaf_oct, g_tile_arr, g_origin,
               g_h, g_band, p_block, p_act, p_ins, p_sdf_offset, p_sdf, p_prefix, p_origin, p_h, p_band, p_top,
               bi, bj, bk, R, T, aligned, t, cut, floor, lut, frac):
    """Minimum of ``d`` over the inside voxels of target block (bi, bj, bk) arrived by ``t``,
    or +inf when no voxel gets below ``cut`` (the best so far, at most the reach). Stops once it
    reaches ``floor``, the most negative value the clamped SDFs can give. ``p_top``: the probe's
    largest sample, which decides a block, octant or group bound without a lookup when even it
    leaves the bound below the cut (the probe's band is narrow next to the reach and the slack).

    Bounds skip work: the clamped SDFs are 1-Lipschitz, so the probe SDF anywhere in a 4^3
    octant (at a voxel) is at least its value at the probe voxel nearest the octant centre (the
    voxel) less the distance between the trilinear corners involved (``slack``).

    ``aligned`` (R is the identity): a voxel's probe-frame coordinate along an axis depends on
    its index along that axis only, so the nearest probe index, the trilinear cell and its
    fractions come from per-axis tables of 8 (``lut`` (9, 8) int64 and ``frac`` (12, 8) float64
    scratch), computed with the very operations of the general path: the same values, bit for
    bit, without a rotation, division and floor per voxel. The bounds are tighter there. For a
    sample ``n`` and a point ``u`` (index units, fractions ``f``) the trilinear weights average
    ``|c - n|_1`` over the corners ``c`` to ``sum_i |u_i - n_i|`` (``n`` an integer is never
    strictly inside the cell), and ``|c - n|^2`` to ``sum_i (u_i - n_i)^2 + f_i (1 - f_i)``. With
    ``s(c) >= s(n) - |c - n|``: a voxel's value is at least ``s(n)`` less the first sum (``n``
    its nearest sample, ``frac[3:6]``), an octant's at least ``s(n)`` less the square root
    (Jensen) of the second sum's maximum over the octant (``n`` nearest the octant centre,
    ``lut[6:]``, ``frac[9:]``); ``LIPSCHITZ_EPS`` voxels cover the float32 rounding of samples.
    """
    val = g_block[bi, bj, bk]
    if val == OUTSIDE:
        return np.inf
    x0 = g_origin[0] + 8 * bi * g_h
    y0 = g_origin[1] + 8 * bj * g_h
    z0 = g_origin[2] + 8 * bk * g_h
    lip_eps = LIPSCHITZ_EPS * p_h
    if aligned:
        for a in range(3):
            corner0 = x0 if a == 0 else (y0 if a == 1 else z0)
            for m in range(8):
                u = (corner0 + m * g_h - T[a] - p_origin[a]) / p_h
                f = np.floor(u)
                nearest = np.floor(u + 0.5)
                lut[a, m] = np.int64(nearest)
                lut[3 + a, m] = np.int64(f)
                frac[a, m] = u - f
                frac[3 + a, m] = abs(u - nearest) * p_h
                frac[6 + a, m] = u
            for half in range(2):
                centre = np.floor(0.5 * (frac[6 + a, 4 * half + 1] + frac[6 + a, 4 * half + 2]) + 0.5)
                lut[6 + a, half] = np.int64(centre)
                spread = 0.0
                for m in range(4 * half, 4 * half + 4):
                    spread = max(spread, (frac[6 + a, m] - centre) ** 2 + frac[a, m] * (1.0 - frac[a, m]))
                frac[9 + a, half] = spread
    else:
        # probe index coordinates of the block's first voxel (the tables below add the others'
        # offsets; the values themselves come from the exact expression of probe_sdf), and one
        # bound for the whole block first (half diagonal 3.5 sqrt(3) voxels)
        bx, by, bz = x0 - T[0], y0 - T[1], z0 - T[2]
        r = g_h / p_h
        for c in range(3):
            frac[c, 0] = (R[0, c] * bx + R[1, c] * by + R[2, c] * bz - p_origin[c]) / p_h
        ux = frac[0, 0] + 3.5 * r * (R[0, 0] + R[1, 0] + R[2, 0])
        uy = frac[1, 0] + 3.5 * r * (R[0, 1] + R[1, 1] + R[2, 1])
        uz = frac[2, 0] + 3.5 * r * (R[0, 2] + R[1, 2] + R[2, 2])
        nx, ny, nz = np.floor(ux + 0.5), np.floor(uy + 0.5), np.floor(uz + 0.5)
        reach_n = 3.5 * SQRT3 * r + np.sqrt((ux - nx) ** 2 + (uy - ny) ** 2 + (uz - nz) ** 2)
        slack = p_h * np.sqrt(reach_n * reach_n + 0.75)
        # (each bound is tried with the probe's largest sample first: the lookup only where that
        # could beat the cut; rounding is monotone, so the outcome is the lookup's)
        if p_top - slack - lip_eps - g_band >= cut \
                and _corner(p_block, p_act, p_ins, p_sdf_offset, p_sdf, p_prefix, p_band, np.int64(nx), np.int64(ny),
                            np.int64(nz)) - slack - lip_eps - g_band >= cut:
            return np.inf
    # per 4^3 octant: skip it when even its bound cannot beat the cut, or when it holds no inside
    # voxel (a leaf's inside mask, one 64-bit word per lx, bit 8 ly + lz); bit o of live
    half_diag = 1.5 * SQRT3 * g_h / p_h  # octant centre to its farthest voxel, probe index units
    leaf = val >= 0
    live = 0
    for o in range(8):
        if leaf:
            w = 4 * (o >> 2)
            if (g_ins[val, w] | g_ins[val, w + 1] | g_ins[val, w + 2] | g_ins[val, w + 3]) \
                    & (_OCTANT_BITS << np.uint64(32 * ((o >> 1) & 1) + 4 * (o & 1))) == 0:
                continue
        if aligned:
            ox, oy, oz = o >> 2, (o >> 1) & 1, o & 1
            slack = p_h * np.sqrt(frac[9, ox] + frac[10, oy] + frac[11, oz])
            if p_top - slack - lip_eps - g_band < cut:
                live |= 1 << o
                continue
            bound = _corner(p_block, p_act, p_ins, p_sdf_offset, p_sdf, p_prefix, p_band, lut[6, ox], lut[7, oy],
                            lut[8, oz]) - slack - lip_eps
        else:
            # the voxel bound (below) for every voxel of the octant: |u - n| grows by at most the
            # octant's half diagonal from its centre's; the table's rounding (1e-13 voxel) is
            # far inside LIPSCHITZ_EPS
            cx, cy, cz = 4.0 * (o >> 2) + 1.5, 4.0 * ((o >> 1) & 1) + 1.5, 4.0 * (o & 1) + 1.5
            ux = frac[0, 0] + r * (cx * R[0, 0] + cy * R[1, 0] + cz * R[2, 0])
            uy = frac[1, 0] + r * (cx * R[0, 1] + cy * R[1, 1] + cz * R[2, 1])
            uz = frac[2, 0] + r * (cx * R[0, 2] + cy * R[1, 2] + cz * R[2, 2])
            nx, ny, nz = np.floor(ux + 0.5), np.floor(uy + 0.5), np.floor(uz + 0.5)
            reach_n = half_diag + np.sqrt((ux - nx) ** 2 + (uy - ny) ** 2 + (uz - nz) ** 2)
            slack = p_h * np.sqrt(reach_n * reach_n + 0.75)
            if p_top - slack - lip_eps - g_band < cut:
                live |= 1 << o
                continue
            bound = _corner(p_block, p_act, p_ins, p_sdf_offset, p_sdf, p_prefix, p_band, np.int64(nx),
                            np.int64(ny), np.int64(nz)) - slack - lip_eps
        if bound - g_band < cut:
            live |= 1 << o
    if live == 0:
        return np.inf
    if not aligned:
        # u = X[lx] + Y[ly] + Z[lz] (frac rows 0-2, 3-5, 6-8: the x, y, z parts, per component)
        for c in range(3):
            base = frac[c, 0]
            for m in range(8):
                frac[c, m] = base + m * r * R[0, c]
                frac[3 + c, m] = m * r * R[1, c]
                frac[6 + c, m] = m * r * R[2, c]
        # the general path's voxel bounds cost most of a near pose: the 2^3 groups of the live
        # octants get a bound of their own first (half diagonal sqrt(3)/2 voxel), their flags in
        # lut (unused here otherwise) at lut[g >> 3, g & 7], g = 16 gx + 4 gy + gz: a 32-voxel
        # run's eight groups are one lut row
        # |u - n| <= sqrt(3) / 2 from the group centre to its nearest sample: one slack for all
        reach_n = 0.5 * SQRT3 * (g_h / p_h + 1.0)
        group_slack = p_h * np.sqrt(reach_n * reach_n + 0.75) + lip_eps + g_band
        any_live = False
        for g in range(64):
            gx, gy, gz = g >> 4, (g >> 2) & 3, g & 3
            flag = 0
            if (live >> ((gx >> 1) * 4 + (gy >> 1) * 2 + (gz >> 1))) & 1 and not (
                    leaf and (g_ins[val, 2 * gx] | g_ins[val, 2 * gx + 1])
                    & (_GROUP_BITS << np.uint64(16 * gy + 2 * gz)) == 0):
                # the group's centre: the mean of its corner voxels' table entries
                ux = 0.5 * (frac[0, 2 * gx] + frac[0, 2 * gx + 1] + frac[3, 2 * gy] + frac[3, 2 * gy + 1]
                            + frac[6, 2 * gz] + frac[6, 2 * gz + 1])
                uy = 0.5 * (frac[1, 2 * gx] + frac[1, 2 * gx + 1] + frac[4, 2 * gy] + frac[4, 2 * gy + 1]
                            + frac[7, 2 * gz] + frac[7, 2 * gz + 1])
                uz = 0.5 * (frac[2, 2 * gx] + frac[2, 2 * gx + 1] + frac[5, 2 * gy] + frac[5, 2 * gy + 1]
                            + frac[8, 2 * gz] + frac[8, 2 * gz + 1])
                if p_top - group_slack < cut or _corner(p_block, p_act, p_ins, p_sdf_offset, p_sdf, p_prefix, p_band,
                                                        np.int64(np.floor(ux + 0.5)), np.int64(np.floor(uy + 0.5)),
                                                        np.int64(np.floor(uz + 0.5))) - group_slack < cut:
                    flag = 1
                    any_live = True
            lut[g >> 3, g & 7] = flag
        if not any_live:
            return np.inf
    best = np.inf
    ks = g_sdf_offset[val] if leaf else 0
    ka = g_arr_offset[val] if leaf else 0
    # 32-voxel runs (one lx, ly 0-3 or 4-7) without an inside voxel or whose two octants are
    # both dead are skipped whole, the packed offsets advanced by popcounts
    for run in range(16):
        w = run >> 1
        half = _HIGH32 if run & 1 else _LOW32
        if aligned:
            run_live = (live >> ((w >> 2) * 4 + (run & 1) * 2)) & 3 != 0
        else:
            row = (w >> 1) * 2 + (run & 1)
            run_live = (lut[row, 0] | lut[row, 1] | lut[row, 2] | lut[row, 3] | lut[row, 4] | lut[row, 5]
                        | lut[row, 6] | lut[row, 7]) != 0
        if not run_live or (leaf and (g_ins[val, w] & half) == 0):
            if leaf:
                ks += popcount64(g_act[val, w] & half)
                ka += popcount64(g_act[val, w] & g_ins[val, w] & half)
            continue
        for v in range(32 * run, 32 * run + 32):
            b = np.uint64(v & 63)
            o0, o1, o2 = v >> 8, (v >> 5) & 1, (v >> 2) & 1
            if leaf:
                a_bit = (g_act[val, w] >> b) & _U1
                i_bit = (g_ins[val, w] >> b) & _U1
                if a_bit:
                    s_t = g_sdf[ks]
                    ks += 1
                    if not i_bit:
                        continue
                    arr = g_arrival[ka]
                    ka += 1
                elif i_bit:
                    s_t = -g_band
                    arr = g_leaf_oct[val, o0, o1, o2]
                else:
                    continue
            else:
                s_t = -g_band
                arr = g_tile_arr[-2 - val, o0, o1, o2]
            if arr > t:
                continue
            if aligned:
                if not (live >> (o0 * 4 + o1 * 2 + o2)) & 1:
                    continue
                lx, ly, lz = v >> 6, (v >> 3) & 7, v & 7
                if _corner(p_block, p_act, p_ins, p_sdf_offset, p_sdf, p_prefix, p_band, lut[0, lx], lut[1, ly],
                           lut[2, lz]) - (frac[3, lx] + frac[4, ly] + frac[5, lz] + lip_eps) + s_t >= cut:
                    continue
                d = _trilinear(p_block, p_act, p_ins, p_sdf_offset, p_sdf, p_prefix, p_band, lut[3, lx], lut[4, ly],
                               lut[5, lz], frac[0, lx], frac[1, ly], frac[2, lz]) + s_t
            else:
                # the bound: n the sample nearest u (per axis the floor, or the one above when the
                # fraction t >= 1/2); the trilinear weights average |c - n|^2 over the cell's
                # corners c to |u - n|^2 + sum t (1 - t), whose per-axis term is min(t, 1 - t):
                # the value is at least s(n) less p_h times its square root (Jensen)
                lx, ly, lz = v >> 6, (v >> 3) & 7, v & 7
                if lut[(lx >> 1) * 2 + (ly >> 2), ((ly >> 1) & 1) * 4 + (lz >> 1)] == 0:
                    continue
                ax = frac[0, lx] + frac[3, ly] + frac[6, lz]
                ay = frac[1, lx] + frac[4, ly] + frac[7, lz]
                az = frac[2, lx] + frac[5, ly] + frac[8, lz]
                ix, iy, iz = np.floor(ax), np.floor(ay), np.floor(az)
                ax -= ix
                ay -= iy
                az -= iz
                # the per-axis terms also average |c - n|_1 (>= |c - n|): the smaller slack of the
                # two, the sum below 1 and its square root above
                spread = min(ax, 1.0 - ax) + min(ay, 1.0 - ay) + min(az, 1.0 - az)
                gap = _corner(p_block, p_act, p_ins, p_sdf_offset, p_sdf, p_prefix, p_band,
                              np.int64(ix) + (ax >= 0.5), np.int64(iy) + (ay >= 0.5), np.int64(iz) + (az >= 0.5)) \
                    - lip_eps + s_t - cut
                if gap >= p_h * spread if spread <= 1.0 else (gap >= 0.0 and gap * gap >= p_h * p_h * spread):
                    continue
                # the target voxel centre in the probe frame, R^T (p - T), and its value exactly
                # as probe_sdf computes it (the axis-aligned path's values, bit for bit, at R = I)
                dx = x0 + lx * g_h - T[0]
                dy = y0 + ly * g_h - T[1]
                dz = z0 + lz * g_h - T[2]
                qx = R[0, 0] * dx + R[1, 0] * dy + R[2, 0] * dz
                qy = R[0, 1] * dx + R[1, 1] * dy + R[2, 1] * dz
                qz = R[0, 2] * dx + R[1, 2] * dy + R[2, 2] * dz
                d = probe_sdf(p_block, p_act, p_ins, p_sdf_offset, p_sdf, p_prefix, p_origin, p_h, p_band, qx, qy,
                              qz) + s_t
            if d < best:
                best = d
                cut = min(cut, d)
                if best <= floor:
                    return best
    return best


@nb.njit(cache=True, inline="always")
def _push(stack, top, gl, gi, gj, gk, pl, pi, pj, pk):
    stack[top, 0] = gl
    stack[top, 1] = gi
    stack[top, 2] = gj
    stack[top, 3] = gk
    stack[top, 4] = pl
    stack[top, 5] = pi
    stack[top, 6] = pj
    stack[top, 7] = pk
    return top + 1


@nb.njit(cache=True, inline="always")
def _split(stack, top, g_lshape, p_lshape, split_obstacle, gl, gi, gj, gk, pl, pi, pj, pk):
    """Push the children of the obstacle node (``split_obstacle``) or of the probe node, each
    paired with the other node unchanged; returns the new stack top."""
    shape = g_lshape if split_obstacle else p_lshape
    level = gl if split_obstacle else pl
    i0, j0, k0 = (gi, gj, gk) if split_obstacle else (pi, pj, pk)
    for di in range(2):
        ci = 2 * i0 + di
        if ci >= shape[level - 1, 0]:
            continue
        for dj in range(2):
            cj = 2 * j0 + dj
            if cj >= shape[level - 1, 1]:
                continue
            for dk in range(2):
                ck = 2 * k0 + dk
                if ck >= shape[level - 1, 2]:
                    continue
                if split_obstacle:
                    top = _push(stack, top, gl - 1, ci, cj, ck, pl, pi, pj, pk)
                else:
                    top = _push(stack, top, gl, gi, gj, gk, pl - 1, ci, cj, ck)
    return top


@nb.njit(cache=True, inline="always")
def _node_centres(pc0, pc1, pc2, pi, pj, pk, p_size, gc0, gc1, gc2, gi, gj, gk, g_size):
    """Box centres of probe node (pi, pj, pk) (side ``p_size``, grid corner ``pc``) and target
    node (gi, gj, gk) (side ``g_size``, corner ``gc``), each in its own body's frame."""
    return (pc0 + (pi + 0.5) * p_size, pc1 + (pj + 0.5) * p_size, pc2 + (pk + 0.5) * p_size,
            gc0 + (gi + 0.5) * g_size, gc1 + (gj + 0.5) * g_size, gc2 + (gk + 0.5) * g_size)


@nb.njit(cache=True, inline="always")
def _posed_offset(R, T, lc0, lc1, lc2, g0, g1, g2):
    """The posed probe box centre relative to the target box centre (target frame)."""
    return (R[0, 0] * lc0 + R[0, 1] * lc1 + R[0, 2] * lc2 + T[0] - g0,
            R[1, 0] * lc0 + R[1, 1] * lc1 + R[1, 2] * lc2 + T[1] - g1,
            R[2, 0] * lc0 + R[2, 1] * lc1 + R[2, 2] * lc2 + T[2] - g2)


@nb.njit(cache=True, inline="always")
def sat_margin(tx, ty, tz, ea, eb, R, AbsR, aligned):
    """How far the half extent ``ea`` of cube A could grow with cube B (half extent ``eb``, axes
    the columns of ``R``) still separated on one of :func:`sat_disjoint`'s axes (the six face
    normals; three when aligned); <= 0 when not.

    Per axis the gap ``|t . a| - ra - rb`` shrinks by ``s`` per unit of growth (``s`` = the sum
    of the |R| terms that multiply ``ea``), and a translation of B by ``v`` moves ``t . a`` by
    at most ``|v| |a| <= |v| s``: a margin above ``delta`` keeps the pair separated with the
    original ``ea`` after any translation of B by up to ``delta``. ``aligned`` (R the identity):
    the other axes repeat A's faces or vanish, so those three suffice.
    """
    best = -np.inf
    tv = (tx, ty, tz)
    for i in range(3):
        best = max(best, abs(tv[i]) - ea - eb * (AbsR[i, 0] + AbsR[i, 1] + AbsR[i, 2]))
    if aligned:
        return best
    for j in range(3):
        s = AbsR[0, j] + AbsR[1, j] + AbsR[2, j]  # >= 1: the |components| of a unit vector
        best = max(best, (abs(tx * R[0, j] + ty * R[1, j] + tz * R[2, j]) - ea * s - eb) / s)
    return best


@nb.njit(cache=True, inline="always")
def _boxes_apart(tx, ty, tz, ha0, ha1, ha2, hb0, hb1, hb2, R, AbsR, aligned):
    """:func:`sat_disjoint` for boxes A (half extents ``ha``, the frame's axes) and B (``hb``, axes
    the columns of ``R``): A's face normals, then (unless ``aligned``) B's."""
    if abs(tx) > ha0 + hb0 * AbsR[0, 0] + hb1 * AbsR[0, 1] + hb2 * AbsR[0, 2] \
            or abs(ty) > ha1 + hb0 * AbsR[1, 0] + hb1 * AbsR[1, 1] + hb2 * AbsR[1, 2] \
            or abs(tz) > ha2 + hb0 * AbsR[2, 0] + hb1 * AbsR[2, 1] + hb2 * AbsR[2, 2]:
        return True
    if aligned:
        return False
    for j in range(3):
        hb = hb0 if j == 0 else (hb1 if j == 1 else hb2)
        reach = ha0 * AbsR[0, j] + ha1 * AbsR[1, j] + ha2 * AbsR[2, j] + hb
        if abs(tx * R[0, j] + ty * R[1, j] + tz * R[2, j]) > reach:
            return True
    return False


@nb.njit(cache=True, inline="always")
def box_margin(tx, ty, tz, ha0, ha1, ha2, hb0, hb1, hb2, R, AbsR, aligned):
    """:func:`sat_margin` for the boxes of :func:`_boxes_apart`: the growth of all of A's half
    extents that keeps them apart on one of its axes; <= 0 when they are not."""
    best = max(abs(tx) - ha0 - (hb0 * AbsR[0, 0] + hb1 * AbsR[0, 1] + hb2 * AbsR[0, 2]),
               abs(ty) - ha1 - (hb0 * AbsR[1, 0] + hb1 * AbsR[1, 1] + hb2 * AbsR[1, 2]),
               abs(tz) - ha2 - (hb0 * AbsR[2, 0] + hb1 * AbsR[2, 1] + hb2 * AbsR[2, 2]))
    if aligned:
        return best
    for j in range(3):
        hb = hb0 if j == 0 else (hb1 if j == 1 else hb2)
        s = AbsR[0, j] + AbsR[1, j] + AbsR[2, j]
        best = max(best, (abs(tx * R[0, j] + ty * R[1, j] + tz * R[2, j])
                          - (ha0 * AbsR[0, j] + ha1 * AbsR[1, j] + ha2 * AbsR[2, j]) - hb) / s)
    return best


@nb.njit(cache=True)
def _descend(G, P, R, AbsR, T, t, reach, cut, ws, stamp, t_window):
    """Minimum ``d`` over the voxels of the blocks in reach when it is below ``cut`` (else +inf),
    and the certified margin (below: ``-inf`` when a block was evaluated or ``t_window < t``).

    Node-pair descent: a pair survives when the target box grown by ``reach`` and the posed probe
    box overlap (SAT); the larger node of a surviving pair is split. A target block reached with
    a probe leaf (or a FULL probe node) is evaluated once per query: ``done[block] == stamp``.
    Before a split, the same test on the nodes' material boxes (``node_box``: the bounding box of
    the cubes of the final pairs below, far smaller than a node's cube at the top of the trees,
    where a thin cone or a flat part fills little of it): boxes apart on an axis put every final
    pair below apart on it (the cubes lie inside the boxes, and a cube's ``SAT_EPS`` slack is at
    most its box's), so the pairs tested at the final level, the blocks evaluated and their order
    are those of the plain descent, without the pairs in between.

    The margin ``M`` (conservative advancement): when no block is evaluated, the minimum of
    :func:`sat_margin` (:func:`box_margin` for material boxes) over the pairs pruned by SAT and
    over those pruned only because their material arrives after ``t`` but by ``t_window``. Then
    the descent at any pose ``T + v``, ``|v| < M``, and any time up to ``t_window`` evaluates no
    block either, so ``d`` is +inf there too. Why: splits, occupancy and the probe's material do
    not depend on the pose, so a pair visited there has its parent visited and split here (by
    induction from the root); a
    pair pruned here by SAT or arriving within the window has a margin above ``|v|`` and is
    pruned there by SAT; one arriving after ``t_window`` is pruned by arrival there too.
    """
    stack, done, lut, frac, thresholds, _, _, _, general = ws
    aligned = True
    for a in range(3):
        for b in range(3):
            aligned = aligned and R[a, b] == (1.0 if a == b else 0.0)
    g_occ, g_marr, g_loff, g_lshape = G.occupancy, G.min_arrival, G.level_offset, G.level_shape
    g_block, g_act, g_ins, g_sdf_offset = G.block, G.leaf_active, G.leaf_inside, G.sdf_offset
    g_sdf, g_arr_offset, g_arrival, g_leaf_oct = G.sdf, G.arr_offset, G.arrival, G.leaf_octant_arrival
    g_tile_arr, g_geo, g_box = G.tile_arrival, G.geo, G.node_box
    p_occ, p_marr, p_loff, p_lshape, p_box = P.occupancy, P.min_arrival, P.level_offset, P.level_shape, P.node_box
    p_block, p_act, p_ins, p_sdf_offset = P.block, P.leaf_active, P.leaf_inside, P.sdf_offset
    p_sdf, p_geo, p_prefix = P.sdf, P.geo, P.rank_prefix
    g_h = g_geo[3]
    g_band = np.float32(g_geo[4])
    g_origin = g_geo[:3]
    p_h = p_geo[3]
    p_band = np.float32(p_geo[4])
    p_origin = p_geo[:3]
    gc0, gc1, gc2 = g_origin[0] - 0.5 * g_h, g_origin[1] - 0.5 * g_h, g_origin[2] - 0.5 * g_h
    pc0, pc1, pc2 = p_origin[0] - 0.5 * p_h, p_origin[1] - 0.5 * p_h, p_origin[2] - 0.5 * p_h
    # Both SDFs are clamped at their bands, so d >= floor: a pose deep in an obstacle (the costly
    # case, every block in reach is solid) stops at the first voxel that reaches it.
    floor = -(g_band + p_band) + 1e-6 * (g_h + p_h)
    best = np.inf
    margin = np.inf if t_window >= t else -np.inf
    top = _push(stack, 0, g_lshape.shape[0] - 1, 0, 0, 0, p_lshape.shape[0] - 1, 0, 0, 0)
    while top > 0:
        top -= 1
        gl, gi, gj, gk = stack[top, 0], stack[top, 1], stack[top, 2], stack[top, 3]
        pl, pi, pj, pk = stack[top, 4], stack[top, 5], stack[top, 6], stack[top, 7]
        gidx = g_loff[gl] + (gi * g_lshape[gl, 1] + gj) * g_lshape[gl, 2] + gk
        # a block evaluated in this query already (then it has material and the margin is -inf)
        if gl == 0 and done[gidx] == stamp:
            continue
        if g_occ[gidx] == 0:
            continue
        arrived = g_marr[gidx] <= t
        if not arrived and not (margin > -np.inf and g_marr[gidx] <= t_window):
            continue
        pidx = p_loff[pl] + (pi * p_lshape[pl, 1] + pj) * p_lshape[pl, 2] + pk
        p_o = p_occ[pidx]
        # probe min arrival +inf: a band-only leaf without any inside voxel, no material
        if p_o == 0 or not (p_marr[pidx] < np.inf):
            continue
        g_size = 8.0 * (1 << gl) * g_h
        ea = 0.5 * g_size + reach
        p_size = 8.0 * (1 << pl) * p_h
        eb = 0.5 * p_size
        lc0, lc1, lc2, g0, g1, g2 = _node_centres(pc0, pc1, pc2, pi, pj, pk, p_size, gc0, gc1, gc2, gi, gj, gk,
                                                  g_size)
        tx, ty, tz = _posed_offset(R, T, lc0, lc1, lc2, g0, g1, g2)
        if not arrived:
            margin = min(margin, sat_margin(tx, ty, tz, ea, eb, R, AbsR, aligned))
            continue
        if (abs(tx) > thresholds[gl, pl, 0] or abs(ty) > thresholds[gl, pl, 1] or abs(tz) > thresholds[gl, pl, 2]) \
                if aligned else _separated(tx, ty, tz, R, general, gl, pl):
            if margin > -np.inf:
                margin = min(margin, sat_margin(tx, ty, tz, ea, eb, R, AbsR, aligned))
            continue
        probe_final = pl == 0 or p_o == 2
        if gl == 0 and probe_final:
            margin = -np.inf
            done[gidx] = stamp
            d = eval_block(g_block, g_act, g_ins, g_sdf_offset, g_sdf, g_arr_offset, g_arrival, g_leaf_oct,
                           g_tile_arr, g_origin, g_h, g_band, p_block, p_act, p_ins, p_sdf_offset, p_sdf, p_prefix,
                           p_origin, p_h, p_band, p_geo[5], gi, gj, gk, R, T, aligned, t, min(best, cut), floor, lut,
                           frac)
            if d < best:
                best = d
                if best <= floor:
                    break
        else:
            # before splitting, the material boxes of the two nodes (their cubes at level 0)
            if gl > 0:
                q = gidx - g_loff[1]
                g0, g1, g2 = g_box[q, 0], g_box[q, 1], g_box[q, 2]
                ha0, ha1, ha2 = g_box[q, 3] + reach, g_box[q, 4] + reach, g_box[q, 5] + reach
            else:
                ha0 = ha1 = ha2 = ea
            if pl > 0:
                q = pidx - p_loff[1]
                lc0, lc1, lc2 = p_box[q, 0], p_box[q, 1], p_box[q, 2]
                hb0, hb1, hb2 = p_box[q, 3], p_box[q, 4], p_box[q, 5]
            else:
                hb0 = hb1 = hb2 = eb
            tx, ty, tz = _posed_offset(R, T, lc0, lc1, lc2, g0, g1, g2)
            if _boxes_apart(tx, ty, tz, ha0, ha1, ha2, hb0, hb1, hb2, R, AbsR, aligned):
                if margin > -np.inf:
                    margin = min(margin, box_margin(tx, ty, tz, ha0, ha1, ha2, hb0, hb1, hb2, R, AbsR, aligned))
                continue
            top = _split(stack, top, g_lshape, p_lshape, gl > 0 and (probe_final or g_size >= p_size),
                         gl, gi, gj, gk, pl, pi, pj, pk)
    return best, margin


@nb.njit(cache=True)
def query(G, P, R, AbsR, T, t, reach, hint, ws, stamp, t_window):
    """Minimum ``d`` between the target at time ``t`` and the posed probe; +inf when it is at
    least ``reach`` (distances beyond are not measured; see module docstring). Also the margin
    of :func:`_descend`: ``d`` is +inf at every pose within it, up to ``t_window``.

    ``hint`` (+inf: none) is a guess of an upper bound of ``d`` that lets the voxel tests skip
    more from the start. The result does not depend on it: every voxel whose value is below the
    cut is evaluated exactly, so a minimum below the hint is the minimum; when blocks were
    evaluated and nothing was found below the hint, the query runs again up to the reach
    (stamp ``-stamp``).
    """
    cut = min(reach, hint)
    best, margin = _descend(G, P, R, AbsR, T, t, reach, cut, ws, stamp, t_window)
    if not best < cut and cut < reach and margin == -np.inf:
        best, margin = _descend(G, P, R, AbsR, T, t, reach, reach, ws, -stamp, -np.inf)
    # values at or beyond the reach are upper bounds only (pairs that far were pruned)
    return (best if best < reach else np.inf), margin


@nb.njit(cache=True)
def _collect(G, P, R, T, t, ws):
    """List, in :func:`_descend`'s order, every (target block, final probe node) pair that
    survives its descent at time ``t`` with the reach grown by ``SHARE_MM`` (R = I); the count,
    or -1 when the list is full.

    A pair separated with the grown reach stays separated with the reach after a translation
    of up to ``SHARE_MM`` (every threshold grows by at least the growth, see
    :func:`sat_margin`), and one pruned by arrival at ``t`` is pruned at any earlier time. So
    the descent at such a pose and time evaluates the blocks of the listed pairs whose SAT
    test passes there, in list order (the descent's order; it only prunes more), each at its
    first such pair: :func:`_replay` does exactly that without descending. A pair and its
    parents differ only where a box touches the pruning distance to rounding (1e-13 mm).
    """
    stack, _, _, _, _, wide, pairs, centres, _ = ws
    g_occ, g_marr, g_loff, g_lshape, g_geo = G.occupancy, G.min_arrival, G.level_offset, G.level_shape, G.geo
    p_occ, p_marr, p_loff, p_lshape, p_geo = P.occupancy, P.min_arrival, P.level_offset, P.level_shape, P.geo
    g_h = g_geo[3]
    p_h = p_geo[3]
    gc0, gc1, gc2 = g_geo[0] - 0.5 * g_h, g_geo[1] - 0.5 * g_h, g_geo[2] - 0.5 * g_h
    pc0, pc1, pc2 = p_geo[0] - 0.5 * p_h, p_geo[1] - 0.5 * p_h, p_geo[2] - 0.5 * p_h
    n = 0
    top = _push(stack, 0, g_lshape.shape[0] - 1, 0, 0, 0, p_lshape.shape[0] - 1, 0, 0, 0)
    while top > 0:
        top -= 1
        gl, gi, gj, gk = stack[top, 0], stack[top, 1], stack[top, 2], stack[top, 3]
        pl, pi, pj, pk = stack[top, 4], stack[top, 5], stack[top, 6], stack[top, 7]
        gidx = g_loff[gl] + (gi * g_lshape[gl, 1] + gj) * g_lshape[gl, 2] + gk
        if g_occ[gidx] == 0 or g_marr[gidx] > t:
            continue
        pidx = p_loff[pl] + (pi * p_lshape[pl, 1] + pj) * p_lshape[pl, 2] + pk
        p_o = p_occ[pidx]
        if p_o == 0 or not (p_marr[pidx] < np.inf):
            continue
        g_size = 8.0 * (1 << gl) * g_h
        p_size = 8.0 * (1 << pl) * p_h
        lc0, lc1, lc2, g0, g1, g2 = _node_centres(pc0, pc1, pc2, pi, pj, pk, p_size, gc0, gc1, gc2, gi, gj, gk,
                                                  g_size)
        tx, ty, tz = _posed_offset(R, T, lc0, lc1, lc2, g0, g1, g2)
        if abs(tx) > wide[gl, pl, 0] or abs(ty) > wide[gl, pl, 1] or abs(tz) > wide[gl, pl, 2]:
            continue
        probe_final = pl == 0 or p_o == 2
        if gl == 0 and probe_final:
            if n == pairs.shape[0]:
                return -1
            pairs[n, 0], pairs[n, 1], pairs[n, 2], pairs[n, 3] = gi, gj, gk, pl
            centres[n, 0], centres[n, 1], centres[n, 2] = lc0, lc1, lc2
            centres[n, 3], centres[n, 4], centres[n, 5] = g0, g1, g2
            n += 1
        else:
            top = _split(stack, top, g_lshape, p_lshape, gl > 0 and (probe_final or g_size >= p_size),
                         gl, gi, gj, gk, pl, pi, pj, pk)
    return n


@nb.njit(cache=True)
def _replay(G, P, R, T, t, cut, ws, n_pairs, stamp):
    """:func:`_descend`'s minimum (R = I) from the pairs of :func:`_collect`; also whether a
    block was evaluated."""
    _, done, lut, frac, thresholds, _, pairs, centres, _ = ws
    g_marr, g_loff, g_lshape, g_block = G.min_arrival, G.level_offset, G.level_shape, G.block
    g_act, g_ins, g_sdf_offset, g_sdf = G.leaf_active, G.leaf_inside, G.sdf_offset, G.sdf
    g_arr_offset, g_arrival, g_leaf_oct, g_tile_arr = G.arr_offset, G.arrival, G.leaf_octant_arrival, G.tile_arrival
    g_geo = G.geo
    p_block, p_act, p_ins, p_sdf_offset = P.block, P.leaf_active, P.leaf_inside, P.sdf_offset
    p_sdf, p_geo, p_prefix = P.sdf, P.geo, P.rank_prefix
    g_h = g_geo[3]
    g_band = np.float32(g_geo[4])
    p_h = p_geo[3]
    p_band = np.float32(p_geo[4])
    floor = -(g_band + p_band) + 1e-6 * (g_h + p_h)
    best = np.inf
    evaluated = False
    for e in range(n_pairs):
        gi, gj, gk, pl = pairs[e, 0], pairs[e, 1], pairs[e, 2], pairs[e, 3]
        gidx = g_loff[0] + (gi * g_lshape[0, 1] + gj) * g_lshape[0, 2] + gk
        if g_marr[gidx] > t or done[gidx] == stamp:
            continue
        lc0, lc1, lc2 = centres[e, 0], centres[e, 1], centres[e, 2]
        tx = R[0, 0] * lc0 + R[0, 1] * lc1 + R[0, 2] * lc2 + T[0] - centres[e, 3]
        ty = R[1, 0] * lc0 + R[1, 1] * lc1 + R[1, 2] * lc2 + T[1] - centres[e, 4]
        tz = R[2, 0] * lc0 + R[2, 1] * lc1 + R[2, 2] * lc2 + T[2] - centres[e, 5]
        if abs(tx) > thresholds[0, pl, 0] or abs(ty) > thresholds[0, pl, 1] or abs(tz) > thresholds[0, pl, 2]:
            continue
        done[gidx] = stamp
        evaluated = True
        d = eval_block(g_block, g_act, g_ins, g_sdf_offset, g_sdf, g_arr_offset, g_arrival, g_leaf_oct, g_tile_arr,
                       g_geo[:3], g_h, g_band, p_block, p_act, p_ins, p_sdf_offset, p_sdf, p_prefix, p_geo[:3], p_h,
                       p_band, p_geo[5], gi, gj, gk, R, T, True, t, min(best, cut), floor, lut, frac)
        if d < best:
            best = d
            if best <= floor:
                break
    return best, evaluated


@nb.njit(cache=True)
def query_shared(G, P, R, T, t, reach, hint, ws, n_pairs, stamp):
    """:func:`query` (R = I) from the pairs of :func:`_collect`: the same value, without a
    descent; also whether a block was evaluated."""
    cut = min(reach, hint)
    best, evaluated = _replay(G, P, R, T, t, cut, ws, n_pairs, stamp)
    if not best < cut and cut < reach and evaluated:
        best, evaluated = _replay(G, P, R, T, t, reach, ws, n_pairs, -stamp)
    return (best if best < reach else np.inf), evaluated


@nb.njit(cache=True)
def _workspace(G, P, AbsR, reach):
    """Pair stack (depth-first: at most 7 siblings per split, one split per level of either
    tree), the per-query evaluated-block stamps over the target's level 0 (stamps are nonzero),
    :func:`eval_block`'s axis tables and the SAT thresholds per pair of levels for R = I
    (:func:`aligned_thresholds`), also for ``reach + SHARE_MM``, and the pair list of
    :func:`_collect`: a workspace serves queries with this ``reach`` only."""
    g_h, p_h = G.geo[3], P.geo[3]
    n_g, n_p = G.level_shape.shape[0], P.level_shape.shape[0]
    thresholds = np.empty((n_g, n_p, 3), np.float64)
    wide = np.empty((n_g, n_p, 3), np.float64)
    for gl in range(n_g):
        for pl in range(n_p):
            aligned_thresholds(0.5 * (8.0 * (1 << gl) * g_h) + reach, 0.5 * (8.0 * (1 << pl) * p_h), AbsR,
                               thresholds[gl, pl])
            aligned_thresholds(0.5 * (8.0 * (1 << gl) * g_h) + (reach + SHARE_MM), 0.5 * (8.0 * (1 << pl) * p_h),
                               AbsR, wide[gl, pl])
    general = np.empty((n_g, n_p, 6), np.float64)
    general_thresholds(G, P, AbsR, reach, general)
    return (np.empty((STACK_PER_LEVEL * (n_g + n_p) + 1, 8), np.int64), np.zeros(G.level_offset[1], np.int64),
            np.empty((9, 8), np.int64), np.empty((12, 8), np.float64), thresholds, wide,
            np.empty((SHARE_CAP, 4), np.int64), np.empty((SHARE_CAP, 6), np.float64), general)


@nb.njit(cache=True)
def general_thresholds(G, P, AbsR, reach, out):
    """:func:`sat_disjoint`'s six thresholds (A's faces, then B's) per pair of levels for the
    rotation whose ``AbsR`` is given, the target box grown by ``reach``: ``out`` (n_g, n_p, 6)."""
    g_h, p_h = G.geo[3], P.geo[3]
    for gl in range(out.shape[0]):
        ea = 0.5 * (8.0 * (1 << gl) * g_h) + reach
        for pl in range(out.shape[1]):
            eb = 0.5 * (8.0 * (1 << pl) * p_h)
            for k in range(3):
                out[gl, pl, k] = ea + eb * AbsR[k, 0] + eb * AbsR[k, 1] + eb * AbsR[k, 2]
                out[gl, pl, 3 + k] = ea * AbsR[0, k] + ea * AbsR[1, k] + ea * AbsR[2, k] + eb


@nb.njit(cache=True, inline="always")
def _separated(tx, ty, tz, R, thr, gl, pl):
    """:func:`sat_disjoint` for cubes from the precomputed thresholds ``thr[gl, pl]`` (6,)."""
    if abs(tx) > thr[gl, pl, 0] or abs(ty) > thr[gl, pl, 1] or abs(tz) > thr[gl, pl, 2]:
        return True
    for j in range(3):
        if abs(tx * R[0, j] + ty * R[1, j] + tz * R[2, j]) > thr[gl, pl, 3 + j]:
            return True
    return False


@nb.njit(cache=True)
def abs_eps(R):
    AbsR = np.empty((3, 3), np.float64)
    for a in range(3):
        for b in range(3):
            AbsR[a, b] = abs(R[a, b]) + SAT_EPS
    return AbsR


@nb.njit(cache=True)
def query_one(G, P, R, T, t, reach):
    """One pose (the scene API)."""
    AbsR = abs_eps(R)
    return query(G, P, R, AbsR, T, t, reach, np.inf, _workspace(G, P, AbsR, reach), 1, -np.inf)[0]


@nb.njit(cache=True, inline="always")
def _dist(tips, q, T):
    dx = tips[q, 0] - T[0]
    dy = tips[q, 1] - T[1]
    dz = tips[q, 2] - T[2]
    return np.sqrt(dx * dx + dy * dy + dz * dz)


@nb.njit(cache=True, inline="always")
def _is_identity(R):
    ok = True
    for a in range(3):
        for b in range(3):
            ok = ok and R[a, b] == (1.0 if a == b else 0.0)
    return ok


def query_poses(G, P, R, tips, times, reach, advance):
    """``d`` for every pose: probe rotation ``R`` fixed, translation ``tips[n]`` at ``times[n]``;
    also the number of poses checked one by one (see :func:`query_poses_rotated`)."""
    R = np.ascontiguousarray(np.asarray(R, np.float64).reshape(1, 3, 3))
    return query_poses_rotated(G, P, R, np.zeros(np.shape(tips)[0], np.int64), tips, times, reach, advance)


def query_poses_rotated(G, P, Rs, rot_index, tips, times, reach, advance):
    """:func:`_query_poses_rotated`, its threads taking the chunks of poses one at a time: a
    thread slowed by another process on its core then holds back one chunk, not a fixed share of
    the path (numba's default hands each thread one contiguous share)."""
    with nb.parallel_chunksize(1):
        return _query_poses_rotated(G, P, Rs, rot_index, tips, times, reach, advance)


@nb.njit(cache=True, parallel=True)
def _query_poses_rotated(G, P, Rs, rot_index, tips, times, reach, advance):
    """``d`` for every pose: probe rotation ``Rs[rot_index[n]]``, translation ``tips[n]`` at
    ``times[n]``; also the number of poses checked one by one (the others were certified out of
    reach).

    With ``advance``, pose coherence among consecutive poses of one rotation (the margins and
    shared pair lists hold for translations only). Conservative advancement: a pose out of reach
    also certifies (the margin of :func:`_descend`) that the following poses closer to it than
    the margin, up to ``ADVANCE_WINDOW_MM`` of them and at their latest time, are out of reach as
    well; they get +inf, what :func:`query` returns there, without a check of their own. Shared
    descents (R = I): after a pose that evaluated blocks, the poses within ``SHARE_MM`` are
    checked one by one from the block pairs of one descent (:func:`_collect`,
    :func:`query_shared`). The values are those of :func:`query` pose by pose, whatever
    ``advance``. Poses whose rotation is the identity take the fixed-axis fast path (per-axis
    tables, three-comparison SAT).
    """
    n = tips.shape[0]
    out = np.empty(n, np.float32)
    identity = np.eye(3)
    AbsI = abs_eps(identity)
    # Poses in chunks, each allocating its workspace once. The work clusters where the path
    # passes near an obstacle: iteration i takes chunk (i % STRIPES) * rows + i // STRIPES, so
    # that any run of iterations samples the whole path (the threads take them one at a time,
    # see query_poses_rotated).
    n_chunks = (n + POSE_CHUNK - 1) // POSE_CHUNK
    rows = (n_chunks + STRIPES - 1) // STRIPES
    queried = np.zeros(rows * STRIPES, np.int64)
    for i in nb.prange(rows * STRIPES):
        c = (i % STRIPES) * rows + i // STRIPES
        if c >= n_chunks:
            continue
        # the workspace's SAT tables serve the identity only (the aligned path)
        ws = _workspace(G, P, AbsI, reach)
        T = np.empty(3, np.float64)
        end = min(n, (c + 1) * POSE_CHUNK)
        p = c * POSE_CHUNK
        cur = -1
        R = Rs[0]
        AbsR = AbsI
        aligned = True
        prev = np.inf  # d of the previous pose
        near = False  # the previous pose evaluated blocks
        share = True
        while p < end:
            if rot_index[p] != cur:
                cur = rot_index[p]
                R = Rs[cur]
                AbsR = abs_eps(R)
                aligned = _is_identity(R)
                general_thresholds(G, P, AbsR, reach, ws[8])
                prev = np.inf
                near = False
                share = True
            T[0] = tips[p, 0]
            T[1] = tips[p, 1]
            T[2] = tips[p, 2]
            if advance and near and aligned and share:
                # the poses within SHARE_MM share one descent, at their latest time
                last = p
                t_share = times[p]
                while last + 1 < end and rot_index[last + 1] == cur \
                        and _dist(tips, last + 1, T) <= SHARE_MM - ADVANCE_TOL_MM:
                    last += 1
                    t_share = max(t_share, times[last])
                n_pairs = _collect(G, P, R, T, t_share, ws)
                share = n_pairs >= 0  # a full list: the rest of the chunk descends pose by pose
                if share:
                    for q in range(p, last + 1):
                        T[0] = tips[q, 0]
                        T[1] = tips[q, 1]
                        T[2] = tips[q, 2]
                        hint = prev + HINT_SLOPE * _dist(tips, q - 1, T) if prev < np.inf else np.inf
                        d, near = query_shared(G, P, R, T, times[q], reach, hint, ws, n_pairs, q + 1)
                        out[q] = d
                        prev = d
                    queried[i] += last + 1 - p
                    p = last + 1
                    continue
            # the window: the following poses of this rotation within ADVANCE_WINDOW_MM, and
            # their latest time
            last = p
            t_window = -np.inf
            if advance:
                t_window = times[p]
                while last + 1 < end and rot_index[last + 1] == cur \
                        and _dist(tips, last + 1, T) <= ADVANCE_WINDOW_MM:
                    last += 1
                    t_window = max(t_window, times[last])
            # the previous pose's minimum voxel moved by the step: its value changes by at most
            # sqrt(3) times the step (1-Lipschitz samples, trilinear), and rarely by more than
            # HINT_SLOPE times (a pose beyond runs its query again; a tighter cut prunes more)
            hint = prev + HINT_SLOPE * _dist(tips, p - 1, T) if prev < np.inf else np.inf
            d, margin = query(G, P, R, AbsR, T, times[p], reach, hint, ws, p + 1, t_window)
            out[p] = d
            prev = d
            near = margin == -np.inf
            queried[i] += 1
            q = p
            # ADVANCE_TOL_MM absorbs the rounding of the SAT terms at the poses covered
            while q < last and _dist(tips, q + 1, T) < margin - ADVANCE_TOL_MM:
                q += 1
                out[q] = np.inf
            p = q + 1
    return out, queried.sum()
