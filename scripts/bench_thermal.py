#!/usr/bin/env python3
"""Benchmark: the demo block's thermal history, and the solver's time per cell-step beside a
plain numpy stencil of the same lattice in the same run.

The demo block (data/demo_block.gcode, 8 layers of the seed's 2.5 mm bead, 185 s) is planned as
`dmdvox thermal` plans it, deposited at the default voxel (0.125 mm, the deposit cache off),
then heated in 316L at the default thermal voxel (a quarter of the bead: 0.625 mm) with a
1000 W beam, absorptivity 0.4. The heat stage is timed (wall and CPU: the machine may be shared);
its energy balance is printed. Then, on the same lattice's box, `--stencil-steps` steps of
plain numpy (a 7-point constant-conductivity explicit update of a dense array with as many
cells as the lattice's box) and of the solver (the lattice itself, warm) are timed, per cell-step.

    .venv/bin/python scripts/bench_thermal.py [--stencil-steps 200]

``--block``: the issue's 30 x 30 x 48 mm block (bench_deposit's: 60 layers of 0.8 mm, the
fixed 2.5 x 0.8 mm bead at 1.25 mm spacing, F750) at a 0.6 mm thermal voxel (deposit voxel
0.2 mm, m = 3). The whole lattice is built and its cells, memory bound (the guard's figure) and
cell-steps counted; the heat runs the first ``--heat-seconds`` of the build (the whole build
is about an hour of 5 ms steps), timed, and the whole run is projected from its CPU time per
cell-step (each cell costs from its birth to the end).

    .venv/bin/python scripts/bench_thermal.py --block [--heat-seconds 60] [--layers 60]
"""

from __future__ import annotations

import argparse
import json
import time
from pathlib import Path

import numpy as np

from dmdvox.deposit.simulate import SimulateRequest, simulate
from dmdvox.process.plan import ProcessSettings, plan_process
from dmdvox.thermal.lattice import bytes_per_cell, lattice_from_birth
from dmdvox.thermal.run import thermal_history, thermal_request
from dmdvox.thermal.solver import SourcePath, run, start
from dmdvox.toolpath.reader import read_gcode

DEMO = Path(__file__).resolve().parents[1] / "data" / "demo_block.gcode"


def numpy_stencil(shape, steps: int) -> float:
    """CPU seconds per cell-step of a dense 7-point explicit update (constant k, no losses)."""
    T = np.full(shape, 20.0) + np.random.default_rng(1).random(shape)
    lap = np.empty_like(T)
    t = time.process_time()
    for _ in range(steps):
        np.multiply(T, -6.0, out=lap)
        lap[1:] += T[:-1]
        lap[:-1] += T[1:]
        lap[:, 1:] += T[:, :-1]
        lap[:, :-1] += T[:, 1:]
        lap[:, :, 1:] += T[:, :, :-1]
        lap[:, :, :-1] += T[:, :, 1:]
        T += 0.1 * lap
    return (time.process_time() - t) / (steps * T.size)


def block(args) -> None:
    """``--block`` (module docstring)."""
    import resource
    import sys
    import tempfile

    sys.path.insert(0, str(Path(__file__).resolve().parent))
    from make_demo_part import hatch_layer

    from dmdvox.process.planner import MotionSettings
    from dmdvox.thermal.build import beam_path, deposit_lattice, lattice_bytes
    from dmdvox.thermal.run import solve_history

    lines = ["M64", "G90 G21", "F750"]
    for k in range(args.layers):
        lines += hatch_layer(30.0, 30.0, k % 2 == 0, 0.8 * k)
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "block.gcode"
        path.write_text("\n".join(lines) + "\n")
        tp = read_gcode(str(path), dialect="seed")
    plan = plan_process(tp, ProcessSettings(profile="rect", width=2.5, height=0.8, model="fixed",
                                            motion=MotionSettings(accel_mm_s2=0.0)))
    sim = simulate(SimulateRequest(plan, voxel=0.2, cache=False))
    request = thermal_request(plan, sim.grid, {"material": "316L", "laser_power": 1000.0, "thermal_voxel": 0.6},
                              sim["plate_z_mm"])
    m = 3
    need = lattice_bytes(sim.grid, m, sim["plate_z_mm"], request.plate)
    lat = deposit_lattice(sim.grid, m, sim["plate_z_mm"], request.plate, end=float(tp.duration))
    warm = start(lattice_from_birth(np.full((4, 4, 4), -np.inf), np.zeros(3), 1.0), request.material,
                 request.settings)
    run(warm, SourcePath.still([0, 0, 0], 0, 1, 100.0), warm.dt * 3)
    path = beam_path(plan, 1000.0)
    until = min(float(args.heat_seconds), float(tp.duration))
    wall, cpu = time.perf_counter(), time.process_time()
    result = solve_history(lat, request.material, request.settings, path, None, until)
    wall, cpu = time.perf_counter() - wall, time.process_time() - cpu
    dt = result.state.dt

    def cell_steps(end):  # every cell from its birth (the plate: from 0) to ``end``
        b = np.clip(np.where(np.isfinite(lat.birth), lat.birth, 0.0), 0.0, None)
        return float(np.sum(np.clip(end - b, 0.0, None)) / dt)

    done = cell_steps(until)
    per = cpu / done
    plain = numpy_stencil(lat.shape, args.stencil_steps)
    out = {
        "program": f"30 x 30 x {0.8 * args.layers:g} mm block, {args.layers} layers", "build_s": float(tp.duration),
        "thermal_voxel_mm": lat.voxel, "cells": len(lat),
        "part_cells": int(np.count_nonzero(np.isfinite(lat.birth))),
        "plate_cells": int(np.count_nonzero(~np.isfinite(lat.birth))),
        "memory_bound_GiB": round(need / 2**30, 3), "time_step_s": dt,
        "heat_simulated_s": until, "heat_wall_s": round(wall, 2), "heat_cpu_s": round(cpu, 2),
        "energy_balance_max_percent": max(abs(e["balance_percent"]) for e in result.energy) if result.energy else 0.0,
        "solver_ns_per_cell_step": round(per * 1e9, 2),
        "numpy_stencil_ns_per_cell_step": round(plain * 1e9, 2),
        "solver_over_numpy": round(per / plain, 2),
        "whole_build_cell_steps": cell_steps(float(tp.duration)),
        "whole_build_projected_cpu_s": round(per * cell_steps(float(tp.duration)), 1),
        "max_rss_GiB": round(resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 2**20, 3),
    }
    print(json.dumps(out, indent=2))


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--stencil-steps", type=int, default=200)
    parser.add_argument("--block", action="store_true", help="the 30 x 30 x 48 mm block at 0.6 mm (docstring)")
    parser.add_argument("--heat-seconds", type=float, default=60.0, help="--block: the build time heated")
    parser.add_argument("--layers", type=int, default=60, help="--block: layers of 0.8 mm")
    args = parser.parse_args()
    if args.block:
        block(args)
        return
    plan = plan_process(read_gcode(str(DEMO)), ProcessSettings())
    sim = simulate(SimulateRequest(plan, cache=False))
    options = {"material": "316L", "laser_power": 1000.0}
    request = thermal_request(plan, sim.grid, options, sim["plate_z_mm"])
    # compile (or load the numba cache) on a small block first
    warm = start(lattice_from_birth(np.full((4, 4, 4), -np.inf), np.zeros(3), 1.0), request.material,
                 request.settings)
    run(warm, SourcePath.still([0, 0, 0], 0, 1, 100.0), warm.dt * 3)
    wall, cpu = time.perf_counter(), time.process_time()
    result = thermal_history(request)
    wall, cpu = time.perf_counter() - wall, time.process_time() - cpu
    s = result.summary()
    lat = result.lattice
    # per cell-step, the solver on its own lattice (the plate and the whole part born) and numpy
    state = start(lat, result.material, result.settings, t_begin=float(np.max(lat.birth[np.isfinite(lat.birth)])))
    run(state, SourcePath.still([0, 0, 0], 0, 0, 0), state.time + state.dt * 3)
    t = time.process_time()
    run(state, SourcePath.still([0, 0, 0], 0, 0, 0), state.time + state.dt * args.stencil_steps)
    solver = (time.process_time() - t) / (args.stencil_steps * state.n_born)
    plain = numpy_stencil(lat.shape, args.stencil_steps)
    out = {
        "program": str(DEMO.name),
        "deposit_voxel_mm": sim["voxel_mm"],
        "thermal_voxel_mm": s["thermal_voxel_mm"],
        "cells": s["cells"], "part_cells": s["part_cells"], "plate_cells": s["plate_cells"],
        "steps": s["steps"], "time_step_s": s["time_step_s"], "simulated_s": s["duration_s"],
        "heat_wall_s": round(wall, 2), "heat_cpu_s": round(cpu, 2),
        "energy_balance_max_percent": s["energy_balance_max_percent"],
        "solver_ns_per_cell_step": round(solver * 1e9, 2),
        "numpy_stencil_ns_per_cell_step": round(plain * 1e9, 2),
        "solver_over_numpy": round(solver / plain, 2),
        "lattice_box_cells": int(np.prod(lat.shape)),
        "bytes_per_cell": bytes_per_cell(),
        "max_peak_temperature_C": s["max_peak_temperature_C"],
        "max_interlayer_temperature_C": s["max_interlayer_temperature_C"],
    }
    print(json.dumps(out, indent=2))


if __name__ == "__main__":
    main()
