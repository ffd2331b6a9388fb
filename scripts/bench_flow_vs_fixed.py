"""The flow model's cost against the fixed bead's (issue 23), on slicer files.

For each file: `dmdvox simulate` with the flow model (the default for E-fed files) and with the
fixed bead of the slicer's line (--model fixed --width W --height H), both at the same voxel (the
flow model's default, w/20), each in its own process: wall time, the stage timings the JSON
reports and the process's peak resident memory. With --profile the flow run's landing is
profiled too (cProfile of ProcessPlan.lay).

    python scripts/bench_flow_vs_fixed.py data/corpus/cylinder_prusa_25.gcode [...] [--profile]
"""

from __future__ import annotations

import argparse
import json
import os
import resource
import subprocess
import sys
import time

RUN = """
import json, resource, sys, time
from dmdvox.cli import main
import contextlib, io
out = io.StringIO()
t = time.perf_counter()
with contextlib.redirect_stdout(out):
    code = main(sys.argv[1:] + ["--json"])
wall = time.perf_counter() - t
summary = json.loads(out.getvalue())
print(json.dumps({"code": code, "wall_s": wall, "timings_s": summary["timings_s"],
                  "voxel_mm": summary["voxel_mm"], "deposit_volume_mm3": summary["deposit_volume_mm3"],
                  "peak_rss_mib": resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024}))
"""

PROFILE = """
import cProfile, pstats, sys
from dmdvox.process.plan import ProcessSettings, plan_process
from dmdvox.toolpath import read_gcode
plan = plan_process(read_gcode(sys.argv[1], dialect="auto"), ProcessSettings())
plan.lay(plan.default_voxel())  # compiled and warm
profile = cProfile.Profile()
profile.enable()
plan.lay(plan.default_voxel())
profile.disable()
pstats.Stats(profile).sort_stats("cumulative").print_stats(12)
"""


def run(args: list[str]) -> dict:
    env = dict(os.environ, NUMBA_NUM_THREADS=os.environ.get("NUMBA_NUM_THREADS", "1"))
    done = subprocess.run([sys.executable, "-c", RUN, *args], capture_output=True, text=True, env=env, check=True)
    return json.loads(done.stdout.strip().splitlines()[-1])


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("files", nargs="+")
    parser.add_argument("--width", type=float, default=0.6, help="the slicer's line width (mm)")
    parser.add_argument("--height", type=float, default=0.3, help="the slicer's layer height (mm)")
    parser.add_argument("--profile", action="store_true")
    args = parser.parse_args()
    voxel = args.width / 20
    print(f"machine: {os.cpu_count()} cpus, load {os.getloadavg()[0]:.2f} at start")
    for path in args.files:
        flow = run(["simulate", path, "--voxel", str(voxel)])
        fixed = run(["simulate", path, "--voxel", str(voxel), "--model", "fixed", "--width", str(args.width),
                     "--height", str(args.height)])
        print(f"{path}: flow {flow['wall_s']:.1f} s {flow['peak_rss_mib']:.0f} MiB, fixed {fixed['wall_s']:.1f} s "
              f"{fixed['peak_rss_mib']:.0f} MiB: time x{flow['wall_s'] / fixed['wall_s']:.2f}, memory "
              f"x{flow['peak_rss_mib'] / fixed['peak_rss_mib']:.2f}")
        for name, result in (("flow", flow), ("fixed", fixed)):
            print(f"  {name:5s} " + " ".join(f"{k[:-2]} {v:.2f}" for k, v in result["timings_s"].items()))
        if args.profile:
            t = time.perf_counter()
            subprocess.run([sys.executable, "-c", PROFILE, path], check=True)
            print(f"  (profile run {time.perf_counter() - t:.1f} s)")
    print(f"children's peak RSS {resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss / 1024:.0f} MiB; "
          f"load {os.getloadavg()[0]:.2f} at the end")


if __name__ == "__main__":
    main()
