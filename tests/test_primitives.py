"""3-D bead solids: volumes against A*L + V_rev and Pappus, distances against sampled surfaces."""

from __future__ import annotations

import math

import numpy as np
import pytest
from numba import njit
from scipy.spatial import cKDTree

from dmdvox.deposit.primitives import arc_sdf, cap_sdf, segment_sdf
from dmdvox.process.profiles import (
    ARC,
    COSINE,
    ELLIPSE,
    LAME,
    PARABOLA,
    PROFILE_NAMES,
    RECT,
    profile_area,
    profile_sdf,
    revolved_volume,
)

from .test_profiles import boundary_points, ref_inside, ref_top

SEGMENT, CAP, ARC_BEAD = 0, 1, 2


@njit
def _eval_points(which, prm, code, w, h, n, pts, ux, uy, uz, foot):
    d = np.empty(pts.shape[0], np.float64)
    frac = np.empty(pts.shape[0], np.float64)
    for i in range(pts.shape[0]):
        x, y, z = pts[i, 0], pts[i, 1], pts[i, 2]
        if which == SEGMENT:
            d[i], frac[i] = segment_sdf(x, y, z, prm[0], prm[1], prm[2], prm[3], prm[4], prm[5], ux, uy, uz,
                                        code, w, h, n, foot)
        elif which == CAP:
            d[i], frac[i] = cap_sdf(x, y, z, prm[0], prm[1], prm[2], ux, uy, uz, code, w, h, n, foot)
        else:
            d[i], frac[i] = arc_sdf(x, y, z, prm[0], prm[1], prm[2], prm[3], prm[4], prm[5], code, w, h, n, foot)
    return d, frac


def eval_points(which, prm, code, w, h, n, pts, up=(0.0, 0.0, 1.0), foot=0.0):
    """(d, frac) of one primitive at each row of pts; prm holds its geometry, ``up`` the bead's
    up axis, ``foot`` how far its section continues straight down."""
    return _eval_points(which, np.asarray(prm, np.float64), code, w, h, n, np.asarray(pts, np.float64),
                        float(up[0]), float(up[1]), float(up[2]), float(foot))


def grid_centres(lo, hi, step):
    """Cell centres of a grid from lo towards hi."""
    axes = [lo[i] + (np.arange(int((hi[i] - lo[i]) / step) + 1) + 0.5) * step for i in range(3)]
    return np.stack(np.meshgrid(*axes, indexing="ij"), axis=-1).reshape(-1, 3)


@njit
def swept_profile_distance(pts, c, radius, thetas, code, w, h, n):
    """Least distance over the given meridian angles to the profile standing in that plane."""
    out = np.full(pts.shape[0], np.inf)
    for i in range(pts.shape[0]):
        dx, dy, dz = pts[i, 0] - c[0], pts[i, 1] - c[1], pts[i, 2] - c[2]
        for th in thetas:
            q = profile_sdf(code, w, h, n, dx * np.cos(th) + dy * np.sin(th) - radius, dz)
            off = dy * np.cos(th) - dx * np.sin(th)
            out[i] = min(out[i], np.sqrt(max(q, 0.0) ** 2 + off * off))
    return out


def profile_fill(code, w, h, n, spacing):
    """Points filling the profile region on a grid (for sampling flat end faces)."""
    y, z = np.meshgrid(np.arange(-w / 2, w / 2 + spacing, spacing), np.arange(0, h + spacing, spacing))
    y, z = y.ravel(), z.ravel()
    keep = ref_inside(code, w, h, n, y, z)
    return y[keep], z[keep]


def frame(a, b):
    """Travel t, up u (+Z made perpendicular to t) and lateral v of a segment."""
    t = (b - a) / np.linalg.norm(b - a)
    u = np.array([0.0, 0.0, 1.0]) - t[2] * t
    u /= np.linalg.norm(u)
    return t, u, np.cross(t, u)


def check_against_samples(d, pts, surface, inside, tol):
    """Sign vs membership; |d| vs the nearest surface sample (never farther, at most tol nearer)."""
    brute, _ = cKDTree(surface, leafsize=32).query(pts)
    assert np.array_equal(d < 0, inside)
    assert np.all(np.abs(d) <= brute + 1e-9)
    assert np.max(brute - np.abs(d)) < tol
    return brute


BEADS = [(RECT, 4.0), (ELLIPSE, 4.0), (PARABOLA, 4.0), (COSINE, 4.0), (ARC, 4.0), (LAME, 4.0), (LAME, 1.5)]


def bead_id(bead):
    code, n = bead
    return PROFILE_NAMES[code] + (f"-n{n}" if code == LAME else "")


# ---------------------------------------------------------------- segments and caps


@pytest.mark.parametrize("bead", BEADS, ids=bead_id)
def test_segment_with_caps_volume_is_area_times_length_plus_revolved_volume(bead):
    code, n = bead
    w, h = 2.0, 0.8
    a = np.array([0.31, -0.17, 0.4])
    b = a + np.array([3.0, 4.0, 0.0])  # horizontal, length 5, diagonal to the grid
    prm = np.r_[a, b]
    lo = np.array([a[0] - 1.1, a[1] - 1.1, a[2]])
    hi = np.array([b[0] + 1.1, b[1] + 1.1, a[2] + h + 0.05])
    # a whole number of cells in the height, so a flat top does not bias the count
    step = h / 24
    pts = grid_centres(lo, hi, step)
    d = eval_points(SEGMENT, prm, code, w, h, n, pts)[0]
    d = np.minimum(d, eval_points(CAP, a, code, w, h, n, pts)[0])
    d = np.minimum(d, eval_points(CAP, b, code, w, h, n, pts)[0])
    vol = np.count_nonzero(d < 0) * step**3
    expected = profile_area(code, w, h, n) * 5.0 + revolved_volume(code, w, h, n)
    assert vol == pytest.approx(expected, rel=5e-3)


SLANTED = [
    (LAME, 4.0, np.array([0.2, -0.1, 0.3]), np.array([3.0, 1.9, 1.1])),
    (COSINE, 4.0, np.array([0.0, 0.0, 0.0]), np.array([-2.5, 1.0, -0.6])),
    (RECT, 4.0, np.array([1.0, 2.0, 0.5]), np.array([1.0, 5.0, 0.5])),
]


@pytest.mark.parametrize("code, n, a, b", SLANTED, ids=lambda v: PROFILE_NAMES[v] if isinstance(v, int) else "")
def test_segment_matches_sampled_surface_and_membership(code, n, a, b):
    w, h = 2.0, 0.8
    length = np.linalg.norm(b - a)
    t, u, v = frame(a, b)
    # surface samples: the profile outline swept along the segment, plus both filled end faces
    outline = boundary_points(code, w, h, n, 2000)
    s = np.linspace(0, length, int(length / 0.01) + 1)
    side = (a + s[:, None, None] * t + outline[None, :, 0:1] * v + outline[None, :, 1:2] * u).reshape(-1, 3)
    fy, fz = profile_fill(code, w, h, n, 0.01)
    faces = np.vstack([a + fy[:, None] * v + fz[:, None] * u, b + fy[:, None] * v + fz[:, None] * u])
    surface = np.vstack([side, faces])

    rng = np.random.default_rng(3)
    k = 3000
    local = np.c_[rng.uniform(-0.3 * length, 1.3 * length, k), rng.uniform(-1.6, 1.6, k), rng.uniform(-0.5, 1.4, k)]
    pts = a + local[:, 0:1] * t + local[:, 1:2] * v + local[:, 2:3] * u
    d, frac = eval_points(SEGMENT, np.r_[a, b], code, w, h, n, pts)
    inside = ref_inside(code, w, h, n, local[:, 1], local[:, 2]) & (local[:, 0] >= 0) & (local[:, 0] <= length)
    check_against_samples(d, pts, surface, inside, tol=0.012)
    np.testing.assert_allclose(frac, np.clip(local[:, 0] / length, 0, 1), atol=1e-12)


def test_segment_frac_is_monotone_and_spans_the_path():
    a, b = np.array([1.0, 1.0, 0.2]), np.array([-2.0, 5.0, 0.7])
    s = np.linspace(-0.2, 1.2, 301)
    pts = a + s[:, None] * (b - a) + 0.3 * frame(a, b)[1]
    d, frac = eval_points(SEGMENT, np.r_[a, b], LAME, 2.0, 0.8, 4.0, pts)
    assert np.all(np.diff(frac) >= 0) and frac[0] == 0.0 and frac[-1] == 1.0
    assert np.all(np.diff(frac[(s > 0) & (s < 1)]) > 0)


def test_cap_is_the_revolved_profile_and_zero_length_segment_is_the_cap():
    rng = np.random.default_rng(8)
    c = np.array([0.5, -0.25, 1.0])
    pts = c + rng.uniform(-2, 2, (500, 3))
    d_cap, f_cap = eval_points(CAP, c, ELLIPSE, 2.0, 0.8, 4.0, pts)
    r = np.hypot(pts[:, 0] - c[0], pts[:, 1] - c[1])
    expected = [profile_sdf(ELLIPSE, 2.0, 0.8, 4.0, ri, zi) for ri, zi in zip(r, pts[:, 2] - c[2])]
    np.testing.assert_allclose(d_cap, expected, rtol=0, atol=1e-12)
    assert np.all(f_cap == 0.0)
    d_seg, _ = eval_points(SEGMENT, np.r_[c, c], ELLIPSE, 2.0, 0.8, 4.0, pts)
    np.testing.assert_array_equal(d_seg, d_cap)


@pytest.mark.parametrize("code, n", [(LAME, 4.0), (RECT, 4.0), (PARABOLA, 4.0)], ids=["lame", "rect", "parabola"])
@pytest.mark.parametrize("downward", [False, True], ids=["up", "down"])
def test_near_vertical_segment_is_the_cap_swept_up(code, n, downward):
    w, h, rise = 2.0, 0.8, 2.5
    a = np.array([0.4, 0.3, 1.0])
    b = a + np.array([0.03, -0.02, rise])  # |t_z| = 0.99989
    if downward:
        a, b = b, a
    base, axis = min(a[2], b[2]), a[:2]
    # meridian section: P standing on a rise-high rectangle; its outline revolved about the axis
    outline = boundary_points(code, w, h, n, 2000)
    outline = outline[outline[:, 0] >= 0]
    top = outline[outline[:, 1] > 0] + np.array([0.0, rise])
    side = np.c_[np.full(400, w / 2), np.linspace(0, rise, 400)]
    bottom = np.c_[np.linspace(0, w / 2, 200), np.zeros(200)]
    section = np.vstack([top, side, bottom])
    phi = np.linspace(0, 2 * np.pi, 700, endpoint=False)
    surface = np.c_[
        (axis[0] + section[:, 0:1] * np.cos(phi)).ravel(),
        (axis[1] + section[:, 0:1] * np.sin(phi)).ravel(),
        np.repeat(base + section[:, 1], phi.size),
    ]

    rng = np.random.default_rng(11)
    k = 3000
    pts = np.c_[axis[0] + rng.uniform(-2, 2, k), axis[1] + rng.uniform(-2, 2, k), base + rng.uniform(-1, rise + 2, k)]
    d, frac = eval_points(SEGMENT, np.r_[a, b], code, w, h, n, pts)
    r = np.hypot(pts[:, 0] - axis[0], pts[:, 1] - axis[1])
    zz = pts[:, 2] - base
    inside = (r <= w / 2) & (zz >= 0) & (zz <= rise + ref_top(code, w, h, n, r))
    check_against_samples(d, pts, surface, inside, tol=0.012)
    along = (pts - a) @ ((b - a) / np.linalg.norm(b - a))
    np.testing.assert_allclose(frac, np.clip(along / np.linalg.norm(b - a), 0, 1), atol=1e-12)


# ---------------------------------------------------------------- arcs


PAPPUS = [(bead, (3.0, 0.4, 1.9)) for bead in BEADS] + [
    ((LAME, 4.0), (1.0, -2.0, -np.pi)),
    ((LAME, 4.0), (2.0, 1.0, 2 * np.pi)),
    ((ELLIPSE, 4.0), (1.5, -0.3, -2 * np.pi)),
]


@pytest.mark.parametrize("bead, arc", PAPPUS, ids=lambda v: bead_id(v) if isinstance(v[0], int) else "r{}-s{:.2f}".format(v[0], v[2]))
def test_arc_volume_follows_pappus(bead, arc):
    code, n = bead
    radius, theta0, sweep = arc
    w, h = 2.0, 0.8
    c = np.array([0.13, -0.27, 0.5])
    reach = radius + w / 2 + 0.05
    lo = np.array([c[0] - reach, c[1] - reach, c[2]])
    hi = np.array([c[0] + reach, c[1] + reach, c[2] + h + 0.05])
    step = h / 24
    d = eval_points(ARC_BEAD, np.r_[c, radius, theta0, sweep], code, w, h, n, grid_centres(lo, hi, step))[0]
    vol = np.count_nonzero(d < 0) * step**3
    assert vol == pytest.approx(profile_area(code, w, h, n) * radius * abs(sweep), rel=5e-3)


def arc_membership(code, w, h, n, c, radius, theta0, sweep, pts):
    """The swept solid by definition: the profile centred at `radius` in each swept meridian
    plane (both sides of the axis when it crosses it)."""
    dx, dy, z = pts[:, 0] - c[0], pts[:, 1] - c[1], pts[:, 2] - c[2]
    rho = np.hypot(dx, dy)
    travelled = (np.sign(sweep) * (np.arctan2(dy, dx) - theta0)) % (2 * np.pi)
    near = (travelled <= abs(sweep)) & ref_inside(code, w, h, n, rho - radius, z)
    far = (((travelled + np.pi) % (2 * np.pi)) <= abs(sweep)) & ref_inside(code, w, h, n, rho + radius, z)
    return near | far


@pytest.mark.parametrize("code, n, sweep", [(LAME, 4.0, 2.0), (PARABOLA, 4.0, -4.0), (ELLIPSE, 4.0, 7.0)],
                         ids=["lame-ccw", "parabola-cw-wide", "ellipse-full-turn"])
def test_arc_matches_sampled_surface_and_membership(code, n, sweep):
    w, h, radius, theta0 = 2.0, 0.8, 2.5, 0.7
    c = np.array([-0.4, 0.9, 0.25])
    outline = boundary_points(code, w, h, n, 1000)
    span = min(abs(sweep), 2 * np.pi)
    theta = theta0 + np.sign(sweep) * np.linspace(0, span, int(span * (radius + w / 2) / 0.02) + 1)
    rr = radius + outline[:, 0]
    side = np.c_[
        (c[0] + rr[None, :] * np.cos(theta)[:, None]).ravel(),
        (c[1] + rr[None, :] * np.sin(theta)[:, None]).ravel(),
        np.tile(c[2] + outline[:, 1], theta.size),
    ]
    parts = [side]
    if abs(sweep) < 2 * np.pi:
        fy, fz = profile_fill(code, w, h, n, 0.01)
        for th in (theta0, theta0 + sweep):
            parts.append(np.c_[c[0] + (radius + fy) * np.cos(th), c[1] + (radius + fy) * np.sin(th), c[2] + fz])
    surface = np.vstack(parts)

    rng = np.random.default_rng(21)
    k = 3000
    rho = rng.uniform(0, radius + 2.0, k)
    ang = rng.uniform(0, 2 * np.pi, k)
    pts = np.c_[c[0] + rho * np.cos(ang), c[1] + rho * np.sin(ang), c[2] + rng.uniform(-0.6, 1.4, k)]
    d, _ = eval_points(ARC_BEAD, np.r_[c, radius, theta0, sweep], code, w, h, n, pts)
    inside = arc_membership(code, w, h, n, c, radius, theta0, sweep, pts)
    check_against_samples(d, pts, surface, inside, tol=0.015)


@pytest.mark.parametrize("sweep", [2.5, -2.5, 5.0, 2 * np.pi])
def test_arc_crossing_its_axis_has_exact_sign_and_exact_outside_distance(sweep):
    code, n, w, h = LAME, 4.0, 2.0, 0.8
    radius, theta0 = 0.4, 0.3
    c = np.array([0.0, 0.0, 0.0])
    rng = np.random.default_rng(2)
    k = 1500
    pts = np.c_[rng.uniform(-2.2, 2.2, k), rng.uniform(-2.2, 2.2, k), rng.uniform(-0.5, 1.3, k)]
    d, _ = eval_points(ARC_BEAD, np.r_[c, radius, theta0, sweep], code, w, h, n, pts)
    inside = arc_membership(code, w, h, n, c, radius, theta0, sweep, pts)
    assert np.array_equal(d < 0, inside)
    # outside: brute-force minimum over the swept meridian planes of the distance to the
    # profile standing in each (in-plane by the 2-D distance, tested on its own; off-plane exact)
    outside = ~inside
    thetas = theta0 + np.sign(sweep) * np.linspace(0, min(abs(sweep), 2 * np.pi), 2001)
    best = swept_profile_distance(pts[outside], c, radius, thetas, code, w, h, n)
    assert np.all(d[outside] <= best + 1e-9)
    assert np.max(best - d[outside]) < 2e-3
    # inside the depth is a lower bound: never deeper than the nearest outside point
    nearest_outside, _ = cKDTree(pts[outside]).query(pts[inside])
    assert np.all(-d[inside] <= nearest_outside)


@pytest.mark.parametrize("theta0, sweep", [(0.5, 2.0), (0.5, -2.0), (-1.0, 9.0)])
def test_arc_frac_is_monotone_along_the_path(theta0, sweep):
    radius, c = 3.0, np.array([1.0, 2.0, 0.0])
    s = (np.arange(400) + 0.5) / 400
    th = theta0 + s * sweep
    pts = np.c_[c[0] + radius * np.cos(th), c[1] + radius * np.sin(th), np.full(s.size, 0.3)]
    d, frac = eval_points(ARC_BEAD, np.r_[c, radius, theta0, sweep], COSINE, 2.0, 0.8, 4.0, pts)
    assert np.all(d < 0)
    if abs(sweep) <= 2 * np.pi:
        np.testing.assert_allclose(frac, s, atol=1e-12)
    else:
        # multi-turn: the first pass over each meridian lays the material
        first = s * abs(sweep) < 2 * np.pi
        np.testing.assert_allclose(frac[first], s[first], atol=1e-12)
    assert np.all(np.diff(frac[s * abs(sweep) < 2 * np.pi]) > 0)
    # beyond the ends: the nearer end's parameter
    end = theta0 + sweep + np.sign(sweep) * 0.2
    start = theta0 - np.sign(sweep) * 0.2
    outside = np.array([[c[0] + radius * np.cos(x), c[1] + radius * np.sin(x), 0.3] for x in (start, end)])
    _, f = eval_points(ARC_BEAD, np.r_[c, radius, theta0, sweep], COSINE, 2.0, 0.8, 4.0, outside)
    if abs(sweep) < 2 * np.pi:
        assert list(f) == [0.0, 1.0]


def test_arc_end_face_distance_matches_a_straight_segment_end():
    # beyond an end, the arc's end face acts like a segment's flat end in that plane
    w, h, radius = 2.0, 0.8, 3.0
    c = np.zeros(3)
    p = np.array([[radius + 0.3, -0.5, 0.4]])  # 0.5 mm behind the start plane (theta0 = 0)
    d, f = eval_points(ARC_BEAD, np.r_[c, radius, 0.0, 1.0], RECT, w, h, 4.0, p)
    assert d[0] == pytest.approx(0.5, abs=1e-12) and f[0] == 0.0
    p = np.array([[radius + 1.3, -0.5, 0.4]])  # also 0.3 mm beyond the outer side
    d, _ = eval_points(ARC_BEAD, np.r_[c, radius, 0.0, 1.0], RECT, w, h, 4.0, p)
    assert d[0] == pytest.approx(math.hypot(0.3, 0.5), abs=1e-12)


# ---------------------------------------------------------------- feet and tilted up axes


def _rotation(axis, angle):
    axis = np.asarray(axis, float) / np.linalg.norm(axis)
    k = np.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]])
    return np.eye(3) + np.sin(angle) * k + (1 - np.cos(angle)) * k @ k


@pytest.mark.parametrize("code, n", [(RECT, 4.0), (PARABOLA, 4.0), (LAME, 4.0)], ids=["rect", "parabola", "lame"])
def test_footed_segment_matches_sampled_surface_and_membership(code, n):
    # the section is the profile on top of a w x foot rectangle: its outline is the top curve,
    # the two sides down to -foot and the bottom at -foot
    w, h, foot = 2.0, 0.8, 0.5
    a, b = np.array([0.2, -0.1, 0.3]), np.array([3.0, 1.9, 0.3])
    length = np.linalg.norm(b - a)
    t, u, v = frame(a, b)
    outline = boundary_points(code, w, h, n, 2000)
    outline = outline[outline[:, 1] > 1e-12]
    sides = np.vstack([np.c_[np.full(300, s * w / 2), np.linspace(-foot, 0, 300)] for s in (-1, 1)])
    bottom = np.c_[np.linspace(-w / 2, w / 2, 600), np.full(600, -foot)]
    section = np.vstack([outline, sides, bottom])
    steps = np.linspace(0, length, int(length / 0.01) + 1)
    side = (a + steps[:, None, None] * t + section[None, :, 0:1] * v + section[None, :, 1:2] * u).reshape(-1, 3)
    fy, fz = profile_fill(code, w, h, n, 0.01)
    ry, rz = np.meshgrid(np.arange(-w / 2, w / 2 + 0.01, 0.01), np.arange(-foot, 0, 0.01))
    fy, fz = np.r_[fy, ry.ravel()], np.r_[fz, rz.ravel()]
    faces = np.vstack([a + fy[:, None] * v + fz[:, None] * u, b + fy[:, None] * v + fz[:, None] * u])
    surface = np.vstack([side, faces])
    rng = np.random.default_rng(21)
    k = 3000
    local = np.c_[rng.uniform(-0.3 * length, 1.3 * length, k), rng.uniform(-1.6, 1.6, k),
                  rng.uniform(-foot - 0.5, 1.4, k)]
    pts = a + local[:, 0:1] * t + local[:, 1:2] * v + local[:, 2:3] * u
    d, _ = eval_points(SEGMENT, np.r_[a, b], code, w, h, n, pts, foot=foot)
    in_section = (ref_inside(code, w, h, n, local[:, 1], local[:, 2])
                  | ((np.abs(local[:, 1]) <= w / 2) & (local[:, 2] >= -foot) & (local[:, 2] <= 0)))
    inside = in_section & (local[:, 0] >= 0) & (local[:, 0] <= length)
    check_against_samples(d, pts, surface, inside, tol=0.012)


@pytest.mark.parametrize("bead", BEADS[:4], ids=bead_id)
def test_footed_cap_volume_is_the_revolved_section(bead):
    code, n = bead
    w, h, foot = 2.0, 0.8, 0.4
    c = np.array([0.13, -0.21, 0.4])
    step = h / 24  # the foot's bottom and the top fall on cell boundaries: a flat face is not biased
    pts = grid_centres(c - [1.1, 1.1, foot], c + [1.1, 1.1, h + 0.05], step)
    d = eval_points(CAP, c, code, w, h, n, pts, foot=foot)[0]
    expected = revolved_volume(code, w, h, n) + np.pi * (w / 2) ** 2 * foot
    assert np.count_nonzero(d < 0) * step**3 == pytest.approx(expected, rel=5e-3)


@pytest.mark.parametrize("which", [SEGMENT, CAP])
@pytest.mark.parametrize("foot", [0.0, 0.3])
def test_tilted_bead_is_the_upright_one_rotated(which, foot):
    # A bead whose up axis is R e_z is the upright bead turned by R: distances are invariant.
    rot = _rotation([0.3, -1.0, 0.4], 1.1)
    a, b = np.array([0.2, -0.1, 0.3]), np.array([2.5, 1.4, 0.9])
    rng = np.random.default_rng(4)
    pts = a + rng.uniform(-2.5, 3.5, (2000, 3))
    prm = np.r_[a, b] if which == SEGMENT else a
    d_up, f_up = eval_points(which, prm, PARABOLA, 2.0, 0.8, 4.0, pts, foot=foot)
    turned = np.r_[rot @ a, rot @ b] if which == SEGMENT else rot @ a
    d_tilt, f_tilt = eval_points(which, turned, PARABOLA, 2.0, 0.8, 4.0, pts @ rot.T, up=rot @ [0, 0, 1], foot=foot)
    np.testing.assert_allclose(d_tilt, d_up, atol=1e-9)
    np.testing.assert_allclose(f_tilt, f_up, atol=1e-9)
