"""`dmdvox simulate`: deposit a toolpath, analyse it, write the grid and its surface."""

from __future__ import annotations

import json
import sys
import time
from pathlib import Path

import numpy as np

from .. import __version__
from ..errors import DmdvoxError
from ..toolpath.model import Toolpath
from .engine import default_voxel, deposit
from ..process.profiles import BeadProfile

SINGLE_LAYER_HEIGHT_RATIO = 0.4  # height/width when a one-layer program gives no layer step


def bead_from_options(tp: Toolpath, profile: str, width: float, height: float | None,
                      exponent: float) -> BeadProfile:
    """The bead for a run: height defaults to the detected layer step."""
    if height is None:
        height = tp.layer_step if tp.layer_step > 0 else SINGLE_LAYER_HEIGHT_RATIO * width
    return BeadProfile(profile, float(width), float(height), float(exponent))


def inputs_from_args(args) -> tuple[Toolpath, BeadProfile, int | None]:
    """For the grid-building commands: the toolpath (its warnings to stderr), the bead from the
    bead options, and ``--max-memory`` in bytes."""
    from ..toolpath.reader import read_gcode_args

    tp = read_gcode_args(args)
    bead = bead_from_options(tp, args.profile, args.width, args.height, args.exponent)
    max_memory = None if args.max_memory is None else int(args.max_memory * 2**30)
    return tp, bead, max_memory


def _progress_callback():
    if not sys.stderr.isatty():
        return None, None
    from tqdm import tqdm

    bar = tqdm(total=0, unit="block layer", desc="deposit", file=sys.stderr, leave=False)

    def update(done, total):
        bar.total = total
        bar.n = done
        bar.refresh()

    return update, bar


def simulate(tp: Toolpath, bead: BeadProfile, voxel: float | None = None, until: float | None = None,
             out_dir: str | Path | None = None, max_memory: int | None = None, extra_bounds=None,
             scheduler: str | None = None) -> dict:
    """Run the deposit and its analyses; write outputs to ``out_dir`` when given.

    The result holds the JSON summary plus ``grid`` (the SparseGrid), ``porosity`` and
    ``surface``: with ``out_dir``, the (vertices, triangles, arrival) it wrote, else None.
    """
    from ..grid.analysis import deposit_bbox, porosity
    from ..grid.surface import surface_arrival, surface_mesh
    from ..grid.vdbio import write_vdb
    from ..io.atomic import write_text
    from ..io.mesh import write_ply, write_stl, write_vtp

    voxel = default_voxel(bead) if voxel is None else float(voxel)
    if until is not None and not np.isfinite(until):
        raise DmdvoxError(f"--until must be a finite time in seconds, got {until}")
    progress, bar = _progress_callback()
    try:
        grid, timings = deposit(tp, bead, voxel, until=until, max_memory=max_memory, progress=progress,
                                extra_bounds=extra_bounds, scheduler=scheduler)
    finally:
        if bar is not None:
            bar.close()
    t = time.perf_counter()
    result_pores = porosity(grid)
    timings["porosity_s"] = time.perf_counter() - t
    outputs = []
    surface = None
    if out_dir is not None:
        out = Path(out_dir)
        stem = Path(tp.source).stem or "deposit"
        t = time.perf_counter()
        meta = {"profile": bead.name, "width_mm": bead.width, "height_mm": bead.height, "voxel_mm": voxel,
                "source": str(tp.source), "dmdvox_version": __version__}
        outputs.append(str(write_vdb(grid, out / f"{stem}.vdb", meta)))
        timings["vdb_s"] = time.perf_counter() - t
        t = time.perf_counter()
        vertices, triangles = surface_mesh(grid)
        arrival = surface_arrival(grid, vertices)
        surface = (vertices, triangles, arrival)
        outputs.append(str(write_vtp(out / f"{stem}_surface.vtp", vertices, triangles,
                                     point_arrays={"arrival_s": np.where(np.isfinite(arrival), arrival, -1.0)})))
        outputs.append(str(write_stl(out / f"{stem}_surface.stl", vertices, triangles)))
        outputs.append(str(write_ply(out / f"{stem}_surface.ply", vertices, triangles)))
        timings["surface_s"] = time.perf_counter() - t
    pores = [{
        "volume_mm3": p.volume_mm3,
        "centroid_mm": [float(v) for v in p.centroid_mm],
        "bbox_mm": np.asarray(p.bbox_mm, float).tolist(),
        "equivalent_diameter_mm": p.equivalent_diameter_mm,
    } for p in result_pores.pores]
    summary = {
        "voxel_mm": voxel,
        "deposit_volume_mm3": result_pores.deposit_volume_mm3,
        "active_voxels": int(grid.active_voxels),
        "memory_bytes": int(grid.memory_bytes),
        "pore_count": len(pores),
        "pores": pores,
        "porosity_percent": result_pores.porosity_percent,
        "bbox_mm": deposit_bbox(grid).tolist(),
        "outputs": outputs,
        "timings_s": {k: round(float(v), 4) for k, v in timings.items() if k.endswith("_s")},
    }
    if out_dir is not None:
        summary_path = Path(out_dir) / f"{Path(tp.source).stem or 'deposit'}_simulate.json"
        summary["outputs"].append(str(summary_path))
        write_text(summary_path, json.dumps(summary, indent=2))
    summary["grid"] = grid
    summary["porosity"] = result_pores
    summary["surface"] = surface
    return summary
