"""The comparison's voxel fields on disk, sparse: OpenVDB grids and VTK image blocks.

Fields (one value per voxel of the shared lattice):

* ``label``: 0 outside both, 1 inside both, 2 void (CAD only), 3 overbuild (deposit only),
  4 pore (the centre of a voxel of an enclosed void: pores and specks);
* ``deposit_sdf_mm``, ``cad_sdf_mm``: both signed distances (clamped at their bands);
* ``deviation_mm`` (OpenVDB only): within the CAD's narrow band, how far the deposit's surface
  lies outside the CAD's there, ``-deposit_sdf`` (positive = excess material).

``<stem>_compare.vdb`` holds them as sparse OpenVDB grids (readable by ParaView, Houdini,
``vdb_print``), each saying its values' unit in its metadata (``unit``: ``mm``, or ``code`` for
``label`` with its ``label_codes``). For VTK, a comparison of up to ``SINGLE_VTI_VOXELS``
voxels is one ``<stem>_compare.vti`` over the whole block table, as before; a larger one is a
``.vtm`` of image blocks of at most ``PIECE_BLOCKS``^3 blocks, one per region that holds a
non-outside block, each one voxel plane wider on its high sides so that neighbouring pieces
share a plane.
Memory follows the occupied regions, one piece at a time.
"""

from __future__ import annotations

from pathlib import Path

import numba as nb
import numpy as np

from ..grid.sparse import BLOCK, BLOCK_VOXELS, OUTSIDE, SparseGrid
from ..grid.vdbio import GRID_UNIT_KEY, UNITS, metadata_value, stable_uuid, voxel_transform, to_openvdb
from ..io.atomic import atomic_path
from ..vdb import openvdb
from .blocks import LABEL_NAMES, block_labels

SINGLE_VTI_VOXELS = 16_000_000
PIECE_BLOCKS = 8  # a VTK piece spans at most 8^3 blocks (64^3 voxels)
# the label grid's legend in the .vdb (file and grid metadata): "0 outside, 1 inside, ..."
LABEL_CODES_TEXT = ", ".join(f"{k} {v}" for k, v in LABEL_NAMES.items())


def pore_voxels(deposit: SparseGrid, porosity):
    """``flags(blocks) -> (m, 512) bool``: which voxels of the given blocks (m, 3) belong to an
    enclosed void of ``porosity`` (:class:`dmdvox.grid.analysis.Porosity`: pores and specks)."""
    voids = porosity.voids
    shape = deposit.block.shape

    def linear(coords: np.ndarray) -> np.ndarray:
        return np.ravel_multi_index(np.asarray(coords, np.int64).reshape(-1, 3).T, shape)

    owner = linear(voids.block_coord)
    order = np.argsort(owner, kind="stable")
    owner = owner[order]
    whole = np.sort(linear(voids.tile_coord))

    def flags(blocks: np.ndarray) -> np.ndarray:
        wanted = linear(blocks)
        out = np.zeros((wanted.size, BLOCK_VOXELS), np.bool_)
        at = np.minimum(np.searchsorted(owner, wanted), max(owner.size - 1, 0))
        hit = owner[at] == wanted if owner.size else np.zeros(wanted.size, bool)
        out[hit] = voids.block_label[order[at[hit]]] >= 0
        at = np.minimum(np.searchsorted(whole, wanted), max(whole.size - 1, 0))
        if whole.size:
            out[whole[at] == wanted] = True
        return out

    return flags


def _labels_box(deposit: SparseGrid, cad: SparseGrid, pore, lo: np.ndarray, hi: np.ndarray) -> np.ndarray:
    """Dense (uint8) labels of blocks ``lo <= b < hi``."""
    axes = [np.arange(lo[q], hi[q]) for q in range(3)]
    blocks = np.stack(np.meshgrid(*axes, indexing="ij"), -1).reshape(-1, 3).astype(np.int64)
    flags = pore(blocks)
    labels = block_labels(deposit.view(), cad.view(), blocks, flags)
    n = hi - lo
    boxes = labels.reshape(n[0], n[1], n[2], BLOCK, BLOCK, BLOCK)
    return boxes.transpose(0, 3, 1, 4, 2, 5).reshape(n[0] * BLOCK, n[1] * BLOCK, n[2] * BLOCK)


def _pieces(deposit: SparseGrid, cad: SparseGrid, pore):
    """(lo, hi, origin, arrays) of every occupied region of blocks ``lo <= b < hi``, the arrays
    one voxel plane wider on its high sides."""
    occupied = (deposit.block != OUTSIDE) | (cad.block != OUTSIDE)
    shape = np.array(occupied.shape)
    for corner in np.argwhere(np.ones(-(-shape // PIECE_BLOCKS), bool)):
        lo = corner * PIECE_BLOCKS
        hi = np.minimum(lo + PIECE_BLOCKS, shape)
        if not occupied[lo[0]:hi[0], lo[1]:hi[1], lo[2]:hi[2]].any():
            continue
        # the shared plane: one voxel of the next blocks (outside the table: nothing to share)
        wide = np.minimum(hi + 1, shape)
        size = BLOCK * (hi - lo) + (wide - hi)
        dep = deposit.dense_sdf(lo, wide)[:size[0], :size[1], :size[2]]
        cad_sdf = cad.dense_sdf(lo, wide)[:size[0], :size[1], :size[2]]
        label = _labels_box(deposit, cad, pore, lo, wide)[:size[0], :size[1], :size[2]]
        yield lo, hi, deposit.index_to_world(BLOCK * lo), {"label": label, "deposit_sdf_mm": dep, "cad_sdf_mm": cad_sdf}


def _empty_vdb(name: str, deposit: SparseGrid):
    """An empty FloatGrid (background 0) on the deposit's lattice."""
    grid = openvdb.FloatGrid(0.0)
    grid.name = name
    grid.transform = voxel_transform(deposit.voxel, deposit.origin)
    return grid


def write_fields(out: Path, stem: str, deposit: SparseGrid, cad: SparseGrid, porosity) -> list[Path]:
    """Write the fields (module docstring); returns the paths written.

    The label and deviation grids of the ``.vdb`` are filled from the same pieces as the
    ``.vtm``, so each piece's labels and both SDFs are computed once."""
    from ..io.vtk_image import write_voxel_pieces, write_voxels

    pore = pore_voxels(deposit, porosity)
    # units from the arrays' names (mm), and "code" pointing at the codes' names for the label
    labels = {"label": LABEL_NAMES}
    written = []
    fields_vdb = _FieldGrids(deposit, cad)
    total = int(np.prod(deposit.block.shape, dtype=np.int64)) * BLOCK**3
    if total <= SINGLE_VTI_VOXELS:
        lo = np.zeros(3, np.int64)
        hi = np.array(deposit.block.shape, np.int64)
        arrays = {"label": _labels_box(deposit, cad, pore, lo, hi), "deposit_sdf_mm": deposit.dense_sdf(),
                  "cad_sdf_mm": cad.dense_sdf()}
        written += write_voxels(out / f"{stem}_compare.vti", deposit.origin, deposit.voxel, arrays, labels=labels)
        fields_vdb.add(lo, hi, arrays)
    else:
        written += write_voxel_pieces(out / f"{stem}_compare.vtm", deposit.voxel,
                                      fields_vdb.passing(_pieces(deposit, cad, pore)), labels=labels)
    written.append(fields_vdb.write(out / f"{stem}_compare.vdb"))
    return written


@nb.njit(cache=True, parallel=True)
def _label_and_deviation(labels, deposit_sdf, cad_sdf, band, label, deviation):
    """The label as float32 and the deviation (minus the deposit's SDF where the CAD's is
    within its band, else 0) over the outputs' extent (the inputs may reach further)."""
    nx, ny, nz = label.shape
    for i in nb.prange(nx):
        for j in range(ny):
            for k in range(nz):
                label[i, j, k] = labels[i, j, k]
                deviation[i, j, k] = -deposit_sdf[i, j, k] if abs(cad_sdf[i, j, k]) < band else np.float32(0.0)


class _FieldGrids:
    """deposit_sdf, cad_sdf (level sets), label and deviation_mm as OpenVDB grids, the last two
    filled piece by piece from the arrays written for VTK."""

    def __init__(self, deposit: SparseGrid, cad: SparseGrid):
        self.deposit, self.cad = deposit, cad
        self.label = _empty_vdb("label", deposit)
        self.label[GRID_UNIT_KEY] = "code"
        self.label["label_codes"] = LABEL_CODES_TEXT
        self.deviation = _empty_vdb("deviation_mm", deposit)
        self.deviation[GRID_UNIT_KEY] = UNITS["length_unit"]

    def add(self, lo: np.ndarray, hi: np.ndarray, arrays: dict) -> None:
        """The fields of blocks ``lo <= b < hi`` from ``arrays`` whose voxel 0 is block ``lo``'s
        (they may reach further, as the pieces' shared planes do)."""
        n = BLOCK * (np.asarray(hi) - np.asarray(lo))
        ijk = tuple(int(BLOCK * c) for c in lo)
        label = np.empty(n, np.float32)
        deviation = np.empty(n, np.float32)
        _label_and_deviation(arrays["label"], arrays["deposit_sdf_mm"], arrays["cad_sdf_mm"], np.float32(self.cad.band),
                             label, deviation)
        self.label.copyFromArray(label, ijk, 0.0)
        self.deviation.copyFromArray(deviation, ijk, 0.0)

    def passing(self, pieces):
        """``pieces`` (:func:`_pieces`) unchanged, each added to the grids on its way."""
        for lo, hi, origin, arrays in pieces:
            self.add(lo, hi, arrays)
            yield origin, arrays

    def write(self, path: Path) -> Path:
        dep_vdb, _ = to_openvdb(self.deposit, arrival=False)
        dep_vdb.name = "deposit_sdf"
        cad_vdb, _ = to_openvdb(self.cad, arrival=False)
        cad_vdb.name = "cad_sdf"
        self.label.prune(0.0)
        self.deviation.prune(0.0)
        meta = {"label_codes": LABEL_CODES_TEXT, **UNITS, "voxel_mm": float(self.deposit.voxel)}
        md = {k: metadata_value(k, v) for k, v in meta.items()}
        with atomic_path(path) as tmp:
            openvdb.write(str(tmp), grids=[dep_vdb, cad_vdb, self.label, self.deviation], metadata=md)
            stable_uuid(tmp)
        return path
