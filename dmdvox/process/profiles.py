"""Bead cross-section profiles: shape codes, areas, volumes and the exact 2-D signed distance.

A cross-section of width ``w`` and height ``h`` stands on its path point. Local coordinates:
``y`` lateral (signed), ``z`` up, ``z = 0`` the bead bottom. The region is
``P = {|y| <= w/2, 0 <= z <= top(y)}``; its boundary is the base segment plus the top curve,
which meets the base at the corners ``(+-w/2, 0)`` (for ``rect`` the top "curve" is the two
sides and the flat top).

:func:`profile_sdf` is the Euclidean signed distance to that boundary, negative inside; the
sign comes from a direct membership test, so it is always right. The distance is closed form
for ``rect``, ``arc`` and ``lame`` with n = 1. For the other shapes the nearest point on the
top curve is found by a safeguarded Newton iteration (to ~1e-9 of the bead size) inside a
bracket that provably holds every local minimum (see :func:`_piece_dist2`); there a single
root is guaranteed for ``ellipse``, ``parabola``, ``cosine`` and for points on the convex
side of a Lame curve. Where a Lame curve can fold around the point (inside for n > 1,
outside for n < 1) the bracket is sampled for all its minima; that part is verified against
brute force over exponents 0.3..100 and aspect ratios 0.025..3, not proven.
"""

from __future__ import annotations

import math
import operator
from dataclasses import dataclass

from numba import njit

from ..errors import DmdvoxError, ParameterError

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
# Newton stops when g (half the derivative of the squared distance, a length) is below this
# fraction of the bead size, i.e. the foot point is within about that much of the root
_NEWTON_TOL = 1e-9
# where Newton keeps failing (infinite curvature at a pointed end) bisection takes over
_BISECT_TOL = 1e-13
# samples of g where the curve may fold around the point, plus extra ones towards a cusp,
# each a quarter of the previous distance from it
_SAMPLES = 8
_CUSP_SAMPLES = 6
_CUSP_RATIO = 0.25
# on which side of a curve piece a point may see several nearest-point candidates
_FOLD_NEVER = 0
_FOLD_BELOW = 1
_FOLD_ABOVE = 2


def profile_code(name: str) -> int:
    """The integer code of a profile name (``PROFILE_NAMES``)."""
    try:
        return PROFILE_CODES[name]
    except (KeyError, TypeError):
        raise ParameterError(
            f"{{profile}}: unknown bead profile {name!r}; choose one of {', '.join(PROFILE_NAMES)}", "profile"
        ) from None


def profile_name(code: int) -> str:
    """The name of a profile code."""
    try:
        index = operator.index(code)
    except TypeError:
        index = -1
    if isinstance(code, bool) or not 0 <= index < len(PROFILE_NAMES):
        raise DmdvoxError(f"unknown bead profile code {code!r}; valid codes are 0..{len(PROFILE_NAMES) - 1}")
    return PROFILE_NAMES[index]


def _positive_mm(value, option: str) -> float:
    try:
        x = float(value)
    except (TypeError, ValueError):
        raise ParameterError(f"{{{option}}} must be a positive length in mm, got {value!r}", option) from None
    if isinstance(value, bool) or not math.isfinite(x) or x <= 0.0:
        raise ParameterError(f"{{{option}}} must be a positive finite length in mm, got {value!r}", option)
    return x


def _check(code: int, w: float, h: float, n: float) -> tuple[float, float, float]:
    """Validated (w, h, n) as floats; raises DmdvoxError naming the option to fix."""
    profile_name(code)
    w = _positive_mm(w, "width")
    h = _positive_mm(h, "height")
    try:
        n_f = float(n)
    except (TypeError, ValueError):
        raise ParameterError(f"{{exponent}} must be a positive number (lame profile), got {n!r}",
                             "exponent") from None
    if isinstance(n, bool) or not math.isfinite(n_f) or n_f <= 0.0:
        raise ParameterError(
            f"{{exponent}} must be a positive finite number (lame profile: 2 is an ellipse, larger is "
            f"squarer), got {n!r}", "exponent"
        )
    if code == ARC and h > 0.5 * w:
        raise ParameterError(
            f"{{height}}: an arc profile needs height <= width/2 (got height {h:g} mm for width {w:g} mm); "
            f"lower {{height}}, widen {{width}}, or use the ellipse profile for taller beads", "height", also=("width",)
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
def _lame_pow(t, n):
    """t^n; integer exponents (the usual ones) by multiplication rather than exp/log."""
    k = int(n)
    if k == n and k <= 64:
        return t**k
    return t**n


@njit(cache=True)
def _lame_root(u, n):
    """u^(1/n); the default exponent 4 by two square roots, several times faster than pow."""
    if n == 4.0:
        return math.sqrt(math.sqrt(u))
    return u ** (1.0 / n)


@njit(cache=True)
def _lame_f(t, n):
    """Normalised Lame top curve Z = (1 - t^n)^(1/n) for 0 <= t <= 1."""
    u = 1.0 - _lame_pow(t, n)
    if u <= 0.0:
        return 0.0
    return _lame_root(u, n)


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
    :func:`top_curve_dist2`), except the vertex t = 0 for 1 < n < 2, where the curvature really
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
    u = _lame_pow(t, n)
    om = 1.0 - u
    if om <= 0.0:
        # the corner of an n < 1 curve, which meets the base tangentially
        return 0.0, 0.0, 0.0
    f = _lame_root(om, n)
    p = f / om  # om^(1/n - 1)
    if t > 0.0:
        tn1 = u / t
        tn2 = tn1 / t
    else:
        tn1 = 0.0
        tn2 = 0.0 if n > 2.0 else math.inf
    return f, -tn1 * p, -(n - 1.0) * tn2 * p / om


@njit(cache=True)
def _box_dist2(r, q, r0, r1, q0, q1):
    dr = max(r0 - r, 0.0, r - r1)
    dq = max(q0 - q, 0.0, q - q1)
    return dr * dr + dq * dq


@njit(cache=True)
def _newton_dist2(kind, n, b, c, rp, qp, left, right, x):
    """Squared distance at a root of g in [left, right] (g(left) <= 0 <= g(right)), from x.

    Newton, with bisection whenever a step would leave the shrinking bracket. Convergence is
    judged on |g|, not on the step: next to a pointed end g' is huge and the steps tiny long
    before the root. At convergence the quadratic model of the last step gives the minimum,
    D(x) - g^2/g', saving the evaluation at the final point.
    """
    cb = c / b
    tol = _NEWTON_TOL * b
    d2 = math.inf
    for _ in range(_NEWTON_MAX_ITER):
        f, fp, fpp = _shape(kind, x / b, n)
        dq = c * f - qp
        dphi = cb * fp
        g = (x - rp) + dphi * dq
        d2 = (x - rp) ** 2 + dq * dq
        gp = 1.0 + dphi * dphi + (cb / b) * fpp * dq
        step = g / gp
        newton_ok = gp > 0.0 and left <= x - step <= right
        if abs(g) <= tol:
            return max(d2 - g * step, 0.0) if newton_ok else d2
        if g < 0.0:
            left = x
        else:
            right = x
        if newton_ok and left < x - step < right:
            x -= step
        else:
            x = 0.5 * (left + right)
            if right - left <= _BISECT_TOL * b:
                break
    return d2


@njit(cache=True)
def _shape_dist2_g(kind, n, b, c, rp, qp, x):
    """(squared distance, g) at abscissa x of the graph q = c F(r/b)."""
    f, fp, fpp = _shape(kind, x / b, n)
    dq = c * f - qp
    return (x - rp) ** 2 + dq * dq, (x - rp) + (c / b) * fp * dq


@njit(cache=True)
def _piece_dist2(kind, n, b, c, t0, t1, q_lo, q_hi, rp, qp, rq, q_at_rp, fold, best2):
    """min(best2, squared distance from (rp, qp) to the graph q = c F(r/b), b*t0 <= r <= b*t1).

    ``F`` is decreasing, ``[q_lo, q_hi]`` the piece's q range (for pruning), ``rq`` the
    abscissa where the whole curve is at height ``qp`` (0 if above it, b if below) and
    ``q_at_rp`` the curve's height at ``rp`` (0 beyond it).

    Why the bracket: g(r) = (r - rp) + phi'(r) (phi(r) - qp) is half the derivative of the
    squared distance. Both terms are <= 0 where r <= rp and phi(r) >= qp, and >= 0 where
    r >= rp and phi(r) <= qp, so every local minimum over the whole curve lies between rp and
    rq, and g(lo) <= 0 <= g(hi) at its ends. On that stretch g is increasing -- one root --
    when the point is above a concave curve or below a convex one, and along the parabola,
    cosine and ellipse whatever the side (their radius of curvature is monotone, so a point
    has at most two normals to the quarter curve, and the bracket holds an odd number).
    Otherwise (``fold``: inside a Lame shape with n > 1, outside one with n < 1) the curve
    can fold around the point -- a squarish shape has a minimum under its flat top and
    another beside its flat side -- and the bracket is sampled for every sign change of g.
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
        return min(best2, _shape_dist2_g(kind, n, b, c, rp, qp, r)[0])
    if fold == _FOLD_BELOW and rp < rq and n > 2.0:
        # g' = 1 + phi'^2 + phi'' (phi - qp), and along a piece of an n > 2 curve |phi''|
        # grows while phi - qp shrinks: the worst case pairs the curvature at the right end
        # with the height at the left one. If even that keeps g' > 0 there is one root.
        f, fp, fpp = _shape(kind, right / b, n)
        q_left = q_at_rp if left == rp else c
        if 1.0 + (c / (b * b)) * fpp * (q_left - qp) <= 0.0:
            return _sampled_dist2(kind, n, b, c, r1, fold, rp, qp, left, right, best2)
    elif (fold == _FOLD_BELOW and rp < rq) or (fold == _FOLD_ABOVE and rp > rq):
        return _sampled_dist2(kind, n, b, c, r1, fold, rp, qp, left, right, best2)
    # one root: only an end clipped to the piece can hold the minimum instead
    if left > lo:
        d2, g = _shape_dist2_g(kind, n, b, c, rp, qp, left)
        if g >= 0.0:
            return min(best2, d2)
    if right < hi:
        d2, g = _shape_dist2_g(kind, n, b, c, rp, qp, right)
        if g <= 0.0:
            return min(best2, d2)
    # start at the foot of the perpendicular on the chord from the point's vertical
    # projection (rp, q_at_rp) to its horizontal one (rq, qp): exact for a straight curve
    dr = rq - rp
    dq = qp - q_at_rp
    x = rp + dr * (dq * dq / (dr * dr + dq * dq))
    if not (left < x < right):
        x = 0.5 * (left + right)
    return min(best2, _newton_dist2(kind, n, b, c, rp, qp, left, right, x))


@njit(cache=True)
def _sampled_dist2(kind, n, b, c, r1, fold, rp, qp, left, right, best2):
    """min(best2, squared distance) over [left, right] where g may have several roots.

    g is sampled and every sign change refined. For n < 1 the pieces end (r1) in a cusp whose
    infinite curvature can hide a minimum within a tiny distance of it, so extra samples
    crowd geometrically towards it.
    """
    cusp = fold == _FOLD_ABOVE and right >= r1
    last = _SAMPLES + _CUSP_SAMPLES if cusp else _SAMPLES
    x_prev = left
    d2, g_prev = _shape_dist2_g(kind, n, b, c, rp, qp, left)
    best2 = min(best2, d2)
    for i in range(1, last + 1):
        if i == last:
            x = right
        elif i < _SAMPLES:
            x = left + (right - left) * (i / _SAMPLES)
        else:
            x = right - (right - left) * (_CUSP_RATIO ** (i - _SAMPLES + 1) / _SAMPLES)
        d2, g = _shape_dist2_g(kind, n, b, c, rp, qp, x)
        best2 = min(best2, d2)
        # g_prev == 0 counts: on the axis of a 1 < n < 2 Lame the pointed vertex is a
        # critical point that is a maximum, with the minimum just beside it
        if g_prev <= 0.0 < g:
            if g_prev < 0.0:
                x0 = x_prev + (x - x_prev) * (g_prev / (g_prev - g))
            else:
                x0 = 0.5 * (x_prev + x)
            best2 = min(best2, _newton_dist2(kind, n, b, c, rp, qp, x_prev, x, x0))
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
def top_curve_dist2(code, a, h, n, yy, z, top_y, best2):
    """min(best2, squared distance from (yy >= 0, z) to the top curve of the profile).

    The curve is symmetric, so its right half (0 <= y <= a, ending at the corner (a, 0))
    holds a nearest point for yy >= 0. ``top_y`` is ``profile_top`` at ``yy``. Any z is
    accepted (the vertical sweep of a bead asks below the curve's base). ``best2`` is a
    known upper bound (a distance to another part of the boundary), used for pruning.
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
        return _piece_dist2(code, n, a, h, 0.0, 1.0, 0.0, h, yy, z, rq, top_y, _FOLD_NEVER, best2)
    if code == LAME and n == 1.0:
        return min(best2, _segment_dist2(yy, z, a, 0.0, 0.0, h))
    kind = ELLIPSE if (code == ELLIPSE or n == 2.0) else LAME
    # Split the quarter curve where it crosses the diagonal of its bounding box (normalised
    # Y = Z = s). Each piece is then a graph of slope <= 1 in normalised units -- z(y) on the
    # part whose slope stays bounded, y(z) on the other -- and the two minima a squarish
    # n > 2 shape offers (under the flat top, beside the flat side) mostly fall in different
    # pieces.
    if kind == ELLIPSE:
        s = math.sqrt(0.5)
        fold = _FOLD_NEVER
    else:
        s = _lame_root(0.5, n)
        fold = _FOLD_BELOW if n > 1.0 else _FOLD_ABOVE
    if kind == ELLIPSE or n > 1.0:
        t0, t1, lo_a, hi_a, lo_b, hi_b = 0.0, s, h * s, h, a * s, a
    else:
        t0, t1, lo_a, hi_a, lo_b, hi_b = s, 1.0, 0.0, h * s, 0.0, a * s
    # piece A: z = h F(y/a); piece B: the same curve read as y = a F(z/h) (F is its own
    # inverse, so each piece's rq is the other's height at its rp)
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
        best2 = _piece_dist2(kind, n, a, h, t0, t1, lo_a, hi_a, yy, z, rq_a, rq_b, fold, best2)
        return _piece_dist2(kind, n, h, a, t0, t1, lo_b, hi_b, z, yy, rq_b, rq_a, fold, best2)
    best2 = _piece_dist2(kind, n, h, a, t0, t1, lo_b, hi_b, z, yy, rq_b, rq_a, fold, best2)
    return _piece_dist2(kind, n, a, h, t0, t1, lo_a, hi_a, yy, z, rq_a, rq_b, fold, best2)


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
        return -math.sqrt(top_curve_dist2(code, a, h, n, yy, z, top_y, z * z))
    base2 = z * z if yy <= a else (yy - a) ** 2 + z * z
    return math.sqrt(top_curve_dist2(code, a, h, n, yy, z, top_y, base2))


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
