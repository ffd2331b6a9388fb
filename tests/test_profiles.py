"""Bead cross-section profiles: closed forms against quadrature, signed distance against brute force."""

from __future__ import annotations

import math

import numpy as np
import pytest
from numba import njit
from scipy.integrate import quad
from scipy.spatial import cKDTree

from dmdvox.process.profiles import (
    ARC,
    COSINE,
    ELLIPSE,
    LAME,
    PARABOLA,
    PROFILE_NAMES,
    RECT,
    BeadProfile,
    profile_area,
    profile_code,
    profile_name,
    profile_sdf,
    profile_top,
    revolved_volume,
)
from dmdvox.errors import DmdvoxError

# (code, w, h, n): every shape, flat and tall; Lame across its regimes (cusped n < 1, straight
# n = 1, pointed 1 < n < 2, ellipse n = 2, squarish n > 2)
CASES = [
    (RECT, 2.5, 0.8, 4.0),
    (RECT, 1.0, 2.0, 4.0),
    (ELLIPSE, 2.5, 0.8, 4.0),
    (ELLIPSE, 1.0, 2.0, 4.0),
    (PARABOLA, 2.5, 0.8, 4.0),
    (PARABOLA, 1.0, 2.0, 4.0),
    (COSINE, 2.5, 0.8, 4.0),
    (COSINE, 1.0, 2.0, 4.0),
    (ARC, 2.5, 0.8, 4.0),
    (ARC, 2.0, 1.0, 4.0),
    (ARC, 3.0, 0.1, 4.0),
    (LAME, 2.5, 0.8, 0.5),
    (LAME, 2.0, 1.5, 0.8),
    (LAME, 2.5, 0.8, 1.0),
    (LAME, 2.0, 0.6, 1.4),
    (LAME, 2.5, 0.8, 2.0),
    (LAME, 2.5, 0.8, 4.0),
    (LAME, 1.0, 1.0, 4.0),
    (LAME, 2.0, 0.3, 10.0),
    (LAME, 1.0, 3.0, 30.0),
]


def case_id(case):
    code, w, h, n = case
    return f"{PROFILE_NAMES[code]}-w{w}-h{h}" + (f"-n{n}" if code == LAME else "")


def ref_top(code, w, h, n, y):
    """Top height straight from the shape definitions (numpy, independent of the module)."""
    a = w / 2
    y = np.abs(np.asarray(y, dtype=np.float64))
    t = np.minimum(y / a, 1.0)
    if code == RECT:
        top = np.full_like(t, h)
    elif code == ELLIPSE:
        top = h * np.sqrt(1 - t**2)
    elif code == PARABOLA:
        top = h * (1 - 4 * y**2 / w**2)
    elif code == COSINE:
        top = h * np.cos(np.pi * y / w)
    elif code == ARC:
        r = (w**2 / 4 + h**2) / (2 * h)
        top = (h - r) + np.sqrt(np.maximum(r**2 - y**2, 0.0))
    else:
        top = h * np.maximum(1 - t**n, 0.0) ** (1 / n)
    return np.where(y <= a, np.maximum(top, 0.0), 0.0)


def ref_half_width(code, w, h, n, z):
    """Inverse of the top curve: the |y| where the top is at height z (0 <= z <= h)."""
    a = w / 2
    s = np.clip(z / h, 0.0, 1.0)
    if code == RECT:
        return np.full_like(s, a)
    if code == ELLIPSE:
        return a * np.sqrt(1 - s**2)
    if code == PARABOLA:
        return a * np.sqrt(1 - s)
    if code == COSINE:
        return w / np.pi * np.arccos(s)
    if code == ARC:
        r = (w**2 / 4 + h**2) / (2 * h)
        return np.sqrt(np.maximum(r**2 - (z - (h - r)) ** 2, 0.0))
    return a * np.maximum(1 - s**n, 0.0) ** (1 / n)


def boundary_points(code, w, h, n, m=200_000):
    """~m points on the boundary; the top curve sampled evenly in y and in z so steep parts are dense."""
    a = w / 2
    k = m // 4
    y = np.linspace(-a, a, k)
    z = np.linspace(0.0, h, k)
    yz = ref_half_width(code, w, h, n, z)
    return np.vstack([np.c_[y, np.zeros(k)], np.c_[y, ref_top(code, w, h, n, y)], np.c_[yz, z], np.c_[-yz, z]])


def ref_inside(code, w, h, n, y, z):
    return (np.abs(y) <= w / 2) & (z >= 0) & (z <= ref_top(code, w, h, n, y))


@njit
def sdf_many(code, w, h, n, ys, zs):
    out = np.empty(ys.size, np.float64)
    for i in range(ys.size):
        out[i] = profile_sdf(code, w, h, n, ys[i], zs[i])
    return out


def probe_points(w, h, rng, k=3000):
    """Random points: around the bead, far away, near the corners, near and on the axis, below."""
    a = w / 2
    ys = np.concatenate([
        rng.uniform(-1.4 * a, 1.4 * a, k),
        rng.uniform(-8 * a, 8 * a, k // 4),
        a + rng.normal(0, 0.02 * w, k // 4),
        rng.normal(0, 0.01 * w, k // 4),
        np.zeros(k // 8),
        rng.uniform(-1.4 * a, 1.4 * a, k // 8),
    ])
    zs = np.concatenate([
        rng.uniform(-0.3 * h, 1.3 * h, k),
        rng.uniform(-8 * h, 8 * h, k // 4),
        rng.normal(0, 0.02 * w, k // 4),
        rng.uniform(-0.2 * h, 1.2 * h, k // 4),
        rng.uniform(-0.2 * h, 1.3 * h, k // 8),
        rng.uniform(-2 * h, 0.0, k // 8),
    ])
    return ys, zs


# ---------------------------------------------------------------- names, validation


def test_names_and_codes_round_trip():
    assert PROFILE_NAMES == ("rect", "ellipse", "parabola", "cosine", "arc", "lame")
    for code, name in enumerate(PROFILE_NAMES):
        assert profile_code(name) == code
        assert profile_name(code) == name
    with pytest.raises(DmdvoxError, match="profile: unknown bead profile 'triangle'") as caught:
        profile_code("triangle")
    assert caught.value.parameter == "profile"
    with pytest.raises(DmdvoxError):
        profile_name(6)


@pytest.mark.parametrize(
    "kwargs, field",
    [
        (dict(name="blob", width=2.0, height=1.0), "--profile"),
        (dict(name="rect", width=0.0, height=1.0), "--width"),
        (dict(name="rect", width=-1.0, height=1.0), "--width"),
        (dict(name="rect", width=math.nan, height=1.0), "--width"),
        (dict(name="rect", width="wide", height=1.0), "--width"),
        (dict(name="ellipse", width=2.0, height=math.inf), "--height"),
        (dict(name="ellipse", width=2.0, height=0.0), "--height"),
        (dict(name="arc", width=2.0, height=1.01), "--height"),
        (dict(name="lame", width=2.0, height=1.0, exponent=0.0), "--exponent"),
        (dict(name="lame", width=2.0, height=1.0, exponent=math.nan), "--exponent"),
    ],
)
def test_bead_profile_rejects_bad_values_naming_the_option(kwargs, field):
    """The library names the field; the command line's table turns it into the option."""
    from dmdvox.cli import OPTION_OF_PARAMETER

    with pytest.raises(DmdvoxError) as caught:
        BeadProfile(**kwargs)
    assert caught.value.parameter in str(caught.value)
    assert OPTION_OF_PARAMETER[caught.value.parameter] == field


def test_messages_say_what_is_allowed():
    with pytest.raises(DmdvoxError, match="rect, ellipse, parabola, cosine, arc, lame"):
        BeadProfile("blob", 2.0, 1.0)
    with pytest.raises(DmdvoxError, match=r"height <= width/2"):
        BeadProfile("arc", 2.0, 1.5)
    with pytest.raises(DmdvoxError, match="height <= width/2"):
        profile_area(ARC, 2.0, 1.5, 4.0)


def test_bead_profile_properties():
    b = BeadProfile("parabola", 3, 1)
    assert b.code == PARABOLA and isinstance(b.width, float)
    assert b.half_width == 1.5 and b.max_height == 1.0
    assert b.area == pytest.approx(2.0, rel=1e-15)
    assert b.revolved_volume == pytest.approx(math.pi * 9 / 8, rel=1e-15)
    with pytest.raises(AttributeError):
        b.width = 2.0  # frozen
    assert BeadProfile("arc", 2.0, 1.0).area == pytest.approx(math.pi / 2, rel=1e-12)  # half disc


# ---------------------------------------------------------------- areas and volumes


@pytest.mark.parametrize("case", CASES, ids=case_id)
def test_area_and_revolved_volume_match_quadrature(case):
    code, w, h, n = case
    a = w / 2

    def top(y):
        return float(ref_top(code, w, h, n, y))

    # break the range where the Lame and arc curves have infinite slope or curvature
    points = [a * 0.5 ** (1 / n), a * 0.999] if code == LAME else None
    area = 2 * quad(top, 0, a, points=points, limit=400, epsabs=0, epsrel=1e-12)[0]
    vol = 2 * math.pi * quad(lambda y: y * top(y), 0, a, points=points, limit=400, epsabs=0, epsrel=1e-12)[0]
    assert profile_area(code, w, h, n) == pytest.approx(area, rel=1e-6)
    assert revolved_volume(code, w, h, n) == pytest.approx(vol, rel=1e-6)


def test_closed_forms_from_the_brief():
    w, h = 2.4, 0.7
    assert profile_area(RECT, w, h, 4) == pytest.approx(w * h)
    assert profile_area(ELLIPSE, w, h, 4) == pytest.approx(math.pi * w * h / 4)
    assert profile_area(COSINE, w, h, 4) == pytest.approx(2 * w * h / math.pi)
    assert revolved_volume(RECT, w, h, 4) == pytest.approx(math.pi * (w / 2) ** 2 * h)
    assert revolved_volume(PARABOLA, w, h, 4) == pytest.approx(math.pi * h * w**2 / 8)
    # Lame: n = 2 is the ellipse, large n tends to the rectangle
    assert profile_area(LAME, w, h, 2.0) == pytest.approx(profile_area(ELLIPSE, w, h, 4), rel=1e-14)
    assert revolved_volume(LAME, w, h, 2.0) == pytest.approx(revolved_volume(ELLIPSE, w, h, 4), rel=1e-14)
    assert profile_area(LAME, w, h, 1e4) == pytest.approx(w * h, rel=1e-3)


@pytest.mark.parametrize("case", CASES, ids=case_id)
def test_profile_top_matches_definition(case):
    code, w, h, n = case
    ys = np.linspace(-0.6 * w, 0.6 * w, 1001)
    got = np.array([profile_top(code, w, h, n, y) for y in ys])
    np.testing.assert_allclose(got, ref_top(code, w, h, n, ys), rtol=0, atol=1e-12 * h)


# ---------------------------------------------------------------- signed distance


@pytest.mark.parametrize("case", CASES, ids=case_id)
def test_sdf_sign_and_distance_match_brute_force(case):
    code, w, h, n = case
    rng = np.random.default_rng(17 + code)
    ys, zs = probe_points(w, h, rng)
    d = sdf_many(code, w, h, n, ys, zs)
    brute, _ = cKDTree(boundary_points(code, w, h, n), leafsize=32).query(np.c_[ys, zs])

    # sign: against membership, away from points within rounding of the boundary
    clear = brute > 1e-4 * w
    inside = ref_inside(code, w, h, n, ys, zs)
    assert clear.sum() > 0.9 * ys.size
    assert np.array_equal((d < 0)[clear], inside[clear])
    # distance: within 1e-3 w of the sampled boundary (which is ~1e-5 w dense), and never
    # farther than a sampled boundary point -- a solver stuck in a local minimum would be
    assert np.max(np.abs(np.abs(d) - brute)) < 1e-3 * w
    assert np.max(np.abs(d) - brute) < 1e-9 * w


@pytest.mark.parametrize("case", CASES, ids=case_id)
def test_sdf_is_zero_on_the_boundary(case):
    code, w, h, n = case
    rng = np.random.default_rng(5)
    a = w / 2
    y = rng.uniform(-a, a, 500)
    z = rng.uniform(0, h, 500)
    ys = np.concatenate([y, y, ref_half_width(code, w, h, n, z), [a, -a, 0.0]])
    zs = np.concatenate([np.zeros_like(y), ref_top(code, w, h, n, y), z, [0.0, 0.0, ref_top(code, w, h, n, 0.0)]])
    d = sdf_many(code, w, h, n, ys, zs)
    assert np.max(np.abs(d)) < 1e-9 * w


def test_sdf_known_values():
    # rect: inside depth to the nearest side, outside corner distance
    assert profile_sdf(RECT, 2.0, 1.0, 4.0, 0.9, 0.5) == pytest.approx(-0.1)
    assert profile_sdf(RECT, 2.0, 1.0, 4.0, 4.0, 5.0) == pytest.approx(5.0)
    # semicircle of radius 1: distance is | |p| - 1 | above the base
    for code in (ELLIPSE, ARC):
        assert profile_sdf(code, 2.0, 1.0, 4.0, 0.6, 0.6) == pytest.approx(math.hypot(0.6, 0.6) - 1, abs=1e-12)
        assert profile_sdf(code, 2.0, 1.0, 4.0, 3.0, 4.0) == pytest.approx(4.0, abs=1e-12)
    # a tall parabola: on the axis below the centre of curvature of the vertex the nearest
    # points are off the axis, not the vertex
    w, h, z = 1.0, 2.0, 1.0
    d = profile_sdf(PARABOLA, w, h, 4.0, 0.0, z)
    t = np.linspace(0, w / 2, 2_000_001)
    assert -d == pytest.approx(np.min(np.hypot(t, h * (1 - 4 * t**2 / w**2) - z)), abs=1e-9)
    assert -d < h - z - 0.1
    # symmetric in y; Lame n = 2 is exactly the ellipse
    for y, z in [(0.3, 0.2), (-1.7, 0.4), (0.1, 3.0)]:
        assert profile_sdf(LAME, 2.5, 0.8, 3.0, y, z) == profile_sdf(LAME, 2.5, 0.8, 3.0, -y, z)
        assert profile_sdf(LAME, 2.5, 0.8, 2.0, y, z) == pytest.approx(profile_sdf(ELLIPSE, 2.5, 0.8, 4.0, y, z), abs=1e-12)
