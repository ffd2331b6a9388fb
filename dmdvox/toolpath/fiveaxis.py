"""Five-axis rows: the interpreter's machine moves turned into the tool tip path and tool axis.

With a machine file (``--machine``, :mod:`dmdvox.toolpath.kinematics`) the G-code interpreter
records every move with its rotary values at both ends and the tool-centre-point (TCP) state;
:func:`tip_rows` turns those rows into rows of the tip path in the workpiece frame, each with a
constant tool axis, and times them. The rules (``docs/MACHINES.md``, "Programs"):

* **TCP on** (G43.4, M128, TRAORI, #TRAFO ON): X Y Z are the tip in the workpiece frame and it
  moves along the programmed line or arc; the rotary axes move linearly with it and set the tool
  axis (forward kinematics of the rotary values).
* **TCP off** (the default; G49, M129, TRAFOOF, #TRAFO OFF): X Y Z A B C are machine joints,
  interpolated linearly (arcs: X Y Z along the arc, the rotary axes linearly). The tip path is
  the forward kinematics of that joint path: a move whose rotary values do not change keeps its
  shape (a line stays a line; an arc stays an exact arc when its plane keeps its normal, else it
  is cut into chords); a move that turns a rotary axis is sampled so that every chord of the tip
  path stays within ``chord_tolerance`` of the curve (checked at each chord's midpoint, the
  sampling refined until it holds).
* A row whose tool axis turns is cut so that consecutive sub-rows' axes differ by at most
  ``axis_step_deg`` (the rotary angles' sum bounds the axis' turn); each sub-row carries the axis
  at its middle.
* Rotary values are unwrapped (C0 to C360 turns once); an axis the machine file marks
  ``wrapped`` goes the short way (:func:`~dmdvox.toolpath.kinematics.short_way`).
* Time: the feed is the tip's speed relative to the workpiece: a row takes its tip path length
  over F. A move whose tip does not move relative to the workpiece (rotary axes alone, e.g. a
  turn about the tip) takes its largest rotary travel in degrees over F read as degrees per
  minute (Fanuc's rule for rotary feeds). G93 inverse time keeps the program's duration; rapids
  use the rapid rate the same way. Sub-rows share their row's time by tip length (by angle when
  the tip stands still). Gaps between rows (dwells, E-only moves) are kept.

Everything is vectorised over rows (numpy and the kinematics' numba kernels); 3-axis programs
never come here.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from types import SimpleNamespace

import numpy as np

from .kinematics import Machine, forward, short_way, workpiece_to_machine
from .gcode_kernel import MODE_INVERSE_TIME, MODE_TCP
from .geometry import arc_chord_counts, arc_points
from .model import LINEAR, ArcTable

DEFAULT_TIP_CHORD_MM = 0.01  # the deposit's finest chord tolerance (process.plan)
DEFAULT_AXIS_STEP_DEG = 2.0  # a bead stands at most 1 degree off: a 2.5 mm one moves 0.022 mm at its corners
_STILL_MM = 1e-9  # a tip path shorter than this does not move relative to the workpiece
_MAX_REFINE = 8


@dataclass(frozen=True, eq=False)
class TipRows:
    """The rows of :func:`tip_rows`: ``src`` is each new row's interpreter row; ``frac0``/``frac1``
    its share of that row (tip length, or angle when the tip stands still): material splits by it."""

    src: np.ndarray  # (m,) int64
    frac0: np.ndarray  # (m,) float64
    frac1: np.ndarray  # (m,) float64
    start: np.ndarray  # (m, 3) float64 tip, workpiece frame
    end: np.ndarray  # (m, 3) float64
    axis: np.ndarray  # (m, 3) float32 unit
    rotary: np.ndarray  # (m, 3) float32 A B C (unwrapped) at the row's end
    kind: np.ndarray  # (m,) uint8
    feed: np.ndarray  # (m,) float32 tip speed, mm/s
    t_start: np.ndarray  # (m,) float64
    t_end: np.ndarray  # (m,) float64
    arcs: ArcTable
    end_time: float


def _rotary_path(machine: Machine, rot0: np.ndarray, rot1: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The rotary values each row really starts and ends at: wrapped axes the short way along
    the program (rows interleaved start, end, start, ...), the others as programmed."""
    n = rot0.shape[0]
    if not any(ax.wrapped for ax in machine.axes) or n == 0:
        return rot0, rot1
    joints = np.zeros((2 * n, 6))
    joints[0::2, 3:] = rot0
    joints[1::2, 3:] = rot1
    path = short_way(machine, joints)
    return path[0::2, 3:].copy(), path[1::2, 3:].copy()


def _joints(xyz: np.ndarray, rot: np.ndarray) -> np.ndarray:
    return np.ascontiguousarray(np.concatenate([xyz, rot], axis=1), np.float64)


def _unit(v: np.ndarray) -> np.ndarray:
    norm = np.linalg.norm(v, axis=1, keepdims=True)
    return v / np.where(norm > 0, norm, 1.0)


def _segment_distance(p: np.ndarray, a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Distance of each point ``p`` from the segment ``a``-``b``."""
    ab = b - a
    ll = np.einsum("ij,ij->i", ab, ab)
    t = np.clip(np.einsum("ij,ij->i", p - a, ab) / np.where(ll > 0, ll, 1.0), 0.0, 1.0)
    d = p - (a + t[:, None] * ab)
    return np.sqrt(np.einsum("ij,ij->i", d, d))


class _Rows:
    """The interpreter's rows and how to evaluate a point along one of them."""

    def __init__(self, machine, start, end, kind, arcs, a0, a1, tcp):
        self.machine = machine
        self.start = start
        self.end = end
        self.kind = kind
        self.arcs = arcs
        self.a0 = a0
        self.a1 = a1
        self.tcp = tcp
        self.arc_of_row = np.full(start.shape[0], -1, np.int64)
        self.arc_of_row[arcs.segment] = np.arange(len(arcs))
        self._arc_view = SimpleNamespace(arcs=arcs, start=start, end=end)

    def xyz(self, rows: np.ndarray, u: np.ndarray) -> np.ndarray:
        """The programmed X Y Z at fraction ``u`` of ``rows`` (arcs along the arc; u = 1 exact)."""
        out = self.start[rows] + u[:, None] * (self.end[rows] - self.start[rows])
        arc = self.arc_of_row[rows]
        on = np.flatnonzero(arc >= 0)
        if on.size:
            out[on] = arc_points(self._arc_view, arc[on], u[on])
        last = u == 1.0
        out[last] = self.end[rows[last]]
        first = u == 0.0
        out[first] = self.start[rows[first]]
        return out

    def rot(self, rows: np.ndarray, u: np.ndarray) -> np.ndarray:
        out = self.a0[rows] + u[:, None] * (self.a1[rows] - self.a0[rows])
        last = u == 1.0
        out[last] = self.a1[rows[last]]
        return out

    def pose(self, rows: np.ndarray, u: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Tip and unit tool axis (workpiece frame) at fraction ``u`` of ``rows``."""
        xyz = self.xyz(rows, u)
        rot = self.rot(rows, u)
        tip, axis = forward(self.machine, _joints(xyz, rot))
        on = self.tcp[rows]
        tip[on] = xyz[on]  # TCP on: X Y Z are the tip already
        return tip, _unit(axis)


def _turn_radians(machine: Machine, a0: np.ndarray, a1: np.ndarray) -> np.ndarray:
    """Sum over the machine's rotary axes of |rotary travel| (radians): it bounds how far any
    unit vector carried by them, the tool axis included, turns along the row."""
    total = np.zeros(a0.shape[0])
    for ax in machine.axes:
        c = ax.column - 3
        total += np.abs(a1[:, c] - a0[:, c])
    return np.radians(total)


def _axis_turn(machine: Machine, a0: np.ndarray, a1: np.ndarray, k0: np.ndarray, k1: np.ndarray) -> np.ndarray:
    """An upper bound (radians) of how far the tool axis turns along each row.

    One rotary axis keeps its angle to the tool axis whatever it turns (a table's C axis in the
    workpiece frame, a head's C axis): the tool axis moves by at most that axis' travel times
    the sine of that angle, which the other (tilt) axis changes by at most its own travel; the
    tilt turns the tool axis by at most its travel. A tool axis along the table's C axis (a
    vertical nozzle over a turning table) does not turn at all."""
    if machine.kind in ("trt-ac", "trt-bc"):
        spin, tilt = machine.axes[1], machine.axes[0]
    else:
        spin, tilt = machine.axes[0], machine.axes[1]
    u = np.asarray(spin.direction)
    d_spin = np.radians(np.abs(a1[:, spin.column - 3] - a0[:, spin.column - 3]))
    d_tilt = np.radians(np.abs(a1[:, tilt.column - 3] - a0[:, tilt.column - 3]))
    sine = np.maximum(np.linalg.norm(np.cross(k0, u), axis=1), np.linalg.norm(np.cross(k1, u), axis=1))
    return d_tilt + d_spin * np.minimum(1.0, sine + d_tilt)


def _chords_for_turn(turn: np.ndarray, radius: np.ndarray, tol: float) -> np.ndarray:
    """Chords of an arc of ``radius`` through ``turn`` radians within ``tol`` (a first guess for
    a tip path turned by the rotary axes; :func:`tip_rows` checks and refines it)."""
    ratio = np.clip(tol / np.maximum(radius, tol), 0.0, 1.0)
    half = np.arccos(1.0 - ratio)
    return np.maximum(1, np.ceil(turn / np.maximum(2.0 * half, 1e-12))).astype(np.int64)


def _expand(counts: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(src, u0, u1): ``counts[i]`` equal parts of every row i."""
    src = np.repeat(np.arange(counts.shape[0], dtype=np.int64), counts)
    first = np.cumsum(counts) - counts
    sub = np.arange(src.shape[0], dtype=np.int64) - first[src]
    u0 = sub / counts[src]
    u1 = (sub + 1) / counts[src]
    return src, u0, u1


def tip_rows(machine: Machine, start, end, kind, feed, t_start, t_end, rot0, rot1, mode, arcs: ArcTable, *,
             end_time: float, chord_tolerance: float = DEFAULT_TIP_CHORD_MM,
             axis_step_deg: float = DEFAULT_AXIS_STEP_DEG) -> TipRows:
    """The tip path rows of the interpreter's five-axis rows (module docstring)."""
    n = start.shape[0]
    a0, a1 = _rotary_path(machine, np.asarray(rot0, np.float64), np.asarray(rot1, np.float64))
    tcp = (mode & MODE_TCP) != 0
    rows = _Rows(machine, start, end, kind, arcs, a0, a1, tcp)
    turn = _turn_radians(machine, a0, a1)
    turning = turn > 0.0
    step = math.radians(axis_step_deg)
    counts = np.ones(n, np.int64)
    spun = np.flatnonzero(turning)
    axis_turn = np.zeros(n)
    if spun.size:
        _, k0 = rows.pose(spun, np.zeros(spun.size))
        _, k1 = rows.pose(spun, np.ones(spun.size))
        axis_turn[spun] = _axis_turn(machine, a0[spun], a1[spun], k0, k1)
        counts[spun] = np.maximum(1, np.ceil(axis_turn[spun] / step - 1e-9)).astype(np.int64)

    # arcs: exact where the tip path is the programmed arc (TCP on) with the tool axis constant,
    # or the programmed arc moved rigidly with its plane's normal kept (TCP off at constant
    # rotary values); else chords
    arc_rows = arcs.segment
    exact_arc = np.zeros(len(arcs), bool)
    moved_centre = arcs.centre.copy()
    if len(arcs):
        still = ~turning[arc_rows]
        on = tcp[arc_rows]
        exact_arc = on & (axis_turn[arc_rows] == 0.0)
        off = np.flatnonzero(still & ~on)
        if off.size:
            joints = _joints(arcs.centre[off], a0[arc_rows[off]])
            R, _ = workpiece_to_machine(machine, joints)
            normal = arcs.normal_axis[off].astype(np.int64)
            # tip = R^T (J - ...) for tables (identity R for heads): the normal is kept when
            # R^T maps it to itself, i.e. R[n, n] == 1
            keeps = np.abs(R[np.arange(off.size), normal, normal] - 1.0) <= 1e-12
            exact_arc[off[keeps]] = True
            centre_tip, _ = forward(machine, joints[keeps])
            moved_centre[off[keeps]] = centre_tip
        chorded = np.flatnonzero(~exact_arc)
        if chorded.size:
            counts[arc_rows[chorded]] = np.maximum(counts[arc_rows[chorded]], arc_chord_counts(
                np.maximum(arcs.r_start[chorded], arcs.r_end[chorded]), arcs.sweep[chorded], chord_tolerance))

    # TCP off and turning: the tip path is curved; sample it within the chord tolerance
    curved = np.flatnonzero(turning & ~tcp)
    if curved.size:
        # a first guess from the tip's spread over five points; the loop below makes it right
        probe_u = np.linspace(0.0, 1.0, 5)
        r = np.repeat(curved, 5)
        tips, _ = rows.pose(r, np.tile(probe_u, curved.size))
        tips = tips.reshape(curved.size, 5, 3)
        spread = np.linalg.norm(tips - tips.mean(axis=1, keepdims=True), axis=2).max(axis=1)
        guess = _chords_for_turn(turn[curved], spread, chord_tolerance)
        counts[curved] = np.maximum(counts[curved], guess)
        todo = curved
        for _ in range(_MAX_REFINE):
            src, u0, u1 = _expand(counts[todo])
            r = todo[src]
            p0, _ = rows.pose(r, u0)
            p1, _ = rows.pose(r, u1)
            pm, _ = rows.pose(r, 0.5 * (u0 + u1))
            dev = _segment_distance(pm, p0, p1)
            worst = np.zeros(todo.size)
            np.maximum.at(worst, src, dev)
            bad = worst > chord_tolerance
            if not bad.any():
                break
            # a chord's sagitta falls with the square of the count
            factor = np.sqrt(worst[bad] / chord_tolerance) * 1.1
            counts[todo[bad]] = np.ceil(counts[todo[bad]] * np.maximum(factor, 1.5)).astype(np.int64)
            todo = todo[bad]

    src, u0, u1 = _expand(counts)
    node_rows = np.concatenate([src, src])
    node_u = np.concatenate([u0, u1])
    tips, _ = rows.pose(node_rows, node_u)
    m = src.shape[0]
    p_start, p_end = tips[:m], tips[m:]
    # the axis at each sub-row's middle (at its start where the row does not turn: exact)
    um = np.where(turning[src], 0.5 * (u0 + u1), 0.0)
    _, axis = rows.pose(src, um)
    rot_end = rows.rot(src, u1)

    # exact arcs keep their table entries (moved with the tip)
    one_piece = counts[arc_rows] == 1
    keep = np.flatnonzero(exact_arc & one_piece)
    first = np.cumsum(counts) - counts
    new_arcs = ArcTable(segment=first[arc_rows[keep]].astype(np.int64), centre=moved_centre[keep],
                        normal_axis=arcs.normal_axis[keep], sweep=arcs.sweep[keep], r_start=arcs.r_start[keep],
                        r_end=arcs.r_end[keep], length=arcs.length[keep])
    sub_kind = kind[src].copy()
    sub_kind[sub_kind > LINEAR] = LINEAR
    sub_kind[new_arcs.segment] = kind[arc_rows[keep]]

    # time: the tip's length over the feed; rotary degrees over F (deg/min) when it stands still
    length = np.linalg.norm(p_end - p_start, axis=1)
    length[new_arcs.segment] = new_arcs.length
    row_length = np.bincount(src, weights=length, minlength=n)
    cum = np.concatenate([[0.0], np.cumsum(length)])
    before = cum[:-1] - cum[first[src]]  # tip length of the row before each sub-row
    travel = np.zeros(n)
    for ax in machine.axes:
        c = ax.column - 3
        travel = np.maximum(travel, np.abs(a1[:, c] - a0[:, c]))
    feed = np.asarray(feed, np.float64)
    old = np.asarray(t_end, np.float64) - np.asarray(t_start, np.float64)
    moving = row_length > _STILL_MM
    inverse_time = (mode & MODE_INVERSE_TIME) != 0
    safe_feed = np.where(feed > 0, feed, 1.0)
    duration = np.where(moving, row_length / safe_feed, travel / safe_feed)
    duration = np.where(inverse_time | (feed <= 0), old, duration)
    # rows start where the previous one ended plus the interpreter's gap (dwells, E-only moves),
    # accumulated as the interpreter does, so that a row without a gap starts at exactly the
    # time the previous one ends (the beads chain on equal times)
    t_start = np.asarray(t_start, np.float64)
    gap = np.zeros(n)
    if n > 1:
        gap[:-1] = t_start[1:] - np.asarray(t_end, np.float64)[:-1]
    step_t = duration + gap
    new_t0 = np.cumsum(np.concatenate([t_start[:1], step_t[:-1]])) if n else np.zeros(0)
    # each sub-row's share, from the tip length before it (by fraction of the joint move when the
    # tip stands still); a sub-row ends at exactly its successor's start
    frac0 = np.where(moving[src], before / np.where(moving, row_length, 1.0)[src], u0)
    last = np.zeros(m, bool)
    last[np.cumsum(counts) - 1] = True
    frac1 = np.empty(m)
    frac1[:-1] = frac0[1:]
    frac1[last] = 1.0
    t0 = new_t0[src] + frac0 * duration[src]
    t1 = np.empty(m)
    t1[:-1] = t0[1:]
    t1[last] = new_t0[src[last]] + duration[src[last]]
    end_shift = (new_t0[-1] + duration[-1]) - float(np.asarray(t_end, np.float64)[-1]) if n else 0.0
    speed = np.where(moving & (duration > 0), row_length / np.where(duration > 0, duration, 1.0), feed)
    return TipRows(src=src, frac0=frac0, frac1=frac1, start=p_start, end=p_end, axis=axis.astype(np.float32),
                   rotary=rot_end.astype(np.float32), kind=sub_kind, feed=speed[src].astype(np.float32),
                   t_start=t0, t_end=t1, arcs=new_arcs,
                   end_time=float(end_time + end_shift))


__all__ = ["DEFAULT_AXIS_STEP_DEG", "DEFAULT_TIP_CHORD_MM", "TipRows", "tip_rows"]
