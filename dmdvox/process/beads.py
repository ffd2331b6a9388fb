"""The beads a toolpath lays: pieces along the deposit rows and caps at their joints and ends.

Every deposit row is cut into **pieces** of constant cross-section (a straight extrusion of the
profile, or an exact G17 arc bead), and every joint and end gets a **cap**: the profile
revolved about the bead's up axis through that point, so corners and U-turns are round at any
angle. The deposit engine sweeps these elements; the landing model (:mod:`.landing`) may first
move them onto the part as it stands.

Cross-section along a row:

* fixed bead (no material source): the profile at ``--width`` x ``--height`` (or the slicer's
  ``;WIDTH:`` / ``;HEIGHT:``), one piece per row (chords for helices and spirals);
* material from E words: ``A = volume / length``, one piece per row;
* material from a rate source (powder, wire): ``A(s) = Q / v(s)`` with ``v(s)`` the planned
  speed. Each acceleration and deceleration part, however short, is sampled at at least
  ``MIN_RAMP_PIECES`` speeds and wherever the speed changes by ``AREA_STEP``, each piece
  carrying exactly the material ``Q dt`` delivered over it, so the excess of a corner or a stop
  (``A0 (v - v_j)^2 / a``) sits on the ramps beside it and the cruise keeps ``Q / F`` (a short
  ramp merged into its row spread it along the row: 2.3 % too much section on a 20 mm side
  between stops). Laid on a grid, consecutive ramp pieces join up to one voxel long, and a
  whole ramp shorter than that takes in the cruise up to a voxel: the height field cannot show
  a shorter piece (it sees the part through the cells whose centres a piece holds), and drawn
  over less than a cell a tall piece stands proud of its neighbours. The cruise is cut half a
  bead width from each end of the row, where the joints' wedges take their material. Where the
  tool is slower than ``FLOOR_RATIO`` times the row's peak speed (the last stretch before a
  stop, the first after one) the material would pile on a vanishing length: it collects in the
  cap at that point instead. A beam-on dwell of ``t`` is a drop of its own where the tool
  stood: the profile revolved, whole, holding ``Q t``. Blobs stand no higher than
  ``BLOB_ASPECT`` times their width (the wetting limit): a larger one spreads wider. Volume is
  conserved exactly; nothing spikes.

At a joint the cap's outer wedge (the profile revolved through the turn) holds material taken,
half from each side, from the pieces within half a bead width of the joint, where the two
beads overlap (:func:`_take_wedges`); no piece gives more than ``WEDGE_SHARE`` of its own.

The width is the melt-pool width (``--width``, else the row's ``;WIDTH:``, else for E-fed
slicer files the width the material gives at the layer height); the height follows from the
area and the profile's shape (``A = k w h``: rect 1, ellipse pi/4, parabola 2/3, cosine 2/pi).

Bottom: the path point is the bead bottom, except where the dialect's Z is the layer top
(slicers): there the bottom is Z minus the layer height (the row's ``;HEIGHT:``, else the layer
step, else the bead's own height).
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass

import numpy as np
from numba import njit

from ..errors import DmdvoxError
from ..toolpath.geometry import arc_chord_counts, arc_points
from ..toolpath.model import Toolpath
from .flow import Flow
from .profiles import ARC as ARC_PROFILE
from .profiles import PROFILE_CODES, BeadProfile, profile_area, revolved_volume

SEGMENT = np.uint8(0)
CAP = np.uint8(1)
ARC = np.uint8(2)

FLOOR_RATIO = 0.25  # below a quarter of the row's peak speed the material collects in the cap
AREA_STEP = 1.1  # consecutive pieces of a speed ramp differ by at most 10 % in area
MIN_RAMP_PIECES = 8  # ... and every ramp has at least this many
WEDGE_SHARE = 0.5  # the most of its material an element gives to the wedges of the joints beside it
# A blob (a dwell's drop, a stop's slow stretch, a run too short for its ends) stands no higher
# than half its base width: a hemisphere, the drop of a melt at a 90-degree contact angle, the
# limit between a melt that wets its substrate (flatter) and one that balls up on it. Metal
# melts wet the metal they are fused to, so a larger drop spreads wider instead of growing taller.
BLOB_ASPECT = 0.5


@dataclass(frozen=True, eq=False)
class Beads:
    """The elements the deposit engine sweeps, in time order.

    ``p0``: a segment's start, a cap's centre, an arc's centre; ``p1``: a segment's end, an
    arc's (radius, start angle, signed sweep), unused for caps. All are bead-bottom points.
    ``up`` is the bead's up axis (the profile stands on the path point along it). ``volume``
    is the material the element carries (mm^3): what the program delivers over a piece, what
    collects in a cap; for a fixed bead, 0. ``floor_z``: beads that landed on a substrate may
    reach below its top (a sunk cap); the deposit is cut there.
    """

    code: int
    exponent: float
    kind: np.ndarray  # (m,) uint8 SEGMENT, CAP, ARC
    p0: np.ndarray  # (m, 3) float64
    p1: np.ndarray  # (m, 3) float64
    up: np.ndarray  # (m, 3) float64 unit
    width: np.ndarray  # (m,) float64 mm
    height: np.ndarray  # (m,) float64 mm
    foot: np.ndarray  # (m,) float64 mm: the section continues straight down this far below the bottom
    t0: np.ndarray  # (m,) float64 s
    t1: np.ndarray  # (m,) float64 s
    row: np.ndarray  # (m,) int64 toolpath row (caps: the row whose end or start they sit on)
    volume: np.ndarray  # (m,) float64 mm^3
    clip: np.ndarray  # (m, 6) float64: a cap's two cut normals (zero: no cut), see clipped_cap_sdf
    floor_z: float = -math.inf  # the substrate's top: nothing is deposited below it

    def __len__(self) -> int:
        return int(self.kind.shape[0])

    def take(self, index) -> "Beads":
        return dataclasses.replace(self, **{name: getattr(self, name)[index] for name in _ELEMENT_FIELDS})

    def until(self, time_s: float) -> "Beads":
        """The part as it stands at ``time_s``: elements started by then, the one in progress cut
        where the tool is (time linear within an element) and capped there, round as its front."""
        started = self.t0 < time_s
        running = np.flatnonzero(started & (self.t1 > time_s) & (self.kind != CAP))
        cut = self.take(started)
        if running.size == 0:
            return cut
        index = np.flatnonzero(started)
        at = np.searchsorted(index, running)
        frac = (time_s - self.t0[running]) / (self.t1[running] - self.t0[running])
        p1 = cut.p1.copy()
        t1 = cut.t1.copy()
        volume = cut.volume.copy()
        tip = np.empty((running.size, 3))
        seg = self.kind[running] == SEGMENT
        p1[at[seg]] = self.p0[running[seg]] + frac[seg, None] * (self.p1[running[seg]] - self.p0[running[seg]])
        tip[seg] = p1[at[seg]]
        arc = ~seg
        if arc.any():
            r, theta0, sweep = self.p1[running[arc]].T
            p1[at[arc], 2] = frac[arc] * sweep
            angle = theta0 + frac[arc] * sweep
            tip[arc] = self.p0[running[arc]] + np.column_stack([r * np.cos(angle), r * np.sin(angle),
                                                                  np.zeros(arc.sum())])
        t1[at] = time_s
        volume[at] *= frac
        cut = dataclasses.replace(cut, p1=p1, t1=t1, volume=volume)
        front = self.take(running)
        front = dataclasses.replace(front, kind=np.full(running.size, CAP, np.uint8), p0=tip, p1=tip.copy(),
                                    t0=np.full(running.size, float(time_s)), t1=np.full(running.size, float(time_s)),
                                    volume=np.zeros(running.size))
        merged = {name: np.concatenate([getattr(cut, name), getattr(front, name)]) for name in _ELEMENT_FIELDS}
        order = np.lexsort((merged["t1"], merged["t0"]))
        return dataclasses.replace(cut, **{name: merged[name][order] for name in _ELEMENT_FIELDS})

    @property
    def max_width(self) -> float:
        return float(self.width.max()) if len(self) else 0.0

    @property
    def max_height(self) -> float:
        return float((self.height + self.foot).max()) if len(self) else 0.0

    @property
    def uniform(self) -> bool:
        """One cross-section for every element (the fixed bead)."""
        return len(self) == 0 or bool(np.all(self.width == self.width[0]) and np.all(self.height == self.height[0])
                                      and not self.foot.any())


_ELEMENT_FIELDS = ("kind", "p0", "p1", "up", "width", "height", "foot", "t0", "t1", "row", "volume", "clip")


def section_height(code: int, width: np.ndarray, area: np.ndarray, exponent: float) -> np.ndarray:
    """Heights giving cross-section ``area`` at ``width`` (``A = k w h``; the arc profile, whose
    shape changes with its height, by bisection up to its half-disc limit)."""
    width = np.asarray(width, np.float64)
    area = np.asarray(area, np.float64)
    if code != PROFILE_CODES["arc"]:
        return area / (width * profile_area(code, 1.0, 1.0, exponent))
    lo = np.zeros_like(area)
    hi = 0.5 * width
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        a_mid = np.array([profile_area(code, w, max(m, 1e-12 * w), exponent) for w, m in zip(width, mid)])
        lo = np.where(a_mid < area, mid, lo)
        hi = np.where(a_mid < area, hi, mid)
    return 0.5 * (lo + hi)


def _check_arc_sections(code: int, width: np.ndarray, area: np.ndarray) -> None:
    if code != ARC_PROFILE:
        return
    too_big = area > 0.5 * np.pi * (0.5 * width) ** 2 * (1 + 1e-9)
    if np.any(too_big):
        raise DmdvoxError(
            f"--profile arc: {int(too_big.sum())} bead pieces carry more material than a half disc of their width "
            f"(the tallest arc section); use --profile ellipse or parabola for such beads")


@njit(cache=True)
def _rate_pieces(rows, length, v0, vc, v1, accel, q, min_piece, edge, out_row, out_sa, out_sb, out_vol, blob_start,
                 blob_end, count_only):
    """Pieces of the deposit rows of a rate source (module docstring): each speed ramp cut at
    speeds in geometric progression, so the pieces' areas ``2 Q / (v_a + v_b)`` follow ``Q / v``,
    consecutive ones joined up to ``min_piece`` long; the cruise cut ``edge[r]`` (half the bead
    width) from the row's ends. With ``count_only`` the output arrays are not touched and only
    the count is returned."""
    m = 0
    log_step = math.log(AREA_STEP)
    for k in range(rows.shape[0]):
        r = rows[k]
        L = length[r]
        if L <= 0.0:
            continue
        a = accel
        peak = vc[r]
        if a <= 0.0 or peak <= 0.0:
            if not count_only:
                out_row[m] = r
                out_sa[m] = 0.0
                out_sb[m] = L
                out_vol[m] = q * L / peak if peak > 0.0 else 0.0
            m += 1
            continue
        floor = FLOOR_RATIO * peak
        d_acc = max(0.0, min(L, (peak * peak - v0[r] * v0[r]) / (2.0 * a)))
        d_dec = max(0.0, min(L - d_acc, (peak * peak - v1[r] * v1[r]) / (2.0 * a)))
        middle_a = 0.0
        middle_b = L
        for side in range(2):
            v_end = v0[r] if side == 0 else v1[r]
            ramp = d_acc if side == 0 else d_dec
            v_lo = v_end
            s_lo = 0.0
            if v_end < floor and ramp > 0.0:
                v_lo = floor
                s_lo = (floor * floor - v_end * v_end) / (2.0 * a)
                stopped = q * (floor - v_end) / a
                if not count_only:
                    if side == 0:
                        blob_start[r] += stopped
                    else:
                        blob_end[r] += stopped
            inner = s_lo
            if ramp - s_lo > 1e-12 * L:
                n_speed = math.ceil(math.log(peak / v_lo) / log_step - 1e-9)
                n = max(MIN_RAMP_PIECES, n_speed)
                va = v_lo
                sa = s_lo
                inner = ramp
                for j in range(n):
                    vb = v_lo * (peak / v_lo) ** ((j + 1) / n) if j + 1 < n else peak
                    sb = (vb * vb - v_end * v_end) / (2.0 * a) if j + 1 < n else ramp
                    # pieces shorter than min_piece join the next ones of their ramp (and the
                    # ramp's last one the piece before it)
                    if j + 1 < n and (sb - sa < min_piece or ramp - sb < min_piece):
                        continue
                    vol = q * (vb - va) / a
                    if j + 1 == n and ramp < min_piece:
                        # a whole ramp shorter than min_piece (drawn from the row's end) takes
                        # in the cruise up to that length: the grid cannot show a shorter
                        # piece, and drawn over less than a cell it would stand proud
                        sb = min(min_piece, ramp + 0.5 * (L - d_acc - d_dec))
                        vol += q * (sb - ramp) / peak
                        inner = sb
                    if not count_only:
                        out_row[m] = r
                        if side == 0:
                            out_sa[m] = sa
                            out_sb[m] = sb
                        else:  # measured back from the row's end
                            out_sa[m] = L - sb
                            out_sb[m] = L - sa
                        out_vol[m] = vol
                    m += 1
                    va = vb
                    sa = sb
            if side == 0:
                middle_a = inner
            else:
                middle_b = L - inner
        # the cruise's first and last half width are pieces of their own: a joint's wedge is
        # taken from there (_take_wedges), not from the whole row
        cut_a = min(max(middle_a, edge[r]), middle_b)
        cut_b = max(min(middle_b, L - edge[r]), cut_a)
        for part in range(3):
            pa = middle_a if part == 0 else (cut_a if part == 1 else cut_b)
            pb = cut_a if part == 0 else (cut_b if part == 1 else middle_b)
            if pb - pa <= 1e-12 * L:
                continue
            vol = q * (pb - pa) / peak
            if not count_only:
                out_row[m] = r
                out_sa[m] = pa
                out_sb[m] = pb
                out_vol[m] = vol
            m += 1
    return m


def _pieces(tp: Toolpath, rows: np.ndarray, flow: Flow, plan, width: np.ndarray, min_piece: float = 0.0) -> tuple:
    """(row, s_a, s_b, volume) of every piece in row order, and the blob volumes at each row's
    start and end; ramp pieces no shorter than ``min_piece`` (but a whole ramp shorter is one),
    ``width`` the rows' bead widths."""
    n = len(tp)
    blob_start = np.zeros(n)  # a dwell's material is a drop of its own (build_beads)
    blob_end = np.zeros(n)
    length = tp.length
    if flow.rate_mm3_s is None:
        return (rows, np.zeros(rows.size), length[rows], flow.volume[rows]), blob_start, blob_end
    args = (rows, length, plan.v_entry, plan.v_cruise, plan.v_exit, float(plan.accel), float(flow.rate_mm3_s),
            float(min_piece), 0.5 * np.asarray(width, np.float64))
    empty_f = np.zeros(0)
    empty_i = np.zeros(0, np.int64)
    m = _rate_pieces(*args, empty_i, empty_f, empty_f, empty_f, blob_start, blob_end, True)
    out = (np.empty(m, np.int64), np.empty(m), np.empty(m), np.empty(m))
    # the pieces come out start ramp, end ramp, cruise within a row: put them in path order
    _rate_pieces(*args, *out, blob_start, blob_end, False)
    order = np.lexsort((out[1], out[0]))
    return tuple(a[order] for a in out), blob_start, blob_end


def exact_arc_rows(tp: Toolpath) -> np.ndarray:
    """Arc table indices drawn as exact arc beads: horizontal (G17), no helix, no spiral, the
    tool axis (the bead's up) vertical; other arcs are chorded."""
    rows = tp.arcs.segment
    flat = np.abs(tp.end[rows, 2] - tp.start[rows, 2]) < 1e-9
    round_ = np.abs(tp.arcs.r_end - tp.arcs.r_start) < 1e-9
    upright = np.all(tp.axis[rows] == np.array([0.0, 0.0, 1.0], np.float32), axis=1)
    return np.flatnonzero((tp.arcs.normal_axis == 2) & flat & round_ & tp.deposit[rows] & upright)


@njit(cache=True)
def _split_at_chords(p_row, p_sa, p_sb, chords, length, out_piece, out_fa, out_fb, out_joint, count_only):
    """Cut pieces at the chord boundaries of their rows (``chords[r]`` chords, 0: a straight row or
    an exact arc). Fractions of the row; ``out_joint`` marks starts at a row start or a chord
    boundary (a cap belongs there), not at a speed-ramp boundary inside a straight stretch."""
    m = 0
    for k in range(p_row.shape[0]):
        r = p_row[k]
        L = length[r]
        fa = p_sa[k] / L
        fb = p_sb[k] / L
        if k + 1 == p_row.shape[0] or p_row[k + 1] != r:
            fb = 1.0  # the last piece ends exactly at the row's end
        if k == 0 or p_row[k - 1] != r:
            fa = 0.0
        c = chords[r]
        joint = fa == 0.0
        if c <= 1:
            if not count_only:
                out_piece[m] = k
                out_fa[m] = fa
                out_fb[m] = fb
                out_joint[m] = joint
            m += 1
            continue
        j = int(math.floor(fa * c + 1e-12)) + 1  # first chord boundary after fa
        cur = fa
        while True:
            bound = j / c
            stop = bound >= fb - 1e-12
            end = fb if stop else bound
            if not count_only:
                out_piece[m] = k
                out_fa[m] = cur
                out_fb[m] = end
                out_joint[m] = joint
            m += 1
            if stop:
                break
            cur = bound
            joint = True
            j += 1
    return m


@dataclass(frozen=True)
class RowSections:
    """Per-row cross-section inputs: width (mm), a fixed height where the height does not come
    from the material (NaN elsewhere), and the z shift from the path point to the bead bottom."""

    width: np.ndarray  # (n,) float64
    fixed_height: np.ndarray  # (n,) float64
    bottom_shift: np.ndarray  # (n,) float64


def build_beads(tp: Toolpath, profile: BeadProfile, sections: RowSections, flow: Flow, plan,
                chord_tolerance: float, min_piece: float = 0.0) -> Beads:
    """The bead elements of the deposit rows of ``tp`` (planned times).

    With material (``flow.from_material``) every run's round ends are paid for by its material:
    the run is shortened at each end by the stretch that carries half a cap's volume, so that
    pieces and caps together hold exactly what was delivered (:func:`_retract_run_ends`).
    ``min_piece``: the shortest ramp piece (the voxel, when laid on a grid: a shorter piece may
    hold no cell of the height field, which sees the part through the cells' owners)."""
    code = profile.code
    dep_rows = np.flatnonzero(tp.deposit)
    (p_row, p_sa, p_sb, p_vol), blob_start, blob_end = _pieces(tp, dep_rows, flow, plan, sections.width, min_piece)
    length = tp.length
    keep = p_sb > p_sa
    p_row, p_sa, p_sb, p_vol = p_row[keep], p_sa[keep], p_sb[keep], p_vol[keep]

    exact = exact_arc_rows(tp)
    arc_of_row = np.full(len(tp), -1, np.int64)
    arc_of_row[tp.arcs.segment] = np.arange(len(tp.arcs))
    chords = np.zeros(len(tp), np.int64)
    chorded = np.setdiff1d(np.flatnonzero(tp.deposit[tp.arcs.segment]), exact)
    chords[tp.arcs.segment[chorded]] = arc_chord_counts(
        np.maximum(tp.arcs.r_start[chorded], tp.arcs.r_end[chorded]), tp.arcs.sweep[chorded], chord_tolerance)

    args = (p_row, p_sa, p_sb, chords, length)
    m = _split_at_chords(*args, np.zeros(0, np.int64), np.zeros(0), np.zeros(0), np.zeros(0, np.bool_), True)
    piece, fa, fb, joint = np.empty(m, np.int64), np.empty(m), np.empty(m), np.empty(m, np.bool_)
    _split_at_chords(*args, piece, fa, fb, joint, False)
    row = p_row[piece]
    # material by length within a piece (its area is constant); a row's first and last pieces are
    # drawn from the row's very ends (the slow stretch beyond them is in the caps) but keep
    # exactly their own material
    span = (p_sb - p_sa)[piece]
    own = np.minimum(fb * length[row], p_sb[piece]) - np.maximum(fa * length[row], p_sa[piece])
    vol = p_vol[piece] * np.where(span > 0, np.clip(own, 0.0, None) / np.where(span > 0, span, 1.0), 1.0)

    width = sections.width[row]
    area = np.where(length[row] * (fb - fa) > 0, vol / np.maximum(length[row] * (fb - fa), 1e-300), 0.0)
    fixed = np.isfinite(sections.fixed_height[row])
    if flow.from_material:
        _check_arc_sections(code, width, area)
    height = np.where(fixed, sections.fixed_height[row], 0.0)
    if not fixed.all():
        height[~fixed] = section_height(code, width[~fixed], area[~fixed], profile.exponent)
    if not flow.from_material:
        vol = np.zeros_like(vol)
    # the bead's up axis is its row's tool axis (+Z on a 3-axis machine); the profile stands on
    # the path point along it, and the bottom shift (slicers' Z at the layer top) runs along it
    row_up = tp.axis[row].astype(np.float64)
    shift = sections.bottom_shift[row][:, None] * row_up

    # geometry: straight pieces (lines and chords) and exact arcs, by their end points; arcs also
    # by (centre, radius, start angle, sweep)
    arc_idx = arc_of_row[row]
    is_arc = arc_idx >= 0
    is_exact = is_arc & np.isin(arc_idx, exact)
    a = np.empty((row.size, 3))
    b = np.empty((row.size, 3))
    straight = np.flatnonzero(~is_arc)
    rs = row[straight]
    a[straight] = tp.start[rs] + fa[straight, None] * (tp.end[rs] - tp.start[rs])
    b[straight] = np.where((fb[straight] == 1.0)[:, None], tp.end[rs],
                           tp.start[rs] + fb[straight, None] * (tp.end[rs] - tp.start[rs]))
    on_arc = np.flatnonzero(is_arc)
    if on_arc.size:
        a[on_arc] = np.where((fa[on_arc] == 0.0)[:, None], tp.start[row[on_arc]],
                             arc_points(tp, arc_idx[on_arc], fa[on_arc]))
        b[on_arc] = np.where((fb[on_arc] == 1.0)[:, None], tp.end[row[on_arc]],
                             arc_points(tp, arc_idx[on_arc], fb[on_arc]))
    a += shift
    b += shift
    if plan is not None and plan.accel > 0:
        t0 = plan.time_at(row, fa * length[row])
        t1 = plan.time_at(row, fb * length[row])
    else:
        duration = tp.t_end[row] - tp.t_start[row]
        t0 = tp.t_start[row] + fa * duration
        t1 = tp.t_start[row] + fb * duration
    arc = np.zeros((row.size, 4))  # centre x, y, radius, start angle; sweep in arc_sweep
    arc_sweep = np.zeros(row.size)
    ex = np.flatnonzero(is_exact)
    if ex.size:
        ai = arc_idx[ex]
        centre = tp.arcs.centre[ai]
        start = tp.start[tp.arcs.segment[ai]]
        theta_start = np.arctan2(start[:, 1] - centre[:, 1], start[:, 0] - centre[:, 0])
        sweep = tp.arcs.sweep[ai]
        arc[ex] = np.column_stack([centre[:, 0], centre[:, 1], tp.arcs.r_start[ai], theta_start + fa[ex] * sweep])
        arc_sweep[ex] = (fb[ex] - fa[ex]) * sweep

    # chains: an element continues the previous one where it starts at its end at the same time;
    # a cap belongs at every chain end and at every joint inside a chain (a chord boundary or a
    # row boundary), not at a speed-ramp cut inside a straight stretch
    n_el = row.size
    cut_inside = np.zeros(n_el, bool)  # the element's end is a speed-ramp cut
    cut_inside[:-1] = ~joint[1:] & (row[1:] == row[:-1])
    continues = np.zeros(n_el, bool)
    if n_el > 1:
        continues[1:] = np.all(a[1:] == b[:-1], axis=1) & (t0[1:] == t1[:-1])
    blob_a = np.where(fa == 0.0, blob_start[row], 0.0)  # material collecting at each element's start
    blob_b = np.where(fb == 1.0, blob_end[row], 0.0)  # ... and end
    alive = np.ones(n_el, bool)
    shrunk = np.full(n_el, -1.0)
    if flow.from_material and n_el:
        cap_half = 0.5 * _revolved(code, profile.exponent, width, height)
        _retract_run_ends(continues, vol, cap_half, a, b, t0, t1, arc, arc_sweep, is_exact, alive, blob_a, blob_b,
                          shrunk)
    small = np.flatnonzero(shrunk >= 0) if flow.from_material and n_el else np.zeros(0, np.int64)
    alive[small] = False  # ... each becomes one whole cap below
    idx = np.flatnonzero(alive)
    prev_linked = np.zeros(n_el, bool)
    prev_linked[1:] = continues[1:] & alive[:-1]
    next_linked = np.zeros(n_el, bool)
    next_linked[:-1] = continues[1:] & alive[1:]
    start_cap = alive & ~prev_linked
    end_cap = alive & ~(next_linked & cut_inside)
    shared = end_cap & next_linked  # that cap also stands at the next element's start

    # cap sections: where two elements meet, the smaller section, so the cap never stands proud
    # of either; blobs add their material (module docstring)
    s_idx = np.flatnonzero(start_cap)
    e_idx = np.flatnonzero(end_cap)
    e_shared = shared[e_idx]
    nxt = e_idx[e_shared] + 1
    cap_w_end = width[e_idx].copy()
    cap_h_end = height[e_idx].copy()
    blob_end_cap = blob_b[e_idx].copy()
    cap_w_end[e_shared] = np.minimum(cap_w_end[e_shared], width[nxt])
    cap_h_end[e_shared] = np.minimum(cap_h_end[e_shared], height[nxt])
    blob_end_cap[e_shared] += blob_a[nxt]
    cap_pts = np.concatenate([a[s_idx], b[e_idx]])
    cap_t = np.concatenate([t0[s_idx], t1[e_idx]])
    cap_w = np.concatenate([width[s_idx], cap_w_end])
    cap_h = np.concatenate([height[s_idx], cap_h_end])
    cap_blob = np.concatenate([blob_a[s_idx], blob_end_cap])
    cap_row = np.concatenate([row[s_idx], row[e_idx]])
    clip = np.zeros((cap_pts.shape[0], 6))
    cap_vol = np.zeros(cap_pts.shape[0])
    keep_cap = np.ones(cap_pts.shape[0], bool)
    if flow.from_material:
        # With material, a cap holds only what its pieces do not cover: the half beyond a run's
        # end (paid for by the run, see _retract_run_ends) or the outer wedge of a joint (taken
        # from the two pieces it joins); caps grown by a blob below half a cap stand whole.
        d_start, d_end = _end_directions(a, b, arc, arc_sweep, is_exact, row_up)
        # first cut: beyond the end of the element before; second: behind the start of the one
        # after (the landing gives the cut lines' cells to the pieces on the same sides)
        ns = s_idx.size
        clip[:ns, 3:] = -d_start[s_idx]
        clip[ns:, :3] = d_end[e_idx]
        clip[ns:, 3:][e_shared] = -d_start[nxt]
        turn = np.full(cap_pts.shape[0], np.pi)  # a run's end: half the cap
        cos_turn = np.clip(np.sum(d_end[e_idx[e_shared]] * d_start[nxt], axis=1), -1.0, 1.0)
        turn[ns:][e_shared] = np.arccos(cos_turn)
        share = turn / (2 * np.pi)
        whole = (share < 0.5) & (cap_blob > 0)
        clip[whole] = 0.0
        share[whole] = 1.0
        keep_cap = (share > 1e-9) | (cap_blob > 0)
        rev = _revolved(code, profile.exponent, cap_w, cap_h)
        wedge = share * rev
        # the joints' wedges come out of the stretches on either side, half each
        joints = ns + np.flatnonzero(e_shared)
        wedge[whole] = 0.0
        seg_len = np.where(is_exact, np.abs(arc[:, 2] * arc_sweep), np.linalg.norm(b - a, axis=1))
        wedge[joints] = _take_wedges(e_idx[e_shared], 0.5 * wedge[joints], 0.5 * cap_w[joints], vol, seg_len,
                                     prev_linked, next_linked)
        cap_vol = wedge + cap_blob
        cap_h, cap_w = _blob_sections(code, profile.exponent, cap_w, cap_h, cap_blob, share)
    else:
        cap_h, cap_w = _blob_sections(code, profile.exponent, cap_w, cap_h, cap_blob, np.ones(cap_pts.shape[0]))
    cap_pts, cap_t, cap_w, cap_h, cap_row, clip, cap_vol = (
        v[keep_cap] for v in (cap_pts, cap_t, cap_w, cap_h, cap_row, clip, cap_vol))
    if small.size:
        # a run too short for its round ends is one revolved blob holding all its material
        blob = shrunk[small] + blob_a[small] + blob_b[small]
        blob_h, blob_w = _blob_sections(code, profile.exponent, width[small], np.zeros(small.size), blob)
        cap_pts = np.concatenate([cap_pts, a[small]])
        cap_t = np.concatenate([cap_t, t0[small]])
        cap_w = np.concatenate([cap_w, blob_w])
        cap_h = np.concatenate([cap_h, blob_h])
        cap_row = np.concatenate([cap_row, row[small]])
        clip = np.concatenate([clip, np.zeros((small.size, 6))])
        cap_vol = np.concatenate([cap_vol, blob])
    dwell = np.flatnonzero(flow.dwell_volume > 0)
    if dwell.size:
        # a beam-on dwell's material is a drop of its own, whole, where the tool stood, formed
        # while it stood there
        drop = flow.dwell_volume[dwell]
        drop_h, drop_w = _blob_sections(code, profile.exponent, sections.width[dwell], np.zeros(dwell.size), drop)
        axis = tp.axis[dwell].astype(np.float64)
        cap_pts = np.concatenate([cap_pts, tp.start[dwell] + sections.bottom_shift[dwell][:, None] * axis])
        cap_t = np.concatenate([cap_t, tp.t_start[dwell] - 0.5 * tp.dwell_on[dwell].astype(np.float64)])
        cap_w = np.concatenate([cap_w, drop_w])
        cap_h = np.concatenate([cap_h, drop_h])
        cap_row = np.concatenate([cap_row, dwell])
        clip = np.concatenate([clip, np.zeros((dwell.size, 6))])
        cap_vol = np.concatenate([cap_vol, drop])

    kind = np.where(is_exact, ARC, SEGMENT).astype(np.uint8)[idx]
    p0 = a[idx].copy()
    p1 = b[idx].copy()
    exi = np.flatnonzero(is_exact[idx])
    p0[exi, :2] = arc[idx[exi], :2]
    p1[exi] = np.column_stack([arc[idx[exi], 2], arc[idx[exi], 3], arc_sweep[idx[exi]]])
    n_keep = idx.size
    n_cap = cap_pts.shape[0]
    kind_all = np.concatenate([kind, np.full(n_cap, CAP, np.uint8)])
    up = np.concatenate([row_up[idx], tp.axis[cap_row].astype(np.float64)])  # caps: the row they sit on
    t0_all = np.concatenate([t0[idx], cap_t])
    t1_all = np.concatenate([t1[idx], cap_t])
    # Time order: a cap at a vertex sits after the element that ends there and before the next.
    order = np.lexsort((t1_all, t0_all))
    return Beads(
        code=code, exponent=profile.exponent, kind=kind_all[order],
        p0=np.concatenate([p0, cap_pts])[order], p1=np.concatenate([p1, cap_pts])[order], up=up[order],
        width=np.concatenate([width[idx], cap_w])[order], height=np.concatenate([height[idx], cap_h])[order],
        foot=np.zeros(n_keep + n_cap), t0=t0_all[order], t1=t1_all[order],
        row=np.concatenate([row[idx], cap_row])[order], volume=np.concatenate([vol[idx], cap_vol])[order],
        clip=np.concatenate([np.zeros((n_keep, 6)), clip])[order])


def _end_directions(a, b, arc, arc_sweep, is_arc, up) -> tuple[np.ndarray, np.ndarray]:
    """Unit travel directions across the up axis at every element's start and end (an arc's
    tangents; horizontal for a vertical up)."""
    chord = b - a
    chord -= np.einsum("ij,ij->i", chord, up)[:, None] * up
    norm = np.linalg.norm(chord, axis=1, keepdims=True)
    d = np.divide(chord, norm, out=np.zeros_like(chord), where=norm > 0)
    d_start = d.copy()
    d_end = d.copy()
    k = np.flatnonzero(is_arc)
    if k.size:
        sign = np.sign(arc_sweep[k])
        for out, angle in ((d_start, arc[k, 3]), (d_end, arc[k, 3] + arc_sweep[k])):
            out[k, 0] = -np.sin(angle) * sign
            out[k, 1] = np.cos(angle) * sign
            out[k, 2] = 0.0
    return d_start, d_end


def _revolved(code: int, exponent: float, width: np.ndarray, height: np.ndarray) -> np.ndarray:
    """Revolved volume of each section (linear in the height but for the arc profile)."""
    width = np.asarray(width, np.float64)
    height = np.asarray(height, np.float64)
    if code != PROFILE_CODES["arc"]:
        return revolved_volume(code, 1.0, 1.0, exponent) * width * width * height
    return np.array([revolved_volume(code, w, h, exponent) if h > 0 else 0.0 for w, h in zip(width, height)])


@njit(cache=True)
def _take_wedges(before, half, reach, vol, seg_len, prev_linked, next_linked):
    """Take each joint's wedge, ``half[k]`` from each side, out of the elements that lie within
    ``reach[k]`` (half the bead width) of the joint along the run before ``before[k]`` and the
    run after it: that is where the two beads overlap, the material the turning melt pool fills
    its outer wedge with. Each of them gives the same fraction of its material, at most
    ``WEDGE_SHARE``, so that none is emptied (an empty piece would stand where it was
    programmed, carrying nothing); what they cannot give comes from the next element out (the
    row's cruise, or the whole row where there is no ramp), again at most that share of it.
    Returns what each joint got (less only where the runs are too short)."""
    got = np.zeros(before.shape[0])
    for k in range(before.shape[0]):
        for side in range(2):
            start = before[k] if side == 0 else before[k] + 1
            step = -1 if side == 0 else 1
            available = 0.0
            last = start
            beyond = -1
            e = start
            covered = 0.0
            while True:
                if e != start and covered + seg_len[e] > reach[k]:
                    beyond = e
                    break
                available += vol[e]
                covered += seg_len[e]
                last = e
                if covered >= reach[k] or not (prev_linked[e] if side == 0 else next_linked[e]):
                    break
                e += step
            need = half[k]
            if available > 0.0:
                fraction = min(WEDGE_SHARE, need / available)
                e = start
                while True:
                    take = fraction * vol[e]
                    vol[e] -= take
                    got[k] += take
                    need -= take
                    if e == last:
                        break
                    e += step
            if beyond >= 0 and need > 1e-12 * half[k]:
                take = min(need, WEDGE_SHARE * vol[beyond])
                vol[beyond] -= take
                got[k] += take
    return got


@njit(cache=True)
def _retract_run_ends(continues, vol, cap_half, a, b, t0, t1, arc, arc_sweep, is_arc, alive, blob_a, blob_b,
                      shrunk):
    """Shorten every run (chain of continuing elements) at both ends by the stretch whose
    material fills half a cap there, so the run's caps are paid for (module docstring). Elements
    used up entirely are marked dead and hand their blobs on to the run's new end; a run with
    less material than its two half caps keeps only its middle element, shrunk to a point, with
    all its material (``shrunk``) and blobs."""
    n = continues.shape[0]
    first = 0
    while first < n:
        last = first
        while last + 1 < n and continues[last + 1]:
            last += 1
        total = 0.0
        for k in range(first, last + 1):
            total += vol[k]
        # the cap stands on the element the cut lands on, so the stretch to remove is half of
        # that element's cap: walk inward until the removed material reaches it
        head = first
        removed = 0.0
        while head <= last and removed + vol[head] <= cap_half[head]:
            removed += vol[head]
            head += 1
        tail = last
        removed_end = 0.0
        while tail >= head and removed_end + vol[tail] <= cap_half[tail]:
            removed_end += vol[tail]
            tail -= 1
        if tail < head or (tail == head and (cap_half[head] - removed) + (cap_half[head] - removed_end) >= vol[head]):
            # too little material for the round ends: shrink to the middle element's midpoint
            mid = (first + last) // 2
            for k in range(first, last + 1):
                if k != mid:
                    alive[k] = False
                    blob_a[mid] += blob_a[k] + blob_b[k]
                    blob_a[k] = 0.0
                    blob_b[k] = 0.0
            _cut(mid, 0.5, 0.5, a, b, t0, t1, arc, arc_sweep, is_arc)
            shrunk[mid] = total
            vol[mid] = 0.0
        else:
            for k in range(first, head):
                alive[k] = False
                vol[k] = 0.0
                blob_a[head] += blob_a[k] + blob_b[k]
                blob_a[k] = 0.0
                blob_b[k] = 0.0
            for k in range(tail + 1, last + 1):
                alive[k] = False
                vol[k] = 0.0
                blob_b[tail] += blob_a[k] + blob_b[k]
                blob_a[k] = 0.0
                blob_b[k] = 0.0
            take_start = cap_half[head] - removed
            take_end = cap_half[tail] - removed_end
            if head == tail:
                _cut(head, take_start / vol[head], 1.0 - take_end / vol[head], a, b, t0, t1, arc, arc_sweep, is_arc)
                vol[head] -= take_start + take_end
            else:
                _cut(head, take_start / vol[head], 1.0, a, b, t0, t1, arc, arc_sweep, is_arc)
                vol[head] -= take_start
                _cut(tail, 0.0, 1.0 - take_end / vol[tail], a, b, t0, t1, arc, arc_sweep, is_arc)
                vol[tail] -= take_end
        first = last + 1


@njit(cache=True)
def _cut(k, fa, fb, a, b, t0, t1, arc, arc_sweep, is_arc):
    """Keep the part of element k between fractions fa and fb of its length (time linear)."""
    ta = t0[k] + fa * (t1[k] - t0[k])
    tb = t0[k] + fb * (t1[k] - t0[k])
    t0[k] = ta
    t1[k] = tb
    if is_arc[k]:
        theta = arc[k, 3]
        sweep = arc_sweep[k]
        z = a[k, 2]
        for which in range(2):
            f = fa if which == 0 else fb
            angle = theta + f * sweep
            x = arc[k, 0] + arc[k, 2] * math.cos(angle)
            y = arc[k, 1] + arc[k, 2] * math.sin(angle)
            if which == 0:
                a[k, 0] = x
                a[k, 1] = y
            else:
                b[k, 0] = x
                b[k, 1] = y
            a[k, 2] = z
            b[k, 2] = z
        arc[k, 3] = theta + fa * sweep
        arc_sweep[k] = (fb - fa) * sweep
    else:
        for q in range(3):
            pa = a[k, q] + fa * (b[k, q] - a[k, q])
            pb = a[k, q] + fb * (b[k, q] - a[k, q])
            a[k, q] = pa
            b[k, q] = pb


def _blob_sections(code: int, exponent: float, width: np.ndarray, height: np.ndarray,
                   blob: np.ndarray, share: np.ndarray | None = None) -> tuple[np.ndarray, np.ndarray]:
    """Cap sections grown by the blob volume they collect, the cap being ``share`` of a whole
    revolved section: taller by ``blob / (share V_rev(w, 1))`` (the revolved volume grows linearly
    with the height), up to ``BLOB_ASPECT`` times the width; beyond it wider and taller at that
    aspect, holding the same volume. The arc profile, whose shape changes with its height, is
    scaled as a whole (from a quarter-width arc where the cap had no height): its half-disc
    limit is that aspect already."""
    width = np.array(width, np.float64)
    height = np.array(height, np.float64)
    share = np.ones(width.shape) if share is None else share
    grow = np.flatnonzero(blob > 0)
    if code != PROFILE_CODES["arc"]:
        unit = share[grow] * _revolved(code, exponent, np.ones(grow.size), np.ones(grow.size))  # V = unit w^2 h
        height[grow] += blob[grow] / (unit * width[grow] ** 2)
        # no higher than the wetting limit: beyond it the drop spreads wider at that aspect
        tall = height[grow] > BLOB_ASPECT * width[grow]
        if tall.any():
            k = grow[tall]
            volume = unit[tall] * width[k] ** 2 * height[k]
            width[k] = (volume / (unit[tall] * BLOB_ASPECT)) ** (1.0 / 3.0)
            height[k] = BLOB_ASPECT * width[k]
        return height, width
    for k in grow:
        h0 = height[k] if height[k] > 0 else 0.25 * width[k]
        base = revolved_volume(code, width[k], height[k], exponent) if height[k] > 0 else 0.0
        scale = ((base + blob[k] / share[k]) / revolved_volume(code, width[k], h0, exponent)) ** (1.0 / 3.0)
        width[k] *= scale
        height[k] = h0 * scale
    return height, width


__all__ = ["Beads", "SEGMENT", "CAP", "ARC", "RowSections", "build_beads", "exact_arc_rows", "section_height",
           "FLOOR_RATIO", "AREA_STEP", "MIN_RAMP_PIECES", "BLOB_ASPECT"]
