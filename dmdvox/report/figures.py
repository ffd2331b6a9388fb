"""The report's plots (matplotlib, inline SVG plus a PNG beside the page) and pictures (PyVista)."""

from __future__ import annotations

import io
import re
from pathlib import Path

import numpy as np

from ..io.atomic import atomic_path

_PLOT_SIZE = (7.0, 3.2)  # inches: wide and low, to sit in the page's text column
PORE_BOX_VOXELS = 64_000_000  # the pores' box is read densely up to this size


class Plot:
    """A matplotlib figure written as a PNG file and kept as SVG text for the page."""

    def __init__(self, title: str, xlabel: str, ylabel: str):
        from matplotlib.figure import Figure

        self.title = title
        self.figure = Figure(figsize=_PLOT_SIZE, layout="constrained")
        self.axes = self.figure.add_subplot()
        self.axes.set_title(title, fontsize=11)
        self.axes.set_xlabel(xlabel)
        self.axes.set_ylabel(ylabel)
        self.axes.grid(True, alpha=0.3)

    def save(self, png: Path) -> tuple[str, str, str]:
        """(PNG path, SVG text, caption): the caption is the plot's own title."""
        with atomic_path(png) as tmp:
            self.figure.savefig(tmp, dpi=150, format="png")
        text = io.StringIO()
        # text as paths: the SVG needs no font and renders alike everywhere; no date, so
        # identical inputs give identical pages
        from matplotlib import rc_context

        with rc_context({"svg.fonttype": "path", "svg.hashsalt": "dmdvox"}):
            self.figure.savefig(text, format="svg", metadata={"Date": None})
        svg = text.getvalue()
        svg = svg[svg.index("<svg"):]
        # the RDF block only names matplotlib as the author; the page says what made it
        return str(png), re.sub(r"<metadata>.*?</metadata>\s*", "", svg, flags=re.S), self.title


def layer_plot(layers: list[dict], png: Path) -> tuple[str, str, str]:
    """Void and overbuild volume per layer, against the layer's Z."""
    return layer_figure(layers).save(png)


def layer_figure(layers: list[dict]) -> Plot:
    plot = Plot("Void and overbuild per layer", "layer Z (mm)", "volume (mm³)")
    z = np.array([row["z_mm"] for row in layers], float)
    void = np.array([row["void_mm3"] for row in layers], float)
    over = np.array([row["overbuild_mm3"] for row in layers], float)
    width = 0.4 * (np.min(np.diff(z)) if z.size > 1 else 1.0)
    plot.axes.bar(z - width / 2, void, width, label="void (CAD not filled)", color="#3b6fb6")
    plot.axes.bar(z + width / 2, over, width, label="overbuild (outside CAD)", color="#d1495b")
    # beside the axes, not over them: a tall first or last layer would hide under it
    plot.axes.legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0.0)
    return plot


def pore_plot(pores: list[dict], png: Path) -> tuple[str, str, str]:
    """Histogram of pore sizes (equivalent sphere diameter) on logarithmic bins."""
    return pore_figure(pores).save(png)


def pore_bins(diameters: np.ndarray) -> np.ndarray:
    """Bin edges of equal width in log(diameter): pore sizes span decades (a voxel-sized gap to a
    missing bead), which linear bins would crush into the first bin."""
    d = np.asarray(diameters, float)
    d = d[np.isfinite(d) & (d > 0)]
    if d.size == 0:
        return np.geomspace(0.1, 1.0, 6)
    lo, hi = float(d.min()) / 1.1, float(d.max()) * 1.1
    count = min(30, max(5, int(np.sqrt(d.size)) + 1))
    return np.geomspace(lo, hi, count + 1)


def pore_figure(pores: list[dict]) -> Plot:
    plot = Plot(f"Pore sizes ({len(pores)} pore{'s' if len(pores) != 1 else ''})",
                "equivalent diameter (mm, log scale)", "pores")
    d = np.array([p["equivalent_diameter_mm"] for p in pores], float)
    plot.axes.hist(d, bins=pore_bins(d), color="#6a4c93", edgecolor="white")
    plot.axes.set_xscale("log")
    return plot


def clearance_plot(time_s: np.ndarray, clearance_mm: np.ndarray, reach_mm: float, threshold_mm: float,
                   collisions: list[dict], png: Path) -> tuple[str, str, str]:
    """Nozzle clearance (to the nearest obstacle) against build time; collisions marked."""
    plot = Plot("Nozzle clearance along the path", "build time (s)", "clearance (mm)")
    shown = np.minimum(clearance_mm, reach_mm)
    plot.axes.plot(time_s, shown, lw=0.8, color="#2a9d8f", label=f"clearance (measured up to {reach_mm:.2f} mm)")
    plot.axes.axhline(threshold_mm, color="#e9c46a", lw=1.0, ls="--", label=f"near-miss threshold {threshold_mm:g} mm")
    if collisions:
        plot.axes.scatter([c["time_s"] for c in collisions], np.zeros(len(collisions)), color="#d62828", s=12, zorder=3,
                          label=f"collisions ({len(collisions)})")
    plot.axes.set_ylim(bottom=min(0.0, float(shown.min()) if shown.size else 0.0))
    plot.axes.legend(fontsize=8, loc="upper right")
    return plot.save(png)


def sphere_mesh(centres: np.ndarray, radii: np.ndarray, segments: int = 12) -> tuple[np.ndarray, np.ndarray]:
    """UV spheres, one per centre, merged into one mesh."""
    lat = np.linspace(0.0, np.pi, segments // 2 + 1)
    lon = np.linspace(0.0, 2 * np.pi, segments, endpoint=False)
    unit = np.stack([np.outer(np.sin(lat), np.cos(lon)), np.outer(np.sin(lat), np.sin(lon)),
                     np.outer(np.cos(lat), np.ones_like(lon))], -1).reshape(-1, 3)
    rows, cols = lat.shape[0], lon.shape[0]
    r, c = np.meshgrid(np.arange(rows - 1), np.arange(cols), indexing="ij")
    a = r * cols + c
    b = r * cols + (c + 1) % cols
    quads = np.stack([a, b, b + cols, a + cols], -1).reshape(-1, 4)
    tris = np.concatenate([quads[:, [0, 1, 2]], quads[:, [0, 2, 3]]])
    n = len(centres)
    vertices = (centres[:, None, :] + radii[:, None, None] * unit[None]).reshape(-1, 3)
    triangles = (tris[None] + (np.arange(n) * unit.shape[0])[:, None, None]).reshape(-1, 3)
    return vertices, triangles


def pore_geometry(grid, pores: list[dict]) -> tuple[np.ndarray, np.ndarray, np.ndarray, str]:
    """(vertices, triangles, pore volume per vertex, what they are): the pores' walls as they
    are, or, when the pores' box is too large to read densely, spheres of equal volume."""
    from scipy.spatial import cKDTree

    from ..grid.surface import pore_surfaces

    boxes = np.array([p["bbox_mm"] for p in pores], float)
    volumes = np.array([p["volume_mm3"] for p in pores], float)
    centroids = np.array([p["centroid_mm"] for p in pores], float)
    walls = pore_surfaces(grid, boxes[:, 0].min(axis=0), boxes[:, 1].max(axis=0), PORE_BOX_VOXELS)
    if walls is not None:
        vertices, triangles, cavity_centre = walls
        # each wall takes the (sub-voxel) volume of the listed pore nearest its cavity's centroid
        return vertices, triangles, volumes[cKDTree(centroids).query(cavity_centre)[1]], "the cavity walls"
    # a pore smaller than a voxel would vanish in the picture: draw it at least that large
    radii = np.maximum(np.array([p["equivalent_diameter_mm"] for p in pores], float) / 2, grid.voxel)
    vertices, triangles = sphere_mesh(centroids, radii)
    return vertices, triangles, np.repeat(volumes, len(vertices) // len(pores)), "spheres of equal volume"


def pore_picture(geometry, surface, count: int, png: Path, size) -> str:
    """The deposit faint and its pores (:func:`pore_geometry`) coloured by volume."""
    from ..view.pictures import render_surface

    vertices, triangles, volume, what = geometry
    title = f"{count} pore{'s' if count > 1 else ''}, drawn as {what}, coloured by pore volume"
    return str(render_surface(png, vertices, triangles, scalars=volume, scalar_name="pore volume (mm³)",
                              cmap="plasma", clim=(0.0, float(volume.max())), title=title, size=size,
                              context_meshes=[(surface[0], surface[1], "lightsteelblue", 0.15)],
                              fit_context=True))


def collision_picture(surface, fixtures: list, nozzle_mesh, collisions: list[dict], voxel: float, png: Path,
                      size) -> str:
    """The part, the fixtures and the nozzle at its first collision; every collision (at least
    one) a red dot at the nozzle tip."""
    from ..view.pictures import render_surface

    tips = np.array([c["position_mm"] for c in collisions], float).reshape(-1, 3)
    contexts = [(v, t, "burlywood", 0.6) for v, t in fixtures]
    if len(surface[1]):
        contexts.append((surface[0], surface[1], "lightsteelblue", 1.0))
    contexts.append((nozzle_mesh[0] + tips[0], nozzle_mesh[1], "darkorange", 0.45))
    marker_v, marker_t = sphere_mesh(tips, np.full(len(tips), max(4 * voxel, 0.3)))
    first = collisions[0]
    title = f"first collision: line {first['line']} with {first['obstacle']} (red dots: every collision)"
    return str(render_surface(png, marker_v, marker_t, scalars=None, title=title, size=size,
                              context_meshes=contexts, fit_context=True, color="red"))
