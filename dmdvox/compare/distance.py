"""Exact unsigned distance from many query points to a triangle mesh.

:class:`MeshDistance` is built once from ``(vertices, triangles)`` and answers
``query(points) -> (distance, closest_point, triangle)`` for any number of points.

Method
------
1. **Sampling.** Every triangle is covered by sample points, each tagged with its triangle.
   A triangle whose *centroid radius* (largest centroid-to-corner distance) is at most the
   target cover radius ``h = spacing / sqrt(2)`` gets one sample, its centroid. A larger
   triangle is laid out in its own plane with its longest edge as the base and cut into rows
   of height ``<= spacing``; each row is cut into cells of width ``<= spacing`` spanning the
   triangle's extent at the row's bottom (the widest), and each cell contributes its centre.
   Sliver triangles therefore cost O(length / spacing) samples, not O((length / spacing)^2).
2. **Cover radius.** Each sample ``p`` of a triangle ``T`` covers the part of ``T`` inside its
   cell (or all of ``T``, for a centroid): a convex set whose farthest point from ``p`` is a
   corner, at ``sqrt(cw^2 + ch^2) / 2`` for a ``cw x ch`` cell, at the centroid radius for a
   centroid. ``H`` is the largest of these over all samples (``H <= h`` unless the sample cap
   raised ``h``), padded by a relative 1e-9 and an absolute 1e-12 x the coordinate scale so
   rounding in the sample positions cannot break it.
3. **The bound.** Every point ``c`` of every triangle ``T`` lies within ``H`` of a sample of
   ``T``. So if ``T*`` is the nearest triangle to a query ``q``, with nearest point ``c*`` at
   the true distance ``d*``, then some sample of ``T*`` lies within ``d* + H <= d_best + H``
   of ``q``, where ``d_best`` is the exact distance to any triangle already evaluated.
4. **Query and certificate.** A cKDTree on the samples gives each query its ``k`` nearest
   samples; the exact distance (below) to each of their triangles gives ``d_best``. If the
   ``k``-th nearest sample is at ``r_k >= d_best + H``, every sample within ``d_best + H`` has
   been seen, ``T*`` among their triangles, so ``d_best = d*``: the answer is certified. The
   others are asked again with ``k`` four times larger and the tree's search cut at
   ``d_best + H`` (a query whose cut search returns fewer than ``k`` samples has seen all
   samples within the cut), until certified; at ``k = number of samples`` everything is seen.
   Queries near the surface (``d`` a few ``H``) certify in the first round; the number of
   samples a query must see grows like ``pi * (2 d H + H^2) / spacing^2``, i.e. linearly with
   ``d / H``, so points far from a finely sampled mesh are slower (still exact).
5. **Exact point-triangle distance.** The region-based closest-point algorithm (vertex, edge
   and face Voronoi regions from the six dot products ``ab.ap, ac.ap, ab.bp, ...``), compiled
   with numba. In the face region the point is projected on the plane along a unit normal
   taken at the triangle's largest angle (the best-conditioned cross product). Degenerate
   triangles (zero or near-zero area: inradius below 1e-8 of the longest edge) use the
   nearest of their three edges instead, which is exact for zero-area triangles and within
   the inradius otherwise; zero-length edges are points.

Spacing
-------
By default ``h`` is the median centroid radius, so a uniformly fine mesh (marching cubes)
gets about one sample per triangle and only the larger half is subdivided, while a CAD mesh
with a few huge faces gets those faces sampled at the scale of its typical triangle. The
sample count is capped (``max_samples``, default ``max(4 m, 2**17)`` for ``m`` triangles);
when the cap binds, ``h`` grows until it fits. The bound in 4. holds for any spacing: the
spacing only trades tree size against how many samples a query must see.
"""

from __future__ import annotations

import math

import numba as nb
import numpy as np
from scipy.spatial import cKDTree

__all__ = ["MeshDistance", "point_triangle_distance"]

_CHUNK = 1 << 18  # queries per batch: bounds the (batch, k) neighbour arrays
_MAX_CELLS = 1 << 22  # (queries x k) per tree call in the growing rounds
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

    ``tri[t]`` holds the corners a, b, c and a unit normal (zero for a degenerate triangle).
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
                        else:  # face region
                            nx = tri[t, 3, 0]
                            ny = tri[t, 3, 1]
                            nz = tri[t, 3, 2]
                            if nx != 0.0 or ny != 0.0 or nz != 0.0:
                                s = apx * nx + apy * ny + apz * nz
                                qx = px - s * nx
                                qy = py - s * ny
                                qz = pz - s * nz
                            else:  # degenerate: the nearest of the three edges
                                best, qx, qy, qz = _closest_on_segment(px, py, pz, ax, ay, az, bx, by, bz)
                                e2, rx, ry, rz = _closest_on_segment(px, py, pz, bx, by, bz, cx, cy, cz)
                                if e2 < best:
                                    best, qx, qy, qz = e2, rx, ry, rz
                                e2, rx, ry, rz = _closest_on_segment(px, py, pz, cx, cy, cz, ax, ay, az)
                                if e2 < best:
                                    best, qx, qy, qz = e2, rx, ry, rz
    dx = px - qx
    dy = py - qy
    dz = pz - qz
    return dx * dx + dy * dy + dz * dz, qx, qy, qz


@nb.njit(cache=True, parallel=True)
def _brute_kernel(points, tri, dist2, closest, which):
    for i in nb.prange(points.shape[0]):
        best = np.inf
        bx = by = bz = np.nan
        bt = np.int64(-1)
        for t in range(tri.shape[0]):
            d2, qx, qy, qz = _closest_on_triangle(points[i, 0], points[i, 1], points[i, 2], tri, t)
            if d2 < best:
                best, bx, by, bz, bt = d2, qx, qy, qz, t
        dist2[i] = best
        closest[i, 0] = bx
        closest[i, 1] = by
        closest[i, 2] = bz
        which[i] = bt


@nb.njit(cache=True, parallel=True)
def _eval_candidates(points, rows, idx, n_samples, sample_tri, tri, dist2, closest, which):
    """For each ``rows[r]``, the exact minimum over the triangles of samples ``idx[r, :]``.

    Updates ``dist2 / closest / which`` in place (they hold the best so far). ``idx`` entries
    equal to ``n_samples`` are cKDTree's "no neighbour" padding and end a row.
    """
    k = idx.shape[1]
    for r in nb.prange(rows.shape[0]):
        i = rows[r]
        px = points[i, 0]
        py = points[i, 1]
        pz = points[i, 2]
        best = dist2[i]
        bx = closest[i, 0]
        by = closest[i, 1]
        bz = closest[i, 2]
        bt = which[i]
        last = np.int64(-1)
        for j in range(k):
            s = idx[r, j]
            if s >= n_samples:
                break
            t = sample_tri[s]
            if t == last or t == bt:
                continue
            last = t
            d2, qx, qy, qz = _closest_on_triangle(px, py, pz, tri, t)
            if d2 < best:
                best, bx, by, bz, bt = d2, qx, qy, qz, t
        dist2[i] = best
        closest[i, 0] = bx
        closest[i, 1] = by
        closest[i, 2] = bz
        which[i] = bt


# ----------------------------------------------------------------------------------------
# triangle data and sampling
# ----------------------------------------------------------------------------------------


def _triangle_data(vertices: np.ndarray, triangles: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(m, 4, 3) corners + unit normal (zero when degenerate), and the centroid radii."""
    corners = vertices[triangles]  # (m, 3, 3)
    a, b, c = corners[:, 0], corners[:, 1], corners[:, 2]
    ab, bc, ca = b - a, c - b, a - c
    lab = np.einsum("ij,ij->i", ab, ab)
    lbc = np.einsum("ij,ij->i", bc, bc)
    lca = np.einsum("ij,ij->i", ca, ca)
    # cross product at the largest angle = the two shorter edges (opposite the longest)
    longest = np.argmax(np.stack([lbc, lca, lab], axis=1), axis=1)  # 0: bc, 1: ca, 2: ab
    n = np.cross(ab, -ca)  # angle at a (opposite bc)
    at_b = longest == 1
    n[at_b] = np.cross(bc[at_b], -ab[at_b])
    at_c = longest == 2
    n[at_c] = np.cross(ca[at_c], -bc[at_c])
    nn = np.sqrt(np.einsum("ij,ij->i", n, n))
    perimeter = np.sqrt(lab) + np.sqrt(lbc) + np.sqrt(lca)
    lmax = np.sqrt(np.maximum(np.maximum(lab, lbc), lca))
    inradius = nn / np.where(perimeter > 0, perimeter, 1.0)
    ok = (inradius > _DEGENERATE * lmax) & (nn > 0)
    unit = np.zeros_like(n)
    unit[ok] = n[ok] / nn[ok, None]
    tri = np.ascontiguousarray(np.concatenate([corners, unit[:, None, :]], axis=1), dtype=np.float64)
    g = corners.mean(axis=1)
    rc = np.sqrt(np.max(np.sum((corners - g[:, None, :]) ** 2, axis=2), axis=1))
    return tri, rc


@nb.njit(cache=True, inline="always")
def _frame(tri, t):
    """Base = longest edge A->B (length L), apex C at (xc, hgt) in the frame (u, v)."""
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
    xc = min(max(xc, 0.0), L)
    return ia, L, xc, hgt, ux, uy, uz, wx, wy, wz


@nb.njit(cache=True, inline="always")
def _row(j, nrows, L, xc, hgt, delta):
    """Row ``j``: bottom y0, height ch, left end xl, width, number of cells, cell width."""
    ch = hgt / nrows
    y0 = j * ch
    f = y0 / hgt if hgt > 0.0 else 0.0
    xl = xc * f
    width = L * (1.0 - f)
    ncol = max(1, int(math.ceil(width / delta)))
    return y0, ch, xl, width, ncol, width / ncol


@nb.njit(cache=True, parallel=True)
def _sample_counts(tri, rc, cover, delta, counts):
    for t in nb.prange(tri.shape[0]):
        if rc[t] <= cover:
            counts[t] = 1
            continue
        ia, L, xc, hgt, ux, uy, uz, wx, wy, wz = _frame(tri, t)
        nrows = max(1, int(math.ceil(hgt / delta)))
        c = 0
        for j in range(nrows):
            y0, ch, xl, width, ncol, cw = _row(j, nrows, L, xc, hgt, delta)
            c += ncol
        counts[t] = c


@nb.njit(cache=True, parallel=True)
def _fill_samples(tri, rc, cover, delta, offsets, samples, sample_tri, tri_cover):
    for t in nb.prange(tri.shape[0]):
        o = offsets[t]
        if rc[t] <= cover:
            for d in range(3):
                samples[o, d] = (tri[t, 0, d] + tri[t, 1, d] + tri[t, 2, d]) / 3.0
            sample_tri[o] = t
            tri_cover[t] = rc[t]
            continue
        ia, L, xc, hgt, ux, uy, uz, wx, wy, wz = _frame(tri, t)
        ax = tri[t, ia, 0]
        ay = tri[t, ia, 1]
        az = tri[t, ia, 2]
        nrows = max(1, int(math.ceil(hgt / delta)))
        worst = 0.0
        for j in range(nrows):
            y0, ch, xl, width, ncol, cw = _row(j, nrows, L, xc, hgt, delta)
            y = y0 + 0.5 * ch
            for i in range(ncol):
                x = xl + (i + 0.5) * cw
                samples[o, 0] = ax + x * ux + y * wx
                samples[o, 1] = ay + x * uy + y * wy
                samples[o, 2] = az + x * uz + y * wz
                sample_tri[o] = t
                o += 1
            worst = max(worst, 0.5 * math.sqrt(cw * cw + ch * ch))
        tri_cover[t] = worst


def _count_bound(tri: np.ndarray, rc: np.ndarray, cover: float) -> float:
    """An upper bound on the number of samples at cover radius ``cover`` (cheap, numpy)."""
    big = rc > cover
    if not big.any():
        return float(len(rc))
    corners = tri[big, :3]
    e = np.sqrt(np.sum((corners - np.roll(corners, 1, axis=1)) ** 2, axis=2))
    L = e.max(axis=1)
    area2 = np.linalg.norm(np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0]), axis=1)
    hgt = area2 / np.where(L > 0, L, 1.0)
    delta = cover * math.sqrt(2.0)
    # rows: ceil(hgt/delta) <= hgt/delta + 1, row height >= delta/2 when there are 2+ rows, so
    # sum_j ceil(width_j/delta) <= 2 area/delta^2 + L/delta + rows
    per = area2 / delta**2 + 2 * L / delta + hgt / delta + 2
    return float((~big).sum() + per.sum())


# ----------------------------------------------------------------------------------------
# public API
# ----------------------------------------------------------------------------------------


class MeshDistance:
    """Exact unsigned distance from points to a triangle mesh (see the module docstring).

    Parameters
    ----------
    vertices : (n, 3) float array
    triangles : (m, 3) int array of vertex indices, m >= 1
    spacing : sample spacing ``s``; every sample covers its part of its triangle within
        ``s / sqrt(2)``. Default: ``sqrt(2)`` x the median triangle centroid radius.
    max_samples : cap on the number of samples (default ``max(4 m, 2**17)``); ``spacing``
        grows when it would exceed it.
    k : neighbours asked for in the first round (default 8).
    workers : cKDTree threads (-1: all).

    Attributes
    ----------
    spacing, cover_radius (the bound ``H``), n_samples, samples (n_samples, 3),
    sample_triangle (n_samples,).
    """

    def __init__(self, vertices, triangles, *, spacing: float | None = None,
                 max_samples: int | None = None, k: int = 8, workers: int = -1):
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
        if not np.isfinite(v[np.unique(f)]).all():
            raise ValueError("mesh vertices must be finite")
        self.k = max(1, int(k))
        self.workers = workers
        self._tri, rc = _triangle_data(v, f)
        m = len(f)
        cap = int(max_samples) if max_samples is not None else max(4 * m, 1 << 17)
        cap = max(cap, m)
        if spacing is not None:
            if not spacing > 0:
                raise ValueError("spacing must be > 0")
            cover = float(spacing) / math.sqrt(2.0)
        else:
            cover = float(np.median(rc))
        if not cover > 0:
            cover = float(rc.max())
        if not cover > 0:  # every triangle is a point
            cover = 1.0
        while _count_bound(self._tri, rc, cover) > cap:
            cover *= 1.25
        delta = cover * math.sqrt(2.0)
        counts = np.empty(m, np.int64)
        _sample_counts(self._tri, rc, cover, delta, counts)
        offsets = np.zeros(m + 1, np.int64)
        np.cumsum(counts, out=offsets[1:])
        n_samples = int(offsets[-1])
        self.samples = np.empty((n_samples, 3), np.float64)
        self.sample_triangle = np.empty(n_samples, np.int64)
        tri_cover = np.empty(m, np.float64)
        _fill_samples(self._tri, rc, cover, delta, offsets, self.samples, self.sample_triangle, tri_cover)
        scale = float(np.abs(self._tri[:, :3]).max())
        self.spacing = delta
        self.cover_radius = float(tri_cover.max()) * (1.0 + 1e-9) + 1e-12 * (scale + 1.0)
        self.n_samples = n_samples
        self._tree = cKDTree(self.samples, leafsize=16, balanced_tree=False, compact_nodes=False)

    @property
    def n_triangles(self) -> int:
        return len(self._tri)

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
        dist2 = np.full(n, np.inf)
        closest = np.full((n, 3), np.nan)
        which = np.full(n, -1, np.int64)
        for start in range(0, n, _CHUNK):
            stop = min(n, start + _CHUNK)
            self._query_chunk(p[start:stop], dist2[start:stop], closest[start:stop], which[start:stop])
        return np.sqrt(dist2), closest, which

    def _knn(self, p, k, bound=np.inf):
        dist, idx = self._tree.query(p, k=k, distance_upper_bound=bound, workers=self.workers)
        if k == 1:
            dist, idx = dist[:, None], idx[:, None]
        return dist, np.ascontiguousarray(idx, dtype=np.int64)

    def _query_chunk(self, p, dist2, closest, which):
        ns = self.n_samples
        H = self.cover_radius
        k = min(self.k, ns)
        rk, idx = self._knn(p, k)
        rows = np.arange(len(p), dtype=np.int64)
        _eval_candidates(p, rows, idx, ns, self.sample_triangle, self._tri, dist2, closest, which)
        if k >= ns:
            return
        todo = rows[rk[:, -1] < np.sqrt(dist2) + H]
        while todo.size:
            k = min(4 * k, ns)
            reach = np.sqrt(dist2[todo]) + H
            order = np.argsort(reach)
            todo, reach = todo[order], reach[order]
            group = max(1, _MAX_CELLS // k)
            left = []
            for g in range(0, todo.size, group):
                sel = todo[g:g + group]
                bound = float(reach[min(g + group, todo.size) - 1]) * (1.0 + 1e-12)
                rk, idx = self._knn(p[sel], k, bound)
                _eval_candidates(p, sel, idx, ns, self.sample_triangle, self._tri, dist2, closest, which)
                if k < ns:
                    left.append(sel[rk[:, -1] < np.sqrt(dist2[sel]) + H])
            todo = np.concatenate(left) if left else todo[:0]


def point_triangle_distance(points, vertices, triangles) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Brute force: the exact kernel against every triangle (O(k m); for small meshes/tests)."""
    v = np.ascontiguousarray(vertices, dtype=np.float64)
    f = np.ascontiguousarray(triangles, dtype=np.int64)
    p = np.ascontiguousarray(points, dtype=np.float64).reshape(-1, 3)
    tri, _ = _triangle_data(v, f)
    dist2 = np.empty(len(p))
    closest = np.empty((len(p), 3))
    which = np.empty(len(p), np.int64)
    _brute_kernel(p, tri, dist2, closest, which)
    return np.sqrt(dist2), closest, which
