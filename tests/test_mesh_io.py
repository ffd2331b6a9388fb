"""Mesh writers round-trip through an independent reader (pyvista/vtk or a parser here)."""

import struct

import numpy as np
import pytest
import pyvista as pv

from dmdvox.errors import InputFileError
from dmdvox.io.mesh import array_unit, read_stl, write_ply, write_stl, write_vtp


@pytest.fixture(scope="module")
def mesh():
    """A closed triangulated sphere of radius 2 mm off the origin, 960 triangles."""
    s = pv.Sphere(radius=2.0, center=(10.0, -3.5, 0.25), theta_resolution=24, phi_resolution=22).triangulate()
    s = s.clean()
    tris = s.faces.reshape(-1, 4)[:, 1:].astype(np.int64)
    return np.asarray(s.points, np.float64), tris


def closed_volume(v, t):
    a, b, c = v[t[:, 0]], v[t[:, 1]], v[t[:, 2]]
    return np.einsum("ij,ij->i", a, np.cross(b, c)).sum() / 6


@pytest.mark.parametrize("binary", [True, False])
def test_stl_round_trip(mesh, tmp_path, binary):
    v, t = mesh
    path = tmp_path / "m.stl"
    write_stl(path, v, t, binary=binary)
    if binary:
        assert path.stat().st_size == 84 + 50 * t.shape[0]
    back_v, back_t = read_stl(path)
    assert back_v.dtype == np.float64 and back_t.dtype == np.int64
    assert back_v.shape == v.shape and back_t.shape == t.shape  # welded back to shared vertices
    # same triangles in the same order with the same winding, to float32 precision
    assert np.allclose(back_v[back_t], v[t], rtol=0, atol=1e-5)
    assert closed_volume(back_v, back_t) == pytest.approx(closed_volume(v, t), rel=1e-6)
    ref = pv.read(path)
    assert ref.n_cells == t.shape[0]
    assert ref.volume == pytest.approx(closed_volume(v, t), rel=1e-5)


def test_stl_facet_normals_are_outward_unit_vectors(mesh, tmp_path):
    v, t = mesh
    write_stl(tmp_path / "m.stl", v, t)
    record = np.dtype([("n", "<f4", 3), ("v", "<f4", (3, 3)), ("a", "<u2")])
    rec = np.frombuffer((tmp_path / "m.stl").read_bytes(), record, offset=84)
    assert np.allclose(np.linalg.norm(rec["n"], axis=1), 1.0, atol=1e-6)
    outward = rec["v"].mean(axis=1) - np.array([10.0, -3.5, 0.25])
    assert np.all(np.einsum("ij,ij->i", rec["n"], outward) > 0)


def parse_ply(data: bytes):
    """A minimal reader for the binary little-endian layout write_ply produces."""
    end = data.index(b"end_header\n") + len(b"end_header\n")
    header = data[:end].decode("ascii").splitlines()
    assert header[:2] == ["ply", "format binary_little_endian 1.0"]
    n_v = int(next(line for line in header if line.startswith("element vertex")).split()[-1])
    n_f = int(next(line for line in header if line.startswith("element face")).split()[-1])
    v = np.frombuffer(data, "<f8", 3 * n_v, end).reshape(-1, 3)
    faces = np.frombuffer(data, np.dtype([("n", "u1"), ("i", "<i4", 3)]), n_f, end + 24 * n_v)
    assert end + 24 * n_v + 13 * n_f == len(data)
    assert np.all(faces["n"] == 3)
    return v, faces["i"]


def test_ply_round_trip(mesh, tmp_path):
    v, t = mesh
    write_ply(tmp_path / "m.ply", v, t)
    pv_, pt = parse_ply((tmp_path / "m.ply").read_bytes())
    assert np.array_equal(pv_, v) and np.array_equal(pt, t)
    ref = pv.read(tmp_path / "m.ply")
    assert np.array_equal(np.asarray(ref.points, np.float64), v)
    assert np.array_equal(ref.faces.reshape(-1, 4)[:, 1:], t)


def test_vtp_round_trip_with_arrays(mesh, tmp_path):
    v, t = mesh
    path = tmp_path / "m.vtp"
    dist = np.linalg.norm(v - [10.0, -3.5, 0.25], axis=1).astype(np.float32)
    layer = np.arange(t.shape[0], dtype=np.int32) % 7
    write_vtp(path, v, t, point_arrays={"radius": dist}, cell_arrays={"layer": layer, "hot": layer > 3})
    assert b'compressor="vtkLZ4DataCompressor"' in path.read_bytes()[:400]
    ref = pv.read(path)
    assert np.array_equal(np.asarray(ref.points), v)
    assert np.array_equal(ref.faces.reshape(-1, 4)[:, 1:], t)
    assert np.array_equal(ref.point_data["radius"], dist)
    assert np.array_equal(ref.cell_data["layer"], layer)
    assert np.array_equal(ref.cell_data["hot"], (layer > 3).astype(np.uint8))
    with pytest.raises(ValueError, match="rows"):
        write_vtp(tmp_path / "bad.vtp", v, t, point_arrays={"x": layer})
    assert not (tmp_path / "bad.vtp").exists()


def test_writers_are_atomic(mesh, tmp_path):
    v, t = mesh
    for name, write in (("a.stl", write_stl), ("a.ply", write_ply), ("a.vtp", write_vtp)):
        write(tmp_path / name, v, t)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["a.ply", "a.stl", "a.vtp"]


def test_read_stl_rejects_bad_files(tmp_path):
    cases = {
        "empty.stl": b"",
        "blank.stl": b"   \n",
        "short.stl": b"\0" * 50,
        "zero.stl": b"\0" * 80 + struct.pack("<I", 0),
        "truncated.stl": b"\0" * 80 + struct.pack("<I", 2) + b"\0" * 60,
        "nofacets.stl": b"solid x\nendsolid x\n",
        "halfascii.stl": b"solid x\nfacet normal 0 0 1\n outer loop\n  vertex 0 0 0\n  vertex 1 0 0\n",
        "nan.stl": b"\0" * 80 + struct.pack("<I12fH", 1, 0, 0, 1, 0, 0, 0, 1, 0, float("nan"), 0, 1, 0, 0),
    }
    for name, data in cases.items():
        (tmp_path / name).write_bytes(data)
        with pytest.raises(InputFileError, match=name):
            read_stl(tmp_path / name)
    with pytest.raises(InputFileError, match="missing.stl"):
        read_stl(tmp_path / "missing.stl")


def field_strings(data, name: str) -> list[str]:
    """A string array of a VTK object's field data, read with VTK's own reader objects."""
    array = data.GetFieldData().GetAbstractArray(name)
    assert array is not None, name
    return [array.GetValue(i) for i in range(array.GetNumberOfValues())]


def test_vtp_field_data_says_the_units(mesh, tmp_path):
    """Units from the arrays' name suffixes (or given), label codes with their names, extra
    entries as given; read back through VTK's XML reader."""
    import vtk
    from vtk.util.numpy_support import vtk_to_numpy

    v, t = mesh
    n, m = v.shape[0], t.shape[0]
    path = write_vtp(tmp_path / "m.vtp", v, t,
                     point_arrays={"arrival_s": np.zeros(n), "deviation_mm": np.zeros(n), "feed_mm_s": np.ones(n),
                                   "speed": np.ones(n)},
                     cell_arrays={"kind": np.zeros(m, np.uint8), "area_mm2": np.ones(m)},
                     units={"speed": "m/min"}, labels={"kind": {2: "void", 0: "outside", 1: "inside"}},
                     field_data={"deviation_sign": "+ = excess material", "voxel_mm": 0.25})
    reader = vtk.vtkXMLPolyDataReader()
    reader.SetFileName(str(path))
    reader.Update()
    data = reader.GetOutput()
    assert field_strings(data, "units") == ["arrival_s: s", "deviation_mm: mm", "feed_mm_s: mm/s", "speed: m/min",
                                            "kind: code (see kind_codes, kind_names)", "area_mm2: mm^2"]
    assert vtk_to_numpy(data.GetFieldData().GetArray("kind_codes")).tolist() == [0, 1, 2]
    assert field_strings(data, "kind_names") == ["outside", "inside", "void"]
    assert field_strings(data, "deviation_sign") == ["+ = excess material"]
    assert vtk_to_numpy(data.GetFieldData().GetArray("voxel_mm")).tolist() == [0.25]
    # pyvista sees the same
    assert list(pv.read(path).field_data["units"])[:2] == ["arrival_s: s", "deviation_mm: mm"]


@pytest.mark.parametrize("name, unit", [("arrival_s", "s"), ("deviation_mm", "mm"), ("deposit_sdf_mm", "mm"),
                                        ("volume_mm3", "mm^3"), ("bead_area_mm2", "mm^2"), ("feed_mm_s", "mm/s"),
                                        ("porosity_percent", "%"), ("label", None), ("mass", None)])
def test_units_from_names(name, unit):
    assert array_unit(name) == unit
