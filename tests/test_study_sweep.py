"""`dmdvox study sweep`: one row per grid point, in order, same as a single simulate run."""

from __future__ import annotations

import argparse

import pytest

from dmdvox.errors import DmdvoxError
from dmdvox.study.sweep import add_sweep_options, parse_set, run_study_sweep

SEED = """G90 G1 X0 Y0 Z0 F600
M65
G1 X10 Y0 Z0
G1 X10 Y2 Z0
G1 X0 Y2 Z0
M64
"""


def _args(gcode, extra: str):
    p = argparse.ArgumentParser()
    p.add_argument("gcode")
    for name in ("--dialect", "--laser-on", "--laser-off", "--height", "--voxel", "--max-memory"):
        p.add_argument(name, default=None, type=str if name in ("--dialect", "--laser-on", "--laser-off") else float)
    p.add_argument("--strict", action="store_true")
    p.add_argument("--json", action="store_true")
    p.add_argument("--profile", default="rect")
    p.add_argument("--width", type=float, default=2.5)
    p.add_argument("--exponent", type=float, default=4.0)
    add_sweep_options(p)
    return p.parse_args([str(gcode), "--dialect", "seed", "--height", "1", "--json"] + extra.split())


def test_sweep_rows_follow_the_grid(gcode_file, tmp_path):
    path = gcode_file(SEED)
    out = tmp_path / "sweep.csv"
    rows = run_study_sweep(_args(path, f"--set width=2.0:2.5:0.5 --set voxel=0.1,0.2 --csv {out}"))["rows"]
    assert [(r["set_width"], r["set_voxel"]) for r in rows] == [(2.0, 0.1), (2.0, 0.2), (2.5, 0.1), (2.5, 0.2)]
    by_width = {r["set_width"]: r["deposit_volume_mm3"] for r in rows if r["set_voxel"] == 0.1}
    assert by_width[2.5] > by_width[2.0]
    # rect beads along a 10 + 2 + 10 mm path with round joints: about w h L plus the caps
    assert by_width[2.0] == pytest.approx(2.0 * 1.0 * 22.0, rel=0.1)
    assert out.read_text().splitlines()[0].startswith("set_width,set_voxel,profile,width_mm")


def test_parse_set():
    assert parse_set("width=2.0:3.0:0.25") == ("width", [2.0, 2.25, 2.5, 2.75, 3.0])
    assert parse_set("profile=rect,parabola") == ("profile", ["rect", "parabola"])
    with pytest.raises(DmdvoxError):
        parse_set("colour=1:2:1")
