"""Exact unsigned distance from many query points to a triangle mesh.

:class:`MeshDistance` is built once from ``(vertices, triangles)`` and answers
``query(points) -> (distance, closest_point, triangle)`` for any number of points.

Method
------
1. **Pieces.** Every triangle is covered by *pieces*, each tagged with its triangle and
   carrying an axis-aligned box that contains it. A triangle whose longest edge is at most the
   spacing ``s`` is one piece: itself, in its corner box. A longer triangle is laid out in its
   own plane with its longest edge ``AB`` as the base and the apex at height ``h``, cut into
   ``ceil(h / s)`` rows of height ``<= s``, and each row into cells of width ``<= s`` spanning
   the triangle's extent at the row's bottom (where it is widest). Every point of the triangle
   lies in one of these ``<= s x s`` in-plane cells; a piece's box is the box of its cell's four
   corners intersected with the triangle's box, padded by ``1e-12`` x the coordinate scale
   against rounding in the cell corners. Sliver triangles cost O(length / s) pieces, not
   O((length / s)^2); a CAD box (12 triangles) keeps 12 pieces unless ``s`` is set smaller.
2. **The bound.** Every point of every triangle lies in the box of one of its pieces, and
   pieces are grouped (Morton order, 8 per leaf) in a bounding-volume hierarchy whose node
   boxes contain their pieces' boxes. So for a query ``q`` and any node, the distance from
   ``q`` to the node's box is a lower bound on the distance from ``q`` to every triangle point
   the node covers. (Sampling a triangle at cell centres instead, a sample covers its cell
   within the half-diagonal, ``<= s / sqrt(2)``, and the same bound reads "``T`` has a sample
   within ``d(q, T) + s / sqrt(2)``"; the box form is that bound made per-piece and tight.)
3. **Query = search + certificate in one pass.** Per query (numba, parallel over queries
   sorted in Morton order), a depth-first branch-and-bound walks the hierarchy nearest child
   first, seeded with the previous query's triangle. A node or piece whose box is no nearer
   than the best exact distance ``d_best`` found so far is skipped; otherwise its triangle
   is evaluated exactly. By 2., a skipped node holds no triangle point nearer than ``d_best``,
   so when the walk ends ``d_best`` is the exact minimum over all triangles (ties may return
   either triangle). Work per query grows with the number of pieces within ``d + s`` of the
   query, i.e. about linearly with ``d / s`` for points far from a finely meshed surface;
   points near the centre of a closed, nearly round surface are the worst case.
4. **Exact point-triangle distance.** The region-based closest-point algorithm (vertex, edge
   and face Voronoi regions from the six dot products ``ab.ap, ac.ap, ab.bp, ...``), compiled
   with numba. In the face region the point is projected on the plane along a unit normal
   taken at the triangle's largest angle (the best-conditioned cross product). Degenerate
   triangles (zero or near-zero area: inradius below 1e-8 of the longest edge) use the
   nearest of their three edges instead, which is exact for zero-area triangles and off by
   less than the inradius otherwise; zero-length edges are points.

Spacing
-------
By default ``s`` is twice the median longest edge, so a uniformly fine mesh (marching cubes)
is one piece per triangle and only triangles much larger than the typical one are cut. The
number of pieces is capped (``max_pieces``, default ``max(4 m, 2**16)`` for ``m`` triangles);
``s`` grows until the cap holds. Exactness does not depend on ``s``: it only trades the size
of the hierarchy against how tight the boxes of large triangles are.
"""

from __future__ import annotations

import math

import numba as nb
import numpy as np

__all__ = ["MeshDistance"]

_LEAF = 8  # pieces per leaf of the hierarchy
_BLOCK = 256  # consecutive (Morton-sorted) queries per parallel task
_STACK = 128  # traversal stack; the hierarchy is balanced, depth ~ log2(pieces / _LEAF)
_DEGENERATE = 1e-8  # inradius / longest edge below which a triangle is treated as its edges


# ----------------------------------------------------------------------------------------
# exact point-triangle distance
# ----------------------------------------------------------------------------------------


@nb.njit(cache=True, inline="always")
def _closest_on_segment(px, py, pz, ax, ay, az, bx, by, bz):
    ex = bx - ax
    ey = by - ay
    ez = bz - az
    ee = ex * ex + ey * ey + ez * ez
    t = 0.0
    if ee > 0.0:
        t = ((px - ax) * ex + (py - ay) * ey + (pz - az) * ez) / ee
        if t < 0.0:
            t = 0.0
        elif t > 1.0:
            t = 1.0
    qx = ax + t * ex
    qy = ay + t * ey
    qz = az + t * ez
    dx = px - qx
    dy = py - qy
    dz = pz - qz
    return dx * dx + dy * dy + dz * dz, qx, qy, qz


@nb.njit(cache=True, inline="always")
def _closest_on_triangle(px, py, pz, tri, t):
    """Squared distance and closest point from ``p`` to triangle ``t`` of ``tri`` (m, 4, 3).

    ``tri[t]`` holds the corners a, b, c and a unit normal, zero for a degenerate triangle
    (inradius <= 1e-8 x longest edge), which is treated as its three edges. A proper triangle
    has no zero-length edge, so the region tests below are unambiguous.
    """
    ax = tri[t, 0, 0]
    ay = tri[t, 0, 1]
    az = tri[t, 0, 2]
    bx = tri[t, 1, 0]
    by = tri[t, 1, 1]
    bz = tri[t, 1, 2]
    cx = tri[t, 2, 0]
    cy = tri[t, 2, 1]
    cz = tri[t, 2, 2]
    nx = tri[t, 3, 0]
    ny = tri[t, 3, 1]
    nz = tri[t, 3, 2]
    if nx == 0.0 and ny == 0.0 and nz == 0.0:
        # degenerate (the region tests are ambiguous when edges vanish): the nearest edge
        best, qx, qy, qz = _closest_on_segment(px, py, pz, ax, ay, az, bx, by, bz)
        e2, rx, ry, rz = _closest_on_segment(px, py, pz, bx, by, bz, cx, cy, cz)
        if e2 < best:
            best, qx, qy, qz = e2, rx, ry, rz
        e2, rx, ry, rz = _closest_on_segment(px, py, pz, cx, cy, cz, ax, ay, az)
        if e2 < best:
            best, qx, qy, qz = e2, rx, ry, rz
        return best, qx, qy, qz
    abx = bx - ax
    aby = by - ay
    abz = bz - az
    acx = cx - ax
    acy = cy - ay
    acz = cz - az
    apx = px - ax
    apy = py - ay
    apz = pz - az
    d1 = abx * apx + aby * apy + abz * apz
    d2 = acx * apx + acy * apy + acz * apz
    if d1 <= 0.0 and d2 <= 0.0:  # vertex region a
        qx, qy, qz = ax, ay, az
    else:
        bpx = px - bx
        bpy = py - by
        bpz = pz - bz
        d3 = abx * bpx + aby * bpy + abz * bpz
        d4 = acx * bpx + acy * bpy + acz * bpz
        if d3 >= 0.0 and d4 <= d3:  # vertex region b
            qx, qy, qz = bx, by, bz
        else:
            vc = d1 * d4 - d3 * d2
            if vc <= 0.0 and d1 >= 0.0 and d3 <= 0.0:  # edge region ab
                den = d1 - d3  # = |ab|^2
                v = d1 / den if den > 0.0 else 0.0
                qx = ax + v * abx
                qy = ay + v * aby
                qz = az + v * abz
            else:
                cpx = px - cx
                cpy = py - cy
                cpz = pz - cz
                d5 = abx * cpx + aby * cpy + abz * cpz
                d6 = acx * cpx + acy * cpy + acz * cpz
                if d6 >= 0.0 and d5 <= d6:  # vertex region c
                    qx, qy, qz = cx, cy, cz
                else:
                    vb = d5 * d2 - d1 * d6
                    if vb <= 0.0 and d2 >= 0.0 and d6 <= 0.0:  # edge region ac
                        den = d2 - d6  # = |ac|^2
                        w = d2 / den if den > 0.0 else 0.0
                        qx = ax + w * acx
                        qy = ay + w * acy
                        qz = az + w * acz
                    else:
                        va = d3 * d6 - d5 * d4
                        e43 = d4 - d3
                        e56 = d5 - d6
                        if va <= 0.0 and e43 >= 0.0 and e56 >= 0.0:  # edge region bc
                            den = e43 + e56  # = |bc|^2
                            w = e43 / den if den > 0.0 else 0.0
                            qx = bx + w * (cx - bx)
                            qy = by + w * (cy - by)
                            qz = bz + w * (cz - bz)
                        else:  # face region: project along the unit normal
                            s = apx * nx + apy * ny + apz * nz
                            qx = px - s * nx
                            qy = py - s * ny
                            qz = pz - s * nz
    dx = px - qx
    dy = py - qy
    dz = pz - qz
    return dx * dx + dy * dy + dz * dz, qx, qy, qz


# ----------------------------------------------------------------------------------------
# triangle data and pieces
# ----------------------------------------------------------------------------------------


def _triangle_data(vertices: np.ndarray, triangles: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(m, 4, 3) corners + unit normal (zero when degenerate), and the longest edges (m,)."""
    m = triangles.shape[0]
    tri = np.empty((m, 4, 3), np.float64)
    lmax = np.empty(m, np.float64)
    _fill_triangle_data(vertices, triangles, tri, lmax)
    return tri, lmax


@nb.njit(cache=True, parallel=True)
def _fill_triangle_data(vertices, triangles, tri, lmax):
    for t in nb.prange(triangles.shape[0]):
        for corner in range(3):
            for d in range(3):
                tri[t, corner, d] = vertices[triangles[t, corner], d]
        ax, ay, az = tri[t, 0, 0], tri[t, 0, 1], tri[t, 0, 2]
        bx, by, bz = tri[t, 1, 0], tri[t, 1, 1], tri[t, 1, 2]
        cx, cy, cz = tri[t, 2, 0], tri[t, 2, 1], tri[t, 2, 2]
        abx, aby, abz = bx - ax, by - ay, bz - az
        bcx, bcy, bcz = cx - bx, cy - by, cz - bz
        cax, cay, caz = ax - cx, ay - cy, az - cz
        lab = abx * abx + aby * aby + abz * abz
        lbc = bcx * bcx + bcy * bcy + bcz * bcz
        lca = cax * cax + cay * cay + caz * caz
        # the cross product p x (-q) at the largest angle (opposite the longest edge), of the
        # two edges next to it
        if lca > lbc and lca >= lab:
            px, py, pz, qx, qy, qz = bcx, bcy, bcz, abx, aby, abz
        elif lab > lbc and lab > lca:
            px, py, pz, qx, qy, qz = cax, cay, caz, bcx, bcy, bcz
        else:
            px, py, pz, qx, qy, qz = abx, aby, abz, cax, cay, caz
        nx = pz * qy - py * qz
        ny = px * qz - pz * qx
        nz = py * qx - px * qy
        nn = math.sqrt(nx * nx + ny * ny + nz * nz)
        perimeter = math.sqrt(lab) + math.sqrt(lbc) + math.sqrt(lca)
        longest = math.sqrt(max(lab, lbc, lca))
        inradius = nn / (perimeter if perimeter > 0 else 1.0)
        if inradius > _DEGENERATE * longest and nn > 0:
            tri[t, 3, 0], tri[t, 3, 1], tri[t, 3, 2] = nx / nn, ny / nn, nz / nn
        else:
            tri[t, 3, 0], tri[t, 3, 1], tri[t, 3, 2] = 0.0, 0.0, 0.0
        lmax[t] = longest


@nb.njit(cache=True, inline="always")
def _frame(tri, t):
    """Base = longest edge A->B (length L), apex C at (xc, hgt) in the in-plane frame (u, w)."""
    l01 = 0.0
    l12 = 0.0
    l20 = 0.0
    for d in range(3):
        l01 += (tri[t, 1, d] - tri[t, 0, d]) ** 2
        l12 += (tri[t, 2, d] - tri[t, 1, d]) ** 2
        l20 += (tri[t, 0, d] - tri[t, 2, d]) ** 2
    ia, ib, ic = 0, 1, 2
    if l12 >= l01 and l12 >= l20:
        ia, ib, ic = 1, 2, 0
    elif l20 >= l01 and l20 >= l12:
        ia, ib, ic = 2, 0, 1
    ux = tri[t, ib, 0] - tri[t, ia, 0]
    uy = tri[t, ib, 1] - tri[t, ia, 1]
    uz = tri[t, ib, 2] - tri[t, ia, 2]
    L = math.sqrt(ux * ux + uy * uy + uz * uz)
    if L > 0.0:
        ux /= L
        uy /= L
        uz /= L
    wx = tri[t, ic, 0] - tri[t, ia, 0]
    wy = tri[t, ic, 1] - tri[t, ia, 1]
    wz = tri[t, ic, 2] - tri[t, ia, 2]
    xc = wx * ux + wy * uy + wz * uz
    wx -= xc * ux
    wy -= xc * uy
    wz -= xc * uz
    hgt = math.sqrt(wx * wx + wy * wy + wz * wz)
    if hgt > 0.0:
        wx /= hgt
        wy /= hgt
        wz /= hgt
    xc = min(max(xc, 0.0), L)  # in [0, L] because AB is the longest edge
    return ia, L, xc, hgt, ux, uy, uz, wx, wy, wz


@nb.njit(cache=True, inline="always")
def _row(j, nrows, L, xc, hgt, delta):
    """Row ``j``: bottom y0, height ch, left end xl, number of cells, cell width."""
    ch = hgt / nrows
    y0 = j * ch
    f = y0 / hgt if hgt > 0.0 else 0.0
    xl = xc * f
    width = L * (1.0 - f)
    ncol = max(1, int(math.ceil(width / delta)))
    return y0, ch, xl, ncol, width / ncol


@nb.njit(cache=True, parallel=True)
def _piece_counts(tri, lmax, delta, counts):
    for t in nb.prange(tri.shape[0]):
        if lmax[t] <= delta:
            counts[t] = 1
            continue
        ia, L, xc, hgt, ux, uy, uz, wx, wy, wz = _frame(tri, t)
        nrows = max(1, int(math.ceil(hgt / delta)))
        c = 0
        for j in range(nrows):
            y0, ch, xl, ncol, cw = _row(j, nrows, L, xc, hgt, delta)
            c += ncol
        counts[t] = c


@nb.njit(cache=True, parallel=True)
def _fill_pieces(tri, lmax, delta, pad, offsets, boxes, piece_tri):
    """Piece boxes (lo x, y, z, hi x, y, z) and their triangles."""
    for t in nb.prange(tri.shape[0]):
        o = offsets[t]
        tlo = np.empty(3)
        thi = np.empty(3)
        for d in range(3):
            tlo[d] = min(tri[t, 0, d], tri[t, 1, d], tri[t, 2, d])
            thi[d] = max(tri[t, 0, d], tri[t, 1, d], tri[t, 2, d])
        if lmax[t] <= delta:
            for d in range(3):
                boxes[o, d] = tlo[d]
                boxes[o, 3 + d] = thi[d]
            piece_tri[o] = t
            continue
        ia, L, xc, hgt, ux, uy, uz, wx, wy, wz = _frame(tri, t)
        u = (ux, uy, uz)
        w = (wx, wy, wz)
        nrows = max(1, int(math.ceil(hgt / delta)))
        for j in range(nrows):
            y0, ch, xl, ncol, cw = _row(j, nrows, L, xc, hgt, delta)
            for i in range(ncol):
                x0 = xl + i * cw
                for d in range(3):
                    a = tri[t, ia, d]
                    c00 = a + x0 * u[d] + y0 * w[d]
                    cx = cw * u[d]
                    cy = ch * w[d]
                    lo = c00 + min(cx, 0.0) + min(cy, 0.0)
                    hi = c00 + max(cx, 0.0) + max(cy, 0.0)
                    boxes[o, d] = max(lo - pad, tlo[d])
                    boxes[o, 3 + d] = min(hi + pad, thi[d])
                piece_tri[o] = t
                o += 1


def _count_bound(tri: np.ndarray, lmax: np.ndarray, delta: float) -> float:
    """Upper bound on the number of pieces at spacing ``delta`` (cheap, numpy)."""
    big = lmax > delta
    if not big.any():
        return float(len(lmax))
    corners = tri[big, :3]
    L = lmax[big]
    area2 = np.linalg.norm(np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0]), axis=1)
    hgt = area2 / L
    # rows R <= h/delta + 1 and sum_j ceil(width_j/delta) <= L (R + 1) / (2 delta) + R
    rows = hgt / delta + 1
    per = L * (rows + 1) / (2 * delta) + rows
    return float((~big).sum() + per.sum())


@nb.njit(cache=True, inline="always")
def _spread_bits(x):
    """The low 21 bits of ``x`` (uint64) two zero bits apart: one axis of a Morton code."""
    x = (x | (x << np.uint64(32))) & np.uint64(0x1F00000000FFFF)
    x = (x | (x << np.uint64(16))) & np.uint64(0x1F0000FF0000FF)
    x = (x | (x << np.uint64(8))) & np.uint64(0x100F00F00F00F00F)
    x = (x | (x << np.uint64(4))) & np.uint64(0x10C30C30C30C30C3)
    return (x | (x << np.uint64(2))) & np.uint64(0x1249249249249249)


@nb.njit(cache=True, parallel=True)
def _morton_codes(points, lo, scale, codes):
    """63-bit Morton codes of ``points`` (k, 3), or of the centres of boxes (k, 6) (lo, hi),
    quantised by ``scale`` from ``lo`` and clamped to 21 bits an axis."""
    top = float(2**21 - 1)
    centres = points.shape[1] == 6
    for k in nb.prange(points.shape[0]):
        code = np.uint64(0)
        for axis in range(3):
            x = 0.5 * (points[k, axis] + points[k, 3 + axis]) if centres else points[k, axis]
            q = min(max((x - lo[axis]) * scale, 0.0), top)
            code |= _spread_bits(np.uint64(q)) << np.uint64(axis)
        codes[k] = code


def _morton(points: np.ndarray, lo: np.ndarray, hi: np.ndarray) -> np.ndarray:
    """63-bit Morton codes of points (k, 3), or of box centres (k, 6), in the box [lo, hi]."""
    ext = float(np.max(hi - lo))
    codes = np.empty(points.shape[0], np.uint64)
    _morton_codes(points, np.ascontiguousarray(lo, np.float64), (2**21 - 1) / ext if ext > 0 else 0.0, codes)
    return codes


@nb.njit(cache=True)
def _corner_bounds(tri):
    """The corners' lowest and highest coordinates, their largest magnitude, and whether every
    value of the triangle data is finite: one pass instead of a copy of the corners and four
    reductions over it."""
    lo = np.full(3, np.inf)
    hi = np.full(3, -np.inf)
    largest = 0.0
    finite = True
    for t in range(tri.shape[0]):
        for row in range(4):
            for d in range(3):
                x = tri[t, row, d]
                if not np.isfinite(x):
                    finite = False
                elif row < 3:
                    lo[d] = min(lo[d], x)
                    hi[d] = max(hi[d], x)
                    largest = max(largest, abs(x))
    return lo, hi, largest, finite


@nb.njit(cache=True)
def _build_tree(boxes, leaf_size):
    """Balanced hierarchy over pieces in their (Morton) order: halve ranges until <= leaf_size.

    Returns node boxes (k, 6), first child (-1 for a leaf; the second child is first + 1),
    and each node's piece range [start, end). Children come after their parent.
    """
    n = boxes.shape[0]
    cap = 4 * (n // leaf_size + 1) + 1
    start = np.empty(cap, np.int64)
    end = np.empty(cap, np.int64)
    child = np.full(cap, -1, np.int64)
    start[0] = 0
    end[0] = n
    count = 1
    i = 0
    while i < count:
        s = start[i]
        e = end[i]
        if e - s > leaf_size:
            mid = (s + e) // 2
            child[i] = count
            start[count] = s
            end[count] = mid
            start[count + 1] = mid
            end[count + 1] = e
            count += 2
        i += 1
    nodes = np.empty((count, 6), np.float64)
    for i in range(count - 1, -1, -1):
        c = child[i]
        if c < 0:
            for d in range(3):
                lo = np.inf
                hi = -np.inf
                for p in range(start[i], end[i]):
                    lo = min(lo, boxes[p, d])
                    hi = max(hi, boxes[p, 3 + d])
                nodes[i, d] = lo
                nodes[i, 3 + d] = hi
        else:
            for d in range(3):
                nodes[i, d] = min(nodes[c, d], nodes[c + 1, d])
                nodes[i, 3 + d] = max(nodes[c, 3 + d], nodes[c + 1, 3 + d])
    return nodes, child[:count].copy(), start[:count].copy(), end[:count].copy()


@nb.njit(cache=True, inline="always")
def _box_d2(b, i, px, py, pz):
    d2 = 0.0
    v = b[i, 0] - px
    if v > 0.0:
        d2 += v * v
    else:
        v = px - b[i, 3]
        if v > 0.0:
            d2 += v * v
    v = b[i, 1] - py
    if v > 0.0:
        d2 += v * v
    else:
        v = py - b[i, 4]
        if v > 0.0:
            d2 += v * v
    v = b[i, 2] - pz
    if v > 0.0:
        d2 += v * v
    else:
        v = pz - b[i, 5]
        if v > 0.0:
            d2 += v * v
    return d2


@nb.njit(cache=True, parallel=True)
def _query_kernel(points, order, nodes, child, start, end, boxes, piece_tri, tri, dist2, closest, which):
    nq = order.shape[0]
    nblocks = (nq + _BLOCK - 1) // _BLOCK
    for blk in nb.prange(nblocks):
        stack_node = np.empty(_STACK, np.int64)
        stack_d2 = np.empty(_STACK, np.float64)
        seed = np.int64(-1)
        for r in range(blk * _BLOCK, min(nq, (blk + 1) * _BLOCK)):
            i = order[r]
            px = points[i, 0]
            py = points[i, 1]
            pz = points[i, 2]
            best = np.inf
            bx = by = bz = np.nan
            bt = np.int64(-1)
            if seed >= 0:  # the previous (nearby, Morton order) query's triangle
                best, bx, by, bz = _closest_on_triangle(px, py, pz, tri, seed)
                bt = seed
            sp = 0
            stack_node[0] = 0
            stack_d2[0] = _box_d2(nodes, 0, px, py, pz)
            sp = 1
            while sp > 0:
                sp -= 1
                nd = stack_node[sp]
                if stack_d2[sp] >= best:
                    continue
                c = child[nd]
                if c < 0:
                    last = np.int64(-1)
                    for p in range(start[nd], end[nd]):
                        t = piece_tri[p]
                        if t == last or t == bt:
                            continue
                        if _box_d2(boxes, p, px, py, pz) >= best:
                            continue
                        last = t
                        d2, qx, qy, qz = _closest_on_triangle(px, py, pz, tri, t)
                        if d2 < best:
                            best, bx, by, bz, bt = d2, qx, qy, qz, t
                else:
                    d0 = _box_d2(nodes, c, px, py, pz)
                    d1 = _box_d2(nodes, c + 1, px, py, pz)
                    near, far, dn, df = c, c + 1, d0, d1
                    if d1 < d0:
                        near, far, dn, df = c + 1, c, d1, d0
                    if df < best:  # pushed first, visited last
                        stack_node[sp] = far
                        stack_d2[sp] = df
                        sp += 1
                    if dn < best:
                        stack_node[sp] = near
                        stack_d2[sp] = dn
                        sp += 1
            dist2[i] = best
            closest[i, 0] = bx
            closest[i, 1] = by
            closest[i, 2] = bz
            which[i] = bt
            seed = bt


# ----------------------------------------------------------------------------------------
# public API
# ----------------------------------------------------------------------------------------


class MeshDistance:
    """Exact unsigned distance from points to a triangle mesh (method: the module docstring).

    Parameters
    ----------
    vertices : (n, 3) float array
    triangles : (m, 3) int array of vertex indices, m >= 1 (any triangles: open, non-manifold,
        duplicated or zero-area ones are fine)
    spacing : piece size ``s``: triangles with a longer edge are cut into ``<= s x s`` pieces.
        Default: twice the median longest edge.
    max_pieces : cap on the number of pieces (default ``max(4 m, 2**16)``); ``spacing`` grows
        when it would exceed it.

    Attributes
    ----------
    spacing, n_pieces, n_triangles.

    ``query(points)`` returns ``(distance (k,), closest_point (k, 3), triangle (k,))``.
    """

    def __init__(self, vertices, triangles, *, spacing: float | None = None,
                 max_pieces: int | None = None):
        v = np.ascontiguousarray(vertices, dtype=np.float64)
        f = np.ascontiguousarray(triangles, dtype=np.int64)
        if v.ndim != 2 or v.shape[1] != 3:
            raise ValueError(f"vertices must be (n, 3), got {v.shape}")
        if f.ndim != 2 or f.shape[1] != 3:
            raise ValueError(f"triangles must be (m, 3), got {f.shape}")
        if len(f) == 0:
            raise ValueError("the mesh has no triangles")
        if f.min() < 0 or f.max() >= len(v):
            raise ValueError("triangle vertex index out of range")
        self._tri, lmax = _triangle_data(v, f)
        self._lo, self._hi, largest, finite = _corner_bounds(self._tri)
        if not finite:
            raise ValueError("mesh vertices must be finite")
        m = len(f)
        cap = max(int(max_pieces) if max_pieces is not None else max(4 * m, 1 << 16), m)
        if spacing is not None:
            if not spacing > 0:
                raise ValueError("spacing must be > 0")
            delta = float(spacing)
        else:
            delta = 2.0 * float(np.median(lmax))
        if not delta > 0:
            delta = float(lmax.max())
        if not delta > 0:  # every triangle is a point
            delta = 1.0
        while _count_bound(self._tri, lmax, delta) > cap:
            delta *= 1.25
        counts = np.empty(m, np.int64)
        _piece_counts(self._tri, lmax, delta, counts)
        offsets = np.zeros(m + 1, np.int64)
        np.cumsum(counts, out=offsets[1:])
        n = int(offsets[-1])
        boxes = np.empty((n, 6), np.float64)
        piece_tri = np.empty(n, np.int64)
        pad = 1e-12 * (largest + float(np.max(self._hi - self._lo)))
        _fill_pieces(self._tri, lmax, delta, pad, offsets, boxes, piece_tri)
        order = np.argsort(_morton(boxes, self._lo, self._hi), kind="stable")
        self._boxes = np.ascontiguousarray(boxes[order])
        self._piece_tri = np.ascontiguousarray(piece_tri[order])
        self._nodes, self._child, self._start, self._end = _build_tree(self._boxes, _LEAF)
        self.spacing = delta
        self.n_pieces = n
        self.n_triangles = m

    def query(self, points) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Distance (k,), closest point on the mesh (k, 3) and its triangle index (k,)."""
        p = np.ascontiguousarray(points, dtype=np.float64)
        if p.ndim == 1 and p.shape[0] == 3:
            p = p.reshape(1, 3)
        if p.ndim != 2 or p.shape[1] != 3:
            raise ValueError(f"points must be (k, 3), got {p.shape}")
        if not np.isfinite(p).all():
            raise ValueError("query points must be finite")
        n = len(p)
        dist2 = np.empty(n, np.float64)
        closest = np.empty((n, 3), np.float64)
        which = np.empty(n, np.int64)
        if n:
            order = np.argsort(_morton(p, self._lo, self._hi)).astype(np.int64)
            _query_kernel(p, order, self._nodes, self._child, self._start, self._end, self._boxes,
                          self._piece_tri, self._tri, dist2, closest, which)
        return np.sqrt(dist2), closest, which

