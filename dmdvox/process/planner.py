"""Motion planning: the speed the machine really runs each row at, not the programmed F.

The G-code reader times every row at its programmed speed (constant feed: the tool jumps to F
at the row's start and stops dead at its end). Real controllers (Grbl, Marlin, Klipper,
LinuxCNC's trajectory planner, the DED cells' CNCs) plan a **trapezoidal** speed profile with
constant acceleration ``a`` and a **look-ahead** over the queued moves. This module gives every
row of a :class:`~dmdvox.toolpath.model.Toolpath` that profile; see ``docs/MOTION.md`` for the
same formulas with worked numbers.

Per row (length ``L``, programmed speed ``F``, entry speed ``v0``, exit speed ``v1``)::

    accelerate at a from v0 to vc, cruise at vc, decelerate at a to v1
    vc = min(F, v_curve, sqrt((2 a L + v0^2 + v1^2) / 2))       # the last term: a triangle
    t  = (vc - v0)/a + (L - d_acc - d_dec)/vc + (vc - v1)/a,    d = (vc^2 - v^2) / (2 a)

Junction speed between rows i and i+1 (Grbl/Marlin **junction deviation**): with theta the
angle between the incoming direction and the *reverse* of the outgoing one
(``cos theta = -u_in . u_out``) and ``s = sin(theta / 2) = sqrt((1 - cos theta) / 2)``::

    v_j^2 = a * JD * s / (1 - s)

It is the speed at which a circle of radius ``JD s / (1 - s)`` tangent to both moves (its
closest point ``JD`` from the corner) is run at centripetal acceleration ``a``. A straight
continuation (theta = 180 deg, s = 1) gets no limit from the rule, a reversal (s = 0) stops.
The junction is also capped by both rows' speed limits.

Klipper's **square corner velocity** ``scv`` (default 5 mm/s) is the same rule with
``JD = scv^2 (sqrt 2 - 1) / a``: at 90 degrees ``s = 1/sqrt 2`` and ``v_j = scv`` exactly.
Marlin users with a classic **jerk** setting convert with Marlin's ``JD = 0.4 jerk^2 / a``
(:func:`junction_deviation_from_jerk`).

**Arcs**: the cruise speed is limited by the centripetal acceleration, ``v^2 <= a rho`` with
``rho`` the radius of curvature: for a plain arc ``rho = r`` (the smaller of the start and end
radius); a helix's rise and a spiral's radius change make the path straighter and ``rho``
follows the exact curvature of the curve ``(r(phi) cos phi, r(phi) sin phi, c phi)``. The
directions at an arc's ends are its exact tangents (rise and radius change included).

**Full stops** (speed 0): at the program's start and end; where the deposit flag changes
between rows (the beam/feeder switches with the motion synchronised); where the constant-feed
timing has a gap between rows (a dwell, an E-only retract: the controller drains its queue);
where row i's end is not row i+1's start (a jump after an unknown position); at zero-length
rows (nothing to plan: they take the time the constant-feed timing gave them, 0 unless G93).

**Look-ahead** over the whole program, on the junction speeds ``J[0..n]`` (``J[i]`` at the start
of row i, ``J[0] = J[n] = 0``), after the geometric/feed/stop limits above:

* backward pass, ``k = n-1 .. 1``: ``J[k] = min(J[k], sqrt(J[k+1]^2 + 2 a L[k]))`` so that the
  tool can still slow down to every later limit;
* forward pass, ``k = 1 .. n-1``: ``J[k] = min(J[k], sqrt(J[k-1]^2 + 2 a L[k-1]))`` so that every
  junction is reachable by accelerating from the earlier ones.

After both passes ``|J[k+1]^2 - J[k]^2| <= 2 a L[k]`` and the per-row trapezoid exists.

**Times**: the first row starts at the toolpath's ``t_start[0]``; each gap of the constant-feed
timing (dwell, retract, other motionless time) is kept as it was, and so is the motionless time
after the last row. ``accel_mm_s2 = 0`` is the constant-feed timing, bit for bit.

Everything per row runs in numba (``@njit(cache=True)``): a million rows plan in about 0.1 s
(``scripts/bench_planner.py``).
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass

import numpy as np
from numba import njit

from ..errors import DmdvoxError
from ..toolpath.geometry import PLANE_AXES
from ..toolpath.model import Toolpath

# Typical of DED cells: gantries and CNC machines carrying a deposition head of several kg
# (nozzle, powder or wire feed, optics) at deposition speeds of 5-25 mm/s accelerate far more
# gently than desktop printers (1000-5000 mm/s^2). At 500 mm/s^2 a 10 mm/s bead reaches F in
# 0.1 mm, so acceleration matters at corners and short moves, not along walls; this is also the
# figure REFERENCE.md section 5 uses for the excess material at a stop.
DEFAULT_ACCEL_MM_S2 = 500.0
# Grbl's default junction deviation (0.01 mm) is tuned for milling and Marlin's (0.013 mm) for
# light printer heads. 0.05 mm is what Marlin's own conversion JD = 0.4 jerk^2 / a gives for a
# classic jerk of 7.9 mm/s at 500 mm/s^2 (Marlin's default XY jerk of 10 mm/s gives 0.08 mm):
# DED moves are slow and the melt pool tolerates a slightly rounded corner. A 90 degree corner
# then runs at sqrt(500 * 0.05 * 2.414) = 7.8 mm/s, near Klipper's default square-corner 5 mm/s.
DEFAULT_JUNCTION_DEVIATION_MM = 0.05
# Klipper's default square_corner_velocity.
DEFAULT_SQUARE_CORNER_VELOCITY_MM_S = 5.0

# A gap between one row's t_end and the next row's t_start larger than this (relative to the
# time, at least 1 s) is a real pause (dwell, retract), not rounding of the summed times.
GAP_REL_TOL = 1e-10
# Row i's end farther than this from row i+1's start is a position jump (mm).
JUMP_TOL_MM = 1e-6

_AXIS0 = np.array([PLANE_AXES[k][0] for k in range(3)], np.int64)
_AXIS1 = np.array([PLANE_AXES[k][1] for k in range(3)], np.int64)


def junction_deviation_from_jerk(jerk_mm_s: float, accel_mm_s2: float) -> float:
    """Marlin's conversion of a classic jerk setting: ``JD = 0.4 jerk^2 / a`` (mm)."""
    return 0.4 * jerk_mm_s * jerk_mm_s / accel_mm_s2


def junction_deviation_from_scv(scv_mm_s: float, accel_mm_s2: float) -> float:
    """Klipper's rule: ``JD = scv^2 (sqrt 2 - 1) / a``, so a 90 degree corner runs at ``scv``."""
    return scv_mm_s * scv_mm_s * (math.sqrt(2.0) - 1.0) / accel_mm_s2


def _finite_number(value, option: str, what: str) -> float:
    try:
        number = float(value)
    except (TypeError, ValueError):
        raise DmdvoxError(f"{option}: {value!r} is not a number; give {what}") from None
    if not math.isfinite(number):
        raise DmdvoxError(f"{option}: {value!r} is not a finite number; give {what}")
    return number


@dataclass(frozen=True)
class MotionSettings:
    """How the machine turns F into motion.

    ``accel_mm_s2 = 0`` keeps the constant-feed timing (the tool at F everywhere). With
    ``square_corner_velocity_mm_s`` given, the junction deviation is derived from it by
    Klipper's rule and ``junction_deviation_mm`` is ignored.
    """

    accel_mm_s2: float = DEFAULT_ACCEL_MM_S2
    junction_deviation_mm: float = DEFAULT_JUNCTION_DEVIATION_MM
    square_corner_velocity_mm_s: float | None = None

    def validate(self) -> None:
        accel = _finite_number(self.accel_mm_s2, "--accel", "an acceleration in mm/s^2 (0 = constant feed)")
        if accel < 0.0:
            raise DmdvoxError(f"--accel: {accel:g} mm/s^2 is negative; give a positive acceleration "
                              f"(default {DEFAULT_ACCEL_MM_S2:g}) or 0 for constant feed")
        jd = _finite_number(self.junction_deviation_mm, "--junction-deviation", "a distance in mm")
        if jd < 0.0:
            raise DmdvoxError(f"--junction-deviation: {jd:g} mm is negative; give a distance "
                              f">= 0 mm (default {DEFAULT_JUNCTION_DEVIATION_MM:g}; 0 stops at every corner)")
        if self.square_corner_velocity_mm_s is not None:
            scv = _finite_number(self.square_corner_velocity_mm_s, "--square-corner-velocity", "a speed in mm/s")
            if scv < 0.0:
                raise DmdvoxError(f"--square-corner-velocity: {scv:g} mm/s is negative; "
                                  f"give a speed >= 0 mm/s (Klipper's default {DEFAULT_SQUARE_CORNER_VELOCITY_MM_S:g})")

    @property
    def effective_junction_deviation_mm(self) -> float:
        """The junction deviation the planner uses (from the square-corner velocity when given)."""
        if self.square_corner_velocity_mm_s is not None and self.accel_mm_s2 > 0.0:
            return junction_deviation_from_scv(float(self.square_corner_velocity_mm_s), float(self.accel_mm_s2))
        return float(self.junction_deviation_mm)

    def to_json(self) -> dict:
        scv = self.square_corner_velocity_mm_s
        return {
            "accel_mm_s2": float(self.accel_mm_s2),
            "junction_deviation_mm": float(self.junction_deviation_mm),
            "square_corner_velocity_mm_s": None if scv is None else float(scv),
            "effective_junction_deviation_mm": self.effective_junction_deviation_mm,
            "constant_feed": float(self.accel_mm_s2) == 0.0,
        }


# ---------------------------------------------------------------------------------------------
# numba kernels


@njit(cache=True)
def _row_geometry(start, end, length, arc_seg, arc_centre, arc_axis, arc_sweep, arc_r0, arc_r1, axis0, axis1,
                  u_in, u_out, curvature):
    """Unit directions at each row's start (``u_in``) and end (``u_out``) and the largest
    curvature along it (0 for lines). Zero-length rows get zero directions."""
    n = start.shape[0]
    for i in range(n):
        L = length[i]
        curvature[i] = 0.0
        if L > 0.0:
            for ax in range(3):
                d = (end[i, ax] - start[i, ax]) / L
                u_in[i, ax] = d
                u_out[i, ax] = d
        else:
            for ax in range(3):
                u_in[i, ax] = 0.0
                u_out[i, ax] = 0.0
    for k in range(arc_seg.shape[0]):
        i = arc_seg[k]
        nrm = np.int64(arc_axis[k])
        a0 = axis0[nrm]
        a1 = axis1[nrm]
        sweep = arc_sweep[k]
        r0 = arc_r0[k]
        r1 = arc_r1[k]
        rise = end[i, nrm] - start[i, nrm]
        th0 = np.arctan2(start[i, a1] - arc_centre[k, a1], start[i, a0] - arc_centre[k, a0])
        th1 = th0 + sweep
        # dP/df along the arc, f the fraction: radius change radially, r * sweep tangentially, rise
        for end_side in range(2):
            th = th0 if end_side == 0 else th1
            r = r0 if end_side == 0 else r1
            c = np.cos(th)
            s = np.sin(th)
            dr = r1 - r0
            t0 = dr * c - r * sweep * s
            t1 = dr * s + r * sweep * c
            tn = rise
            norm = np.sqrt(t0 * t0 + t1 * t1 + tn * tn)
            if norm > 0.0 and length[i] > 0.0:
                t0 /= norm
                t1 /= norm
                tn /= norm
            else:
                t0 = 0.0
                t1 = 0.0
                tn = 0.0
            if end_side == 0:
                u_in[i, 0] = 0.0
                u_in[i, 1] = 0.0
                u_in[i, 2] = 0.0
                u_in[i, a0] = t0
                u_in[i, a1] = t1
                u_in[i, nrm] = tn
            else:
                u_out[i, 0] = 0.0
                u_out[i, 1] = 0.0
                u_out[i, 2] = 0.0
                u_out[i, a0] = t0
                u_out[i, a1] = t1
                u_out[i, nrm] = tn
        # Curvature of (r(phi) cos phi, r(phi) sin phi, c phi), r' = b per radian:
        # kappa = sqrt(c^2 (4 b^2 + r^2) + (2 b^2 + r^2)^2) / (b^2 + r^2 + c^2)^1.5, largest at the
        # smaller radius (decreasing in r); a plain arc (b = c = 0) gives 1 / r.
        span = abs(sweep)
        kappa = 0.0
        if span > 0.0 and length[i] > 0.0:
            b = (r1 - r0) / span
            cz = rise / span
            for end_side in range(2):
                r = r0 if end_side == 0 else r1
                den = b * b + r * r + cz * cz
                if den > 0.0:
                    num = np.sqrt(cz * cz * (4.0 * b * b + r * r) + (2.0 * b * b + r * r) ** 2)
                    kv = num / (den * np.sqrt(den))
                    if kv > kappa:
                        kappa = kv
        curvature[i] = kappa


@njit(cache=True)
def _plan_kernel(start, end, deposit, feed, t_start, t_end, length, u_in, u_out, curvature, accel, jd,
                 gap_rel_tol, jump_tol, v_entry, v_cruise, v_exit, new_start, new_end):
    n = start.shape[0]
    vmax = np.empty(n)
    for i in range(n):
        L = length[i]
        if L > 0.0:
            v = np.float64(feed[i])
            if curvature[i] > 0.0:
                vc = np.sqrt(accel / curvature[i])
                if vc < v:
                    v = vc
            vmax[i] = v
        else:
            vmax[i] = 0.0

    # Junction limits J[k] at the start of row k (J[n]: the end of the last row).
    J = np.empty(n + 1)
    J[0] = 0.0
    J[n] = 0.0
    for k in range(1, n):
        i = k - 1
        stop = deposit[i] != deposit[k]
        gap = t_start[k] - t_end[i]
        if gap > gap_rel_tol * max(1.0, abs(t_end[i])):
            stop = True
        for ax in range(3):
            if abs(end[i, ax] - start[k, ax]) > jump_tol:
                stop = True
        if stop:
            J[k] = 0.0
            continue
        lim = min(vmax[i], vmax[k])
        cos_theta = -(u_out[i, 0] * u_in[k, 0] + u_out[i, 1] * u_in[k, 1] + u_out[i, 2] * u_in[k, 2])
        s2 = 0.5 * (1.0 - cos_theta)
        s = np.sqrt(max(s2, 0.0))
        if s < 1.0 - 1e-12:
            vj = np.sqrt(accel * jd * s / (1.0 - s))
            if vj < lim:
                lim = vj
        J[k] = lim

    two_a = 2.0 * accel
    for k in range(n - 1, 0, -1):  # backward: able to slow down to every later limit
        reach = np.sqrt(J[k + 1] * J[k + 1] + two_a * length[k])
        if reach < J[k]:
            J[k] = reach
    for k in range(1, n):  # forward: reachable by accelerating from the earlier ones
        reach = np.sqrt(J[k - 1] * J[k - 1] + two_a * length[k - 1])
        if reach < J[k]:
            J[k] = reach

    t = t_start[0] if n > 0 else 0.0
    for i in range(n):
        if i > 0:
            t = new_end[i - 1] + (t_start[i] - t_end[i - 1])
        v0 = J[i]
        v1 = J[i + 1]
        L = length[i]
        peak = np.sqrt(max((two_a * L + v0 * v0 + v1 * v1) * 0.5, 0.0))
        vc = min(vmax[i], peak)
        if vc < v0:  # rounding only: the passes keep v0, v1 <= vmax and <= the peak
            vc = v0
        if vc < v1:
            vc = v1
        v_entry[i] = v0
        v_exit[i] = v1
        v_cruise[i] = vc
        if L > 0.0 and vc > 0.0:
            d_acc = (vc * vc - v0 * v0) / two_a
            d_dec = (vc * vc - v1 * v1) / two_a
            d_cruise = max(L - d_acc - d_dec, 0.0)
            duration = (vc - v0) / accel + d_cruise / vc + (vc - v1) / accel
        else:
            duration = t_end[i] - t_start[i]  # zero-length rows keep their constant-feed time
        new_start[i] = t
        new_end[i] = t + duration


@njit(cache=True)
def _profile_kernel(rows, values, mode, v_entry, v_cruise, v_exit, t_start, t_end, length, accel, out):
    """mode 0: speed at distance; 1: time at distance; 2: distance at time."""
    for q in range(rows.shape[0]):
        i = rows[q]
        v0 = v_entry[i]
        vc = v_cruise[i]
        v1 = v_exit[i]
        L = length[i]
        duration = t_end[i] - t_start[i]
        if L <= 0.0 or vc <= 0.0 or accel <= 0.0:
            # constant feed (or a motionless row): linear in time
            if mode == 0:
                out[q] = vc if L > 0.0 else 0.0
            elif mode == 1:
                s = min(max(values[q], 0.0), L)
                out[q] = t_start[i] + (duration * (s / L) if L > 0.0 else 0.0)
            else:
                tau = min(max(values[q] - t_start[i], 0.0), duration)
                out[q] = L * (tau / duration) if duration > 0.0 else 0.0
            continue
        d_acc = min((vc * vc - v0 * v0) / (2.0 * accel), L)
        d_dec = (vc * vc - v1 * v1) / (2.0 * accel)
        d_cruise = max(L - d_acc - d_dec, 0.0)
        t_acc = (vc - v0) / accel
        t_cruise = d_cruise / vc
        if mode == 2:
            tau = min(max(values[q] - t_start[i], 0.0), duration)
            if tau <= t_acc:
                s = v0 * tau + 0.5 * accel * tau * tau
            elif tau <= t_acc + t_cruise:
                s = d_acc + vc * (tau - t_acc)
            else:  # decelerating: from the row's end backwards (exact at the end)
                w = min(duration - tau, (vc - v1) / accel)
                s = L - (v1 * w + 0.5 * accel * w * w)
            out[q] = min(max(s, 0.0), L)
            continue
        s = min(max(values[q], 0.0), L)
        if s <= d_acc:
            v = min(np.sqrt(v0 * v0 + 2.0 * accel * s), vc)
            tt = 2.0 * s / (v0 + v) if v0 + v > 0.0 else 0.0
        elif s <= d_acc + d_cruise:
            v = vc
            tt = t_acc + (s - d_acc) / vc
        else:
            x = s - d_acc - d_cruise
            v = min(np.sqrt(v1 * v1 + 2.0 * accel * max(L - s, 0.0)), vc)
            tt = t_acc + t_cruise + 2.0 * x / (vc + v)
        if mode == 0:
            out[q] = v
        else:
            out[q] = t_start[i] + min(tt, duration)


# ---------------------------------------------------------------------------------------------


@dataclass(frozen=True, eq=False)
class MotionPlan:
    """The planned speed profile of every row (trapezoids joined by the junction speeds)."""

    v_entry: np.ndarray  # (n,) float64 mm/s at the row's start
    v_cruise: np.ndarray  # (n,) float64 highest speed reached in the row (a triangle's peak)
    v_exit: np.ndarray  # (n,) float64 mm/s at the row's end
    t_start: np.ndarray  # (n,) float64 s
    t_end: np.ndarray  # (n,) float64 s
    accel: float  # mm/s^2 used (0: constant feed)
    settings: MotionSettings
    length: np.ndarray | None = None  # (n,) float64 row lengths (the toolpath's ``length``)
    tail_s: float = 0.0  # motionless time after the last row (kept from the toolpath)

    def __len__(self) -> int:
        return int(self.v_entry.shape[0])

    @property
    def duration_s(self) -> float:
        """Program duration: the last row's end plus the motionless time after it."""
        if len(self) == 0:
            return float(self.tail_s)
        return float(self.t_end[-1]) + float(self.tail_s)

    def _lengths(self) -> np.ndarray:
        if self.length is not None:
            return self.length
        # Derived from the profile when the plan was built without lengths.
        a = self.accel
        duration = self.t_end - self.t_start
        if a <= 0.0:
            return self.v_cruise * duration
        v0, vc, v1 = self.v_entry, self.v_cruise, self.v_exit
        t_acc, t_dec = (vc - v0) / a, (vc - v1) / a
        return (vc * vc - v0 * v0) / (2 * a) + (vc * vc - v1 * v1) / (2 * a) + vc * np.maximum(duration - t_acc - t_dec, 0)

    def _query(self, rows, values, mode: int) -> np.ndarray:
        rows_b, values_b = np.broadcast_arrays(np.asarray(rows, np.int64), np.asarray(values, np.float64))
        shape = rows_b.shape
        flat_rows = np.array(rows_b, np.int64).reshape(-1)  # copies: broadcast views are read-only
        if flat_rows.size and (flat_rows.min() < 0 or flat_rows.max() >= len(self)):
            raise IndexError(f"row index out of range for a plan of {len(self)} rows")
        out = np.empty(flat_rows.shape[0], np.float64)
        _profile_kernel(flat_rows, np.array(values_b, np.float64).reshape(-1), mode, self.v_entry,
                        self.v_cruise, self.v_exit, self.t_start, self.t_end,
                        np.ascontiguousarray(self._lengths(), np.float64), float(self.accel), out)
        return out.reshape(shape)

    def speed_at(self, rows, distance) -> np.ndarray:
        """Speed (mm/s) at ``distance`` mm from the start of ``rows`` (broadcast; clamped to the row)."""
        return self._query(rows, distance, 0)

    def time_at(self, rows, distance) -> np.ndarray:
        """Absolute time (s) at which the tool is ``distance`` mm into ``rows``."""
        return self._query(rows, distance, 1)

    def distance_at(self, rows, time) -> np.ndarray:
        """Distance (mm) from the start of ``rows`` at absolute ``time``, clamped to the row."""
        return self._query(rows, time, 2)


def plan_motion(tp: Toolpath, settings: MotionSettings = MotionSettings()) -> MotionPlan:
    """Plan the trapezoidal speed profile of every row of ``tp`` with look-ahead (see the module
    docstring for the rules)."""
    settings.validate()
    n = len(tp)
    length = np.ascontiguousarray(tp.length, np.float64)
    tail = max(float(tp.duration) - float(tp.t_end[-1]), 0.0) if n else float(tp.duration)
    accel = float(settings.accel_mm_s2)
    if accel == 0.0:
        feed = tp.feed.astype(np.float64)
        return MotionPlan(v_entry=feed, v_cruise=feed.copy(), v_exit=feed.copy(), t_start=tp.t_start.copy(),
                          t_end=tp.t_end.copy(), accel=0.0, settings=settings, length=length, tail_s=tail)
    start = np.ascontiguousarray(tp.start, np.float64)
    end = np.ascontiguousarray(tp.end, np.float64)
    arcs = tp.arcs
    u_in = np.empty((n, 3), np.float64)
    u_out = np.empty((n, 3), np.float64)
    curvature = np.empty(n, np.float64)
    _row_geometry(start, end, length, np.ascontiguousarray(arcs.segment, np.int64),
                  np.ascontiguousarray(arcs.centre, np.float64), np.ascontiguousarray(arcs.normal_axis, np.uint8),
                  np.ascontiguousarray(arcs.sweep, np.float64), np.ascontiguousarray(arcs.r_start, np.float64),
                  np.ascontiguousarray(arcs.r_end, np.float64), _AXIS0, _AXIS1, u_in, u_out, curvature)
    v_entry = np.empty(n, np.float64)
    v_cruise = np.empty(n, np.float64)
    v_exit = np.empty(n, np.float64)
    t_start = np.empty(n, np.float64)
    t_end = np.empty(n, np.float64)
    _plan_kernel(start, end, np.ascontiguousarray(tp.deposit, np.bool_), np.ascontiguousarray(tp.feed, np.float64),
                 np.ascontiguousarray(tp.t_start, np.float64), np.ascontiguousarray(tp.t_end, np.float64), length,
                 u_in, u_out, curvature, accel, settings.effective_junction_deviation_mm, GAP_REL_TOL, JUMP_TOL_MM,
                 v_entry, v_cruise, v_exit, t_start, t_end)
    return MotionPlan(v_entry=v_entry, v_cruise=v_cruise, v_exit=v_exit, t_start=t_start, t_end=t_end, accel=accel,
                      settings=settings, length=length, tail_s=tail)


def apply_plan(tp: Toolpath, plan: MotionPlan) -> Toolpath:
    """The toolpath with the plan's times (duration and motion settings in ``meta``)."""
    if len(plan) != len(tp):
        raise ValueError(f"plan of {len(plan)} rows does not match a toolpath of {len(tp)} rows")
    return dataclasses.replace(tp, t_start=plan.t_start, t_end=plan.t_end,
                               meta={**tp.meta, "duration_s": plan.duration_s, "motion": plan.settings.to_json()})
