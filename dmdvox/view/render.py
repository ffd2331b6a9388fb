"""`dmdvox render`: a headless picture of the part as it stands at a moment of the build."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from ..errors import DmdvoxError

VIEW_NAMES = ("iso", "top", "front")
TABLE_KINDS = ("trt-ac", "trt-bc")


def tool_pose(tp, time_s: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(path point, unit tool axis, rotary A B C) at ``time_s``: the point linear within its row,
    the row's axis, the rotary values between the previous row's end and this row's."""
    if len(tp) == 0:
        return np.zeros(3), np.array([0.0, 0.0, 1.0]), np.zeros(3)
    t = float(time_s)
    row = int(np.clip(np.searchsorted(tp.t_end, t, side="left"), 0, len(tp) - 1))
    span = tp.t_end[row] - tp.t_start[row]
    frac = float(np.clip((t - tp.t_start[row]) / span, 0.0, 1.0)) if span > 0 else 1.0
    point = tp.start[row] + frac * (tp.end[row] - tp.start[row])
    axis = np.asarray(tp.axis[row], np.float64)
    axis = axis / np.linalg.norm(axis)
    before = np.asarray(tp.rotary[row - 1] if row > 0 else tp.rotary[row], np.float64)
    rotary = before + frac * (np.asarray(tp.rotary[row], np.float64) - before)
    return point, axis, rotary


def nozzle_matrix(point, axis, standoff: float) -> np.ndarray:
    """4x4 placing a nozzle mesh (tip at the origin, axis +Z) with its tip ``standoff`` up the tool
    axis from the path point, its +Z along the axis (the minimal rotation, as `collide` poses it)."""
    from ..collision.path import axis_rotations

    Rs, _ = axis_rotations(np.asarray(axis, np.float64).reshape(1, 3))
    m = np.eye(4)
    m[:3, :3] = Rs[0]
    m[:3, 3] = np.asarray(point, np.float64) + float(standoff) * np.asarray(axis, np.float64)
    return m


def machine_axes(tp, rotary) -> np.ndarray | None:
    """The machine's X, Y, Z directions (rows) in the workpiece frame at ``rotary`` (A B C) for a
    table-table machine, whose table turns the part; None otherwise (the workpiece frame is then
    the machine's)."""
    doc = tp.meta.get("machine")
    if not doc or doc.get("kind") not in TABLE_KINDS:
        return None
    from ..toolpath.kinematics import machine_from_json, workpiece_to_machine

    joints = np.zeros((1, 6))
    joints[0, 3:] = rotary
    R, _ = workpiece_to_machine(machine_from_json(doc), joints)
    return R[0].copy()  # machine = R workpiece: row i of R is machine axis i in the workpiece frame


def tool_meshes(tp, time_s: float, bead_width: float, standoff: float = 0.0, size: float | None = None) -> list:
    """Context meshes ``(vertices, triangles, colour, opacity)`` showing the tool at ``time_s``:
    the nozzle along the tool axis at the tool point and, for a table-table machine, the machine's
    X (red), Y (green) and Z (blue) axes turned about the workpiece origin as the table turns it."""
    from ..collision.bodies import Cone

    point, axis, rotary = tool_pose(tp, time_s)
    nv, nt = Cone(tip=0.4 * bead_width, top=4.0 * bead_width, length=6.0 * bead_width).mesh(48)
    m = nozzle_matrix(point, axis, standoff)
    out = [(nv @ m[:3, :3].T + m[:3, 3], nt, "red", 0.8)]
    axes = machine_axes(tp, rotary)
    if axes is not None:
        length = size if size is not None else 6.0 * bead_width
        rod = Cone(tip=0.05 * length, top=0.05 * length, length=length).mesh(16)
        for direction, colour in zip(axes, ("red", "green", "blue")):
            r = nozzle_matrix(np.zeros(3), direction, 0.0)
            out.append((rod[0] @ r[:3, :3].T, rod[1], colour, 0.9))
    return out


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
    voxel = plan.resolve_voxel(voxel)
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
    if "machine" in tp.meta:
        # five-axis: the tool at the moment, the nozzle along the tool axis (and the table's turn
        # for a trunnion); 3-axis pictures stay as they were
        contexts += tool_meshes(tp, until if until is not None else tp.duration, plan.profile.width,
                                size=0.3 * float(np.max(full_box[1] - full_box[0])))
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
