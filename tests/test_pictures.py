"""Headless PNG pictures: size, content, views, colour limits, context meshes."""

import numpy as np
import pytest
import pyvista as pv
from PIL import Image

from dmdvox.view.pictures import color_limits, image_is_blank, render_surface


@pytest.fixture(scope="module")
def sphere():
    s = pv.Sphere(radius=10.0, center=(40.0, -20.0, 15.0), theta_resolution=48, phi_resolution=32)
    return np.asarray(s.points, np.float64), s.faces.reshape(-1, 4)[:, 1:].astype(np.int64)


def pixels(path):
    with Image.open(path) as im:
        return np.asarray(im.convert("RGB"), np.int16)


def test_sphere_coloured_by_z(tmp_path, sphere):
    v, t = sphere
    out = render_surface(tmp_path / "sphere.png", v, t, scalars=v[:, 2] - 15.0, title="sphere z", size=(640, 480))
    assert out == tmp_path / "sphere.png"
    with Image.open(out) as im:  # the title drawn is also the file's own
        assert im.info["Title"] == "sphere z" and im.info["Software"] == "dmdvox"
    assert [p.name for p in tmp_path.iterdir()] == ["sphere.png"]  # nothing left over
    with Image.open(out) as im:
        assert im.format == "PNG" and im.size == (640, 480)
    assert not image_is_blank(out)
    rgb = pixels(out)
    # both ends of the diverging map appear: reddish pixels (top of the sphere) and bluish ones
    assert np.any((rgb[..., 0] - rgb[..., 2]) > 80)
    assert np.any((rgb[..., 2] - rgb[..., 0]) > 80)
    # the part is centred left of the colour bar and fills the frame: its coloured pixels
    # (neither white background nor grey text) reach near both top and bottom
    saturated = (rgb.max(axis=2) - rgb.min(axis=2)) > 40
    saturated[:, int(0.78 * 640):] = False  # ignore the colour bar column
    rows, cols = np.nonzero(saturated)
    assert rows.min() < 0.2 * 480 and rows.max() > 0.85 * 480
    assert abs((cols.min() + cols.max()) / 2 - 0.4 * 640) < 0.06 * 640


def test_views_differ(tmp_path, sphere):
    v, t = sphere
    z = v[:, 2] - 15.0
    top = render_surface(tmp_path / "top.png", v, t, scalars=z, view="top", size=(320, 240))
    front = render_surface(tmp_path / "front.png", v, t, scalars=z, view="front", size=(320, 240))
    a, b = pixels(top), pixels(front)
    assert a.shape == b.shape == (240, 320, 3)
    a, b = a[:, : int(0.78 * 320)], b[:, : int(0.78 * 320)]  # leave out the colour bar
    assert not image_is_blank(top) and not image_is_blank(front)
    # seen from above the sphere is all positive z (red); from the front, half of it is blue
    assert np.mean(np.abs(a - b)) > 5
    blue = lambda rgb: np.count_nonzero((rgb[..., 2] - rgb[..., 0]) > 60)  # noqa: E731
    assert blue(b) > 2000 and blue(a) < blue(b) / 50


def test_plain_mesh_with_context(tmp_path, sphere):
    v, t = sphere
    plate = pv.Box(bounds=(20, 60, -40, 0, 2, 5)).triangulate()
    out = render_surface(
        tmp_path / "ctx.png", v, t, view="iso", size=(320, 240),
        context_meshes=[(plate.points, plate.faces.reshape(-1, 4)[:, 1:], "tan", 0.3),
                        (plate.points + (0, 0, 40), plate.faces.reshape(-1, 4)[:, 1:])],
        fit_context=True,
    )
    assert not image_is_blank(out)


def test_color_limits():
    assert color_limits([-0.2, 0.05, 0.5]) == (-0.5, 0.5)
    assert color_limits([0.1, 0.3, np.nan]) == (0.1, 0.3)
    assert color_limits([-3.0, -1.0]) == (-3.0, -1.0)
    lo, hi = color_limits([0.0, 0.0])
    assert lo < 0.0 < hi
    assert color_limits([np.nan]) == (-1.0, 1.0)


def test_image_is_blank(tmp_path):
    flat = tmp_path / "flat.png"
    Image.new("RGB", (100, 80), (255, 255, 255)).save(flat)
    assert image_is_blank(flat)
    noisy = np.full((80, 100, 3), 200, np.uint8)
    noisy[10:20, 30:60] = (10, 40, 200)
    Image.fromarray(noisy).save(tmp_path / "mark.png")
    assert not image_is_blank(tmp_path / "mark.png")


@pytest.mark.parametrize(
    "kwargs, message",
    [
        ({"view": "side"}, "unknown view"),
        ({"scalars": np.zeros(5)}, "scalars have 5 values"),
        ({"clim": (1.0, 1.0), "scalars": "z"}, "colour limits"),
        ({"path": "pic.jpg"}, "PNG"),
        ({"triangles": np.array([[0, 1, 10**6]])}, "outside"),
    ],
)
def test_bad_requests(tmp_path, sphere, kwargs, message):
    v, t = sphere
    kwargs = dict(kwargs)
    if isinstance(kwargs.get("scalars"), str):
        kwargs["scalars"] = v[:, 2]
    path = tmp_path / kwargs.pop("path", "pic.png")
    with pytest.raises(ValueError, match=message):
        render_surface(path, v, kwargs.pop("triangles", t), **kwargs)
    assert list(tmp_path.iterdir()) == []


def test_per_triangle_scalars(tmp_path, sphere):
    v, t = sphere
    centroid_z = v[t].mean(axis=1)[:, 2] - 15.0
    out = render_surface(tmp_path / "cells.png", v, t, scalars=centroid_z, scalar_name="z_mm", size=(200, 150))
    assert not image_is_blank(out)


def test_colour_bar_titles_in_words():
    from dmdvox.view.pictures import scalar_title

    assert scalar_title("arrival_s") == "deposition time (s)"
    assert scalar_title("deviation_mm") == "deviation from CAD (mm)\n+ = excess material"
    assert scalar_title("pore volume (mm³)") == "pore volume (mm³)"  # already words: kept


def test_colour_bar_title_drawn_above_the_bar_and_kept_in_the_file(tmp_path, sphere):
    """The bar's title is drawn in the bar's column just above it, and the PNG says it; a
    picture without scalars has neither bar nor title."""
    from dmdvox.view.pictures import png_colour_bar_title

    v, t = sphere
    width, height = 640, 480
    named = render_surface(tmp_path / "named.png", v, t, scalars=v[:, 2], scalar_name="arrival_s", size=(width, height))
    other = render_surface(tmp_path / "other.png", v, t, scalars=v[:, 2], scalar_name="arrival_s",
                           bar_title="bead cross-section area (mm²)", size=(width, height))
    assert png_colour_bar_title(named) == "deposition time (s)"
    assert png_colour_bar_title(other) == "bead cross-section area (mm²)"
    differ = (np.abs(pixels(named) - pixels(other)) > 8).any(axis=2)
    rows, cols = np.nonzero(differ)
    assert rows.size > 50  # the words differ, so their pixels do
    # only the title strip: the bar's column (right fifth), between the picture's title band and the
    # bar's top (0.775 of the height from the bottom, text growing upwards)
    assert cols.min() >= 0.78 * width
    assert rows.min() >= 0.08 * height and rows.max() <= (1 - 0.76) * height
    plain = render_surface(tmp_path / "plain.png", v, t, size=(width, height))
    assert png_colour_bar_title(plain) is None


def test_scale_bar_matches_the_picture(tmp_path, sphere):
    """The bar's length in pixels is its round length at the picture's own scale, measured here
    from the sphere's 20 mm diameter (top view, parallel projection)."""
    from dmdvox.view.pictures import scale_bar_length, scale_bar_pixels

    v, t = sphere
    width, height = 800, 600
    out = render_surface(tmp_path / "s.png", v, t, scalars=v[:, 2] - 15.0, scalar_name="arrival_s", view="top",
                         size=(width, height))
    rgb = pixels(out)
    # the sphere: every non-white pixel left of the colour bar, below the title, above the axes widget
    # (its shaded rim is dark grey, so not "coloured")
    body = (rgb < 245).any(axis=2)[int(0.1 * height):int(0.75 * height), :int(0.78 * width)]
    cols = np.flatnonzero(body.any(axis=0))
    mm_per_px = 20.0 / (cols[-1] - cols[0] + 1)
    saturated = (rgb.max(axis=2) - rgb.min(axis=2)) > 40
    # the bar: the longest run of dark pixels in a row of the bottom strip, right of the axes
    dark = rgb.max(axis=2) < 80
    strip = dark[int(0.90 * height):, int(0.21 * width):int(0.78 * width)]
    runs = [np.diff(np.flatnonzero(np.diff(np.concatenate([[0], row, [0]]))))[::2] for row in strip.astype(int)]
    bar_px = max(int(r.max()) for r in runs if r.size)
    length, expected_px = scale_bar_pixels(mm_per_px, width)
    assert length == scale_bar_length(mm_per_px, 0.2 * width) and length / 10 ** np.floor(np.log10(length)) in (1, 2, 5)
    assert bar_px == pytest.approx(expected_px, rel=0.03, abs=3)
    # nothing of the part in the strip kept for the bar
    assert not saturated[int(0.93 * height):].any()


def test_scale_bar_lengths_are_round():
    from dmdvox.view.pictures import scale_bar_length

    assert scale_bar_length(0.1, 240) == 20.0  # at most 24 mm -> 20
    assert scale_bar_length(0.01, 240) == 2.0
    assert scale_bar_length(0.05, 240) == 10.0  # at most 12 mm -> 10
    assert scale_bar_length(0.03, 240) == 5.0  # 7.2 mm -> 5
    assert scale_bar_length(0.001, 100) == 0.1


def test_layer_plot_legend_clear_of_the_bars():
    """Tall first and last layers: the legend sits beside the axes, over no bar."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    from dmdvox.reporting.figures import layer_figure

    layers = [{"layer": k, "z_mm": 0.75 * k, "void_mm3": v, "overbuild_mm3": o}
              for k, (v, o) in enumerate([(9.0, 8.5), (1.0, 0.2), (0.5, 0.1), (9.5, 9.0)])]
    plot = layer_figure(layers)
    FigureCanvasAgg(plot.figure).draw()
    legend = plot.axes.get_legend().get_window_extent()
    bars = [patch.get_window_extent() for patch in plot.axes.patches]
    assert len(bars) == 8
    assert not any(legend.overlaps(bar) for bar in bars)
    assert legend.x0 >= plot.axes.get_window_extent().x1  # outside the plotting area
    assert plot.figure.get_window_extent().contains(legend.x1 - 1, legend.y1 - 1)  # still on the figure


def test_pore_histogram_on_log_bins():
    from dmdvox.reporting.figures import pore_bins, pore_figure

    d = np.array([0.05, 0.08, 0.3, 0.31, 1.2, 4.0])
    edges = pore_bins(d)
    ratios = edges[1:] / edges[:-1]
    assert np.allclose(ratios, ratios[0]) and ratios[0] > 1  # equal widths in log(diameter)
    assert edges[0] < d.min() and edges[-1] > d.max()
    plot = pore_figure([{"equivalent_diameter_mm": x} for x in d])
    assert plot.axes.get_xscale() == "log"
    assert sum(patch.get_height() for patch in plot.axes.patches) == d.size
    assert plot.title == "Pore sizes (6 pores)"
    one = pore_bins(np.array([0.4]))
    assert one[0] < 0.4 < one[-1]


def test_a_mesh_past_the_picture_budget_looks_the_same_decimated(tmp_path, monkeypatch):
    # A fine mesh is decimated to the picture's triangle budget before drawing: the picture
    # shows the same part in the same colours (a few pixels differ along the silhouette).
    from dmdvox.view import pictures

    fine = pv.Sphere(radius=10.0, theta_resolution=240, phi_resolution=240)
    v, t = np.asarray(fine.points, np.float64), fine.faces.reshape(-1, 4)[:, 1:].astype(np.int64)
    full = render_surface(tmp_path / "full.png", v, t, scalars=v[:, 2], size=(320, 240))
    monkeypatch.setattr(pictures, "PICTURE_TRIANGLES", len(t) // 20)
    drawn = []
    monkeypatch.setattr(pictures, "_polydata", lambda pv_, v_, t_, what: drawn.append(len(t_)) or pv_.PolyData(
        np.asarray(v_, np.float64), np.column_stack([np.full(len(t_), 3), t_]).ravel()))
    coarse = render_surface(tmp_path / "coarse.png", v, t, scalars=v[:, 2], size=(320, 240))
    assert len(t) // 40 < drawn[0] <= len(t) // 20
    difference = np.abs(pixels(full) - pixels(coarse)).max(axis=2)
    assert np.mean(difference > 40) < 0.01 and not image_is_blank(coarse)
