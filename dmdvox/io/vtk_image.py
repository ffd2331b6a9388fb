"""Voxel volumes as compressed VTK XML ImageData (``.vti``), split into a ``.vtm`` when large.

Arrays are given in numpy ``[i, j, k]`` order (shape ``(nx, ny, nz)``, optionally with a
trailing component axis ``(nx, ny, nz, c)``) and stored as *point* data: every voxel centre is
one VTK point, so ``origin`` is the world position of the centre of voxel ``(0, 0, 0)`` and the
spacing is the voxel size on all three axes. VTK stores points x-fastest, which is numpy's
Fortran order of the ``[i, j, k]`` array; the conversion is done here, once per piece.

A volume with more voxels than ``max_voxels_per_piece`` is cut along z into slabs
``stem_000.vti``, ``stem_001.vti``, ... that each repeat the last z plane of the slab below,
so the cells between slabs exist and ParaView draws no gap; ``stem.vtm`` lists the slabs by
relative file name and opens them as one multiblock data set. Every file is LZ4 compressed
(appended raw binary, 64-bit headers) and written atomically (:func:`..io.mesh.write_vtk_xml`).
Each piece says its arrays' units, and a label array's codes and names, in its field data
(:func:`..io.mesh.add_field_data`).
"""

from __future__ import annotations

import math
import os
import re
from pathlib import Path
from xml.sax.saxutils import quoteattr

import numpy as np

from .atomic import write_text
from .mesh import add_field_data, write_vtk_xml

_SUFFIXES = (".vti", ".vtm", "")


def write_voxels(
    path: str | os.PathLike,
    origin,
    voxel: float,
    point_arrays: dict[str, np.ndarray],
    max_voxels_per_piece: int = 50_000_000,
    units: dict | None = None,
    labels: dict | None = None,
    field_data: dict | None = None,
) -> list[Path]:
    """Write voxel arrays as one ``.vti`` or, when too large, ``.vti`` slabs plus a ``.vtm``.

    ``path`` may end in ``.vti``, ``.vtm`` or have no suffix; the single-file result is
    ``<stem>.vti`` and the split result is ``<stem>.vtm`` with ``<stem>_NNN.vti`` beside it.
    Arrays must all have the same ``(nx, ny, nz)`` leading shape; supported dtypes are bool
    (stored as uint8), every integer type, float32 and float64. Pieces hold at most
    ``max_voxels_per_piece`` voxels, except that a slab always has at least two z planes.

    Stale outputs of an earlier call with the same stem (slabs beyond the new count, or a
    ``.vtm`` when the new result is a single ``.vti``) are removed so the folder never mixes
    two runs. Returns the written paths, the ``.vtm`` first when there is one.

    ``units`` (array name -> unit, beyond those the names' suffixes give), ``labels`` (label
    array name -> ``{code: name}``) and ``field_data`` go into every piece's field data.
    """
    path = Path(path)
    if path.suffix.lower() not in _SUFFIXES:
        raise ValueError(f"{path}: voxel output must end in .vti or .vtm (or have no suffix)")
    origin = np.asarray(origin, np.float64).reshape(-1)
    if origin.shape != (3,) or not np.all(np.isfinite(origin)):
        raise ValueError(f"origin must be 3 finite numbers, got {origin.tolist()}")
    voxel = float(voxel)
    if not (math.isfinite(voxel) and voxel > 0):
        raise ValueError(f"voxel size must be a positive number, got {voxel}")
    if int(max_voxels_per_piece) < 1:
        raise ValueError(f"max_voxels_per_piece must be positive, got {max_voxels_per_piece}")
    arrays, shape = _check_arrays(point_arrays)
    nx, ny, nz = shape

    folder = path.parent
    stem = path.stem if path.suffix else path.name
    single = folder / f"{stem}.vti"
    vtm = folder / f"{stem}.vtm"

    slabs = _z_slabs(nx, ny, nz, int(max_voxels_per_piece))
    described = dict(units=units, labels=labels, field_data=field_data)
    if len(slabs) == 1:
        _write_piece(single, origin, voxel, arrays, 0, nz - 1, described)
        _remove_stale(folder, stem, written=(), leftover=vtm)
        return [single]

    width = max(3, len(str(len(slabs) - 1)))
    pieces = []
    for index, (z0, z1) in enumerate(slabs):
        piece = folder / f"{stem}_{index:0{width}d}.vti"
        _write_piece(piece, origin, voxel, arrays, z0, z1, described)
        pieces.append(piece)
    # the .vtm goes last: whenever it exists, every slab it names exists too
    write_text(vtm, _vtm_text([p.name for p in pieces]))
    _remove_stale(folder, stem, written={p.name for p in pieces}, leftover=single)
    return [vtm, *pieces]


def write_voxel_pieces(path: str | os.PathLike, voxel: float, pieces, units: dict | None = None,
                       labels: dict | None = None, field_data: dict | None = None) -> list[Path]:
    """Write separate voxel boxes as ``<stem>_NNN.vti`` pieces listed by ``<stem>.vtm`` (a sparse
    field: blocks of image data covering only the occupied regions). ``pieces`` yields
    ``(origin, point_arrays)`` per box, each as :func:`write_voxels` takes them; boxes should
    share their boundary planes with their neighbours, so that ParaView draws no gap. Returns
    the ``.vtm`` first, then the pieces."""
    path = Path(path)
    folder = path.parent
    stem = path.stem if path.suffix else path.name
    described = dict(units=units, labels=labels, field_data=field_data)
    written = []
    for index, (origin, point_arrays) in enumerate(pieces):
        arrays, shape = _check_arrays(point_arrays)
        piece = folder / f"{stem}_{index:05d}.vti"
        _write_piece(piece, np.asarray(origin, np.float64), float(voxel), arrays, 0, shape[2] - 1, described)
        written.append(piece)
    vtm = folder / f"{stem}.vtm"
    write_text(vtm, _vtm_text([p.name for p in written]))
    _remove_stale(folder, stem, written={p.name for p in written}, leftover=folder / f"{stem}.vti")
    return [vtm, *written]


def _check_arrays(point_arrays: dict) -> tuple[dict[str, np.ndarray], tuple[int, int, int]]:
    if not point_arrays:
        raise ValueError("write_voxels needs at least one point array")
    arrays: dict[str, np.ndarray] = {}
    shape = None
    for name, values in point_arrays.items():
        a = np.asarray(values)
        if a.ndim not in (3, 4) or (a.ndim == 4 and a.shape[3] < 1):
            raise ValueError(f"array {name!r} must have shape (nx, ny, nz) or (nx, ny, nz, c), got {a.shape}")
        if shape is None:
            shape = a.shape[:3]
        elif a.shape[:3] != shape:
            raise ValueError(f"array {name!r} has shape {a.shape[:3]}, expected {shape} like the others")
        if a.dtype == np.bool_:
            a = a.view(np.uint8)
        elif not (np.issubdtype(a.dtype, np.integer) or a.dtype in (np.float32, np.float64)):
            raise ValueError(f"array {name!r} has dtype {a.dtype}; use bool, an integer type, float32 or float64")
        arrays[str(name)] = a
    if min(shape) < 1:
        raise ValueError(f"voxel arrays are empty (shape {shape})")
    return arrays, tuple(int(n) for n in shape)


def _z_slabs(nx: int, ny: int, nz: int, max_voxels: int) -> list[tuple[int, int]]:
    """Inclusive z index ranges; neighbours share their boundary plane."""
    if nx * ny * nz <= max_voxels or nz <= 2:
        return [(0, nz - 1)]
    planes = max(2, max_voxels // (nx * ny))
    step = planes - 1
    count = math.ceil((nz - 1) / step)
    return [(s * step, min((s + 1) * step, nz - 1)) for s in range(count)]


def _write_piece(target: Path, origin: np.ndarray, voxel: float, arrays: dict, z0: int, z1: int,
                 described: dict) -> None:
    import vtk
    from vtk.util.numpy_support import numpy_to_vtk

    first = next(iter(arrays.values()))
    nx, ny = first.shape[:2]
    image = vtk.vtkImageData()
    image.SetDimensions(nx, ny, z1 - z0 + 1)
    image.SetOrigin(origin[0], origin[1], origin[2] + z0 * voxel)
    image.SetSpacing(voxel, voxel, voxel)
    keep = []  # shallow VTK arrays borrow these buffers until the writer is done
    for name, a in arrays.items():
        slab = a[:, :, z0 : z1 + 1]
        if a.ndim == 3:
            flat = np.ascontiguousarray(slab.ravel(order="F"))
        else:  # (nx, ny, nz, c) -> (points, c) with x fastest
            flat = np.ascontiguousarray(slab.transpose(2, 1, 0, 3).reshape(-1, a.shape[3]))
        keep.append(flat)
        va = numpy_to_vtk(flat, deep=False)
        va.SetName(name)
        image.GetPointData().AddArray(va)
    image.GetPointData().SetActiveScalars(next(iter(arrays)))
    add_field_data(image, list(arrays), **described)
    write_vtk_xml(vtk.vtkXMLImageDataWriter(), image, target)
    del keep


def _vtm_text(names: list[str]) -> str:
    rows = "".join(
        f"    <DataSet index={quoteattr(str(i))} name={quoteattr(Path(n).stem)} file={quoteattr(n)}/>\n"
        for i, n in enumerate(names)
    )
    return (
        '<?xml version="1.0"?>\n'
        '<VTKFile type="vtkMultiBlockDataSet" version="1.0" byte_order="LittleEndian" header_type="UInt64">\n'
        "  <vtkMultiBlockDataSet>\n"
        f"{rows}"
        "  </vtkMultiBlockDataSet>\n"
        "</VTKFile>\n"
    )


def _remove_stale(folder: Path, stem: str, written, leftover: Path) -> None:
    """Delete ``stem_NNN.vti`` slabs not in ``written``, and ``leftover`` (the other layout)."""
    pattern = re.compile(re.escape(stem) + r"_\d{3,}\.vti")
    try:
        entries = list(folder.iterdir())
    except OSError:
        return
    for entry in entries:
        if pattern.fullmatch(entry.name) and entry.name not in written:
            entry.unlink(missing_ok=True)
    leftover.unlink(missing_ok=True)
