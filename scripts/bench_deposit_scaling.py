#!/usr/bin/env python3
"""Deposit cost as a part grows while its walls stay thin (issue 15): thin-walled square boxes.

Each box is two concentric square tracks per layer (the seed's 2.5 mm track at 1.25 mm spacing,
a 3.75 mm wall), 0.8 mm layers, 100 mm tall, rect bead 2.5 x 0.8 mm at constant feed, swept at
0.1 mm. Sides 50, 100, 200 and 400 mm by default: the bounding box grows 64x, the deposit 8x.
Each side runs in a fresh process (a warm-up deposit first fills numba's cache), so that its
peak RSS is its own; the table gives per side the box and active voxels, the warm deposit time
(best of ``--repeat``), ns per active voxel, the peak RSS and its increase over the RSS before
the deposit, bytes per active voxel of the grid, and the ratio max/min of the time per active
voxel over the series (goal: within 1.5x). Beside the wall time, the process's CPU time (all its
threads) of the same run: on a machine other jobs share, the steadier measure of the work.

    .venv/bin/python scripts/bench_deposit_scaling.py [--sides 50,100,200,400] [--height 100]
                                                      [--voxel 0.1] [--repeat 1] [--json]
"""

from __future__ import annotations

import argparse
import json
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path

TRACK_WIDTH = 2.5
SPACING = 1.25
FEED_MM_MIN = 750.0


def wall_layer(side: float, z: float) -> list[str]:
    """Two concentric square tracks inside a side x side square whose corner is the origin."""
    lines = []
    for k in range(2):
        a = TRACK_WIDTH / 2 + k * SPACING
        b = side - a
        lines += [f"G0 X{a:.4f} Y{a:.4f} Z{z:.4f}", "M65", f"G1 X{b:.4f} Y{a:.4f} F{FEED_MM_MIN:.1f}",
                  f"G1 X{b:.4f} Y{b:.4f}", f"G1 X{a:.4f} Y{b:.4f}", f"G1 X{a:.4f} Y{a:.4f}", "M64"]
    return lines


def box_program(side: float, height: float, step: float) -> str:
    lines = ["M64", "G90 G21 G17", f"F{FEED_MM_MIN:.1f}"]
    for layer in range(int(round(height / step))):
        lines += wall_layer(side, layer * step)
    return "\n".join(lines) + "\n"


def rss_mb() -> float:
    with open("/proc/self/status") as fh:
        for line in fh:
            if line.startswith("VmRSS:"):
                return int(line.split()[1]) / 1024
    return 0.0


def toolpath(text: str):
    from dmdvox.toolpath import read_gcode

    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "box.gcode"
        path.write_text(text)
        return read_gcode(path, dialect="seed")


def run_one(side: float, height: float, step: float, voxel: float, repeat: int) -> dict:
    """One box in this process (the child's side of the benchmark)."""
    from dmdvox.deposit.engine import deposit_beads
    from dmdvox.deposit.simulate import fixed_plan
    from dmdvox.process.profiles import BeadProfile

    bead = BeadProfile("rect", TRACK_WIDTH, step)
    deposit_beads(fixed_plan(toolpath(box_program(20.0, 4 * step, step)), bead).beads(voxel), voxel)  # warm-up
    beads = fixed_plan(toolpath(box_program(side, height, step)), bead).beads(voxel)
    before = rss_mb()
    best = None
    for _ in range(repeat):
        t0, c0 = time.perf_counter(), time.process_time()
        grid, timings = deposit_beads(beads, voxel)
        elapsed, cpu = time.perf_counter() - t0, time.process_time() - c0
        if best is None or elapsed < best[0]:
            best = (elapsed, cpu, grid, timings)
        del grid
    elapsed, cpu, grid, timings = best
    peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
    active = grid.active_voxels
    return {
        "side_mm": side,
        "box_voxels": int(timings["domain_voxels"]),
        "active_voxels": int(active),
        "active_percent_of_box": round(100 * active / timings["domain_voxels"], 2),
        "seconds": round(elapsed, 2),
        "ns_per_active_voxel": round(elapsed / active * 1e9, 1),
        "cpu_seconds": round(cpu, 2),
        "cpu_ns_per_active_voxel": round(cpu / active * 1e9, 1),
        "peak_rss_mb": round(peak, 1),
        "rss_increase_mb": round(peak - before, 1),
        "grid_bytes_per_active_voxel": round(grid.memory_bytes / active, 2),
        "peak_bytes_per_active_voxel": round((peak - before) * 2**20 / active, 2),
        "leaves": grid.n_leaf,
        "tiles": grid.n_tile,
        "chunks": int(timings.get("chunks", 0)),  # (an engine before the block walk had none)
        "swept_blocks": int(timings.get("swept_blocks", 0)),
        "timings_s": {k: round(v, 2) for k, v in timings.items() if k.endswith("_s")},
    }


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--sides", default="50,100,200,400")
    parser.add_argument("--height", type=float, default=100.0)
    parser.add_argument("--layer-step", type=float, default=0.8)
    parser.add_argument("--voxel", type=float, default=0.1)
    parser.add_argument("--repeat", type=int, default=1)
    parser.add_argument("--json", action="store_true", help="print the rows as JSON")
    parser.add_argument("--one", type=float, help=argparse.SUPPRESS)  # the child: one side, JSON on stdout
    args = parser.parse_args()
    if args.one is not None:
        print(json.dumps(run_one(args.one, args.height, args.layer_step, args.voxel, args.repeat)))
        return
    rows = []
    for side in (float(v) for v in args.sides.split(",")):
        out = subprocess.run([sys.executable, __file__, "--one", str(side), "--height", str(args.height),
                              "--layer-step", str(args.layer_step), "--voxel", str(args.voxel),
                              "--repeat", str(args.repeat)], capture_output=True, text=True, check=True)
        rows.append(json.loads(out.stdout))
        print(json.dumps(rows[-1]), file=sys.stderr, flush=True)
    per_voxel = [r["ns_per_active_voxel"] for r in rows]
    cpu_per_voxel = [r["cpu_ns_per_active_voxel"] for r in rows]
    summary = {"rows": rows, "ns_per_active_voxel_max_over_min": round(max(per_voxel) / min(per_voxel), 2),
               "cpu_ns_per_active_voxel_max_over_min": round(max(cpu_per_voxel) / min(cpu_per_voxel), 2)}
    if args.json:
        print(json.dumps(summary, indent=2))
        return
    print("| side | box voxels | active voxels | time | ns / active voxel | CPU time | CPU ns / active voxel "
          "| peak RSS (increase) | bytes / active voxel: peak increase (grid) |")
    print("|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        print(f"| {r['side_mm']:g} mm | {r['box_voxels'] / 1e6:,.0f} M | {r['active_voxels'] / 1e6:,.1f} M "
              f"({r['active_percent_of_box']:g} %) | {r['seconds']:.1f} s | {r['ns_per_active_voxel']:.0f} | "
              f"{r['cpu_seconds']:.1f} s | {r['cpu_ns_per_active_voxel']:.0f} | "
              f"{r['peak_rss_mb'] / 1024:.2f} GB ({r['rss_increase_mb'] / 1024:.2f} GB) | "
              f"{r['peak_bytes_per_active_voxel']:.1f} ({r['grid_bytes_per_active_voxel']:.2f}) |")
    print(f"\ntime per active voxel, max / min: {summary['ns_per_active_voxel_max_over_min']} (wall), "
          f"{summary['cpu_ns_per_active_voxel_max_over_min']} (CPU)")


if __name__ == "__main__":
    main()
