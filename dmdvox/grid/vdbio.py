"""OpenVDB export and import of a :class:`SparseGrid`.

A file holds two FloatGrids sharing the grid's transform (linear, voxel size ``voxel``,
translation ``origin``: voxel centres on integer index coordinates):

- ``sdf``: a level set (gridClass LEVEL_SET, background = band) whose active voxels are
  exactly the grid's active voxels with their float32 values; inactive space reads as +band
  outside and -band inside (signed flood fill).
- ``arrival``: arrival time in seconds (background +inf) on every inside voxel: its own value
  for active inside voxels of a leaf, its octant's minimum for the other inside voxels of a
  leaf and every voxel of an inside tile (the grid keeps no finer value there).

Both directions move dense arrays of whole blocks through ``copyFromArray`` / ``copyToArray``
(hundreds of M voxels/s, bit exact) instead of per-voxel Python. Writing follows the part, not
its box: each (x, y) column of blocks gives its runs of consecutive leaves (for ``sdf``) or of
blocks not outside (for ``arrival``) as one (8, 8, 8 n) array each, decoded a bounded batch at a
time; inside tiles are left to ``signedFloodFill``, which makes every inactive region enclosed
by negative values -band, and the leaves' inactive inside voxels go in as +band, which OpenVDB
keeps inactive, for the same fill (a solid 100 mm block: 78 k leaves in 31 k runs instead of
504 M voxels of slabs). Reading copies x-slabs of the file's active box and feeds them to
:class:`GridBuilder`, so a round trip gives back the same active values, inside masks and
per-voxel arrival times; leaf and tile octant minima are recomputed from the voxel values,
which reproduces them (each octant's minimum is among the values written). A leaf with no
active voxel cannot be represented by a level set and is lost.

File-level metadata carries the caller's provenance, the units (``arrival_unit`` = ``s``: the
``arrival`` grid holds seconds from the program's start; ``length_unit`` = ``mm``: the
transform, the ``sdf`` values and the band), and each grid says its values' unit in its own
metadata too (``unit``: ``mm`` for ``sdf``, ``s`` for ``arrival``), for tools that show one grid
at a time; plus ``dmdvox_block_shape`` so that a round trip keeps the block table; files from
elsewhere get a table around their active voxels with one block of margin (their index space
shifted to start at block 1 if needed).
"""

from __future__ import annotations

import hashlib
import json
import os
import uuid
from contextlib import contextmanager
from pathlib import Path

import numba as nb
import numpy as np

from ..errors import InputFileError
from ..io.atomic import atomic_path
from ..vdb import openvdb
from .build import GridBuilder
from .sparse import BLOCK, BLOCK_VOXELS, OUTSIDE, SparseGrid, block_values_into

SDF_NAME = "sdf"
ARRIVAL_NAME = "arrival"
_BLOCK_SHAPE_KEY = "dmdvox_block_shape"
# what the numbers in the file mean; written whatever the caller's metadata says
UNITS = {"arrival_unit": "s", "length_unit": "mm"}
GRID_UNIT_KEY = "unit"  # a grid's own metadata: the unit of its values
_SLAB_VOXELS = 1 << 24  # 64 MB of float32 per dense slab


def voxel_transform(voxel: float, origin: np.ndarray):
    # scale-then-translate keeps voxelSize() exact; a 4x4 matrix input rounds it
    t = openvdb.createLinearTransform(voxelSize=float(voxel))
    t.translate(tuple(float(c) for c in origin))
    return t


def metadata_value(key: str, value):
    """A value pyopenvdb accepts (str, bool, int, float, 3-tuples); containers become JSON."""
    if isinstance(value, np.generic):
        value = value.item()
    if isinstance(value, (bool, int, float, str)):
        return value
    if isinstance(value, os.PathLike):
        return os.fspath(value)
    if isinstance(value, (list, tuple, dict, np.ndarray)):
        return json.dumps(np.asarray(value).tolist() if isinstance(value, np.ndarray) else value, default=str)
    raise TypeError(f"metadata {key!r}: cannot store a {type(value).__name__} in a .vdb file")


def _slabs(lo: np.ndarray, hi: np.ndarray):
    """x-ranges of blocks whose dense slab over [lo, hi) stays under _SLAB_VOXELS."""
    per_x = 512 * int(hi[1] - lo[1]) * int(hi[2] - lo[2])
    step = max(1, _SLAB_VOXELS // per_x)
    for x0 in range(int(lo[0]), int(hi[0]), step):
        yield x0, min(int(hi[0]), x0 + step)


@nb.njit(cache=True)
def _column_runs(block, leaves_only):
    """Runs ``(bx, by, bz0, bz1)`` of consecutive blocks along z: leaves (``leaves_only``), or
    every block that is not outside. Counted first, so the list is the size of the runs, not of
    the block table."""
    nx, ny, nz = block.shape
    m = 0
    for write in (False, True):
        if write:
            runs = np.empty((m, 4), np.int64)
            m = 0
        for bx in range(nx):
            for by in range(ny):
                bz = 0
                while bz < nz:
                    if not ((block[bx, by, bz] >= 0) if leaves_only else (block[bx, by, bz] != OUTSIDE)):
                        bz += 1
                        continue
                    start = bz
                    bz += 1
                    while bz < nz and ((block[bx, by, bz] >= 0) if leaves_only else (block[bx, by, bz] != OUTSIDE)):
                        bz += 1
                    if write:
                        runs[m, 0], runs[m, 1], runs[m, 2], runs[m, 3] = bx, by, start, bz
                    m += 1
    return runs


@nb.njit(cache=True, parallel=True)
def _run_values(block, runs, offsets, leaf_active, leaf_inside, sdf_offset, sdf, arr_offset, arrival,
                leaf_octant_arrival, tile_arrival, band, want_sdf, out):
    """Each run's values as a C-ordered (8, 8, 8 n) array at ``out[offsets[r]:]``; for the sdf the
    inactive inside voxels read +band (the background, filled in by ``signedFloodFill``)."""
    for r in nb.prange(runs.shape[0]):
        bx, by, z0, z1 = runs[r, 0], runs[r, 1], runs[r, 2], runs[r, 3]
        dst = out[offsets[r]:offsets[r + 1]].reshape((BLOCK, BLOCK, BLOCK * (z1 - z0)))
        for q in range(z1 - z0):
            block_values_into(block[bx, by, z0 + q], leaf_active, leaf_inside, sdf_offset, sdf, arr_offset, arrival,
                              leaf_octant_arrival, tile_arrival, band, want_sdf,
                              dst[:, :, BLOCK * q:BLOCK * (q + 1)])
        if want_sdf:
            flat = out[offsets[r]:offsets[r + 1]]
            for v in range(flat.shape[0]):
                if flat[v] == -band:
                    flat[v] = band


def _copy_runs(target, grid: SparseGrid, want_sdf: bool) -> None:
    """Write the grid's sdf (its leaves) or arrival (every block not outside) into ``target``."""
    runs = _column_runs(grid.block, want_sdf)
    ends = np.cumsum(BLOCK_VOXELS * (runs[:, 3] - runs[:, 2]))
    first = 0
    while first < runs.shape[0]:
        base = ends[first - 1] if first else 0
        last = max(first + 1, int(np.searchsorted(ends, base + _SLAB_VOXELS, side="right")))
        offsets = np.concatenate(([0], ends[first:last] - base)).astype(np.int64)
        out = np.empty(int(offsets[-1]), np.float32)
        _run_values(grid.block, runs[first:last], offsets, *grid._packed(), grid.tile_arrival, np.float32(grid.band),
                    want_sdf, out)
        for r in range(last - first):
            bx, by, z0, z1 = (int(c) for c in runs[first + r])
            target.copyFromArray(out[offsets[r]:offsets[r + 1]].reshape(BLOCK, BLOCK, BLOCK * (z1 - z0)),
                                 (BLOCK * bx, BLOCK * by, BLOCK * z0), 0.0)
        first = last


def to_openvdb(grid: SparseGrid, world: bool = True, arrival: bool = True):
    """The grid as OpenVDB FloatGrids ``(sdf, arrival)``.

    ``world=False`` gives an identity transform (index space); ``arrival=False`` leaves the
    arrival grid empty for callers that only need the level set. Inside :func:`reusing`, each
    grid's level set is built once and every later call gets a copy of it (the caller may rename
    or change its own).
    """
    if _reused is None:
        return build_openvdb(grid, world, arrival)
    kept = _reused.get(id(grid))
    if kept is None or kept[0] is not grid:
        sdf_vdb, arr_vdb = build_openvdb(grid, True, arrival)
        kept = _reused[id(grid)] = (grid, sdf_vdb.deepCopy(), arr_vdb.deepCopy() if arrival else None)
        if world:
            return sdf_vdb, arr_vdb
    _, sdf_kept, arr_kept = kept
    sdf_vdb = sdf_kept.deepCopy()
    # a fresh transform: Transform.deepCopy() turns the map affine and rounds voxelSize()
    sdf_vdb.transform = _transform(grid, world)
    if arrival and arr_kept is None:
        arr_vdb = build_openvdb(grid, world, True, sdf=False)[1]
        _reused[id(grid)] = (grid, sdf_kept, arr_vdb.deepCopy())
    elif arrival:
        arr_vdb = arr_kept.deepCopy()
        arr_vdb.transform = _transform(grid, world)
    else:
        arr_vdb = _arrival_grid(grid, world)
    return sdf_vdb, arr_vdb


_reused: dict[int, tuple] | None = None  # inside reusing(): id(grid) -> (grid, its sdf, its arrival or None)


@contextmanager
def reusing(kept: dict | None = None):
    """Within: :func:`to_openvdb` converts each grid once (the steps that write a deposit's
    file, mesh its surface and write the comparison's fields share one conversion), keeping the
    conversions in ``kept`` (a caller's store, to share them with later calls; default: dropped
    on leaving). Nested, the outermost store serves."""
    global _reused
    outer = _reused
    if outer is None:
        _reused = {} if kept is None else kept
    try:
        yield
    finally:
        if outer is None:
            _reused = None


def _transform(grid: SparseGrid, world: bool):
    return voxel_transform(grid.voxel, grid.origin) if world else voxel_transform(1.0, np.zeros(3))


def _arrival_grid(grid: SparseGrid, world: bool):
    arr_vdb = openvdb.FloatGrid(float("inf"))
    arr_vdb.name = ARRIVAL_NAME
    arr_vdb.transform = _transform(grid, world)
    arr_vdb[GRID_UNIT_KEY] = UNITS["arrival_unit"]
    return arr_vdb


def build_openvdb(grid: SparseGrid, world: bool = True, arrival: bool = True, sdf: bool = True):
    """The conversion itself (:func:`to_openvdb`, whatever is kept); ``sdf=False`` leaves the
    level set empty."""
    band = np.float32(grid.band)
    sdf_vdb = openvdb.FloatGrid(float(band))
    sdf_vdb.name = SDF_NAME
    sdf_vdb.gridClass = openvdb.GridClass.LEVEL_SET
    sdf_vdb.transform = _transform(grid, world)
    sdf_vdb[GRID_UNIT_KEY] = UNITS["length_unit"]
    arr_vdb = _arrival_grid(grid, world)
    if sdf:
        _copy_runs(sdf_vdb, grid, want_sdf=True)
    if arrival:
        _copy_runs(arr_vdb, grid, want_sdf=False)
    if sdf:
        sdf_vdb.signedFloodFill()
    return sdf_vdb, arr_vdb


def write_vdb(grid: SparseGrid, path: str | os.PathLike, metadata: dict | None = None) -> Path:
    """Write ``grid`` as an OpenVDB file (grids ``sdf`` and ``arrival``), atomically.

    File metadata: ``grid.meta`` updated with ``metadata`` and :data:`UNITS`; numpy scalars
    become Python scalars, containers JSON strings.
    """
    merged = {**grid.meta, **(metadata or {}), **UNITS}
    md = {str(k): metadata_value(str(k), v) for k, v in merged.items()}
    md[_BLOCK_SHAPE_KEY] = tuple(int(n) for n in grid.block.shape)
    sdf_vdb, arr_vdb = to_openvdb(grid)
    with atomic_path(path) as tmp:
        openvdb.write(str(tmp), grids=[sdf_vdb, arr_vdb], metadata=md)
        stable_uuid(tmp)
    return Path(path)


# OpenVDB file header: magic (8 bytes), file version, library major, minor (4 each), "has grid
# offsets" (1), then the file's UUID as 36 ASCII characters.
_UUID_AT = 21
_UUID_LEN = 36
_VDB_MAGIC = 0x56444220


def stable_uuid(path: Path) -> None:
    """Replace the random UUID OpenVDB writes with one derived from the file's content, so the
    same grid gives the same bytes (reproducible results, diffable outputs). The file is hashed
    in chunks and patched in place: a solid part's file is hundreds of MB."""
    digest = hashlib.sha256()
    with open(path, "r+b") as f:
        head = f.read(_UUID_AT + _UUID_LEN)
        if len(head) < _UUID_AT + _UUID_LEN or int.from_bytes(head[:8], "little") != _VDB_MAGIC:
            raise OSError(f"{path}: unexpected OpenVDB header; cannot make the file reproducible")
        digest.update(head[:_UUID_AT])
        for chunk in iter(lambda: f.read(1 << 22), b""):
            digest.update(chunk)
        f.seek(_UUID_AT)
        f.write(str(uuid.UUID(bytes=digest.digest()[:16], version=4)).encode("ascii"))


def _uniform_transform(g, path) -> tuple[float, np.ndarray]:
    t = g.transform
    origin = np.array(t.indexToWorld((0, 0, 0)), np.float64)
    steps = np.array([t.indexToWorld(e) for e in ((1, 0, 0), (0, 1, 0), (0, 0, 1))], np.float64) - origin
    # voxelSize() is the stored scale; differences of indexToWorld carry rounding from origin
    voxel = float(t.voxelSize()[0])
    if not (voxel > 0 and np.allclose(steps, voxel * np.eye(3), rtol=1e-9, atol=1e-9 * voxel)):
        raise InputFileError(f"{path}: grid {g.name!r} does not have an axis-aligned uniform voxel transform")
    return voxel, origin


def read_vdb(path: str | os.PathLike) -> SparseGrid:
    """Read a file written by :func:`write_vdb` (or any float level set) into a SparseGrid.

    Without an ``arrival`` grid, inside voxels get arrival 0 (material present from the
    start). ``meta`` holds the file metadata plus ``vdb_file``.
    """
    path = Path(path)
    try:
        grids, file_meta = openvdb.readAll(str(path))
    except (OSError, RuntimeError, ValueError, KeyError) as exc:
        raise InputFileError(f"{path}: cannot read OpenVDB file ({exc})") from exc
    floats = [g for g in grids if isinstance(g, openvdb.FloatGrid)]
    by_name = {g.name: g for g in floats}
    sdf_vdb = by_name.get(SDF_NAME) or next((g for g in floats if g.gridClass == openvdb.GridClass.LEVEL_SET), None)
    if sdf_vdb is None:
        raise InputFileError(f"{path}: no float level set grid (expected a grid named {SDF_NAME!r})")
    arr_vdb = by_name.get(ARRIVAL_NAME)
    voxel, origin = _uniform_transform(sdf_vdb, path)
    if arr_vdb is not None:
        arr_voxel, arr_origin = _uniform_transform(arr_vdb, path)
        same = np.isclose(arr_voxel, voxel, rtol=1e-12, atol=0) and np.allclose(arr_origin, origin, rtol=0, atol=1e-9 * voxel)
        if not same:
            raise InputFileError(f"{path}: grids {SDF_NAME!r} and {ARRIVAL_NAME!r} have different transforms")
    band = float(sdf_vdb.background)
    if not band >= 3.0 * voxel * (1 - 1e-6):
        raise InputFileError(
            f"{path}: level set background {band} is not a narrow band of at least 3 voxels ({3 * voxel} mm)"
        )

    meta = {k: v for k, v in file_meta.items() if k != _BLOCK_SHAPE_KEY}
    meta["vdb_file"] = str(path)
    stored_shape = file_meta.get(_BLOCK_SHAPE_KEY)
    (imin, jmin, kmin), (imax, jmax, kmax) = sdf_vdb.evalActiveVoxelBoundingBox()
    empty = sdf_vdb.activeVoxelCount() == 0
    vmin = np.array([imin, jmin, kmin], np.int64)
    vmax = np.array([imax, jmax, kmax], np.int64)
    if stored_shape is not None and len(stored_shape) == 3 and (
        empty or (vmin.min() >= 0 and np.all(vmax < 8 * np.asarray(stored_shape)))
    ):
        shift = np.zeros(3, np.int64)
        block_shape = tuple(int(n) for n in stored_shape)
    elif empty:
        shift = np.zeros(3, np.int64)
        block_shape = (1, 1, 1)
    else:
        # one block of outside margin on each side keeps the table's outer layer exterior
        shift = 8 * (np.floor_divide(vmin, 8) - 1)
        block_shape = tuple(int(n) for n in (np.floor_divide(vmax - shift, 8) + 2))
    builder = GridBuilder(voxel, origin + voxel * shift, block_shape, band)
    if not empty:
        lo = np.floor_divide(vmin - shift, 8)
        hi = np.floor_divide(vmax - shift, 8) + 1
        ny, nz = int(hi[1] - lo[1]), int(hi[2] - lo[2])
        for x0, x1 in _slabs(lo, hi):
            shape = (8 * (x1 - x0), 8 * ny, 8 * nz)
            ijk = tuple(int(c) for c in (8 * np.array([x0, lo[1], lo[2]]) + shift))
            sdf = np.empty(shape, np.float32)
            sdf_vdb.copyToArray(sdf, ijk)
            arrival = np.empty(shape, np.float32)
            if arr_vdb is not None:
                arr_vdb.copyToArray(arrival, ijk)
            else:
                arrival[:] = np.where(sdf < 0, np.float32(0.0), np.float32(np.inf))
            builder.add_dense(sdf, arrival, (x0, lo[1], lo[2]))
    return builder.finish(meta)
