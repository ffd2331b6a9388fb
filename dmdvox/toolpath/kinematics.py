"""Machine kinematics: machine joint values <-> tool tip and tool axis in the workpiece frame.

Pure geometry for the five-axis DED cells dmdvox knows (see ``docs/MACHINES.md`` for the file
format, the sign conventions and the formulas):

``none``
    a 3-axis machine: the tip is X Y Z, the tool axis is +Z, A B C are ignored.
``trt-ac`` / ``trt-bc``
    table-table trunnions: the workpiece sits on a C rotary table carried by an A (about X) or
    B (about Y) tilt; the nozzle stays vertical. The workpiece frame is fixed to the C table and
    coincides with the machine frame when the rotary axes are at 0 (LinuxCNC ``xyzac-trt`` /
    ``xyzbc-trt``).
``head-bc``
    a head-head machine: the workpiece stays still (workpiece frame = machine frame); the nozzle
    turns about C (the head's vertical axis) and tilts about B; both axes meet at the pivot.
    X Y Z are the tip's position when B = C = 0, i.e. the pivot is at X Y Z + pivot_length * Z
    (LinuxCNC ``5axiskins``).

Conventions: joints are ``(n, 6)`` float64 arrays ``X Y Z A B C`` (mm, degrees). By default
(``sense = "iso"``) a positive rotary value turns the TOOL right-handed about the axis direction
relative to the workpiece (ISO 841, RS274/NGC "counterclockwise from the point of view of the
workpiece"): a head turns the nozzle right-handed, a table turns the workpiece left-handed.
``sense = "reversed"`` flips one axis, which is what LinuxCNC's trt kinematics (both axes) and
``5axiskins`` (its B axis) do. The tool axis is the unit vector from the tip up the nozzle.

Per-pose math is in numba kernels (10^6 poses in well under a second); ``inverse`` solves the
two rotary angles with the Paden-Kahan "two rotations" subproblem, so calibrated (not exactly
X/Y/Z) axis directions work as well as nominal ones.
"""

from __future__ import annotations

import math
import tomllib
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
from numba import njit

from dmdvox.errors import DmdvoxError, InputFileError

MACHINE_KINDS = ("none", "trt-ac", "trt-bc", "head-bc")
SENSES = ("iso", "reversed")
JOINT_COLUMNS = {"X": 0, "Y": 1, "Z": 2, "A": 3, "B": 4, "C": 5}

# The rotary axes of each kind, OUTER first (the outer axis is carried by the machine frame, the
# inner one by the outer one): a trunnion's tilt carries the C table; a head's C carries the B tilt.
_KIND_AXES = {"none": (), "trt-ac": ("A", "C"), "trt-bc": ("B", "C"), "head-bc": ("C", "B")}
_TABLE_KINDS = ("trt-ac", "trt-bc")
_HEAD_KINDS = ("head-bc",)

_ANGLE_SLACK = 1e-9  # degrees a solution may exceed a limit by (rounding)
_PARALLEL_COS = 1.0 - 1e-9  # axes whose directions' |cos| exceeds this are parallel


Vec3 = tuple[float, float, float]


@dataclass(frozen=True)
class RotaryAxis:
    """One rotary axis of a machine.

    ``letter``    "A", "B" or "C": the joint column it reads (3, 4, 5).
    ``direction`` unit vector of the axis line in machine coordinates with every rotary axis at 0.
    ``point``     a point on the axis line, machine mm, every rotary axis at 0 (table-table only;
                  a head's axes pass through the pivot).
    ``sense``     "iso": a positive value turns the tool right-handed about ``direction``
                  relative to the workpiece (a table then turns the workpiece left-handed);
                  "reversed": the opposite (LinuxCNC trt kinematics).
    ``wrapped``   the axis turns without end: programmed moves take the short way (see
                  :func:`short_way`); it has no limits.
    ``limits``    (low, high) degrees the joint can reach, or None for no limit.
    """

    letter: str
    direction: Vec3
    point: Vec3 = (0.0, 0.0, 0.0)
    sense: str = "iso"
    wrapped: bool = False
    limits: tuple[float, float] | None = None

    def __post_init__(self):
        if self.letter not in ("A", "B", "C"):
            raise DmdvoxError(f"rotary axis letter {self.letter!r}: must be A, B or C")
        d = np.asarray(self.direction, dtype=np.float64)
        norm = float(np.linalg.norm(d)) if d.shape == (3,) else float("nan")
        if not (np.isfinite(norm) and norm > 1e-12):
            raise DmdvoxError(f"{self.letter} axis direction {self.direction!r}: must be three finite "
                              f"numbers, not all zero")
        object.__setattr__(self, "direction", tuple(float(v) for v in d / norm))
        object.__setattr__(self, "point", tuple(float(v) for v in self.point))
        if self.sense not in SENSES:
            raise DmdvoxError(f"{self.letter} axis sense {self.sense!r}: must be one of {SENSES}")
        if self.limits is not None:
            lo, hi = (float(v) for v in self.limits)
            if not (math.isfinite(lo) and math.isfinite(hi) and lo < hi):
                raise DmdvoxError(f"{self.letter} axis limits {self.limits!r}: need two finite "
                                  f"numbers, low < high")
            if self.wrapped:
                raise DmdvoxError(f"{self.letter} axis: a wrapped axis has no limits")
            object.__setattr__(self, "limits", (lo, hi))

    @property
    def column(self) -> int:
        return JOINT_COLUMNS[self.letter]

    @property
    def sign(self) -> float:
        return 1.0 if self.sense == "iso" else -1.0

    def to_json(self) -> dict:
        return {"letter": self.letter, "direction": list(self.direction), "point": list(self.point),
                "sense": self.sense, "wrapped": self.wrapped,
                "limits": None if self.limits is None else list(self.limits)}


@dataclass(frozen=True)
class Machine:
    """A machine's kinematic chain.

    ``kind``          one of :data:`MACHINE_KINDS`.
    ``name``          from the file, for messages and reports.
    ``axes``          the rotary axes, OUTER first: trt-ac (A, C), trt-bc (B, C), head-bc (C, B).
    ``tool_length``   table-table: the programmed X Y Z is a controlled point this far above the
                      tip along the (vertical) tool axis; 0 when the controller compensates the
                      tool length (the usual case: X Y Z is the nozzle tip).
    ``pivot_length``  head-head: from the pivot to the tip along the tool axis; the pivot is at
                      X Y Z + pivot_length * (0, 0, 1).
    ``source``        the file it came from ("" for built-in machines).
    """

    kind: str
    name: str
    axes: tuple[RotaryAxis, ...] = ()
    tool_length: float = 0.0
    pivot_length: float = 0.0
    source: str = field(default="", compare=False)

    def __post_init__(self):
        where = f"machine {self.name!r}"
        if self.kind not in MACHINE_KINDS:
            raise DmdvoxError(f"{where}: unknown kind {self.kind!r}; use one of {MACHINE_KINDS}")
        letters = tuple(a.letter for a in self.axes)
        if letters != _KIND_AXES[self.kind]:
            raise DmdvoxError(f"{where}: a {self.kind} machine has rotary axes "
                              f"{_KIND_AXES[self.kind]} (outer first), not {letters}")
        object.__setattr__(self, "axes", tuple(self.axes))
        for name in ("tool_length", "pivot_length"):
            v = float(getattr(self, name))
            if not (math.isfinite(v) and v >= 0.0):
                raise DmdvoxError(f"{where}: {name} must be a finite number >= 0, not {v}")
            object.__setattr__(self, name, v)
        if len(self.axes) == 2:
            c = abs(float(np.dot(self.axes[0].direction, self.axes[1].direction)))
            if c > _PARALLEL_COS:
                raise DmdvoxError(f"{where}: the {letters[0]} and {letters[1]} axis directions are "
                                  f"parallel; two parallel axes cannot orient the tool")

    def axis(self, letter: str) -> RotaryAxis:
        for a in self.axes:
            if a.letter == letter:
                return a
        raise KeyError(letter)

    @property
    def is_five_axis(self) -> bool:
        return self.kind != "none"

    def to_json(self) -> dict:
        out = {"kind": self.kind, "name": self.name, "source": self.source,
               "axes": [a.to_json() for a in self.axes]}
        if self.kind in _TABLE_KINDS:
            out["tool_length"] = self.tool_length
        if self.kind in _HEAD_KINDS:
            out["pivot_length"] = self.pivot_length
        return out


NO_MACHINE = Machine(kind="none", name="3-axis (no rotary axes)")


def machine_from_json(doc: dict) -> Machine:
    """The :class:`Machine` of :meth:`Machine.to_json` (e.g. a toolpath's ``meta["machine"]``)."""
    axes = tuple(RotaryAxis(letter=a["letter"], direction=tuple(a["direction"]), point=tuple(a["point"]),
                            sense=a["sense"], wrapped=a["wrapped"],
                            limits=None if a["limits"] is None else tuple(a["limits"]))
                 for a in doc.get("axes", ()))
    return Machine(kind=doc["kind"], name=doc["name"], axes=axes, tool_length=float(doc.get("tool_length", 0.0)),
                   pivot_length=float(doc.get("pivot_length", 0.0)), source=doc.get("source", ""))


# --------------------------------------------------------------------------------------------
# Loading
# --------------------------------------------------------------------------------------------

_AXIS_FIELDS_TABLE = ("point", "direction", "sense", "wrapped", "limits")
_AXIS_FIELDS_HEAD = ("direction", "sense", "wrapped", "limits")
_TOP_FIELDS = {
    "none": ("kind", "name"),
    "trt-ac": ("kind", "name", "tool_length", "a", "c"),
    "trt-bc": ("kind", "name", "tool_length", "b", "c"),
    "head-bc": ("kind", "name", "pivot_length", "b", "c"),
}


def load_machine(path) -> Machine:
    """Read a machine file (TOML; format in ``docs/MACHINES.md``).

    Every problem is a :class:`DmdvoxError` naming the file and the field.
    """
    path = Path(path)
    try:
        text = path.read_bytes().decode("utf-8")
    except FileNotFoundError:
        raise InputFileError(f"{path}: machine file not found") from None
    except IsADirectoryError:
        raise InputFileError(f"{path}: is a directory, not a machine file") from None
    except UnicodeDecodeError as exc:
        raise InputFileError(f"{path}: not a text (UTF-8) machine file: {exc}") from None
    except OSError as exc:
        raise InputFileError(f"{path}: cannot read the machine file: {exc.strerror}") from None
    try:
        doc = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise DmdvoxError(f"{path}: not valid TOML ({exc}); see docs/MACHINES.md for the format") from None
    return _machine_from_dict(doc, str(path))


def _fail(src: str, fieldname: str, what: str):
    raise DmdvoxError(f"{src}: field '{fieldname}': {what} (see docs/MACHINES.md)")


def _number(src, fieldname, v, *, minimum=None) -> float:
    if isinstance(v, bool) or not isinstance(v, (int, float)):
        _fail(src, fieldname, f"must be a number, not {v!r}")
    v = float(v)
    if not math.isfinite(v):
        _fail(src, fieldname, f"must be a finite number, not {v!r}")
    if minimum is not None and v < minimum:
        _fail(src, fieldname, f"must be >= {minimum:g}, not {v:g}")
    return v


def _vector(src, fieldname, v) -> Vec3:
    if not isinstance(v, list) or len(v) != 3:
        _fail(src, fieldname, f"must be three numbers like [0, 0, 1], not {v!r}")
    return tuple(_number(src, f"{fieldname}[{i}]", x) for i, x in enumerate(v))


def _axis_from_dict(src, kind, letter, table) -> RotaryAxis:
    key = letter.lower()
    if not isinstance(table, dict):
        _fail(src, key, f"must be a table [{key}] describing the {letter} axis")
    allowed = _AXIS_FIELDS_TABLE if kind in _TABLE_KINDS else _AXIS_FIELDS_HEAD
    for k in table:
        if k not in allowed:
            hint = " (a head's axes pass through the pivot: no point)" if k == "point" else ""
            _fail(src, f"{key}.{k}", f"unknown field for the {letter} axis of a {kind} machine{hint}; "
                                     f"the fields are {', '.join(allowed)}")
    required = ("point", "direction") if kind in _TABLE_KINDS else ("direction",)
    for k in required:
        if k not in table:
            _fail(src, f"{key}.{k}", f"missing: the {letter} axis needs it")
    direction = _vector(src, f"{key}.direction", table["direction"])
    if math.sqrt(sum(x * x for x in direction)) <= 1e-12:
        nominal = {"A": "[1, 0, 0]", "B": "[0, 1, 0]", "C": "[0, 0, 1]"}[letter]
        _fail(src, f"{key}.direction", f"is zero; give the axis line's direction, e.g. {nominal}")
    point = _vector(src, f"{key}.point", table["point"]) if "point" in table else (0.0, 0.0, 0.0)
    sense = table.get("sense", "iso")
    if sense not in SENSES:
        _fail(src, f"{key}.sense", f"must be \"iso\" or \"reversed\", not {sense!r}")
    wrapped = table.get("wrapped", False)
    if not isinstance(wrapped, bool):
        _fail(src, f"{key}.wrapped", f"must be true or false, not {wrapped!r}")
    limits = None
    if "limits" in table:
        lim = table["limits"]
        if not isinstance(lim, list) or len(lim) != 2:
            _fail(src, f"{key}.limits", f"must be [low, high] in degrees, not {lim!r}")
        lo = _number(src, f"{key}.limits[0]", lim[0])
        hi = _number(src, f"{key}.limits[1]", lim[1])
        if not lo < hi:
            _fail(src, f"{key}.limits", f"low ({lo:g}) must be below high ({hi:g})")
        if wrapped:
            _fail(src, f"{key}.limits", "a wrapped axis turns without end: remove the limits "
                                        "or set wrapped = false")
        limits = (lo, hi)
    return RotaryAxis(letter=letter, direction=direction, point=point, sense=sense,
                      wrapped=wrapped, limits=limits)


def _machine_from_dict(doc: dict, src: str) -> Machine:
    if "kind" not in doc:
        _fail(src, "kind", f"missing; one of {', '.join(MACHINE_KINDS)}")
    kind = doc["kind"]
    if kind not in MACHINE_KINDS:
        _fail(src, "kind", f"unknown machine kind {kind!r}; use one of {', '.join(MACHINE_KINDS)}")
    if "name" not in doc:
        _fail(src, "name", "missing: give the machine a name for messages and reports")
    name = doc["name"]
    if not isinstance(name, str) or not name.strip():
        _fail(src, "name", f"must be a non-empty string, not {name!r}")
    allowed = _TOP_FIELDS[kind]
    for k in doc:
        if k not in allowed:
            _fail(src, k, f"unknown field for a {kind} machine; the fields are {', '.join(allowed)}")
    tool_length = 0.0
    pivot_length = 0.0
    if kind in _TABLE_KINDS and "tool_length" in doc:
        tool_length = _number(src, "tool_length", doc["tool_length"], minimum=0.0)
    if kind in _HEAD_KINDS:
        if "pivot_length" not in doc:
            _fail(src, "pivot_length", "missing: the distance from the pivot to the tip (mm)")
        pivot_length = _number(src, "pivot_length", doc["pivot_length"], minimum=0.0)
    axes = []
    for letter in _KIND_AXES[kind]:
        key = letter.lower()
        if key not in doc:
            _fail(src, key, f"missing: a {kind} machine needs a [{key}] table for its {letter} axis")
        axes.append(_axis_from_dict(src, kind, letter, doc[key]))
    if len(axes) == 2:
        c = abs(sum(p * q for p, q in zip(axes[0].direction, axes[1].direction)))
        if c > _PARALLEL_COS:
            _fail(src, f"{axes[1].letter.lower()}.direction",
                  f"parallel to {axes[0].letter.lower()}.direction; the two rotary axes must not "
                  f"be parallel")
    return Machine(kind=kind, name=name, axes=tuple(axes), tool_length=tool_length,
                   pivot_length=pivot_length, source=src)


# --------------------------------------------------------------------------------------------
# numba kernels
# --------------------------------------------------------------------------------------------
# Geometry vector g (float64) for the two-axis chains, outer axis 1, inner axis 2:
#   g[0:3] point of axis 1, g[3:6] direction of axis 1, g[6] sign 1,
#   g[7:10] point of axis 2, g[10:13] direction of axis 2, g[13] sign 2,
#   g[14] tool_length (table) or pivot_length (head),
#   g[15:17] limits of axis 1 (lo, hi), g[17] 1.0 if axis 1 is limited,
#   g[18:20] limits of axis 2, g[20] 1.0 if axis 2 is limited.
# cols[0], cols[1]: the joint columns of axes 1 and 2.

_DEG = math.pi / 180.0


@njit(cache=True)
def _rodrigues(g, o, theta, R):
    """R = rotation by theta (radians) about the unit vector g[o:o+3] (right-handed)."""
    ux = g[o]
    uy = g[o + 1]
    uz = g[o + 2]
    c = math.cos(theta)
    s = math.sin(theta)
    v = 1.0 - c
    R[0, 0] = c + ux * ux * v
    R[0, 1] = ux * uy * v - uz * s
    R[0, 2] = ux * uz * v + uy * s
    R[1, 0] = uy * ux * v + uz * s
    R[1, 1] = c + uy * uy * v
    R[1, 2] = uy * uz * v - ux * s
    R[2, 0] = uz * ux * v - uy * s
    R[2, 1] = uz * uy * v + ux * s
    R[2, 2] = c + uz * uz * v


@njit(cache=True)
def _table_pose(th1, th2, g, R1, R2, R, t):
    """Workpiece -> machine for a table-table chain at joint angles th1 (outer), th2 (inner), degrees.

    m = R1 (R2 (p - P2) + P2 - P1) + P1 with Rk = Rot(uk, -sk thk): the tables carry the
    workpiece, so an "iso" positive angle turns it left-handed. Fills R = R1 R2 and t.
    """
    _rodrigues(g, 3, -g[6] * th1 * _DEG, R1)
    _rodrigues(g, 10, -g[13] * th2 * _DEG, R2)
    for i in range(3):
        for j in range(3):
            R[i, j] = R1[i, 0] * R2[0, j] + R1[i, 1] * R2[1, j] + R1[i, 2] * R2[2, j]
    # w = P2 - P1 - R2 P2
    w0 = g[7] - g[0] - (R2[0, 0] * g[7] + R2[0, 1] * g[8] + R2[0, 2] * g[9])
    w1 = g[8] - g[1] - (R2[1, 0] * g[7] + R2[1, 1] * g[8] + R2[1, 2] * g[9])
    w2 = g[9] - g[2] - (R2[2, 0] * g[7] + R2[2, 1] * g[8] + R2[2, 2] * g[9])
    for i in range(3):
        t[i] = R1[i, 0] * w0 + R1[i, 1] * w1 + R1[i, 2] * w2 + g[i]


@njit(cache=True)
def _table_transform_kernel(joints, g, cols, Rout, tout):
    R1 = np.empty((3, 3))
    R2 = np.empty((3, 3))
    R = np.empty((3, 3))
    t = np.empty(3)
    for n in range(joints.shape[0]):
        _table_pose(joints[n, cols[0]], joints[n, cols[1]], g, R1, R2, R, t)
        for i in range(3):
            tout[n, i] = t[i]
            for j in range(3):
                Rout[n, i, j] = R[i, j]


@njit(cache=True)
def _table_forward_kernel(joints, g, cols, tip, axis):
    R1 = np.empty((3, 3))
    R2 = np.empty((3, 3))
    R = np.empty((3, 3))
    t = np.empty(3)
    L = g[14]
    for n in range(joints.shape[0]):
        _table_pose(joints[n, cols[0]], joints[n, cols[1]], g, R1, R2, R, t)
        d0 = joints[n, 0] - t[0]
        d1 = joints[n, 1] - t[1]
        d2 = joints[n, 2] - L - t[2]
        for i in range(3):  # p = R^T (m - t); the tool axis is machine +Z
            tip[n, i] = R[0, i] * d0 + R[1, i] * d1 + R[2, i] * d2
            axis[n, i] = R[2, i]


@njit(cache=True)
def _head_frame(th1, th2, g, R1, R2, R):
    """Head-head tool orientation R = Rot(u1, s1 th1) Rot(u2, s2 th2) (degrees; outer axis 1)."""
    _rodrigues(g, 3, g[6] * th1 * _DEG, R1)
    _rodrigues(g, 10, g[13] * th2 * _DEG, R2)
    for i in range(3):
        for j in range(3):
            R[i, j] = R1[i, 0] * R2[0, j] + R1[i, 1] * R2[1, j] + R1[i, 2] * R2[2, j]


@njit(cache=True)
def _head_forward_kernel(joints, g, cols, tip, axis):
    R1 = np.empty((3, 3))
    R2 = np.empty((3, 3))
    R = np.empty((3, 3))
    L = g[14]
    for n in range(joints.shape[0]):
        _head_frame(joints[n, cols[0]], joints[n, cols[1]], g, R1, R2, R)
        # tool axis = R (0, 0, 1); pivot = XYZ + L z; tip = pivot - L axis
        for i in range(3):
            axis[n, i] = R[i, 2]
        tip[n, 0] = joints[n, 0] - L * R[0, 2]
        tip[n, 1] = joints[n, 1] - L * R[1, 2]
        tip[n, 2] = joints[n, 2] + L - L * R[2, 2]


@njit(cache=True)
def _place(theta, nearv, lo, hi, limited):
    """The value theta + 360 k nearest nearv (within [lo, hi] when limited); nan if none fits."""
    k = math.floor((nearv - theta) / 360.0 + 0.5)
    if limited:
        kmin = math.ceil((lo - _ANGLE_SLACK - theta) / 360.0)
        kmax = math.floor((hi + _ANGLE_SLACK - theta) / 360.0)
        if kmin > kmax:
            return math.nan
        if k < kmin:
            k = kmin
        if k > kmax:
            k = kmax
    return theta + 360.0 * k


@njit(cache=True)
def _clamp(v, lo, hi, limited):
    if limited:
        if v < lo:
            return lo
        if v > hi:
            return hi
    return v


_FREE_EPS2 = 1e-20  # |perpendicular part|^2 below which a vector lies on an axis (C undefined)


@njit(cache=True, inline="always")
def _turn_about(u0, u1, u2, f0, f1, f2, t0, t1, t2):
    """Signed angle about the unit axis u from f (perpendicular to u) to the part of t
    perpendicular to u."""
    ut = u0 * t0 + u1 * t1 + u2 * t2
    tp0 = t0 - u0 * ut
    tp1 = t1 - u1 * ut
    tp2 = t2 - u2 * ut
    cx = f1 * tp2 - f2 * tp1
    cy = f2 * tp0 - f0 * tp2
    cz = f0 * tp1 - f1 * tp0
    return math.atan2(u0 * cx + u1 * cy + u2 * cz, f0 * tp0 + f1 * tp1 + f2 * tp2)


@njit(cache=True)
def _two_rotations(g, p0, p1, p2, q0, q1, q2, out):
    """Paden-Kahan subproblem 2: angles (radians) f1, f2 with Rot(u1, f1) Rot(u2, f2) p = q.

    u1 = g[3:6], u2 = g[10:13] unit, not parallel; p, q unit. Writes up to two solutions into
    out[k] = (f1, f2, free1, free2) (free: that angle is undefined, any value works) and returns
    their number (0: q cannot be reached from p).

    The intermediate vector z = Rot(u2, f2) p = Rot(u1, -f1) q satisfies u2.z = u2.p,
    u1.z = u1.q and |z| = |p|; writing z = a u1 + b u2 + c (u1 x u2) gives a, b in closed form
    and c = +-sqrt(...). Each angle is then the one-axis rotation taking one vector to another.
    """
    a0 = g[3]
    a1 = g[4]
    a2 = g[5]
    b0 = g[10]
    b1 = g[11]
    b2 = g[12]
    c12 = a0 * b0 + a1 * b1 + a2 * b2
    w0 = a1 * b2 - a2 * b1
    w1 = a2 * b0 - a0 * b2
    w2 = a0 * b1 - a1 * b0
    ww = w0 * w0 + w1 * w1 + w2 * w2
    bp = b0 * p0 + b1 * p1 + b2 * p2
    aq = a0 * q0 + a1 * q1 + a2 * q2
    den = c12 * c12 - 1.0
    al = (c12 * bp - aq) / den
    be = (c12 * aq - bp) / den
    pp = p0 * p0 + p1 * p1 + p2 * p2
    gg = (pp - al * al - be * be - 2.0 * al * be * c12) / ww
    if gg < -1e-12:
        return 0
    if gg < 0.0:
        gg = 0.0
    ga = math.sqrt(gg)
    # perpendicular parts of p about u2 and q about u1 (for the free-angle test)
    pp0 = p0 - b0 * bp
    pp1 = p1 - b1 * bp
    pp2 = p2 - b2 * bp
    free2 = pp0 * pp0 + pp1 * pp1 + pp2 * pp2 < _FREE_EPS2
    qp0 = q0 - a0 * aq
    qp1 = q1 - a1 * aq
    qp2 = q2 - a2 * aq
    free1 = qp0 * qp0 + qp1 * qp1 + qp2 * qp2 < _FREE_EPS2
    nsol = 2
    if ga == 0.0 or free1 or free2:
        nsol = 1
    for k in range(nsol):
        sg = ga if k == 0 else -ga
        z0 = al * a0 + be * b0 + sg * w0
        z1 = al * a1 + be * b1 + sg * w1
        z2 = al * a2 + be * b2 + sg * w2
        # f2: about u2 from p to z; f1: about u1 from z to q (minus the turn from q to z)
        f2 = 0.0 if free2 else _turn_about(b0, b1, b2, pp0, pp1, pp2, z0, z1, z2)
        f1 = 0.0 if free1 else -_turn_about(a0, a1, a2, qp0, qp1, qp2, z0, z1, z2)
        out[k, 0] = f1
        out[k, 1] = f2
        out[k, 2] = 1.0 if free1 else 0.0
        out[k, 3] = 1.0 if free2 else 0.0
    return nsol


@njit(cache=True)
def _choose(sol, nsol, to_joint1, to_joint2, g, n1, n2, best):
    """Of the candidate solutions, the joint pair (degrees) nearest (n1, n2) within the limits.

    to_jointk converts the subproblem's angle fk (radians) to joint k's degrees (the sign of the
    chain and the sense of the axis). Returns 0 when found, 1 when no candidate fits the limits.
    """
    bestcost = math.inf
    for k in range(nsol):
        if sol[k, 2] != 0.0:
            j1 = _clamp(n1, g[15], g[16], g[17] != 0.0)
        else:
            j1 = _place(to_joint1 * sol[k, 0] / _DEG, n1, g[15], g[16], g[17] != 0.0)
        if sol[k, 3] != 0.0:
            j2 = _clamp(n2, g[18], g[19], g[20] != 0.0)
        else:
            j2 = _place(to_joint2 * sol[k, 1] / _DEG, n2, g[18], g[19], g[20] != 0.0)
        if math.isnan(j1) or math.isnan(j2):
            continue
        cost = (j1 - n1) * (j1 - n1) + (j2 - n2) * (j2 - n2)
        if cost < bestcost:
            bestcost = cost
            best[0] = j1
            best[1] = j2
    return 0 if bestcost < math.inf else 1


@njit(cache=True)
def _table_inverse_kernel(tip, axis, near, g, cols, out, status):
    """Status per pose: 0 ok, 1 orientation outside the limits, 2 orientation unreachable."""
    R1 = np.empty((3, 3))
    R2 = np.empty((3, 3))
    R = np.empty((3, 3))
    t = np.empty(3)
    sol = np.empty((2, 4))
    best = np.empty(2)
    L = g[14]
    for n in range(tip.shape[0]):
        for i in range(6):
            out[n, i] = near[n, i]
        # Rot(u1, -s1 th1) Rot(u2, -s2 th2) k = +Z (machine tool axis)
        nsol = _two_rotations(g, axis[n, 0], axis[n, 1], axis[n, 2], 0.0, 0.0, 1.0, sol)
        if nsol == 0:
            status[n] = 2
            continue
        if _choose(sol, nsol, -g[6], -g[13], g, near[n, cols[0]], near[n, cols[1]], best) != 0:
            status[n] = 1
            continue
        status[n] = 0
        _table_pose(best[0], best[1], g, R1, R2, R, t)
        for i in range(3):
            out[n, i] = (R[i, 0] * tip[n, 0] + R[i, 1] * tip[n, 1] + R[i, 2] * tip[n, 2] + t[i])
        out[n, 2] += L
        out[n, cols[0]] = best[0]
        out[n, cols[1]] = best[1]


@njit(cache=True)
def _head_inverse_kernel(tip, axis, near, g, cols, out, status):
    sol = np.empty((2, 4))
    best = np.empty(2)
    L = g[14]
    for n in range(tip.shape[0]):
        for i in range(6):
            out[n, i] = near[n, i]
        # Rot(u1, s1 th1) Rot(u2, s2 th2) (0, 0, 1) = k
        nsol = _two_rotations(g, 0.0, 0.0, 1.0, axis[n, 0], axis[n, 1], axis[n, 2], sol)
        if nsol == 0:
            status[n] = 2
            continue
        if _choose(sol, nsol, g[6], g[13], g, near[n, cols[0]], near[n, cols[1]], best) != 0:
            status[n] = 1
            continue
        status[n] = 0
        # pivot = tip + L k; X Y Z = pivot - L z
        out[n, 0] = tip[n, 0] + L * axis[n, 0]
        out[n, 1] = tip[n, 1] + L * axis[n, 1]
        out[n, 2] = tip[n, 2] + L * axis[n, 2] - L
        out[n, cols[0]] = best[0]
        out[n, cols[1]] = best[1]


@njit(cache=True)
def _short_way_kernel(values, out):
    out[0] = values[0]
    for n in range(1, values.shape[0]):
        v = values[n]
        out[n] = v + 360.0 * math.floor((out[n - 1] - v) / 360.0 + 0.5)


# --------------------------------------------------------------------------------------------
# Public functions
# --------------------------------------------------------------------------------------------


def _geometry(machine: Machine) -> tuple[np.ndarray, np.ndarray]:
    g = np.zeros(21)
    a1, a2 = machine.axes
    for off, ax in ((0, a1), (7, a2)):
        g[off:off + 3] = ax.point
        g[off + 3:off + 6] = ax.direction
        g[off + 6] = ax.sign
    g[14] = machine.tool_length if machine.kind in _TABLE_KINDS else machine.pivot_length
    for off, ax in ((15, a1), (18, a2)):
        if ax.limits is not None:
            g[off], g[off + 1] = ax.limits
            g[off + 2] = 1.0
    cols = np.array([a1.column, a2.column], dtype=np.int64)
    return g, cols


def _as_poses(a, width: int, what: str) -> np.ndarray:
    arr = np.asarray(a, dtype=np.float64)
    if arr.ndim == 1:
        arr = arr.reshape(1, -1)
    if arr.ndim != 2 or arr.shape[1] != width:
        raise ValueError(f"{what} must have shape (n, {width}), not {np.shape(a)}")
    return np.ascontiguousarray(arr)


def forward(machine: Machine, joints) -> tuple[np.ndarray, np.ndarray]:
    """Tool tip (n, 3) and unit tool axis (n, 3), both in the workpiece frame, for (n, 6) joints.

    ``joints`` are X Y Z A B C as programmed on the machine (mm, degrees); rotary columns the
    machine does not have are ignored. The tool axis points from the tip up the nozzle.
    """
    j = _as_poses(joints, 6, "joints")
    n = j.shape[0]
    tip = np.empty((n, 3))
    axis = np.empty((n, 3))
    if machine.kind == "none":
        tip[:] = j[:, :3]
        axis[:] = (0.0, 0.0, 1.0)
        return tip, axis
    g, cols = _geometry(machine)
    if machine.kind in _TABLE_KINDS:
        _table_forward_kernel(j, g, cols, tip, axis)
    else:
        _head_forward_kernel(j, g, cols, tip, axis)
    return tip, axis


def _unit_axes(machine: Machine, axis: np.ndarray) -> np.ndarray:
    norm = np.sqrt(np.einsum("ij,ij->i", axis, axis))
    bad = ~(np.isfinite(norm) & (norm > 1e-12))
    if bad.any():
        i = int(np.flatnonzero(bad)[0])
        raise DmdvoxError(f"machine {machine.name!r}: pose {i}: the tool axis {axis[i].tolist()} is "
                          f"zero or not finite; give a direction from the tip up the nozzle")
    return axis / norm[:, None]


def inverse(machine: Machine, tip, axis, near=None) -> np.ndarray:
    """Joints (n, 6) putting the tip at ``tip`` (n, 3) with tool axis ``axis`` (n, 3).

    Both are in the workpiece frame; ``axis`` need not be unit. Of the solutions (generally two
    per pose: the tilt's two signs), the one nearest ``near`` (n, 6) is chosen, with every rotary
    value on the turn (value + 360 k) nearest ``near`` and within the axis limits. Where the tool
    axis lies along the inner table axis (trunnion) or the head's C axis, C is undefined: C is
    then ``near``'s (clamped to the limits). Columns the machine does not use are copied from
    ``near`` (0 without it). For ``none`` the axis must be +Z.

    Raises :class:`DmdvoxError` naming the first pose that the machine cannot reach.
    """
    p = _as_poses(tip, 3, "tip")
    k = _unit_axes(machine, _as_poses(axis, 3, "axis"))
    n = p.shape[0]
    if k.shape[0] != n:
        raise ValueError(f"tip and axis must have the same number of poses ({n} != {k.shape[0]})")
    if near is None:
        nr = np.zeros((n, 6))
    else:
        nr = _as_poses(near, 6, "near")
        if nr.shape[0] == 1 and n != 1:
            nr = np.ascontiguousarray(np.broadcast_to(nr, (n, 6)))
        if nr.shape[0] != n:
            raise ValueError(f"near must have shape ({n}, 6), not {nr.shape}")
    if machine.kind == "none":
        off = np.abs(k - np.array([0.0, 0.0, 1.0])).max(axis=1) > 1e-9
        if off.any():
            i = int(np.flatnonzero(off)[0])
            raise DmdvoxError(
                f"machine {machine.name!r} ({machine.source or 'built-in'}): pose {i}: tool axis "
                f"{k[i].round(6).tolist()} is not +Z, and a 3-axis machine cannot tilt the nozzle; "
                f"give a five-axis machine file (--machine, see docs/MACHINES.md)")
        out = nr.copy()
        out[:, :3] = p
        return out
    g, cols = _geometry(machine)
    out = np.empty((n, 6))
    status = np.zeros(n, dtype=np.int8)
    kernel = _table_inverse_kernel if machine.kind in _TABLE_KINDS else _head_inverse_kernel
    kernel(p, k, nr, g, cols, out, status)
    if status.any():
        i = int(np.flatnonzero(status)[0])
        letters = "/".join(a.letter for a in machine.axes)
        where = f"machine {machine.name!r} ({machine.source or 'built-in'}): pose {i}"
        if status[i] == 2:
            raise DmdvoxError(f"{where}: no {letters} angles turn the tool axis to "
                              f"{k[i].round(6).tolist()}; check the axis directions in the machine "
                              f"file or the program's tool axis")
        lims = ", ".join(f"{a.letter.lower()}.limits = {list(a.limits)}" for a in machine.axes
                         if a.limits is not None)
        raise DmdvoxError(f"{where}: the tool axis {k[i].round(6).tolist()} needs {letters} angles "
                          f"outside the machine's limits ({lims}); widen the limits in the machine "
                          f"file or change the program")
    return out


def workpiece_to_machine(machine: Machine, joints) -> tuple[np.ndarray, np.ndarray]:
    """(R (n, 3, 3), t (n, 3)) with machine_point = R @ workpiece_point + t at each pose.

    Things bolted to the table (fixtures, the part) move with it. Identity for ``none`` and
    head-head machines, whose workpiece does not move.
    """
    j = _as_poses(joints, 6, "joints")
    n = j.shape[0]
    if machine.kind not in _TABLE_KINDS:
        return np.broadcast_to(np.eye(3), (n, 3, 3)).copy(), np.zeros((n, 3))
    g, cols = _geometry(machine)
    R = np.empty((n, 3, 3))
    t = np.empty((n, 3))
    _table_transform_kernel(j, g, cols, R, t)
    return R, t


def short_way(machine: Machine, joints) -> np.ndarray:
    """The joint path the machine follows for programmed ``joints`` (n, 6) in order.

    Each wrapped axis moves from one value to the next by the shorter way (at most 180 degrees),
    so its returned values are continuous (unwrapped); other columns are returned unchanged.
    """
    j = _as_poses(joints, 6, "joints").copy()
    if j.shape[0] == 0:
        return j
    for ax in machine.axes:
        if ax.wrapped:
            col = np.ascontiguousarray(j[:, ax.column])
            res = np.empty_like(col)
            _short_way_kernel(col, res)
            j[:, ax.column] = res
    return j


def check_limits(machine: Machine, joints) -> None:
    """Raise a :class:`DmdvoxError` naming the first pose whose rotary value is outside a limit."""
    j = _as_poses(joints, 6, "joints")
    for ax in machine.axes:
        if ax.limits is None:
            continue
        lo, hi = ax.limits
        v = j[:, ax.column]
        bad = (v < lo - _ANGLE_SLACK) | (v > hi + _ANGLE_SLACK) | ~np.isfinite(v)
        if bad.any():
            i = int(np.flatnonzero(bad)[0])
            raise DmdvoxError(f"machine {machine.name!r} ({machine.source or 'built-in'}): pose {i}: "
                              f"{ax.letter} = {v[i]:g} is outside {ax.letter.lower()}.limits = "
                              f"[{lo:g}, {hi:g}]")
