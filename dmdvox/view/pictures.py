"""Headless PNG pictures of triangle meshes coloured by a per-vertex scalar.

Rendering is off screen through VTK's EGL window (Mesa llvmpipe on a machine without a GPU),
chosen by ``VTK_DEFAULT_OPENGL_WINDOW=vtkEGLRenderWindow`` unless the caller already set that
variable (e.g. to ``vtkOSOpenGLRenderWindow`` for OSMesa). No display or X server is needed.

Pictures use a parallel (orthographic) projection so that distances in a view are comparable
across the picture; the camera is fitted to the projected vertices of the main mesh so the part
is centred in the space left of the colour bar and fills most of it. Views: ``top`` looks down
-z with +y up the picture, ``front`` looks along +y (from the -y side) with +z up, ``iso``
looks from the (+x, -y, +z) octant, i.e. the front view turned to show the right side and top.
"""

from __future__ import annotations

import math
import os
from pathlib import Path

import numpy as np

from ..io.atomic import atomic_path

if not (os.environ.get("DISPLAY") or os.environ.get("WAYLAND_DISPLAY")):
    # No screen: render through EGL (an interactive window needs the X one VTK picks by default).
    os.environ.setdefault("VTK_DEFAULT_OPENGL_WINDOW", "vtkEGLRenderWindow")

# view name -> (direction from the part towards the camera, picture "up" vector)
VIEWS = {
    "iso": ((1.0, -1.0, 1.0), (0.0, 0.0, 1.0)),
    "top": ((0.0, 0.0, 1.0), (0.0, 1.0, 0.0)),
    "front": ((0.0, -1.0, 0.0), (0.0, 0.0, 1.0)),
}
_BACKGROUND = "white"
_TEXT = "black"
_SOLID = "lightsteelblue"
_NAN = "darkgray"
_BAR_SHARE = 0.20  # fraction of the width kept for the colour bar
_TITLE_SHARE = 0.08  # fraction of the height kept for the title
_FILL = 0.90  # the part spans this fraction of its free area along the tighter axis


def color_limits(scalars) -> tuple[float, float]:
    """Default colour range: symmetric about 0 when values have both signs, else min..max.

    Non-finite values are ignored; a constant or empty field gets a small range around its value.
    """
    s = np.asarray(scalars, np.float64)
    s = s[np.isfinite(s)]
    if s.size == 0:
        return -1.0, 1.0
    lo, hi = float(s.min()), float(s.max())
    if lo < 0.0 < hi:
        m = max(-lo, hi)
        return -m, m
    if lo == hi:
        pad = abs(lo) * 0.05 if lo != 0.0 else 1.0
        return lo - pad, hi + pad
    return lo, hi


def render_surface(
    path_png: str | os.PathLike,
    vertices,
    triangles,
    scalars=None,
    scalar_name: str = "deviation_mm",
    clim: tuple[float, float] | None = None,
    cmap: str = "coolwarm",
    view: str = "iso",
    size: tuple[int, int] = (1200, 900),
    title: str | None = None,
    context_meshes=(),
    fit_context: bool = False,
    color: str = _SOLID,
) -> Path:
    """Render a triangle mesh to a PNG file (written atomically) and return its path.

    ``scalars`` holds one value per vertex (or per triangle); without it the mesh is drawn in
    ``color`` and no colour bar is shown. NaN values are drawn grey. ``clim`` defaults to
    :func:`color_limits`. ``context_meshes`` are ``(vertices, triangles, color, opacity)``
    tuples (color and opacity optional, default light grey at 0.3) drawn translucent around
    the part, e.g. the CAD model or the substrate; the camera frames only the main mesh
    unless ``fit_context`` is true.
    """
    import pyvista as pv

    path_png = Path(path_png)
    if path_png.suffix.lower() != ".png":
        raise ValueError(f"{path_png}: pictures are written as PNG; use a .png file name")
    if view not in VIEWS:
        raise ValueError(f"unknown view {view!r}; choose one of {', '.join(VIEWS)}")
    width, height = (int(n) for n in size)
    if width < 64 or height < 64:
        raise ValueError(f"picture size {size} is too small (at least 64 x 64 pixels)")

    mesh = _polydata(pv, vertices, triangles, "mesh")
    bar = scalars is not None
    if bar:
        s = np.asarray(scalars, np.float64).reshape(-1)
        if s.shape[0] not in (mesh.n_points, mesh.n_cells):
            raise ValueError(f"scalars have {s.shape[0]} values; expected one per vertex ({mesh.n_points})"
                             f" or per triangle ({mesh.n_cells})")
        lo, hi = color_limits(s) if clim is None else (float(clim[0]), float(clim[1]))
        if not (math.isfinite(lo) and math.isfinite(hi) and lo < hi):
            raise ValueError(f"colour limits must be two finite increasing numbers, got {clim}")
        if s.shape[0] == mesh.n_points:
            mesh.point_data[scalar_name] = s
        else:
            mesh.cell_data[scalar_name] = s

    contexts = []
    for n, item in enumerate(context_meshes):
        item = tuple(item)
        if not 2 <= len(item) <= 4:
            raise ValueError("context meshes are (vertices, triangles, color, opacity) tuples")
        v, t, context_color, opacity = item + ("lightgray", 0.3)[len(item) - 2:]
        contexts.append((_polydata(pv, v, t, f"context mesh {n}"), context_color, float(opacity)))

    # a headlight keeps faces that look at the viewer at their true colour-bar colour
    plotter = pv.Plotter(off_screen=True, window_size=(width, height), lighting="none")
    shading = dict(smooth_shading=True, split_sharp_edges=True, ambient=0.3, diffuse=0.7, specular=0.1)
    try:
        plotter.add_light(pv.Light(light_type="headlight", intensity=1.0))
        plotter.set_background(_BACKGROUND)
        scale = height / 900.0
        if bar:
            plotter.add_mesh(
                mesh, scalars=scalar_name, cmap=cmap, clim=(lo, hi), nan_color=_NAN,
                show_scalar_bar=False, **shading,
            )
            plotter.add_scalar_bar(
                title=scalar_name, vertical=True, n_labels=5, fmt=_label_format(lo, hi),
                position_x=1.0 - _BAR_SHARE + 0.06, position_y=0.12, width=0.07, height=0.72,
                title_font_size=max(12, round(22 * scale)), label_font_size=max(11, round(18 * scale)),
                color=_TEXT, font_family="arial", bold=False, shadow=False,
            )
        else:
            plotter.add_mesh(mesh, color=color, **shading)
        for cmesh, context_color, opacity in contexts:
            plotter.add_mesh(cmesh, color=context_color, opacity=opacity, **shading)
        if contexts:
            plotter.enable_depth_peeling()
        if title:
            plotter.add_text(str(title), position="upper_edge", font_size=max(8, round(16 * scale)),
                             color=_TEXT, font="arial")
        plotter.add_axes(color=_TEXT, line_width=2)
        framed = [mesh.points] + ([c.points for c, _, _ in contexts] if fit_context else [])
        everything = np.concatenate([mesh.points] + [c.points for c, _, _ in contexts])
        _fit_camera(plotter, np.concatenate(framed), everything, view, width, height,
                    right_share=_BAR_SHARE if bar else 0.0, top_share=_TITLE_SHARE if title else 0.0)
        plotter.enable_anti_aliasing("ssaa")
        with atomic_path(path_png) as tmp:
            plotter.screenshot(str(tmp), window_size=(width, height))
    finally:
        plotter.close()
    return path_png


def image_is_blank(path: str | os.PathLike, tol: int = 8, max_fraction: float = 1e-4) -> bool:
    """True when (almost) every pixel has the picture's most common colour.

    A pixel counts as different when a channel differs by more than ``tol`` (0..255); the
    picture is blank when at most ``max_fraction`` of its pixels differ.
    """
    from PIL import Image

    with Image.open(path) as im:
        rgb = np.asarray(im.convert("RGB"), np.int16).reshape(-1, 3)
    packed = (rgb[:, 0].astype(np.int32) << 16) | (rgb[:, 1].astype(np.int32) << 8) | rgb[:, 2]
    values, counts = np.unique(packed, return_counts=True)
    mode = rgb[np.flatnonzero(packed == values[np.argmax(counts)])[0]]
    differ = np.any(np.abs(rgb - mode) > tol, axis=1)
    return bool(differ.mean() <= max_fraction)


def _polydata(pv, vertices, triangles, what: str):
    v = np.asarray(vertices, np.float64).reshape(-1, 3)
    t = np.asarray(triangles, np.int64).reshape(-1, 3)
    if t.shape[0] == 0 or v.shape[0] == 0:
        raise ValueError(f"{what} has no triangles to draw")
    if t.min() < 0 or t.max() >= v.shape[0]:
        raise ValueError(f"{what}: triangle indices outside 0..{v.shape[0] - 1}")
    if not np.all(np.isfinite(v)):
        raise ValueError(f"{what} has non-finite vertex coordinates")
    faces = np.hstack([np.full((t.shape[0], 1), 3, np.int64), t]).reshape(-1)
    return pv.PolyData(v, faces)


def _label_format(lo: float, hi: float) -> str:
    """printf format giving about three significant digits across the colour range."""
    span = hi - lo
    magnitude = max(abs(lo), abs(hi))
    if magnitude >= 1e5 or magnitude < 1e-3:
        return "%.2e"
    decimals = min(6, max(0, 2 - math.floor(math.log10(span))))
    return f"%.{decimals}f"


def _fit_camera(plotter, points: np.ndarray, everything: np.ndarray, view: str, width: int, height: int,
                right_share: float, top_share: float) -> None:
    """Parallel projection along the view direction, framing ``points`` in the free area.

    The camera stands outside the bounding sphere of ``everything`` so no mesh is clipped.
    """
    direction, up = (np.asarray(a, np.float64) for a in VIEWS[view])
    direction /= np.linalg.norm(direction)
    right = np.cross(up, direction)  # picture x: camera looks along -direction
    right /= np.linalg.norm(right)
    up = np.cross(direction, right)
    lo, hi = points.min(axis=0), points.max(axis=0)
    centre = (lo + hi) / 2
    rel = points - centre
    u, v = rel @ right, rel @ up
    u_mid, v_mid = (u.min() + u.max()) / 2, (v.min() + v.max()) / 2
    u_span, v_span = max(u.max() - u.min(), 1e-9), max(v.max() - v.min(), 1e-9)
    free_w = width * (1.0 - right_share)
    # parallel scale = half the visible world height
    scale = max(u_span * height / (2 * free_w * _FILL), v_span / (2 * (1.0 - top_share) * _FILL))
    world_per_px = 2 * scale / height
    # move the focal point so the part's centre lands in the middle of the free area
    focal = centre + right * (u_mid + width * right_share / 2 * world_per_px) \
        + up * (v_mid + height * top_share / 2 * world_per_px)
    radius = float(np.linalg.norm(everything - focal, axis=1).max()) + 1e-9
    camera = plotter.camera
    camera.parallel_projection = True
    camera.focal_point = tuple(focal)
    camera.position = tuple(focal + direction * 4 * radius)
    camera.up = tuple(up)
    camera.parallel_scale = scale
    plotter.renderer.ResetCameraClippingRange()
