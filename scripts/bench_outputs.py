#!/usr/bin/env python3
"""The 100 mm seed block's grid through the steps that follow the deposit (issue 15): the
``.vdb`` export (sdf alone, sdf and arrival, the whole file) and the void analysis, each timed
on the same grid, best of ``--repeat``.

    PYTHONPATH=. .venv/bin/python scripts/bench_outputs.py [--repeat 2]

Run it with another checkout on ``PYTHONPATH`` to time that code on the same part.
"""

from __future__ import annotations

import argparse
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

from bench_scale import VOXEL, block_part  # noqa: E402


def best_of(repeat: int, work) -> float:
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        work()
        times.append(time.perf_counter() - start)
    return min(times)


def main() -> None:
    import dmdvox
    from dmdvox.grid.enclosure import enclosed_voids
    from dmdvox.grid.vdbio import to_openvdb, write_vdb

    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--repeat", type=int, default=2)
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        gcode, _ = block_part(Path(tmp))
        plan = dmdvox.plan(dmdvox.read_gcode(gcode, dialect="seed"))
        grid, width = dmdvox.simulate(plan, voxel=VOXEL).grid, plan.profile.width
        print(f"{dmdvox.__file__}: {grid.n_leaf:,} leaves, {grid.n_tile:,} inside tiles, "
              f"{grid.active_voxels:,} active voxels")
        to_openvdb(grid)  # compile
        enclosed_voids(grid, bead_width=width)
        rows = [("to_openvdb, sdf only", lambda: to_openvdb(grid, arrival=False)),
                ("to_openvdb, sdf and arrival", lambda: to_openvdb(grid)),
                ("write_vdb", lambda: write_vdb(grid, Path(tmp) / "block.vdb")),
                ("enclosed_voids", lambda: enclosed_voids(grid, bead_width=width))]
        for name, work in rows:
            print(f"  {name:<28} {best_of(args.repeat, work):6.2f} s")


if __name__ == "__main__":
    main()
