"""Collision detection: analytic scenes with known first contacts, growth awareness, containment,
rotated bodies (the scene API), the plate, option errors."""

from __future__ import annotations

import json

import numpy as np
import pytest

from dmdvox.cli import build_parser, cmd_collide as run_collide
from dmdvox.collision import parse_cone, parse_fixture
from dmdvox.collision.scene import Scene, rotation_matrix
from dmdvox.errors import DmdvoxError
from dmdvox.io.mesh import box_mesh, write_stl
from dmdvox.toolpath import read_gcode


def args_for(gcode, **kw):
    """The options of `dmdvox collide` as the command line gives them (constant feed: these tests
    time the nozzle at F), with ``kw`` set on top."""
    args = build_parser().parse_args(
        ["collide", str(gcode), "--dialect", "seed", "--strict", "--json", "--profile", "rect", "--width", "2.5",
         "--height", "1.0", "--voxel", "0.25", "--nozzle", "cone:tip=4,top=20,length=25", "--standoff", "0",
         "--accel", "0"])
    for key, value in kw.items():
        setattr(args, key, value)
    return args


@pytest.fixture
def box_stl(tmp_path):
    """A 10 x 10 x 10 mm box fixture, x from 20 to 30, centred on y = 0."""
    path = tmp_path / "vise.stl"
    write_stl(path, *box_mesh((20.0, -5.0, 0.0), (30.0, 5.0, 10.0)))
    return path


# Cone tip 4 mm, top 20 mm over 25 mm: radius 2 + 0.32 z above the tip. With the tip at z = 2
# the cone meets the box top (z = 10) with radius 2 + 0.32 * 8 = 4.56 mm: moving along +x it
# first touches the box face x = 20 when the tip is at x = 15.44.
CONTACT_X = 20.0 - (2.0 + 0.32 * 8.0)
SLANT = np.cos(np.arctan(0.32))  # distance to the face shrinks by this per mm along x


def test_cone_first_collides_partway_through_a_travel_move(gcode_file, box_stl):
    program = gcode_file("G90 G21\nG1 X0 Y0 Z2 F600\nG1 X10\nG1 X15\nG1 X16\nG1 X40\n")
    tp = read_gcode(program, dialect="seed")
    result = run_collide(args_for(program, fixture=[str(box_stl)]))
    assert result["first_collision_line"] == 5  # G1 X16: contact at 15.44, partway through the move
    lines = sorted({c["line"] for c in result["collisions"]})
    assert lines == [5, 6]
    first = result["collisions"][0]
    assert first["obstacle"] == "fixture:vise"
    voxel = 0.25
    assert first["position_mm"][0] == pytest.approx(CONTACT_X, abs=voxel)
    assert first["position_mm"][1:] == pytest.approx([0.0, 2.0], abs=1e-9)
    row = int(np.flatnonzero(tp.line == 5)[0])
    speed = 10.0  # F600 mm/min
    assert first["time_s"] == pytest.approx(tp.t_start[row] + (CONTACT_X - 15.0) / speed, abs=voxel / speed)
    # deepest at the end of the line: 0.56 mm past contact along x
    assert first["depth_mm"] == pytest.approx((16.0 - CONTACT_X) * SLANT, abs=voxel)
    # line 4 ends 0.44 mm short of contact: a near miss at its end, at the slanted distance
    near = [m for m in result["near_misses"] if m["line"] == 4]
    assert len(near) == 1
    assert near[0]["distance_mm"] == pytest.approx((CONTACT_X - 15.0) * SLANT, abs=0.5 * voxel)
    assert result["min_clearance_mm"] == 0.0
    assert result["poses_checked"] > 40.0 / (voxel / 2)
    json.dumps(result, allow_nan=False)


def test_no_collision_when_the_approach_stops_short(gcode_file, box_stl):
    program = gcode_file("G90 G21\nG1 X0 Y0 Z2 F600\nG1 X14.3\n")
    result = run_collide(args_for(program, fixture=[f"{box_stl}@0,0,0"]))
    assert result["collisions"] == [] and result["first_collision_line"] is None
    assert result["near_misses"] == []  # 1.14 mm along x, 1.09 mm away: beyond --clearance 1
    # the clearance is measured up to clearance + 1 voxel
    assert result["min_clearance_mm"] == pytest.approx((CONTACT_X - 14.3) * SLANT, abs=0.125)
    far = run_collide(args_for(program, fixture=[str(box_stl)], clearance=0.5))
    assert far["min_clearance_mm"] is None  # nothing within 0.5 + 1 voxel
    # the same fixture moved 5 mm towards -x by its offset now collides on line 3
    moved = run_collide(args_for(program, fixture=[f"{box_stl}@-5,0,0"]))
    assert moved["first_collision_line"] == 3
    assert moved["collisions"][0]["position_mm"][0] == pytest.approx(CONTACT_X - 5.0, abs=0.25)
    # 3.86 mm past contact along x at the end: 3.68 mm deep across the cone's slanted side, more
    # than the clamped SDFs measure (the two bands: 0.75 + 2.5 mm here); the record says so
    true_depth = (14.3 - (CONTACT_X - 5.0)) * SLANT
    c = moved["collisions"][0]
    assert c["depth_limit_mm"] == pytest.approx(0.75 + 2.5) and true_depth > c["depth_limit_mm"]
    assert c["depth_capped"] and c["depth_mm"] == pytest.approx(c["depth_limit_mm"], abs=1e-4)
    # a shallow collision is measured, not capped: 0.56 mm past contact, to within a voxel
    shallow = run_collide(args_for(gcode_file("G90 G21\nG1 X0 Y0 Z2 F600\nG1 X16\n"), fixture=[str(box_stl)]))
    c = shallow["collisions"][0]
    assert not c["depth_capped"] and c["depth_mm"] == pytest.approx((16.0 - CONTACT_X) * SLANT, abs=0.25)


# two 1 mm layers along y at x = 10; travels above the wall in between
WALL = "G0 X10 Y-6 Z0\nM65\nG1 X10 Y6 F600\nM64\nG0 Z5\nG0 Y-6\nG0 Z1\nM65\nG1 Y6\nM64\nG0 Z10\n"
CROSS = "G0 X0 Y0 Z0.5\nG0 X20 Y0 Z0.5\n"  # a travel through the wall, 0.5 mm above its bottom


@pytest.mark.parametrize("before", [True, False])
def test_travel_across_the_wall_collides_only_after_it_is_built(gcode_file, before):
    body = ("G90 G21\nM64\nG0 X0 Y0 Z10\n" + (CROSS + WALL if before else WALL + CROSS) + "G0 Z30\n")
    program = gcode_file(body)
    tp = read_gcode(program, dialect="seed")
    cross_line = 5 + (0 if before else WALL.count("\n"))  # the "G0 X20" line
    assert tp.deposit.sum() == 2
    result = run_collide(args_for(program, nozzle="cone:tip=1,top=1,length=5", standoff=0.0))
    crossing = [c for c in result["collisions"] if c["line"] == cross_line]
    if before:
        assert crossing == []
    else:
        assert [c["obstacle"] for c in crossing] == ["part"]
        # the wall (2.5 mm wide, centred on x = 10) is met by the 0.5 mm radius nozzle at x = 8.25
        assert crossing[0]["position_mm"][0] == pytest.approx(10.0 - 1.25 - 0.5, abs=0.25)
    # with standoff 0 the tip sits in the bead being laid: every deposit line collides with the part
    deposit_lines = {int(n) for n in tp.line[tp.deposit]}
    assert deposit_lines <= {c["line"] for c in result["collisions"] if c["obstacle"] == "part"}


def test_nozzle_inside_a_big_fixture_collides(gcode_file, tmp_path):
    big = tmp_path / "block.stl"
    write_stl(big, *box_mesh((-50.0, -50.0, -10.0), (50.0, 50.0, 60.0)))
    program = gcode_file("G90 G21\nG1 X0 Y0 Z5 F600\nG1 X1\n")
    result = run_collide(args_for(program, fixture=[str(big)], voxel=0.5))
    assert [(c["line"], c["obstacle"]) for c in result["collisions"]] == [(3, "fixture:block")]
    assert all(c["depth_mm"] > 1.0 for c in result["collisions"])  # deep: capped by the bands


def test_plate(gcode_file):
    program = gcode_file("G90 G21\nG1 X0 Y0 Z5 F600\nG1 Z3\nG1 Z-1\nG1 Z5\n")
    result = run_collide(args_for(program, plate=0.5, standoff=0.0))
    # line 4 goes down through the plate, line 5 starts under it
    assert [(c["line"], c["obstacle"]) for c in result["collisions"]] == [(4, "plate"), (5, "plate")]
    c = result["collisions"][0]
    assert c["depth_mm"] == pytest.approx(1.5)  # the tip goes down to -1 under a plate at 0.5
    assert c["position_mm"][2] < 0.5 and c["position_mm"][2] > 0.5 - 0.125 - 1e-9
    # with the default standoff the tip stays 11.7 mm above the plate
    assert run_collide(args_for(program, plate=0.5, standoff=12.7))["collisions"] == []


def test_rotated_fixture_in_the_scene():
    scene = Scene(voxel=0.2, reach=2.0)
    # a 10 mm cube turned 45 degrees about z reaches 5 * sqrt(2) = 7.07 mm along x, not 5
    scene.add("fixture", *box_mesh((-5, -5, -5), (5, 5, 5)), rotation=rotation_matrix("z", 45.0))
    scene.add("probe", *box_mesh((-1, -1, -1), (1, 1, 1)), position=(12.0, 0.0, 0.0))
    steps = 0
    while scene.move("probe", (-0.1, 0.0, 0.0)):
        steps += 1
        assert steps < 200
    x = scene.objects["probe"].position[0]
    assert x - 1.0 == pytest.approx(5.0 * np.sqrt(2.0), abs=2 * scene.voxel)
    # refused: the probe stays where it was
    assert scene.objects["probe"].position[0] == x
    # turning the fixture back to 0 degrees frees the probe; another 45 degrees does too
    assert scene.rotate("fixture", "z", -45.0)
    assert scene.objects["fixture"].rotation == pytest.approx(np.eye(3), abs=1e-12)
    assert scene.move("probe", (-0.5, 0.0, 0.0))
    # the probe now 1.4 mm from the face x = 5: rotating the fixture by 45 degrees again is refused
    assert not scene.rotate("fixture", "z", 45.0)
    gap = x - 0.5 - 1.0 - 5.0
    assert scene.clearance("probe", "fixture") == pytest.approx(gap, abs=scene.voxel)
    assert scene.clearance("probe", "fixture", reach=gap - 0.3) == np.inf  # not measured beyond the reach


def test_option_errors(tmp_path):
    with pytest.raises(DmdvoxError, match="--nozzle"):
        parse_cone("cone:tip=4,top=20")
    with pytest.raises(DmdvoxError, match="--nozzle"):
        parse_cone("cone:tip=4,top=x,length=3")
    with pytest.raises(DmdvoxError, match="--fixture"):
        parse_fixture(str(tmp_path / "missing.stl"))
    path = tmp_path / "f.stl"
    write_stl(path, *box_mesh((0, 0, 0), (1, 1, 1)))
    with pytest.raises(DmdvoxError, match="--fixture"):
        parse_fixture(f"{path}@1,2")
    assert parse_fixture(f"{path}@1,2,3") == ("f", path, (1.0, 2.0, 3.0))
