"""The data of the report's embedded 3-D view: meshes, toolpath and collisions, packed small.

Vertex positions are quantised to 16 bits over the scene's bounding box (0.5 µm steps on a
30 mm part, 15 µm on a 1 m one: far below a voxel), indices are 32-bit, per-vertex scalars
float32, all base64 in one JSON object the page's script reads. The deposit surface is
decimated to a triangle budget so that a report stays a few MB whatever the voxel size; its
arrival times and deviations follow the decimated vertices from the nearest full-resolution
vertex, so the time slider cuts the decimated mesh where the full one would be cut.
"""

from __future__ import annotations

import base64
from dataclasses import dataclass, field

import numpy as np

MAX_SURFACE_TRIANGLES = 200_000
MAX_PATH_SEGMENTS = 400_000
COLORMAP_SAMPLES = 16


@dataclass(frozen=True, eq=False)
class SceneMesh:
    """One mesh of the view; ``scalars`` maps a name (e.g. ``arrival_s``) to one value per vertex.

    ``timed`` meshes are cut by the time slider at their ``arrival_s`` scalar; a ``capped`` one
    (a closed solid's outward surface) shows its inside, where the cut opens it, as a solid cap;
    a ``solid`` one keeps its colour whatever the view is coloured by."""

    name: str
    vertices: np.ndarray
    triangles: np.ndarray
    color: tuple[float, float, float]
    opacity: float = 1.0
    scalars: dict = field(default_factory=dict)
    timed: bool = False
    capped: bool = False
    solid: bool = False


def _b64(array: np.ndarray) -> str:
    return base64.b64encode(np.ascontiguousarray(array).tobytes()).decode("ascii")


def vertex_normals(vertices: np.ndarray, triangles: np.ndarray) -> np.ndarray:
    """Area-weighted unit vertex normals as int8 (-127..127): smooth shading for 3 bytes a vertex."""
    corners = vertices[triangles]
    face = np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0])
    normals = np.zeros_like(vertices, dtype=np.float64)
    for k in range(3):
        np.add.at(normals, triangles[:, k], face)
    length = np.linalg.norm(normals, axis=1, keepdims=True)
    normals = np.divide(normals, length, out=np.zeros_like(normals), where=length > 0)
    return np.rint(normals * 127.0).astype(np.int8)


def decimate(vertices: np.ndarray, triangles: np.ndarray, scalars: dict, max_triangles: int):
    """(vertices, triangles, scalars) with at most ``max_triangles`` triangles.

    VTK's quadric clustering: one vertex per cell of a lattice, placed by the quadric error of
    the triangles in it, so flats stay flat and edges sharp; linear in the mesh (quadric
    decimation took minutes on the 10 M triangles of a fine infill). The cell is sized from the
    surface area so that about two triangles fall to each occupied cell, and grown until the
    budget holds. Each scalar follows its nearest original vertex: interpolating arrival times
    across a layer boundary would invent times at which nothing was deposited."""
    if len(triangles) <= max_triangles:
        return vertices, triangles, scalars
    import pyvista as pv
    from scipy.spatial import cKDTree
    from vtkmodules.vtkFiltersCore import vtkQuadricClustering

    vertices = np.asarray(vertices, np.float64)
    faces = np.column_stack([np.full(len(triangles), 3, np.int64), triangles]).ravel()
    mesh = pv.PolyData(vertices, faces)
    corners = vertices[triangles]
    area = 0.5 * np.linalg.norm(np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0]), axis=1).sum()
    extent = np.ptp(vertices, axis=0)
    cell = np.sqrt(2.0 * area / max_triangles)
    while True:
        clustering = vtkQuadricClustering()
        clustering.SetInputData(mesh)
        clustering.AutoAdjustNumberOfDivisionsOff()
        clustering.SetNumberOfDivisions(*(int(n) for n in np.maximum(1, np.ceil(extent / cell))))
        clustering.Update()
        reduced = pv.wrap(clustering.GetOutput())
        if reduced.n_cells <= max_triangles:
            break
        cell *= 1.05 * np.sqrt(reduced.n_cells / max_triangles)
    new_vertices = np.asarray(reduced.points, np.float64)
    new_triangles = np.asarray(reduced.faces, np.int64).reshape(-1, 4)[:, 1:]
    nearest = cKDTree(vertices).query(new_vertices)[1]
    return new_vertices, new_triangles, {name: np.asarray(v)[nearest] for name, v in scalars.items()}


def colormap(name: str) -> list[list[float]]:
    """``COLORMAP_SAMPLES`` RGB samples of a matplotlib colour map, for the page's shader."""
    from matplotlib import colormaps

    rgba = colormaps[name](np.linspace(0.0, 1.0, COLORMAP_SAMPLES))
    return np.round(rgba[:, :3], 4).tolist()


def path_lines(tp) -> dict:
    """The toolpath as line segments (arcs as chords) with their start and end times."""
    from ..toolpath.geometry import linearized

    lin = linearized(tp)
    keep = np.flatnonzero(np.linalg.norm(lin.end - lin.start, axis=1) > 0)
    if keep.shape[0] > MAX_PATH_SEGMENTS:
        # Every k-th segment keeps the path's look and its timing; the exact path is in the G-code.
        keep = keep[:: int(np.ceil(keep.shape[0] / MAX_PATH_SEGMENTS))]
    points = np.stack([lin.start[keep], lin.end[keep]], 1).reshape(-1, 3)
    times = np.stack([lin.t_start[keep], lin.t_end[keep]], 1).reshape(-1)
    return {"points": points, "times": times, "deposit": lin.deposit[keep].astype(np.uint8)}


def scene_payload(meshes: list[SceneMesh], tp, markers: np.ndarray, standoff: float | None,
                  nozzle: tuple[np.ndarray, np.ndarray] | None, deviation_range: float | None) -> dict:
    """The JSON object the page's viewer reads (see ``viewer.js``).

    ``markers`` holds ``(x, y, z, time_s)`` rows (nozzle-tip positions of collisions); the
    ``nozzle`` mesh (tip at its origin) follows the path point at the slider's time, lifted by
    ``standoff``."""
    path = path_lines(tp)
    corners = [path["points"]] + [m.vertices for m in meshes]
    if nozzle is not None:
        corners.append(nozzle[0] + path["points"].min(axis=0) + [0, 0, standoff])
        corners.append(nozzle[0] + path["points"].max(axis=0) + [0, 0, standoff])
    everything = np.concatenate([c for c in corners if len(c)]) if any(len(c) for c in corners) else np.zeros((1, 3))
    lo, hi = everything.min(axis=0), everything.max(axis=0)
    extent = np.maximum(hi - lo, 1e-6)

    def quantised(v: np.ndarray) -> str:
        q = np.clip(np.rint((np.asarray(v) - lo) / extent * 65535.0), 0, 65535).astype("<u2")
        return _b64(q)

    def packed_mesh(m: SceneMesh) -> dict:
        return {"name": m.name, "positions": quantised(m.vertices), "indices": _b64(m.triangles.astype("<u4")),
                "normals": _b64(vertex_normals(np.asarray(m.vertices, np.float64), m.triangles)),
                "count": int(m.triangles.size), "color": list(m.color), "opacity": float(m.opacity),
                "timed": m.timed, "capped": m.capped, "solid": m.solid,
                "scalars": {k: _b64(np.asarray(v, "<f4")) for k, v in m.scalars.items()}}

    # the camera frames the first mesh (the deposit), not the travel moves or fixtures around it,
    # and the nozzle's lower third above it
    focus = meshes[0].vertices if meshes and len(meshes[0].vertices) else everything
    focus_lo, focus_hi = focus.min(axis=0), focus.max(axis=0)
    if nozzle is not None:
        focus_hi[2] += float(standoff or 0.0) + np.ptp(np.asarray(nozzle[0])[:, 2]) / 3
    payload = {
        "lo": lo.tolist(), "extent": extent.tolist(), "duration": float(tp.duration),
        "focus": [focus_lo.tolist(), focus_hi.tolist()],
        "meshes": [packed_mesh(m) for m in meshes if len(m.triangles)],
        "path": {"points": _b64(path["points"].astype("<f4")), "times": _b64(path["times"].astype("<f4")),
                 "deposit": _b64(path["deposit"]), "count": int(path["deposit"].shape[0])},
        "markers": np.asarray(markers, np.float64).reshape(-1, 4).round(4).tolist(),
        "colormaps": {"arrival_s": colormap("viridis"), "deviation_mm": colormap("coolwarm")},
        "deviation_range": deviation_range,
        "nozzle": None,
    }
    if nozzle is not None:
        payload["nozzle"] = {"positions": _b64(np.asarray(nozzle[0], "<f4")),
                             "indices": _b64(np.asarray(nozzle[1], "<u4")), "count": int(np.asarray(nozzle[1]).size),
                             "standoff": float(standoff or 0.0)}
    return payload
