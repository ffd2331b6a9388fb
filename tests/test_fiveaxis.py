"""Five-axis programs (issue 16): machine files, tool-centre-point control, the tip path and the
tool axis per row, beads standing on the tool axis, the nozzle following it in collisions, the
shipped sample. Closed forms and independent references (the kinematics' formulas, python-fcl)."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest

from dmdvox.cli import build_parser, main
from dmdvox.cli import cmd_collide as run_collide
from dmdvox.collision.bodies import Cone, mesh_body, nozzle_body
from dmdvox.collision.kernels import query_one, query_poses_rotated
from dmdvox.collision.path import axis_rotations, sample_poses
from dmdvox.deposit.simulate import SimulateRequest, simulate
from dmdvox.errors import DmdvoxError
from dmdvox.io.mesh import box_mesh, write_stl
from dmdvox.toolpath.kinematics import forward, inverse, load_machine
from dmdvox.process.plan import ProcessSettings, plan_process
from dmdvox.process.planner import MotionSettings
from dmdvox.toolpath import read_gcode
from dmdvox.toolpath.fiveaxis import DEFAULT_AXIS_STEP_DEG, DEFAULT_TIP_CHORD_MM

from .conftest import DATA, DEV_EXTRAS, require_module

MACHINES = DATA / "machines"
TRUNNION = MACHINES / "trunnion-ac.toml"
HEAD = MACHINES / "head-bc.toml"
VOXEL = 0.1
W, H = 2.0, 1.0  # the fixed bead of the geometry tests
FEED = 600.0  # mm/min


def fixed_plan(tp, width=W, height=H):
    """A fixed bead at constant feed: geometry and times without the planner's ramps."""
    return plan_process(tp, ProcessSettings(profile="rect", width=width, height=height, model="fixed",
                                            motion=MotionSettings(accel_mm_s2=0)))


def chords_of(arc: float, radius: float, length: float) -> bool:
    """Whether ``length`` is that of chords of an arc within the chord tolerance ``s``: each chord
    of angle t falls short of its arc by R t^3 / 24 = (s / 3R) of its length at most (s = R t^2 / 8)."""
    return arc * (1.0 - DEFAULT_TIP_CHORD_MM / (3.0 * radius) * 1.01) <= length <= arc


def inside_points(grid) -> np.ndarray:
    """World centres of the grid's inside voxels."""
    sdf = grid.dense_sdf()
    ijk = np.argwhere(sdf < 0)
    return grid.index_to_world(ijk)


def sdf_at(grid, points: np.ndarray) -> np.ndarray:
    """The grid's SDF at the voxel nearest each point (outside its domain: +band)."""
    ijk = np.rint(grid.world_to_index(points)).astype(np.int64)
    return grid.value_at_index(ijk)


# ------------------------------------------------------------------------------------------
# A ring on a rotating table: TCP off (the table turns C) and TCP on (a G2 circle)
# ------------------------------------------------------------------------------------------

R = 10.0
RING_OFF = f"G90 G21\nG0 X{R} Y0 Z0 A0 C0\nM65\nG1 C360 F{FEED}\nM64\n"
RING_ON = f"G90 G21\nG43.4 H1\nG0 X{R} Y0 Z0 A0 C0\nM65\nG3 X{R} Y0 I{-R} J0 C360 F{FEED}\nM64\nG49\n"


def test_ring_on_a_rotating_table_tcp_off(gcode_file):
    tp = read_gcode(gcode_file(RING_OFF), dialect="seed", strict=True, machine=TRUNNION)
    dep = np.flatnonzero(tp.deposit)
    # the tip path: chords of the circle of radius R about the C axis, within the chord tolerance
    for points in (tp.start[dep], tp.end[dep]):
        np.testing.assert_allclose(np.hypot(points[:, 0], points[:, 1]), R, atol=1e-9)
        np.testing.assert_allclose(points[:, 2], 0.0, atol=1e-12)
    mid = 0.5 * (tp.start[dep] + tp.end[dep])
    sagitta = R - np.hypot(mid[:, 0], mid[:, 1])
    assert sagitta.max() <= DEFAULT_TIP_CHORD_MM and sagitta.min() >= 0
    # the table turns once: the tip goes counterclockwise about the workpiece (iso sense), all the way
    angle = np.unwrap(np.arctan2(tp.end[dep, 1], tp.end[dep, 0]))
    assert np.all(np.diff(angle) > 0) and angle[-1] == pytest.approx(2 * np.pi, abs=1e-9)
    assert np.all(tp.axis[dep] == np.array([0, 0, 1], np.float32))  # A = 0: the nozzle stays vertical
    # the time its tip feed gives: the sampled length at F
    length = np.linalg.norm(tp.end[dep] - tp.start[dep], axis=1).sum()
    assert tp.t_end[dep[-1]] - tp.t_start[dep[0]] == pytest.approx(length / (FEED / 60), rel=1e-12)
    assert chords_of(2 * np.pi * R, R, length)

    res = simulate(SimulateRequest(fixed_plan(tp), voxel=VOXEL))
    # volume 2 pi R A; the joint at the start (the revolved end caps) lies inside the ring
    assert res["deposit_volume_mm3"] == pytest.approx(2 * np.pi * R * W * H, rel=0.01)
    pts = inside_points(res.grid)
    r = np.hypot(pts[:, 0], pts[:, 1])
    assert r.min() >= R - W / 2 - VOXEL and r.max() <= R + W / 2 + VOXEL
    # mean radius R: the inner and outer edges, direction by direction, straddle it
    sector = np.floor((np.arctan2(pts[:, 1], pts[:, 0]) + np.pi) / (2 * np.pi) * 36).astype(int)
    inner = np.array([r[sector == s].min() for s in range(36)])
    outer = np.array([r[sector == s].max() for s in range(36)])
    np.testing.assert_allclose(0.5 * (inner + outer), R, atol=VOXEL)
    assert pts[:, 2].min() >= -VOXEL and pts[:, 2].max() <= H + VOXEL


def test_the_same_ring_with_tcp_on_is_the_same_part_in_its_tip_feed_time(gcode_file):
    off = read_gcode(gcode_file(RING_OFF), dialect="seed", strict=True, machine=TRUNNION)
    on = read_gcode(gcode_file(RING_ON), dialect="seed", strict=True, machine=TRUNNION)
    dep = np.flatnonzero(on.deposit)
    # TCP on: the tip follows the programmed circle exactly (one exact arc: the axis stays +Z)
    assert len(on.arcs) == 1 and on.arcs.segment[0] == dep[0] and dep.size == 1
    assert on.t_end[dep[-1]] - on.t_start[dep[0]] == pytest.approx(2 * np.pi * R / (FEED / 60), rel=1e-12)
    a = simulate(SimulateRequest(fixed_plan(off), voxel=VOXEL)).grid
    b = simulate(SimulateRequest(fixed_plan(on), voxel=VOXEL)).grid
    # every voxel of either part lies within a voxel of the other
    assert sdf_at(b, inside_points(a)).max() <= VOXEL
    assert sdf_at(a, inside_points(b)).max() <= VOXEL


# ------------------------------------------------------------------------------------------
# Tilted beads: a head-head machine at B = 90
# ------------------------------------------------------------------------------------------

def test_a_bead_laid_sideways_grows_along_x(gcode_file):
    # TCP on: X Y Z are the tip; B = 90 points the nozzle along +X (tool axis from the tip up it):
    # the bead on a vertical wall at x = 0 grows towards +X
    on = read_gcode(gcode_file("G90\nG43.4\nG0 X0 Y0 Z10 B90 C0\nM65\nG1 Y20 F600\nM64\n"), dialect="seed",
                    strict=True, machine=HEAD)
    # the same bead with TCP off: the joints that put the tip there (the machine's inverse)
    m = load_machine(HEAD)
    joints = inverse(m, [[0.0, 0.0, 10.0], [0.0, 20.0, 10.0]], [[1.0, 0.0, 0.0]] * 2)
    (x0, y0, z0, _, b0, c0), (x1, y1, z1, _, _, _) = joints
    off = read_gcode(gcode_file(f"G90\nG0 X{x0:.9f} Y{y0:.9f} Z{z0:.9f} B{b0:.9f} C{c0:.9f}\nM65\n"
                                f"G1 X{x1:.9f} Y{y1:.9f} Z{z1:.9f} F600\nM64\n"), dialect="seed", strict=True,
                     machine=HEAD)
    for tp in (on, off):
        dep = np.flatnonzero(tp.deposit)
        np.testing.assert_allclose(tp.start[dep[0]], [0, 0, 10], atol=1e-6)
        np.testing.assert_allclose(tp.end[dep[-1]], [0, 20, 10], atol=1e-6)
        np.testing.assert_allclose(tp.axis[dep], [[1, 0, 0]], atol=1e-7)
        res = simulate(SimulateRequest(fixed_plan(tp), voxel=VOXEL))
        pts = inside_points(res.grid)
        # height along X, width along Z, within a voxel; round ends (revolved about X) along Y
        assert pts[:, 0].min() == pytest.approx(0.0, abs=VOXEL) and pts[:, 0].max() == pytest.approx(H, abs=VOXEL)
        assert pts[:, 2].min() == pytest.approx(10 - W / 2, abs=VOXEL)
        assert pts[:, 2].max() == pytest.approx(10 + W / 2, abs=VOXEL)
        assert pts[:, 1].min() == pytest.approx(-W / 2, abs=VOXEL) and pts[:, 1].max() == pytest.approx(20 + W / 2,
                                                                                                      abs=VOXEL)
        assert res["deposit_volume_mm3"] == pytest.approx(20 * W * H + np.pi * (W / 2) ** 2 * H, rel=0.01)


def test_head_turn_without_tcp_samples_the_tip_arc_and_steps_the_axis(gcode_file):
    # B 0 -> 90 alone with TCP off: the tip swings a quarter circle of the pivot length about the
    # pivot (X Y Z + L z), the tool axis turning from +Z to +X
    m = load_machine(HEAD)
    L = m.pivot_length
    tp = read_gcode(gcode_file("G90\nG0 X0 Y0 Z0 B0 C0\nG1 B90 F600\n"), dialect="seed", strict=True, machine=HEAD)
    pivot = np.array([0.0, 0.0, L])
    np.testing.assert_allclose(np.linalg.norm(tp.start - pivot, axis=1), L, atol=1e-9)
    np.testing.assert_allclose(tp.end[-1], [-L, 0, L], atol=1e-9)
    mid = 0.5 * (tp.start + tp.end)
    assert (L - np.linalg.norm(mid - pivot, axis=1)).max() <= DEFAULT_TIP_CHORD_MM
    # consecutive rows' axes differ by at most the axis step; the axis is unit and in the xz plane
    a, b = tp.axis[:-1].astype(float), tp.axis[1:].astype(float)
    turn = np.degrees(np.arctan2(np.linalg.norm(np.cross(a, b), axis=1), np.einsum("ij,ij->i", a, b)))
    assert turn.max() <= DEFAULT_AXIS_STEP_DEG + 1e-4  # float32 axes
    np.testing.assert_allclose(np.linalg.norm(tp.axis, axis=1), 1.0, atol=1e-6)
    # the feed is the tip's speed: a quarter circle of radius L at 10 mm/s (sampled length)
    length = np.linalg.norm(tp.end - tp.start, axis=1).sum()
    assert chords_of(0.5 * np.pi * L, L, length)
    assert tp.duration == pytest.approx(length / 10.0, rel=1e-12)
    # rows split the joint move evenly: row k's start is the closed form at B = 90 k / n, its
    # axis the one at its middle (iso B: the nozzle tilts towards +X)
    n = len(tp)
    b = np.radians(90.0 * np.arange(n) / n)
    np.testing.assert_allclose(tp.start, np.column_stack([-L * np.sin(b), np.zeros(n), L - L * np.cos(b)]),
                               atol=1e-9)
    b_mid = np.radians(90.0 * (np.arange(n) + 0.5) / n)
    np.testing.assert_allclose(tp.axis, np.column_stack([np.sin(b_mid), np.zeros(n), np.cos(b_mid)]), atol=1e-6)
    tips, axes = forward(m, np.column_stack([np.zeros((n, 4)), np.degrees(b), np.zeros(n)]))
    np.testing.assert_allclose(tips, tp.start, atol=1e-9)  # the kinematics agree with the closed form


# ------------------------------------------------------------------------------------------
# Tool-centre-point control: every keyword in every dialect; rotary moves' time
# ------------------------------------------------------------------------------------------

TCP_WORDS = [("G43.4 H1", "G49"), ("M128", "M129"), ("TRAORI", "TRAFOOF"), ("traori(1)", "trafoof"),
             ("#TRAFO ON", "#TRAFO OFF")]


@pytest.mark.parametrize("dialect", ["auto", "seed", "linuxcnc", "reprap", "grbl", "meltio"])
@pytest.mark.parametrize("on, off", TCP_WORDS)
def test_tcp_words_in_every_dialect(gcode_file, dialect, on, off):
    # C 0 -> 90 at X = 10 on the trunnion: with TCP on, X Y Z are the tip, which stays put while
    # the table turns (a turn about the tip: 90 deg at F600 read as deg/min = 9 s); with TCP off
    # the tip rides a quarter circle of radius 10 (15.7 mm at 10 mm/s)
    text = f"G90\nG0 X10 Y0 Z0 A0 C0\n{on}\nG1 C90 F600\n{off}\nG1 C180\n"
    tp = read_gcode(gcode_file(text), dialect=dialect, strict=True, machine=TRUNNION)
    assert tp.meta["unknown_codes"] == {} and tp.meta["warnings"] == []
    assert tp.meta["tcp_used"]
    first = tp.line == 4
    np.testing.assert_allclose(tp.start[first], [[10, 0, 0]] * first.sum())
    np.testing.assert_allclose(tp.end[first], [[10, 0, 0]] * first.sum())
    assert tp.t_end[first][-1] - tp.t_start[first][0] == pytest.approx(9.0)
    second = tp.line == 6
    length = np.linalg.norm(tp.end[second] - tp.start[second], axis=1).sum()
    assert chords_of(0.5 * np.pi * 10, 10.0, length)
    assert tp.t_end[second][-1] - tp.t_start[second][0] == pytest.approx(length / 10.0)
    np.testing.assert_allclose(tp.end[second][-1], [-10, 0, 0], atol=1e-9)


def test_rotary_moves_unwrapped_short_way_and_inverse_time(gcode_file):
    # trunnion-ac's C is unwrapped: C0 -> C720 turns twice; trunnion-bc's is wrapped: C350 -> C10
    # goes +20 degrees, not -340
    tp = read_gcode(gcode_file("G90\nG0 X5 Y0 Z0 A0 C0\nG1 C720 F600\n"), dialect="seed", machine=TRUNNION)
    angle = np.unwrap(np.arctan2(tp.end[:, 1], tp.end[:, 0]))
    assert angle[-1] == pytest.approx(4 * np.pi, abs=1e-9)
    bc = read_gcode(gcode_file("G90\nG0 X5 Y0 Z0 B0 C350\nG1 C10 F600\n"), dialect="seed",
                    machine=MACHINES / "trunnion-bc.toml")
    turn = bc.line == 3
    length = np.linalg.norm(bc.end[turn] - bc.start[turn], axis=1).sum()
    assert chords_of(np.radians(20) * 5, 5.0, length)
    np.testing.assert_array_equal(bc.rotary[turn][-1], np.float32([0, 0, 370]))
    # G93: the move takes 1/F minutes, whatever the axes do
    inv = read_gcode(gcode_file("G90\nG0 X5 Y0 Z0 A0 C0\nG93 G1 C90 F30\nG94\n"), dialect="seed", machine=TRUNNION)
    turn = inv.line == 3
    assert inv.t_end[turn][-1] - inv.t_start[turn][0] == pytest.approx(2.0)


def test_three_axis_programs_keep_a_vertical_axis_view(gcode_file):
    tp = read_gcode(gcode_file("G90\nG1 X0 Y0 Z0 F600\nG1 X10\nG2 X20 Y0 I5 J0\n"))
    assert tp.vertical and tp.axis.strides[0] == 0 and tp.axis.shape == (2, 3)
    np.testing.assert_array_equal(tp.axis, [[0, 0, 1]] * 2)
    assert "machine" not in tp.meta
    # the view holds one row whatever the program's length; selections keep it a view
    assert tp.select(np.array([True, False])).axis.strides[0] == 0
    assert tp.until(0.5).axis.shape == (1, 3)
    # a machine file whose axes stay at 0 gives the same rows
    five = read_gcode(gcode_file("G90\nG1 X0 Y0 Z0 F600\nG1 X10\nG2 X20 Y0 I5 J0\n"), machine=TRUNNION)
    np.testing.assert_array_equal(five.start, tp.start)
    np.testing.assert_array_equal(five.end, tp.end)
    np.testing.assert_allclose(five.t_end, tp.t_end, rtol=1e-12)
    assert len(five.arcs) == 1


def test_rotary_words_without_a_machine_are_warned_and_refused_under_strict(gcode_file, capsys):
    path = gcode_file("G90 G21\nG1 X0 Y0 Z0 F600\nM65\nG1 X10 C90\nM64\n")
    assert main(["info", str(path), "--dialect", "seed", "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert any("rotary" in w for w in out["warnings"])
    assert main(["info", str(path), "--dialect", "seed", "--strict"]) == 2
    # with the machine the words are the model: no warning
    assert main(["info", str(path), "--dialect", "seed", "--json", "--machine", str(TRUNNION)]) == 0
    out = json.loads(capsys.readouterr().out)
    assert not any("rotary" in w for w in out["warnings"])
    assert out["machine"]["kind"] == "trt-ac" and out["max_tilt_deg"] == pytest.approx(0.0)


def test_machine_option_errors(gcode_file, tmp_path, capsys):
    path = gcode_file("G90\nG1 X0 Y0 Z0 F600\n")
    assert main(["info", str(path), "--machine", str(tmp_path / "nope.toml")]) == 2
    assert "--machine" in capsys.readouterr().err
    bad = tmp_path / "bad.toml"
    bad.write_text('kind = "trt-ac"\nname = "x"\n')
    assert main(["info", str(path), "--machine", str(bad)]) == 2
    assert "bad.toml" in capsys.readouterr().err
    with pytest.raises(DmdvoxError, match="axis_step_deg"):
        read_gcode(path, machine=TRUNNION, axis_step_deg=0.0)


# ------------------------------------------------------------------------------------------
# Collision with a tilted nozzle
# ------------------------------------------------------------------------------------------

# a cylinder nozzle (4 mm, 20 mm long) on the head-bc machine, TCP on, tip at z = 5, moving along
# +x to x = 35 towards a block whose face is x = 40 (z 10..35): tilted 45 degrees towards the
# block (B = 45: axis (s, 0, s), s = sqrt(1/2)) the top rim's outer point, (L + r) s ahead of
# the tip and (L - r) s above it (z = 17.7, on the face), touches the face first
CYL_R, CYL_L = 2.0, 20.0
S = math.sqrt(0.5)
FACE_X = 40.0
BLOCK = ((FACE_X, -10.0, 10.0), (FACE_X + 10.0, 10.0, 35.0))
CONTACT_X = FACE_X - (CYL_L + CYL_R) * S


def tilted_program(b: float) -> str:
    return f"G90 G21\nG43.4\nG0 X0 Y0 Z5 B{b:g} C0\nG1 X35 F600\nG0 Z60\n"


def collide_args(gcode, fixture, **kw):
    args = build_parser().parse_args(
        ["collide", str(gcode), "--dialect", "seed", "--strict", "--json", "--machine", str(HEAD),
         "--width", "2.5", "--height", "1.0", "--voxel", "0.25", "--nozzle",
         f"cone:tip={2 * CYL_R:g},top={2 * CYL_R:g},length={CYL_L:g}", "--standoff", "0", "--accel", "0",
         "--fixture", str(fixture)])
    for key, value in kw.items():
        setattr(args, key, value)
    return args


@pytest.fixture
def block_stl(tmp_path):
    path = tmp_path / "block.stl"
    write_stl(path, *box_mesh(*BLOCK))
    return path


def test_tilted_nozzle_meets_the_block_at_the_analytic_line(gcode_file, block_stl):
    toward = run_collide(collide_args(gcode_file(tilted_program(45.0)), block_stl))
    assert toward["first_collision_line"] == 4
    first = toward["collisions"][0]
    assert first["obstacle"] == "fixture:block"
    # position_mm is the tip: at the contact line x = 40 - 22 s = 24.44, within a voxel
    assert first["position_mm"][0] == pytest.approx(CONTACT_X, abs=0.25)
    assert first["position_mm"][1:] == pytest.approx([0.0, 5.0], abs=1e-9)
    assert first["time_s"] == pytest.approx(CONTACT_X / 10.0, abs=0.25 / 10.0)
    # turned away (B = -45) the nozzle leans back: its nearest point stays 40 - 35 - r s away
    away = run_collide(collide_args(gcode_file(tilted_program(-45.0)), block_stl))
    assert away["collisions"] == [] and away["first_collision_line"] is None
    # vertical (B = 0): the side of the cylinder, r from the tip's x, would meet the face at 38
    upright = run_collide(collide_args(gcode_file(tilted_program(0.0)), block_stl))
    assert upright["collisions"] == []


def test_rotated_poses_agree_with_python_fcl(gcode_file):
    fcl = require_module("fcl", "python-fcl", DEV_EXTRAS)
    rng = np.random.default_rng(16)
    voxel = 0.2
    cone = Cone(2 * CYL_R, 2 * CYL_R, CYL_L)
    reach = 0.5
    nozzle = nozzle_body(f"cone:tip={cone.tip},top={cone.top},length={cone.length}", voxel, reach + 5 * voxel)
    block = mesh_body("block", *box_mesh(*BLOCK), voxel, 3 * voxel)
    # the poses of both tilts along the path, and random tilts and positions near the block
    poses = []
    for b in (45.0, -45.0):
        tp = read_gcode(gcode_file(tilted_program(b)), dialect="seed", machine=HEAD)
        p = sample_poses(tp, 0.5)
        poses.append((p.point, p.axis))
    k = rng.normal(size=(300, 3))
    k[:, 2] = np.abs(k[:, 2])
    k /= np.linalg.norm(k, axis=1, keepdims=True)
    poses.append((np.column_stack([rng.uniform(15, 45, 300), rng.uniform(-12, 12, 300), rng.uniform(0, 30, 300)]), k))
    point = np.concatenate([p for p, _ in poses])
    axis = np.concatenate([a for _, a in poses])
    Rs, index = axis_rotations(axis)
    np.testing.assert_allclose(np.einsum("nij,j->ni", Rs[index], [0, 0, 1.0]), axis, atol=1e-12)
    np.testing.assert_allclose(np.einsum("nij,nkj->nik", Rs, Rs), np.broadcast_to(np.eye(3), Rs.shape), atol=1e-12)
    tips = np.ascontiguousarray(point)
    d, _ = query_poses_rotated(block.kernel_args(), nozzle.kernel_args(), Rs, index, tips, np.zeros(len(tips)),
                               reach, True)
    raw, _ = query_poses_rotated(block.kernel_args(), nozzle.kernel_args(), Rs, index, tips, np.zeros(len(tips)),
                                 reach, False)
    np.testing.assert_array_equal(d, raw)  # pose coherence changes no value

    def fcl_object(vertices, triangles, rotation, position):
        model = fcl.BVHModel()
        model.beginModel(len(vertices), len(triangles))
        model.addSubModel(np.asarray(vertices, np.float64), np.asarray(triangles, np.int32))
        model.endModel()
        return fcl.CollisionObject(model, fcl.Transform(np.asarray(rotation, np.float64),
                                                        np.asarray(position, np.float64)))

    box = fcl_object(*box_mesh(*BLOCK), np.eye(3), np.zeros(3))
    mesh = cone.mesh(192)
    lo, hi = (np.asarray(c) for c in BLOCK)
    hits = apart = inside = 0
    for n in range(len(tips)):
        rot = Rs[index[n]]
        placed = mesh[0] @ rot.T + tips[n]
        if np.all((placed > lo) & (placed < hi)):
            # wholly inside the block: FCL's meshes are surfaces and see no crossing there
            assert d[n] < 0, n
            inside += 1
            continue
        noz = fcl_object(*mesh, rot, tips[n])
        collides = fcl.collide(noz, box, fcl.CollisionRequest(), fcl.CollisionResult()) > 0
        if collides:
            # clearly overlapping: still so with the nozzle moved a voxel along any axis
            clear = all(fcl.collide(fcl_object(*mesh, rot, tips[n] + s * voxel * e), box, fcl.CollisionRequest(),
                                    fcl.CollisionResult()) > 0 for e in np.eye(3) for s in (-1, 1))
            if clear:
                assert d[n] < 0, n
                hits += 1
        else:
            gap = fcl.distance(noz, box, fcl.DistanceRequest(), fcl.DistanceResult())
            if gap > voxel:
                assert not d[n] < 0, n
                apart += 1
    assert hits > 20 and apart > 200 and inside > 0
    # and each pose's value is the single-pose query's
    some = rng.choice(len(tips), 40, replace=False)
    for n in some:
        assert d[n] == np.float32(query_one(block.kernel_args(), nozzle.kernel_args(), Rs[index[n]], tips[n], 0.0,
                                            reach))


# ------------------------------------------------------------------------------------------
# The shipped sample: a tube on the trunnion's rotating table
# ------------------------------------------------------------------------------------------

SAMPLE = DATA / "tube_trunnion.gcode"
SAMPLE_CAD = DATA / "tube_trunnion.stl"
TUBE_R, TUBE_W, TUBE_STEP, TUBE_LAYERS = 15.0, 2.5, 0.8, 12  # scripts/make_tube_sample.py


def test_sample_tube_on_a_rotating_table(tmp_path, capsys):
    common = [str(SAMPLE), "--machine", str(TRUNNION), "--dialect", "seed", "--strict"]
    args = [*common, "--width", str(TUBE_W), "--height", str(TUBE_STEP), "--json"]
    assert main(["info", *common, "--json"]) == 0
    info = json.loads(capsys.readouterr().out)
    assert info["machine"]["kind"] == "trt-ac" and not info["tcp_used"]
    # 12 rings of the tip feed's length, each one turn of the table
    circumference = 2 * np.pi * TUBE_R
    assert chords_of(TUBE_LAYERS * circumference, TUBE_R, info["deposit_length_mm"])
    assert info["layers"] == TUBE_LAYERS
    assert main(["compare", *args[:1], str(SAMPLE_CAD), *args[1:], "--voxel", "0.125"]) == 0
    out = json.loads(capsys.readouterr().out)
    volume = TUBE_LAYERS * TUBE_STEP * circumference * TUBE_W
    assert out["deposit_volume_mm3"] == pytest.approx(volume, rel=0.01)
    assert out["void_percent"] < 1.0 and out["overbuild_percent"] < 1.0
    # the picture shows the nozzle at the tool point and the machine's axes turned with the table
    png = tmp_path / "tube.png"
    assert main(["render", *args[:-1], "--png", str(png), "--at", "0.5", "--size", "320x240"]) == 0
    assert png.stat().st_size > 1000


def test_view_turns_the_nozzle_and_the_machine_axes(gcode_file):
    require_module("pyvista", "pyvista")
    from dmdvox.view.interactive import Replay
    from dmdvox.view.render import machine_axes, tool_pose

    tp = read_gcode(SAMPLE, dialect="seed", machine=TRUNNION)
    surface = (np.zeros((0, 3)), np.zeros((0, 3), np.int64), np.zeros(0))
    replay = Replay(tp, surface, off_screen=True, window_size=(320, 240))
    try:
        dep = np.flatnonzero(tp.deposit)
        t = 0.5 * (tp.t_start[dep[0]] + tp.t_end[dep[20]])
        replay.state.seek(t)
        replay.update_scene()
        point, axis, rotary = tool_pose(tp, t)
        assert 0 < rotary[2] < 360  # C turning during the first ring
        # the machine's X axis, seen from the part, turned by C about +Z (iso: the table turns the
        # workpiece clockwise, so the machine's X turns counterclockwise in the workpiece frame)
        axes = machine_axes(tp, rotary)
        c = np.radians(rotary[2])
        np.testing.assert_allclose(axes[0], [np.cos(c), np.sin(c), 0], atol=1e-9)
        m = replay.machine_axis_actors[0].user_matrix
        np.testing.assert_allclose(np.asarray(m)[:3, 2], axes[0], atol=1e-9)
    finally:
        replay.close()
    # a tilted program turns the nozzle: its +Z along the tool axis, its tip at the tool point
    tilted = read_gcode(gcode_file("G90\nG43.4\nG0 X0 Y0 Z10 B45 C0\nM65\nG1 Y20 F600\nM64\n"), dialect="seed",
                        machine=HEAD)
    replay = Replay(tilted, surface, off_screen=True, window_size=(320, 240), standoff=3.0)
    try:
        replay.state.seek(1.0)
        replay.update_scene()
        m = np.asarray(replay.nozzle_actor.user_matrix)
        np.testing.assert_allclose(m[:3, 2], [S, 0, S], atol=1e-6)
        np.testing.assert_allclose(m[:3, 3], [0, 10, 10] + 3.0 * np.array([S, 0, S]), atol=1e-6)
    finally:
        replay.close()


def test_collision_poses_turn_the_nozzle_continuously(gcode_file):
    # the head's B 0 -> 90 without TCP: 90 rows whose axes step by 1 degree; the poses turn the
    # axis continuously through each row's (at its middle), a point 40 mm up the nozzle moving
    # at most the step between poses
    tp = read_gcode(gcode_file("G90\nG0 X0 Y0 Z0 B0 C0\nG1 X1 F600\nG1 B90\nG1 Y10\n"), dialect="seed",
                    machine=HEAD)
    step, lever = 0.5, 40.0
    poses = sample_poses(tp, step, lever)
    a, b = poses.axis[:-1], poses.axis[1:]
    turn = np.arctan2(np.linalg.norm(np.cross(a, b), axis=1), np.einsum("ij,ij->i", a, b))
    moved = np.linalg.norm(np.diff(poses.point, axis=0), axis=1) + lever * turn
    assert moved.max() <= step * (1 + 1e-9)
    np.testing.assert_allclose(np.linalg.norm(poses.axis, axis=1), 1.0, atol=1e-12)
    # the moves before and after the turn keep their axes (B = 0, B = 90): one rotation each
    for row in (0, len(tp) - 1):
        on = poses.row == row
        assert np.unique(poses.axis[on], axis=0).shape[0] == 1
        np.testing.assert_allclose(poses.axis[on][0], tp.axis[row], atol=1e-7)
    np.testing.assert_allclose(tp.axis[0], [0, 0, 1], atol=1e-7)
    np.testing.assert_allclose(tp.axis[-1], [1, 0, 0], atol=1e-7)
    # along the turn the axis is the joints' at each pose: B = 90 s over the move, within the
    # angle a row's axis stands for (its middle), to rounding
    turn = (poses.row > 0) & (poses.row < len(tp) - 1)
    b = np.degrees(np.arctan2(poses.axis[turn, 0], poses.axis[turn, 2]))
    rows = len(tp) - 2
    expected = 90.0 * ((poses.row[turn] - 1) + (poses.time[turn] - tp.t_start[poses.row[turn]])
                       / (tp.t_end[poses.row[turn]] - tp.t_start[poses.row[turn]])) / rows
    np.testing.assert_allclose(b, expected, atol=1e-4)


def test_rotary_values_past_the_machine_limits(gcode_file):
    # head-bc: b.limits = [-110, 110]
    path = gcode_file("G90\nG0 X0 Y0 Z10 B0 C0\nG1 B100 F600\nG1 B115\n")
    tp = read_gcode(path, dialect="seed", machine=HEAD)
    assert any(w.startswith(f"{path}:4: B = ") and "b.limits = [-110, 110]" in w for w in tp.meta["warnings"])
    with pytest.raises(DmdvoxError, match=r"b\.limits") as err:
        read_gcode(path, dialect="seed", machine=HEAD, strict=True)
    assert err.value.line == 4
