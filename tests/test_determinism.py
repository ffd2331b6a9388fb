"""Identical results across runs and thread counts: JSON numbers and output bytes."""

import hashlib
import json
import os
import subprocess
import sys

from .conftest import DATA, REPO


def run(tmp_path, threads, tag):
    out = tmp_path / tag
    env = dict(os.environ, NUMBA_NUM_THREADS=str(threads))
    proc = subprocess.run([sys.executable, "-m", "dmdvox.cli", "simulate", str(DATA / "prusa_block_20.gcode"),
                           "--width", "0.6", "--voxel", "0.1", "--out", str(out), "--json"],
                          capture_output=True, text=True, cwd=REPO, env=env)
    assert proc.returncode == 0, proc.stderr
    result = json.loads(proc.stdout)
    result.pop("timings_s")
    result.pop("outputs")
    digests = {p.name: hashlib.sha256(p.read_bytes()).hexdigest() for p in sorted(out.iterdir())
               if p.suffix in (".vdb", ".stl", ".ply")}
    return result, digests


def test_simulate_is_deterministic_across_threads(tmp_path):
    one, one_files = run(tmp_path, 1, "t1")
    two, two_files = run(tmp_path, 2, "t2")
    again, again_files = run(tmp_path, 2, "t2b")
    assert one == two == again
    assert one["pore_count"] > 0  # the infill cells: a non-trivial result
    assert set(one_files) == {"prusa_block_20.vdb", "prusa_block_20_surface.stl", "prusa_block_20_surface.ply"}
    assert one_files == two_files == again_files


def _json(tmp_path, threads, args):
    env = dict(os.environ, NUMBA_NUM_THREADS=str(threads))
    proc = subprocess.run([sys.executable, "-m", "dmdvox.cli", *args, "--json"], capture_output=True, text=True,
                          cwd=REPO, env=env)
    assert proc.returncode == 0, proc.stderr
    result = json.loads(proc.stdout)
    result.pop("timings_s", None)
    return result


def test_compare_and_collide_are_deterministic_across_threads(tmp_path):
    """The CAD level set (OpenVDB, threaded by TBB), volumes, depths, deviation statistics and
    the collision check give the same numbers with 1 and 2 threads and on a second run."""
    compare = ["compare", str(DATA / "prusa_block_20.gcode"), str(DATA / "slicer_block.stl"), "--width", "0.6",
               "--voxel", "0.1"]
    collide = ["collide", str(DATA / "demo_block.gcode"), "--nozzle", "cone:tip=4,top=20,length=25",
               "--fixture", str(DATA / "demo_clamp.stl"), "--plate", "0", "--voxel", "0.25"]
    for args in (compare, collide):
        one, two, again = (_json(tmp_path, t, args) for t in (1, 2, 2))
        assert one == two == again
    assert one["collisions"]  # the clamp is hit: a non-trivial result
