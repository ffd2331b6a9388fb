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

**The program's own limits** (:mod:`dmdvox.toolpath.motion_codes`): M201/M203/M204/M205,
Klipper's SET_VELOCITY_LIMIT and the slicers' machine settings, each from its line on; the
command line over the program over the defaults (:func:`resolve_limits`). A move's limits are the
tightest of its axes' (X Y Z and E, the filament per mm of path): ``v <= max_feed_a / f_a`` and
``a <= max_accel_a / f_a`` with ``f_a`` the axis's share of the path speed; its acceleration is the
print, travel or retract one by what it does. With a classic jerk (M205 X Y Z E, no J) junctions
follow Marlin's classic-jerk rule (per axis, or of the XY vector as Marlin 1.0 and Cura's
estimator) and moves start and stop at their safe speed. Retract-only moves are blocks of their
own (length ``|ΔE|``, the retract acceleration) between the rows.

**Full stops** (speed 0, or the safe speed with classic jerk): at the program's start and end;
after a code the dialect's controller stops for (``STOP_CODES``: LinuxCNC's M3/M5 and M64/M65,
not M62/M63; the Fadal's M-functions; Marlin's M400; switching the extrusion is E's motion and
does not stop; a dialect without a known rule stops where deposition switches); where the
constant-feed timing has a gap that is not retract-only moves (a dwell: the controller drains its
queue); where row i's end is not row i+1's start (a jump after an unknown position); at
zero-length rows (nothing to plan: they take the time the constant-feed timing gave them, 0
unless G93).

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

from ..errors import ParameterError
from ..toolpath.geometry import PLANE_AXES
from ..toolpath import motion_codes as M
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
# Klipper's default max_accel_to_decel is half max_accel (minimum_cruise_ratio 0.5).
KLIPPER_CRUISE_RATIO = 0.5
# Marlin's default classic jerk (Configuration.h DEFAULT_XJERK/YJERK/ZJERK/EJERK), for the axes
# a program's M205 leaves unset.
MARLIN_JERK_MM_S = (10.0, 10.0, 0.3, 5.0)

# A gap between one row's t_end and the next row's t_start larger than this (relative to the
# time, at least 1 s) is a real pause (dwell, retract), not rounding of the summed times.
GAP_REL_TOL = 1e-10
# Row i's end farther than this from row i+1's start is a position jump (mm).
JUMP_TOL_MM = 1e-6

_AXIS0 = np.array([PLANE_AXES[k][0] for k in range(3)], np.int64)
_AXIS1 = np.array([PLANE_AXES[k][1] for k in range(3)], np.int64)

# Columns of the resolved limits table the kernel reads (one row per span of program lines).
C_ACCEL_PRINT, C_ACCEL_TRAVEL, C_ACCEL_RETRACT = 0, 1, 2
C_AMAX = 3  # X Y Z E: 3..6
C_VMAX = 7  # X Y Z E: 7..10
C_VELOCITY = 11
C_JERK = 12  # X Y Z E: 12..15
C_JD = 16
C_ACCEL_TO_DECEL = 17
N_COLUMNS = 18
# Block kinds: what sets a block's acceleration (M204 P / T / R).
PRINT, TRAVEL, RETRACT = 0, 1, 2
# Junction rules: Grbl/Marlin 2/Klipper junction deviation; Marlin 1.1+/2 classic jerk per axis
# (PrusaSlicer's estimator); Marlin 1.0's jerk of the XY velocity vector (Cura's estimator).
JUNCTION_DEVIATION, JERK_AXIS, JERK_XY = 0, 1, 2
JERK_RULES = {"axis": JERK_AXIS, "xy": JERK_XY}
JUNCTION_NAMES = {JUNCTION_DEVIATION: "junction deviation", JERK_AXIS: "classic jerk per axis",
                  JERK_XY: "classic jerk of the XY vector"}


def junction_deviation_from_jerk(jerk_mm_s: float, accel_mm_s2: float) -> float:
    """Marlin's conversion of a classic jerk setting: ``JD = 0.4 jerk^2 / a`` (mm)."""
    return 0.4 * jerk_mm_s * jerk_mm_s / accel_mm_s2


def junction_deviation_from_scv(scv_mm_s: float, accel_mm_s2: float) -> float:
    """Klipper's rule: ``JD = scv^2 (sqrt 2 - 1) / a``, so a 90 degree corner runs at ``scv``."""
    return scv_mm_s * scv_mm_s * (math.sqrt(2.0) - 1.0) / accel_mm_s2


def _finite_number(value, parameter: str, what: str) -> float:
    try:
        number = float(value)
    except (TypeError, ValueError):
        raise ParameterError(f"{{{parameter}}}: {value!r} is not a number; give {what}", parameter) from None
    if not math.isfinite(number):
        raise ParameterError(f"{{{parameter}}}: {value!r} is not a finite number; give {what}", parameter)
    return number


def _positive(value, parameter: str, what: str, zero_ok: bool = False) -> float:
    number = _finite_number(value, parameter, what)
    if number < 0.0 or (number == 0.0 and not zero_ok):
        raise ParameterError(f"{{{parameter}}}: {number:g} is not {'>= 0' if zero_ok else 'positive'}; give {what}",
                             parameter)
    return number


def _axes(value, parameter: str, what: str) -> tuple[float, float, float, float]:
    """X, Y, Z, E from a 4-tuple (or a comma list "X,Y,Z,E")."""
    items = value.split(",") if isinstance(value, str) else list(value)
    if len(items) != 4:
        raise ParameterError(f"{{{parameter}}}: {value!r} is not four values X,Y,Z,E; give {what}, e.g. "
                             "500,500,12,120", parameter)
    return tuple(_positive(v, parameter, what) for v in items)  # type: ignore[return-value]


@dataclass(frozen=True)
class MotionSettings:
    """How the machine turns F into motion: the run's own choices. ``None`` takes the program's
    own limits (M201/M203/M204/M205, SET_VELOCITY_LIMIT, the slicer's machine settings) and,
    where it states none, the defaults; a value given here overrides the program's.

    ``accel_mm_s2 = 0`` keeps the constant-feed timing (the tool at F everywhere); a positive one
    sets every move's acceleration (print, travel and retract) unless ``travel_accel_mm_s2`` or
    ``retract_accel_mm_s2`` says otherwise. Corners follow the junction deviation (from
    ``square_corner_velocity_mm_s`` by Klipper's rule when given) or, with ``jerk_mm_s`` given
    or a program that states classic jerk and no junction deviation, Marlin's classic jerk.
    ``program_limits = False`` ignores what the program says.
    """

    accel_mm_s2: float | None = None
    junction_deviation_mm: float | None = None
    square_corner_velocity_mm_s: float | None = None
    travel_accel_mm_s2: float | None = None
    retract_accel_mm_s2: float | None = None
    max_feed_mm_s: tuple | None = None  # X, Y, Z, E
    max_axis_accel_mm_s2: tuple | None = None  # X, Y, Z, E
    jerk_mm_s: tuple | None = None  # X, Y, Z, E classic jerk
    accel_to_decel_mm_s2: float | None = None
    jerk_rule: str | None = None  # "axis" (Marlin 1.1+) or "xy" (Marlin 1.0, Cura's estimator)
    program_limits: bool = True

    def validate(self) -> None:
        if self.accel_mm_s2 is not None:
            _positive(self.accel_mm_s2, "accel_mm_s2", "an acceleration in mm/s^2 "
                      f"(default {DEFAULT_ACCEL_MM_S2:g}; 0 = constant feed)", zero_ok=True)
        if self.junction_deviation_mm is not None:
            _positive(self.junction_deviation_mm, "junction_deviation_mm", "a distance in mm "
                      f"(default {DEFAULT_JUNCTION_DEVIATION_MM:g}; 0 stops at every corner)", zero_ok=True)
        if self.square_corner_velocity_mm_s is not None:
            _positive(self.square_corner_velocity_mm_s, "square_corner_velocity_mm_s",
                      f"a speed in mm/s (Klipper's default {DEFAULT_SQUARE_CORNER_VELOCITY_MM_S:g})", zero_ok=True)
        for value, parameter in ((self.travel_accel_mm_s2, "travel_accel_mm_s2"),
                                 (self.retract_accel_mm_s2, "retract_accel_mm_s2"),
                                 (self.accel_to_decel_mm_s2, "accel_to_decel_mm_s2")):
            if value is not None:
                _positive(value, parameter, "an acceleration in mm/s^2")
        for value, parameter, what in ((self.max_feed_mm_s, "max_feed_mm_s", "the axes' top speeds in mm/s"),
                                       (self.max_axis_accel_mm_s2, "max_axis_accel_mm_s2",
                                        "the axes' accelerations in mm/s^2"),
                                       (self.jerk_mm_s, "jerk_mm_s", "the axes' classic jerk in mm/s")):
            if value is not None:
                _axes(value, parameter, what)
        if self.jerk_rule is not None and self.jerk_rule not in JERK_RULES:
            raise ParameterError(f"{{jerk_rule}}: unknown rule {self.jerk_rule!r}; choose axis (Marlin 1.1 and "
                                 "later, PrusaSlicer's estimate) or xy (Marlin 1.0, Cura's estimate)", "jerk_rule")

    @property
    def effective_junction_deviation_mm(self) -> float:
        """The junction deviation the planner uses (from the square-corner velocity when given)."""
        accel = DEFAULT_ACCEL_MM_S2 if self.accel_mm_s2 is None else float(self.accel_mm_s2)
        if self.square_corner_velocity_mm_s is not None and accel > 0.0:
            return junction_deviation_from_scv(float(self.square_corner_velocity_mm_s), accel)
        return DEFAULT_JUNCTION_DEVIATION_MM if self.junction_deviation_mm is None else float(self.junction_deviation_mm)

    def to_json(self) -> dict:
        def number(v):
            return None if v is None else float(v)

        def axes(v):  # an axis without a limit is null
            if v is None:
                return None
            return [float(x) if math.isfinite(float(x)) else None for x in (v.split(",") if isinstance(v, str) else v)]

        accel = DEFAULT_ACCEL_MM_S2 if self.accel_mm_s2 is None else float(self.accel_mm_s2)
        return {
            "accel_mm_s2": accel,
            "junction_deviation_mm": DEFAULT_JUNCTION_DEVIATION_MM if self.junction_deviation_mm is None
            else float(self.junction_deviation_mm),
            "square_corner_velocity_mm_s": number(self.square_corner_velocity_mm_s),
            "effective_junction_deviation_mm": self.effective_junction_deviation_mm,
            "travel_accel_mm_s2": number(self.travel_accel_mm_s2),
            "retract_accel_mm_s2": number(self.retract_accel_mm_s2),
            "max_feed_mm_s": axes(self.max_feed_mm_s),
            "max_axis_accel_mm_s2": axes(self.max_axis_accel_mm_s2),
            "jerk_mm_s": axes(self.jerk_mm_s),
            "accel_to_decel_mm_s2": number(self.accel_to_decel_mm_s2),
            "jerk_rule": self.jerk_rule if self.jerk_mm_s is not None else None,
            "constant_feed": accel == 0.0,
        }


@dataclass(frozen=True, eq=False)
class ResolvedLimits:
    """The limits the planner runs a program with: ``table`` rows (``N_COLUMNS``, infinite where
    nothing limits) in force from ``line`` on, the junction rule, and where each came from."""

    line: np.ndarray  # (m,) int64
    table: np.ndarray  # (m, N_COLUMNS) float64
    rule: int  # JUNCTION_DEVIATION, JERK_AXIS or JERK_XY
    sources: dict  # setting name -> "--option", the program's code and line, or "default"
    settings: MotionSettings  # the limits in force at the start, as settings (JSON, reports)


def _program_value(program, index: int, column: int) -> float:
    return float("nan") if program is None else float(program.values[index, column])


def resolve_limits(settings: MotionSettings, program, at_line: int = 0) -> ResolvedLimits:
    """Command line over program over defaults, for each span of lines of the program's limit
    codes (``program``: a :class:`~dmdvox.toolpath.motion_codes.ProgramMotion`, or None);
    ``settings`` of the result: those in force at ``at_line``."""
    if program is not None and not settings.program_limits:
        program = None
    lines = np.zeros(1, np.int64) if program is None else program.line
    m = lines.shape[0]
    table = np.full((m, N_COLUMNS), np.inf)
    given = program.sources if program is not None else {}
    sources: dict[str, str] = {}
    cli_accel = settings.accel_mm_s2
    cli_jd = settings.junction_deviation_mm
    cli_scv = settings.square_corner_velocity_mm_s
    any_jerk = program is not None and bool(np.isfinite(program.values[:, M.JERK_X:M.JERK_X + 4]).any())
    any_jd = program is not None and bool(np.isfinite(program.values[:, [M.JD, M.SCV]]).any())
    klipper = program is not None and program.klipper
    jerk = settings.jerk_mm_s is not None or (cli_jd is None and cli_scv is None and any_jerk and not any_jd
                                               and not klipper)
    # a jerk from Cura's settings is its XY vector's (machine_max_jerk_xy)
    cura = any(str(given.get(f"jerk_{a}", "")).startswith(";SETTING_3") for a in "xy")
    rule = JUNCTION_DEVIATION if not jerk else JERK_RULES[settings.jerk_rule or ("xy" if cura else "axis")]

    k_at = max(int(np.searchsorted(lines, at_line, side="right")) - 1, 0)  # whose sources are told

    def tell(k, name, source):
        if k == k_at:
            sources[name] = source

    def pick(cli, option, name, column, k, default):
        if cli is not None:
            tell(k, name, option)
            return float(cli)
        value = _program_value(program, k, column)
        if math.isfinite(value):
            tell(k, name, given.get(M.VALUE_NAMES[column], "program"))
            return value
        if default is not None:
            tell(k, name, "default")
        return default

    for k in range(m):
        row = table[k]
        ap = pick(cli_accel, "--accel", "accel_print", M.ACCEL_PRINT, k, DEFAULT_ACCEL_MM_S2)
        row[C_ACCEL_PRINT] = ap
        for cli, option, name, col, out in ((settings.travel_accel_mm_s2, "--travel-accel", "accel_travel",
                                             M.ACCEL_TRAVEL, C_ACCEL_TRAVEL),
                                            (settings.retract_accel_mm_s2, "--retract-accel", "accel_retract",
                                             M.ACCEL_RETRACT, C_ACCEL_RETRACT)):
            if cli is None and cli_accel is not None:
                cli, option = cli_accel, "--accel"
            row[out] = pick(cli, option, name, col, k, ap)
        for ax in range(4):
            cli = None if settings.max_axis_accel_mm_s2 is None else _axes(settings.max_axis_accel_mm_s2, "", "")[ax]
            v = pick(cli, "--max-axis-accel", M.VALUE_NAMES[M.AMAX_X + ax], M.AMAX_X + ax, k, None)
            row[C_AMAX + ax] = np.inf if v is None else v
            cli = None if settings.max_feed_mm_s is None else _axes(settings.max_feed_mm_s, "", "")[ax]
            v = pick(cli, "--max-feed", M.VALUE_NAMES[M.VMAX_X + ax], M.VMAX_X + ax, k, None)
            row[C_VMAX + ax] = np.inf if v is None else v
        v = pick(None, "", "velocity", M.VELOCITY, k, None)
        row[C_VELOCITY] = np.inf if v is None else v
        if jerk:
            for ax in range(4):
                cli = None if settings.jerk_mm_s is None else _axes(settings.jerk_mm_s, "", "")[ax]
                fallback = MARLIN_JERK_MM_S[ax]
                if ax == 1 and cli is None:  # an unset Y jerk follows X (M205 X10 sets both in PrusaSlicer)
                    fallback = row[C_JERK]
                row[C_JERK + ax] = pick(cli, "--jerk", M.VALUE_NAMES[M.JERK_X + ax], M.JERK_X + ax, k, fallback)
        if cli_scv is not None:
            row[C_JD] = junction_deviation_from_scv(float(cli_scv), ap) if ap > 0 else 0.0
            tell(k, "junction_deviation", "--square-corner-velocity")
        elif cli_jd is not None:
            row[C_JD] = float(cli_jd)
            tell(k, "junction_deviation", "--junction-deviation")
        else:
            jd = _program_value(program, k, M.JD)
            scv = _program_value(program, k, M.SCV)
            if math.isfinite(jd):
                row[C_JD] = jd
                tell(k, "junction_deviation", given.get("junction_deviation", "program"))
            elif math.isfinite(scv) or klipper:
                scv = scv if math.isfinite(scv) else DEFAULT_SQUARE_CORNER_VELOCITY_MM_S
                row[C_JD] = junction_deviation_from_scv(scv, ap) if ap > 0 else 0.0
                tell(k, "junction_deviation", given.get("square_corner_velocity", "Klipper's default"))
            else:
                row[C_JD] = DEFAULT_JUNCTION_DEVIATION_MM
                tell(k, "junction_deviation", "default")
        a2d = settings.accel_to_decel_mm_s2
        if a2d is not None:
            tell(k, "accel_to_decel", "--accel-to-decel")
        else:
            a2d = _program_value(program, k, M.ACCEL_TO_DECEL)
            ratio = _program_value(program, k, M.CRUISE_RATIO)
            if math.isfinite(a2d):
                tell(k, "accel_to_decel", given.get("accel_to_decel", "program"))
            elif math.isfinite(ratio) or klipper:
                ratio = ratio if math.isfinite(ratio) else KLIPPER_CRUISE_RATIO
                a2d = ap * (1.0 - ratio)
                tell(k, "accel_to_decel", given.get("minimum_cruise_ratio", "Klipper's default"))
            else:
                a2d = np.inf
        row[C_ACCEL_TO_DECEL] = min(float(a2d), ap) if ap > 0 else np.inf
    first = table[k_at]

    def axes_or_none(c):
        values = first[c:c + 4]
        return None if not np.isfinite(values).any() else tuple(float(v) for v in values)

    resolved = MotionSettings(
        accel_mm_s2=float(first[C_ACCEL_PRINT]), junction_deviation_mm=float(first[C_JD]),
        square_corner_velocity_mm_s=cli_scv, travel_accel_mm_s2=float(first[C_ACCEL_TRAVEL]),
        retract_accel_mm_s2=float(first[C_ACCEL_RETRACT]), max_feed_mm_s=axes_or_none(C_VMAX),
        max_axis_accel_mm_s2=axes_or_none(C_AMAX), jerk_mm_s=axes_or_none(C_JERK) if jerk else None,
        accel_to_decel_mm_s2=float(first[C_ACCEL_TO_DECEL]) if first[C_ACCEL_TO_DECEL] < first[C_ACCEL_PRINT] else None,
        jerk_rule=None if not jerk else ("xy" if rule == JERK_XY else "axis"), program_limits=settings.program_limits)
    if cli_scv is not None:
        resolved = dataclasses.replace(resolved, junction_deviation_mm=settings.junction_deviation_mm)
    return ResolvedLimits(lines, table, rule, sources, resolved)


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
def _block_limits(length, frac, feed, curvature, kind, epoch, table, jerk_model, vmax, accel, a2d, safe):
    """Each block's top speed (its F within every axis's top speed, Klipper's velocity and the
    arc's centripetal limit), acceleration (its kind's, within every axis's), the peak
    acceleration of a triangle (Klipper's accel_to_decel) and, for classic jerk, the speed it may
    start or stop at (Marlin's safe speed)."""
    for b in range(length.shape[0]):
        row = table[epoch[b]]
        a = row[C_ACCEL_PRINT + kind[b]]
        v = min(np.float64(feed[b]), row[C_VELOCITY])
        for ax in range(4):
            f = frac[b, ax]
            if f > 0.0:
                if row[C_AMAX + ax] / f < a:
                    a = row[C_AMAX + ax] / f
                if row[C_VMAX + ax] / f < v:
                    v = row[C_VMAX + ax] / f
        if curvature[b] > 0.0:
            vc = np.sqrt(a / curvature[b])
            if vc < v:
                v = vc
        if length[b] <= 0.0:
            v = 0.0
        vmax[b] = v
        accel[b] = a
        a2d[b] = min(a, row[C_ACCEL_TO_DECEL])
        sv = 0.0
        if jerk_model == JERK_XY and v > 0.0:
            # Marlin 1.0's (and Cura's estimator's): half the jerks, whatever the direction
            sv = min(v, 0.5 * row[C_JERK])
            if v * frac[b, 2] > 0.5 * row[C_JERK + 2]:
                sv = min(sv, 0.5 * row[C_JERK + 2])
            if v * frac[b, 3] > 0.5 * row[C_JERK + 3]:
                sv = min(sv, 0.5 * row[C_JERK + 3])
        elif jerk_model == JERK_AXIS and v > 0.0:
            # Marlin's classic-jerk safe speed: the first axis over its jerk sets the speed to
            # that jerk, every further one scales it down in proportion
            sv = v
            limited = False
            for ax in range(4):
                speed = v * frac[b, ax]
                jerk = row[C_JERK + ax]
                if speed > jerk:
                    if limited:
                        if speed * sv > jerk * v:
                            sv = jerk * v / speed
                    else:
                        limited = True
                        sv = jerk
        safe[b] = sv


@njit(cache=True)
def _jerk_junction(v_prev, v_curr, d_prev, d_curr, jerk, safe_prev, safe_curr):
    """Marlin's classic-jerk junction speed (planner.cpp, as PrusaSlicer's estimator runs it):
    the smaller nominal speed, scaled down until no axis changes speed by more than its jerk."""
    prev_larger = v_prev > v_curr
    factor_speed = v_curr / v_prev if prev_larger else v_prev / v_curr
    vj = v_curr if prev_larger else v_prev
    v_factor = 1.0
    limited = False
    for ax in range(4):
        v_exit = v_prev * d_prev[ax]
        v_entry = v_curr * d_curr[ax]
        if prev_larger:
            v_exit *= factor_speed
        if limited:
            v_exit *= v_factor
            v_entry *= v_factor
        if v_exit > v_entry:
            j = (v_exit - v_entry) if (v_entry > 0.0 or v_exit < 0.0) else max(v_exit, -v_entry)
        else:
            j = (v_entry - v_exit) if (v_entry < 0.0 or v_exit > 0.0) else max(-v_exit, v_entry)
        if j > jerk[ax]:
            v_factor *= jerk[ax] / j
            limited = True
    if limited:
        vj *= v_factor
    # not coasting: both moves may start and stop at their safe speeds anyway
    threshold = vj * 0.99
    if safe_prev > threshold and safe_curr > threshold:
        vj = safe_curr
    return vj


@njit(cache=True)
def _xy_junction(v_prev, v_curr, d_prev, d_curr, jerk):
    """Marlin 1.0's junction speed (Cura's estimator): the change of the XY velocity vector
    within the XY jerk, Z's and E's within theirs, no faster than the earlier move's speed."""
    dx = v_curr * d_curr[0] - v_prev * d_prev[0]
    dy = v_curr * d_curr[1] - v_prev * d_prev[1]
    factor = 1.0
    xy = np.sqrt(dx * dx + dy * dy)
    if xy > jerk[0]:
        factor = jerk[0] / xy
    for ax in (2, 3):
        dv = abs(v_curr * d_curr[ax] - v_prev * d_prev[ax])
        if dv > jerk[ax]:
            factor = min(factor, jerk[ax] / dv)
    return min(v_prev, v_curr * factor)


@njit(cache=True)
def _plan_blocks(length, u_in, u_out, e_frac, frac, curvature, feed, kind, epoch, table, jerk_model, stop, gap,
                 t0, fixed_time, v_entry, v_cruise, v_exit, accel, new_start, new_end):
    """Junction limits, look-ahead and trapezoids over the blocks (rows and retract-only moves
    in program order); ``stop[b]``: the tool stops before block b; ``gap[b]``: motionless time
    before it; ``fixed_time``: the time of blocks of no length (kept)."""
    nb = length.shape[0]
    vmax = np.empty(nb)
    a2d = np.empty(nb)
    safe = np.empty(nb)
    _block_limits(length, frac, feed, curvature, kind, epoch, table, jerk_model, vmax, accel, a2d, safe)

    lim = np.empty(nb)  # the entry limit of every block
    d_prev = np.empty(4)
    d_curr = np.empty(4)
    jerk = np.empty(4)
    for b in range(nb):
        if b == 0 or stop[b]:
            lim[b] = safe[b]
            continue
        p = b - 1
        top = min(vmax[p], vmax[b])
        if top <= 0.0:
            lim[b] = 0.0
            continue
        if jerk_model != JUNCTION_DEVIATION:
            for ax in range(3):
                d_prev[ax] = u_out[p, ax]
                d_curr[ax] = u_in[b, ax]
            d_prev[3] = e_frac[p]
            d_curr[3] = e_frac[b]
            for ax in range(4):
                jerk[ax] = table[epoch[b], C_JERK + ax]
            if jerk_model == JERK_XY:
                vj = _xy_junction(vmax[p], vmax[b], d_prev, d_curr, jerk)
            else:
                vj = _jerk_junction(vmax[p], vmax[b], d_prev, d_curr, jerk, safe[p], safe[b])
        else:
            # junction deviation on the direction of all four axes (a retract's is E alone)
            n_prev = np.sqrt(u_out[p, 0] ** 2 + u_out[p, 1] ** 2 + u_out[p, 2] ** 2 + e_frac[p] ** 2)
            n_curr = np.sqrt(u_in[b, 0] ** 2 + u_in[b, 1] ** 2 + u_in[b, 2] ** 2 + e_frac[b] ** 2)
            dot = (u_out[p, 0] * u_in[b, 0] + u_out[p, 1] * u_in[b, 1] + u_out[p, 2] * u_in[b, 2]
                   + e_frac[p] * e_frac[b])
            cos_theta = -dot / (n_prev * n_curr) if n_prev > 0.0 and n_curr > 0.0 else 1.0
            s = np.sqrt(max(0.5 * (1.0 - cos_theta), 0.0))
            vj = top
            if s < 1.0 - 1e-12:
                vj = np.sqrt(accel[b] * table[epoch[b], C_JD] * s / (1.0 - s))
        lim[b] = min(vj, top)

    ent = np.empty(nb)
    ext = np.empty(nb)
    for b in range(nb - 1, -1, -1):  # backward: able to slow down to every later limit
        if b == nb - 1 or stop[b + 1]:
            ext[b] = safe[b]
        else:
            ext[b] = min(lim[b + 1], ent[b + 1])
        ent[b] = min(lim[b], np.sqrt(ext[b] * ext[b] + 2.0 * accel[b] * length[b]))
    for b in range(nb):  # forward: reachable by accelerating from the earlier ones
        if b > 0 and not stop[b]:
            ent[b] = min(ent[b], ext[b - 1])
        ext[b] = min(ext[b], np.sqrt(ent[b] * ent[b] + 2.0 * accel[b] * length[b]))

    t = t0
    for b in range(nb):
        t += gap[b]
        v0 = ent[b]
        v1 = ext[b]
        L = length[b]
        a = accel[b]
        peak = np.sqrt(max((2.0 * a2d[b] * L + v0 * v0 + v1 * v1) * 0.5, 0.0))
        vc = min(vmax[b], peak)
        if vc < v0:  # rounding only: the passes keep v0, v1 <= vmax and <= the peak
            vc = v0
        if vc < v1:
            vc = v1
        v_entry[b] = v0
        v_exit[b] = v1
        v_cruise[b] = vc
        if L > 0.0 and vc > 0.0:
            d_acc = (vc * vc - v0 * v0) / (2.0 * a)
            d_dec = (vc * vc - v1 * v1) / (2.0 * a)
            d_cruise = max(L - d_acc - d_dec, 0.0)
            duration = (vc - v0) / a + d_cruise / vc + (vc - v1) / a
        else:
            duration = fixed_time[b]
        new_start[b] = t
        t += duration
        new_end[b] = t


@njit(cache=True)
def _profile_kernel(rows, values, mode, v_entry, v_cruise, v_exit, t_start, t_end, length, row_accel, out):
    """mode 0: speed at distance; 1: time at distance; 2: distance at time."""
    for q in range(rows.shape[0]):
        i = rows[q]
        accel = row_accel[i]
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
    accel: float  # mm/s^2 of print moves where deposition starts (0: constant feed)
    settings: MotionSettings  # the limits in force there (command line, program, defaults)
    length: np.ndarray | None = None  # (n,) float64 row lengths (the toolpath's ``length``)
    tail_s: float = 0.0  # motionless time after the last row (kept from the toolpath)
    row_accel: np.ndarray | None = None  # (n,) float64 each row's acceleration (None: ``accel`` everywhere)
    sources: dict = dataclasses.field(default_factory=dict)  # setting -> where it came from
    junction: str = "junction deviation"  # JUNCTION_NAMES
    retract_moves: int = 0  # retract-only moves run with their acceleration
    retract_s: float = 0.0  # the time they take

    def __len__(self) -> int:
        return int(self.v_entry.shape[0])

    @property
    def duration_s(self) -> float:
        """Program duration: the last row's end plus the motionless time after it."""
        if len(self) == 0:
            return float(self.tail_s)
        return float(self.t_end[-1]) + float(self.tail_s)

    def to_json(self) -> dict:
        out = self.settings.to_json()
        if not out["constant_feed"]:
            out.update(junction=self.junction, retract_moves=self.retract_moves, retract_s=float(self.retract_s),
                       sources=dict(sorted(self.sources.items())))
        return out

    def _accels(self) -> np.ndarray:
        if self.row_accel is not None:
            return self.row_accel
        return np.full(len(self), float(self.accel))

    def _lengths(self) -> np.ndarray:
        if self.length is not None:
            return self.length
        # Derived from the profile when the plan was built without lengths.
        a = self._accels()
        duration = self.t_end - self.t_start
        if self.accel <= 0.0:
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
        accel = np.ascontiguousarray(self._accels(), np.float64) if self.accel > 0 else np.zeros(len(self))
        _profile_kernel(flat_rows, np.array(values_b, np.float64).reshape(-1), mode, self.v_entry,
                        self.v_cruise, self.v_exit, self.t_start, self.t_end,
                        np.ascontiguousarray(self._lengths(), np.float64), accel, out)
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


def _axis_fractions(tp: Toolpath, u_in: np.ndarray, u_out: np.ndarray) -> np.ndarray:
    """|share| of each axis X Y Z in a row's path speed, its largest along the row: the chord's
    direction for lines; for arcs the whole in-plane speed on both in-plane axes (the tangent
    turns through them) and the rise's share on the normal."""
    frac = np.maximum(np.abs(u_in), np.abs(u_out))
    arcs = tp.arcs
    if len(arcs):
        rows = arcs.segment
        normal = arcs.normal_axis.astype(np.int64)
        rise = np.abs(frac[rows, normal])
        in_plane = np.sqrt(np.maximum(1.0 - rise * rise, 0.0))
        for k in range(3):
            on = normal != k
            frac[rows[on], k] = in_plane[on]
    return frac


def _stop_rows(tp: Toolpath, program) -> np.ndarray:
    """Rows before which the dialect's code stops the tool (its stop codes, see
    :data:`dmdvox.toolpath.motion_codes.STOP_CODES`); a dialect with no known rule (custom, or a
    toolpath not read from a file) stops wherever deposition switches."""
    n = len(tp)
    stop = np.zeros(n, np.bool_)
    if tp.dialect in M.STOP_CODES and program is not None:
        rows = np.searchsorted(tp.line, program.stop_line, side="left")
        stop[rows[rows < n]] = True
    else:
        stop[1:] = tp.deposit[1:] != tp.deposit[:-1]
    return stop


def plan_motion(tp: Toolpath, settings: MotionSettings = MotionSettings()) -> MotionPlan:
    """Plan the trapezoidal speed profile of every row of ``tp`` with look-ahead (see the module
    docstring for the rules), with the limits of the command line, the program and the defaults
    in that order."""
    settings.validate()
    n = len(tp)
    length = np.ascontiguousarray(tp.length, np.float64)
    tail = max(float(tp.duration) - float(tp.t_end[-1]), 0.0) if n else float(tp.duration)
    program = tp.meta.get("program_motion") if settings.program_limits else None
    deposit_rows = np.flatnonzero(tp.deposit)
    first_line = int(tp.line[deposit_rows[0]] if deposit_rows.size else (tp.line[0] if n else 0))
    limits = resolve_limits(settings, program, first_line)
    if settings.accel_mm_s2 is not None and float(settings.accel_mm_s2) == 0.0:
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
    e_per_mm = np.divide(tp.e_material.astype(np.float64), length, out=np.zeros(n), where=length > 0)
    frac = np.column_stack([_axis_fractions(tp, u_in, u_out), np.abs(e_per_mm)])
    kind = np.where(tp.deposit, PRINT, TRAVEL).astype(np.int64)

    # motionless time before each row, and where the tool stops
    gap = np.zeros(n)
    if n:
        gap[0] = float(tp.t_start[0])
        gap[1:] = tp.t_start[1:] - tp.t_end[:-1]
    stop = _stop_rows(tp, program)
    if n > 1:
        stop[1:] |= np.any(np.abs(end[:-1] - start[1:]) > JUMP_TOL_MM, axis=1)

    # retract-only moves: blocks of their own before the row they precede, their constant-feed
    # time taken out of that row's gap
    if program is not None and program.e_line.size and n:
        before = np.searchsorted(tp.line, program.e_line, side="right")
        keep = (before > 0) & (before < n)
        e_before = before[keep]
        e_len = np.abs(program.e_delta[keep])
        e_feed = program.e_feed[keep]
        np.subtract.at(gap, e_before, e_len / e_feed)
    else:
        e_before = np.zeros(0, np.int64)
        e_len = e_feed = np.zeros(0)
    stop[1:] |= gap[1:] > GAP_REL_TOL * np.maximum(1.0, np.abs(tp.t_end[:-1]))
    gap = np.maximum(gap, 0.0)
    m = e_before.size
    # block order: a row's retract-only moves (in line order) come just before it
    order = np.argsort(np.concatenate([np.arange(n) * 2 + 1, e_before * 2]), kind="stable")
    is_row = order < n
    row_of = np.where(is_row, order, -1)
    e_of = np.where(is_row, -1, order - n)
    nb = n + m
    b_len = np.empty(nb)
    b_len[is_row] = length[row_of[is_row]]
    b_len[~is_row] = e_len[e_of[~is_row]]
    b_u_in = np.zeros((nb, 3))
    b_u_out = np.zeros((nb, 3))
    b_u_in[is_row] = u_in[row_of[is_row]]
    b_u_out[is_row] = u_out[row_of[is_row]]
    b_e = np.empty(nb)
    b_e[is_row] = e_per_mm[row_of[is_row]]
    b_e[~is_row] = np.sign(program.e_delta[keep][e_of[~is_row]]) if m else 0.0
    b_frac = np.zeros((nb, 4))
    b_frac[is_row] = frac[row_of[is_row]]
    b_frac[~is_row, 3] = 1.0
    b_curv = np.zeros(nb)
    b_curv[is_row] = curvature[row_of[is_row]]
    b_feed = np.empty(nb)
    b_feed[is_row] = tp.feed[row_of[is_row]]
    b_feed[~is_row] = e_feed[e_of[~is_row]]
    b_kind = np.full(nb, RETRACT, np.int64)
    b_kind[is_row] = kind[row_of[is_row]]
    b_line = np.empty(nb, np.int64)
    b_line[is_row] = tp.line[row_of[is_row]]
    b_line[~is_row] = program.e_line[keep][e_of[~is_row]] if m else 0
    epoch = np.searchsorted(limits.line, b_line, side="right") - 1
    epoch = np.maximum(epoch, 0).astype(np.int64)
    b_stop = np.zeros(nb, np.bool_)
    b_gap = np.zeros(nb)
    # a row's stop and gap belong before its first block (its first retract-only move, if any)
    block_index = np.arange(nb)
    row_block = np.empty(n, np.int64)
    row_block[row_of[is_row]] = block_index[is_row]
    lead = row_block.copy()
    if m:
        e_block = np.empty(m, np.int64)
        e_block[e_of[~is_row]] = block_index[~is_row]
        np.minimum.at(lead, e_before, e_block)
    b_stop[lead] = stop
    b_gap[lead] = gap
    if nb:
        b_gap[0] = 0.0  # the first row's start is t0
    fixed = np.zeros(nb)
    fixed[is_row] = (tp.t_end - tp.t_start)[row_of[is_row]]
    v_entry = np.empty(nb)
    v_cruise = np.empty(nb)
    v_exit = np.empty(nb)
    b_accel = np.empty(nb)
    t_start = np.empty(nb)
    t_end = np.empty(nb)
    t0 = float(tp.t_start[0]) if n else 0.0
    _plan_blocks(b_len, b_u_in, b_u_out, b_e, np.ascontiguousarray(b_frac), b_curv, b_feed, b_kind, epoch,
                 np.ascontiguousarray(limits.table), limits.rule, b_stop, b_gap, t0, fixed, v_entry, v_cruise,
                 v_exit, b_accel, t_start, t_end)
    rb = row_block
    retract_s = float((t_end - t_start)[~is_row].sum()) if m else 0.0
    return MotionPlan(v_entry=v_entry[rb], v_cruise=v_cruise[rb], v_exit=v_exit[rb], t_start=t_start[rb],
                      t_end=t_end[rb], accel=float(limits.settings.accel_mm_s2), settings=limits.settings,
                      length=length, tail_s=tail, row_accel=b_accel[rb], sources=limits.sources,
                      junction=JUNCTION_NAMES[limits.rule], retract_moves=int(m),
                      retract_s=retract_s)


def apply_plan(tp: Toolpath, plan: MotionPlan) -> Toolpath:
    """The toolpath with the plan's times (duration and motion settings in ``meta``)."""
    if len(plan) != len(tp):
        raise ValueError(f"plan of {len(plan)} rows does not match a toolpath of {len(tp)} rows")
    return dataclasses.replace(tp, t_start=plan.t_start, t_end=plan.t_end,
                               meta={**tp.meta, "duration_s": plan.duration_s, "motion": plan.to_json()})
