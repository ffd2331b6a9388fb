"""The deposit engine against closed forms and brute force."""

import json
import math

import numpy as np
import pytest
from numba import njit, prange

from dmdvox.deposit import engine
from dmdvox.deposit.engine import build_primitives, deposit, _eval
from dmdvox.process.plan import fixed_beads
from dmdvox.process.profiles import PROFILE_NAMES, BeadProfile
from dmdvox.deposit.simulate import SimulateRequest, fixed_plan, simulate
from dmdvox.errors import ResourceError
from dmdvox.grid.analysis import porosity, volume
from dmdvox.toolpath import read_gcode

W = 2.5


def bead_volume(profile, length):
    return profile.area * length + profile.revolved_volume


@pytest.mark.parametrize("name", PROFILE_NAMES)
def test_straight_bead_volume(gcode_file, name):
    # Height 1.0 (arc needs h <= w/2); an oblique segment so faces do not follow the grid.
    prog = gcode_file("G90 G1 X0.31 Y0.17 Z0 F600\nM65\nG1 X12.31 Y5.17\nM64\n")
    tp = read_gcode(prog, dialect="seed")
    bead = BeadProfile(name, W, 1.0)
    grid, _ = deposit(tp, bead, W / 20)
    assert volume(grid) == pytest.approx(bead_volume(bead, 13.0), rel=0.01)


def test_arc_bead_volume(gcode_file):
    # Half circle of radius 8: exact arc bead, Pappus volume A * r * pi plus the two round ends.
    tp = read_gcode(gcode_file("G90 G1 X8 Y0 Z0 F600\nM65\nG3 X-8 Y0 I-8 J0\nM64\n"), dialect="seed")
    bead = BeadProfile("parabola", W, 1.0)
    prims = build_primitives(fixed_beads(tp, bead, 0.01))
    assert (prims.kind == 2).sum() == 1  # kept as an arc, not chords
    grid, _ = deposit(tp, bead, W / 20)
    assert volume(grid) == pytest.approx(bead.area * 8 * math.pi + bead.revolved_volume, rel=0.01)


def test_touching_rect_beads_are_one_solid(gcode_file):
    # 4 tracks at spacing = width, 3 layers at step = height: a 10 x 10 x 3 box with round ends
    # only on the outer tracks' ends... every track ends in a half disc of radius w/2.
    lines = ["G90 G1 X0 Y0 Z0 F600"]
    for layer in range(3):
        for k in range(4):
            y = k * W
            lines += [f"G1 X0 Y{y} Z{layer}", "M65", f"G1 X10 Y{y} Z{layer}", "M64"]
    tp = read_gcode(gcode_file("\n".join(lines) + "\n"), dialect="seed")
    bead = BeadProfile("rect", W, 1.0)
    grid, _ = deposit(tp, bead, W / 20)
    # Straight parts fill a 10 x 10 x 3 box exactly; each track adds one full disc (two halves).
    expected = 10 * 10 * 3 + 12 * math.pi * (W / 2) ** 2 * 1.0
    assert volume(grid) == pytest.approx(expected, rel=0.003)
    result = porosity(grid)
    assert result.pores == ()
    # No internal surfaces: every voxel strictly inside the box's core is deep inside.
    core = grid.value_at_index(np.rint(grid.world_to_index(
        np.stack(np.meshgrid(np.arange(1, 9, 0.25), np.arange(0.5, 6.0, 0.25), [0.5, 1.0, 1.5, 2.0],
                             indexing="ij"), -1).reshape(-1, 3))).astype(np.int64))
    assert np.all(core < -0.5 * grid.voxel)


def test_u_turn_has_no_spikes(gcode_file):
    # A hairpin: every surface point lies within the profile's reach of the path.
    tp = read_gcode(gcode_file("G90 G1 X0 Y0 Z0 F600\nM65\nG1 X10 Y0\nG1 X0 Y0.4\nG1 X10 Y0.8\nM64\n"),
                    dialect="seed")
    bead = BeadProfile("parabola", W, 1.0)
    grid, _ = deposit(tp, bead, 0.1)
    from dmdvox.grid.surface import surface_mesh

    vertices, _ = surface_mesh(grid)
    path = np.array([[0, 0], [10, 0], [0, 0.4], [10, 0.8]], float)
    a, b = path[:-1], path[1:]
    p = vertices[:, None, :2]
    t = np.clip(np.sum((p - a) * (b - a), -1) / np.sum((b - a) ** 2, -1), 0, 1)
    lateral = np.linalg.norm(p - (a + t[..., None] * (b - a)), axis=-1).min(axis=1)
    assert lateral.max() <= W / 2 + grid.voxel
    assert vertices[:, 2].max() <= 1.0 + grid.voxel


def test_sign_matches_brute_force(gcode_file):
    rng = np.random.default_rng(3)
    pts = np.round(rng.uniform(0, 8, (6, 2)), 2)
    text = "G90 G1 X%.2f Y%.2f Z0 F600\nM65\n" % tuple(pts[0]) + "".join(
        f"G1 X{x:.2f} Y{y:.2f} Z{0.3 * i:.2f}\n" for i, (x, y) in enumerate(pts[1:])) + "M64\n"
    tp = read_gcode(gcode_file(text), dialect="seed")
    bead = BeadProfile("ellipse", 1.5, 0.8)
    grid, _ = deposit(tp, bead, 0.1)
    prims = build_primitives(fixed_beads(tp, bead, 0.01))
    ijk = np.stack(np.meshgrid(*[np.arange(0, s * 8, 3) for s in grid.block_shape], indexing="ij"), -1).reshape(-1, 3)
    world = grid.index_to_world(ijk)
    inside_brute = np.zeros(len(world), bool)
    for k in range(len(prims)):
        for i, (x, y, z) in enumerate(world):
            if not inside_brute[i]:
                inside_brute[i] = _eval(prims.kind[k], prims.geom[k], x, y, z, bead.code, bead.exponent)[0] <= 0
    assert np.array_equal(grid.value_at_index(ijk) < 0, inside_brute)


def test_hollow_box_reports_its_cavity(gcode_file):
    # Full bottom layer, perimeter walls, full top layer (rect, spacing = width): an 8 x 8 mm
    # inner cavity of height 2 (layers 1-2) enclosed on every side.
    lines = ["G90 G1 X0 Y0 Z0 F600"]
    size = 12.5  # 6 tracks of 2.5 mm

    def full(z):
        out = []
        for k in range(6):
            y = W / 2 + k * W
            out += [f"G1 X{W / 2} Y{y} Z{z}", "M65", f"G1 X{size - W / 2} Y{y} Z{z}", "M64"]
        return out

    lines += full(0)
    for z in (1, 2):
        c0, c1 = W / 2, size - W / 2
        lines += [f"G1 X{c0} Y{c0} Z{z}", "M65", f"G1 X{c1} Y{c0}", f"G1 X{c1} Y{c1}", f"G1 X{c0} Y{c1}",
                  f"G1 X{c0} Y{c0}", "M64"]
    lines += full(3)
    tp = read_gcode(gcode_file("\n".join(lines) + "\n"), dialect="seed")
    grid, _ = deposit(tp, BeadProfile("rect", W, 1.0), W / 20)
    result = porosity(grid)
    assert len(result.pores) == 1
    cavity = (size - 2 * W) ** 2 * 2.0
    assert result.pores[0].volume_mm3 == pytest.approx(cavity, rel=0.03)
    np.testing.assert_allclose(result.pores[0].centroid_mm, [size / 2, size / 2, 2.0], atol=0.05)


def test_until_is_monotone_and_arrival_is_time(gcode_file):
    tp = read_gcode(gcode_file("G90 G1 X0 Y0 Z0 F600\nM65\nG1 X20\nG1 Y5\nG1 X0\nM64\n"), dialect="seed")
    bead = BeadProfile("rect", W, 1.0)
    volumes = [volume(deposit(tp, bead, 0.125, until=t)[0]) for t in (0.5, 1.5, 2.5, 4.5)]
    assert np.all(np.diff(volumes) > 0)
    grid, _ = deposit(tp, bead, 0.125)
    # At F600 (10 mm/s) the voxel at x = 10 on the first line arrives at t = 1 s (near the top:
    # inside the band arrival is per voxel; deeper it is the octant minimum, 4 voxels coarser).
    t = grid.arrival_at_index(np.rint(grid.world_to_index([[10.0, 0.0, 0.875], [10.0, 0.0, 0.5]])).astype(np.int64))
    assert t[0] == pytest.approx(1.0, abs=1e-6)
    assert 1.0 - 4 * 0.125 / 10 <= t[1] <= 1.0


def test_memory_guard_refuses_with_suggestion(gcode_file):
    tp = read_gcode(gcode_file("G90 G1 X0 Y0 Z0 F600\nM65\nG1 X100\nM64\n"), dialect="seed")
    with pytest.raises(ResourceError, match=r"^voxel 0.01: .* use voxel [0-9.]+ or larger") as caught:
        deposit(tp, BeadProfile("rect", W, 1.0), 0.01, max_memory=10 * 2**20)
    assert caught.value.parameter == "voxel"


def test_simulate_writes_vdb_and_surfaces(gcode_file, tmp_path):
    import subprocess

    tp = read_gcode(gcode_file("G90 G1 X0 Y0 Z0 F600\nM65\nG1 X10\nM64\n", name="bead.gcode"), dialect="seed")
    result = simulate(SimulateRequest(fixed_plan(tp, BeadProfile("rect", W, 1.0)), voxel=0.125,
                                      out_dir=tmp_path / "out"))
    names = sorted(p.split("/")[-1] for p in result["outputs"])
    assert names == ["bead.vdb", "bead_rows.csv", "bead_simulate.json", "bead_surface.ply", "bead_surface.stl",
                     "bead_surface.vtp"]
    listing = subprocess.run(["vdb_print", "-l", str(tmp_path / "out" / "bead.vdb")], capture_output=True,
                             text=True, check=True).stdout
    assert "sdf" in listing and "arrival" in listing
    # the files say their units: the .vdb's metadata (file and arrival grid), the surface's field data
    import pyvista as pv

    from dmdvox.vdb import openvdb

    vdb_path = str(tmp_path / "out" / "bead.vdb")
    assert openvdb.readMetadata(vdb_path)["arrival_unit"] == "s"
    assert openvdb.readGridMetadata(vdb_path, "arrival")["unit"] == "s"
    assert list(pv.read(tmp_path / "out" / "bead_surface.vtp").field_data["units"]) == ["arrival_s: s"]
    from dmdvox.grid.vdbio import read_vdb

    back = read_vdb(tmp_path / "out" / "bead.vdb")
    assert volume(back) == pytest.approx(result["deposit_volume_mm3"], rel=1e-6)
    # The deposit's own box, round ends included (to a voxel), not the path's.
    np.testing.assert_allclose(result["bbox_mm"], [[-W / 2, -W / 2, 0], [10 + W / 2, W / 2, 1.0]], atol=0.125)
    saved = json.loads((tmp_path / "out" / "bead_simulate.json").read_text())
    assert saved["deposit_volume_mm3"] == pytest.approx(10 * W + math.pi * (W / 2) ** 2, rel=0.01)


@pytest.mark.parametrize("name", ["rect", "parabola"])
@pytest.mark.parametrize("tilted", [False, True])
def test_framed_segment_matches_primitive(name, tilted):
    from dmdvox.deposit.engine import segment_frame, segment_sdf_framed
    from dmdvox.deposit.primitives import segment_sdf

    bead = BeadProfile(name, W, 1.0)
    rng = np.random.default_rng(5)
    for k in range(200):
        a = rng.uniform(-3, 3, 3)
        up = np.array([0.0, 0.0, 1.0])
        if tilted:
            up = rng.normal(size=3)
            up /= np.linalg.norm(up)
        foot = [0.0, 0.4][k % 2]
        # Horizontal, sloped, along the up axis and zero-length segments.
        b = a + [rng.uniform(-4, 4), rng.uniform(-4, 4), [0.0, rng.uniform(-2, 2), 3.0, 0.0][k % 4]]
        if k % 4 == 2:
            b = a + 3.0 * up
        if k % 4 == 3 and k % 8 == 3:
            b = a.copy()
        frame = segment_frame(*a, *b, *up)
        for p in rng.uniform(-6, 6, (20, 3)):
            d_ref, f_ref = segment_sdf(*p, *a, *b, *up, bead.code, W, 1.0, 4.0, foot)
            d, f = segment_sdf_framed(*p, *a, *frame, bead.code, W, 1.0, 4.0, foot)
            assert d == pytest.approx(d_ref, abs=1e-9)
            if d <= 0:
                assert f == pytest.approx(f_ref, abs=1e-9)


@njit(parallel=True)
def _brute_union(kind, geom, t0, t1, points, code, n, dist, first):
    """Per point, the least distance over every primitive and the earliest time one covers it."""
    for q in prange(points.shape[0]):
        best = np.inf
        t = np.inf
        for p in range(kind.shape[0]):
            d, f = _eval(kind[p], geom[p], points[q, 0], points[q, 1], points[q, 2], code, n)
            best = min(best, d)
            if d <= 0.0:
                t = min(t, t0[p] + f * (t1[p] - t0[p]))
        dist[q] = best
        first[q] = t


@pytest.mark.parametrize("tiny_chunks", [False, True])
def test_grid_matches_brute_force_union(gcode_file, monkeypatch, tiny_chunks):
    # Straight, sloped and crossing beads, a half circle and a helix, at every voxel of the table:
    # the block walk (which blocks each primitive reaches, lists cut at inside tiles, chunks with
    # their halo) against the min over all primitives, voxel by voxel.
    text = ("G90 G1 X0.13 Y0.21 Z0 F600\nM65\nG1 X8.13 Y0.21\nG3 X8.13 Y4.21 I0 J2\nG1 X1.13 Y4.21 Z0.6\n"
            "G2 X1.13 Y2.21 Z0.9 I0 J-1\nG1 X6.07 Y2.19\nM64\nG0 X3.03 Y-1.1 Z1.4\nM65\nG1 X3.03 Y5.9\nM64\n")
    tp = read_gcode(gcode_file(text), dialect="seed")
    bead = BeadProfile("ellipse", 1.5, 0.8)
    if tiny_chunks:
        monkeypatch.setattr(engine, "WINDOW_BYTES", 3 * engine.SWEPT_BLOCK_BYTES * 30)
        monkeypatch.setattr(engine, "CHUNK_OUTPUT_BYTES", 16 << 10)
    beads = fixed_beads(tp, bead, 0.01)
    grid, timings = engine.deposit_beads(beads, 0.1)
    assert (timings["chunks"] >= 8) == tiny_chunks
    prims = build_primitives(beads)
    assert set(np.unique(prims.kind)) == {0, 1, 2}  # segments, caps and arcs
    shape = tuple(8 * s for s in grid.block_shape)
    world = grid.index_to_world(np.indices(shape).reshape(3, -1).T)
    dist, first = np.empty(len(world)), np.empty(len(world))
    _brute_union(prims.kind, prims.geom, prims.t0, prims.t1, world, bead.code, bead.exponent, dist, first)
    dist, first = dist.reshape(shape).astype(np.float32), first.reshape(shape).astype(np.float32)
    sdf, arrival = grid.dense_sdf(), grid.dense_arrival()
    band = np.float32(grid.band)
    inside = dist <= 0
    assert 1000 < inside.sum() < inside.size // 4
    assert np.array_equal(sdf < 0, inside)
    # Outside, the min over primitives is exact: the same float32, up to the band.
    np.testing.assert_array_equal(sdf[~inside], np.minimum(dist[~inside], band))
    # Inside, the stored depth is at least the min's (the correction only deepens).
    assert np.all(sdf[inside] <= np.maximum(dist[inside], -band))
    assert np.all(sdf[inside] >= -band)
    # Arrival: the earliest covering time per active voxel, the octant's least over inside ones beyond.
    active = inside & (sdf > -band)
    np.testing.assert_array_equal(arrival[active], first[active])
    octants = np.where(inside, first, np.inf).reshape(shape[0] // 4, 4, shape[1] // 4, 4, shape[2] // 4, 4)
    least = octants.min(axis=(1, 3, 5)).repeat(4, 0).repeat(4, 1).repeat(4, 2)
    deep = inside & ~active
    assert deep.sum() > 0
    np.testing.assert_array_equal(arrival[deep], least[deep])
    assert np.all(np.isinf(arrival[~inside]))


@pytest.mark.parametrize("name", PROFILE_NAMES)
def test_union_distance_is_the_minimum_over_every_primitive(gcode_file, name):
    # The depth search's exact distance skips primitives by their boxes; it must give the
    # least value over all of them, at points inside, in the band and far away.
    text = ("G90 G1 X0.13 Y0.21 Z0 F600\nM65\nG1 X8.13 Y0.21\nG3 X8.13 Y4.21 I0 J2\nG1 X1.13 Y4.21 Z0.6\n"
            "G2 X1.13 Y2.21 Z0.9 I0 J-1\nG1 X6.07 Y2.19\nM64\nG0 X3.03 Y-1.1 Z1.4\nM65\nG1 X3.03 Y5.9\nM64\n")
    tp = read_gcode(gcode_file(text), dialect="seed")
    bead = BeadProfile(name, 1.6, 0.7)  # an arc needs h <= w / 2
    prims = build_primitives(fixed_beads(tp, bead, 0.01))
    points = np.random.default_rng(7).uniform((-3, -4, -2), (11, 8, 4), (4000, 3))
    dist, first = np.empty(len(points)), np.empty(len(points))
    _brute_union(prims.kind, prims.geom, prims.t0, prims.t1, points, bead.code, bead.exponent, dist, first)
    assert (dist < 0).sum() > 100 and (dist > 2).sum() > 100
    # (to rounding: a box's corners are computed from the frame, the distances through it)
    np.testing.assert_allclose(engine.union_distance(prims, bead.code, bead.exponent, points), dist, rtol=0,
                               atol=1e-12)
