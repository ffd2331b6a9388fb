"""The report's plots (matplotlib, inline SVG plus a PNG beside the page) and pictures (PyVista)."""

from __future__ import annotations

import io
import re
from pathlib import Path

import numpy as np

from ..io.atomic import atomic_path

_PLOT_SIZE = (7.0, 3.2)  # inches: wide and low, to sit in the page's text column


class Plot:
    """A matplotlib figure written as a PNG file and kept as SVG text for the page.

    With ``lower_ylabel`` a second, lower panel shares the x axis (``self.lower``): a quantity
    derived from the upper one, read against the same x."""

    def __init__(self, title: str, xlabel: str, ylabel: str, lower_ylabel: str | None = None):
        from matplotlib.figure import Figure

        self.title = title
        if lower_ylabel is None:
            self.figure = Figure(figsize=_PLOT_SIZE, layout="constrained")
            self.axes = self.figure.add_subplot()
            self.lower = None
            self.axes.set_xlabel(xlabel)
        else:
            self.figure = Figure(figsize=(_PLOT_SIZE[0], _PLOT_SIZE[1] * 1.45), layout="constrained")
            self.axes, self.lower = self.figure.subplots(2, 1, sharex=True, height_ratios=(2, 1))
            self.lower.set_xlabel(xlabel)
            self.lower.set_ylabel(lower_ylabel)
            self.lower.grid(True, alpha=0.3)
        self.axes.set_title(title, fontsize=11)
        self.axes.set_ylabel(ylabel)
        self.axes.grid(True, alpha=0.3)

    def legend_below(self, axes=None, ncol: int = 3) -> None:
        """One legend for the lines of ``axes`` (default: the upper panel), under the plot: beside
        it, it would squeeze the axes when the page sets plots two abreast."""
        handles = [h for ax in (axes or [self.axes]) for h in ax.get_legend_handles_labels()[0]]
        if sum(len(h.get_label()) for h in handles) > 75:  # one row of long labels would not fit the width
            ncol = min(ncol, 2)
        self.figure.legend(handles=handles, loc="outside lower center", ncol=ncol, fontsize=8, frameon=False)

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


def pore_geometry(voids, surface, pores: list[dict]) -> tuple[np.ndarray, np.ndarray, np.ndarray, str]:
    """(vertices, triangles, pore volume per vertex, what they are): the walls of the pores, cut
    from the deposit's full ``surface`` (vertices, triangles) where a pore lies beyond the face
    (:func:`~dmdvox.grid.enclosure.void_walls`: no dense read, any part size), and spheres of
    equal volume for the pores too thin to have a wall of their own at this voxel."""
    from ..grid.enclosure import void_walls

    vertices, triangles = surface
    volumes = np.array([p["volume_mm3"] for p in pores], float)
    walls, owner = void_walls(voids, vertices, triangles)
    used, local = np.unique(triangles[walls], return_inverse=True)
    wall_vertices = vertices[used]
    wall_volume = np.zeros(len(used))
    wall_volume[local.reshape(-1, 3)] = volumes[owner][:, None]
    bare = np.setdiff1d(np.arange(len(pores)), owner)
    what = [f"{len(pores) - len(bare)} drawn as walls"] if len(bare) < len(pores) else []
    parts = [(wall_vertices, local.reshape(-1, 3).astype(np.int64), wall_volume)]
    if len(bare):
        # a pore smaller than a voxel would vanish in the picture: draw it at least that large
        radii = np.maximum(np.array([pores[i]["equivalent_diameter_mm"] for i in bare], float) / 2, voids.voxel)
        centroids = np.array([pores[i]["centroid_mm"] for i in bare], float).reshape(-1, 3)
        sphere_v, sphere_t = sphere_mesh(centroids, radii)
        parts.append((sphere_v, sphere_t, np.repeat(volumes[bare], len(sphere_v) // len(bare))))
        what.append(f"{len(bare)} as spheres of equal volume")
    offsets = np.cumsum([0] + [len(v) for v, _, _ in parts[:-1]])
    return (np.concatenate([v for v, _, _ in parts]),
            np.concatenate([t + o for (_, t, _), o in zip(parts, offsets)]),
            np.concatenate([c for _, _, c in parts]),
            " and ".join(what))


def pore_picture(geometry, surface, count: int, png: Path, size) -> str:
    """The deposit faint and its pores (:func:`pore_geometry`) coloured by volume."""
    from ..view.pictures import render_surface

    vertices, triangles, volume, what = geometry
    title = f"{count} pore{'s' if count > 1 else ''} ({what}), coloured by pore volume"
    return str(render_surface(png, vertices, triangles, scalars=volume, scalar_name="pore volume (mm³)",
                              cmap="plasma", clim=(0.0, float(volume.max())), title=title, size=size,
                              context_meshes=[(surface[0], surface[1], "lightsteelblue", 0.15)],
                              fit_context=True))


def collision_picture(surface, fixtures: list, nozzle_mesh, collisions: list[dict], voxel: float, png: Path,
                      size) -> str:
    """The part (``surface``: as it stood at the first collision), the fixtures and the nozzle
    at its first collision; every collision (at least one) a red dot at the nozzle tip."""
    from ..view.pictures import render_surface

    tips = np.array([c["position_mm"] for c in collisions], float).reshape(-1, 3)
    contexts = [(v, t, "burlywood", 0.6) for v, t in fixtures]
    if len(surface[1]):
        contexts.append((surface[0], surface[1], "lightsteelblue", 1.0))
    contexts.append((nozzle_mesh[0] + tips[0], nozzle_mesh[1], "darkorange", 0.45))
    marker_v, marker_t = sphere_mesh(tips, np.full(len(tips), max(4 * voxel, 0.3)))
    first = collisions[0]
    title = (f"first collision: line {first['line']} with {first['obstacle']} at t = {first['time_s']:.1f} s, the part "
             "as it stood then (red dots: every collision)")
    return str(render_surface(png, marker_v, marker_t, scalars=None, title=title, size=size,
                              context_meshes=contexts, fit_context=True, color="red"))


# -- material, speed and growth along the path ---------------------------------------------------

MAX_PLOT_POINTS = 4000  # beyond this a series is drawn as its min..max band per time bin: the SVG stays small
BAND_BINS = 800  # about one bin per drawn pixel of a plot in the page's column


def polyline_series(times, values, gap_s: float = 1e-9) -> tuple[np.ndarray, np.ndarray]:
    """(x, y) of one polyline per row of ``times``/``values`` (k rows, m points, time order):
    a row is joined to the next where it ends when the next starts, and broken by a NaN
    elsewhere (travel, a pause), so that no line bridges time when nothing was deposited."""
    times = np.asarray(times, np.float64)
    values = np.asarray(values, np.float64)
    if times.ndim != 2 or times.shape[0] == 0:
        return np.zeros(0), np.zeros(0)
    k, m = times.shape
    gap = np.append(times[1:, 0] > times[:-1, -1] + gap_s, False)
    x = np.concatenate([times, np.full((k, 1), np.nan)], axis=1)
    y = np.concatenate([values, np.full((k, 1), np.nan)], axis=1)
    keep = np.ones((k, m + 1), bool)
    keep[:, m] = gap
    return x[keep], y[keep]


def step_series(t0, t1, values, gap_s: float = 1e-9) -> tuple[np.ndarray, np.ndarray]:
    """(x, y) of a quantity constant over each interval ``[t0, t1]`` (time order)."""
    t0, t1, values = (np.asarray(a, np.float64).reshape(-1) for a in (t0, t1, values))
    return polyline_series(np.column_stack([t0, t1]), np.column_stack([values, values]), gap_s)


def series_band(x, y, bins: int = BAND_BINS) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(x, lo, hi) of a step band: the min..max of a polyline (NaN breaks) over each of ``bins``
    equal x bins. A segment crossing a bin counts where it crosses the bin's edges, since a long
    cruise has no sample inside most bins; a bin the line skips entirely (a break) is NaN."""
    x = np.asarray(x, np.float64)
    y = np.asarray(y, np.float64)
    ok = np.isfinite(x) & np.isfinite(y)
    if not ok.any():
        return np.zeros(0), np.zeros(0), np.zeros(0)
    edges = np.linspace(x[ok].min(), x[ok].max(), bins + 1)
    lo = np.full(bins, np.inf)
    hi = np.full(bins, -np.inf)
    at = np.clip(np.searchsorted(edges, x[ok], side="right") - 1, 0, bins - 1)
    np.minimum.at(lo, at, y[ok])
    np.maximum.at(hi, at, y[ok])
    pair = ok[:-1] & ok[1:]
    xa, ya, xb, yb = x[:-1][pair], y[:-1][pair], x[1:][pair], y[1:][pair]
    if xa.size:
        k = np.searchsorted(xa, edges, side="right") - 1
        kk = np.clip(k, 0, xa.size - 1)
        covered = (k >= 0) & (edges <= xb[kk])
        span = xb[kk] - xa[kk]
        frac = np.divide(edges - xa[kk], span, out=np.zeros(edges.size), where=span > 0)
        at_edge = np.where(covered, ya[kk] + frac * (yb[kk] - ya[kk]), np.nan)
        for side in (at_edge[:-1], at_edge[1:]):
            lo, hi = np.fmin(lo, side), np.fmax(hi, side)
    empty = ~np.isfinite(lo)
    lo[empty] = hi[empty] = np.nan
    return np.repeat(edges, 2)[1:-1], np.repeat(lo, 2), np.repeat(hi, 2)


def draw_series(axes, x, y, label: str, color: str, **style):
    """A line of the plot; with more than ``MAX_PLOT_POINTS`` points, its min..max band per time
    bin instead (the artist's label says which)."""
    x = np.asarray(x, np.float64)
    if np.count_nonzero(np.isfinite(x)) <= MAX_PLOT_POINTS:
        return axes.plot(x, y, label=label, color=color, **style)[0]
    bx, lo, hi = series_band(x, y)
    # the outline too: where the band is flat (a constant feed) the fill alone would vanish
    return axes.fill_between(bx, lo, hi, facecolor=color, edgecolor=color, alpha=0.5, lw=0.6,
                             label=f"{label} (min … max)")


SPEED_COLOR, AREA_COLOR, FEED_COLOR = "#3b6fb6", "#d1495b", "#8a90a0"


def speed_area_figure(speed: tuple, feed: tuple, area: tuple) -> Plot:
    """The planned speed and the programmed feed (mm/s, upper panel) and the bead's
    cross-section area (mm², lower panel) against build time: each an (x, y) series with NaN
    breaks. Two panels on one time axis: on twin axes the two curves cross and hide each other."""
    plot = Plot("Planned speed and bead cross-section along the path", "build time (s)", "speed (mm/s)",
                lower_ylabel="area (mm²)")
    ax, low = plot.axes, plot.lower
    draw_series(ax, *feed, "programmed feed F", FEED_COLOR, lw=1.0, ls=":")
    draw_series(ax, *speed, "planned speed", SPEED_COLOR, lw=1.0)
    ax.set_ylim(bottom=0.0)
    draw_series(low, *area, "bead cross-section area", AREA_COLOR, lw=1.0)
    low.set_ylim(bottom=0.0)
    plot.legend_below([ax, low])
    return plot


def growth_layers_figure(layers: list[dict]) -> Plot:
    """Per layer (the flow model's ``layers``): the programmed bead from its bottom to its top,
    the built top (mean, and min..max over the layer's beads) and, below, the drift."""
    plot = Plot("Programmed and built layers", "layer", "Z (mm)", lower_ylabel="drift (mm)")
    k = np.array([r["layer"] for r in layers], np.float64)
    bottom = np.array([r["programmed_z_mm"] for r in layers], np.float64)
    mean = np.array([r["built_top_mm"]["mean"] for r in layers], np.float64)
    lo = np.array([r["built_top_mm"]["min"] for r in layers], np.float64)
    hi = np.array([r["built_top_mm"]["max"] for r in layers], np.float64)
    drift = np.array([r["drift_mm"] for r in layers], np.float64)
    # drift is the weighted mean of (programmed top - built top), so this is the mean programmed top
    top = mean + drift
    ax = plot.axes
    ax.bar(k, top - bottom, bottom=bottom, width=0.7, color="#bcd0ea", edgecolor="#3b6fb6", lw=0.6,
           label="programmed bead (bottom to top)")
    ax.vlines(k, lo, hi, color="#d1495b", lw=2.0, label="built top (min … max)")
    ax.plot(k, mean, color="#d1495b", marker="o" if k.size <= 60 else None, ms=3.5, lw=1.0, label="built top (mean)")
    plot.legend_below()
    low = plot.lower
    low.bar(k, drift, width=0.7, color=np.where(drift >= 0, "#3b6fb6", "#d1495b"), label="drift")
    low.axhline(0.0, color="#1d2330", lw=0.8)
    low.set_title("drift: programmed top − built top (+ = part below the program)", fontsize=8, loc="left")
    if k.size <= 30:
        low.set_xticks(k)
    return plot


def standoff_figure(standoff: tuple, lost: tuple, nominal_mm: float, focus_mm: float | None) -> Plot:
    """The standoff each bead piece met (nozzle tip to the part below it) against build time,
    with the contact line at 0, the programmed standoff, the powder focus of a catchment
    profile, and the pieces whose material was lost."""
    plot = Plot("Standoff along the path", "build time (s)", "standoff (mm)")
    ax = plot.axes
    draw_series(ax, *standoff, "standoff met by the beads", "#2a9d8f", lw=1.2)
    ax.axhline(0.0, color="#d62828", lw=1.2, label="nozzle touches the part")
    ax.axhline(nominal_mm, color=FEED_COLOR, lw=1.0, ls=":", label=f"programmed standoff {nominal_mm:g} mm")
    if focus_mm is not None:
        ax.axhline(focus_mm, color="#e9a23b", lw=1.0, ls="--", label=f"powder focus {focus_mm:g} mm")
    lost_t, lost_s = (np.asarray(a, np.float64) for a in lost)
    if lost_t.size:
        ax.scatter(lost_t, lost_s, marker="x", s=14, color="#d62828", zorder=3,
                   label=f"material lost ({lost_t.size} bead piece{'s' if lost_t.size != 1 else ''})")
    values = np.concatenate([np.asarray(standoff[1], np.float64), lost_s, [0.0, nominal_mm]])
    values = values[np.isfinite(values)]
    span = max(float(values.max() - values.min()), 1e-3)
    ax.set_ylim(min(float(values.min()), 0.0) - 0.06 * span, float(values.max()) + 0.06 * span)
    plot.legend_below()
    return plot


def heat_layers_figure(layers: list[dict], liquidus: float) -> Plot:
    """Per layer (the heat's ``layers``): the interlayer temperature (the mean of its top cells
    when the next layer starts) and the peak its cells reached, against the liquidus."""
    plot = Plot("Interlayer and peak temperature by layer", "layer", "temperature (°C)")
    k = np.array([r["layer"] for r in layers], np.float64)
    inter = np.array([np.nan if r["interlayer_C"] is None else r["interlayer_C"] for r in layers], np.float64)
    peak = np.array([np.nan if r["peak_C"] is None else r["peak_C"] for r in layers], np.float64)
    ax = plot.axes
    marker = "o" if k.size <= 60 else None
    ax.plot(k, inter, color="#3b6fb6", marker=marker, ms=3.5, lw=1.2, label="interlayer (top, next layer's start)")
    ax.plot(k, peak, color="#d1495b", marker=marker, ms=3.5, lw=1.0, label="peak of the layer's cells")
    ax.axhline(liquidus, color="#1d2330", lw=0.8, ls="--", label=f"liquidus {liquidus:.0f} °C")
    if k.size <= 30:
        ax.set_xticks(k)
    plot.legend_below()
    return plot


def melt_pool_figure(pools: list[dict]) -> Plot:
    """The melt pool's width, length and depth at the middle of each deposit row, against time."""
    plot = Plot("Melt pool along the path", "time (s)", "size (mm)")
    t = np.array([p["time_s"] for p in pools], np.float64)
    for key, label, colour in (("width_mm", "width", "#d1495b"), ("length_mm", "length", "#3b6fb6"),
                               ("depth_mm", "depth", "#6a994e")):
        plot.axes.plot(t, np.array([p[key] for p in pools], np.float64), color=colour,
                       marker="o" if t.size <= 80 else None, ms=3, lw=1.0, label=label)
    plot.legend_below()
    return plot


def peak_map_figure(ij: np.ndarray, peak: np.ndarray, origin, voxel: float, liquidus: float) -> Plot:
    """Top view of the part: each column's highest peak temperature (cells ``ij`` at lattice
    ``origin``, ``voxel``), the liquidus marked on the colour bar."""
    plot = Plot("Peak temperature, top view (hottest cell of each column)", "X (mm)", "Y (mm)")
    ax = plot.axes
    if ij.shape[0] == 0:
        return plot
    lo = ij.min(axis=0)
    shape = tuple(ij.max(axis=0) - lo + 1)
    image = np.full(shape, -np.inf)
    np.maximum.at(image, (ij[:, 0] - lo[0], ij[:, 1] - lo[1]), peak)
    image[~np.isfinite(image)] = np.nan
    x0 = origin[0] + voxel * (lo[0] - 0.5)
    y0 = origin[1] + voxel * (lo[1] - 0.5)
    shown = ax.imshow(image.T, origin="lower", cmap="inferno", interpolation="nearest",
                      extent=(x0, x0 + voxel * shape[0], y0, y0 + voxel * shape[1]))
    ax.set_aspect("equal")
    ax.grid(False)
    bar = plot.figure.colorbar(shown, ax=ax, label="peak temperature (°C)")
    bar.ax.axhline(liquidus, color="#3b6fb6", lw=1.5)
    return plot
