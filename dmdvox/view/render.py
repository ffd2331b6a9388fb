"""`dmdvox render`: a headless picture of the part as it stands at a moment of the build."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from ..errors import DmdvoxError

VIEW_NAMES = ("iso", "top", "front")


def parse_size(text: str) -> tuple[int, int]:
    try:
        width, height = (int(v) for v in text.lower().split("x"))
    except ValueError:
        raise DmdvoxError(f"--size: expected WIDTHxHEIGHT in pixels (e.g. 1200x900), got '{text}'") from None
    if not (64 <= width <= 8192 and 64 <= height <= 8192):
        raise DmdvoxError(f"--size: {width}x{height} is outside 64..8192 pixels per side")
    return width, height


def moment(tp, at: float | None, time_s: float | None) -> float | None:
    """The build time to show: ``--time`` in seconds or ``--at`` as a fraction of the build."""
    if at is not None and time_s is not None:
        raise DmdvoxError("give --at FRACTION or --time S, not both")
    if at is not None:
        if not 0.0 <= at <= 1.0:
            raise DmdvoxError(f"--at must be a fraction of the build between 0 and 1, got {at}")
        return at * tp.duration
    if time_s is not None and not np.isfinite(time_s):
        raise DmdvoxError(f"--time must be a finite number of seconds, got {time_s}")
    return time_s


def render_moment(plan, png: str | Path, voxel: float | None = None, at: float | None = None,
                  time_s: float | None = None, view: str = "iso", size=(1200, 900), cad_path=None,
                  max_memory: int | None = None) -> dict:
    """Deposit the plan's beads up to the moment, mesh them, colour them by arrival time, and
    write the PNG.

    The camera frames the whole build (and the CAD part), so pictures of different moments of
    one program line up."""
    from ..deposit.engine import build_primitives, deposit_beads
    from ..grid.surface import surface_arrival, surface_mesh
    from ..io.mesh import box_mesh, read_stl
    from .pictures import render_surface

    if view not in VIEW_NAMES:
        raise DmdvoxError(f"--view: unknown view '{view}'; choose one of {', '.join(VIEW_NAMES)}")
    tp = plan.toolpath
    until = moment(tp, at, time_s)
    voxel = plan.default_voxel() if voxel is None else float(voxel)
    stamp = f"t = {until:.1f} s of {tp.duration:.1f} s" if until is not None else f"{tp.duration:.1f} s build"
    if not tp.deposit.any():
        raise DmdvoxError(f"{tp.source}: the program deposits nothing; check --dialect and the laser codes")
    beads = plan.lay(voxel, max_memory=max_memory).beads
    prims = build_primitives(beads)
    full_box = np.stack([prims.lo.min(axis=0), prims.hi.max(axis=0)])
    contexts = [(*box_mesh(*full_box), "white", 0.0)]
    if cad_path is not None:
        cad_vertices, cad_triangles = read_stl(cad_path)
        contexts.append((cad_vertices, cad_triangles, "lightgray", 0.25))
    shown = beads.until(until) if until is not None else beads
    if len(shown) == 0:
        vertices, triangles, arrival = np.zeros((0, 3)), np.zeros((0, 3), np.int64), None
    else:
        grid, _ = deposit_beads(shown, voxel, max_memory=max_memory)
        vertices, triangles = surface_mesh(grid)
        arrival = surface_arrival(grid, vertices)
    if len(triangles) == 0:
        # Nothing deposited yet: show the frame (and the CAD) only.
        vertices, triangles = box_mesh(full_box[0], full_box[0] + 1e-3)
        arrival = None
    path = render_surface(png, vertices, triangles, scalars=arrival, scalar_name="arrival_s",
                          clim=(0.0, max(tp.duration, 1e-9)) if arrival is not None else None, cmap="viridis",
                          view=view, size=size, title=f"{Path(tp.source).name}: {stamp}", context_meshes=contexts,
                          fit_context=True)
    return {"png": str(path), "time_s": until if until is not None else tp.duration, "triangles": int(len(triangles))}
