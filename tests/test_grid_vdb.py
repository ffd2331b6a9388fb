"""OpenVDB export/import of SparseGrid (checked with pyopenvdb and vdb_print) and surface meshes."""

import math
import re
import subprocess
from pathlib import Path

import numpy as np
import pytest

from dmdvox.errors import InputFileError
from dmdvox.grid import vdbio
from dmdvox.grid.analysis import volume
from dmdvox.grid.surface import surface_mesh
from dmdvox.grid.vdbio import read_vdb, write_vdb
from dmdvox.vdb import openvdb

from .conftest import require_tool
from .test_grid import assert_same_grid, field_grid, sphere


@pytest.fixture(scope="module")
def ball():
    grid, _, _ = field_grid(128, 0.1, sphere(5.0), meta={"profile": "parabola", "width": np.float32(1.5)})
    return grid


def test_round_trip_is_bit_exact(ball, tmp_path):
    path = tmp_path / "part.vdb"
    write_vdb(ball, path, {"source": Path("x.gcode"), "layers": np.int64(12), "closed": np.bool_(True),
                           "speeds": [1.0, 2.0]})
    assert [p.name for p in tmp_path.iterdir()] == ["part.vdb"]  # no temporary left behind
    back = read_vdb(path)
    assert_same_grid(ball, back)
    assert volume(back) == volume(ball)
    assert back.meta == {"profile": "parabola", "width": 1.5, "source": "x.gcode", "layers": 12, "closed": True,
                         "speeds": "[1.0, 2.0]", "arrival_unit": "s", "length_unit": "mm", "vdb_file": str(path)}


def test_file_says_its_units(ball, tmp_path):
    """The file's metadata says the arrival grid holds seconds and lengths are mm, whatever the
    caller's metadata claims; OpenVDB reads it without loading the grids."""
    path = tmp_path / "part.vdb"
    write_vdb(ball, path, {"arrival_unit": "min", "source": "x.gcode"})
    meta = openvdb.readMetadata(str(path))
    assert meta["arrival_unit"] == "s" and meta["length_unit"] == "mm" and meta["source"] == "x.gcode"
    # each grid says its own values' unit too
    assert openvdb.readGridMetadata(str(path), "arrival")["unit"] == "s"
    assert openvdb.readGridMetadata(str(path), "sdf")["unit"] == "mm"
    # and the arrival grid's values are those seconds: the grid's own times, unscaled
    arrival = openvdb.read(str(path), "arrival")
    dense = np.empty((128, 128, 128), np.float32)
    arrival.copyToArray(dense, (0, 0, 0))
    assert np.array_equal(dense, ball.dense_arrival())


def test_round_trip_through_several_slabs(ball, tmp_path, monkeypatch):
    monkeypatch.setattr(vdbio, "_SLAB_VOXELS", 3 * 512 * 16 * 16)
    write_vdb(ball, tmp_path / "a.vdb")
    assert_same_grid(ball, read_vdb(tmp_path / "a.vdb"))


def test_file_contents_seen_by_openvdb(ball, tmp_path):
    path = tmp_path / "part.vdb"
    write_vdb(ball, path, {})
    grids, meta = openvdb.readAll(str(path))
    by_name = {g.name: g for g in grids}
    sdf, arr = by_name["sdf"], by_name["arrival"]
    assert sdf.gridClass == openvdb.GridClass.LEVEL_SET
    assert sdf.background == np.float32(ball.band) and math.isinf(arr.background)
    assert sdf.activeVoxelCount() == ball.active_voxels
    assert sdf.transform.voxelSize() == (0.1, 0.1, 0.1)
    assert np.allclose(sdf.transform.indexToWorld((0, 0, 0)), ball.origin, atol=1e-12)
    assert meta["dmdvox_block_shape"] == ball.block_shape
    dense = np.empty((128, 128, 128), np.float32)
    sdf.copyToArray(dense, (0, 0, 0))
    assert np.array_equal(dense, ball.dense_sdf())  # interior flood-filled to -band
    arr.copyToArray(dense, (0, 0, 0))
    assert np.array_equal(dense, ball.dense_arrival())
    # per voxel in the band, the octant minimum on the deeper inside voxels of leaves
    leaf = ball.block[8, 8, 2]
    _, a8 = ball.decode_leaf(leaf)
    s8 = ball.dense_sdf((8, 8, 2), (9, 9, 3))
    deep = s8 == -np.float32(ball.band)
    assert np.array_equal(dense[64:72, 64:72, 16:24], a8)
    lx, ly, lz = np.nonzero(deep)
    assert deep.any()  # the leaf has voxels deeper than the band
    assert np.array_equal(a8[deep], ball.leaf_octant_arrival[leaf][lx >> 2, ly >> 2, lz >> 2])


def test_vdb_print_reads_the_file(ball, tmp_path):
    vdb_print = require_tool(("vdb_print",), "OpenVDB's vdb_print",
                             "scripts/setup.sh installs it (Debian package libopenvdb-tools)")
    path = tmp_path / "part.vdb"
    write_vdb(ball, path, {"profile": "parabola"})
    listing = subprocess.run([vdb_print, "-l", str(path)], capture_output=True, text=True, check=True).stdout
    assert "Name: sdf" in listing and "Name: arrival" in listing
    counts = re.findall(r"Number of active voxels:\s+([\d,]+)", listing)
    # every inside voxel has a finite arrival in the file, fine or octant minimum
    inside_voxels = int(np.unpackbits(ball.leaf_inside.view(np.uint8)).sum()) + 512 * ball.n_tile
    assert sorted(int(c.replace(",", "")) for c in counts) == sorted([ball.active_voxels, inside_voxels])
    assert "profile: parabola" in listing


def test_foreign_level_set_gets_a_shifted_table(tmp_path):
    ls = openvdb.createLevelSetSphere(radius=4.0, center=(1.0, -2.0, 0.5), voxelSize=0.1, halfWidth=3.0)
    ls.name = "surface"
    path = tmp_path / "foreign.vdb"
    openvdb.write(str(path), grids=[ls])
    grid = read_vdb(path)
    assert grid.active_voxels == ls.activeVoxelCount()
    assert volume(grid) == pytest.approx(4 / 3 * math.pi * 64, rel=3e-3)
    # index space shifted to blocks >= 1; world positions unchanged
    assert np.all(grid.leaf_coord >= 1) and np.all(grid.leaf_coord < np.array(grid.block_shape) - 1)
    centre = np.rint(grid.world_to_index([1.0, -2.0, 0.5])).astype(np.int64)
    assert grid.value_at_index(centre[None])[0] < 0
    assert np.all(grid.arrival == 0.0)  # no arrival grid: material present from the start
    octs = grid.leaf_octant_arrival
    assert np.all((octs == 0.0) | np.isinf(octs)) and np.any(octs == 0.0)


def test_unreadable_files_name_the_file(tmp_path):
    missing = tmp_path / "nope.vdb"
    with pytest.raises(InputFileError, match="nope.vdb"):
        read_vdb(missing)
    garbage = tmp_path / "garbage.vdb"
    garbage.write_bytes(b"not a vdb file at all" * 20)
    with pytest.raises(InputFileError, match="garbage.vdb"):
        read_vdb(garbage)
    no_levelset = tmp_path / "fog.vdb"
    fog = openvdb.FloatGrid()
    fog.name = "density"
    openvdb.write(str(no_levelset), grids=[fog])
    with pytest.raises(InputFileError, match="fog.vdb.*level set"):
        read_vdb(no_levelset)
    thin = tmp_path / "thin.vdb"
    openvdb.write(str(thin), grids=[openvdb.createLevelSetSphere(radius=1.0, voxelSize=0.1, halfWidth=2.0)])
    with pytest.raises(InputFileError, match="thin.vdb.*3 voxels"):
        read_vdb(thin)


# ---- surface mesh ---------------------------------------------------------------------------------

def test_sphere_mesh_is_closed_outward_and_accurate():
    R = 5.0
    grid, _, _ = field_grid(128, 0.1, sphere(R), centre_offset=0.037)
    vertices, triangles = surface_mesh(grid)
    assert vertices.dtype == np.float64 and triangles.dtype == np.int64
    directed = np.concatenate([triangles[:, [0, 1]], triangles[:, [1, 2]], triangles[:, [2, 0]]])
    # closed and consistently oriented: each directed edge once, its reverse exactly once
    _, counts = np.unique(directed, axis=0, return_counts=True)
    assert np.all(counts == 1)
    undirected, counts = np.unique(np.sort(directed, axis=1), axis=0, return_counts=True)
    assert np.all(counts == 2)
    V, E, F = vertices.shape[0], undirected.shape[0], triangles.shape[0]
    assert V - E + F == 2  # a sphere
    a, b, c = (vertices[triangles[:, q]] for q in range(3))
    signed = np.einsum("ij,ij->i", a, np.cross(b, c)).sum() / 6
    assert signed > 0 and signed == pytest.approx(4 / 3 * math.pi * R**3, rel=0.01)
    normals = np.cross(b - a, c - a)
    assert np.all(np.einsum("ij,ij->i", normals, (a + b + c) / 3) > 0)
    assert np.abs(np.linalg.norm(vertices, axis=1) - R).max() < 0.01  # the sphere stays at 0


def test_mesh_of_an_empty_grid(tmp_path):
    grid, _, _ = field_grid(16, 0.1, lambda X, Y, Z: X * 0 + 1.0)
    vertices, triangles = surface_mesh(grid)
    assert vertices.shape == (0, 3) and triangles.shape == (0, 3)
