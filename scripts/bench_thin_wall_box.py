#!/usr/bin/env python3
"""The void search against the sweep on thin walls (issue 26): thin-walled square boxes.

Each box is two overlapping square tracks per layer (the seed's 2.5 mm track at 1.25 mm
spacing: a 3.75 mm wall), 0.8 mm layers, ``--height`` mm tall (default 50), the fixed bead (rect
2.5 x 0.8 mm at constant feed), swept at 0.1 mm; then the void search ``simulate`` runs on it
(:func:`dmdvox.grid.analysis.porosity`, the substrate at the lowest deposit and the bead's
channel rule). Each side runs in a fresh process after a small warm-up box (numba's cache
filled, the kernels loaded), so that its figures are its own. Per side: active voxels, sweep and
void-search wall and CPU time (all threads), the pores found, the time per active voxel of the
two together and its max / min over the series (goal: within 1.2x), and with ``--phases`` the
void search's own kernels timed one by one (each wrapped where :func:`enclosed_voids` calls it).

    .venv/bin/python scripts/bench_thin_wall_box.py [--sides 50,100] [--height 50] [--voxel 0.1]
                                                     [--phases] [--json]
"""

from __future__ import annotations

import argparse
import functools
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
LAYER_STEP = 0.8

# the kernels enclosed_voids calls, by the phase they belong to
PHASES = {
    "work blocks": ("_work_blocks",),
    "classify": ("_classify",),
    "clearance beyond the band": ("_extend_clearance",),
    "label and connect": ("_label_blocks", "_connect", "_mark_exterior_centres", "_number"),
    "reach": ("_reach",),
    "members, fractions, stats": ("_enclosed_members", "_holding", "_fractions", "_void_stats", "_owned"),
}


def box_program(side: float, height: float) -> str:
    lines = ["M64", "G90 G21 G17", f"F{FEED_MM_MIN:.1f}"]
    for layer in range(int(round(height / LAYER_STEP))):
        z = layer * LAYER_STEP
        for k in range(2):
            a = TRACK_WIDTH / 2 + k * SPACING
            b = side - a
            lines += [f"G0 X{a:.4f} Y{a:.4f} Z{z:.4f}", "M65", f"G1 X{b:.4f} Y{a:.4f} F{FEED_MM_MIN:.1f}",
                      f"G1 X{b:.4f} Y{b:.4f}", f"G1 X{a:.4f} Y{b:.4f}", f"G1 X{a:.4f} Y{a:.4f}", "M64"]
    return "\n".join(lines) + "\n"


def plan_of(side: float, height: float):
    from dmdvox.deposit.simulate import fixed_plan
    from dmdvox.process.profiles import BeadProfile
    from dmdvox.toolpath import read_gcode

    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "box.gcode"
        path.write_text(box_program(side, height))
        tp = read_gcode(path, dialect="seed")
    return fixed_plan(tp, BeadProfile("rect", TRACK_WIDTH, LAYER_STEP))


def timed(fn):
    t0, c0 = time.perf_counter(), time.process_time()
    out = fn()
    return out, time.perf_counter() - t0, time.process_time() - c0


def wrap_phases(module, spent: dict):
    """Time each kernel of :data:`PHASES` where ``module`` calls it (wall seconds summed per phase)."""
    for phase, names in PHASES.items():
        spent[phase] = 0.0
        for name in names:
            original = getattr(module, name)

            @functools.wraps(original)
            def wrapper(*args, _original=original, _phase=phase, **kwargs):
                t = time.perf_counter()
                try:
                    return _original(*args, **kwargs)
                finally:
                    spent[_phase] += time.perf_counter() - t

            setattr(module, name, wrapper)


def run_one(side: float, height: float, voxel: float, phases: bool) -> dict:
    """One box in this process (the child's side of the benchmark)."""
    from dmdvox.deposit.engine import deposit_beads
    from dmdvox.grid import enclosure
    from dmdvox.grid.analysis import porosity

    def search(grid, plan):
        return porosity(grid, plate_z=None, bead_width=plan.profile.width)

    warm = plan_of(20.0, 4 * LAYER_STEP)
    search(deposit_beads(warm.beads(voxel), voxel)[0], warm)
    plan = plan_of(side, height)
    beads = plan.beads(voxel)
    (grid, timings), sweep_s, sweep_cpu = timed(lambda: deposit_beads(beads, voxel))
    spent: dict = {}
    if phases:
        wrap_phases(enclosure, spent)
    result, void_s, void_cpu = timed(lambda: search(grid, plan))
    active = grid.active_voxels
    return {
        "side_mm": side,
        "height_mm": height,
        "box_voxels": int(timings["domain_voxels"]),
        "active_voxels": int(active),
        "leaves": int(grid.n_leaf),
        "tiles": int(grid.n_tile),
        "sweep_s": round(sweep_s, 2),
        "sweep_cpu_s": round(sweep_cpu, 2),
        "void_search_s": round(void_s, 2),
        "void_search_cpu_s": round(void_cpu, 2),
        "void_over_sweep": round(void_s / sweep_s, 2),
        "ns_per_active_voxel": round((sweep_s + void_s) / active * 1e9, 1),
        "cpu_ns_per_active_voxel": round((sweep_cpu + void_cpu) / active * 1e9, 1),
        "pores": len(result.pores),
        "specks": int(result.speck_count),
        "pore_volume_mm3": round(result.pore_volume_mm3, 4),
        "deposit_volume_mm3": round(result.deposit_volume_mm3, 1),
        "peak_rss_mb": round(resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024, 1),
        "phases_s": {k: round(v, 2) for k, v in spent.items()},
    }


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--sides", default="50,100")
    parser.add_argument("--height", type=float, default=50.0)
    parser.add_argument("--voxel", type=float, default=0.1)
    parser.add_argument("--phases", action="store_true", help="time the void search's kernels one by one")
    parser.add_argument("--json", action="store_true", help="print the rows as JSON")
    parser.add_argument("--one", type=float, help=argparse.SUPPRESS)  # the child: one side, JSON on stdout
    args = parser.parse_args()
    if args.one is not None:
        print(json.dumps(run_one(args.one, args.height, args.voxel, args.phases)))
        return
    rows = []
    for side in (float(v) for v in args.sides.split(",")):
        argv = [sys.executable, __file__, "--one", str(side), "--height", str(args.height), "--voxel", str(args.voxel)]
        out = subprocess.run(argv + (["--phases"] if args.phases else []), capture_output=True, text=True, check=True)
        rows.append(json.loads(out.stdout))
        print(json.dumps(rows[-1]), file=sys.stderr, flush=True)
    per_voxel = [r["ns_per_active_voxel"] for r in rows]
    cpu_per_voxel = [r["cpu_ns_per_active_voxel"] for r in rows]
    summary = {"rows": rows, "ns_per_active_voxel_max_over_min": round(max(per_voxel) / min(per_voxel), 2),
               "cpu_ns_per_active_voxel_max_over_min": round(max(cpu_per_voxel) / min(cpu_per_voxel), 2)}
    if args.json:
        print(json.dumps(summary, indent=2))
        return
    print("| side | active voxels | sweep (CPU) | void search (CPU) | void / sweep | ns / active voxel (CPU) | pores |")
    print("|---|---|---|---|---|---|---|")
    for r in rows:
        print(f"| {r['side_mm']:g} mm | {r['active_voxels'] / 1e6:,.1f} M | {r['sweep_s']:.1f} s ({r['sweep_cpu_s']:.1f} s) "
              f"| {r['void_search_s']:.1f} s ({r['void_search_cpu_s']:.1f} s) | {r['void_over_sweep']:.2f} "
              f"| {r['ns_per_active_voxel']:.0f} ({r['cpu_ns_per_active_voxel']:.0f}) | {r['pores']} |")
        if r["phases_s"]:
            print("|  | " + ", ".join(f"{k} {v:.1f} s" for k, v in r["phases_s"].items()) + " | | | | | |")
    print(f"\n(sweep + void search) per active voxel, max / min: {summary['ns_per_active_voxel_max_over_min']} (wall), "
          f"{summary['cpu_ns_per_active_voxel_max_over_min']} (CPU)")


if __name__ == "__main__":
    main()
