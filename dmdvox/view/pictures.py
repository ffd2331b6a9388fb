"""Headless PNG pictures of triangle meshes coloured by a per-vertex scalar.

Rendering is off screen through VTK's EGL window (Mesa llvmpipe on a machine without a GPU),
chosen by ``VTK_DEFAULT_OPENGL_WINDOW=vtkEGLRenderWindow`` unless the caller already set that
variable (e.g. to ``vtkOSOpenGLRenderWindow`` for OSMesa). No display or X server is needed.

Pictures use a parallel (orthographic) projection so that distances in a view are comparable
across the picture, and a scale bar (a round length in mm) gives them; the camera is fitted to
the projected vertices of the main mesh so the part is centred in the space left of the colour
bar, between the title and the scale bar, and fills most of it. The colour bar is titled in
words with the unit (:data:`SCALAR_TITLES` for the names dmdvox writes). Views: ``top`` looks down
-z with +y up the picture, ``front`` looks along +y (from the -y side) with +z up, ``iso``
looks from the (+x, -y, +z) octant, i.e. the front view turned to show the right side and top.
"""

from __future__ import annotations

import math
import os
from pathlib import Path

import numpy as np

from ..grid.levelset import mesh_area
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
_SCALE_SHARE = 0.07  # fraction of the height kept for the scale bar
_FILL = 0.90  # the part spans this fraction of its free area along the tighter axis

# colour-bar titles, in words with the unit, of the scalars dmdvox writes
SCALAR_TITLES = {
    "arrival_s": "deposition time (s)",
    "deviation_mm": "deviation from CAD (mm)\n+ = excess material",
    "layer": "layer number (0 = lowest)",
    "feed_mm_s": "feed (mm/s)",
    "bead_area_mm2": "bead cross-section area (mm²)",
    "change_mm": "change from old (mm)\n+ = added, - = removed",
}


COLOUR_BAR_KEY = "Colour bar"  # the PNG text keyword holding the colour bar's title
# a picture's triangle budget: at its ~1 M pixels a finer mesh looks the same (a 100 mm part's
# CAD surface at 0.1 mm has 4 M triangles, whose normals alone took 5 s)
PICTURE_TRIANGLES = 400_000


def scalar_title(name: str) -> str:
    """The colour-bar title of a scalar: its words and unit when dmdvox knows the name."""
    return SCALAR_TITLES.get(name, name)


def scale_bar_length(world_per_px: float, most_px: float) -> float:
    """The longest round length (1, 2 or 5 times a power of ten, mm) drawn in at most ``most_px`` pixels."""
    most = most_px * world_per_px
    power = 10.0 ** math.floor(math.log10(most))
    return next((m * power for m in (5.0, 2.0, 1.0) if m * power <= most * (1 + 1e-9)), power)


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

    vertices = np.ascontiguousarray(vertices, np.float64)
    triangles = np.ascontiguousarray(triangles, np.int64)
    mesh = pv.PolyData.from_regular_faces(vertices, triangles)
    area = mesh_area(vertices, triangles)
    extent = vertices.max(axis=0) - vertices.min(axis=0)
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
    # an unbalanced tree builds in a third of the time and finds the same nearest vertices
    nearest = cKDTree(vertices, balanced_tree=False, compact_nodes=False).query(new_vertices)[1]
    return new_vertices, new_triangles, {name: np.asarray(v)[nearest] for name, v in scalars.items()}


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
    bar_title: str | None = None,
    scale_bar: bool = True,
) -> Path:
    """Render a triangle mesh to a PNG file (written atomically) and return its path.

    ``scalars`` holds one value per vertex (or per triangle); without it the mesh is drawn in
    ``color`` and no colour bar is shown. NaN values are drawn grey. ``clim`` defaults to
    :func:`color_limits`. ``context_meshes`` are ``(vertices, triangles, color, opacity)``
    tuples (color and opacity optional, default light grey at 0.3) drawn translucent around
    the part, e.g. the CAD model or the substrate; the camera frames only the main mesh
    unless ``fit_context`` is true. ``bar_title`` titles the colour bar (default
    :func:`scalar_title` of ``scalar_name``); ``scale_bar`` draws a round length in mm at the
    bottom, true in the picture's plane (the projection is parallel).
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

    if len(triangles) > PICTURE_TRIANGLES and (scalars is None or len(scalars) == len(vertices)):
        # more triangles than pixels draw nothing more, and their normals cost seconds
        kept = {} if scalars is None else {"s": np.asarray(scalars, np.float64).reshape(-1)}
        vertices, triangles, kept = decimate(vertices, triangles, kept, PICTURE_TRIANGLES)
        scalars = kept.get("s")
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
            bar_actor = plotter.add_scalar_bar(
                title=scalar_name, vertical=True, n_labels=5, fmt=_label_format(lo, hi),
                position_x=1.0 - _BAR_SHARE + 0.06, position_y=0.12, width=0.07, height=0.62,
                title_font_size=max(12, round(22 * scale)), label_font_size=max(11, round(18 * scale)),
                color=_TEXT, font_family="arial", bold=False, shadow=False,
            )
            # VTK squeezes a title into the bar's width; words with a unit need the whole column
            bar_actor.SetTitle("")
            bar_title = scalar_title(scalar_name) if bar_title is None else bar_title
            _add_text(plotter, bar_title, (1.0 - _BAR_SHARE / 2) * width, 0.775 * height,
                      max(10, round(17 * scale)), centred=True)
        else:
            plotter.add_mesh(mesh, color=color, **shading)
        for cmesh, context_color, opacity in contexts:
            plotter.add_mesh(cmesh, color=context_color, opacity=opacity, **shading)
        if contexts:
            plotter.enable_depth_peeling()
        if title:
            # a long title (a long file name) gets a smaller font rather than losing its ends;
            # at this font size one character is about 1.3 units wide
            fits = int(0.92 * width / (1.3 * max(len(str(title)), 1)))
            plotter.add_text(str(title), position="upper_edge", font_size=max(6, min(round(16 * scale), fits)),
                             color=_TEXT, font="arial")
        plotter.add_axes(color=_TEXT, line_width=2)
        framed = [mesh.points] + ([c.points for c, _, _ in contexts] if fit_context else [])
        everything = np.concatenate([mesh.points] + [c.points for c, _, _ in contexts])
        world_per_px = _fit_camera(plotter, np.concatenate(framed), everything, view, width, height,
                                   right_share=_BAR_SHARE if bar else 0.0, top_share=_TITLE_SHARE if title else 0.0,
                                   bottom_share=_SCALE_SHARE if scale_bar else 0.0)
        if scale_bar:
            _add_scale_bar(plotter, world_per_px, width, height, scale)
        plotter.enable_anti_aliasing("ssaa")
        image = plotter.screenshot(return_img=True, window_size=(width, height))
        # the title travels in the file too (PNG "Title" text), so a page's caption is the title;
        # so does the colour bar's, for whoever reads the picture's values back
        _write_png(path_png, image, title, bar_title if bar else None)
    finally:
        plotter.close()
    return path_png


def cad_deviation_picture(out: Path, stem: str, cad_surface, size: tuple[int, int] = (1200, 900)) -> list[Path]:
    """The comparison's picture: the CAD surface coloured by signed deviation (+ = excess)."""
    vertices, triangles, deviation = cad_surface
    return [render_surface(Path(out) / f"{stem}_cad_deviation.png", vertices, triangles, scalars=deviation,
                           scalar_name="deviation_mm", size=size, title=f"{stem}: CAD surface deviation")]


def diff_picture(out: Path, stem: str, new_surface, old_surface, size: tuple[int, int] = (1200, 900)) -> list[Path]:
    """The diff's picture: the new part's surface coloured by its distance from the old part's
    (+ = material added, - = removed; clamped at the old grid's band), the old part translucent."""
    vertices, triangles, change = new_surface
    reach = float(np.max(np.abs(change))) if len(change) else 0.0
    clim = (-reach, reach) if reach > 0 else None
    return [render_surface(Path(out) / f"{stem}_diff.png", vertices, triangles, scalars=change,
                           scalar_name="change_mm", clim=clim, size=size, title=f"{stem}: material added and removed",
                           context_meshes=[(old_surface[0], old_surface[1], "lightgray", 0.25)], fit_context=True)]


def _write_png(path: Path, image: np.ndarray, title: str | None, bar_title: str | None = None) -> None:
    from PIL import Image
    from PIL.PngImagePlugin import PngInfo

    info = PngInfo()
    if title:
        info.add_itxt("Title", str(title))  # international text: any character of the title
    if bar_title:
        info.add_itxt(COLOUR_BAR_KEY, str(bar_title))
    info.add_text("Software", "dmdvox")
    with atomic_path(path) as tmp:
        Image.fromarray(np.asarray(image, np.uint8)).save(tmp, format="PNG", pnginfo=info)


def png_title(path: str | os.PathLike) -> str | None:
    """The title a picture was drawn with (its PNG "Title" text), or None."""
    from PIL import Image

    with Image.open(path) as im:
        return im.info.get("Title")


def png_colour_bar_title(path: str | os.PathLike) -> str | None:
    """The title of a picture's colour bar as drawn (its PNG text :data:`COLOUR_BAR_KEY`), or
    None for a picture without a colour bar."""
    from PIL import Image

    with Image.open(path) as im:
        return im.info.get(COLOUR_BAR_KEY)


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


def _add_text(plotter, text: str, x: float, y: float, size: int, centred: bool = False):
    """A text at pixel ``(x, y)`` (from the bottom left); centred on x when ``centred``, growing
    upwards from y (a second line goes above the first)."""
    import vtk

    actor = vtk.vtkTextActor()
    actor.SetInput(text)
    prop = actor.GetTextProperty()
    prop.SetFontSize(size)
    prop.SetFontFamilyToArial()
    prop.SetColor(0.0, 0.0, 0.0)
    if centred:
        prop.SetJustificationToCentered()
    prop.SetVerticalJustificationToBottom()
    actor.SetDisplayPosition(int(round(x)), int(round(y)))
    plotter.renderer.AddViewProp(actor)
    return actor


# where the scale bar starts: right of the axes widget in the bottom-left corner
_SCALE_X = 0.22


def scale_bar_pixels(world_per_px: float, width: int) -> tuple[float, float]:
    """(length mm, length px) of the scale bar of a picture ``width`` pixels wide."""
    length = scale_bar_length(world_per_px, 0.2 * width)
    return length, length / world_per_px


def _add_scale_bar(plotter, world_per_px: float, width: int, height: int, scale: float) -> None:
    """A round length as a bar with end ticks and its value, in the strip under the part."""
    import vtk

    length, px = scale_bar_pixels(world_per_px, width)
    x0, y0 = _SCALE_X * width, 0.03 * height
    tick = max(4.0, 8.0 * scale)
    points = vtk.vtkPoints()
    for x, y in ((x0, y0 + tick), (x0, y0), (x0 + px, y0), (x0 + px, y0 + tick)):
        points.InsertNextPoint(x, y, 0.0)
    lines = vtk.vtkCellArray()
    lines.InsertNextCell(4)
    for i in range(4):
        lines.InsertCellPoint(i)
    poly = vtk.vtkPolyData()
    poly.SetPoints(points)
    poly.SetLines(lines)
    mapper = vtk.vtkPolyDataMapper2D()
    mapper.SetInputData(poly)
    actor = vtk.vtkActor2D()
    actor.SetMapper(mapper)
    actor.GetProperty().SetColor(0.0, 0.0, 0.0)
    actor.GetProperty().SetLineWidth(max(2.0, 3.0 * scale))
    plotter.renderer.AddViewProp(actor)
    label = f"{length:g} mm"
    _add_text(plotter, label, x0 + px + 10 * scale, y0 - 2 * scale, max(11, round(18 * scale)))


def _fit_camera(plotter, points: np.ndarray, everything: np.ndarray, view: str, width: int, height: int,
                right_share: float, top_share: float, bottom_share: float = 0.0) -> float:
    """Parallel projection along the view direction, framing ``points`` in the free area; returns
    the picture's scale (mm per pixel).

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
    free_h = 1.0 - top_share - bottom_share
    scale = max(u_span * height / (2 * free_w * _FILL), v_span / (2 * free_h * _FILL))
    world_per_px = 2 * scale / height
    # move the focal point so the part's centre lands in the middle of the free area
    focal = centre + right * (u_mid + width * right_share / 2 * world_per_px) \
        + up * (v_mid + height * (top_share - bottom_share) / 2 * world_per_px)
    radius = float(np.linalg.norm(everything - focal, axis=1).max()) + 1e-9
    camera = plotter.camera
    camera.parallel_projection = True
    camera.focal_point = tuple(focal)
    camera.position = tuple(focal + direction * 4 * radius)
    camera.up = tuple(up)
    camera.parallel_scale = scale
    plotter.renderer.ResetCameraClippingRange()
    return world_per_px
