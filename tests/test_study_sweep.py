"""`dmdvox study sweep`: one row per grid point, in order, same as a single simulate run."""

from __future__ import annotations

import math

import pytest

from dmdvox.errors import DmdvoxError
from dmdvox.cli import build_parser
from dmdvox.cli import cmd_study_sweep as run_study_sweep
from dmdvox.study.sweep import parse_set

SEED = """G90 G1 X0 Y0 Z0 F600
M65
G1 X10 Y0 Z0
G1 X10 Y2 Z0
G1 X0 Y2 Z0
M64
"""


def _args(gcode, extra: str):
    """`dmdvox study sweep` options as the command line gives them."""
    return build_parser().parse_args(["study", "sweep", str(gcode), "--dialect", "seed", "--height", "1", "--width",
                                      "2.5", "--json"] + extra.split())


def test_sweep_rows_follow_the_grid(gcode_file, tmp_path):
    path = gcode_file(SEED)
    out = tmp_path / "sweep.csv"
    rows = run_study_sweep(_args(path, f"--set width=2.0:2.5:0.5 --set voxel=0.1,0.2 --csv {out}"))["rows"]
    assert [(r["set_width"], r["set_voxel"]) for r in rows] == [(2.0, 0.1), (2.0, 0.2), (2.5, 0.1), (2.5, 0.2)]
    volume = {(r["set_width"], r["set_voxel"]): r["deposit_volume_mm3"] for r in rows}
    # A rect bead 2 x 1 mm revolved at every vertex and end: the part is h times the set of
    # points within r = w/2 = 1 mm of the U-shaped path (10 + 2 + 10 mm). The three strips
    # 2 r L_i overlap in two r x r squares on the inside of the two right-angle turns (the 2 mm
    # middle segment is exactly 2 r, so the long strips just touch); the outside of each turn
    # adds a quarter disc and the two ends a half disc each (they touch at one point only):
    # h (2 r L - 2 r^2 + 2 pi r^2 / 4 + pi r^2) = 44 - 2 + pi/2 + pi = 42 + 3 pi / 2 mm^3.
    exact = 42.0 + 1.5 * math.pi
    # The sub-voxel occupancy is second-order accurate on curved walls (grid/analysis.py): the
    # error shrinks about fourfold per halving of the voxel (measured 1.2 % at 0.2 mm, 0.3 % at
    # 0.1 mm, 0.07 % at 0.05 mm). At the default voxel w/20 = 0.1 mm: within 0.5 %.
    assert volume[(2.0, 0.1)] == pytest.approx(exact, rel=0.005)
    assert abs(volume[(2.0, 0.2)] - exact) > abs(volume[(2.0, 0.1)] - exact)
    assert volume[(2.0, 0.2)] == pytest.approx(exact, rel=4 * 0.005)
    # r = 1.25 mm: the long strips overlap across the whole 2 mm gap, so the part is the 10 x
    # (2 + 2 r) band, a 2 x r rectangle with two quarter discs at the turns, and the two end
    # half discs less the half of their lens (centres d = 2 apart) that lies beyond x = 0.
    r, d = 1.25, 2.0
    lens = 2 * r**2 * math.acos(d / (2 * r)) - d / 2 * math.sqrt(4 * r**2 - d**2)
    exact_wide = 10 * (2 + 2 * r) + (2 * r + math.pi * r**2 / 2) + (math.pi * r**2 - lens / 2)
    assert volume[(2.5, 0.1)] == pytest.approx(exact_wide, rel=0.005)
    assert out.read_text().splitlines()[0].startswith("set_width,set_voxel,profile,width_mm")


def test_parse_set():
    assert parse_set("width=2.0:3.0:0.25") == ("width", [2.0, 2.25, 2.5, 2.75, 3.0])
    assert parse_set("profile=rect,parabola") == ("profile", ["rect", "parabola"])
    with pytest.raises(DmdvoxError):
        parse_set("colour=1:2:1")
