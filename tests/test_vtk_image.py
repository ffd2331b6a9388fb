"""VTK ImageData voxel output: index order, geometry, compression, z-slab splitting."""

import numpy as np
import pytest
import pyvista as pv

from dmdvox.io.vtk_image import write_voxels

ORIGIN = np.array([-3.0, 1.5, 10.25])
VOXEL = 0.25


def labelled(shape=(7, 5, 9)):
    """An array whose value encodes its own index: label = 10000 i + 100 j + k."""
    i, j, k = np.indices(shape)
    return (10000 * i + 100 * j + k).astype(np.int32)


def value_at(mesh, name, point):
    idx = mesh.find_closest_point(point)
    assert np.allclose(mesh.points[idx], point)
    return mesh.point_data[name][idx]


def world(ijk):
    return ORIGIN + VOXEL * np.asarray(ijk, float)


def test_single_file_round_trip(tmp_path):
    lab = labelled()
    dens = (lab % 7).astype(np.float32) / 7
    solid = lab % 3 == 0
    paths = write_voxels(tmp_path / "vol.vti", ORIGIN, VOXEL,
                         {"label": lab, "density": dens, "solid": solid, "f64": lab.astype(np.float64) / 3,
                          "u8": (lab % 256).astype(np.uint8)})
    assert paths == [tmp_path / "vol.vti"]
    assert sorted(p.name for p in tmp_path.iterdir()) == ["vol.vti"]  # no temp files left

    mesh = pv.read(paths[0])
    assert isinstance(mesh, pv.ImageData)
    assert mesh.dimensions == lab.shape
    assert np.allclose(mesh.origin, ORIGIN)
    assert np.allclose(mesh.spacing, (VOXEL,) * 3)
    assert set(mesh.point_data.keys()) >= {"label", "density", "solid", "f64", "u8"}
    assert mesh.point_data["label"].dtype == np.int32
    assert mesh.point_data["density"].dtype == np.float32
    assert mesh.point_data["f64"].dtype == np.float64
    assert mesh.point_data["solid"].dtype == np.uint8
    for ijk in [(0, 0, 0), (6, 4, 8), (1, 2, 3), (6, 0, 0), (0, 4, 0), (0, 0, 8), (3, 1, 7)]:
        assert value_at(mesh, "label", world(ijk)) == lab[ijk]
        assert value_at(mesh, "density", world(ijk)) == dens[ijk]
        assert value_at(mesh, "solid", world(ijk)) == solid[ijk]
    # whole-array check: VTK's x-fastest order is numpy's Fortran order
    assert np.array_equal(mesh.point_data["label"], lab.ravel(order="F"))


def test_vector_array_components(tmp_path):
    lab = labelled((3, 4, 5))
    vec = np.stack([lab, -lab, 2 * lab], axis=-1).astype(np.float32)
    mesh = pv.read(write_voxels(tmp_path / "v", ORIGIN, VOXEL, {"grad": vec})[0])
    assert mesh.point_data["grad"].shape == (60, 3)
    assert np.array_equal(value_at(mesh, "grad", world((2, 1, 3))), vec[2, 1, 3])


def test_output_is_compressed(tmp_path):
    a = np.zeros((64, 64, 64), np.float32)
    a[20:30, 20:30, 20:30] = 1.0
    (path,) = write_voxels(tmp_path / "c.vti", ORIGIN, VOXEL, {"sdf": a})
    assert 'compressor="vtkLZ4DataCompressor"' in path.read_bytes()[:2000].decode("latin-1")
    assert path.stat().st_size < a.nbytes / 50


def test_split_into_z_slabs(tmp_path):
    lab = labelled((6, 5, 23))
    mask = (lab % 2).astype(np.uint8)
    # 6 * 5 * 4 = 120 voxels a slab at most -> 4 planes, 3 new ones each: ceil(22 / 3) = 8 slabs
    paths = write_voxels(tmp_path / "big.vti", ORIGIN, VOXEL, {"label": lab, "mask": mask}, max_voxels_per_piece=120)
    assert paths[0] == tmp_path / "big.vtm"
    assert [p.name for p in paths[1:]] == [f"big_{n:03d}.vti" for n in range(8)]
    assert all(p.exists() for p in paths)
    assert not (tmp_path / "big.vti").exists()
    assert 'file="big_000.vti"' in paths[0].read_text()  # relative references

    blocks = pv.read(paths[0])
    assert isinstance(blocks, pv.MultiBlock) and len(blocks) == 8
    assert np.allclose(blocks.bounds, [ORIGIN[0], ORIGIN[0] + 5 * VOXEL, ORIGIN[1], ORIGIN[1] + 4 * VOXEL,
                                       ORIGIN[2], ORIGIN[2] + 22 * VOXEL])
    z_seen = set()
    previous_top = None
    for block in blocks:
        assert block.n_points <= 120
        assert np.allclose(block.spacing, (VOXEL,) * 3)
        assert set(block.point_data.keys()) >= {"label", "mask"}
        # every point carries the value of the voxel at that world position
        ijk = np.rint((block.points - ORIGIN) / VOXEL).astype(int)
        assert np.allclose(block.points, world(ijk))
        assert np.array_equal(block.point_data["label"], lab[ijk[:, 0], ijk[:, 1], ijk[:, 2]])
        assert np.array_equal(block.point_data["mask"], mask[ijk[:, 0], ijk[:, 1], ijk[:, 2]])
        zs = np.unique(ijk[:, 2])
        if previous_top is not None:
            assert zs[0] == previous_top  # neighbouring slabs share a plane: no gap
        previous_top = zs[-1]
        z_seen.update(zs.tolist())
    assert z_seen == set(range(23))


def test_rewrite_removes_stale_layout(tmp_path):
    lab = labelled((4, 4, 12))
    write_voxels(tmp_path / "r.vti", ORIGIN, VOXEL, {"label": lab}, max_voxels_per_piece=40)
    assert len(list(tmp_path.glob("r_*.vti"))) > 2
    few = write_voxels(tmp_path / "r.vti", ORIGIN, VOXEL, {"label": lab}, max_voxels_per_piece=100)
    assert sorted(p.name for p in tmp_path.iterdir()) == sorted(p.name for p in few)
    write_voxels(tmp_path / "r.vti", ORIGIN, VOXEL, {"label": lab})
    assert sorted(p.name for p in tmp_path.iterdir()) == ["r.vti"]


def test_small_volume_stays_single_even_with_vtm_name(tmp_path):
    paths = write_voxels(tmp_path / "s.vtm", ORIGIN, VOXEL, {"label": labelled((2, 2, 2))})
    assert paths == [tmp_path / "s.vti"]


@pytest.mark.parametrize(
    "kwargs, message",
    [
        ({"point_arrays": {}}, "at least one"),
        ({"point_arrays": {"a": np.zeros((2, 2))}}, "shape"),
        ({"point_arrays": {"a": np.zeros((2, 2, 2)), "b": np.zeros((2, 2, 3))}}, "expected"),
        ({"point_arrays": {"a": np.zeros((2, 2, 2), np.complex64)}}, "dtype"),
        ({"voxel": 0.0}, "voxel size"),
        ({"origin": (0, 0)}, "origin"),
    ],
)
def test_bad_input(tmp_path, kwargs, message):
    args = {"origin": ORIGIN, "voxel": VOXEL, "point_arrays": {"a": np.zeros((2, 2, 2))}} | kwargs
    with pytest.raises(ValueError, match=message):
        write_voxels(tmp_path / "bad.vti", **args)
    assert list(tmp_path.iterdir()) == []


def test_bad_suffix(tmp_path):
    with pytest.raises(ValueError, match=".vti"):
        write_voxels(tmp_path / "bad.vtk", ORIGIN, VOXEL, {"a": np.zeros((2, 2, 2))})


def test_every_piece_says_its_units_and_labels(tmp_path):
    """Each slab's field data names its arrays' units and the label codes with their names."""
    import vtk
    from vtk.util.numpy_support import vtk_to_numpy

    lab = labelled((4, 3, 12)) % 5
    names = {0: "outside both", 1: "inside both", 2: "void (CAD only)", 3: "overbuild (deposit only)", 4: "pore"}
    paths = write_voxels(tmp_path / "cmp.vti", ORIGIN, VOXEL,
                         {"label": lab.astype(np.uint8), "deposit_sdf_mm": lab.astype(np.float32)},
                         max_voxels_per_piece=40, labels={"label": names})
    assert len(paths) > 2
    for piece in paths[1:]:
        reader = vtk.vtkXMLImageDataReader()
        reader.SetFileName(str(piece))
        reader.Update()
        fd = reader.GetOutput().GetFieldData()
        units = fd.GetAbstractArray("units")
        assert [units.GetValue(i) for i in range(units.GetNumberOfValues())] == \
            ["label: code (see label_codes, label_names)", "deposit_sdf_mm: mm"]
        assert vtk_to_numpy(fd.GetArray("label_codes")).tolist() == [0, 1, 2, 3, 4]
        label_names = fd.GetAbstractArray("label_names")
        assert [label_names.GetValue(i) for i in range(5)] == [names[k] for k in range(5)]
    # a volume without label legend still says the units its names carry
    (single,) = write_voxels(tmp_path / "t.vti", ORIGIN, VOXEL, {"arrival_s": np.zeros((2, 2, 2), np.float32)})
    assert list(pv.read(single).field_data["units"]) == ["arrival_s: s"]
