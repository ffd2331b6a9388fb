#!/usr/bin/env python3
"""Growth-aware collision pose checks per second on a realistic scene.

The scene: the 30 x 30 mm zigzag block of ``make_demo_part.hatch_layer`` (seed parameters,
2.5 mm track, layers alternating X / Y), a cone nozzle (tip 4, top 20, length 25 mm) at the
default 12.7 mm standoff, and one fixture (a clamp block beside the part). Every pose is
checked at its own time against the part as deposited by then, and against the fixture.
Only the pose checks are timed (after one warm-up run that compiles the kernels); the deposit
and the voxelization of the bodies are reported separately.

    .venv/bin/python scripts/bench_collide.py [--layers 6] [--voxel 0.125] [--repeat 3]
"""

from __future__ import annotations

import argparse
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))

from make_demo_part import FEED_MM_MIN, box_mesh, hatch_layer  # noqa: E402

from dmdvox.collide.path import Obstacle, TOOL_AXIS, sample_poses  # noqa: E402
from dmdvox.collide.bodies import body_from_grid, mesh_body  # noqa: E402
from dmdvox.collide.kernels import query_poses  # noqa: E402
from dmdvox.collide.run import BAND_VOXELS, DEFAULT_STANDOFF_MM, nozzle_for  # noqa: E402
from dmdvox.deposit.engine import deposit  # noqa: E402
from dmdvox.deposit.profiles import BeadProfile  # noqa: E402
from dmdvox.toolpath import read_gcode  # noqa: E402


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--layers", type=int, default=6)
    parser.add_argument("--voxel", type=float, default=0.125)
    parser.add_argument("--clearance", type=float, default=1.0)
    parser.add_argument("--repeat", type=int, default=3)
    args = parser.parse_args()

    step = 0.75
    program = ["M64", "G90 G21 G17", f"F{FEED_MM_MIN:.1f}"]
    for layer in range(args.layers):
        program += hatch_layer(30.0, 30.0, along_x=layer % 2 == 0, z=layer * step)
    program.append("G0 Z50")
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "block.gcode"
        path.write_text("\n".join(program) + "\n")
        tp = read_gcode(path, dialect="seed")
    bead = BeadProfile("rect", 2.5, step)

    t = time.perf_counter()
    grid, _ = deposit(tp, bead, args.voxel)
    t_deposit = time.perf_counter() - t
    t = time.perf_counter()
    part = body_from_grid("part", grid)
    clamp = mesh_body("clamp", *box_mesh((32.0, 5.0, -5.0), (45.0, 25.0, 15.0)), args.voxel,
                      BAND_VOXELS * args.voxel, anchor=grid.origin)
    reach = args.clearance + args.voxel
    nozzle = nozzle_for("cone:tip=4,top=20,length=25", args.voxel, reach)
    t_bodies = time.perf_counter() - t
    obstacles = [Obstacle("part", part), Obstacle("fixture:clamp", clamp)]
    poses = sample_poses(tp, 0.5 * args.voxel)
    tips = np.ascontiguousarray(poses.point + DEFAULT_STANDOFF_MM * TOOL_AXIS)
    n = tips.shape[0]

    def run() -> tuple[list[float], float]:
        seconds = []
        closest = np.inf
        for o in obstacles:
            t0 = time.perf_counter()
            d = query_poses(o.body.kernel_args(), nozzle.kernel_args(), np.eye(3), tips, poses.time, reach)
            seconds.append(time.perf_counter() - t0)
            closest = min(closest, float(d.min()))
        return seconds, closest

    run()  # compile / load the cached kernels
    runs = [run() for _ in range(args.repeat)]
    per_obstacle = np.min([r[0] for r in runs], axis=0)
    best = float(per_obstacle.sum())
    closest = runs[0][1]
    import numba

    print(f"scene: {args.layers} layers of the 30x30 mm zigzag block, {len(tp)} rows, voxel {args.voxel} mm; "
          f"part {grid.n_leaf} leaves + {grid.n_tile} tiles; cone nozzle 4/20/25 mm at standoff "
          f"{DEFAULT_STANDOFF_MM} mm; one fixture; {numba.get_num_threads()} threads")
    print(f"deposit {t_deposit:.2f} s, bodies {t_bodies:.2f} s")
    print(f"{n:,d} poses (step {0.5 * args.voxel} mm) x {len(obstacles)} obstacles in {best:.3f} s: "
          f"{n / best:,.0f} growth-aware pose checks/s (min clearance "
          f"{'> reach' if not np.isfinite(closest) else f'{closest:.3f} mm'})")
    for o, sec in zip(obstacles, per_obstacle):
        print(f"  {o.label:<16s} {sec:.3f} s  ({n / sec:,.0f} poses/s)")


if __name__ == "__main__":
    main()
