"""Bead cross-section profiles: shape codes, areas, volumes and the exact 2-D signed distance.

A cross-section of width ``w`` and height ``h`` stands on its path point. Local coordinates:
``y`` lateral (signed), ``z`` up, ``z = 0`` the bead bottom. The region is
``P = {|y| <= w/2, 0 <= z <= top(y)}``; its boundary is the base segment plus the top curve,
which meets the base at the corners ``(+-w/2, 0)`` (for ``rect`` the top "curve" is the two
sides and the flat top).

:func:`profile_sdf` is the Euclidean signed distance to that boundary, negative inside. It is
exact in closed form for ``rect``, ``arc`` and ``lame`` with n = 1; for the other shapes the
nearest point on the top curve is found by a bracketed Newton iteration to ~1e-12 of the bead
size. The bracket comes from a geometric fact valid for every decreasing top curve (see
:func:`_piece_dist2`), so the iteration never has to search the whole curve.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from numba import njit

from ..errors import DmdvoxError

RECT = 0
ELLIPSE = 1
PARABOLA = 2
COSINE = 3
ARC = 4
LAME = 5

PROFILE_NAMES = ("rect", "ellipse", "parabola", "cosine", "arc", "lame")
PROFILE_CODES = {name: code for code, name in enumerate(PROFILE_NAMES)}

_HALF_PI = 0.5 * math.pi
_NEWTON_MAX_ITER = 100
# Newton stops when the foot point moves less than this fraction of the bead size; the
# distance error is quadratic in the foot error (the distance is stationary there).
_NEWTON_TOL = 1e-12
_SAMPLES = 8
_FOLD_NEVER = 0
_FOLD_BELOW = 1
_FOLD_ABOVE = 2


def profile_code(name: str) -> int:
    """The integer code of a profile name (``PROFILE_NAMES``)."""
    try:
        return PROFILE_CODES[name]
    except (KeyError, TypeError):
        raise DmdvoxError(
            f"--profile: unknown bead profile {name!r}; choose one of {', '.join(PROFILE_NAMES)}"
        ) from None


def profile_name(code: int) -> str:
    """The name of a profile code."""
    if not isinstance(code, int) or isinstance(code, bool) or not 0 <= code < len(PROFILE_NAMES):
        raise DmdvoxError(f"unknown bead profile code {code!r}; valid codes are 0..{len(PROFILE_NAMES) - 1}")
    return PROFILE_NAMES[code]


def _positive_mm(value, option: str) -> float:
    try:
        x = float(value)
    except (TypeError, ValueError):
        raise DmdvoxError(f"{option} must be a positive length in mm, got {value!r}") from None
    if isinstance(value, bool) or not math.isfinite(x) or x <= 0.0:
        raise DmdvoxError(f"{option} must be a positive finite length in mm, got {value!r}")
    return x


def _check(code: int, w: float, h: float, n: float) -> tuple[float, float, float]:
    """Validated (w, h, n) as floats; raises DmdvoxError naming the option to fix."""
    profile_name(code)
    w = _positive_mm(w, "--width")
    h = _positive_mm(h, "--height")
    try:
        n_f = float(n)
    except (TypeError, ValueError):
        raise DmdvoxError(f"--exponent must be a positive number (lame profile), got {n!r}") from None
    if isinstance(n, bool) or not math.isfinite(n_f) or n_f <= 0.0:
        raise DmdvoxError(
            f"--exponent must be a positive finite number (lame profile: 2 is an ellipse, larger is "
            f"squarer), got {n!r}"
        )
    if code == ARC and h > 0.5 * w:
        raise DmdvoxError(
            f"--height: an arc profile needs height <= width/2 (got height {h:g} mm for width {w:g} mm); "
            f"lower --height, widen --width, or use the ellipse profile for taller beads"
        )
    return w, h, n_f


def profile_area(code: int, w: float, h: float, n: float = 4.0) -> float:
    """Cross-section area in mm^2."""
    w, h, n = _check(code, w, h, n)
    if code == RECT:
        return w * h
    if code == ELLIPSE:
        return 0.25 * math.pi * w * h
    if code == PARABOLA:
        return 2.0 * w * h / 3.0
    if code == COSINE:
        return 2.0 * w * h / math.pi
    if code == ARC:
        a = 0.5 * w
        r = (a * a + h * h) / (2.0 * h)
        # circular segment: sector minus the triangle under the chord
        return r * r * math.acos((r - h) / r) - (r - h) * a
    # quarter of the unit superellipse: Gamma(1+1/n)^2 / Gamma(1+2/n); lgamma avoids overflow
    return w * h * math.exp(2.0 * math.lgamma(1.0 + 1.0 / n) - math.lgamma(1.0 + 2.0 / n))


def revolved_volume(code: int, w: float, h: float, n: float = 4.0) -> float:
    """Volume (mm^3) of the profile revolved about its vertical axis: 2*pi*int_0^{w/2} y top(y) dy."""
    w, h, n = _check(code, w, h, n)
    a = 0.5 * w
    if code == RECT:
        return math.pi * a * a * h
    if code == ELLIPSE:
        return 2.0 * math.pi * a * a * h / 3.0
    if code == PARABOLA:
        return 0.5 * math.pi * a * a * h
    if code == COSINE:
        return 4.0 * a * a * h * (1.0 - 2.0 / math.pi)
    if code == ARC:
        r = (a * a + h * h) / (2.0 * h)
        return math.pi * h * h * (3.0 * r - h) / 3.0  # spherical cap
    # int_0^1 t (1 - t^n)^(1/n) dt = Gamma(1+2/n) Gamma(1+1/n) / (2 Gamma(1+3/n))
    g = math.lgamma(1.0 + 2.0 / n) + math.lgamma(1.0 + 1.0 / n) - math.lgamma(1.0 + 3.0 / n)
    return math.pi * a * a * h * math.exp(g)


@njit(cache=True)
def _lame_f(t, n):
    """Normalised Lame top curve Z = (1 - t^n)^(1/n) for 0 <= t <= 1."""
    u = 1.0 - t**n
    if u <= 0.0:
        return 0.0
    return u ** (1.0 / n)


@njit(cache=True)
def profile_top(code, w, h, n, y):
    """Top height of the profile at lateral position ``y``; 0 outside ``|y| > w/2``."""
    a = 0.5 * w
    t = abs(y) / a
    if t > 1.0:
        return 0.0
    if code == RECT:
        return h
    if code == ELLIPSE:
        return h * math.sqrt(1.0 - t * t)
    if code == PARABOLA:
        return h * (1.0 - t * t)
    if code == COSINE:
        return h * math.cos(_HALF_PI * t)
    if code == ARC:
        r = (a * a + h * h) / (2.0 * h)
        yy = a * t
        return max((h - r) + math.sqrt(r * r - yy * yy), 0.0)
    return h * _lame_f(t, n)


@njit(cache=True)
def _shape(kind, t, n):
    """F, F', F'' of the normalised top curve Z = F(Y) at Y = t, for the graph-type kinds.

    Lame pieces keep away from the point where F' or F'' is singular for their exponent (see
    :func:`_curve_dist2`), except the vertex t = 0 for 1 < n < 2, where the curvature really
    is infinite and F'' = -inf only makes Newton fall back to bisection.
    """
    if kind == PARABOLA:
        return 1.0 - t * t, -2.0 * t, -2.0
    if kind == COSINE:
        s = math.sin(_HALF_PI * t)
        c = math.cos(_HALF_PI * t)
        return c, -_HALF_PI * s, -_HALF_PI * _HALF_PI * c
    if kind == ELLIPSE:
        f = math.sqrt(1.0 - t * t)
        return f, -t / f, -1.0 / (f * f * f)
    u = t**n
    om = 1.0 - u
    if om <= 0.0:
        # the corner of an n < 1 curve, which meets the base tangentially
        return 0.0, 0.0, 0.0
    p = om ** (1.0 / n - 1.0)
    if t > 0.0:
        tn1 = u / t
        tn2 = tn1 / t
    else:
        tn1 = 0.0
        tn2 = 0.0 if n > 2.0 else math.inf
    return om * p, -tn1 * p, -(n - 1.0) * tn2 * p / om


@njit(cache=True)
def _box_dist2(r, q, r0, r1, q0, q1):
    dr = max(r0 - r, 0.0, r - r1)
    dq = max(q0 - q, 0.0, q - q1)
    return dr * dr + dq * dq


@njit(cache=True)
def _newton_dist2(kind, n, b, c, rp, qp, left, right, g_left, g_right):
    """Squared distance at the root of g in [left, right], where g(left) < 0 < g(right)."""
    cb = c / b
    # start from the regula falsi point, then Newton kept inside the shrinking bracket
    x = left + (right - left) * (g_left / (g_left - g_right))
    tol = _NEWTON_TOL * b
    for _ in range(_NEWTON_MAX_ITER):
        f, fp, fpp = _shape(kind, x / b, n)
        dq = c * f - qp
        dphi = cb * fp
        g = (x - rp) + dphi * dq
        if g == 0.0:
            break
        if g < 0.0:
            left = x
        else:
            right = x
        gp = 1.0 + dphi * dphi + (cb / b) * fpp * dq
        xn = x - g / gp if gp > 0.0 else left
        if not (left < xn < right):
            xn = 0.5 * (left + right)
        if abs(xn - x) <= tol:
            x = xn
            break
        x = xn
    f, fp, fpp = _shape(kind, x / b, n)
    dq = c * f - qp
    return (x - rp) ** 2 + dq * dq


@njit(cache=True)
def _piece_dist2(kind, n, b, c, t0, t1, q_lo, q_hi, rp, qp, rq, fold, best2):
    """min(best2, squared distance from (rp, qp) to the graph q = c F(r/b), b*t0 <= r <= b*t1).

    ``F`` is decreasing, ``[q_lo, q_hi]`` the piece's q range (for pruning) and ``rq`` the
    abscissa where the whole curve is at height ``qp`` (0 if above it, b if below).

    Why the bracket: g(r) = (r - rp) + phi'(r) (phi(r) - qp) is half the derivative of the
    squared distance. Both terms are <= 0 where r <= rp and phi(r) >= qp, and >= 0 where
    r >= rp and phi(r) <= qp, so every local minimum over the whole curve lies between rp and
    rq. On that stretch g is increasing (one root) when the point is above a concave curve or
    below a convex one; the other side (inside a convex shape, outside an n < 1 Lame) can have
    two roots only when the point is deeper than the radius of curvature, which the caller
    avoids by splitting the curve so each piece holds at most one of them.
    """
    r0 = b * t0
    r1 = b * t1
    if _box_dist2(rp, qp, r0, r1, q_lo, q_hi) >= best2:
        return best2
    lo = min(rp, rq)
    hi = max(rp, rq)
    left = max(lo, r0)
    right = min(hi, r1)
    if left >= right:
        # the bracket misses the piece: the nearest point of the piece is its end facing it
        r = r0 if hi <= r0 else (r1 if lo >= r1 else left)
        f, fp, fpp = _shape(kind, r / b, n)
        dq = c * f - qp
        return min(best2, (r - rp) ** 2 + dq * dq)
    cb = c / b
    f, fp, fpp = _shape(kind, left / b, n)
    dq = c * f - qp
    g_left = (left - rp) + cb * fp * dq
    best2 = min(best2, (left - rp) ** 2 + dq * dq)
    f, fp, fpp = _shape(kind, right / b, n)
    dq = c * f - qp
    g_right = (right - rp) + cb * fp * dq
    best2 = min(best2, (right - rp) ** 2 + dq * dq)
    if not ((fold == _FOLD_BELOW and rp < rq) or (fold == _FOLD_ABOVE and rp > rq)):
        if g_left < 0.0 < g_right:
            best2 = min(best2, _newton_dist2(kind, n, b, c, rp, qp, left, right, g_left, g_right))
        return best2
    x_prev = left
    g_prev = g_left
    for i in range(1, _SAMPLES + 1):
        if i == _SAMPLES:
            x = right
            g = g_right
        else:
            x = left + (right - left) * (i / _SAMPLES)
            f, fp, fpp = _shape(kind, x / b, n)
            dq = c * f - qp
            g = (x - rp) + cb * fp * dq
            best2 = min(best2, (x - rp) ** 2 + dq * dq)
        if g_prev < 0.0 < g:
            best2 = min(best2, _newton_dist2(kind, n, b, c, rp, qp, x_prev, x, g_prev, g))
        x_prev = x
        g_prev = g
    return best2


@njit(cache=True)
def _segment_dist2(px, py, ax, ay, bx, by):
    ex = bx - ax
    ey = by - ay
    t = ((px - ax) * ex + (py - ay) * ey) / (ex * ex + ey * ey)
    t = min(max(t, 0.0), 1.0)
    dx = px - ax - t * ex
    dy = py - ay - t * ey
    return dx * dx + dy * dy


@njit(cache=True)
def _curve_dist2(code, a, h, n, yy, z, top_y, best2):
    """min(best2, squared distance from (yy >= 0, z) to the top curve of the profile).

    The curve is symmetric, so its right half (0 <= y <= a, ending at the corner (a, 0))
    holds a nearest point for yy >= 0. ``top_y`` is ``profile_top`` at ``yy``. Any z is
    accepted (the vertical sweep asks below the curve's base).
    """
    if code == RECT:
        d2 = _segment_dist2(yy, z, a, 0.0, a, h)
        return min(best2, d2, _segment_dist2(yy, z, a, h, 0.0, h))
    if code == ARC:
        r = (a * a + h * h) / (2.0 * h)
        zc = z - (h - r)  # height above the circle's centre
        if yy * (r - h) <= a * zc:
            # inside the cone from the centre through the corners: the radial foot is on the arc
            d = math.sqrt(yy * yy + zc * zc) - r
            return min(best2, d * d)
        return min(best2, (yy - a) ** 2 + z * z)
    if code == PARABOLA or code == COSINE:
        zq = z / h
        if zq >= 1.0:
            rq = 0.0
        elif zq <= 0.0:
            rq = a
        elif code == PARABOLA:
            rq = a * math.sqrt(1.0 - zq)
        else:
            rq = a * math.acos(zq) / _HALF_PI
        # radius of curvature is monotone along these curves, so one piece has one minimum
        return _piece_dist2(code, n, a, h, 0.0, 1.0, 0.0, h, yy, z, rq, _FOLD_NEVER, best2)
    if code == LAME and n == 1.0:
        return min(best2, _segment_dist2(yy, z, a, 0.0, 0.0, h))
    kind = ELLIPSE if (code == ELLIPSE or n == 2.0) else LAME
    # Split the quarter curve where it crosses the diagonal of its bounding box (normalised
    # Y = Z = s). Each piece is then a graph of slope <= 1 in normalised units -- z(y) on the
    # part whose slope stays bounded, y(z) on the other -- and, for squarish n > 2 shapes,
    # the minimum near the flat top and the one near the flat side fall in different pieces.
    if kind == ELLIPSE:
        s = math.sqrt(0.5)
    else:
        s = 0.5 ** (1.0 / n)
    if kind == ELLIPSE:
        fold = _FOLD_NEVER
    else:
        fold = _FOLD_BELOW if n > 1.0 else _FOLD_ABOVE
    if kind == ELLIPSE or n > 1.0:
        t0, t1, lo_a, hi_a, lo_b, hi_b = 0.0, s, h * s, h, a * s, a
    else:
        t0, t1, lo_a, hi_a, lo_b, hi_b = s, 1.0, 0.0, h * s, 0.0, a * s
    # piece A: z = h F(y/a); piece B: the same curve read as y = a F(z/h) (F is its own inverse)
    zq = z / h
    if zq >= 1.0:
        rq_a = 0.0
    elif zq <= 0.0:
        rq_a = a
    elif kind == ELLIPSE:
        rq_a = a * math.sqrt(1.0 - zq * zq)
    else:
        rq_a = a * _lame_f(zq, n)
    rq_b = top_y if yy <= a else 0.0
    # nearer piece first so the farther one is usually pruned by its bounding box
    if _box_dist2(yy, z, a * t0, a * t1, lo_a, hi_a) <= _box_dist2(z, yy, h * t0, h * t1, lo_b, hi_b):
        best2 = _piece_dist2(kind, n, a, h, t0, t1, lo_a, hi_a, yy, z, rq_a,fold, best2)
        return _piece_dist2(kind, n, h, a, t0, t1, lo_b, hi_b, z, yy, rq_b,fold, best2)
    best2 = _piece_dist2(kind, n, h, a, t0, t1, lo_b, hi_b, z, yy, rq_b,fold, best2)
    return _piece_dist2(kind, n, a, h, t0, t1, lo_a, hi_a, yy, z, rq_a,fold, best2)


@njit(cache=True)
def profile_sdf(code, w, h, n, y, z):
    """Exact Euclidean signed distance (mm, negative inside) from (y, z) to the profile region.

    ``code`` is one of the module constants, ``n`` the Lame exponent (ignored by the others).
    Preconditions (checked by :class:`BeadProfile`, not here): w, h > 0, n > 0, h <= w/2 for arc.
    """
    a = 0.5 * w
    yy = abs(y)
    if z <= 0.0:
        # the whole region lies in |y| <= a, z >= 0: below it the base or a corner is nearest
        if yy <= a:
            return -z
        return math.sqrt((yy - a) ** 2 + z * z)
    top_y = profile_top(code, w, h, n, yy)
    if yy <= a and z <= top_y:
        return -math.sqrt(_curve_dist2(code, a, h, n, yy, z, top_y, z * z))
    base2 = z * z if yy <= a else (yy - a) ** 2 + z * z
    return math.sqrt(_curve_dist2(code, a, h, n, yy, z, top_y, base2))


@dataclass(frozen=True)
class BeadProfile:
    """A validated bead cross-section: shape name, width and height in mm, Lame exponent."""

    name: str
    width: float
    height: float
    exponent: float = 4.0

    def __post_init__(self) -> None:
        w, h, n = _check(profile_code(self.name), self.width, self.height, self.exponent)
        object.__setattr__(self, "width", w)
        object.__setattr__(self, "height", h)
        object.__setattr__(self, "exponent", n)

    @property
    def code(self) -> int:
        return PROFILE_CODES[self.name]

    @property
    def area(self) -> float:
        """Cross-section area, mm^2."""
        return profile_area(self.code, self.width, self.height, self.exponent)

    @property
    def revolved_volume(self) -> float:
        """Volume of the profile revolved about its axis (one end cap pair), mm^3."""
        return revolved_volume(self.code, self.width, self.height, self.exponent)

    @property
    def max_height(self) -> float:
        return self.height

    @property
    def half_width(self) -> float:
        return 0.5 * self.width
