#!/usr/bin/env python3
"""The 3-axis reader and deposit of two source trees side by side, alternating (issue 16: are
3-axis programs as fast as before?). Each measurement runs in a fresh process importing
``dmdvox`` from the given tree; times are warm (a first call compiles), best of ``--repeat``,
by the wall clock and in process CPU time (steadier on a shared machine).

    git archive c16c72b | tar -x -C /tmp/base      # the tree before issue 16
    .venv/bin/python scripts/bench_trees.py /tmp/base . [--rounds 3] [--repeat 8]

Reader: the 1 M-line RepRap file of bench_gcode.py, numba on one thread. Deposit: the block of
bench_deposit.py (30 x 30 x 48 mm, fixed 2.5 x 0.8 mm bead, voxel 0.1 mm): beads and sweep.
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile
import textwrap
from pathlib import Path

HERE = Path(__file__).resolve().parent

READ = textwrap.dedent('''
    import json, sys, time
    sys.path.insert(0, sys.argv[1])
    from dmdvox.toolpath import read_gcode
    read_gcode(sys.argv[2])
    wall = cpu = 1e9
    for _ in range(int(sys.argv[3])):
        t0, c0 = time.perf_counter(), time.process_time()
        tp = read_gcode(sys.argv[2])
        wall, cpu = min(wall, time.perf_counter() - t0), min(cpu, time.process_time() - c0)
    print(json.dumps({"wall_s": wall, "cpu_s": cpu, "rows": len(tp), "bytes_per_row": tp.nbytes / len(tp)}))
''')

DEPOSIT = textwrap.dedent('''
    import json, sys, tempfile, time
    from pathlib import Path
    sys.path.insert(0, sys.argv[1])
    sys.path.insert(0, sys.argv[2])
    from make_demo_part import hatch_layer
    from dmdvox.deposit.engine import deposit_beads
    from dmdvox.process.plan import ProcessSettings, plan_process
    from dmdvox.process.planner import MotionSettings
    from dmdvox.toolpath import read_gcode
    lines = ["M64", "G90 G21", "F750"]
    for k in range(60):
        lines += hatch_layer(30, 30, k % 2 == 0, k * 0.8)
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "block.gcode"
        path.write_text("\\n".join(lines) + "\\n")
        tp = read_gcode(path, dialect="seed")
    plan = plan_process(tp, ProcessSettings(profile="rect", width=2.5, height=0.8, model="fixed",
                                            motion=MotionSettings(accel_mm_s2=0.0)))
    deposit_beads(plan.beads(1.0), 1.0)
    wall = cpu = 1e9
    for _ in range(int(sys.argv[3])):
        t0, c0 = time.perf_counter(), time.process_time()
        grid, timings = deposit_beads(plan.beads(0.1), 0.1)
        wall, cpu = min(wall, time.perf_counter() - t0), min(cpu, time.process_time() - c0)
    print(json.dumps({"wall_s": wall, "cpu_s": cpu, "domain_voxels": int(timings["domain_voxels"])}))
''')


def measure(code: str, args: list[str], env=None) -> dict:
    out = subprocess.run([sys.executable, "-c", code, *args], capture_output=True, text=True, check=True, env=env)
    return json.loads(out.stdout.strip().splitlines()[-1])


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("trees", nargs=2, help="two source trees (each holds dmdvox/)")
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--repeat", type=int, default=8)
    args = parser.parse_args()
    sys.path.insert(0, str(HERE))
    from bench_gcode import make_reprap

    trees = [str(Path(t).resolve()) for t in args.trees]
    results = {t: {"read": [], "deposit": []} for t in trees}
    one_thread = {**os.environ, "NUMBA_NUM_THREADS": "1"}
    with tempfile.TemporaryDirectory() as tmp:
        gcode = Path(tmp) / "bench.gcode"
        make_reprap(gcode, 1_000_000)
        for _ in range(args.rounds):
            for tree in trees:
                results[tree]["read"].append(measure(READ, [tree, str(gcode), str(args.repeat)], one_thread))
                results[tree]["deposit"].append(measure(DEPOSIT, [tree, str(HERE), str(max(1, args.repeat // 4))]))
    summary = {}
    for tree, r in results.items():
        summary[tree] = {
            "read_cpu_s": sorted(round(x["cpu_s"], 4) for x in r["read"]),
            "read_wall_s": sorted(round(x["wall_s"], 4) for x in r["read"]),
            "bytes_per_row": round(r["read"][0]["bytes_per_row"], 1),
            "deposit_cpu_s": sorted(round(x["cpu_s"], 3) for x in r["deposit"]),
            "deposit_wall_s": sorted(round(x["wall_s"], 3) for x in r["deposit"]),
        }
    print(json.dumps(summary, indent=2))


if __name__ == "__main__":
    main()
