#!/usr/bin/env python3
"""Benchmark the deposit engine on the seed's zigzag block (issue figures).

Default: a 30 x 30 x 48 mm block, 2.5 mm track, 1.25 mm spacing, 60 layers of 0.8 mm,
rect profile, voxel 0.1 mm; timed warm (a first run fills numba's cache).

``--model fixed`` (default) is the constant 2.5 x 0.8 mm bead at constant feed; ``union`` and
``flow`` meter powder (6 g/min of 8 g/cm^3 at F750: 1.0 mm^2 at cruise, so that beads at the
1.25 mm spacing build the programmed 0.8 mm layers) with the default motion planner, at the
programmed positions (``union``) or landed on the part (``flow``). Times include building (and
landing) the beads.

    .venv/bin/python scripts/bench_deposit.py [--size 30,30] [--layers 60] [--voxel 0.1] [--repeat 2]
                                              [--model fixed|union|flow]
"""

from __future__ import annotations

import argparse
import json
import resource
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

from make_demo_part import hatch_layer  # noqa: E402


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--size", default="30,30")
    parser.add_argument("--layers", type=int, default=60)
    parser.add_argument("--layer-step", type=float, default=0.8)
    parser.add_argument("--voxel", type=float, default=0.1)
    parser.add_argument("--profile", default="rect")
    parser.add_argument("--repeat", type=int, default=2)
    parser.add_argument("--model", default="fixed", choices=("fixed", "union", "flow"))
    args = parser.parse_args()
    sx, sy = (float(v) for v in args.size.split(","))

    from dmdvox.deposit.engine import deposit_beads
    from dmdvox.grid.analysis import volume
    from dmdvox.process.flow import FlowSettings
    from dmdvox.process.plan import ProcessSettings, plan_process
    from dmdvox.process.planner import MotionSettings
    from dmdvox.toolpath import read_gcode

    lines = ["M64", "G90 G21", "F750"]
    for k in range(args.layers):
        lines += hatch_layer(sx, sy, k % 2 == 0, k * args.layer_step)
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "block.gcode"
        path.write_text("\n".join(lines) + "\n")
        tp = read_gcode(path, dialect="seed")
    if args.model == "fixed":
        settings = ProcessSettings(profile=args.profile, width=2.5, height=args.layer_step, model="fixed",
                                   motion=MotionSettings(accel_mm_s2=0.0))
    else:
        settings = ProcessSettings(profile=args.profile, width=2.5, model=args.model,
                                   flow=FlowSettings(powder_rate_g_min=6.0, density_g_cm3=8.0))
    plan = plan_process(tp, settings)

    def run(voxel):
        t = time.perf_counter()
        beads = plan.beads(voxel)
        grid, timings = deposit_beads(beads, voxel)
        timings["beads_s"] = time.perf_counter() - t - timings["sweep_s"] - timings["primitives_s"]
        return grid, timings

    run(1.0)  # compile / load numba's cache
    best = None
    for _ in range(args.repeat):
        t0 = time.perf_counter()
        grid, timings = run(args.voxel)
        elapsed = time.perf_counter() - t0
        if best is None or elapsed < best[0]:
            best = (elapsed, grid, timings)
    elapsed, grid, timings = best
    result = {
        "model": args.model,
        "part_mm": [sx, sy, args.layers * args.layer_step],
        "voxel_mm": args.voxel,
        "segments": int(tp.deposit.sum()),
        "seconds_warm": round(elapsed, 3),
        "domain_voxels": int(timings["domain_voxels"]),
        "domain_voxels_per_s": round(timings["domain_voxels"] / elapsed / 1e6, 1),
        "active_voxels": grid.active_voxels,
        "memory_bytes": grid.memory_bytes,
        "bytes_per_active_voxel": round(grid.memory_bytes / max(1, grid.active_voxels), 2),
        "leaves": grid.n_leaf,
        "inside_tiles": grid.n_tile,
        "volume_mm3": round(volume(grid), 2),
        "peak_rss_mb": round(resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024, 1),
        "timings_s": {k: round(v, 3) for k, v in timings.items() if k.endswith("_s")},
    }
    print(json.dumps(result, indent=2))


if __name__ == "__main__":
    main()
