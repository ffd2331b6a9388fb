"""The toolpath: one row per motion segment, as numpy arrays.

Rows are in program order. Arcs are kept exact: an arc row has ``kind`` ARC_CW or ARC_CCW and
its geometry in :class:`ArcTable` (``arcs.segment`` gives the row). Dwells, E-only moves
(retracts) and other motionless time show up as gaps between one row's ``t_end`` and the next
row's ``t_start``.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from functools import cached_property

import numpy as np

RAPID = np.uint8(0)
LINEAR = np.uint8(1)
ARC_CW = np.uint8(2)
ARC_CCW = np.uint8(3)

# Arc plane, named by its normal axis: G17 -> Z, G18 -> Y, G19 -> X.
PLANE_NORMAL_X = np.uint8(0)
PLANE_NORMAL_Y = np.uint8(1)
PLANE_NORMAL_Z = np.uint8(2)

NO_FEATURE = 255  # ``feature`` of rows before any ;TYPE: comment

# The per-row arrays of a Toolpath (indexed together when rows are selected or split)
ROW_FIELDS = ("start", "end", "deposit", "kind", "feed", "power", "t_start", "t_end", "line", "layer", "rotary",
              "e_material", "dwell_on", "width", "height", "feature", "axis")

PLUS_Z = np.array([0.0, 0.0, 1.0], np.float32)


def vertical_axis(n: int) -> np.ndarray:
    """The tool axis of ``n`` rows of a 3-axis program: +Z, as a read-only (n, 3) view of one row
    (no memory per row: a 3-axis toolpath stays as small as before the axis existed)."""
    return np.broadcast_to(PLUS_Z, (int(n), 3))


def is_vertical_view(axis: np.ndarray) -> bool:
    """Whether ``axis`` is a :func:`vertical_axis` view (every row +Z by construction)."""
    return axis.ndim == 2 and axis.shape[0] > 0 and axis.strides[0] == 0 and bool(np.all(axis[0] == PLUS_Z))


def _owned_nbytes(a: np.ndarray) -> int:
    """Bytes an array really holds (a broadcast view repeats one row: it holds that row)."""
    if a.ndim and any(s == 0 for s in a.strides):
        return int(a.itemsize * np.prod([n for n, s in zip(a.shape, a.strides) if s != 0]))
    return int(a.nbytes)


@dataclass(frozen=True)
class ArcTable:
    """Exact geometry of the arc rows of a :class:`Toolpath`.

    The arc turns about ``centre`` (a point on the axis, in the start point's plane) around
    the plane normal ``normal_axis`` by ``sweep`` radians (positive = counter-clockwise seen
    from the normal's positive side, full turns included). The radius goes linearly from
    ``r_start`` to ``r_end`` (equal for a proper arc; LinuxCNC-style spiral otherwise) and
    the coordinate along the normal goes linearly from the start's to the end's (a helix).
    """

    segment: np.ndarray  # (m,) int64 row in the toolpath
    centre: np.ndarray  # (m, 3) float64
    normal_axis: np.ndarray  # (m,) uint8 PLANE_NORMAL_*
    sweep: np.ndarray  # (m,) float64 radians, signed
    r_start: np.ndarray  # (m,) float64
    r_end: np.ndarray  # (m,) float64
    length: np.ndarray  # (m,) float64 exact path length (helix and spiral included)

    def __len__(self) -> int:
        return int(self.segment.shape[0])

    @property
    def nbytes(self) -> int:
        return sum(a.nbytes for a in (self.segment, self.centre, self.normal_axis, self.sweep, self.r_start, self.r_end, self.length))

    @staticmethod
    def empty() -> "ArcTable":
        return ArcTable(
            segment=np.zeros(0, np.int64),
            centre=np.zeros((0, 3), np.float64),
            normal_axis=np.zeros(0, np.uint8),
            sweep=np.zeros(0, np.float64),
            r_start=np.zeros(0, np.float64),
            r_end=np.zeros(0, np.float64),
            length=np.zeros(0, np.float64),
        )


@dataclass(frozen=True)
class Toolpath:
    """Segments of a G-code program: the tool tip in the workpiece frame (mm, s).

    Without a machine file (3-axis) the workpiece frame is the programmed X Y Z frame (machine
    coordinates after G92); with one, rows are the tip path the kinematics give (see
    :mod:`dmdvox.toolpath.fiveaxis`) and ``axis`` the tool axis of each row."""

    start: np.ndarray  # (n, 3) float64
    end: np.ndarray  # (n, 3) float64
    deposit: np.ndarray  # (n,) bool: material is deposited along this row
    kind: np.ndarray  # (n,) uint8: RAPID, LINEAR, ARC_CW, ARC_CCW
    feed: np.ndarray  # (n,) float32 mm/s
    # (n,) float32 laser power in force, in the program's own unit (no scaling): the S word, or under
    # --dialect custom the power word of the last rule that matched (SDC of `M201 (SDC 37.8)`, Q of
    # `M68 E2 Q40`; dmdvox.toolpath.dialects); NaN where no word has given it yet
    power: np.ndarray
    t_start: np.ndarray  # (n,) float64 s
    t_end: np.ndarray  # (n,) float64 s
    line: np.ndarray  # (n,) int32 1-based physical line in the source file
    layer: np.ndarray  # (n,) int32 index into ``layer_z`` (travel: the next deposit's layer)
    rotary: np.ndarray  # (n, 3) float32 A, B, C at the end of the row (degrees)
    arcs: ArcTable
    layer_z: np.ndarray  # (k,) float64 distinct deposit Z levels, ascending
    e_material: np.ndarray  # (n,) float32 filament mm fed as material (E words; retracts repaid first)
    dwell_on: np.ndarray  # (n,) float32 s the beam stood still while on, just before the row
    width: np.ndarray  # (n,) float32 mm from the slicer's ;WIDTH: comments (NaN: none)
    height: np.ndarray  # (n,) float32 mm from the slicer's ;HEIGHT: comments (NaN: none)
    feature: np.ndarray  # (n,) uint8 index into meta["features"] (;TYPE:), NO_FEATURE before any
    # (n, 3) float32 unit tool axis (tip up the nozzle) in the workpiece frame, constant over a
    # row; None: +Z for every row (a 3-axis program; stored as a view of one row)
    axis: np.ndarray | None = None
    z_is_layer_top: bool = False  # slicer dialects: Z is the top of the bead, not its bottom
    source: str = ""
    dialect: str = ""
    meta: dict = field(default_factory=dict, compare=False)

    def __post_init__(self):
        n = int(self.start.shape[0])
        if self.axis is None:
            object.__setattr__(self, "axis", vertical_axis(n))
        elif self.axis.shape != (n, 3):
            raise ValueError(f"axis must have shape ({n}, 3), not {self.axis.shape}")

    def __len__(self) -> int:
        return int(self.start.shape[0])

    @property
    def nbytes(self) -> int:
        return sum(_owned_nbytes(getattr(self, name)) for name in ROW_FIELDS) + self.arcs.nbytes + self.layer_z.nbytes

    @property
    def vertical(self) -> bool:
        """Every row's tool axis is +Z (a 3-axis program, or a five-axis one that never tilts)."""
        return is_vertical_view(self.axis) or len(self) == 0 or bool(np.all(self.axis == PLUS_Z))

    def take_rows(self, index) -> dict:
        """Every per-row array indexed by ``index`` (a mask or indices), as replace() keywords."""
        rows = {name: getattr(self, name)[index] for name in ROW_FIELDS if name != "axis"}
        if is_vertical_view(self.axis):
            rows["axis"] = vertical_axis(rows["start"].shape[0])
        else:
            rows["axis"] = self.axis[index]
        return rows

    @cached_property
    def length(self) -> np.ndarray:
        """Path length of each row (exact for arcs and helices); derived, not stored."""
        length = np.linalg.norm(self.end - self.start, axis=1)
        length[self.arcs.segment] = self.arcs.length
        return length

    @property
    def duration(self) -> float:
        return float(self.meta.get("duration_s", self.t_end[-1] if len(self) else 0.0))

    @property
    def layer_step(self) -> float:
        """Median distance between consecutive deposit Z levels (0 for a single layer)."""
        if self.layer_z.shape[0] < 2:
            return 0.0
        return float(np.median(np.diff(self.layer_z)))

    def deposit_bbox(self) -> np.ndarray:
        """``[[xmin,ymin,zmin],[xmax,ymax,zmax]]`` of the deposit path (arcs included)."""
        from .geometry import path_bbox

        return path_bbox(self, self.deposit)

    def until(self, time_s: float) -> "Toolpath":
        """The program as executed up to ``time_s``; a row in progress is cut at that time."""
        from .geometry import truncate

        return truncate(self, time_s)

    def select(self, mask: np.ndarray) -> "Toolpath":
        """A toolpath with only the rows in ``mask`` (the arc table follows)."""
        from .geometry import select_rows

        return select_rows(self, mask)
