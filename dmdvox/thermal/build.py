"""From a planned program and its deposit to what the solver takes: the lattice and the beam.

Lattice (aligned with the deposit grid)
    The thermal voxel is a whole number ``m`` of deposit voxels (the nearest to the one asked
    for); thermal cell (I, J, K) covers deposit voxels ``m I .. m I + m - 1`` along each axis
    (from a base chosen so that a cell boundary lies on the plate's top, within half a deposit
    voxel), and is born at the arrival time at its centre: a cell exists where the deposit holds
    its centre, from the moment the bead covered it (odd ``m``: the central deposit voxel; even
    ``m``: the mean over the 2 x 2 x 2 voxels around the centre, at least half of them filled).
Plate
    A solid block under the part, there from the start at ``--preheat``: by default the part's
    footprint plus ``PLATE_MARGIN_MM`` on every side and ``PLATE_THICKNESS_MM`` thick; with
    ``plate_size`` (X, Y, thickness) centred on the footprint.
Beam
    Every deposit row of the plan, at the planner's times (its acceleration and dwells): pieces
    of at most ``PIECE_S`` seconds placed by the speed profile (arcs on the arc), and a still
    piece for every dwell with the beam on. Power: ``--laser-power`` W where given, else the
    program's ``S`` word read as watts.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .. import checks
from ..errors import DmdvoxError
from ..grid.sparse import BLOCK, SparseGrid
from ..process.plan import ProcessPlan
from ..toolpath.geometry import arc_points
from .lattice import Lattice, bytes_per_cell, lattice_from_birth
from .solver import SourcePath

PLATE_MARGIN_MM = 5.0
PLATE_THICKNESS_MM = 10.0
# The plate coarsens downwards, where the heat arrives smoothed: under its top PLATE_FINE_LAYERS
# layers of cells, a layer of cells twice as tall, then layers PLATE_COARSE times as tall (the
# bottom one what is left); each cell keeps the thermal voxel across.
PLATE_FINE_LAYERS = 2
PLATE_COARSE = 4
PIECE_S = 0.02  # the beam's pieces: 0.25 mm at 12.5 mm/s, a tenth of the seed's bead


@dataclass(frozen=True)
class PlateSpec:
    """The plate's size (mm): X and Y extent (None: the footprint plus the margin) and thickness."""

    x: float | None = None
    y: float | None = None
    thickness: float = PLATE_THICKNESS_MM


def parse_plate_size(text: str) -> PlateSpec:
    """``X,Y,T`` in mm (``--plate-size``)."""
    try:
        values = [float(v) for v in text.split(",")]
    except ValueError:
        values = []
    if len(values) != 3 or not all(math.isfinite(v) and v > 0 for v in values):
        raise DmdvoxError(f"--plate-size: expected X,Y,THICKNESS in mm, three positive numbers, got {text!r}")
    return PlateSpec(*values)


def thermal_voxel(grid: SparseGrid, asked: float | None, bead_width: float) -> tuple[int, float]:
    """(m, m * deposit voxel): the thermal voxel on the deposit's lattice (default: a quarter of
    the bead width); refused coarser than the bead."""
    want = bead_width / 4.0 if asked is None else float(asked)
    if not math.isfinite(want) or want <= 0:
        raise DmdvoxError(f"--thermal-voxel: {asked!r} mm must be a positive number")
    if want > bead_width:
        raise DmdvoxError(f"--thermal-voxel: {want:g} mm is coarser than the bead ({bead_width:g} mm wide): the "
                          f"melt pool would be one cell; give at most {bead_width:g} mm (default a quarter, "
                          f"{bead_width / 4:g} mm)")
    m = max(1, int(round(want / grid.voxel)))
    return m, m * grid.voxel


def check_inputs(bead_width: float, voxel: float | None, laser_power: float | None) -> None:
    """The options that need no deposit, refused before it is swept."""
    if voxel is not None and (not math.isfinite(voxel) or voxel <= 0 or voxel > bead_width):
        raise DmdvoxError(f"--thermal-voxel: {voxel:g} mm; give a positive size at most the bead width "
                          f"({bead_width:g} mm; default a quarter, {bead_width / 4:g} mm)")
    if laser_power is not None and (not math.isfinite(laser_power) or laser_power < 0):
        raise DmdvoxError(f"--laser-power: {laser_power:g} W; give the beam's power in W (>= 0)")


def _deposit_index_box(grid: SparseGrid) -> tuple[np.ndarray, np.ndarray]:
    coords = [grid.leaf_coord.astype(np.int64)]
    if grid.n_tile:
        coords.append(grid.tile_coord.astype(np.int64))
    blocks = np.concatenate(coords)
    if blocks.size == 0:
        raise DmdvoxError("the deposit is empty: nothing to heat")
    return BLOCK * blocks.min(axis=0), BLOCK * (blocks.max(axis=0) + 1)


# Bytes per cell of the box while the lattice is built, beyond what each cell then holds
# (bytes_per_cell): the dense birth times 8, the id table 4, the index of existing cells and its
# sort 16, the box's (i, j, k) and order 12; per cell of the part's slab, its index grids and
# arrival lookup 60; with an even m 68 (the corner and shifted indices 48, an arrival, its
# selection and their sum 16, masks and counts 3).
BUILD_BOX_BYTES = 40
BUILD_PART_BYTES = 68


def lattice_bytes(grid: SparseGrid, m: int, plate_top: float, plate: PlateSpec = PlateSpec()) -> int:
    """An upper bound of the bytes the lattice takes to build and to run (every cell of its box
    a cell), known before anything is allocated: the memory guard's figure."""
    shape, k_plate = _layout(grid, m, plate_top, plate)[:2]
    box = shape[0] * shape[1] * shape[2]
    part = shape[0] * shape[1] * (shape[2] - k_plate)
    return int(box * (BUILD_BOX_BYTES + bytes_per_cell()) + part * BUILD_PART_BYTES)


def _layout(grid: SparseGrid, m: int, plate_top: float, plate: PlateSpec):
    """(shape, plate layers, index base, plate footprint lo and hi) of the lattice."""
    lo, hi = _deposit_index_box(grid)
    v = grid.voxel
    h = m * v
    # index base in z: the boundary below deposit voxel b_z lies on the plate's top
    b_z = int(round((plate_top - grid.origin[2]) / v + 0.5))
    # the deposit's footprint from the voxels that hold material above the plate
    lo_xy, hi_xy = grid.index_to_world(lo)[:2] - v / 2, grid.index_to_world(hi)[:2] - v / 2
    centre = 0.5 * (lo_xy + hi_xy)
    size = np.array([plate.x if plate.x is not None else hi_xy[0] - lo_xy[0] + 2 * PLATE_MARGIN_MM,
                     plate.y if plate.y is not None else hi_xy[1] - lo_xy[1] + 2 * PLATE_MARGIN_MM])
    plate_lo, plate_hi = centre - size / 2, centre + size / 2
    world_lo = np.minimum(plate_lo, lo_xy)
    world_hi = np.maximum(plate_hi, hi_xy)
    # lateral base: a multiple of m deposit voxels below the box, so cells stay on the deposit's lattice
    base_xy = np.floor(((world_lo - grid.origin[:2]) / v + 0.5) / m).astype(np.int64) * m
    n_xy = np.ceil(((world_hi - grid.origin[:2]) / v + 0.5 - base_xy) / m).astype(np.int64)
    k_plate = max(1, int(round(plate.thickness / h)))
    k_part = max(1, int(math.ceil((hi[2] - b_z) / m)))
    shape = (int(n_xy[0]), int(n_xy[1]), k_plate + k_part)
    base = np.array([base_xy[0], base_xy[1], b_z - k_plate * m], np.int64)
    return shape, k_plate, base, plate_lo, plate_hi


def deposit_lattice(grid: SparseGrid, m: int, plate_top: float, plate: PlateSpec = PlateSpec(),
                    end: float | None = None) -> Lattice:
    """The lattice of the deposit (cells born at their arrival) on its plate (module docstring).
    ``end``: the program's end; the deposit keeps arrivals as float32, so the last bead's end can
    round up past it (by up to 6e-8 of the time): such a birth is put at ``end``."""
    v = grid.voxel
    h = m * v
    shape, k_plate, base, plate_lo, plate_hi = _layout(grid, m, plate_top, plate)
    birth = np.full(shape, np.inf)
    # plate cells: those whose centre lies over the plate's footprint
    centre_index = base[None, :] + m * np.stack(np.meshgrid(*[np.arange(n) for n in shape[:2]], [0],
                                                               indexing="ij"), -1).reshape(-1, 3) + (m - 1) / 2
    xy = grid.origin[:2] + v * centre_index[:, :2]
    over = np.all((xy >= plate_lo) & (xy <= plate_hi), axis=1).reshape(shape[:2])
    birth[:, :, :k_plate][over] = -np.inf
    arrival = _centre_arrival(grid, m, base, shape, k_plate)
    if end is not None:
        arrival = np.where(np.isfinite(arrival), np.minimum(arrival, float(end)), arrival)
    birth[:, :, k_plate:] = arrival
    origin = grid.origin + v * (base + (m - 1) / 2)
    layers = np.ones(shape[2], np.int64)
    layers[:k_plate] = plate_layers(k_plate)
    return lattice_from_birth(birth, origin, h, plate_bottom=True, layers=layers)


def plate_layers(k_plate: int) -> np.ndarray:
    """The height in cells of each of the plate's ``k_plate`` layers, from its bottom (0: a layer
    a coarser one below covers): PLATE_FINE_LAYERS of 1 at the top, then 2, then PLATE_COARSE."""
    heights = []
    left = k_plate
    for size in [1] * PLATE_FINE_LAYERS + [2]:
        if left <= 0:
            break
        heights.append(min(size, left))
        left -= heights[-1]
    while left > 0:
        heights.append(min(PLATE_COARSE, left))
        left -= heights[-1]
    out = np.zeros(k_plate, np.int64)
    top = k_plate
    for size in heights:  # from the top down
        out[top - size] = size
        top -= size
    return out


def _centre_arrival(grid: SparseGrid, m: int, base: np.ndarray, shape, k_plate: int) -> np.ndarray:
    """Each part cell's birth (+inf: no cell): the arrival at its centre. Odd ``m``: the central
    deposit voxel's. Even ``m``: the centre is the corner of the 2 x 2 x 2 central voxels; the
    cell exists when at least half of them hold material and is born at the mean of their
    arrivals, which is the arrival at the centre where it varies linearly (a bead passing)."""
    I, J, K = np.meshgrid(np.arange(shape[0]), np.arange(shape[1]), np.arange(k_plate, shape[2]), indexing="ij")
    cells = I.shape
    corner = np.stack([base[0] + m * I, base[1] + m * J, base[2] + m * K], -1).reshape(-1, 3)
    del I, J, K
    if m % 2:
        return grid.arrival_at_index(corner + m // 2).astype(np.float64).reshape(cells)
    total = np.zeros(corner.shape[0])
    held = np.zeros(corner.shape[0], np.uint8)
    for offset in np.array(np.meshgrid([0, 1], [0, 1], [0, 1], indexing="ij")).reshape(3, -1).T:
        a = grid.arrival_at_index(corner + (m // 2 - 1) + offset)
        inside = np.isfinite(a)
        total[inside] += a[inside]
        held += inside
    enough = held >= 4
    total[enough] /= held[enough]
    total[~enough] = np.inf
    return total.reshape(cells)


def beam_path(plan: ProcessPlan, laser_power: float | None) -> SourcePath:
    """The beam along the plan's deposit rows (module docstring)."""
    tp = plan.toolpath
    rows = np.flatnonzero(tp.deposit & (tp.length > 0) & (tp.t_end > tp.t_start))
    if laser_power is not None:
        if not math.isfinite(laser_power) or laser_power < 0:
            raise DmdvoxError(f"--laser-power: {laser_power:g} W; give the beam's power in W (>= 0)")
        power = np.full(len(tp), float(laser_power))
    else:
        power = tp.power.astype(np.float64)
        if rows.size and not np.any(power[rows] > 0):
            raise DmdvoxError(f"--laser-power: {tp.source} gives no power on its deposit rows (no S words); give "
                              "the beam's power in W")
        checks.warn(f"{tp.source}: the beam's power is the program's S word read as watts "
                    f"({np.min(power[rows]):g}-{np.max(power[rows]):g}); give --laser-power W if S is a scale")
    duration = tp.t_end[rows] - tp.t_start[rows]
    pieces = np.maximum(1, np.ceil(duration / PIECE_S).astype(np.int64))
    row_of = np.repeat(rows, pieces)
    first = np.repeat(np.cumsum(pieces) - pieces, pieces)
    j = np.arange(row_of.size) - first
    n_of = pieces[np.searchsorted(rows, row_of)]
    ta = tp.t_start[row_of] + duration[np.searchsorted(rows, row_of)] * j / n_of
    tb = tp.t_start[row_of] + duration[np.searchsorted(rows, row_of)] * (j + 1) / n_of
    tb = np.where(j + 1 == n_of, tp.t_end[row_of], tb)
    length = tp.length[row_of]
    da = plan.motion.distance_at(row_of, ta) / length
    db = plan.motion.distance_at(row_of, tb) / length
    pa = tp.start[row_of] + da[:, None] * (tp.end[row_of] - tp.start[row_of])
    pb = tp.start[row_of] + db[:, None] * (tp.end[row_of] - tp.start[row_of])
    arc_of_row = np.full(len(tp), -1, np.int64)
    arc_of_row[tp.arcs.segment] = np.arange(len(tp.arcs))
    on_arc = arc_of_row[row_of] >= 0
    if on_arc.any():
        pa[on_arc] = arc_points(tp, arc_of_row[row_of[on_arc]], da[on_arc])
        pb[on_arc] = arc_points(tp, arc_of_row[row_of[on_arc]], db[on_arc])
    t0, t1, p0, p1, pw, which = [ta], [tb], [pa], [pb], [power[row_of]], [row_of]
    dwell = rows[tp.dwell_on[rows] > 0]
    if dwell.size:
        t0.append(tp.t_start[dwell] - tp.dwell_on[dwell])
        t1.append(tp.t_start[dwell].astype(np.float64))
        p0.append(tp.start[dwell])
        p1.append(tp.start[dwell])
        pw.append(power[dwell])
        which.append(dwell)
    t0, t1, p0, p1, pw, which = (np.concatenate(a) for a in (t0, t1, p0, p1, pw, which))
    order = np.lexsort((which, t0))
    return SourcePath(t0[order].astype(np.float64), t1[order].astype(np.float64),
                      np.ascontiguousarray(p0[order], np.float64), np.ascontiguousarray(p1[order], np.float64),
                      pw[order], which[order])


__all__ = ["check_inputs", "plate_layers", "PlateSpec", "parse_plate_size", "thermal_voxel", "deposit_lattice", "lattice_bytes", "beam_path", "PLATE_MARGIN_MM",
           "PLATE_THICKNESS_MM"]
