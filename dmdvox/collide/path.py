"""Collisions along a toolpath: the nozzle at sampled poses against the growing part and fixtures.

Every row, deposit and travel alike, is sampled so that consecutive poses are at most ``step``
apart (half a voxel: with the tool axis fixed the nozzle only translates, so no nozzle point
moves more than that between samples). Each pose is checked at its own time against the part
as it stands then (material with arrival <= t, so the bead being laid counts), the fixtures
and the build plate. Results are grouped per (G-code line, obstacle).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..toolpath.geometry import linearized
from ..toolpath.model import Toolpath
from .bodies import Body
from .kernels import query_poses

TOOL_AXIS = np.array([0.0, 0.0, 1.0])  # without a kinematics model the tool axis is vertical


@dataclass(frozen=True, eq=False)
class Obstacle:
    """A body (``label`` ``part`` or ``fixture:<name>``) or the plate half-space z < ``plate_z``."""

    label: str
    body: Body | None = None
    plate_z: float | None = None


@dataclass(frozen=True, eq=False)
class Poses:
    point: np.ndarray  # (n, 3) float64 path point
    time: np.ndarray  # (n,) float64 s
    row: np.ndarray  # (n,) int64 row of the (linearized) toolpath
    line: np.ndarray  # (n,) int64 G-code line


@dataclass(frozen=True, eq=False)
class PathCheck:
    """The outcome of :func:`check_toolpath` (``as_dict`` gives the CLI's JSON)."""

    poses_checked: int
    collisions: list  # dicts: line, time_s, position_mm (tip), obstacle, depth_mm
    near_misses: list  # dicts: line, time_s, position_mm, obstacle, distance_mm
    min_clearance_mm: float | None  # None: nothing came within reach_mm
    reach_mm: float
    pose_time_s: np.ndarray  # (n,) time of every pose checked
    pose_clearance_mm: np.ndarray  # (n,) distance to the nearest obstacle (negative: depth), capped at reach_mm

    @property
    def first_collision_line(self) -> int | None:
        return self.collisions[0]["line"] if self.collisions else None

    def as_dict(self) -> dict:
        return {
            "poses_checked": self.poses_checked,
            "collisions": self.collisions,
            "first_collision_line": self.first_collision_line,
            "min_clearance_mm": self.min_clearance_mm,
            "near_misses": self.near_misses,
        }


def sample_poses(tp: Toolpath, step: float) -> Poses:
    """Path points at most ``step`` apart along every row (both ends included), in time order."""
    tp = linearized(tp, chord_tolerance=min(0.01, step / 2))
    n = len(tp)
    if n == 0:
        return Poses(np.zeros((0, 3)), np.zeros(0), np.zeros(0, np.int64), np.zeros(0, np.int64))
    delta = tp.end - tp.start
    intervals = np.maximum(1, np.ceil(np.linalg.norm(delta, axis=1) / step)).astype(np.int64)
    rows = np.repeat(np.arange(n, dtype=np.int64), intervals + 1)
    first = np.cumsum(intervals + 1) - (intervals + 1)
    s = (np.arange(rows.shape[0], dtype=np.int64) - first[rows]) / intervals[rows]
    point = tp.start[rows] + s[:, None] * delta[rows]
    time = tp.t_start[rows] + s * (tp.t_end - tp.t_start)[rows]
    return Poses(point, time, rows, tp.line[rows].astype(np.int64))


def _pose_distances(poses: Poses, tips: np.ndarray, nozzle: Body, obstacle: Obstacle, reach: float) -> np.ndarray:
    if obstacle.body is not None:
        d, _ = query_poses(obstacle.body.kernel_args(), nozzle.kernel_args(), np.eye(3), tips, poses.time,
                           float(reach), True)
        return d.astype(np.float64)
    # the plate: the nozzle's lowest hull point against the plane, exact
    return tips[:, 2] + nozzle.hull[:, 2].min() - float(obstacle.plate_z)


def _records(d: np.ndarray, sel: np.ndarray, poses: Poses, tips: np.ndarray, label: str, key: str,
             value: np.ndarray) -> list[dict]:
    """One record per line among the poses ``sel``: the first pose in time, with ``key`` the
    maximum of ``value`` over the line's selected poses."""
    idx = np.flatnonzero(sel)
    if idx.size == 0:
        return []
    lines = poses.line[idx]
    uniq, first, inverse = np.unique(lines, return_index=True, return_inverse=True)
    best = np.full(uniq.shape[0], -np.inf)
    np.maximum.at(best, inverse, value[idx])
    out = []
    for u in range(uniq.shape[0]):
        p = idx[first[u]]
        out.append({"line": int(uniq[u]), "time_s": float(poses.time[p]),
                    "position_mm": [float(c) for c in tips[p]], "obstacle": label, key: float(best[u])})
    return out


def check_toolpath(tp: Toolpath, nozzle: Body, obstacles: list[Obstacle], *, standoff: float, clearance: float,
                   step: float, reach: float) -> PathCheck:
    """Check every pose of ``tp`` (see module docstring).

    ``reach`` (>= ``clearance``) bounds the distances measured: the nozzle's band must exceed the
    obstacles' bands plus ``reach`` (see :mod:`dmdvox.collide.kernels`).
    """
    poses = sample_poses(tp, step)
    tips = np.ascontiguousarray(poses.point + standoff * TOOL_AXIS)
    collisions: list[dict] = []
    near: list[dict] = []
    closest = np.inf
    nearest = np.full(poses.time.shape[0], float(reach))
    for obstacle in obstacles:
        d = _pose_distances(poses, tips, nozzle, obstacle, reach)
        np.minimum(nearest, d, out=nearest)
        hit = d < 0.0
        collisions += _records(d, hit, poses, tips, obstacle.label, "depth_mm", -d)
        if d.size:
            closest = min(closest, float(d.min()))
        # near misses: per line, the closest pose, on lines that do not collide with this obstacle
        hit_lines = np.unique(poses.line[hit])
        close = (d >= 0.0) & (d < clearance) & ~np.isin(poses.line, hit_lines)
        if close.any():
            idx = np.flatnonzero(close)
            order = idx[np.lexsort((d[idx], poses.line[idx]))]
            _, first = np.unique(poses.line[order], return_index=True)
            for p in order[first]:
                near.append({"line": int(poses.line[p]), "time_s": float(poses.time[p]),
                             "position_mm": [float(c) for c in tips[p]], "obstacle": obstacle.label,
                             "distance_mm": float(d[p])})
    collisions.sort(key=lambda c: (c["time_s"], c["line"], c["obstacle"]))
    near.sort(key=lambda c: (c["time_s"], c["line"], c["obstacle"]))
    min_clearance = None if not closest < reach else max(0.0, closest)
    return PathCheck(poses_checked=int(poses.time.shape[0]), collisions=collisions, near_misses=near,
                     min_clearance_mm=min_clearance, reach_mm=float(reach), pose_time_s=poses.time,
                     pose_clearance_mm=nearest)
