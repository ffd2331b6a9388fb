#!/usr/bin/env python3
"""Five-axis programs of about 100 k rows against their 3-axis twin: reading, planning and
simulating, and the voxel rate (issue 16).

Three programs build a tube of radius 15 mm, 2.5 mm bead, 0.8 mm layers, seed dialect, fixed
bead at constant feed (``--accel 0``), each about ``--rows`` toolpath rows:

* ``3-axis``: every ring as G1 chords in X Y (the chords the five-axis reader samples: the
  same rows, the same part);
* ``table``: the same tube on ``data/machines/trunnion-ac.toml``, TCP off, one ``G1 C..``
  per ring (the reader samples the tip path within 0.01 mm);
* ``tilted``: on ``data/machines/head-bc.toml``, TCP on, the chords of the 3-axis program with
  the nozzle tilted ``--tilt`` degrees outwards (B) and turned with the ring (C): beads whose up
  axis is not vertical (the engine's general frames), split into rows of at most 1 degree of
  axis turn.

Times are warm (a first run compiles), best of ``--repeat``; the voxel rate is the deposit's
domain voxels per second of planning plus simulating (beads, sweep), as in bench_deposit.py,
by the wall clock and by the process's CPU time (the steadier of the two on a shared machine).

    .venv/bin/python scripts/bench_fiveaxis.py [--rows 100000] [--voxel 0.25] [--repeat 2]
"""

from __future__ import annotations

import argparse
import json
import math
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

REPO = Path(__file__).resolve().parents[1]
RADIUS = 15.0
WIDTH = 2.5
STEP = 0.8
FEED = 600.0


def chords_per_ring(tolerance: float = 0.01) -> int:
    return int(math.ceil(math.pi / math.acos(1.0 - tolerance / RADIUS)))


def programs(rings: int, tilt: float) -> dict[str, str]:
    k = chords_per_ring()
    angle = 2 * np.pi * np.arange(k + 1) / k
    x, y = RADIUS * np.cos(angle), RADIUS * np.sin(angle)
    flat = ["M64", "G90 G21", f"G0 X{RADIUS:.4f} Y0 Z0", f"G1 F{FEED:.1f}"]
    table = ["M64", "G90 G21", "G49", f"G0 X{RADIUS:.4f} Y0 Z0 A0 C0", f"G1 F{FEED:.1f}"]
    tilted = ["M64", "G90 G21", "G43.4", f"G0 X{RADIUS:.4f} Y0 Z0 B{tilt:g} C0", f"G1 F{FEED:.1f}"]
    for ring in range(rings):
        z = ring * STEP
        if ring:
            for prog in (flat, table, tilted):
                prog.append(f"G1 Z{z:.4f}")
        for prog in (flat, table, tilted):
            prog.append("M65")
        flat += [f"G1 X{x[i]:.6f} Y{y[i]:.6f}" for i in range(1, k + 1)]
        table.append(f"G1 C{360 * (ring + 1)}")
        tilted += [f"G1 X{x[i]:.6f} Y{y[i]:.6f} C{np.degrees(angle[i]) + 360 * ring:.6f}" for i in range(1, k + 1)]
        for prog in (flat, table, tilted):
            prog.append("M64")
    return {"3-axis": "\n".join(flat) + "\n", "table": "\n".join(table) + "\n", "tilted": "\n".join(tilted) + "\n"}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--rows", type=int, default=100_000)
    parser.add_argument("--voxel", type=float, default=0.25)
    parser.add_argument("--tilt", type=float, default=20.0)
    parser.add_argument("--repeat", type=int, default=2)
    args = parser.parse_args()
    from dmdvox.deposit.engine import deposit_beads
    from dmdvox.process.plan import ProcessSettings, plan_process
    from dmdvox.process.planner import MotionSettings
    from dmdvox.toolpath import read_gcode

    rings = max(1, args.rows // (chords_per_ring() + 2))
    machines = {"3-axis": None, "table": REPO / "data/machines/trunnion-ac.toml",
                "tilted": REPO / "data/machines/head-bc.toml"}
    settings = ProcessSettings(profile="rect", width=WIDTH, height=STEP, model="fixed",
                               motion=MotionSettings(accel_mm_s2=0.0))
    results = {}
    with tempfile.TemporaryDirectory() as tmp:
        texts = programs(rings, args.tilt)
        for name, text in texts.items():
            path = Path(tmp) / f"{name}.gcode"
            path.write_text(text)

            def run(voxel):
                t0 = time.perf_counter()
                tp = read_gcode(path, dialect="seed", machine=machines[name])
                t1 = time.perf_counter()
                c1 = time.process_time()
                plan = plan_process(tp, settings)
                beads = plan.beads(voxel)
                grid, timings = deposit_beads(beads, voxel)
                t2 = time.perf_counter()
                return tp, grid, timings, t1 - t0, t2 - t1, time.process_time() - c1

            run(4.0 * args.voxel)  # compile / load numba's cache
            best = None
            for _ in range(args.repeat):
                out = run(args.voxel)
                if best is None or out[4] < best[4]:
                    best = out
            tp, grid, timings, read_s, work_s, cpu_s = best
            results[name] = {
                "rows": len(tp), "deposit_rows": int(tp.deposit.sum()), "read_s": round(read_s, 3),
                "plan_and_simulate_s": round(work_s, 3), "domain_voxels": int(timings["domain_voxels"]),
                "active_voxels": int(grid.active_voxels),
                "domain_voxels_per_s_M": round(timings["domain_voxels"] / work_s / 1e6, 2),
                "cpu_s": round(cpu_s, 3),
                "domain_voxels_per_cpu_s_M": round(timings["domain_voxels"] / cpu_s / 1e6, 2),
                "max_tilt_deg": round(float(np.degrees(np.arccos(np.clip(tp.axis[:, 2].astype(float), -1, 1)).max())),
                                      2),
            }
    base = results["3-axis"]["domain_voxels_per_s_M"]
    base_cpu = results["3-axis"]["domain_voxels_per_cpu_s_M"]
    for name in ("table", "tilted"):
        results[name]["rate_vs_3axis"] = round(results[name]["domain_voxels_per_s_M"] / base, 2)
        results[name]["cpu_rate_vs_3axis"] = round(results[name]["domain_voxels_per_cpu_s_M"] / base_cpu, 2)
    print(json.dumps({"rings": rings, "voxel_mm": args.voxel, "results": results}, indent=2))


if __name__ == "__main__":
    sys.exit(main())
