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


def arc_points(tp: Toolpath, arc: int, fractions: np.ndarray) -> np.ndarray:
    """Points (k, 3) at the given fractions (0 = start, 1 = end) along arc ``arc``."""
    arcs = tp.arcs
    row = int(arcs.segment[arc])
    normal = int(arcs.normal_axis[arc])
    a0, a1 = PLANE_AXES[normal]
    start = tp.start[row]
    centre = arcs.centre[arc]
    theta0 = np.arctan2(start[a1] - centre[a1], start[a0] - centre[a0])
    f = np.asarray(fractions, np.float64)
    theta = theta0 + f * arcs.sweep[arc]
    radius = arcs.r_start[arc] + f * (arcs.r_end[arc] - arcs.r_start[arc])
    points = np.empty((f.shape[0], 3), np.float64)
    points[:, a0] = centre[a0] + radius * np.cos(theta)
    points[:, a1] = centre[a1] + radius * np.sin(theta)
    points[:, normal] = start[normal] + f * (tp.end[row, normal] - start[normal])
    return points


def arc_chord_count(radius: float, sweep: float, chord_tolerance: float) -> int:
    """Chords needed so that no chord strays more than ``chord_tolerance`` from the arc."""
    if radius <= chord_tolerance:
        return max(1, int(np.ceil(abs(sweep) / (np.pi / 2))))
    half_angle = np.arccos(1.0 - chord_tolerance / radius)
    return max(1, int(np.ceil(abs(sweep) / (2.0 * half_angle))))


def linearized(tp: Toolpath, chord_tolerance: float = DEFAULT_CHORD_TOLERANCE_MM) -> Toolpath:
    """Replace every arc row by chords within ``chord_tolerance``; times split by length."""
    if len(tp.arcs) == 0:
        return tp
    counts = np.ones(len(tp), np.int64)
    for a in range(len(tp.arcs)):
        radius = max(tp.arcs.r_start[a], tp.arcs.r_end[a])
        counts[tp.arcs.segment[a]] = arc_chord_count(radius, tp.arcs.sweep[a], chord_tolerance)
    src = np.repeat(np.arange(len(tp)), counts)
    first = np.cumsum(counts) - counts
    sub = np.arange(src.shape[0]) - first[src]
    frac0 = sub / counts[src]
    frac1 = (sub + 1) / counts[src]
    start = tp.start[src] + frac0[:, None] * (tp.end[src] - tp.start[src])
    end = np.where((frac1 == 1.0)[:, None], tp.end[src], tp.start[src] + frac1[:, None] * (tp.end[src] - tp.start[src]))
    for a in range(len(tp.arcs)):
        row = tp.arcs.segment[a]
        sel = slice(first[row], first[row] + counts[row])
        pts = arc_points(tp, a, np.linspace(0.0, 1.0, counts[row] + 1))
        start[sel] = pts[:-1]
        end[sel] = pts[1:]
    duration = tp.t_end[src] - tp.t_start[src]
    kind = tp.kind[src].copy()
    kind[kind > LINEAR] = LINEAR
    return dataclasses.replace(
        tp, start=start, end=end, deposit=tp.deposit[src], kind=kind, feed=tp.feed[src], power=tp.power[src],
        t_start=tp.t_start[src] + frac0 * duration, t_end=tp.t_start[src] + frac1 * duration,
        line=tp.line[src], layer=tp.layer[src], rotary=tp.rotary[src], arcs=ArcTable.empty(),
    )


def _arc_extreme_fractions(tp: Toolpath, arc: int) -> np.ndarray:
    """Fractions where an arc reaches an in-plane axis extreme (for exact bounding boxes)."""
    normal = int(tp.arcs.normal_axis[arc])
    a0, a1 = PLANE_AXES[normal]
    row = int(tp.arcs.segment[arc])
    centre = tp.arcs.centre[arc]
    start = tp.start[row]
    theta0 = np.arctan2(start[a1] - centre[a1], start[a0] - centre[a0])
    sweep = tp.arcs.sweep[arc]
    quarter = np.pi / 2
    lo, hi = sorted((theta0, theta0 + sweep))
    k = np.arange(np.ceil(lo / quarter), np.floor(hi / quarter) + 1)
    return np.concatenate([[0.0, 1.0], (k * quarter - theta0) / sweep])


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
    for a in np.flatnonzero(mask[tp.arcs.segment]):
        pts = arc_points(tp, a, _arc_extreme_fractions(tp, a))
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
    return dataclasses.replace(
        tp, start=tp.start[mask], end=tp.end[mask], deposit=tp.deposit[mask], kind=tp.kind[mask],
        feed=tp.feed[mask], power=tp.power[mask], t_start=tp.t_start[mask], t_end=tp.t_end[mask],
        line=tp.line[mask], layer=tp.layer[mask], rotary=tp.rotary[mask], arcs=arcs,
    )


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
    return dataclasses.replace(cut, end=end, t_end=t_end, arcs=arcs)
