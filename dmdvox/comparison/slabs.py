"""The comparison's block passes as slab tasks: in this process or on a dask cluster, one result.

The two grids are cut along x into slabs of about :data:`SLAB_BLOCKS` occupied blocks, each
with a halo of one block on both sides (the kernels read a voxel's neighbours, never farther
than the next block). A task (:class:`CompareSlab`) carries its slab of both grids and returns
what the summary needs from it (:class:`SlabResult`): per-plane volumes, the depths within the
bands and the blocks to search beyond them, and the CAD surface's crossings with the deposit's
SDF there. The merge adds them in slab order. The local run cuts the same slabs and runs them
here, so ``--scheduler`` changes where the work runs, never the numbers.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..defaults import SLAB_BLOCKS
from ..grid.sparse import OUTSIDE, SparseGrid
from ..tasks import map_tasks
from .blocks import block_sums, crossings, union_blocks

SUM_CHUNK_BLOCKS = 1 << 14  # blocks per call of block_sums: its per-block arrays stay ~6 MB
COLUMNS = 5  # per plane: CAD, void below / above the layer cut, overbuild below / above


@dataclass(frozen=True, eq=False)
class CompareSlab:
    """Blocks ``core`` (a range of x block numbers of the slab's own grids) of the deposit and
    the CAD, with a block of halo around; ``bx0`` is the slab's first block in the whole grid."""

    deposit: SparseGrid
    cad: SparseGrid
    bx0: int
    core: tuple[int, int]
    plane_cut: np.ndarray


@dataclass(frozen=True, eq=False)
class SlabResult:
    per_plane: np.ndarray  # (COLUMNS, nz) volumes in voxels
    under: float  # largest underfill depth within the deposit's band, mm
    over: float  # largest overbuild depth within the CAD's band, mm
    far_under: np.ndarray  # (m, 3) blocks (whole-grid numbers) with void beyond the deposit's band
    far_over: np.ndarray  # (m, 3) blocks with overbuild beyond the CAD's band
    deviation: np.ndarray  # (n,) the deposit's SDF at the CAD surface's crossings, mm
    weights: np.ndarray  # (n,) their area weights
    far: np.ndarray  # (k,) indices into ``deviation`` of values clamped by the deposit's band
    far_points: np.ndarray  # (k, 3) world points of those crossings, to measure exactly


def compare_slab(task: CompareSlab) -> SlabResult:
    """One slab's share of the comparison (pure: the same slab gives the same result anywhere)."""
    dep, cad = task.deposit, task.cad
    dep_view, cad_view = dep.view(), cad.view()
    c0, c1 = task.core
    blocks = union_blocks(dep.block[c0:c1], cad.block[c0:c1])
    blocks[:, 0] += c0
    nz = task.plane_cut.shape[0]
    per_plane = np.zeros((COLUMNS, nz))
    under = over = 0.0
    far_under, far_over = [], []
    for start in range(0, len(blocks), SUM_CHUNK_BLOCKS):
        chunk = blocks[start:start + SUM_CHUNK_BLOCKS]
        sums, chunk_under, chunk_over, chunk_far_under, chunk_far_over = block_sums(dep_view, cad_view, chunk,
                                                                                   dep.voxel, task.plane_cut)
        planes = (8 * chunk[:, 2:3] + np.arange(8)).ravel()
        for column in range(COLUMNS):
            per_plane[column] += np.bincount(planes, sums[:, :, column].ravel(), nz)
        under = max(under, float(chunk_under.max(initial=0.0)))
        over = max(over, float(chunk_over.max(initial=0.0)))
        far_under.append(chunk[chunk_far_under])
        far_over.append(chunk[chunk_far_over])
    shift = np.array([task.bx0, 0, 0], np.int64)
    empty = np.zeros((0, 3), np.int64)
    core_leaves = cad.leaf_coord[(cad.leaf_coord[:, 0] >= c0) & (cad.leaf_coord[:, 0] < c1)].astype(np.int64)
    index_points, deviation, weights = crossings(cad_view, dep_view, core_leaves)
    far = np.flatnonzero(np.abs(deviation) >= dep.band - dep.voxel)
    return SlabResult(per_plane, under, over, np.concatenate([empty, *far_under]) + shift,
                      np.concatenate([empty, *far_over]) + shift, deviation, weights, far,
                      dep.origin + dep.voxel * index_points[far])


def slab_ranges(deposit: SparseGrid, cad: SparseGrid) -> list[tuple[int, int]]:
    """Consecutive x block ranges of about :data:`SLAB_BLOCKS` occupied blocks each (never an
    empty one), from the two block tables alone."""
    occupied = ((deposit.block != OUTSIDE) | (cad.block != OUTSIDE)).sum(axis=(1, 2), dtype=np.int64)
    bounds, count = [0], 0
    for bx, n in enumerate(occupied):
        if count and count + n > SLAB_BLOCKS:
            bounds.append(bx)
            count = 0
        count += n
    bounds.append(len(occupied))
    return list(zip(bounds[:-1], bounds[1:]))


def slab_tasks(deposit: SparseGrid, cad: SparseGrid, plane_cut: np.ndarray, ranges: list[tuple[int, int]]):
    """The tasks of :func:`compare_slab` for the x block ``ranges``, made one at a time as they
    are drawn (each holds copies of its slab)."""
    nbx = deposit.block.shape[0]
    for x0, x1 in ranges:
        lo, hi = max(0, x0 - 1), min(nbx, x1 + 1)
        yield CompareSlab(deposit.crop_x(lo, hi), cad.crop_x(lo, hi), lo, (x0 - lo, x1 - lo), plane_cut)


@dataclass(frozen=True, eq=False)
class BlockPasses:
    """The merged slab results (:class:`SlabResult`, per-plane volumes in mm^3)."""

    per_plane: np.ndarray
    under: float
    over: float
    far_under: np.ndarray
    far_over: np.ndarray
    deviation: np.ndarray
    weights: np.ndarray
    far: np.ndarray
    far_points: np.ndarray


def block_passes(deposit: SparseGrid, cad: SparseGrid, plane_cut: np.ndarray,
                 scheduler: str | None = None) -> BlockPasses:
    """Every slab's :func:`compare_slab`, here or on the cluster at ``scheduler``, merged."""
    per_plane = np.zeros((COLUMNS, plane_cut.shape[0]))
    under = over = 0.0
    parts: dict[str, list] = {name: [] for name in ("far_under", "far_over", "deviation", "weights", "far",
                                                    "far_points")}
    offset = 0
    ranges = slab_ranges(deposit, cad)
    for result in map_tasks(compare_slab, slab_tasks(deposit, cad, plane_cut, ranges), scheduler=scheduler,
                            desc="compare slabs" if scheduler else None, total=len(ranges)):
        per_plane += result.per_plane
        under, over = max(under, result.under), max(over, result.over)
        for name in parts:
            parts[name].append(getattr(result, name) + (offset if name == "far" else 0))
        offset += result.deviation.shape[0]
    empty = {"far_under": np.zeros((0, 3), np.int64), "far_over": np.zeros((0, 3), np.int64),
             "deviation": np.zeros(0), "weights": np.zeros(0), "far": np.zeros(0, np.int64),
             "far_points": np.zeros((0, 3))}
    merged = {name: np.concatenate([empty[name], *values]) for name, values in parts.items()}
    return BlockPasses(per_plane * deposit.voxel**3, under, over, **merged)
