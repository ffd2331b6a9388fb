"""Collisions along a toolpath: the nozzle at sampled poses against the growing part and fixtures.

Every row, deposit and travel alike, is sampled so that consecutive poses are at most ``step``
apart (half a voxel: along a row the tool axis is fixed and the nozzle only translates, so no
nozzle point moves more than that between samples). Each pose is checked at its own time
against the part as it stands then (material with arrival <= t, so the bead being laid counts),
the fixtures and the build plate. Results are grouped per (G-code line, obstacle).

Five-axis programs: everything is in the workpiece frame, where the toolpath's rows are. The
nozzle (its mesh's +Z) follows the tool axis with its tip at the path point plus the standoff
along the axis. The rows carry the axis at the middle of their turn; the poses turn it
continuously through those (see :func:`sample_poses`), so that no nozzle point moves more
than ``step`` between poses. Its turn about its own axis is not modelled (the minimal rotation
from +Z is used: a coaxial nozzle is exact). Fixtures bolted to the table and the part are
static in the workpiece frame; the plate is the table (head-head machines: workpiece frame =
machine frame).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..toolpath.geometry import linearized
from ..toolpath.model import Toolpath
from .bodies import Body
from .kernels import query_poses_rotated

TOOL_AXIS = np.array([0.0, 0.0, 1.0])  # a 3-axis machine's tool axis


DEPTH_CAP_TOL_MM = 1e-4  # a depth this close to the bands' sum is the measurement's limit


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
    axis: np.ndarray | None = None  # (n, 3) float64 unit tool axis; None: +Z everywhere


def axis_rotations(axis: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(Rs (m, 3, 3), index (n,)): the minimal rotation taking +Z to each distinct unit axis, and
    each pose's. +Z gives the identity exactly (the kernels' fixed-axis fast path)."""
    uniq, index = np.unique(np.asarray(axis, np.float64), axis=0, return_inverse=True)
    k = uniq / np.linalg.norm(uniq, axis=1, keepdims=True)
    c = k[:, 2]
    vx, vy = -k[:, 1], k[:, 0]  # v = z x k
    Rs = np.zeros((k.shape[0], 3, 3))
    flip = c < -1.0 + 1e-12
    f = np.where(flip, 0.0, 1.0 / np.where(flip, 1.0, 1.0 + c))
    # R = I + [v]x + [v]x^2 / (1 + c), v = (vx, vy, 0)
    Rs[:, 0, 0] = 1.0 - vy * vy * f
    Rs[:, 0, 1] = vx * vy * f
    Rs[:, 0, 2] = vy
    Rs[:, 1, 0] = vx * vy * f
    Rs[:, 1, 1] = 1.0 - vx * vx * f
    Rs[:, 1, 2] = -vx
    Rs[:, 2, 0] = -vy
    Rs[:, 2, 1] = vx
    Rs[:, 2, 2] = 1.0 - (vx * vx + vy * vy) * f
    Rs[flip] = np.diag([1.0, -1.0, -1.0])  # upside down: half a turn about x
    return np.ascontiguousarray(Rs), np.ascontiguousarray(index.reshape(-1), np.int64)


def _slerp(a: np.ndarray, b: np.ndarray, f: np.ndarray) -> np.ndarray:
    """Unit vectors a fraction ``f`` of the way from ``a`` to ``b`` along the great circle
    (``a`` itself, bit for bit, where ``b`` equals it or ``f`` is 0; ``b`` where ``f`` is 1:
    poses of one axis share one rotation)."""
    theta = _angle(a, b)
    s = np.sin(theta)
    small = s < 1e-9
    wa = np.where(small, 1.0 - f, np.sin((1.0 - f) * theta) / np.where(small, 1.0, s))
    wb = np.where(small, f, np.sin(f * theta) / np.where(small, 1.0, s))
    out = wa[:, None] * a + wb[:, None] * b
    out /= np.linalg.norm(out, axis=1, keepdims=True)
    same = np.all(a == b, axis=1) | (f == 0.0)
    out[same] = a[same]
    out[f == 1.0] = b[f == 1.0]
    return out


@dataclass(frozen=True, eq=False)
class PathCheck:
    """The outcome of :func:`check_toolpath` (``as_dict`` gives the CLI's JSON)."""

    poses_checked: int
    # dicts: line, time_s, position_mm (tip), obstacle, depth_mm (the deepest pose of the line;
    # measured up to depth_limit_mm, the obstacle's and the nozzle's bands: when depth_capped the
    # true penetration is deeper; None for the plate, which is exact), depth_capped
    collisions: list
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


def sample_poses(tp: Toolpath, step: float, lever: float = 0.0) -> Poses:
    """Path points at most ``step`` apart along every row (both ends included), in time order.

    Five-axis rows (a tool axis per row, the middle of its turn): the axis turns continuously,
    from the middle of one row's to the next's at their junction, through each row's own at its
    middle (along great circles), and poses are close enough that a point ``lever`` mm from the
    path point (the nozzle's farthest) moves at most ``step`` between them too."""
    tp = linearized(tp, chord_tolerance=min(0.01, step / 2))
    n = len(tp)
    if n == 0:
        return Poses(np.zeros((0, 3)), np.zeros(0), np.zeros(0, np.int64), np.zeros(0, np.int64))
    delta = tp.end - tp.start
    length = np.linalg.norm(delta, axis=1)
    vertical = tp.vertical
    if not vertical:
        mid = tp.axis.astype(np.float64)
        mid /= np.linalg.norm(mid, axis=1, keepdims=True)
        # where each row's axis starts and ends. A row whose rotary values do not change keeps
        # its axis; at a junction (the path runs on, no jump) the axis is that of a row that
        # keeps it, else halfway between the two rows'; a turning row that ends the path (or a
        # jump) goes on past its middle as far as it came
        joined = np.all(np.abs(tp.end[:-1] - tp.start[1:]) <= 1e-9, axis=1)
        turning = np.zeros(n, bool)
        turning[1:] = joined & np.any(tp.rotary[1:] != tp.rotary[:-1], axis=1)
        junction = _slerp(mid[:-1], mid[1:], np.full(n - 1, 0.5))
        junction = np.where((~turning[:-1])[:, None], mid[:-1], np.where((~turning[1:])[:, None], mid[1:], junction))
        a_start = mid.copy()
        a_end = mid.copy()
        a_start[1:][joined] = junction[joined]
        a_end[:-1][joined] = junction[joined]
        open_end = turning.copy()
        open_end[:-1] &= ~joined
        a_end[open_end] = _slerp(a_start[open_end], mid[open_end], np.full(int(open_end.sum()), 2.0))
        # each half row turns its own angle over half the poses; a point lever mm up the nozzle
        # moves by the path's step plus lever times the turn
        turn = 2.0 * np.maximum(_angle(a_start, mid), _angle(mid, a_end))
        intervals = np.maximum(1, np.ceil((length + max(lever, 0.0) * turn) / step)).astype(np.int64)
    else:
        intervals = np.maximum(1, np.ceil(length / step)).astype(np.int64)
    rows = np.repeat(np.arange(n, dtype=np.int64), intervals + 1)
    first = np.cumsum(intervals + 1) - (intervals + 1)
    s = (np.arange(rows.shape[0], dtype=np.int64) - first[rows]) / intervals[rows]
    point = tp.start[rows] + s[:, None] * delta[rows]
    time = tp.t_start[rows] + s * (tp.t_end - tp.t_start)[rows]
    if vertical:
        return Poses(point, time, rows, tp.line[rows].astype(np.int64))
    early = s < 0.5
    axis = np.where(early[:, None], _slerp(a_start[rows], mid[rows], 2.0 * s),
                    _slerp(mid[rows], a_end[rows], 2.0 * s - 1.0))
    return Poses(point, time, rows, tp.line[rows].astype(np.int64), axis)


def _angle(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Angle (radians) between unit vectors, accurate near zero."""
    return np.arctan2(np.linalg.norm(np.cross(a, b), axis=1), np.einsum("ij,ij->i", a, b))


def _pose_distances(poses: Poses, tips: np.ndarray, Rs: np.ndarray, rot_index: np.ndarray, nozzle: Body,
                    obstacle: Obstacle, reach: float) -> np.ndarray:
    if obstacle.body is not None:
        d, _ = query_poses_rotated(obstacle.body.kernel_args(), nozzle.kernel_args(), Rs, rot_index, tips,
                                   poses.time, float(reach), True)
        return d.astype(np.float64)
    # the plate: the nozzle's lowest hull point (turned with the pose) against the plane, exact
    lowest = np.einsum("rj,mj->rm", Rs[:, 2, :], nozzle.hull).min(axis=1)
    return tips[:, 2] + lowest[rot_index] - float(obstacle.plate_z)


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
    obstacles' bands plus ``reach`` (see :mod:`dmdvox.collision.kernels`).
    """
    lever = abs(float(standoff)) + float(np.linalg.norm(nozzle.hull, axis=1).max(initial=0.0))
    poses = sample_poses(tp, step, lever)
    if poses.axis is None:
        tips = np.ascontiguousarray(poses.point + standoff * TOOL_AXIS)
        Rs, rot_index = np.eye(3)[None], np.zeros(poses.time.shape[0], np.int64)
    else:
        tips = np.ascontiguousarray(poses.point + standoff * poses.axis)
        Rs, rot_index = axis_rotations(poses.axis)
    collisions: list[dict] = []
    near: list[dict] = []
    closest = np.inf
    nearest = np.full(poses.time.shape[0], float(reach))
    for obstacle in obstacles:
        d = _pose_distances(poses, tips, Rs, rot_index, nozzle, obstacle, reach)
        np.minimum(nearest, d, out=nearest)
        hit = d < 0.0
        found = _records(d, hit, poses, tips, obstacle.label, "depth_mm", -d)
        # the clamped SDFs measure a penetration up to the two bands: beyond, a lower bound
        limit = None if obstacle.body is None else float(obstacle.body.band + nozzle.band)
        for c in found:
            c["depth_limit_mm"] = limit
            c["depth_capped"] = limit is not None and c["depth_mm"] >= limit - DEPTH_CAP_TOL_MM
        collisions += found
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
