"""Deposit volume and enclosed pores of a :class:`SparseGrid`.

Sub-voxel occupancy
    A voxel is counted as ``clamp(0.5 - sdf / voxel, 0, 1)`` full: the fraction of its cell
    below a plane at the stored distance. It is exact for grid-aligned planes (a face through
    voxel centres gives 0.5 to each centre voxel, so CAD faces at round coordinates are not
    biased) and second-order accurate for curved surfaces. Inactive voxels are exactly 0 or 1.

Pores
    :mod:`enclosure` finds the enclosed voids: the substrate closes them from below, channels
    narrower than a quarter of the bead do not open them, and their volumes use the same
    sub-voxel fractions as the deposit (partial voxels included). Voids below a size floor are
    specks, counted apart from the pores.
"""

from __future__ import annotations

from dataclasses import dataclass

import numba as nb
import numpy as np

from .enclosure import Voids, enclosed_voids
from .sparse import BLOCK_VOXELS, SparseGrid, bit_is_set


@nb.njit(cache=True, parallel=True)
def _leaf_fill(leaf_active, leaf_inside, sdf_offset, sdf, inv_voxel):
    """Per leaf: the sum of inside fractions, in voxels (one leaf per iteration: deterministic)."""
    n = leaf_active.shape[0]
    out = np.zeros(n, np.float64)
    for leaf in nb.prange(n):
        k = sdf_offset[leaf]
        act = leaf_active[leaf]
        ins = leaf_inside[leaf]
        acc = 0.0
        for v in range(BLOCK_VOXELS):
            if bit_is_set(act, v):
                acc += min(max(0.5 - np.float64(sdf[k]) * inv_voxel, 0.0), 1.0)
                k += 1
            elif bit_is_set(ins, v):
                acc += 1.0
        out[leaf] = acc
    return out


def volume(grid: SparseGrid) -> float:
    """Deposit volume in mm^3 from the sub-voxel occupancy of every voxel (module docstring)."""
    per_leaf = _leaf_fill(grid.leaf_active, grid.leaf_inside, grid.sdf_offset, grid.sdf, 1.0 / grid.voxel)
    voxels = float(np.sum(per_leaf)) + BLOCK_VOXELS * grid.n_tile
    return voxels * grid.voxel**3


@dataclass(frozen=True, eq=False)
class Pore:
    """One enclosed void. ``bbox_mm`` is (2, 3): min and max corners of its voxel cells."""

    volume_mm3: float
    centroid_mm: np.ndarray  # (3,) float64
    bbox_mm: np.ndarray  # (2, 3) float64
    equivalent_diameter_mm: float
    wide: bool = True  # holds a ball of the channel width (a cavity), not only slivers


@dataclass(frozen=True, eq=False)
class Porosity:
    """Pores (voids above the speck floor) by descending volume, the specks, and the porosity.

    ``pore_volume_mm3`` is the pores' volume and ``porosity_percent`` is ``100 * pore /
    (deposit + pore)``: the pores ``pore_count`` counts, the specks apart in both
    (``speck_count``, ``speck_volume_mm3``). ``voids`` holds every void with the voxels it owns
    (:class:`enclosure.Voids`, numbered as ``pores`` then the specks).
    """

    pores: tuple[Pore, ...]
    deposit_volume_mm3: float
    pore_volume_mm3: float
    porosity_percent: float
    speck_count: int = 0
    speck_volume_mm3: float = 0.0
    plate_z: float = -np.inf
    channel_mm: float = 0.0
    speck_floor_mm3: float = 0.0
    voids: Voids | None = None


def porosity(grid: SparseGrid, plate_z: float | None = None, bead_width: float | None = None,
             scheduler: str | None = None) -> Porosity:
    """Enclosed voids (:mod:`enclosure`: the substrate below ``plate_z`` is solid, default the
    lowest deposit; with ``bead_width``, channels narrower than a quarter of it do not open a
    void), pores and specks, and the porosity of the deposit. With ``scheduler`` (a dask
    address) the search runs in tiles on the cluster's workers (:mod:`tilelabels`: the same
    voids)."""
    if scheduler:
        from .tilelabels import tiled_voids

        voids = tiled_voids(grid, plate_z=plate_z, bead_width=bead_width, scheduler=scheduler)
    else:
        voids = enclosed_voids(grid, plate_z=plate_z, bead_width=bead_width)
    return porosity_of(voids, volume(grid))


def porosity_of(voids: Voids, deposit_volume_mm3: float) -> Porosity:
    """The pores, specks and porosity of a deposit of ``deposit_volume_mm3`` holding ``voids``."""
    pores = tuple(
        Pore(
            volume_mm3=float(voids.volume_mm3[p]),
            centroid_mm=voids.centroid_mm[p],
            bbox_mm=voids.bbox_mm[p],
            equivalent_diameter_mm=float((6.0 * voids.volume_mm3[p] / np.pi) ** (1.0 / 3.0)),
            wide=bool(voids.wide[p]),
        )
        for p in np.flatnonzero(~voids.speck)
    )
    total = float(np.sum(voids.volume_mm3[~voids.speck]))
    deposit = float(deposit_volume_mm3)
    return Porosity(
        pores=pores,
        deposit_volume_mm3=deposit,
        pore_volume_mm3=total,
        porosity_percent=100.0 * total / (deposit + total) if deposit + total > 0 else 0.0,
        speck_count=int(np.count_nonzero(voids.speck)),
        speck_volume_mm3=float(np.sum(voids.volume_mm3[voids.speck])),
        plate_z=voids.plate_z,
        channel_mm=voids.channel_mm,
        speck_floor_mm3=voids.speck_floor_mm3,
        voids=voids,
    )


def pores(grid: SparseGrid, plate_z: float | None = None, bead_width: float | None = None) -> list[Pore]:
    """Enclosed pores sorted by descending volume (see :func:`porosity`)."""
    return list(porosity(grid, plate_z, bead_width).pores)


@nb.njit(cache=True)
def _inside_index_bounds(block, leaf_coord, leaf_inside):
    lo = np.full(3, np.iinfo(np.int64).max, np.int64)
    hi = np.full(3, np.iinfo(np.int64).min, np.int64)
    nx, ny, nz = block.shape
    for bx in range(nx):
        for by in range(ny):
            for bz in range(nz):
                if block[bx, by, bz] <= -2:  # inside tile: all of it
                    base = (8 * bx, 8 * by, 8 * bz)
                    for q in range(3):
                        lo[q] = min(lo[q], base[q])
                        hi[q] = max(hi[q], base[q] + 7)
    for leaf in range(leaf_coord.shape[0]):
        for v in range(512):
            if bit_is_set(leaf_inside[leaf], v):
                ijk = (8 * leaf_coord[leaf, 0] + (v >> 6), 8 * leaf_coord[leaf, 1] + ((v >> 3) & 7),
                       8 * leaf_coord[leaf, 2] + (v & 7))
                for q in range(3):
                    lo[q] = min(lo[q], ijk[q])
                    hi[q] = max(hi[q], ijk[q])
    return lo, hi


def deposit_bbox(grid: SparseGrid) -> np.ndarray:
    """``[[xmin,ymin,zmin],[xmax,ymax,zmax]]`` of the inside voxels' cells (to a voxel)."""
    lo, hi = _inside_index_bounds(grid.block, grid.leaf_coord, grid.leaf_inside)
    if lo[0] > hi[0]:
        return np.zeros((2, 3))
    return np.stack([grid.index_to_world(lo) - 0.5 * grid.voxel, grid.index_to_world(hi) + 0.5 * grid.voxel])
