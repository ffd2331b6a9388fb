#!/usr/bin/env python3
"""The 100 mm seed block's grid through the steps that follow the deposit (issue 15): the
``.vdb`` export (sdf alone, sdf and arrival, the whole file), the void analysis, the surface and
what the outputs do with it (decimation, exact distances' set-up, STL, arrival times), the CAD
box's level set on the deposit's lattice, and the deposit cache's store and load where the
checkout has one; each timed on the same grid, best of ``--repeat``.

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
    from dmdvox.comparison.distance import MeshDistance
    from dmdvox.grid.enclosure import enclosed_voids
    from dmdvox.grid.levelset import like_grid
    from dmdvox.grid.surface import surface_arrival, surface_mesh
    from dmdvox.grid.vdbio import to_openvdb, write_vdb
    from dmdvox.io.mesh import box_mesh, write_stl
    from dmdvox.view.pictures import decimate

    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--repeat", type=int, default=2, help="runs of each step; the first one compiles")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        gcode, _ = block_part(Path(tmp))
        plan = dmdvox.plan(dmdvox.read_gcode(gcode, dialect="seed"))
        simulation = dmdvox.simulate(plan, voxel=VOXEL)
        grid, width = simulation.grid, plan.profile.width
        print(f"{dmdvox.__file__}: {grid.n_leaf:,} leaves, {grid.n_tile:,} inside tiles, "
              f"{grid.active_voxels:,} active voxels")
        vertices, triangles = surface_mesh(grid)
        print(f"  surface: {len(triangles):,} triangles")
        cad = box_mesh((0.0, 0.0, 0.0), (100.0, 100.0, 50.4))
        rows = [("to_openvdb, sdf only", lambda: to_openvdb(grid, arrival=False)),
                ("to_openvdb, sdf and arrival", lambda: to_openvdb(grid)),
                ("write_vdb", lambda: write_vdb(grid, Path(tmp) / "block.vdb")),
                ("enclosed_voids", lambda: enclosed_voids(grid, bead_width=width)),
                ("surface_mesh", lambda: surface_mesh(grid)),
                ("decimate to 400 k", lambda: decimate(vertices, triangles, {"z": vertices[:, 2]}, 400_000)),
                ("MeshDistance set-up", lambda: MeshDistance(vertices, triangles)),
                ("write_stl", lambda: write_stl(Path(tmp) / "surface.stl", vertices, triangles)),
                ("surface_arrival", lambda: surface_arrival(grid, vertices)),
                ("like_grid (the CAD box)", lambda: like_grid(*cad, grid))]
        try:
            from dmdvox.deposit.cache import DepositCache
        except ImportError:
            print("  (no deposit cache in this checkout)")
        else:
            cache = DepositCache(Path(tmp) / "cache", min_active_voxels=0)
            key = cache.key(simulation.beads, VOXEL, None, width)
            rows += [("deposit cache: store", lambda: cache.store(key, grid, simulation.porosity)),
                     ("deposit cache: load", lambda: cache.load(key, VOXEL, None))]
        for name, work in rows:
            print(f"  {name:<28} {best_of(args.repeat, work):6.2f} s", flush=True)


if __name__ == "__main__":
    main()
