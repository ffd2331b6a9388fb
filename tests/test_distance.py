"""Exact point-to-mesh distance (dmdvox.comparison.distance) against brute force and geometry."""

import numpy as np
import pytest

from dmdvox.comparison.distance import MeshDistance

# ----------------------------------------------------------------------------------------
# reference: numpy brute force over all triangles (an independent algorithm: plane
# projection + inside test, else the nearest of the three edges)
# ----------------------------------------------------------------------------------------


def _segment_d2(p, x, y):
    e = y - x
    ee = np.einsum("...i,...i->...", e, e)
    t = np.clip(np.einsum("...i,...i->...", p - x, e) / np.where(ee > 0, ee, 1.0), 0.0, 1.0)
    r = p - (x + t[..., None] * e)
    return np.einsum("...i,...i->...", r, r)


def brute_distance(points, vertices, triangles, chunk=16):
    """(k,) exact distances: the minimum over every triangle, in numpy."""
    points = np.asarray(points, np.float64).reshape(-1, 3)
    a, b, c = (vertices[triangles[:, i]] for i in range(3))
    n = np.cross(b - a, c - a)
    nn = np.einsum("ij,ij->i", n, n)
    scale = np.maximum.reduce([np.einsum("ij,ij->i", e, e) for e in (b - a, c - b, a - c)])
    flat = nn <= 1e-24 * scale**2 + 1e-300
    out = np.empty(len(points))
    for s in range(0, len(points), chunk):
        p = points[s:s + chunk, None, :]
        d2 = np.minimum(np.minimum(_segment_d2(p, a, b), _segment_d2(p, b, c)), _segment_d2(p, c, a))
        h = np.einsum("kmi,mi->km", p - a, n)
        nn_safe = np.where(flat, 1.0, nn)
        proj = p - (h / nn_safe)[..., None] * n
        inside = np.broadcast_to(~flat, h.shape).copy()
        for x, y in ((a, b), (b, c), (c, a)):
            inside &= np.einsum("kmi,mi->km", np.cross(y - x, proj - x), n) >= 0
        d2 = np.where(inside, np.minimum(d2, h * h / nn_safe), d2)
        out[s:s + chunk] = np.sqrt(d2.min(axis=1))
    return out


def check_against_brute(md, points, vertices, triangles, tol):
    d, cp, tri = md.query(points)
    ref = brute_distance(points, vertices, triangles)
    assert d.shape == (len(points),) and cp.shape == (len(points), 3) and tri.shape == (len(points),)
    assert d.dtype == np.float64 and cp.dtype == np.float64 and tri.dtype == np.int64
    np.testing.assert_allclose(d, ref, rtol=0, atol=tol)
    # the closest point is at the reported distance and lies on the reported triangle
    np.testing.assert_allclose(np.linalg.norm(points - cp, axis=1), d, rtol=0, atol=tol)
    assert tri.min() >= 0 and tri.max() < len(triangles)
    on_own = np.array([brute_distance(cp[i], vertices, triangles[tri[i]][None])[0] for i in range(0, len(cp), 7)])
    assert on_own.max() < tol
    return d, cp, tri


# ----------------------------------------------------------------------------------------
# meshes
# ----------------------------------------------------------------------------------------

BOX_SIZE = np.array([2.0, 1.0, 3.0])


def box_mesh(size=BOX_SIZE, origin=(0.0, 0.0, 0.0)):
    """An axis-aligned box as 12 triangles (a CAD box)."""
    o = np.asarray(origin, np.float64)
    v = np.array([[x, y, z] for x in (0, 1) for y in (0, 1) for z in (0, 1)], np.float64) * size + o
    quads = [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)]
    f = np.array([t for q in quads for t in ((q[0], q[1], q[2]), (q[0], q[2], q[3]))], np.int64)
    return v, f


def icosphere(level, radius=1.0):
    t = (1 + 5**0.5) / 2
    v = [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t), (0, -1, -t), (0, 1, -t),
         (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]
    f = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4), (11, 10, 2),
         (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8), (3, 8, 9), (4, 9, 5),
         (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    v = np.array(v, np.float64)
    v /= np.linalg.norm(v, axis=1, keepdims=True)
    f = np.array(f, np.int64)
    for _ in range(level):
        edges = np.sort(np.concatenate([f[:, [0, 1]], f[:, [1, 2]], f[:, [2, 0]]]), axis=1)
        uniq, inv = np.unique(edges, axis=0, return_inverse=True)
        inv = inv.reshape(-1)
        mid = v[uniq].mean(axis=1)
        mid /= np.linalg.norm(mid, axis=1, keepdims=True)
        m = len(f)
        ab, bc, ca = (inv[:m] + len(v), inv[m:2 * m] + len(v), inv[2 * m:] + len(v))
        v = np.concatenate([v, mid])
        f = np.concatenate([np.stack([f[:, 0], ab, ca], 1), np.stack([ab, f[:, 1], bc], 1),
                            np.stack([ca, bc, f[:, 2]], 1), np.stack([ab, bc, ca], 1)])
    return v * radius, f


def box_exact(points, size=BOX_SIZE):
    """Analytic distance to the surface of [0, size]."""
    below = np.maximum(-points, 0.0)
    above = np.maximum(points - size, 0.0)
    outside = np.linalg.norm(below + above, axis=1)
    inside_depth = np.min(np.minimum(points, size - points), axis=1)
    is_inside = np.all((points >= 0) & (points <= size), axis=1)
    return np.where(is_inside, inside_depth, outside)


def box_queries(rng, size=BOX_SIZE):
    inside = rng.uniform(0, 1, (300, 3)) * size
    outside = rng.uniform(-1.5, 1.5, (300, 3)) * size + 0.5 * size
    # near edges: a point on each edge, offset by 1e-9 .. 0.3 in a random direction
    corners = np.array([[x, y, z] for x in (0, 1) for y in (0, 1) for z in (0, 1)], np.float64) * size
    pairs = [(i, j) for i in range(8) for j in range(i + 1, 8) if bin(i ^ j).count("1") == 1]
    e = np.array(pairs)[rng.integers(0, 12, 400)]
    on_edge = corners[e[:, 0]] + rng.random((400, 1)) * (corners[e[:, 1]] - corners[e[:, 0]])
    direction = rng.normal(size=(400, 3))
    direction /= np.linalg.norm(direction, axis=1, keepdims=True)
    near_edge = on_edge + direction * 10.0 ** rng.uniform(-9, -0.5, (400, 1))
    near_corner = corners[rng.integers(0, 8, 200)] + rng.normal(size=(200, 3)) * 10.0 ** rng.uniform(-9, 0, (200, 1))
    on_face = rng.uniform(0, 1, (100, 3)) * size
    on_face[np.arange(100), rng.integers(0, 3, 100)] = 0.0
    far = rng.normal(size=(50, 3)) * 100.0
    centre = 0.5 * size[None]
    return np.concatenate([inside, outside, on_edge[:50], near_edge, near_corner, on_face, far, centre])


# ----------------------------------------------------------------------------------------
# tests
# ----------------------------------------------------------------------------------------


@pytest.mark.parametrize("spacing", [None, 0.05])
def test_box_inside_outside_edges_corners(spacing):
    rng = np.random.default_rng(1)
    v, f = box_mesh()
    md = MeshDistance(v, f, spacing=spacing)
    if spacing is None:
        assert md.n_pieces == 12  # big triangles stay whole: the hierarchy is brute force
    else:
        assert md.n_pieces > 1000  # cut into <= 0.05 x 0.05 pieces
    q = box_queries(rng)
    d, cp, tri = check_against_brute(md, q, v, f, tol=1e-12)
    np.testing.assert_allclose(d, box_exact(q), rtol=0, atol=1e-12)
    # the centre of the box is 0.5 from the two y faces
    assert d[-1] == pytest.approx(0.5, abs=1e-15)
    assert abs(cp[-1, 1] - 0.5) == pytest.approx(0.5, abs=1e-15)


def test_box_translated_far_from_origin():
    """Machine coordinates (hundreds of mm) do not hurt exactness."""
    rng = np.random.default_rng(2)
    origin = np.array([350.0, -220.0, 15.0])
    v, f = box_mesh(origin=origin)
    md = MeshDistance(v, f, spacing=0.1)
    q = box_queries(rng)
    d, _, _ = md.query(q + origin)
    np.testing.assert_allclose(d, box_exact(q), rtol=0, atol=1e-9)


def test_sphere_20k_triangles():
    rng = np.random.default_rng(3)
    v, f = icosphere(5)  # 20480 triangles
    assert len(f) == 20480
    md = MeshDistance(v, f)
    random = rng.uniform(-1.5, 1.5, (400, 3))
    u = rng.normal(size=(400, 3))
    u /= np.linalg.norm(u, axis=1, keepdims=True)
    near = u * (1.0 + rng.normal(0, 0.02, (400, 1)))
    q = np.concatenate([random, near, [[0.0, 0.0, 0.0]]])
    d, cp, _ = check_against_brute(md, q, v, f, tol=1e-9)
    # and against the sphere itself: the mesh is inscribed, so it is within the sagitta
    sagitta = 1 - np.cos(np.max(np.linalg.norm(v[f[:, 0]] - v[f[:, 1]], axis=1)))
    assert np.abs(d - np.abs(np.linalg.norm(q, axis=1) - 1)).max() < 2 * sagitta
    np.testing.assert_allclose(np.linalg.norm(cp, axis=1), 1.0, atol=2 * sagitta)


def test_mixed_scales_slivers_and_soup():
    """A CAD-like mix: huge faces, long slivers, a fine sphere, duplicates; default and fine spacing."""
    rng = np.random.default_rng(4)
    vb, fb = box_mesh(size=np.array([40.0, 30.0, 20.0]), origin=(-20.0, -15.0, -10.0))
    vs, fs = icosphere(3, radius=3.0)
    n = 60
    start = rng.uniform(-25, 25, (n, 3))
    axis = rng.normal(size=(n, 3))
    sliver = np.stack([start, start + axis * 10, start + axis * 10 + rng.normal(0, 1e-3, (n, 3))], 1)
    tiny = rng.uniform(-25, 25, (n, 1, 3)) + rng.normal(0, 1e-3, (n, 3, 3))
    soup = np.concatenate([sliver, tiny]).reshape(-1, 3)
    v = np.concatenate([vb, vs, soup])
    f = np.concatenate([fb, fs + len(vb), np.arange(len(soup)).reshape(-1, 3) + len(vb) + len(vs), fs[:50] + len(vb)])
    q = np.concatenate([rng.uniform(-30, 30, (500, 3)), rng.normal(0, 3.5, (300, 3)),
                        vs[rng.integers(0, len(vs), 100)] + rng.normal(0, 1e-3, (100, 3))])
    for spacing in (None, 0.5):
        md = MeshDistance(v, f, spacing=spacing)
        check_against_brute(md, q, v, f, tol=1e-9)


def test_degenerate_triangles():
    rng = np.random.default_rng(5)
    v = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0],  # a proper triangle
                  [2, 2, 2], [3, 3, 3], [4, 4, 4],  # collinear (zero area)
                  [5, 0, 0], [5, 0, 0], [6, 1, 0],  # a repeated vertex: a segment
                  [0, 5, 5], [0, 5, 5], [0, 5, 5],  # a point
                  [-1, -1, 0], [-1, -1, 0], [-3, -1, 0]], np.float64)
    f = np.arange(15).reshape(5, 3)
    f = np.concatenate([f, [[0, 0, 1], [2, 2, 2]]])  # more zero-area triangles on real vertices
    q = np.concatenate([rng.uniform(-2, 7, (500, 3)), v + rng.normal(0, 1e-3, v.shape), v])
    for spacing in (None, 0.3):  # 0.3: long degenerate triangles are cut into pieces too
        md = MeshDistance(v, f, spacing=spacing)
        d, cp, tri = check_against_brute(md, q, v, f, tol=1e-12)
        assert np.isfinite(d).all() and np.isfinite(cp).all()
    # nearly degenerate: apex 1e-10 off the base is treated as the edges, off by < the inradius
    cap = np.array([[0.0, 0.0, 0.0], [2.0, 0.0, 0.0], [1.0, 1e-10, 0.0]])
    qc = rng.uniform(-1, 3, (300, 3))
    dc, _, _ = MeshDistance(cap, np.array([[0, 1, 2]])).query(qc)
    np.testing.assert_allclose(dc, brute_distance(qc, cap, np.array([[0, 1, 2]])), rtol=0, atol=1e-10)
    # a mesh of nothing but degenerate triangles, one of them the collinear one
    md = MeshDistance(v, f[1:4])
    d, _, _ = md.query(np.array([[3.0, 3.0, 3.0], [0.0, 5.0, 6.0], [5.0, 1.0, 0.0]]))
    np.testing.assert_allclose(d, [0.0, 1.0, np.sqrt(0.5)], atol=1e-12)
    # every triangle a single point
    md = MeshDistance(np.zeros((3, 3)), np.array([[0, 1, 2], [0, 0, 0]]))
    np.testing.assert_allclose(md.query(np.array([[3.0, 4.0, 0.0]]))[0], [5.0])


def test_query_shapes_and_errors():
    v, f = box_mesh()
    md = MeshDistance(v, f)
    d, cp, tri = md.query(np.empty((0, 3)))
    assert d.shape == (0,) and cp.shape == (0, 3) and tri.shape == (0,)
    d, cp, tri = md.query([1.0, 0.5, -2.0])
    assert d.shape == (1,) and d[0] == pytest.approx(2.0)
    np.testing.assert_allclose(cp[0], [1.0, 0.5, 0.0])
    d32, _, _ = md.query(np.array([[1.0, 0.5, -2.0]], np.float32))
    assert d32[0] == pytest.approx(2.0)
    with pytest.raises(ValueError):
        md.query(np.zeros((4, 2)))
    with pytest.raises(ValueError):
        md.query([[np.nan, 0.0, 0.0]])
    with pytest.raises(ValueError):
        MeshDistance(v, np.empty((0, 3), np.int64))
    with pytest.raises(ValueError):
        MeshDistance(v, f + 8)
    with pytest.raises(ValueError):
        MeshDistance(v[:, :2], f)


def test_piece_cap_and_deterministic():
    """A tiny spacing on big triangles is capped; results do not depend on spacing or order."""
    rng = np.random.default_rng(6)
    v, f = box_mesh(size=np.array([100.0, 100.0, 100.0]))
    md = MeshDistance(v, f, spacing=1e-4, max_pieces=50_000)
    assert 12 <= md.n_pieces <= 50_000
    q = rng.uniform(-20, 120, (2000, 3))
    d1, _, _ = md.query(q)
    d2, _, _ = MeshDistance(v, f).query(q[::-1])
    np.testing.assert_allclose(d1, d2[::-1], rtol=0, atol=1e-12)
    np.testing.assert_allclose(d1, box_exact(q, np.array([100.0, 100.0, 100.0])), rtol=0, atol=1e-11)
