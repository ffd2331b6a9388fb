"""`dmdvox diff`: what a change to the program does to the part.

Both programs are deposited at one voxel size. Every grid puts its voxel centres at integer
multiples of the voxel (docs/DESIGN.md), so the two deposits share a lattice even though their
block tables start at different places: voxel ``(i, j, k)`` of the common index space (whose
origin is the lower of the two grids' origins, corner by corner) is voxel ``(i, j, k) - off``
of each grid. The block passes walk only the common blocks that either grid's non-outside
blocks cover, never a box:

* added and removed volume: the sub-voxel material of each deposit as the comparison counts it
  (``1 -`` :func:`dmdvox.grid.enclosure.cell_empty`), per voxel ``max(0, f_new - f_old)``
  (added) and ``max(0, f_old - f_new)`` (removed);
* where: every changed voxel carries the arrival time, in the program that holds its material
  (the new one for added, the old one for removed), of the voxel among itself and its six
  neighbours that lies deepest in the changed material, and that time falls in one deposit row
  of that program: its G-code line and layer. A voxel at a joint of two rows takes either, so
  the lines are exact to within one segment;
* with a CAD part: both deposits compared with it (:func:`dmdvox.comparison.compare.compare`),
  the change of void and overbuild.

With ``out_dir``: the diff map as VTK image data over the common lattice (``occupancy_change``
new minus old in fractions of a voxel, ``label`` and both SDFs; one ``.vti`` when small, else
a ``.vtm`` of pieces covering only the occupied regions, as ``compare`` writes them), the new
deposit's surface coloured by its distance from the old one (``.vtp``), the pictures the caller
draws, and the JSON.
"""

from __future__ import annotations

import json
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from numba import njit, prange

from . import progress
from .errors import DmdvoxError
from .grid.enclosure import cell_empty
from .grid.sparse import BLOCK, BLOCK_VOXELS, OUTSIDE, SparseGrid, leaf_arrival, sdf_at
from .comparison.compare import Comparison
from .deposit.simulate import Simulation
from .process.plan import ProcessPlan
from .summary import SummaryResult

# Occupancy differences below this fraction of a voxel are the float32 rounding of two sweeps of
# the same beads on differently placed block tables, not a change.
ROUNDING = 1e-4
MAX_LINES_LISTED = 50
LABEL_NAMES = {0: "outside both", 1: "inside both", 2: "added (new only)", 3: "removed (old only)"}
SINGLE_VTI_VOXELS = 16_000_000
CHUNK_BLOCKS = 8192  # changed blocks decoded at once (16 KiB each)
PIECE_BLOCKS = 8


@dataclass(frozen=True)
class DiffRequest:
    """Two programs to compare: ``old`` and ``new`` deposited at ``voxel`` (default: the old
    plan's), against the CAD STL ``cad`` (moved by ``cad_offset``) when given; outputs to
    ``out_dir``; within ``max_memory`` bytes; sweeps on the dask cluster at ``scheduler``."""

    old: ProcessPlan
    new: ProcessPlan
    voxel: float | None = None
    cad: str | Path | None = None
    cad_offset: tuple[float, float, float] = (0.0, 0.0, 0.0)
    out_dir: str | Path | None = None
    max_memory: int | None = None
    scheduler: str | None = None


@dataclass(frozen=True, eq=False)
class Diff(SummaryResult):
    """A diff's result: ``summary`` (the JSON ``--json`` prints, also readable as
    ``result[key]``), both deposits (:class:`~dmdvox.deposit.simulate.Simulation`) and, with a
    CAD part, both comparisons."""

    summary: dict
    old: Simulation
    new: Simulation
    old_comparison: Comparison | None = None
    new_comparison: Comparison | None = None

    def text(self) -> str:
        s = self.summary
        out = [f"{s['old']} -> {s['new']}: voxel {s['voxel_mm']:g} mm",
               f"  added    {s['added_mm3']:,.3f} mm^3", f"  removed  {s['removed_mm3']:,.3f} mm^3",
               f"  net      {s['net_mm3']:+,.3f} mm^3"]
        for side, program in (("added", "new"), ("removed", "old")):
            for row in s[f"{side}_lines"][:10]:
                out.append(f"    {side:<8s} line {row['line']:>6d} of the {program} program (layer {row['layer']}): "
                           f"{row['volume_mm3']:.3f} mm^3")
        if "cad" in s:
            for key in ("void_percent", "overbuild_percent"):
                c = s["cad"][key]
                out.append(f"  {key:<18s} {c['old']:.3f} -> {c['new']:.3f} ({c['change']:+.3f})")
        out += [f"  wrote {path}" for path in s["outputs"]]
        return "\n".join(out)


@njit(cache=True)
def _arrival(g, i, j, k):
    """Arrival time at integer index (i, j, k) as the grid keeps it (inf outside, octant minima
    deeper than the band)."""
    bi, bj, bk = i >> 3, j >> 3, k >> 3
    if i < 0 or j < 0 or k < 0 or bi >= g.block.shape[0] or bj >= g.block.shape[1] or bk >= g.block.shape[2]:
        return np.inf
    val = g.block[bi, bj, bk]
    if val >= 0:
        return np.float64(leaf_arrival(val, (i & 7) * 64 + (j & 7) * 8 + (k & 7), g.leaf_active, g.leaf_inside,
                                       g.arr_offset, g.arrival, g.leaf_octant_arrival))
    if val == OUTSIDE:
        return np.inf
    return np.float64(g.tile_arrival[-2 - val, (i & 7) >> 2, (j & 7) >> 2, (k & 7) >> 2])


_STEPS = np.array([[0, 0, 0], [-1, 0, 0], [1, 0, 0], [0, -1, 0], [0, 1, 0], [0, 0, -1], [0, 0, 1]], np.int64)


@njit(cache=True)
def _changed_arrival(src, other, i, j, k, off_src, off_other):
    """The arrival, in ``src``, of the material a changed voxel (i, j, k) (common index space)
    gained or lost: of the voxel and its six neighbours whose centres lie inside ``src``, the
    one farthest outside ``other`` (deepest in the changed material; a voxel on a layer face
    would otherwise take the time of the unchanged layer below); inf when none is inside."""
    best_t = np.inf
    best = -np.inf
    for n in range(_STEPS.shape[0]):
        a, b, c = i + _STEPS[n, 0], j + _STEPS[n, 1], k + _STEPS[n, 2]
        if sdf_at(src, a - off_src[0], b - off_src[1], c - off_src[2]) >= 0.0:
            continue
        outside = sdf_at(other, a - off_other[0], b - off_other[1], c - off_other[2])
        if outside > best:
            best = outside
            best_t = _arrival(src, a - off_src[0], b - off_src[1], c - off_src[2])
    return best_t


@njit(cache=True)
def _occupancies(old, new, i, j, k, off_old, off_new, inv):
    f_old = 1.0 - cell_empty(old, i - off_old[0], j - off_old[1], k - off_old[2], inv)
    f_new = 1.0 - cell_empty(new, i - off_new[0], j - off_new[1], k - off_new[2], inv)
    return f_old, f_new


@njit(cache=True)
def _solid(g, bx, by, bz, off):
    """Whether common block (bx, by, bz) lies wholly in inside tiles of ``g`` (offset ``off``
    voxels): the (up to 8) blocks of ``g`` it overlaps are all inside tiles."""
    lo0, lo1, lo2 = (8 * bx - off[0]) >> 3, (8 * by - off[1]) >> 3, (8 * bz - off[2]) >> 3
    hi0, hi1, hi2 = (8 * bx + 7 - off[0]) >> 3, (8 * by + 7 - off[1]) >> 3, (8 * bz + 7 - off[2]) >> 3
    nx, ny, nz = g.block.shape
    if lo0 < 0 or lo1 < 0 or lo2 < 0 or hi0 >= nx or hi1 >= ny or hi2 >= nz:
        return False
    for a in range(lo0, hi0 + 1):
        for b in range(lo1, hi1 + 1):
            for c in range(lo2, hi2 + 1):
                if g.block[a, b, c] > -2:
                    return False
    return True


@njit(parallel=True, cache=True)
def block_changes(old, new, blocks, off_old, off_new, voxel):
    """Per common block (m, 3): (m, 2) added and removed volume in voxels."""
    m = blocks.shape[0]
    sums = np.zeros((m, 2))
    inv = 1.0 / voxel
    for b in prange(m):
        bx, by, bz = blocks[b, 0], blocks[b, 1], blocks[b, 2]
        if _solid(old, bx, by, bz, off_old) and _solid(new, bx, by, bz, off_new):
            continue  # deep inside both: no change (and no voxel to decode)
        for v in range(BLOCK_VOXELS):
            i, j, k = 8 * blocks[b, 0] + (v >> 6), 8 * blocks[b, 1] + ((v >> 3) & 7), 8 * blocks[b, 2] + (v & 7)
            f_old, f_new = _occupancies(old, new, i, j, k, off_old, off_new, inv)
            q = f_new - f_old
            if q > ROUNDING:
                sums[b, 0] += q
            elif q < -ROUNDING:
                sums[b, 1] -= q
    return sums


@njit(cache=True, inline="always")
def _change_at(old, new, blocks, b, v, off_old, off_new, inv):
    """Voxel v of block b in the common index space, and its occupancy change (new - old)."""
    i, j, k = 8 * blocks[b, 0] + (v >> 6), 8 * blocks[b, 1] + ((v >> 3) & 7), 8 * blocks[b, 2] + (v & 7)
    f_old, f_new = _occupancies(old, new, i, j, k, off_old, off_new, inv)
    return i, j, k, f_new - f_old


@njit(parallel=True, cache=True)
def changed_voxels(old, new, blocks, off_old, off_new, voxel):
    """For the changed blocks (m, 3): (m, 512) added and removed volume per voxel (in voxels)
    and the arrival time of that material (the new program's for added, the old's for
    removed; inf where nothing changed)."""
    m = blocks.shape[0]
    added = np.zeros((m, BLOCK_VOXELS))
    removed = np.zeros((m, BLOCK_VOXELS))
    t_added = np.full((m, BLOCK_VOXELS), np.inf)
    t_removed = np.full((m, BLOCK_VOXELS), np.inf)
    inv = 1.0 / voxel
    for b in prange(m):
        for v in range(BLOCK_VOXELS):
            i, j, k, q = _change_at(old, new, blocks, b, v, off_old, off_new, inv)
            if q > ROUNDING:
                added[b, v] = q
                t_added[b, v] = _changed_arrival(new, old, i, j, k, off_new, off_old)
            elif q < -ROUNDING:
                removed[b, v] = -q
                t_removed[b, v] = _changed_arrival(old, new, i, j, k, off_old, off_new)
    return added, removed, t_added, t_removed


@njit(parallel=True, cache=True)
def block_fields(old, new, blocks, off_old, off_new, voxel):
    """For blocks (m, 3) of the common index space: (m, 512) occupancy change (new - old, in
    fractions of a voxel), label (:data:`LABEL_NAMES`, by the voxel centres) and both SDFs."""
    m = blocks.shape[0]
    change = np.zeros((m, BLOCK_VOXELS), np.float32)
    label = np.zeros((m, BLOCK_VOXELS), np.uint8)
    sdf_old = np.zeros((m, BLOCK_VOXELS), np.float32)
    sdf_new = np.zeros((m, BLOCK_VOXELS), np.float32)
    inv = 1.0 / voxel
    for b in prange(m):
        for v in range(BLOCK_VOXELS):
            i, j, k, q = _change_at(old, new, blocks, b, v, off_old, off_new, inv)
            change[b, v] = q if abs(q) > ROUNDING else 0.0
            so = sdf_at(old, i - off_old[0], j - off_old[1], k - off_old[2])
            sn = sdf_at(new, i - off_new[0], j - off_new[1], k - off_new[2])
            sdf_old[b, v] = so
            sdf_new[b, v] = sn
            if so < 0 and sn < 0:
                label[b, v] = 1
            elif sn < 0:
                label[b, v] = 2
            elif so < 0:
                label[b, v] = 3
    return change, label, sdf_old, sdf_new


@dataclass(frozen=True)
class Lattice:
    """The common index space of two grids on one lattice: its origin, each grid's offset in
    voxels, and its block table's shape."""

    voxel: float
    origin: np.ndarray
    off_old: np.ndarray
    off_new: np.ndarray
    shape: tuple[int, int, int]

    @staticmethod
    def of(old: SparseGrid, new: SparseGrid) -> "Lattice":
        voxel = float(old.voxel)
        if not np.isclose(new.voxel, voxel, rtol=1e-12):
            raise DmdvoxError(f"the two deposits have different voxels ({old.voxel:g}, {new.voxel:g} mm)")
        origin = np.minimum(old.origin, new.origin)
        offsets = []
        for grid in (old, new):
            off = (grid.origin - origin) / voxel
            if np.any(np.abs(off - np.round(off)) > 1e-6):
                raise DmdvoxError("the two deposits are not on one voxel lattice (grids put voxel centres at "
                                  "multiples of the voxel)")
            offsets.append(np.round(off).astype(np.int64))
        ends = [off + BLOCK * np.array(g.block.shape) for off, g in zip(offsets, (old, new))]
        shape = tuple(int(v) for v in -(-np.maximum(*ends) // BLOCK))
        return Lattice(voxel, origin, offsets[0], offsets[1], shape)

    def blocks(self, old: SparseGrid, new: SparseGrid) -> np.ndarray:
        """(m, 3) int64 common blocks that any non-outside block of either grid overlaps, in
        linear order."""
        parts = []
        for grid, off in ((old, self.off_old), (new, self.off_new)):
            own = np.argwhere(grid.block != OUTSIDE).astype(np.int64)
            lo = (BLOCK * own + off) // BLOCK
            hi = (BLOCK * own + off + BLOCK - 1) // BLOCK
            for corner in np.ndindex(2, 2, 2):
                parts.append(np.where(np.array(corner, bool), hi, lo))
        if not parts:
            return np.zeros((0, 3), np.int64)
        return np.unique(np.concatenate(parts), axis=0)  # rows sorted: linear block order


def _row_volumes(plan: ProcessPlan, volume: np.ndarray, times: np.ndarray) -> tuple[np.ndarray, float]:
    """``volume`` (voxels) arriving at ``times`` summed per toolpath row (the deposit row whose
    time span holds the time: the last one started by then), and the volume no arrival places."""
    tp = plan.toolpath
    rows = np.flatnonzero(tp.deposit)
    placed = np.isfinite(times)
    at = np.clip(np.searchsorted(tp.t_start[rows], times[placed], side="right") - 1, 0, rows.size - 1)
    return np.bincount(rows[at], volume[placed], len(tp)), float(volume[~placed].sum())


def _where(plan: ProcessPlan, per_row: np.ndarray) -> tuple[list, list]:
    """The lines (largest first) and the layers that hold the volume ``per_row`` (mm^3)."""
    tp = plan.toolpath
    rows = np.flatnonzero(per_row > 0)
    lines, where = np.unique(tp.line[rows], return_inverse=True)
    per_line = np.bincount(where, per_row[rows], lines.size)
    layer_of_line = np.zeros(lines.size, np.int64)
    layer_of_line[where] = tp.layer[rows]
    order = np.argsort(-per_line, kind="stable")
    line_list = [{"line": int(lines[n]), "layer": int(layer_of_line[n]), "volume_mm3": float(per_line[n])}
                 for n in order[:MAX_LINES_LISTED]]
    layers, where = np.unique(tp.layer[rows], return_inverse=True)
    per_layer = np.bincount(where, per_row[rows], layers.size)
    layer_list = [{"layer": int(layers[n]), "volume_mm3": float(per_layer[n])} for n in range(layers.size)]
    return line_list, layer_list


def diff(request: DiffRequest, *, pictures=None) -> Diff:
    """Deposit both programs and tell what changed (module docstring). ``pictures(out_dir, stem,
    new_surface, old_surface)`` draws what the caller wants beside the files (the diff draws
    nothing itself) and returns the paths."""
    from .comparison.compare import CompareRequest, compare
    from .deposit.simulate import SimulateRequest, describe, simulate

    voxel = request.old.resolve_voxel(request.voxel)
    runs, comparisons = [], []
    for name, plan in (("old", request.old), ("new", request.new)):
        holds = {"the old deposit": int(runs[0].grid.memory_bytes)} if runs else None
        if request.cad is not None:
            progress.stage("diff", f"the {name} program against the CAD part")
            comparison = compare(CompareRequest(plan, request.cad, cad_offset=tuple(request.cad_offset), voxel=voxel,
                                                max_memory=request.max_memory, scheduler=request.scheduler),
                                 also_holds=holds)
            comparisons.append(comparison)
            runs.append(comparison.simulation)
        else:
            progress.stage("diff", f"depositing the {name} program: {describe(plan)}")
            runs.append(simulate(SimulateRequest(plan, voxel=voxel, max_memory=request.max_memory,
                                                 scheduler=request.scheduler), also_holds=holds))
    old_grid, new_grid = runs[0].grid, runs[1].grid
    progress.stage("diff", "added and removed material")
    lattice = Lattice.of(old_grid, new_grid)
    blocks = lattice.blocks(old_grid, new_grid)
    old_view, new_view = old_grid.view(), new_grid.view()
    sums = block_changes(old_view, new_view, blocks, lattice.off_old, lattice.off_new, voxel)
    voxel_volume = voxel**3
    changed = blocks[sums.sum(axis=1) > 0]
    # the changed blocks a chunk at a time: per voxel arrays stay within CHUNK_BLOCKS blocks
    added_rows, removed_rows = np.zeros(len(request.new.toolpath)), np.zeros(len(request.old.toolpath))
    added_unplaced = removed_unplaced = 0.0
    for first in range(0, changed.shape[0], CHUNK_BLOCKS):
        added, removed, t_added, t_removed = changed_voxels(old_view, new_view, changed[first:first + CHUNK_BLOCKS],
                                                            lattice.off_old, lattice.off_new, voxel)
        hit = added > 0
        per_row, unplaced = _row_volumes(request.new, added[hit], t_added[hit])
        added_rows += per_row * voxel_volume
        added_unplaced += unplaced * voxel_volume
        hit = removed > 0
        per_row, unplaced = _row_volumes(request.old, removed[hit], t_removed[hit])
        removed_rows += per_row * voxel_volume
        removed_unplaced += unplaced * voxel_volume
    added_lines, added_layers = _where(request.new, added_rows)
    removed_lines, removed_layers = _where(request.old, removed_rows)
    added_mm3 = float(sums[:, 0].sum() * voxel_volume)
    removed_mm3 = float(sums[:, 1].sum() * voxel_volume)
    summary = {
        "old": str(request.old.toolpath.source),
        "new": str(request.new.toolpath.source),
        "voxel_mm": voxel,
        "old_deposit_volume_mm3": runs[0].summary["deposit_volume_mm3"],
        "new_deposit_volume_mm3": runs[1].summary["deposit_volume_mm3"],
        "added_mm3": added_mm3,
        "removed_mm3": removed_mm3,
        "net_mm3": added_mm3 - removed_mm3,
        "changed_blocks": int(changed.shape[0]),
        "added_lines": added_lines,
        "added_layers": added_layers,
        "added_unplaced_mm3": added_unplaced,
        "removed_lines": removed_lines,
        "removed_layers": removed_layers,
        "removed_unplaced_mm3": removed_unplaced,
        "warnings": [w for run in runs for w in run.summary["warnings"]],
        "outputs": [],
    }
    if comparisons:
        summary["cad"] = {"file": str(request.cad)}
        for key in ("void_volume_mm3", "overbuild_volume_mm3", "void_percent", "overbuild_percent",
                    "porosity_percent", "max_underfill_mm", "max_overbuild_mm"):
            a, b = comparisons[0].summary[key], comparisons[1].summary[key]
            summary["cad"][key] = {"old": a, "new": b, "change": b - a}
    if request.out_dir is not None:
        out = Path(request.out_dir)
        stem = f"{Path(summary['old']).stem}_vs_{Path(summary['new']).stem}"
        summary["outputs"] += [str(p) for p in _write_outputs(out, stem, old_grid, new_grid, lattice, blocks,
                                                              pictures)]
        summary["outputs"].append(str(out / f"{stem}_diff.json"))
        from .io.atomic import write_text

        write_text(Path(summary["outputs"][-1]), json.dumps(summary, indent=2))
    return Diff(summary, runs[0], runs[1], *(comparisons or [None, None]))


def _dense(lattice: Lattice, old: SparseGrid, new: SparseGrid, lo: np.ndarray, hi: np.ndarray) -> dict:
    """The fields of common blocks ``lo <= b < hi`` as dense (nx, ny, nz) arrays."""
    axes = [np.arange(lo[q], hi[q]) for q in range(3)]
    blocks = np.stack(np.meshgrid(*axes, indexing="ij"), -1).reshape(-1, 3).astype(np.int64)
    fields = block_fields(old.view(), new.view(), blocks, lattice.off_old, lattice.off_new, lattice.voxel)
    n = hi - lo
    out = {}
    for name, values in zip(("occupancy_change", "label", "old_sdf_mm", "new_sdf_mm"), fields):
        boxes = values.reshape(n[0], n[1], n[2], BLOCK, BLOCK, BLOCK)
        out[name] = boxes.transpose(0, 3, 1, 4, 2, 5).reshape(n[0] * BLOCK, n[1] * BLOCK, n[2] * BLOCK)
    return out


def _pieces(lattice: Lattice, old: SparseGrid, new: SparseGrid, blocks: np.ndarray):
    """(origin, arrays) of every region of ``PIECE_BLOCKS``^3 common blocks holding one of
    ``blocks``, one voxel plane wider on its high sides so that neighbouring pieces share it."""
    shape = np.array(lattice.shape)
    corners = np.unique(blocks // PIECE_BLOCKS, axis=0)
    for corner in corners:
        lo = corner * PIECE_BLOCKS
        hi = np.minimum(lo + PIECE_BLOCKS, shape)
        wide = np.minimum(hi + 1, shape)
        size = BLOCK * (hi - lo) + (wide - hi)
        arrays = {name: a[:size[0], :size[1], :size[2]] for name, a in _dense(lattice, old, new, lo, wide).items()}
        yield lattice.origin + lattice.voxel * BLOCK * lo, arrays


def _write_outputs(out: Path, stem: str, old: SparseGrid, new: SparseGrid, lattice: Lattice, blocks: np.ndarray,
                   pictures) -> list[Path]:
    """The diff map (.vti or .vtm), the new surface's distance from the old (.vtp), pictures."""
    from .grid.surface import surface_mesh
    from .io.mesh import write_vtp
    from .io.vtk_image import write_voxel_pieces, write_voxels

    units = {"occupancy_change": "fraction of a voxel", "label": "code", "old_sdf_mm": "mm", "new_sdf_mm": "mm"}
    labels = {"label": LABEL_NAMES}
    shape = np.array(lattice.shape, np.int64)
    if int(np.prod(shape)) * BLOCK_VOXELS <= SINGLE_VTI_VOXELS:
        written = write_voxels(out / f"{stem}_diff.vti", lattice.origin, lattice.voxel,
                               _dense(lattice, old, new, np.zeros(3, np.int64), shape), units=units, labels=labels)
    else:
        written = write_voxel_pieces(out / f"{stem}_diff.vtm", lattice.voxel, _pieces(lattice, old, new, blocks),
                                     units=units, labels=labels)
    vertices, triangles = surface_mesh(new)
    # + : the new surface lies outside the old deposit (material added), - : inside it (removed)
    change = old.trilinear(vertices)
    written.append(write_vtp(out / f"{stem}_diff.vtp", vertices, triangles, point_arrays={"change_mm": change}))
    if pictures is not None:
        written += pictures(out, stem, (vertices, triangles, change), surface_mesh(old))
    return written


__all__ = ["Diff", "DiffRequest", "LABEL_NAMES", "diff"]
