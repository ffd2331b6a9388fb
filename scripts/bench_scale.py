#!/usr/bin/env python3
"""Real part sizes, end to end (issue 15): each command in its own process, its wall time and
peak RSS (the process's own high-water mark, from wait4).

* ``block``: the seed's zigzag block, 100 x 100 x 50.4 mm (63 layers of 0.8 mm, 2.5 mm track,
  1.25 mm spacing), its CAD box, at 0.1 mm: ``simulate``, ``compare`` and ``report``;
* ``thinbox``: a thin-walled square box, 200 x 200 x 100 mm, two tracks per layer (2.5 mm wide,
  1.25 mm apart: a 3.75 mm wall), 125 layers of 0.8 mm, its hollow CAD, at 0.1 mm (an 800 M-voxel
  box, a few percent of it active): ``compare``.

By default ``simulate`` keeps its deposit in a deposit cache of the run's own (emptied first),
and ``compare`` and ``report`` take it from there, as they would after a user's ``simulate``;
``--no-cache`` makes every command sweep its own.

Bytes per active voxel are given for the deposit's grid (its arrays) and for the whole
comparison (the process's peak over the deposit's and the CAD's active voxels).

    .venv/bin/python scripts/bench_scale.py [--part block|thinbox|all] [--side 200] [--out DIR] [--no-cache]
"""

from __future__ import annotations

import argparse
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))

from make_demo_part import FEED_MM_MIN, SPACING, TRACK_WIDTH, hatch_layer  # noqa: E402

LAYER_STEP = 0.8
VOXEL = 0.1


def block_part(folder: Path, size: float = 100.0, layers: int = 63) -> tuple[Path, Path]:
    from dmdvox.io.mesh import box_mesh, write_stl

    program = ["M64", "G90 G21 G17", f"F{FEED_MM_MIN:.1f}"]
    for layer in range(layers):
        program += hatch_layer(size, size, along_x=layer % 2 == 0, z=layer * LAYER_STEP)
    gcode = folder / "block100.gcode"
    gcode.write_text("\n".join(program) + "\n")
    stl = folder / "block100.stl"
    write_stl(stl, *box_mesh((0.0, 0.0, 0.0), (size, size, layers * LAYER_STEP)))
    return gcode, stl


def thin_box_part(folder: Path, side: float = 200.0, height: float = 100.0) -> tuple[Path, Path]:
    """Two closed square tracks per layer, the outer one's centre line 1.25 mm inside the wall's
    outer face; the CAD is the wall (outer box minus inner box, the inner faces turned in)."""
    from dmdvox.io.mesh import write_stl

    layers = int(round(height / LAYER_STEP))
    insets = [TRACK_WIDTH / 2, TRACK_WIDTH / 2 + SPACING]
    program = ["M64", "G90 G21 G17", f"F{FEED_MM_MIN:.1f}"]
    for layer in range(layers):
        z = layer * LAYER_STEP
        for inset in insets:
            lo, hi = inset, side - inset
            corners = [(lo, lo), (hi, lo), (hi, hi), (lo, hi), (lo, lo)]
            program += [f"G0 X{lo:.4f} Y{lo:.4f} Z{z + 5:.4f}", f"G1 Z{z:.4f}", "M65"]
            program += [f"G1 X{x:.4f} Y{y:.4f} Z{z:.4f}" for x, y in corners[1:]]
            program.append("M64")
    gcode = folder / f"thinbox{side:g}.gcode"
    gcode.write_text("\n".join(program) + "\n")
    wall = TRACK_WIDTH / 2 + SPACING + TRACK_WIDTH / 2
    stl = folder / f"thinbox{side:g}.stl"
    write_stl(stl, *square_ring(side, wall, layers * LAYER_STEP))
    return gcode, stl


def square_ring(side: float, wall: float, height: float) -> tuple[np.ndarray, np.ndarray]:
    """A closed mesh of a square tube: outer side ``side``, wall ``wall``, from z 0 to
    ``height``; faces wound outward."""
    outer = [(0.0, 0.0), (side, 0.0), (side, side), (0.0, side)]
    inner = [(wall, wall), (side - wall, wall), (side - wall, side - wall), (wall, side - wall)]
    vertices = np.array([(x, y, z) for z in (0.0, height) for ring in (outer, inner) for x, y in ring], np.float64)
    ob, ib, ot, it = 0, 4, 8, 12  # outer/inner rings at the bottom and the top
    quads = []
    for k in range(4):
        n = (k + 1) % 4
        quads.append((ob + k, ob + n, ot + n, ot + k))  # outer side, facing out
        quads.append((ib + n, ib + k, it + k, it + n))  # inner side, facing the hole
        quads.append((ot + k, ot + n, it + n, it + k))  # top, facing up
        quads.append((ob + n, ob + k, ib + k, ib + n))  # bottom, facing down
    triangles = np.array([t for a, b, c, d in quads for t in ((a, b, c), (a, c, d))], np.int64)
    return vertices, triangles


def run(argv: list[str], cache: str) -> dict:
    """One dmdvox command in its own process, with the deposit cache ``cache`` (a folder, or
    "off"): wall time, peak RSS and its JSON."""
    t = time.perf_counter()
    proc = subprocess.Popen([sys.executable, "-m", "dmdvox.cli", *map(str, argv), "--json"], stdout=subprocess.PIPE,
                            stderr=subprocess.DEVNULL, text=True, env={**os.environ, "DMDVOX_CACHE": cache})
    stdout = proc.stdout.read()
    _, status, usage = os.wait4(proc.pid, 0)
    proc.returncode = os.waitstatus_to_exitcode(status)
    elapsed = time.perf_counter() - t
    if proc.returncode != 0:
        raise SystemExit(f"dmdvox {' '.join(map(str, argv))} failed ({proc.returncode}): {stdout[-2000:]}")
    return {"seconds": elapsed, "peak_rss_gb": usage.ru_maxrss * 1024 / 1e9, "result": json.loads(stdout)}


def describe(name: str, run_: dict) -> str:
    return f"  {name:<9} {run_['seconds']:7.1f} s   peak RSS {run_['peak_rss_gb']:6.2f} GB"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--part", default="all", choices=("block", "thinbox", "all"))
    parser.add_argument("--side", type=float, default=200.0, help="thin-walled box side (mm)")
    parser.add_argument("--out", default=None, help="keep the parts and outputs here (default: a temporary folder)")
    parser.add_argument("--no-cache", action="store_true",
                        help="every command sweeps its own deposit (default: simulate keeps it in an empty deposit "
                             "cache of its own, for compare and report to take)")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        folder = Path(args.out or tmp)
        folder.mkdir(parents=True, exist_ok=True)
        cache = folder / "deposit-cache"
        shutil.rmtree(cache, ignore_errors=True)
        cache = "off" if args.no_cache else str(cache)
        if args.part in ("block", "all"):
            gcode, stl = block_part(folder)
            common = [gcode, "--dialect", "seed", "--voxel", VOXEL]
            print(f"seed block 100 x 100 x 50.4 mm at {VOXEL} mm ({gcode})")
            total = 0.0
            for name, argv in (("simulate", ["simulate", *common]), ("compare", ["compare", gcode, stl, *common[1:]]),
                               ("report", ["report", *common, "--cad", stl, "--out", folder / "report"])):
                result = run(argv, cache)
                total += result["seconds"]
                print(describe(name, result))
            print(f"  total     {total:7.1f} s")
        if args.part in ("thinbox", "all"):
            gcode, stl = thin_box_part(folder, args.side)
            print(f"thin-walled box {args.side:g} x {args.side:g} x 100 mm at {VOXEL} mm ({gcode})")
            result = run(["compare", gcode, stl, "--dialect", "seed", "--voxel", VOXEL], cache)
            summary = result["result"]
            active = summary["active_voxels"]
            memory = summary["memory_bytes"]
            box = np.prod(np.ceil((np.array([args.side, args.side, 100.0]) + 2) / VOXEL))
            print(describe("compare", result))
            print(f"  box {box / 1e6:,.0f} M voxels; active: deposit {active['deposit'] / 1e6:,.1f} M, "
                  f"CAD {active['cad'] / 1e6:,.1f} M ({100 * active['deposit'] / box:.1f} % of the box)")
            print(f"  bytes per active voxel: deposit grid {memory['deposit'] / active['deposit']:.1f}, whole "
                  f"comparison {result['peak_rss_gb'] * 1e9 / (active['deposit'] + active['cad']):.1f} (peak RSS)")
            print(f"  void {summary['void_percent']:.2f} %, overbuild {summary['overbuild_percent']:.2f} %")


if __name__ == "__main__":
    main()
