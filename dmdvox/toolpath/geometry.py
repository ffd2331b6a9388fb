"""Geometry on toolpaths: arc evaluation, linearisation, bounding boxes, truncation in time."""

from __future__ import annotations

import dataclasses

import numpy as np
from numba import njit

from .model import LINEAR, ArcTable, Toolpath

DEFAULT_CHORD_TOLERANCE_MM = 0.01

# In-plane axes (first, second) for each normal axis, ordered so that positive sweep is
# counter-clockwise seen from the normal's positive end (RS274: G18's plane is Z-X).
PLANE_AXES = {0: (1, 2), 1: (2, 0), 2: (0, 1)}


# in-plane axes as arrays indexed by the normal axis, for many arcs at once
_AXIS0 = np.array([PLANE_AXES[n][0] for n in range(3)])
_AXIS1 = np.array([PLANE_AXES[n][1] for n in range(3)])


def _arc_start_angles(tp: Toolpath, arcs: np.ndarray) -> np.ndarray:
    rows = tp.arcs.segment[arcs]
    normal = tp.arcs.normal_axis[arcs]
    centre = tp.arcs.centre[arcs]
    k = np.arange(arcs.shape[0])
    return np.arctan2(tp.start[rows, _AXIS1[normal]] - centre[k, _AXIS1[normal]],
                      tp.start[rows, _AXIS0[normal]] - centre[k, _AXIS0[normal]])


def arc_points(tp: Toolpath, arc, fractions) -> np.ndarray:
    """Points (k, 3) at ``fractions`` (0 = start, 1 = end) along arcs ``arc`` (one index, or
    one per fraction)."""
    f = np.asarray(fractions, np.float64).reshape(-1)
    arcs = np.broadcast_to(np.asarray(arc, np.int64), f.shape)
    table = tp.arcs
    rows = table.segment[arcs]
    normal = table.normal_axis[arcs].astype(np.int64)
    a0, a1 = _AXIS0[normal], _AXIS1[normal]
    centre = table.centre[arcs]
    k = np.arange(f.shape[0])
    theta = _arc_start_angles(tp, arcs) + f * table.sweep[arcs]
    radius = table.r_start[arcs] + f * (table.r_end[arcs] - table.r_start[arcs])
    points = np.empty((f.shape[0], 3), np.float64)
    points[k, a0] = centre[k, a0] + radius * np.cos(theta)
    points[k, a1] = centre[k, a1] + radius * np.sin(theta)
    points[k, normal] = tp.start[rows, normal] + f * (tp.end[rows, normal] - tp.start[rows, normal])
    return points


def arc_chord_counts(radius: np.ndarray, sweep: np.ndarray, chord_tolerance: float) -> np.ndarray:
    """Chords needed so that no chord strays more than ``chord_tolerance`` from its arc."""
    radius = np.asarray(radius, np.float64)
    sweep = np.abs(np.asarray(sweep, np.float64))
    tiny = radius <= chord_tolerance
    half_angle = np.arccos(1.0 - chord_tolerance / np.where(tiny, 2.0 * chord_tolerance, radius))
    counts = np.where(tiny, np.ceil(sweep / (np.pi / 2)), np.ceil(sweep / (2.0 * half_angle)))
    return np.maximum(1, counts).astype(np.int64)


def linearized(tp: Toolpath, chord_tolerance: float = DEFAULT_CHORD_TOLERANCE_MM) -> Toolpath:
    """Replace every arc row by chords within ``chord_tolerance``; times split by length."""
    if len(tp.arcs) == 0:
        return tp
    counts = np.ones(len(tp), np.int64)
    counts[tp.arcs.segment] = arc_chord_counts(np.maximum(tp.arcs.r_start, tp.arcs.r_end), tp.arcs.sweep,
                                               chord_tolerance)
    src = np.repeat(np.arange(len(tp)), counts)
    first = np.cumsum(counts) - counts
    sub = np.arange(src.shape[0]) - first[src]
    frac0 = sub / counts[src]
    frac1 = (sub + 1) / counts[src]
    start = tp.start[src] + frac0[:, None] * (tp.end[src] - tp.start[src])
    end = np.where((frac1 == 1.0)[:, None], tp.end[src], tp.start[src] + frac1[:, None] * (tp.end[src] - tp.start[src]))
    arc_of_row = np.full(len(tp), -1, np.int64)
    arc_of_row[tp.arcs.segment] = np.arange(len(tp.arcs))
    chord_arc = arc_of_row[src]
    on_arc = np.flatnonzero(chord_arc >= 0)
    start[on_arc] = arc_points(tp, chord_arc[on_arc], frac0[on_arc])
    end[on_arc] = arc_points(tp, chord_arc[on_arc], frac1[on_arc])
    duration = tp.t_end[src] - tp.t_start[src]
    rows = tp.take_rows(src)
    rows["kind"][rows["kind"] > LINEAR] = LINEAR
    # a chord carries its share of the row's material; the dwell before the row stays with the first
    rows["e_material"] = (tp.e_material[src] / counts[src]).astype(np.float32)
    rows["dwell_on"] = np.where(sub == 0, tp.dwell_on[src], np.float32(0.0)).astype(np.float32)
    rows.update(start=start, end=end, t_start=tp.t_start[src] + frac0 * duration,
                t_end=tp.t_start[src] + frac1 * duration)
    return dataclasses.replace(tp, **rows, arcs=ArcTable.empty())


def _arc_extreme_fractions(tp: Toolpath, arcs: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(arc, fraction) pairs covering where each arc reaches an in-plane axis extreme, plus its
    ends (for exact bounding boxes). Many turns (P words): the radius changes linearly, so along
    each axis direction the extreme is on the first or the last turn; four quarter angles from
    each end cover both."""
    theta0 = _arc_start_angles(tp, arcs)
    sweep = tp.arcs.sweep[arcs]
    quarter = np.pi / 2
    lo = np.minimum(theta0, theta0 + sweep)
    hi = np.maximum(theta0, theta0 + sweep)
    k_first = np.ceil(lo / quarter)[:, None]
    k_last = np.floor(hi / quarter)[:, None]
    steps = np.arange(4)
    k = np.concatenate([k_first + steps, k_last - steps], axis=1)
    valid = (k >= k_first) & (k <= k_last) & (sweep != 0.0)[:, None]
    safe_sweep = np.where(sweep == 0.0, 1.0, sweep)[:, None]
    fractions = np.where(valid, (k * quarter - theta0[:, None]) / safe_sweep, 0.0)
    fractions = np.concatenate([np.zeros((arcs.shape[0], 1)), np.ones((arcs.shape[0], 1)), fractions], axis=1)
    return np.repeat(arcs, fractions.shape[1]), fractions.reshape(-1)


@njit(cache=True)
def _masked_bounds(start, end, mask):
    """Box of the start and end points of the rows in ``mask``, in one pass (no copies: `info`
    runs this over millions of rows)."""
    lo = np.full(3, np.inf)
    hi = np.full(3, -np.inf)
    for i in range(start.shape[0]):
        if mask[i]:
            for a in range(3):
                lo[a] = min(lo[a], start[i, a], end[i, a])
                hi[a] = max(hi[a], start[i, a], end[i, a])
    return lo, hi


def path_bbox(tp: Toolpath, mask: np.ndarray) -> np.ndarray:
    """Bounding box of the rows in ``mask`` (arcs exactly, spirals through their extremes)."""
    mask = np.asarray(mask, np.bool_)
    if not np.any(mask):
        return np.zeros((2, 3), np.float64)
    lo, hi = _masked_bounds(tp.start, tp.end, mask)
    arcs = np.flatnonzero(mask[tp.arcs.segment])
    if arcs.size:
        pts = arc_points(tp, *_arc_extreme_fractions(tp, arcs))
        lo = np.minimum(lo, pts.min(axis=0))
        hi = np.maximum(hi, pts.max(axis=0))
    return np.stack([lo, hi])


def select_rows(tp: Toolpath, mask: np.ndarray) -> Toolpath:
    mask = np.asarray(mask, bool)
    new_index = np.cumsum(mask) - 1
    keep_arc = mask[tp.arcs.segment]
    arcs = ArcTable(
        segment=new_index[tp.arcs.segment[keep_arc]].astype(np.int64), centre=tp.arcs.centre[keep_arc],
        normal_axis=tp.arcs.normal_axis[keep_arc], sweep=tp.arcs.sweep[keep_arc],
        r_start=tp.arcs.r_start[keep_arc], r_end=tp.arcs.r_end[keep_arc], length=tp.arcs.length[keep_arc],
    )
    return dataclasses.replace(tp, **tp.take_rows(mask), arcs=arcs)


def truncate(tp: Toolpath, time_s: float) -> Toolpath:
    """Rows started by ``time_s``; the row in progress ends where the tool is at that time."""
    keep = tp.t_start < time_s
    cut = select_rows(tp, keep)
    if len(cut) == 0:
        return cut
    last = len(cut) - 1
    if cut.t_end[last] <= time_s:
        return cut
    duration = cut.t_end[last] - cut.t_start[last]
    frac = (time_s - cut.t_start[last]) / duration
    end = cut.end.copy()
    t_end = cut.t_end.copy()
    t_end[last] = time_s
    e_material = cut.e_material.copy()
    e_material[last] *= frac
    sweep = cut.arcs.sweep
    r_end = cut.arcs.r_end
    arc_length = cut.arcs.length
    arc_hit = np.flatnonzero(cut.arcs.segment == last)
    if arc_hit.size:
        a = int(arc_hit[0])
        end[last] = arc_points(cut, a, np.array([frac]))[0]
        sweep = sweep.copy()
        r_end = r_end.copy()
        sweep[a] *= frac
        arc_length = arc_length.copy()
        arc_length[a] *= frac  # time is linear in length; the angle follows it exactly unless the radius spirals
        r_end[a] = cut.arcs.r_start[a] + frac * (cut.arcs.r_end[a] - cut.arcs.r_start[a])
    else:
        end[last] = cut.start[last] + frac * (cut.end[last] - cut.start[last])
    arcs = dataclasses.replace(cut.arcs, sweep=sweep, r_end=r_end, length=arc_length)
    return dataclasses.replace(cut, end=end, t_end=t_end, e_material=e_material, arcs=arcs)
