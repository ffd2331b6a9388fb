#!/usr/bin/env python3
"""Benchmark `compare`: CAD level set + comparison against the deposit simulation of the same grid.

    .venv/bin/python scripts/bench_compare.py [--voxel 0.05]

Runs on the shipped samples (warm: a first run fills numba's cache) and prints, per sample, the
simulation time and the CAD + comparison time (level set, volumes, depths, surface deviation).
"""

from __future__ import annotations

import argparse
import json
from pathlib import Path

DATA = Path(__file__).resolve().parents[1] / "data"
SAMPLES = [("prusa_block_100.gcode", "slicer_block.stl", 0.6), ("prusa_block_20.gcode", "slicer_block.stl", 0.6),
           ("demo_block.gcode", "demo_block.stl", 2.5)]


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--voxel", type=float, default=0.05)
    args = parser.parse_args()
    from dmdvox.comparison.compare import CompareRequest, compare
    from dmdvox.deposit.simulate import fixed_plan
    from dmdvox.process.profiles import BeadProfile
    from dmdvox.toolpath import read_gcode

    rows = []
    for gcode, cad, width in SAMPLES:
        tp = read_gcode(DATA / gcode)
        plan = fixed_plan(tp, BeadProfile("rect", width, tp.layer_step))
        compare(CompareRequest(plan, DATA / cad, voxel=args.voxel * 2))  # warm-up
        t = compare(CompareRequest(plan, DATA / cad, voxel=args.voxel))["timings_s"]
        comparison = t["cad_level_set_s"] + t["volumes_s"] + t["deviation_s"]
        rows.append({"sample": gcode, "voxel_mm": args.voxel, "simulate_s": t["simulate_s"],
                     "cad_and_compare_s": round(comparison, 3), "ratio": round(comparison / t["simulate_s"], 2),
                     "detail_s": {k: t[k] for k in ("cad_level_set_s", "volumes_s", "deviation_s")}})
    print(json.dumps(rows, indent=2))


if __name__ == "__main__":
    main()
