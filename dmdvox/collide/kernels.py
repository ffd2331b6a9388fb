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

Bodies are passed as tuples (see :meth:`dmdvox.collide.bodies.Body.kernel_args`):
``(occ, min_arrival, level_offset, level_shape, block, leaf_active, leaf_inside, sdf_offset,
sdf, arr_offset, arrival, leaf_octant_arrival, tile_arrival, geo, rank_prefix)`` with ``geo``
float64 ``[origin x, y, z, voxel, band]`` and ``rank_prefix`` (n_leaf, 8) int64, the number of
active voxels of a leaf before each 64-bit word.
"""

from __future__ import annotations

import numba as nb
import numpy as np

from ..grid.sparse import BLOCK_VOXELS, OUTSIDE, popcount64

_U1 = np.uint64(1)
SQRT3 = np.sqrt(3.0)
SAT_EPS = 1e-9  # added to |R|: keeps the cross-product axes robust when two edges are parallel
STACK_PER_LEVEL = 8


@nb.njit(cache=True, inline="always")
def sat_disjoint(tx, ty, tz, ea0, ea1, ea2, eb0, eb1, eb2, R, AbsR):
    """Separating-axis test of box A (half extents ``ea``, axes = the frame's) and box B
    (half extents ``eb``, axes = columns of ``R``, centre offset ``t`` from A's, in A's frame).

    True when one of the 15 axes (3 + 3 face normals, 9 edge cross products) separates them
    (Gottschalk's OBB test; ``AbsR = |R| + eps``, hoisted by the caller since R is fixed per pose).
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
    # A_i x B_j
    ea = (ea0, ea1, ea2)
    ebv = (eb0, eb1, eb2)
    tv = (tx, ty, tz)
    for i in range(3):
        i1 = (i + 1) % 3
        i2 = (i + 2) % 3
        for j in range(3):
            j1 = (j + 1) % 3
            j2 = (j + 2) % 3
            ra = ea[i1] * AbsR[i2, j] + ea[i2] * AbsR[i1, j]
            rb = ebv[j1] * AbsR[i, j2] + ebv[j2] * AbsR[i, j1]
            if abs(tv[i2] * R[i1, j] - tv[i1] * R[i2, j]) > ra + rb:
                return True
    return False


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


@nb.njit(cache=True)
def probe_sdf(block, act, ins, sdf_offset, sdf, prefix, origin, h, band, qx, qy, qz):
    """Trilinear probe SDF at a probe-frame point; +inf where any corner is clamped at +band
    (the distance there is unknown beyond the band, see module docstring)."""
    ux = (qx - origin[0]) / h
    uy = (qy - origin[1]) / h
    uz = (qz - origin[2]) / h
    fx, fy, fz = np.floor(ux), np.floor(uy), np.floor(uz)
    i0, j0, k0 = np.int64(fx), np.int64(fy), np.int64(fz)
    if i0 < 0 or j0 < 0 or k0 < 0 or i0 + 1 >= 8 * block.shape[0] or j0 + 1 >= 8 * block.shape[1] \
            or k0 + 1 >= 8 * block.shape[2]:
        return np.inf
    tx, ty, tz = ux - fx, uy - fy, uz - fz
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
def eval_block(g_block, g_act, g_ins, g_sdf_offset, g_sdf, g_arr_offset, g_arrival, g_leaf_oct, g_tile_arr, g_origin,
               g_h, g_band, p_block, p_act, p_ins, p_sdf_offset, p_sdf, p_prefix, p_origin, p_h, p_band,
               bi, bj, bk, R, T, t, cut, floor):
    """Minimum of ``d`` over the inside voxels of target block (bi, bj, bk) arrived by ``t``,
    or +inf when no voxel gets below ``cut`` (the best so far, at most the reach). Stops once it
    reaches ``floor``, the most negative value the clamped SDFs can give.

    Bounds skip work: the clamped SDFs are 1-Lipschitz, so the probe SDF anywhere in a 4^3
    octant (at a voxel) is at least its value at the probe voxel nearest the octant centre (the
    voxel) less the distance between the trilinear corners involved (``slack``).
    """
    val = g_block[bi, bj, bk]
    if val == OUTSIDE:
        return np.inf
    x0 = g_origin[0] + 8 * bi * g_h
    y0 = g_origin[1] + 8 * bj * g_h
    z0 = g_origin[2] + 8 * bk * g_h
    # per 4^3 octant: skip it when even its bound cannot beat the cut
    slack = SQRT3 * (1.5 * g_h + 1.5 * p_h)
    live = np.zeros(8, np.bool_)
    any_live = False
    for o in range(8):
        dx = x0 + (4 * (o >> 2) + 1.5) * g_h - T[0]
        dy = y0 + (4 * ((o >> 1) & 1) + 1.5) * g_h - T[1]
        dz = z0 + (4 * (o & 1) + 1.5) * g_h - T[2]
        qx = R[0, 0] * dx + R[1, 0] * dy + R[2, 0] * dz
        qy = R[0, 1] * dx + R[1, 1] * dy + R[2, 1] * dz
        qz = R[0, 2] * dx + R[1, 2] * dy + R[2, 2] * dz
        if _nearest(p_block, p_act, p_ins, p_sdf_offset, p_sdf, p_prefix, p_origin, p_h, p_band, qx, qy, qz) \
                - slack - g_band < cut:
            live[o] = True
            any_live = True
    if not any_live:
        return np.inf
    voxel_slack = SQRT3 * 1.5 * p_h
    best = np.inf
    leaf = val >= 0
    ks = g_sdf_offset[val] if leaf else 0
    ka = g_arr_offset[val] if leaf else 0
    for v in range(BLOCK_VOXELS):
        w = v >> 6
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
        if arr > t or not live[o0 * 4 + o1 * 2 + o2]:
            continue
        # the target voxel centre in the probe frame: R^T (p - T)
        dx = x0 + (v >> 6) * g_h - T[0]
        dy = y0 + ((v >> 3) & 7) * g_h - T[1]
        dz = z0 + (v & 7) * g_h - T[2]
        qx = R[0, 0] * dx + R[1, 0] * dy + R[2, 0] * dz
        qy = R[0, 1] * dx + R[1, 1] * dy + R[2, 1] * dz
        qz = R[0, 2] * dx + R[1, 2] * dy + R[2, 2] * dz
        if _nearest(p_block, p_act, p_ins, p_sdf_offset, p_sdf, p_prefix, p_origin, p_h, p_band, qx, qy, qz) \
                - voxel_slack + s_t >= cut:
            continue
        d = probe_sdf(p_block, p_act, p_ins, p_sdf_offset, p_sdf, p_prefix, p_origin, p_h, p_band, qx, qy, qz) + s_t
        if d < best:
            best = d
            cut = min(cut, d)
            if best <= floor:
                break
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


@nb.njit(cache=True)
def query(G, P, R, AbsR, T, t, reach, stack, done, stamp):
    """Minimum ``d`` between the target at time ``t`` and the posed probe; +inf when it is at
    least ``reach`` (distances beyond are not measured; see module docstring).

    Node-pair descent: a pair survives when the target box grown by ``reach`` and the posed probe
    box overlap (SAT); the larger node of a surviving pair is split. A target block reached with
    a probe leaf (or a FULL probe node) is evaluated once per query: ``done[block] == stamp``.
    """
    (g_occ, g_marr, g_loff, g_lshape, g_block, g_act, g_ins, g_sdf_offset, g_sdf, g_arr_offset, g_arrival,
     g_leaf_oct, g_tile_arr, g_geo, _) = G
    (p_occ, p_marr, p_loff, p_lshape, p_block, p_act, p_ins, p_sdf_offset, p_sdf, _, _, _, _, p_geo, p_prefix) = P
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
        # probe min arrival +inf: a band-only leaf without any inside voxel, no material
        if p_o == 0 or not (p_marr[pidx] < np.inf):
            continue
        if gl == 0 and g_block[gi, gj, gk] != OUTSIDE and done[gidx] == stamp:
            continue
        g_size = 8.0 * (1 << gl) * g_h
        ea = 0.5 * g_size + reach
        p_size = 8.0 * (1 << pl) * p_h
        eb = 0.5 * p_size
        lc0 = pc0 + (pi + 0.5) * p_size
        lc1 = pc1 + (pj + 0.5) * p_size
        lc2 = pc2 + (pk + 0.5) * p_size
        # posed probe box centre relative to the target box centre (target frame)
        tx = R[0, 0] * lc0 + R[0, 1] * lc1 + R[0, 2] * lc2 + T[0] - (gc0 + (gi + 0.5) * g_size)
        ty = R[1, 0] * lc0 + R[1, 1] * lc1 + R[1, 2] * lc2 + T[1] - (gc1 + (gj + 0.5) * g_size)
        tz = R[2, 0] * lc0 + R[2, 1] * lc1 + R[2, 2] * lc2 + T[2] - (gc2 + (gk + 0.5) * g_size)
        if sat_disjoint(tx, ty, tz, ea, ea, ea, eb, eb, eb, R, AbsR):
            continue
        probe_final = pl == 0 or p_o == 2
        if gl == 0 and probe_final:
            done[gidx] = stamp
            d = eval_block(g_block, g_act, g_ins, g_sdf_offset, g_sdf, g_arr_offset, g_arrival, g_leaf_oct,
                           g_tile_arr, g_origin, g_h, g_band, p_block, p_act, p_ins, p_sdf_offset, p_sdf, p_prefix,
                           p_origin, p_h, p_band, gi, gj, gk, R, T, t, min(best, reach), floor)
            if d < best:
                best = d
                if best <= floor:
                    break
        elif gl > 0 and (probe_final or g_size >= p_size):
            for di in range(2):
                ci = 2 * gi + di
                if ci >= g_lshape[gl - 1, 0]:
                    continue
                for dj in range(2):
                    cj = 2 * gj + dj
                    if cj >= g_lshape[gl - 1, 1]:
                        continue
                    for dk in range(2):
                        ck = 2 * gk + dk
                        if ck < g_lshape[gl - 1, 2]:
                            top = _push(stack, top, gl - 1, ci, cj, ck, pl, pi, pj, pk)
        else:
            for di in range(2):
                ci = 2 * pi + di
                if ci >= p_lshape[pl - 1, 0]:
                    continue
                for dj in range(2):
                    cj = 2 * pj + dj
                    if cj >= p_lshape[pl - 1, 1]:
                        continue
                    for dk in range(2):
                        ck = 2 * pk + dk
                        if ck < p_lshape[pl - 1, 2]:
                            top = _push(stack, top, gl, gi, gj, gk, pl - 1, ci, cj, ck)
    # values at or beyond the reach are upper bounds only (pairs that far were pruned)
    return best if best < reach else np.inf


@nb.njit(cache=True)
def _workspace(G, P):
    """Pair stack (depth-first: at most 7 siblings per split, one split per level of either
    tree) and the per-query evaluated-block stamps over the target's level 0."""
    depth = G[3].shape[0] + P[3].shape[0]
    return np.empty((STACK_PER_LEVEL * depth + 1, 8), np.int64), np.zeros(G[2][1], np.int64)


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
    stack, done = _workspace(G, P)
    return query(G, P, R, abs_eps(R), T, t, reach, stack, done, 1)


@nb.njit(cache=True, parallel=True)
def query_poses(G, P, R, tips, times, reach):
    """``d`` for every pose: probe rotation ``R`` fixed, translation ``tips[n]`` at ``times[n]``."""
    n = tips.shape[0]
    out = np.empty(n, np.float32)
    AbsR = abs_eps(R)
    # poses in chunks so that each chunk allocates its workspace once
    chunk = 4096
    n_chunks = (n + chunk - 1) // chunk
    for c in nb.prange(n_chunks):
        stack, done = _workspace(G, P)
        T = np.empty(3, np.float64)
        for p in range(c * chunk, min(n, (c + 1) * chunk)):
            T[0] = tips[p, 0]
            T[1] = tips[p, 1]
            T[2] = tips[p, 2]
            out[p] = query(G, P, R, AbsR, T, times[p], reach, stack, done, p + 1)
    return out
