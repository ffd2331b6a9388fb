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
  reported lost, and it is not drawn.

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
from ..errors import DmdvoxError
from .beads import ARC, CAP, SEGMENT, Beads
from .profiles import profile_area, profile_top, revolved_volume

# Coaxial powder nozzles keep their powder focus (catchment within a few % of its best) over about
# +-1 mm; a bead whose programmed bottom is more than twice that above the surface does not form.
DEFAULT_MAX_DROP_MM = 2.0
_UP_TOL = 1e-9


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

    def validate(self) -> None:
        if not (self.max_drop_mm > 0):  # inf: nothing is ever lost
            raise DmdvoxError(f"--max-drop must be a positive distance in mm, got {self.max_drop_mm!r}")
        if not (np.isfinite(self.standoff_mm) and self.standoff_mm >= 0):
            raise DmdvoxError(f"--standoff must be a distance >= 0 mm, got {self.standoff_mm!r}")
        if self.fusion_depth_mm is not None and not (np.isfinite(self.fusion_depth_mm) and self.fusion_depth_mm >= 0):
            raise DmdvoxError(f"--fusion-depth must be a distance >= 0 mm, got {self.fusion_depth_mm!r}")
        if self.plate_z is not None and not np.isfinite(self.plate_z):
            raise DmdvoxError(f"--plate must be a finite height in mm, got {self.plate_z!r}")


@dataclass(frozen=True, eq=False)
class Landing:
    """Where every element landed: its offset along the up axis, the foot drawn below it, the
    standoff it met, the material it added (0 where lost) and whether it was lost."""

    dz: np.ndarray  # (m,) float64 mm, solved bottom minus programmed bottom
    foot: np.ndarray  # (m,) float64 mm
    standoff: np.ndarray  # (m,) float64 mm, nozzle tip to the surface below, before landing
    added: np.ndarray  # (m,) float64 mm^3
    lost: np.ndarray  # (m,) bool
    landed: np.ndarray  # (m,) bool: solved on the height field (False: tilted, drawn as programmed)
    plate_z: float


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
def _land(kind, p0, p1, clip, width, height, volume, geom_volume, landable, code, n_exp, fusion, max_drop,
          H, ox, oy, voxel, standoff0, cat_on, eta0, focus, sigma, eta_ref, ci, cj, top, zc,
          out_dz, out_foot, out_standoff, out_added, out_lost):
    """Land the elements in order (module docstring). Besides the surface ``H`` every column
    keeps the one void it may have just below its surface (bottom ``VB``, top ``VT``; -inf: none),
    left where a gap was deeper than the melt reaches."""
    nx, ny = H.shape
    VB = np.full((nx, ny), -np.inf)
    VT = np.full((nx, ny), -np.inf)
    cell = voxel * voxel
    for k in range(kind.shape[0]):
        if not landable[k]:
            continue
        m = _collect(kind[k], p0[k], p1[k], clip[k], width[k], height[k], code, n_exp, ox, oy, voxel, nx, ny, H,
                     ci, cj, top, zc)
        # the standoff the element meets: from the nominal nozzle tip over its start to the surface
        px = p0[k, 0]
        py = p0[k, 1]
        pz = p0[k, 2]
        if kind[k] == ARC:
            px = p0[k, 0] + p1[k, 0] * math.cos(p1[k, 1])
            py = p0[k, 1] + p1[k, 0] * math.sin(p1[k, 1])
        ii = min(max(int(round((px - ox) / voxel)), 0), nx - 1)
        jj = min(max(int(round((py - oy) / voxel)), 0), ny - 1)
        standoff = standoff0 + pz - H[ii, jj]
        out_standoff[k] = standoff
        budget = volume[k]
        if cat_on:
            budget *= eta0 * math.exp(-((standoff - focus) ** 2) / (2.0 * sigma * sigma)) / eta_ref
        if m == 0 or budget <= 0.0:
            # smaller than a cell, or carrying nothing: drawn where programmed (its own volume
            # is below the resolution of the height field)
            out_added[k] = budget
            continue
        sum_top = 0.0
        for c in range(m):
            sum_top += top[c]
        # the footprint's cells hold sum_top * cell of the section on a flat surface: scale the
        # budget so that a bead on a flat surface lands exactly at its programmed bottom
        target = budget * (sum_top * cell / geom_volume[k]) / cell
        depth = fusion if fusion >= 0.0 else height[k]
        # The drawn foot has one depth (the deepest gap it fills) under the whole element, so
        # where the gap is smaller it reaches below the surface: into solid, or into a void an
        # earlier bead left (lack of fusion), which it then fills. That material counts too.
        refill = 0.0
        for _ in range(4):
            dz = _solve(m, H, ci, cj, top, zc, depth, target - refill)
            foot = _foot(m, H, ci, cj, top, zc, depth, dz)
            again = _refill(m, ci, cj, zc, dz, foot, VB, VT)
            if abs(again - refill) <= 1e-9 * max(target, 1.0):
                break
            refill = min(again, target)
        if dz < -max_drop:
            out_lost[k] = True
            out_dz[k] = 0.0
            continue
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
                if bottom - depth > H[i, j]:  # a gap deeper than the melt reaches: a void stays
                    VB[i, j] = H[i, j]
                    VT[i, j] = bottom - depth
                H[i, j] = bottom + top[c]
        out_dz[k] = dz
        out_foot[k] = foot
        out_added[k] = budget


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


def land(beads: Beads, voxel: float, settings: LandingSettings) -> tuple[Beads, Landing]:
    """Land ``beads`` on the part as it stands (module docstring); the landed beads (lost ones
    removed, the others moved and footed) and where each element went."""
    settings.validate()
    m = len(beads)
    vertical = np.abs(beads.up[:, 2] - 1.0) <= _UP_TOL
    landable = vertical & (beads.height > 0)
    bottoms = beads.p0[:, 2]
    plate = float(bottoms.min()) if settings.plate_z is None and m else float(settings.plate_z or 0.0)
    reach = np.maximum(0.5 * beads.width, 0.0)
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
    H = np.full(shape, plate, np.float64)
    # footprint cells of the largest element: a strip of its length and width, plus its border
    length = np.where(beads.kind == SEGMENT, np.hypot(*(beads.p1[:, :2] - beads.p0[:, :2]).T), 0.0)
    length = np.where(arcs, beads.p1[:, 0] * np.abs(beads.p1[:, 2]) + beads.width, length)
    bound = ((length + beads.width + 2 * voxel) * (beads.width + 2 * voxel) / voxel**2
             + 2 * (length + beads.width) / voxel + 8)
    cap_bound = (beads.p1[:, 0] + beads.width + 2 * voxel) ** 2 * 4 / voxel**2
    size = int(max(bound.max(initial=0.0), np.where(arcs, cap_bound, 0.0).max(initial=0.0))) + 16
    ci = np.empty(size, np.int64)
    cj = np.empty(size, np.int64)
    top = np.empty(size)
    zc = np.empty(size)
    dz = np.zeros(m)
    foot = np.zeros(m)
    standoff = np.zeros(m)
    added = np.zeros(m)
    lost = np.zeros(m, bool)
    cat = settings.catchment
    _land(beads.kind, np.ascontiguousarray(beads.p0), np.ascontiguousarray(beads.p1), np.ascontiguousarray(beads.clip),
          beads.width, beads.height, beads.volume, _geometric_volumes(beads), landable, beads.code, beads.exponent,
          -1.0 if settings.fusion_depth_mm is None else float(settings.fusion_depth_mm), float(settings.max_drop_mm),
          H, float(origin[0]), float(origin[1]), float(voxel), float(settings.standoff_mm), cat is not None,
          cat.eta0 if cat else 1.0, cat.focus if cat else 0.0, cat.sigma if cat else 1.0,
          float(settings.nominal_catchment), ci, cj, top, zc, dz, foot, standoff, added, lost)
    added[~landable] = beads.volume[~landable]
    shift = np.zeros((m, 3))
    shift[:, 2] = dz
    p1 = beads.p1 + np.where((beads.kind == ARC)[:, None], 0.0, shift)
    moved = dataclasses.replace(beads, p0=beads.p0 + shift, p1=p1, foot=foot, volume=added, floor_z=plate)
    landing = Landing(dz=dz, foot=foot, standoff=standoff, added=added, lost=lost, landed=landable, plate_z=plate)
    return moved.take(~lost), landing


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
