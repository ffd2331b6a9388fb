#!/usr/bin/env python3
"""Benchmark: planning the motion of a 1,000,000-row toolpath (mixed short moves and arcs).

The program is generated as G-code (seed dialect) and read once: short lines of 0.05-2 mm in
random directions, every fourth row an arc (radius 0.5-10 mm, sweep up to 3 rad, a quarter of
them helical), feeds of 5-40 mm/s, a 0.5 s dwell every 5,000 rows and the deposit switching
every 20,000 rows. ``plan_motion`` runs once to compile (or load the numba cache), then is timed
warm, best of --repeat, each run on a fresh toolpath object so that the row lengths are computed
inside the timing as a caller would see it.

    .venv/bin/python scripts/bench_planner.py [--rows 1000000] [--repeat 3]
"""

from __future__ import annotations

import argparse
import dataclasses
import json
import math
import tempfile
import time
from pathlib import Path

import numpy as np

from dmdvox.process.planner import MotionSettings, apply_plan, plan_motion
from dmdvox.toolpath import read_gcode


def write_program(path: Path, n: int, seed: int = 12) -> None:
    rng = np.random.default_rng(seed)
    heading = rng.uniform(0, 2 * np.pi, n)
    span = rng.uniform(0.05, 2.0, n)
    radius = rng.uniform(0.5, 10.0, n)
    sweep = rng.uniform(0.1, 3.0, n) * rng.choice([-1.0, 1.0], n)
    helix = rng.random(n) < 0.25
    feeds = rng.choice([300.0, 600.0, 1000.0, 1500.0, 2400.0], n)  # mm/min: 5-40 mm/s
    out = ["G90 G21 G17", "G0 X0 Y0 Z0", "M65"]
    x = y = z = 0.0
    for i in range(n):
        if i and i % 5000 == 0:
            out.append("G4 P500")
        if i and i % 20000 == 0:
            out.append("M64" if (i // 20000) % 2 else "M65")
        if i % 4 == 3:
            r, phi = radius[i], heading[i]
            cx, cy = x - r * math.cos(phi), y - r * math.sin(phi)
            ex = round(cx + r * math.cos(phi + sweep[i]), 4)
            ey = round(cy + r * math.sin(phi + sweep[i]), 4)
            if helix[i]:
                z = round(z + 0.2, 4)
            out.append(f"{'G3' if sweep[i] > 0 else 'G2'} X{ex:.4f} Y{ey:.4f} Z{z:.4f} I{cx - x:.4f} J{cy - y:.4f} "
                       f"F{feeds[i]:g}")
            x, y = ex, ey
        else:
            x = round(x + span[i] * math.cos(heading[i]), 4)
            y = round(y + span[i] * math.sin(heading[i]), 4)
            out.append(f"G1 X{x:.4f} Y{y:.4f} F{feeds[i]:g}")
    path.write_text("\n".join(out) + "\n")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rows", type=int, default=1_000_000)
    parser.add_argument("--repeat", type=int, default=3)
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "bench_planner.gcode"
        write_program(path, args.rows)
        tp = read_gcode(path, dialect="seed")
    settings = MotionSettings()
    t0 = time.perf_counter()
    plan = plan_motion(tp, settings)  # compiles or loads the numba cache
    first = time.perf_counter() - t0
    times = []
    for _ in range(args.repeat):
        fresh = dataclasses.replace(tp)  # no cached row lengths
        t0 = time.perf_counter()
        plan = plan_motion(fresh, settings)
        times.append(time.perf_counter() - t0)
    t0 = time.perf_counter()
    apply_plan(tp, plan)
    apply_s = time.perf_counter() - t0
    best = min(times)
    print(json.dumps({
        "rows": len(tp),
        "arcs": len(tp.arcs),
        "first_call_s": round(first, 4),
        "plan_motion_best_s": round(best, 4),
        "plan_motion_runs_s": [round(t, 4) for t in times],
        "rows_per_s": round(len(tp) / best),
        "apply_plan_s": round(apply_s, 4),
        "constant_feed_duration_s": round(tp.duration, 1),
        "planned_duration_s": round(plan.duration_s, 1),
        "settings": settings.to_json(),
    }, indent=2))


if __name__ == "__main__":
    main()
