"""Beads that land on the part as it stands: mass conserved, real layer heights, standoff drift.

The ``flow`` model. Elements (pieces and caps, :mod:`.beads`) are laid in deposition order on a
**height field** ``H(x, y)``: the top of the part (or the substrate) at every voxel column,
starting flat at the substrate top. Each element keeps its cross-section shape and moves along
its up axis by the one offset ``dz`` that makes the material it adds above the surface equal to
the material it carries::

    added(dz) = sum over its footprint cells c of  clip(z_c + dz + top_c - H_c, 0, top_c + D) * cell area

``z_c`` is the programmed bottom over cell c, ``top_c`` the profile's height there. The melt
wets the surface: below the bead's bottom the material fills down to the surface (the section's
**foot**), but no deeper than the fusion depth ``D`` (default: the element's own height, the
depth a melt pool of that size reaches). So:

* overlapping material goes up, not away: parallel beads of area A at spacing d build layers of
  mean height A / d whatever the profile;
* a bead programmed below the surface is lifted, one programmed above it drops onto it; a layer
  programmed higher or lower than the part has grown shows as drift;
* where the gap under a bead is deeper than ``D`` (heavy overlap lifting the toe, a step) a void
  stays below it: lack of fusion, which the grid's pores then show;
* an element that would have to drop more than ``max_drop`` (default ``DEFAULT_MAX_DROP_MM``:
  the depth of field of a coaxial powder nozzle's focus) never reaches the part: its material is
  reported lost (``Landing.reason``: it fell off the part, or dropped beyond the bridge span),
  and it is not drawn.

**Piece by piece.** A piece does not land by one offset: it is cut into stretches no longer than
``PIECE_WIDTHS`` bead widths, and also wherever the surface under its path changes (from support
to gap, see below, or by a jump of more than ``JUMP_VOXELS`` voxels or ``JUMP_HEIGHTS`` bead
heights from one voxel to the next); each stretch lands on what is under it. Material and time
go by the share of length (a piece's section and speed are constant along it), so a stretch
carries exactly its part of the piece's material and starts when the tool reaches it.
Consecutive stretches that land within ``MERGE_VOXELS`` voxels of each other are drawn as one
element again: on a flat layer a piece stays one element.

**Bridges.** A point of the surface under the path *supports* the bead when it lies less than
``SUPPORT_DEPTH`` bead heights below its programmed bottom. Where it does not, the bead may still
be held *beside* its path, by a surface that does within its own width across it (a wall, or the
strand laid just before: the strands fuse): it then hangs there, at most at its programmed
bottom (filament strands only: a melt pool is held by what is under it). Neither is a gap. A gap closed by
supports on both sides (along the path, across the pieces that continue each other) no longer
than the bridge span (``--bridge-span``; default ``FILAMENT_BRIDGE_SPAN_MM`` for extruded
filament, ``MELT_BRIDGE_WIDTHS`` bead widths for a powder or wire melt pool) is spanned: the
bead hangs on the line between where the support behind it landed and the support ahead, sagging
by ``SAG_HEIGHTS`` bead heights x (gap / span)^2 at the middle of the gap (a parabola), with air
below it (or on what is below, if that is higher). A held bead has no foot but where its
section overlaps what holds it (the strand beside it, the support at a bridge's end): that share
is already solid, and the melt it displaces sags into the gap under the bead as a foot just deep
enough to hold the rest (:func:`_hang_foot`), so a bridge keeps its material. Longer gaps, and a gap open at one end (a
free end) longer than half the span, drop: the material lands on what is below, or is lost
beyond ``max_drop``. A free end within half the span of its one support hangs at that support's
level (filament; a cap, a strand's round end, stays with the stretch it ends or rests on what
is under or beside it).

**Filament squish.** With extruded filament (the reprap dialect's E words, Z the layer top) the
nozzle tip, the layer height above the programmed bottom, bounds the bead's top: a bead that
would stand above it is flattened to the gap between its landed bottom and the tip and spreads
sideways, wider, until its cells hold its material (at most ``MAX_SQUISH_WIDTHS`` widths:
beyond, there is no room beside it either and it grows in height). So an over-extruding program
overbuilds sideways, at the walls, not in height. A powder or wire bead (DED) grows freely.

The material offered to the surface can depend on the standoff (nozzle tip to the surface below
it, before the element lands: the programmed bottom plus the nominal standoff, minus ``H``): with
a Gaussian catchment profile ``eta(s) = eta0 exp(-(s - focus)^2 / (2 sigma^2))`` a part that grows
too fast catches less powder and one that lags catches more, which is what makes DED layer
heights settle (``s_{n+1} = s_n + dz - h(s_n)``, stable where ``0 < h'(s) < 2``).

The solved offsets move the elements; the sweep engine then draws them where they landed, so the
grid, arrival times, pores and every analysis see the built part.

What a height field cannot represent: undercuts and overhangs (material below material with air
between), and beads whose up axis is not vertical. Elements tilted off +Z are drawn where
programmed and counted in ``not_landed`` with a warning; voids left by lack of fusion are not
refilled later (the height field only sees the top).
"""

from __future__ import annotations

import dataclasses
import math
import re
from dataclasses import dataclass

import numpy as np
from numba import njit

from ..defaults import STANDOFF_MM
from ..errors import DmdvoxError, ParameterError
from .beads import ARC, CAP, SEGMENT, Beads
from .profiles import profile_area, profile_top, revolved_volume

# Coaxial powder nozzles keep their powder focus (catchment within a few % of its best) over about
# +-1 mm; a bead whose programmed bottom is more than twice that above the surface does not form.
DEFAULT_MAX_DROP_MM = 2.0
_UP_TOL = 1e-9
# Every piece lands stretch by stretch, each no longer than this many bead widths.
PIECE_WIDTHS = 0.5
# A point of the surface supports a bead when it lies less than this many bead heights below the
# bead's programmed bottom; deeper is a gap.
SUPPORT_DEPTH = 0.5
# A stretch also ends where the surface under the path jumps by more than this many voxels or
# bead heights (the larger) from one voxel to the next (a step).
JUMP_VOXELS = 2.0
JUMP_HEIGHTS = 0.25
# Consecutive stretches of a piece that land within this many voxels of each other are drawn
# as one element.
MERGE_VOXELS = 0.25
# Bridges: a strand of molten thermoplastic drawn by the nozzle holds over several mm (slicers
# bridge far longer with their bridge flow and fan); a powder or wire melt pool spans about its
# own width. A bridge of the full span sags by half a bead height at its middle, less with the
# square of a shorter gap.
FILAMENT_BRIDGE_SPAN_MM = 5.0
MELT_BRIDGE_WIDTHS = 1.0
SAG_HEIGHTS = 0.5
# Filament squish: the flattened section spreads to at most this many widths (beyond: no room
# beside it, it grows in height); no flattening once the gap under the nozzle is below this
# share of the bead height; the spread width holds the material to this fraction.
MAX_SQUISH_WIDTHS = 3.0
MIN_SQUISH_RATIO = 0.1
SQUISH_TOL = 1e-3
# Why material was lost (Landing.reason): it fell off the part (nothing below within
# --max-drop), or it dropped from a gap longer than the bridge span between its supports.
LOST_FELL_OFF = 1
# What holds a bead at a point of its path (_sample).
GAP = 0
SUPPORTED = 1
BESIDE = 2
LOST_BEYOND_SPAN = 2
LOST_REASONS = {LOST_FELL_OFF: "fell off the part", LOST_BEYOND_SPAN: "beyond the bridge span"}


@dataclass(frozen=True)
class GaussCatchment:
    """``eta(s) = eta0 exp(-(s - focus)^2 / (2 sigma^2))`` of the standoff s (mm)."""

    eta0: float
    focus: float
    sigma: float

    def __call__(self, standoff):
        return self.eta0 * np.exp(-((np.asarray(standoff) - self.focus) ** 2) / (2.0 * self.sigma**2))


_PROFILE_SPEC = re.compile(r"^gauss:(.*)$")


def parse_catchment_profile(text: str) -> GaussCatchment:
    """``gauss:eta0=0.8,focus=12,sigma=1.5`` (the option ``--catchment-profile``)."""
    match = _PROFILE_SPEC.match(text.strip())
    if not match:
        raise DmdvoxError(f"--catchment-profile: expected gauss:eta0=E,focus=MM,sigma=MM, got {text!r}")
    values = {}
    for item in match.group(1).split(","):
        key, _, value = item.partition("=")
        try:
            values[key.strip()] = float(value)
        except ValueError:
            raise DmdvoxError(f"--catchment-profile: {item!r} is not NAME=NUMBER") from None
    missing = {"eta0", "focus", "sigma"} - set(values)
    extra = set(values) - {"eta0", "focus", "sigma"}
    if missing or extra:
        raise DmdvoxError(f"--catchment-profile: give exactly eta0, focus and sigma (missing: "
                          f"{', '.join(sorted(missing)) or 'none'}; unknown: {', '.join(sorted(extra)) or 'none'})")
    if not 0.0 < values["eta0"] <= 1.0:
        raise DmdvoxError(f"--catchment-profile: eta0 is a fraction in (0, 1], got {values['eta0']:g}")
    if not values["sigma"] > 0.0 or not np.isfinite(values["sigma"]) or not np.isfinite(values["focus"]):
        raise DmdvoxError("--catchment-profile: focus must be finite and sigma positive (mm)")
    return GaussCatchment(values["eta0"], values["focus"], values["sigma"])


@dataclass(frozen=True)
class LandingSettings:
    plate_z: float | None = None  # substrate top; None: the lowest programmed bead bottom
    max_drop_mm: float = DEFAULT_MAX_DROP_MM
    fusion_depth_mm: float | None = None  # None: each element's own height
    standoff_mm: float = STANDOFF_MM
    catchment: GaussCatchment | None = None
    nominal_catchment: float = 1.0  # the catchment the material was metered with
    bridge_span_mm: float | None = None  # None: the process's default (bridge_span)
    filament: bool = False  # extruded filament: the nozzle flattens the beads, strands bridge far

    def validate(self) -> None:
        if not (self.max_drop_mm > 0):  # inf: nothing is ever lost
            raise ParameterError(f"{{max_drop_mm}} must be a positive distance in mm, got {self.max_drop_mm!r}",
                                 "max_drop_mm")
        if not (np.isfinite(self.standoff_mm) and self.standoff_mm >= 0):
            raise ParameterError(f"{{standoff_mm}} must be a distance >= 0 mm, got {self.standoff_mm!r}", "standoff_mm")
        if self.fusion_depth_mm is not None and not (np.isfinite(self.fusion_depth_mm) and self.fusion_depth_mm >= 0):
            raise ParameterError(f"{{fusion_depth_mm}} must be a distance >= 0 mm, got {self.fusion_depth_mm!r}",
                                 "fusion_depth_mm")
        if self.bridge_span_mm is not None and not (np.isfinite(self.bridge_span_mm) and self.bridge_span_mm >= 0):
            raise ParameterError(f"{{bridge_span_mm}} must be a length >= 0 mm, got {self.bridge_span_mm!r}",
                                 "bridge_span_mm")
        if self.plate_z is not None and not np.isfinite(self.plate_z):
            raise ParameterError(f"{{plate_z}} must be a finite height in mm, got {self.plate_z!r}", "plate_z")


@dataclass(frozen=True, eq=False)
class Landing:
    """Where every stretch landed (``programmed``: the elements cut into the stretches that
    landed alike, where the program puts them): its offset along the up axis, the foot drawn
    below it, the standoff it met, the material it added (0 where lost), whether it was lost, how
    much and why (``reason``: 0, or a key of ``LOST_REASONS``)."""

    dz: np.ndarray  # (m,) float64 mm, solved bottom minus programmed bottom
    foot: np.ndarray  # (m,) float64 mm
    standoff: np.ndarray  # (m,) float64 mm, nozzle tip to the surface below, before landing
    added: np.ndarray  # (m,) float64 mm^3
    lost: np.ndarray  # (m,) bool
    landed: np.ndarray  # (m,) bool: solved on the height field (False: tilted, drawn as programmed)
    plate_z: float
    programmed: Beads
    lost_volume: np.ndarray  # (m,) float64 mm^3
    reason: np.ndarray  # (m,) uint8


@njit(cache=True)
def _interval(lo, hi, offset, slope):
    """Values y with lo <= offset + slope * y <= hi."""
    if abs(slope) < 1e-12:
        if lo <= offset <= hi:
            return -np.inf, np.inf
        return np.inf, -np.inf
    a = (lo - offset) / slope
    b = (hi - offset) / slope
    return min(a, b), max(a, b)


@njit(cache=True)
def _collect(kind, p0, p1, clip, w, h, code, n_exp, ox, oy, voxel, nx, ny, H, out_i, out_j, out_top, out_z):
    """The element's footprint cells (centre inside its horizontal footprint; every range
    half-open, so that pieces which follow or touch each other share no cell; a cut cap's only
    beyond its cuts): index, profile height there and programmed bottom there. Returns the
    count."""
    half = 0.5 * w
    m = 0
    if kind == CAP:
        i0 = max(0, int(math.ceil((p0[0] - half - ox) / voxel)))
        i1 = min(nx - 1, int(math.floor((p0[0] + half - ox) / voxel)))
        for i in range(i0, i1 + 1):
            x = ox + i * voxel
            dx = x - p0[0]
            if abs(dx) > half:
                continue
            reach = math.sqrt(half * half - dx * dx)
            j0 = max(0, int(math.ceil((p0[1] - reach - oy) / voxel)))
            j1 = min(ny - 1, int(math.floor((p0[1] + reach - oy) / voxel)))
            for j in range(j0, j1 + 1):
                dy = oy + j * voxel - p0[1]
                # the cells on a cut line belong to the piece that owns that line (pieces own
                # their start, not their end: the half-open along range below)
                if dx * clip[0] + dy * clip[1] < 0.0:
                    continue
                if (clip[3] != 0.0 or clip[4] != 0.0) and dx * clip[3] + dy * clip[4] <= 0.0:
                    continue
                r = math.hypot(dx, dy)
                if r >= half:
                    continue
                top = profile_top(code, w, h, n_exp, r)
                if top <= 0.0:
                    continue
                out_i[m] = i
                out_j[m] = j
                out_top[m] = top
                out_z[m] = p0[2]
                m += 1
        return m
    if kind == ARC:
        cx, cy, cz = p0[0], p0[1], p0[2]
        radius, theta0, sweep = p1[0], p1[1], p1[2]
        reach = radius + half
        i0 = max(0, int(math.ceil((cx - reach - ox) / voxel)))
        i1 = min(nx - 1, int(math.floor((cx + reach - ox) / voxel)))
        direction = 1.0 if sweep >= 0.0 else -1.0
        span = abs(sweep)
        for i in range(i0, i1 + 1):
            dx = ox + i * voxel - cx
            if abs(dx) > reach:
                continue
            ry = math.sqrt(reach * reach - dx * dx)
            j0 = max(0, int(math.ceil((cy - ry - oy) / voxel)))
            j1 = min(ny - 1, int(math.floor((cy + ry - oy) / voxel)))
            for j in range(j0, j1 + 1):
                dy = oy + j * voxel - cy
                rho = math.hypot(dx, dy)
                lateral = rho - radius
                if lateral < -half or lateral >= half:
                    continue
                alpha = ((math.atan2(dy, dx) - theta0) * direction) % (2.0 * math.pi)
                if span < 2.0 * math.pi and alpha >= span:
                    continue
                top = profile_top(code, w, h, n_exp, lateral)
                if top <= 0.0:
                    continue
                out_i[m] = i
                out_j[m] = j
                out_top[m] = top
                out_z[m] = cz
                m += 1
        return m
    ax, ay, az = p0[0], p0[1], p0[2]
    ex, ey, ez = p1[0] - ax, p1[1] - ay, p1[2] - az
    lh = math.hypot(ex, ey)
    if lh <= 1e-12:
        return 0
    tx, ty = ex / lh, ey / lh
    # the lateral axis points the same way for a bead and its reverse, so that the half-open
    # lateral range picks the same cells for both (walls laid back and forth stack exactly)
    lx, ly = -ty, tx
    if ly < 0.0 or (ly == 0.0 and lx < 0.0):
        lx, ly = -lx, -ly
    x_lo = min(ax, p1[0]) - half
    x_hi = max(ax, p1[0]) + half
    i0 = max(0, int(math.ceil((x_lo - ox) / voxel)))
    i1 = min(nx - 1, int(math.floor((x_hi - ox) / voxel)))
    for i in range(i0, i1 + 1):
        x = ox + i * voxel
        # |lateral| <= half and 0 <= along < lh, both linear in y along the column
        llo, lhi = _interval(-half, half, (x - ax) * lx - ay * ly, ly)
        alo, ahi = _interval(0.0, lh, (x - ax) * tx - ay * ty, ty)
        ylo, yhi = max(llo, alo), min(lhi, ahi)
        if ylo > yhi:
            continue
        j0 = max(0, int(math.ceil((min(max(ylo, oy - voxel), oy + ny * voxel) - oy) / voxel)))
        j1 = min(ny - 1, int(math.floor((min(max(yhi, oy - voxel), oy + ny * voxel) - oy) / voxel)))
        for j in range(j0, j1 + 1):
            y = oy + j * voxel
            along = (x - ax) * tx + (y - ay) * ty
            if along < 0.0 or along >= lh:
                continue
            lateral = (x - ax) * lx + (y - ay) * ly
            if lateral < -half or lateral >= half:
                continue
            top = profile_top(code, w, h, n_exp, lateral)
            if top <= 0.0:
                continue
            out_i[m] = i
            out_j[m] = j
            out_top[m] = top
            out_z[m] = az + ez * along / lh
            m += 1
    return m


@njit(cache=True)
def _added(dz, m, H, ci, cj, top, zc, depth):
    """Material (in cell-area units) added at offset dz, and the number of cells still filling."""
    total = 0.0
    filling = 0
    for c in range(m):
        g = zc[c] + dz + top[c] - H[ci[c], cj[c]]
        cap = top[c] + depth
        if g <= 0.0:
            continue
        if g >= cap:
            total += cap
        else:
            total += g
            filling += 1
    return total, filling


@njit(cache=True)
def _solve(m, H, ci, cj, top, zc, depth, target):
    """The offset dz with _added(dz) = target: safeguarded Newton on the piecewise-linear,
    nondecreasing sum of clipped ramps, inside a bracket that always holds the root."""
    lo = np.inf
    hi = -np.inf
    for c in range(m):
        base = H[ci[c], cj[c]] - zc[c] - top[c]  # below this the cell adds nothing
        lo = min(lo, base)
        hi = max(hi, base + top[c] + depth)  # above this every cell is full
    full, _ = _added(hi, m, H, ci, cj, top, zc, depth)
    if target >= full:
        # more than the footprint holds with its feet: rise by the rest, spread evenly
        return hi + (target - full) / m
    if target <= 0.0:
        return lo
    x = min(max(0.0, lo), hi)
    for _ in range(100):
        f, slope = _added(x, m, H, ci, cj, top, zc, depth)
        r = f - target
        if abs(r) <= 1e-12 * max(target, 1.0):
            return x
        if r < 0.0:
            lo = x
        else:
            hi = x
        step_ok = slope > 0
        nxt = x - r / slope if step_ok else 0.5 * (lo + hi)
        if not (lo < nxt < hi):
            nxt = 0.5 * (lo + hi)
        if hi - lo <= 1e-13 * max(1.0, abs(x)):
            return nxt
        x = nxt
    return x


@njit(cache=True)
def _point(kind, p0, p1, f, out):
    """The programmed bottom point at fraction f along a piece (segment or exact arc)."""
    if kind == ARC:
        angle = p1[1] + f * p1[2]
        out[0] = p0[0] + p1[0] * math.cos(angle)
        out[1] = p0[1] + p1[0] * math.sin(angle)
        out[2] = p0[2]
    else:
        for q in range(3):
            out[q] = p0[q] + f * (p1[q] - p0[q])


@njit(cache=True)
def _piece_length(kind, p0, p1):
    if kind == ARC:
        return p1[0] * abs(p1[2])
    return math.hypot(p1[0] - p0[0], p1[1] - p0[1])


@njit(cache=True)
def _sub_piece(kind, p0, p1, fa, fb, q0, q1):
    """The stretch [fa, fb) of a piece as a piece of its own."""
    if kind == ARC:
        q0[0], q0[1], q0[2] = p0[0], p0[1], p0[2]
        q1[0] = p1[0]
        q1[1] = p1[1] + fa * p1[2]
        q1[2] = (fb - fa) * p1[2]
    else:
        for q in range(3):
            q0[q] = p0[q] + fa * (p1[q] - p0[q])
            q1[q] = p0[q] + fb * (p1[q] - p0[q])


@njit(cache=True)
def _surface(H, x, y, ox, oy, voxel):
    nx, ny = H.shape
    i = min(max(int(round((x - ox) / voxel)), 0), nx - 1)
    j = min(max(int(round((y - oy) / voxel)), 0), ny - 1)
    return H[i, j]


@njit(cache=True)
def _sample(kind, p0, p1, f, w, reach, strands, H, ox, oy, voxel, pt):
    """What holds the bead at fraction f along a piece: ``SUPPORTED`` (the surface under the
    path is within ``reach`` below the programmed bottom), ``BESIDE`` (not under the path but
    within the bead's width across it: a wall or the strand laid before), ``GAP``; the surface
    level that holds it (the one under the path for a gap). The point is left in pt."""
    _point(kind, p0, p1, f, pt)
    centre = _surface(H, pt[0], pt[1], ox, oy, voxel)
    if centre >= pt[2] - reach:
        return SUPPORTED, centre
    if not strands:
        return GAP, centre
    if kind == ARC:
        angle = p1[1] + f * p1[2]
        nx_, ny_ = math.cos(angle), math.sin(angle)
    else:
        dx, dy = p1[0] - p0[0], p1[1] - p0[1]
        norm = math.hypot(dx, dy)
        if norm <= 0.0:
            return GAP, centre
        nx_, ny_ = -dy / norm, dx / norm
    side = -np.inf
    steps = int(0.5 * w / voxel) + 1  # to the edge and the cell beyond it: what it touches
    for q in range(1, steps + 1):
        u = q * voxel
        side = max(side, _surface(H, pt[0] + u * nx_, pt[1] + u * ny_, ox, oy, voxel),
                   _surface(H, pt[0] - u * nx_, pt[1] - u * ny_, ox, oy, voxel))
    if side >= pt[2] - reach:
        return BESIDE, side
    return GAP, centre


@njit(cache=True)
def _support_ahead(k, need, kind, p0, p1, width, height, landable, cont, strands, H, ox, oy, voxel, pt):
    """From the end of piece k along the pieces that continue it: the distance to the first point
    where something holds its bead (within ``need``; -1: none) and the offset to the surface
    there."""
    n = kind.shape[0]
    walked = 0.0
    j = k + 1
    while j < n and walked <= need:
        if kind[j] == CAP:
            j += 1
            continue
        if not cont[j] or not landable[j]:
            break
        length = _piece_length(kind[j], p0[j], p1[j])
        ns = max(1, int(math.ceil(length / voxel)))
        for i in range(ns):
            f = (i + 0.5) / ns
            state, s_level = _sample(kind[j], p0[j], p1[j], f, width[j], SUPPORT_DEPTH * height[j], strands, H,
                                     ox, oy, voxel, pt)
            if state != GAP:
                d = walked + f * length
                return (d, s_level - pt[2]) if d <= need else (-1.0, 0.0)
        walked += length
        j += 1
    return -1.0, 0.0


@njit(cache=True)
def _free(m, H, ci, cj, top, zc, depth, target, VB, VT):
    """Free landing of collected cells (module docstring): the offset and the foot. The drawn
    foot has one depth (the deepest gap it fills) under the whole element, so where the gap is
    smaller it reaches below the surface: into solid, or into a void an earlier bead left (lack
    of fusion), which it then fills. That material counts too."""
    refill = 0.0
    dz = 0.0
    foot = 0.0
    for _ in range(4):
        dz = _solve(m, H, ci, cj, top, zc, depth, target - refill)
        foot = _foot(m, H, ci, cj, top, zc, depth, dz)
        again = _refill(m, ci, cj, zc, dz, foot, VB, VT)
        if abs(again - refill) <= 1e-9 * max(target, 1.0):
            break
        refill = min(again, target)
    return dz, foot


@njit(cache=True)
def _hang_foot(m, H, ci, cj, top, zc, dz, target):
    """The foot of a held bead (a bridge, a strand hanging beside its neighbour): where its
    section overlaps what holds it, that share is already solid, and the melt it displaces sags
    into the gap under the bead. The depth F with sum_c clip(g_c, 0, top_c + F) = target (g_c the
    cell's gap above the surface at offset dz), at most the deepest gap: Newton from F = 0 on
    that concave, piecewise-linear sum reaches the root from below."""
    held, _ = _added(dz, m, H, ci, cj, top, zc, 0.0)
    deepest = 0.0
    for c in range(m):
        deepest = max(deepest, zc[c] + dz - H[ci[c], cj[c]])
    if held >= target or deepest <= 0.0:
        return 0.0
    f = 0.0
    for _ in range(100):
        total = 0.0
        slope = 0
        for c in range(m):
            gap = zc[c] + dz - H[ci[c], cj[c]]  # below the bead's bottom, down to the surface
            if gap <= 0.0:
                total += max(0.0, gap + top[c])
            elif gap > f:
                total += top[c] + f
                slope += 1
            else:
                total += top[c] + gap
        if slope == 0 or total >= target * (1.0 - 1e-12):
            break
        f += (target - total) / slope
    return min(f, deepest)


@njit(cache=True)
def _place(kind, q0, q1, clip, w, h, budget, geom, code, n_exp, fusion, H, VB, VT, ox, oy, voxel, hang, dz_hang,
           ceiling, ci, cj, top, zc):
    """Land one element of ``budget`` mm^3 (module docstring). Returns the cell count (0: no
    cell), the offset, the foot, the drawn width and height, and whether it hangs (a bridge);
    the cells of the drawn section are left in ci, cj, top, zc."""
    nx, ny = H.shape
    cell = voxel * voxel
    m = _collect(kind, q0, q1, clip, w, h, code, n_exp, ox, oy, voxel, nx, ny, H, ci, cj, top, zc)
    if m == 0:
        return 0, 0.0, 0.0, w, h, False
    sum_top = 0.0
    for c in range(m):
        sum_top += top[c]
    # the footprint's cells hold sum_top * cell of the section on a flat surface: scale the
    # budget so that a bead on a flat surface lands exactly at its programmed bottom
    ratio = geom / (sum_top * cell)
    target = budget / (ratio * cell)
    depth = fusion if fusion >= 0.0 else h
    dz, foot = _free(m, H, ci, cj, top, zc, depth, target, VB, VT)
    if hang and dz_hang > dz:
        return m, dz_hang, _hang_foot(m, H, ci, cj, top, zc, dz_hang, target), w, h, True
    if not ceiling < np.inf:
        return m, dz, foot, w, h, False
    crown = -np.inf
    for c in range(m):
        crown = max(crown, zc[c] + dz + top[c])
    if crown <= ceiling + 1e-9 * max(1.0, abs(ceiling)):
        return m, dz, foot, w, h, False
    # The nozzle bounds the top: the bead is pressed onto the surface at its programmed bottom
    # or below it (not lifted by the neighbour it overlaps: that material goes sideways),
    # flattened to the gap between that bottom and the tip and spread sideways until its cells
    # hold the budget (a cap spreads in both directions).
    dz_s = min(dz, 0.0)
    squeezed = ceiling - (zc[0] + dz_s)
    if squeezed <= MIN_SQUISH_RATIO * h:
        return m, dz, foot, w, h, False  # the part has grown into the nozzle: it grows freely
    power = 0.5 if kind == CAP else 1.0
    widest = MAX_SQUISH_WIDTHS * w
    wq = min(w * (h / squeezed) ** power, widest)
    lo = -1.0  # widest width known to hold too little, narrowest known to hold enough
    hi = -1.0
    for _ in range(40):
        m = _collect(kind, q0, q1, clip, wq, squeezed, code, n_exp, ox, oy, voxel, nx, ny, H, ci, cj, top, zc)
        if m == 0:
            break
        sum_q = 0.0
        for c in range(m):
            sum_q += top[c]
        per_cell = geom * (wq / w) ** (2.0 if kind == CAP else 1.0) * (squeezed / h) / sum_q
        filled, _ = _added(dz_s, m, H, ci, cj, top, zc, depth)
        held = filled * per_cell
        # the cells enter the footprint one by one: within half a voxel of the width that holds
        # the budget, the narrowest that holds enough is the answer
        if abs(held - budget) <= SQUISH_TOL * budget or (held >= budget and lo >= 0.0 and wq - lo <= 0.5 * voxel):
            return m, dz_s, _foot(m, H, ci, cj, top, zc, depth, dz_s), wq, squeezed, False
        if held < budget:
            lo = wq
            if wq >= widest:
                # no room beside it either: the rest raises the widest flattened bead
                dz_w, foot_w = _free(m, H, ci, cj, top, zc, depth, budget / per_cell, VB, VT)
                return m, dz_w, foot_w, wq, squeezed, False
        else:
            hi = wq
        guess = wq * (budget / max(held, 1e-300 * budget)) ** power
        if lo >= 0.0 and hi >= 0.0 and not (lo < guess < hi):
            guess = 0.5 * (lo + hi)
        wq = min(guess, widest)
    m = _collect(kind, q0, q1, clip, w, h, code, n_exp, ox, oy, voxel, nx, ny, H, ci, cj, top, zc)
    return m, dz, foot, w, h, False


@njit(cache=True)
def _commit(m, H, ci, cj, top, zc, dz, foot, void_depth, VB, VT):
    """Put a landed element's cells on the height field. Besides the surface ``H`` every column
    keeps the one void it may have just below its surface (bottom ``VB``, top ``VT``; -inf:
    none), left where a gap was deeper than the melt reaches or under a bridge."""
    for c in range(m):
        i = ci[c]
        j = cj[c]
        bottom = zc[c] + dz
        below = bottom - foot
        if VT[i, j] > below:  # the foot fills the void's upper part, or all of it
            if below > VB[i, j]:
                VT[i, j] = below
            else:
                VB[i, j] = -np.inf
                VT[i, j] = -np.inf
        if bottom + top[c] > H[i, j]:
            if bottom - void_depth > H[i, j]:
                VB[i, j] = H[i, j]
                VT[i, j] = bottom - void_depth
            H[i, j] = bottom + top[c]


@njit(cache=True)
def _emit(n_out, k, fa, fb, dz, foot, standoff, added, reason, w, h, landed, tol, merge,
          o_parent, o_fa, o_fb, o_dz, o_foot, o_standoff, o_added, o_reason, o_w, o_h, o_landed):
    """Write one landed stretch, joined to the one before where they continue each other and
    landed alike. Returns the new count, -1 when the output is full."""
    if merge and n_out > 0:
        p = n_out - 1
        if (o_parent[p] == k and o_fb[p] == fa and o_reason[p] == reason and o_landed[p] == landed
                and abs(o_dz[p] - dz) <= tol and abs(o_foot[p] - foot) <= tol and abs(o_w[p] - w) <= tol
                and abs(o_h[p] - h) <= tol):
            a = o_fb[p] - o_fa[p]
            b = fb - fa
            o_dz[p] = (a * o_dz[p] + b * dz) / (a + b)
            o_w[p] = (a * o_w[p] + b * w) / (a + b)
            o_h[p] = (a * o_h[p] + b * h) / (a + b)
            o_foot[p] = max(o_foot[p], foot)
            o_fb[p] = fb
            o_added[p] += added
            return n_out
    if n_out >= o_parent.shape[0]:
        return -1
    o_parent[n_out] = k
    o_fa[n_out] = fa
    o_fb[n_out] = fb
    o_dz[n_out] = dz
    o_foot[n_out] = foot
    o_standoff[n_out] = standoff
    o_added[n_out] = added
    o_reason[n_out] = reason
    o_w[n_out] = w
    o_h[n_out] = h
    o_landed[n_out] = landed
    return n_out + 1


@njit(cache=True)
def _land(kind, p0, p1, clip, width, height, volume, geom_volume, landable, cont, ceiling, span, code, n_exp,
          fusion, max_drop, piece_widths, strands, H, ox, oy, voxel, standoff0, cat_on, eta0, focus, sigma, eta_ref,
          ci, cj, top, zc, status, level, o_parent, o_fa, o_fb, o_dz, o_foot, o_standoff, o_added, o_reason,
          o_w, o_h, o_landed):
    """Land the elements in order (module docstring), every piece stretch by stretch. Returns
    the number of stretches written, -1 when the output arrays are too small."""
    nx, ny = H.shape
    VB = np.full((nx, ny), -np.inf)
    VT = np.full((nx, ny), -np.inf)
    q0 = np.empty(3)
    q1 = np.empty(3)
    pt = np.empty(3)
    tol = MERGE_VOXELS * voxel
    n_out = 0
    support_behind = False  # the pieces continuing into this one rest on a support somewhere
    gap_behind = 0.0  # ... this far back along the path
    dz_behind = 0.0  # ... where the last supported stretch landed at this offset
    last_end = np.full(3, np.nan)  # where the last stretch landed ends (programmed), and its offset
    last_dz = 0.0
    last_foot = 0.0  # ... its foot, drawn section and element
    last_w = 0.0
    last_h = 0.0
    last_k = -1
    pending = -1  # a stretch without a cell of its own, written before the stretch it joins landed
    pend_end = np.full(3, np.nan)  # ... where it ends (programmed)
    for k in range(kind.shape[0]):
        if kind[k] != CAP and not (cont[k] and landable[k]):
            support_behind = False
            gap_behind = 0.0
        if not landable[k]:
            n_out = _emit(n_out, k, 0.0, 1.0, 0.0, 0.0, 0.0, volume[k], 0, width[k], height[k], False, tol, False,
                          o_parent, o_fa, o_fb, o_dz, o_foot, o_standoff, o_added, o_reason, o_w, o_h, o_landed)
            if n_out < 0:
                return -1
            continue
        if kind[k] == CAP:
            _point(SEGMENT, p0[k], p0[k], 0.0, pt)
            standoff = standoff0 + pt[2] - _surface(H, pt[0], pt[1], ox, oy, voxel)
            budget = volume[k]
            if cat_on:
                budget *= eta0 * math.exp(-((standoff - focus) ** 2) / (2.0 * sigma * sigma)) / eta_ref
            # a cap at the end of a stretch stays with it (it is the same strand's round end); one
            # over a surface that supports it rests on it, at most at its programmed bottom
            hold = -np.inf
            if strands and (abs(last_end[0] - p0[k, 0]) <= 1e-6 and abs(last_end[1] - p0[k, 1]) <= 1e-6
                    and abs(last_end[2] - p0[k, 2]) <= 1e-6):
                hold = last_dz
            reach = SUPPORT_DEPTH * height[k]
            below = standoff0 + pt[2] - standoff
            if strands and below < pt[2] - reach:
                # or beside it, in any direction, within its radius
                for q in range(1, int(0.5 * width[k] / voxel) + 2):
                    for a in range(8):
                        u = q * voxel
                        below = max(below, _surface(H, pt[0] + u * math.cos(a * math.pi / 4),
                                                    pt[1] + u * math.sin(a * math.pi / 4), ox, oy, voxel))
            if strands and below >= pt[2] - reach:
                hold = max(hold, min(below - pt[2], 0.0))
            m, dz, foot, w, h, hanging = _place(kind[k], p0[k], p1[k], clip[k], width[k], height[k], budget,
                                                geom_volume[k], code, n_exp, fusion, H, VB, VT, ox, oy, voxel,
                                                hold > -np.inf, hold, ceiling[k], ci, cj, top, zc)
            reason = 0
            if m > 0 and budget > 0.0:
                if dz < -max_drop:
                    reason = LOST_FELL_OFF
                    dz = 0.0
                    foot = 0.0
                else:
                    _commit(m, H, ci, cj, top, zc, dz, foot, foot if hanging else (fusion if fusion >= 0.0 else h),
                            VB, VT)
            else:
                dz, foot, w, h = 0.0, 0.0, width[k], height[k]
            n_out = _emit(n_out, k, 0.0, 1.0, dz, foot, standoff, budget if reason == 0 else 0.0, reason, w, h,
                          True, tol, False, o_parent, o_fa, o_fb, o_dz, o_foot, o_standoff, o_added, o_reason, o_w,
                          o_h, o_landed)
            if n_out < 0:
                return -1
            continue
        length = _piece_length(kind[k], p0[k], p1[k])
        ns = min(max(1, int(math.ceil(length / voxel))), status.shape[0])
        reach = SUPPORT_DEPTH * height[k]
        for i in range(ns):
            status[i], level[i] = _sample(kind[k], p0[k], p1[k], (i + 0.5) / ns, width[k], reach, strands, H, ox,
                                          oy, voxel, pt)
        jump = max(JUMP_VOXELS * voxel, JUMP_HEIGHTS * height[k])
        piece_max = max(piece_widths * width[k], voxel)
        i = 0
        while i < ns:
            j = i + 1
            while j < ns and status[j] == status[i] and abs(level[j] - level[j - 1]) <= jump:
                j += 1
            fa_run = i / ns
            fb_run = 1.0 if j == ns else j / ns
            run = (fb_run - fa_run) * length
            held = False
            free_end = False  # held from one side only, at that side's level
            dz_end = 0.0
            left = gap_behind
            total = 0.0
            dz_right = 0.0
            if status[i] == BESIDE:
                held = True  # hanging on what is beside it, at most at its programmed bottom
            elif status[i] == GAP:
                # a gap: held as a bridge between the supports on either side when they are
                # within the bridge span, a free end when its one support is within half of it,
                # else the material drops onto what is below
                right = -1.0
                for jj in range(j, ns):
                    if status[jj] != GAP:
                        _point(kind[k], p0[k], p1[k], (jj + 0.5) / ns, pt)
                        right = (jj / ns - fb_run) * length
                        dz_right = level[jj] - pt[2]
                        break
                if right < 0.0:
                    need = span[k] - left - run - (1.0 - fb_run) * length
                    if need >= 0.0:
                        d, dz_right = _support_ahead(k, need, kind, p0, p1, width, height, landable, cont, strands,
                                                     H, ox, oy, voxel, pt)
                        if d >= 0.0:
                            right = (1.0 - fb_run) * length + d
                dz_right = min(dz_right, 0.0)
                if right >= 0.0 and support_behind:
                    total = left + run + right
                    held = total <= span[k]
                elif right >= 0.0 and strands:
                    free_end = left + run + right <= 0.5 * span[k]
                    dz_end = dz_right
                elif support_behind and strands:
                    free_end = left + run <= 0.5 * span[k]
                    dz_end = dz_behind
            n_p = max(1, int(math.ceil(run / piece_max - 1e-9)))
            for p in range(n_p):
                fa = fa_run + (fb_run - fa_run) * p / n_p
                fb = fb_run if p + 1 == n_p else fa_run + (fb_run - fa_run) * (p + 1) / n_p
                _sub_piece(kind[k], p0[k], p1[k], fa, fb, q0, q1)
                # the standoff over the stretch's middle: its start may lie on the cell of the
                # stretch before, which has just landed
                _point(kind[k], p0[k], p1[k], 0.5 * (fa + fb), pt)
                standoff = standoff0 + pt[2] - _surface(H, pt[0], pt[1], ox, oy, voxel)
                budget = volume[k] * (fb - fa)
                if cat_on:
                    budget *= eta0 * math.exp(-((standoff - focus) ** 2) / (2.0 * sigma * sigma)) / eta_ref
                dz_hang = 0.0
                if status[i] == BESIDE:
                    at = min(int(0.5 * (fa + fb) * ns), ns - 1)
                    _point(kind[k], p0[k], p1[k], 0.5 * (fa + fb), pt)
                    dz_hang = min(level[at] - pt[2], 0.0)
                elif free_end:
                    dz_hang = dz_end
                elif held:
                    t = (left + (p + 0.5) / n_p * run) / total
                    sag = SAG_HEIGHTS * height[k] * (total / span[k]) ** 2 * 4.0 * t * (1.0 - t)
                    dz_hang = dz_behind + (dz_right - dz_behind) * t - sag
                m, dz, foot, w, h, hanging = _place(kind[k], q0, q1, clip[k], width[k], height[k], budget,
                                                    geom_volume[k] * (fb - fa), code, n_exp, fusion, H, VB, VT, ox,
                                                    oy, voxel, held or free_end, dz_hang, ceiling[k], ci, cj, top, zc)
                reason = 0
                merge = True
                _point(kind[k], p0[k], p1[k], fa, pt)
                if fa == 0.0 and kind[k] == SEGMENT:
                    pt[:] = p0[k]
                if m > 0 and budget > 0.0:
                    if dz < -max_drop:
                        reason = LOST_BEYOND_SPAN if support_behind and status[i] == GAP else LOST_FELL_OFF
                        dz = 0.0
                        foot = 0.0
                    else:
                        void_depth = foot if hanging else (fusion if fusion >= 0.0 else h)
                        _commit(m, H, ci, cj, top, zc, dz, foot, void_depth, VB, VT)
                        if pending >= 0 and _same_point(pend_end, pt):
                            o_dz[pending], o_foot[pending], o_w[pending], o_h[pending] = dz, foot, w, h
                        last_dz, last_foot, last_w, last_h, last_k = dz, foot, w, h, k
                        _point(kind[k], p0[k], p1[k], fb, last_end)
                        if fb == 1.0 and kind[k] == SEGMENT:
                            last_end[:] = p1[k]
                        if status[i] != GAP:
                            dz_behind = min(dz, 0.0)  # a bridge hangs at most at its programmed bottom
                    pending = -1
                elif budget > 0.0:
                    # A stretch shorter than a cell holds no cell centre (a piece cut where the
                    # surface under it changes, or where ramp pieces meet): the height field
                    # cannot land it, but drawn where programmed it would sink into the part it
                    # overlaps and its material vanish in the union. It goes with its
                    # neighbours along the path: the stretch it continues, else the one that
                    # continues it (patched when that lands).
                    if _same_point(last_end, pt):
                        dz, foot = last_dz, last_foot
                        if last_k == k:
                            w, h = last_w, last_h
                        else:
                            w, h = width[k], height[k]
                        _point(kind[k], p0[k], p1[k], fb, last_end)
                        if fb == 1.0 and kind[k] == SEGMENT:
                            last_end[:] = p1[k]
                    else:
                        dz, foot, w, h = 0.0, 0.0, width[k], height[k]
                        pending = n_out
                        merge = False
                        _point(kind[k], p0[k], p1[k], fb, pend_end)
                        if fb == 1.0 and kind[k] == SEGMENT:
                            pend_end[:] = p1[k]
                else:
                    # carrying nothing: drawn where programmed
                    dz, foot, w, h = 0.0, 0.0, width[k], height[k]
                n_out = _emit(n_out, k, fa, fb, dz, foot, standoff, budget if reason == 0 else 0.0, reason, w, h,
                              True, tol, merge, o_parent, o_fa, o_fb, o_dz, o_foot, o_standoff, o_added, o_reason,
                              o_w, o_h, o_landed)
                if n_out < 0:
                    return -1
            if status[i] != GAP:
                support_behind = True
                gap_behind = 0.0
            else:
                gap_behind += run
            i = j
    return n_out


@njit(cache=True)
def _same_point(a, b):
    return abs(a[0] - b[0]) <= 1e-6 and abs(a[1] - b[1]) <= 1e-6 and abs(a[2] - b[2]) <= 1e-6


@njit(cache=True)
def _foot(m, H, ci, cj, top, zc, depth, dz):
    """How far the element's section must reach below its bottom: its deepest filled gap."""
    foot = 0.0
    for c in range(m):
        bottom = zc[c] + dz
        g = bottom - H[ci[c], cj[c]]
        if g > 0.0 and bottom + top[c] > H[ci[c], cj[c]]:
            foot = max(foot, min(g, depth))
    return foot


@njit(cache=True)
def _refill(m, ci, cj, zc, dz, foot, VB, VT):
    """Void (in cell-area units) that a foot of depth ``foot`` fills below the surface."""
    total = 0.0
    for c in range(m):
        i = ci[c]
        j = cj[c]
        if VT[i, j] == -np.inf:
            continue
        bottom = zc[c] + dz
        total += max(0.0, min(VT[i, j], bottom) - max(VB[i, j], bottom - foot))
    return total


def _geometric_volumes(beads: Beads) -> np.ndarray:
    """Each element's own volume on a flat surface: section area times horizontal length, the
    arc's by Pappus, the cap's revolved."""
    out = np.empty(len(beads))
    code, n = beads.code, beads.exponent
    for k in range(len(beads)):
        w, h = beads.width[k], beads.height[k]
        if h <= 0:
            out[k] = 0.0
        elif beads.kind[k] == CAP:
            out[k] = revolved_volume(code, w, h, n) * _cap_share(beads.clip[k])
        elif beads.kind[k] == ARC:
            out[k] = profile_area(code, w, h, n) * beads.p1[k, 0] * abs(beads.p1[k, 2])
        else:
            out[k] = profile_area(code, w, h, n) * math.hypot(*(beads.p1[k, :2] - beads.p0[k, :2]))
    return out


def _cap_share(clip: np.ndarray) -> float:
    """The share of the whole revolved section a cut cap keeps: the angle between its cuts over
    a full turn (half for one cut, all for none)."""
    a, b = clip[:3], clip[3:]
    if not a.any() and not b.any():
        return 1.0
    if not a.any() or not b.any():
        return 0.5
    cos_phi = float(np.clip(np.dot(a, b) / (np.linalg.norm(a) * np.linalg.norm(b)), -1.0, 1.0))
    return (math.pi - math.acos(cos_phi)) / (2 * math.pi)


def _continues(beads: Beads) -> np.ndarray:
    """Pieces (not caps) that start where the piece before them ends, when it ends: the path
    goes on, so a bridge may rest on a support behind them."""
    m = len(beads)
    out = np.zeros(m, bool)
    pieces = np.flatnonzero(beads.kind != CAP)
    if pieces.size < 2:
        return out
    end = beads.p1.copy()
    arcs = beads.kind == ARC
    if arcs.any():
        angle = beads.p1[arcs, 1] + beads.p1[arcs, 2]
        end[arcs] = beads.p0[arcs] + np.column_stack([beads.p1[arcs, 0] * np.cos(angle),
                                                      beads.p1[arcs, 0] * np.sin(angle), np.zeros(arcs.sum())])
    start = beads.p0.copy()
    if arcs.any():
        angle = beads.p1[arcs, 1]
        start[arcs] = beads.p0[arcs] + np.column_stack([beads.p1[arcs, 0] * np.cos(angle),
                                                        beads.p1[arcs, 0] * np.sin(angle), np.zeros(arcs.sum())])
    a, b = pieces[:-1], pieces[1:]
    out[b] = (np.abs(start[b] - end[a]).max(axis=1) <= 1e-6) & (np.abs(beads.t0[b] - beads.t1[a]) <= 1e-9)
    return out


def bridge_span(settings: LandingSettings, width: np.ndarray) -> np.ndarray:
    """The longest gap each element's bead spans (``--bridge-span``, else the process's
    default: ``FILAMENT_BRIDGE_SPAN_MM`` for filament, ``MELT_BRIDGE_WIDTHS`` bead widths for a
    powder or wire melt pool)."""
    if settings.bridge_span_mm is not None:
        return np.full(width.shape, float(settings.bridge_span_mm))
    if settings.filament:
        return np.full(width.shape, FILAMENT_BRIDGE_SPAN_MM)
    return MELT_BRIDGE_WIDTHS * np.asarray(width, np.float64)


def land(beads: Beads, voxel: float, settings: LandingSettings,
         nozzle: np.ndarray | None = None) -> tuple[Beads, Landing]:
    """Land ``beads`` on the part as it stands (module docstring); the landed beads (lost ones
    removed, the others moved, footed and, under a filament nozzle, flattened) and where each
    stretch went. ``nozzle``: per element, the nozzle tip's height above the programmed bead
    bottom (used with ``settings.filament``: the tip bounds the bead's top)."""
    settings.validate()
    m = len(beads)
    vertical = np.abs(beads.up[:, 2] - 1.0) <= _UP_TOL
    landable = vertical & (beads.height > 0)
    bottoms = beads.p0[:, 2]
    plate = float(bottoms.min()) if settings.plate_z is None and m else float(settings.plate_z or 0.0)
    squish = settings.filament and nozzle is not None
    reach = np.maximum(0.5 * beads.width * (MAX_SQUISH_WIDTHS if squish else 1.0), 0.0)
    lo = np.full(2, np.inf)
    hi = np.full(2, -np.inf)
    for part in (beads.p0[:, :2], np.where((beads.kind == SEGMENT)[:, None], beads.p1[:, :2], beads.p0[:, :2])):
        lo = np.minimum(lo, (part - reach[:, None]).min(axis=0, initial=np.inf))
        hi = np.maximum(hi, (part + reach[:, None]).max(axis=0, initial=-np.inf))
    arcs = beads.kind == ARC
    if arcs.any():
        r = (beads.p1[arcs, 0] + reach[arcs])[:, None]
        lo = np.minimum(lo, (beads.p0[arcs, :2] - r).min(axis=0))
        hi = np.maximum(hi, (beads.p0[arcs, :2] + r).max(axis=0))
    origin = np.floor(lo / voxel) * voxel - voxel
    shape = (int(np.ceil((hi[0] - origin[0]) / voxel)) + 2, int(np.ceil((hi[1] - origin[1]) / voxel)) + 2)
    # footprint cells of the largest stretch: a strip of its length (at most PIECE_WIDTHS bead
    # widths, an arc's a little more) and its widest section, plus its border; a cap's square
    w_max = 2.0 * reach + 2 * voxel
    piece = np.maximum(PIECE_WIDTHS * beads.width, voxel) * 1.5 + 2 * voxel
    bound = np.where(beads.kind == CAP, w_max**2, (piece + w_max) * w_max) / voxel**2 + 4 * w_max / voxel + 8
    size = int(bound.max(initial=0.0)) + 16
    ci = np.empty(size, np.int64)
    cj = np.empty(size, np.int64)
    top = np.empty(size)
    zc = np.empty(size)
    length = np.where(beads.kind == SEGMENT, np.hypot(*(beads.p1[:, :2] - beads.p0[:, :2]).T),
                      np.where(arcs, beads.p1[:, 0] * np.abs(beads.p1[:, 2]), 0.0))
    samples = int(np.ceil(length.max(initial=0.0) / voxel)) + 1
    status = np.empty(samples, np.uint8)
    level = np.empty(samples)
    ceiling = np.full(m, np.inf)
    if squish:
        ceiling = beads.p0[:, 2] + np.asarray(nozzle, np.float64)
    span = bridge_span(settings, beads.width)
    cat = settings.catchment
    kernel_args = (beads.kind, np.ascontiguousarray(beads.p0), np.ascontiguousarray(beads.p1),
                   np.ascontiguousarray(beads.clip), beads.width, beads.height, beads.volume, _geometric_volumes(beads),
                   landable, _continues(beads), ceiling, span, beads.code, beads.exponent,
                   -1.0 if settings.fusion_depth_mm is None else float(settings.fusion_depth_mm),
                   float(settings.max_drop_mm), PIECE_WIDTHS, bool(settings.filament))
    # every piece lands as at least ceil(length / piece_max) stretches, one more per change of
    # the surface under it; sized so a pass rarely runs out (a rerun lands everything again)
    stretches = np.where(beads.kind == CAP, 1.0, np.ceil(length / np.maximum(PIECE_WIDTHS * beads.width, voxel)))
    capacity = int(stretches.sum()) + m + 1024
    while True:
        out = (np.empty(capacity, np.int64), np.empty(capacity), np.empty(capacity), np.empty(capacity),
               np.empty(capacity), np.empty(capacity), np.empty(capacity), np.empty(capacity, np.uint8),
               np.empty(capacity), np.empty(capacity), np.empty(capacity, np.bool_))
        H = np.full(shape, plate, np.float64)
        n = _land(*kernel_args, H, float(origin[0]), float(origin[1]), float(voxel), float(settings.standoff_mm),
                  cat is not None, cat.eta0 if cat else 1.0, cat.focus if cat else 0.0, cat.sigma if cat else 1.0,
                  float(settings.nominal_catchment), ci, cj, top, zc, status, level, *out)
        if n >= 0:
            break
        capacity *= 2
    parent, fa, fb, dz, foot, standoff, added, reason, width, height, landed = (a[:n] for a in out)
    programmed = _stretches(beads, parent, fa, fb)
    shift = np.zeros((n, 3))
    shift[:, 2] = dz
    p1 = programmed.p1 + np.where((programmed.kind == ARC)[:, None], 0.0, shift)
    moved = dataclasses.replace(programmed, p0=programmed.p0 + shift, p1=p1, foot=foot, volume=added, width=width,
                                height=height, floor_z=plate)
    lost = reason != 0
    landing = Landing(dz=dz, foot=foot, standoff=standoff, added=added, lost=lost, landed=landed, plate_z=plate,
                      programmed=programmed, lost_volume=np.where(lost, programmed.volume, 0.0), reason=reason)
    return moved.take(~lost), landing


def _stretches(beads: Beads, parent: np.ndarray, fa: np.ndarray, fb: np.ndarray) -> Beads:
    """The stretches [fa, fb) of the elements ``parent`` as elements of their own, where the
    program puts them: material and time by the share of length (a piece's section and speed
    are constant along it)."""
    out = beads.take(parent)
    whole = (fa == 0.0) & (fb == 1.0)
    if whole.all():
        return out
    cut = np.flatnonzero(~whole)
    p0 = out.p0.copy()
    p1 = out.p1.copy()
    seg = cut[out.kind[cut] == SEGMENT]
    a, b = beads.p0[parent[seg]], beads.p1[parent[seg]]
    p0[seg] = a + fa[seg, None] * (b - a)
    p1[seg] = np.where((fb[seg] == 1.0)[:, None], b, a + fb[seg, None] * (b - a))
    arc = cut[out.kind[cut] == ARC]
    sweep = beads.p1[parent[arc], 2]
    p1[arc, 1] = beads.p1[parent[arc], 1] + fa[arc] * sweep
    p1[arc, 2] = (fb[arc] - fa[arc]) * sweep
    t0, t1 = beads.t0[parent], beads.t1[parent]
    share = fb - fa
    return dataclasses.replace(out, p0=p0, p1=p1, t0=t0 + fa * (t1 - t0), t1=t0 + fb * (t1 - t0),
                               volume=out.volume * share)


MAX_LINES_LISTED = 50
# |standoff change per layer| over the last third of the layers, against the first third
SETTLING_RATIO = 0.5
RUNAWAY_RATIO = 1.5


def growth_report(programmed: Beads, landing: Landing, layer: np.ndarray, line: np.ndarray,
                  lost: np.ndarray) -> dict:
    """Per-layer programmed and built heights, the standoff met and where material was lost.

    ``layer`` and ``line`` give each element's toolpath layer and source line; ``lost`` the
    elements (up to the moment reported) whose material never reached the part. Heights come from
    the pieces (caps are joints), weighted by their horizontal length:

    * ``programmed_z_mm``: the layer's programmed bead bottom;
    * ``built_top_mm``: mean, min and max of its beads' built tops (landed bottom + height);
    * ``drift_mm``: programmed top (programmed bottom + bead height) minus built top: positive
      when the part lags below the program (the standoff grows), negative when it outgrows it.
    """
    pieces = (programmed.kind != CAP) & landing.landed & ~landing.lost
    length = np.where(programmed.kind == SEGMENT, np.hypot(*(programmed.p1[:, :2] - programmed.p0[:, :2]).T),
                      programmed.p1[:, 0] * np.abs(programmed.p1[:, 2]))
    weight = np.where(pieces, length, 0.0)
    layers = []
    layer_standoff = []
    for k in np.unique(layer[pieces]):
        sel = pieces & (layer == k) & (weight > 0)
        if not sel.any():
            continue
        wsel = weight[sel]
        z_prog = programmed.p0[sel, 2]
        top_built = z_prog + landing.dz[sel] + programmed.height[sel]
        top_prog = z_prog + programmed.height[sel]
        layers.append({
            "layer": int(k),
            "programmed_z_mm": float(np.average(z_prog, weights=wsel)),
            "built_top_mm": {"mean": float(np.average(top_built, weights=wsel)), "min": float(top_built.min()),
                             "max": float(top_built.max())},
            "drift_mm": float(np.average(top_prog - top_built, weights=wsel)),
            "standoff_mm": float(np.average(landing.standoff[sel], weights=wsel)),
        })
        layer_standoff.append(layers[-1]["standoff_mm"])
    # the standoff the pieces met: a run's end cap lands after its own pieces, on its own bead,
    # so its standoff reads about a bead height short and would call a false crash
    met = pieces
    standoff = landing.standoff[met]
    order = np.argsort(programmed.t0[met], kind="stable")
    lost_lines = np.unique(line[lost])
    return {
        "layers": layers,
        "standoff_mm": ({"min": float(standoff.min()), "max": float(standoff.max()), "final": float(standoff[order[-1]])}
                        if standoff.size else None),
        "standoff_trend": standoff_trend(np.array(layer_standoff)),
        "lost_volume_mm3": float(programmed.volume[lost].sum()),
        "lost_lines": [int(v) for v in lost_lines[:MAX_LINES_LISTED]],
        "lost_line_count": int(lost_lines.size),
        "not_landed": int(np.count_nonzero(~landing.landed & (programmed.height > 0))),
    }


def standoff_trend(per_layer: np.ndarray, step_hint: float | None = None) -> str:
    """How the standoff evolves over the layers: ``steady`` (no change), ``settling`` (the
    change per layer shrinks: the self-stabilising catchment), ``drifting`` (a change that
    neither dies out nor keeps growing: growth per layer differs from the programmed step),
    ``runaway`` (the change grows layer after layer: growth feeding on its own error)."""
    if per_layer.size < 6:
        return "steady" if per_layer.size < 2 or np.ptp(per_layer) < 1e-6 else "drifting"
    change = np.abs(np.diff(per_layer))
    third = max(1, change.size // 3)
    first, last = change[:third].mean(), change[-third:].mean()
    scale = step_hint if step_hint else max(np.abs(per_layer).max(), 1.0)
    if max(first, last) <= 1e-4 * scale:
        return "steady"
    if last <= SETTLING_RATIO * first:
        return "settling"
    # runaway: the change grows layer after layer (until the catchment is gone and it stays at the
    # programmed step), not a jump from one kind of layer to another
    growing = np.all(np.diff(change) >= -0.02 * change.max())
    if growing and last >= RUNAWAY_RATIO * first:
        return "runaway"
    return "drifting"
