"""`dmdvox report`: one self-contained HTML page, checked as data and in headless Chromium."""

import base64
import dataclasses
import json
import math
from html import unescape
import re
import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from dmdvox.reporting import scene3d
from dmdvox.view.pictures import decimate
from dmdvox.reporting.scene3d import (LINE_NO_TEXT, LINE_TRAVEL, ScalarField, SceneMesh, deposit_rows_at,
                                   gcode_lines, layer_table, row_values_on_vertices, scene_payload, vertex_normals)
from dmdvox.process.plan import plan_process
from dmdvox.toolpath.reader import read_gcode

from .conftest import DATA, DEMO_MAX_UNDERFILL_MM, DEV_EXTRAS, REPO, demo_void_percent, require_module, require_tool

CHROMIUM = shutil.which("chromium") or shutil.which("chromium-browser")
NOZZLE = "cone:tip=4,top=20,length=25"


def _playwright():
    """playwright's sync API with Debian's Chromium, or the test fails naming the install step:
    CI installs both (scripts/setup.sh), so a missing one is a broken install, not a skip."""
    require_tool(("chromium", "chromium-browser"), "Chromium", "scripts/setup.sh installs it (Debian package chromium)")
    return require_module("playwright.sync_api", "playwright", DEV_EXTRAS)


def _decode(text: str, dtype) -> np.ndarray:
    return np.frombuffer(base64.b64decode(text), dtype)


@pytest.fixture(scope="module")
def report(tmp_path_factory):
    """The demo block against its CAD, a cone nozzle, the clamp and the plate (one run per module)."""
    out = tmp_path_factory.mktemp("report")
    proc = subprocess.run([sys.executable, "-m", "dmdvox.cli", "report", str(DATA / "demo_block.gcode"),
                           "--cad", str(DATA / "demo_block.stl"), "--nozzle", NOZZLE,
                           "--fixture", str(DATA / "demo_clamp.stl"), "--plate", "0", "--out", str(out), "--json"],
                          capture_output=True, text=True, cwd=REPO, timeout=600)
    assert proc.returncode == 0, proc.stderr
    return json.loads(proc.stdout), out


def test_report_json_and_files(report):
    summary, out = report
    # (the command line may add its own keys, e.g. warnings)
    assert {"report_html", "info", "simulate", "compare", "collide", "layers", "outputs"} <= set(summary)
    assert summary["warnings"] == []  # cli.main gives every command's --json one; nothing doubtful here
    assert all(Path(p).is_file() for p in summary["outputs"])
    names = {Path(p).name for p in summary["outputs"]}
    assert {"demo_block_report.html", "demo_block_iso.png", "demo_block_top.png", "demo_block_cad_deviation.png",
            "demo_block_layers.png", "demo_block_clearance.png", "demo_block_collisions.png",
            "demo_block.vdb", "demo_block_compare.vti"} <= names
    # the same numbers as the separate commands give on the same inputs
    assert summary["info"]["layers"] == 8
    # the corners and notches the round track ends leave (closed form and tolerance: test_demo.py)
    assert summary["compare"]["void_percent"] == pytest.approx(demo_void_percent(), rel=0.08)
    assert summary["compare"]["max_underfill_mm"] == pytest.approx(DEMO_MAX_UNDERFILL_MM,
                                                                   abs=0.5 * summary["compare"]["voxel_mm"])
    assert summary["collide"]["first_collision_line"] is not None
    assert {c["obstacle"] for c in summary["collide"]["collisions"]} == {"fixture:demo_clamp"}
    # each picture's colour bar titled in words with the unit (as drawn, kept in the PNG); the
    # collision picture has none: nothing on it is coloured by a value
    from dmdvox.view.pictures import png_colour_bar_title

    bars = {name: png_colour_bar_title(out / name) for name in
            ("demo_block_iso.png", "demo_block_top.png", "demo_block_collisions.png")}
    bars["deviation"] = png_colour_bar_title(next(p for p in summary["outputs"] if p.endswith("_cad_deviation.png")))
    assert bars == {"demo_block_iso.png": "deposition time (s)", "demo_block_top.png": "deposition time (s)",
                    "demo_block_collisions.png": None,
                    "deviation": "deviation from CAD (mm)\n+ = excess material"}


def test_report_page_is_self_contained(report):
    summary, _ = report
    html = Path(summary["report_html"]).read_text()
    for attr, value in re.findall(r'\b(src|href)\s*=\s*"([^"]*)"', html):
        assert value.startswith("data:") if attr == "src" else value.startswith("#"), (attr, value)
    assert not re.search(r"@import|url\((?!data:|#)|<link\b|<iframe\b", html)  # url(#id): SVG clip paths
    # namespace declarations are names, not fetches; nothing else may name a web address
    assert not re.search(r"https?://", re.sub(r'xmlns(:\w+)?="[^"]*"', "", html))
    for anchor in ("summary", "toolpath", "deposit", "compare", "pores", "collide", "view3d"):
        assert f'<section id="{anchor}">' in html
    # the fixed bead of a program without material: no material or growth sections
    assert '<section id="material">' not in html and '<section id="growth">' not in html
    assert summary["material"] is None and summary["growth"] is None
    # each picture's caption is the title it was drawn with (kept in the PNG), each plot's its title
    from io import BytesIO

    from PIL import Image

    figures = re.findall(r'<figure><img alt="([^"]*)" src="data:image/png;base64,([^"]+)"><figcaption>(.*?)'
                         r"</figcaption></figure>", html)
    assert len(figures) == 4  # iso, top, deviation, collisions
    for alt, data, caption in figures:
        title = Image.open(BytesIO(base64.b64decode(data))).info["Title"]
        assert re.fullmatch(re.escape(unescape(title)) + r" \(demo_block_\w+\.png\)", unescape(caption))
        assert unescape(alt) == title
    captions = [unescape(c) for c in re.findall(r'<figure class="plot">.*?<figcaption>(.*?)</figcaption>', html, re.S)]
    assert captions == ["Void and overbuild per layer (demo_block_layers.png)",
                        "Nozzle clearance along the path (demo_block_clearance.png)"]
    # the numbers the page shows are the JSON's
    c = summary["compare"]
    assert f"{c['void_percent']:.2f} % / {c['overbuild_percent']:.2f} %" in html
    assert f"first at line {summary['collide']['first_collision_line']}" in html


def test_scene_payload_round_trip():
    """Quantised positions come back within half a step; normals are unit; times and scalars stay."""
    tp = read_gcode(DATA / "demo_block.gcode")
    rng = np.random.default_rng(3)
    vertices = rng.uniform([-5, -5, 0], [25, 25, 6], (500, 3))
    triangles = rng.integers(0, 500, (900, 3))
    arrival = rng.uniform(0, tp.duration, 500)
    layer = np.floor(arrival / tp.duration * 8)
    fields = [ScalarField("arrival_s", "deposition time", "s", range=(0.0, tp.duration), time=True),
              ScalarField("layer", "layer", "", "turbo", integer=True),
              ScalarField("feed_mm_s", "feed", "mm/s", "plasma")]
    payload = scene_payload([SceneMesh("deposit", vertices, triangles, (1, 1, 1), timed=True,
                                       scalars={"arrival_s": arrival, "layer": layer, "feed_mm_s": np.full(500, 12.5)})],
                            tp, np.array([[1.0, 2.0, 3.0, 4.0]]), 12.7, None, fields)
    lo, extent = np.array(payload["lo"]), np.array(payload["extent"])
    mesh = payload["meshes"][0]
    q = _decode(mesh["positions"], "<u2").reshape(-1, 3)
    assert np.all(np.abs(lo + q / 65535.0 * extent - vertices) <= 0.5 * extent / 65535.0 + 1e-12)
    assert np.array_equal(_decode(mesh["indices"], "<u4").reshape(-1, 3), triangles)
    assert np.allclose(_decode(mesh["scalars"]["arrival_s"], "<f4"), arrival, rtol=1e-6)
    assert np.array_equal(_decode(mesh["scalars"]["layer"], "<f4"), layer)
    assert mesh["scalars"]["feed_mm_s"] == 12.5  # a constant field travels as one number
    # each field with its words, unit, 16-sample map and range: given, or the values' min..max
    by_name = {f["name"]: f for f in payload["fields"]}
    assert [f["name"] for f in payload["fields"]] == ["arrival_s", "layer", "feed_mm_s"]
    assert by_name["arrival_s"]["title"] == "deposition time (s)" and by_name["arrival_s"]["time"]
    assert by_name["arrival_s"]["range"] == [0.0, tp.duration]
    assert by_name["layer"]["title"] == "layer" and by_name["layer"]["integer"]
    assert by_name["layer"]["range"] == [layer.min(), layer.max()]
    assert by_name["feed_mm_s"]["title"] == "feed (mm/s)" and by_name["feed_mm_s"]["range"] == [12.5, 12.5]
    assert all(len(f["colormap"]) == 16 and all(len(c) == 3 for c in f["colormap"]) for f in payload["fields"])
    # the G-code table: every row of the program with its start time and line
    g = payload["gcode"]
    assert g["count"] == len(tp)
    assert np.array_equal(_decode(g["lines"], "<u4"), tp.line)
    assert np.allclose(_decode(g["times"], "<f4"), tp.t_start, rtol=1e-6, atol=1e-4)
    assert payload["duration"] == pytest.approx(tp.duration)
    assert payload["markers"] == [[1.0, 2.0, 3.0, 4.0]]
    path_times = _decode(payload["path"]["times"], "<f4")
    assert np.all(np.diff(path_times) >= -1e-3) and path_times[-1] == pytest.approx(tp.duration, rel=1e-6)
    assert payload["focus"] == [vertices.min(0).tolist(), vertices.max(0).tolist()]


def test_vertex_normals_of_a_box_point_along_its_diagonals():
    from dmdvox.io.mesh import box_mesh

    vertices, triangles = box_mesh((0, 0, 0), (1, 1, 1))
    normals = vertex_normals(vertices, triangles).astype(float) / 127
    outward = np.sign(vertices - 0.5)
    # a corner's area-weighted normal leans into the octant of the corner
    assert np.all(np.sign(normals) == outward)
    assert np.allclose(np.linalg.norm(normals, axis=1), 1.0, atol=0.02)


def test_decimate_keeps_the_budget_and_nearest_scalars():
    import pyvista as pv

    sphere = pv.Sphere(radius=5.0, theta_resolution=200, phi_resolution=200)
    vertices = np.asarray(sphere.points, float)
    triangles = np.asarray(sphere.faces).reshape(-1, 4)[:, 1:]
    height = vertices[:, 2].copy()
    dv, dt, ds = decimate(vertices, triangles, {"z": height}, 10_000)
    assert 5_000 < len(dt) <= 10_000  # the budget, not far below it
    assert np.allclose(np.linalg.norm(dv, axis=1), 5.0, atol=0.1)  # still the sphere
    assert np.max(np.abs(ds["z"] - dv[:, 2])) < 0.3  # each value is a near original vertex's


# Two layers at 10 mm/s (F600): layer 0 one 20 mm line, then 1 + 10 mm of travel, then layer 1
# a 20 mm and a 10 mm line. Rows: line 3 deposit, 5 and 6 travel, 8 and 9 deposit.
TWO_LAYERS = """G90 G1 X0 Y0 Z0 F600
M65
G1 X20 Y0 Z0
M64
G1 X20 Y0 Z1
G1 X20 Y10 Z1
M65
G1 X0 Y10 Z1
G1 X0 Y20 Z1
M64
"""
FEED = 10.0  # mm/s


def two_layer_closed_forms(height: float) -> list[dict]:
    """Each layer's times from lengths over the feed alone (constant-feed timing)."""
    end0 = 20 / FEED
    start1 = end0 + (1 + 10) / FEED
    end1 = start1 + (20 + 10) / FEED
    return [{"layer": 0, "z_mm": 0.0, "bottom_mm": 0.0, "top_mm": height, "start_s": 0.0, "end_s": end0,
             "deposit_s": 20 / FEED, "length_mm": 20.0, "first_line": 3, "interlayer_s": None},
            {"layer": 1, "z_mm": 1.0, "bottom_mm": 1.0, "top_mm": 1.0 + height, "start_s": start1, "end_s": end1,
             "deposit_s": 30 / FEED, "length_mm": 30.0, "first_line": 8, "interlayer_s": start1 - end0}]


def assert_rows_equal(got: list[dict], expected: list[dict]) -> None:
    assert len(got) == len(expected)
    for g, e in zip(got, expected):
        assert g.keys() == e.keys()
        for key, value in e.items():
            assert g[key] == (value if value is None or isinstance(value, int) else pytest.approx(value, abs=1e-9)), key


def test_layer_table_closed_forms(gcode_file):
    tp = read_gcode(gcode_file(TWO_LAYERS), dialect="seed")
    assert_rows_equal(layer_table(tp, 1.0), two_layer_closed_forms(1.0))


def test_interlayer_time_is_negative_when_a_layer_starts_before_the_one_below_ends(gcode_file):
    """Two parts side by side, each layer in turn: part A's layer 1 is laid before part B's
    layer 0, so layer 1 starts before layer 0 ends. Rows at 10 mm/s: layer 0 (A) 10 mm, 1 mm
    up, layer 1 (A) 10 mm, travel down and across (sqrt(10² + 1²) mm), layer 0 (B) 10 mm."""
    tp = read_gcode(gcode_file("""G90 G1 X0 Y0 Z0 F600
M65
G1 X10 Y0 Z0
M64
G1 X10 Y0 Z1
M65
G1 X20 Y0 Z1
M64
G1 X20 Y10 Z0
M65
G1 X30 Y10 Z0
M64
"""), dialect="seed")
    start1 = (10 + 1) / FEED
    end0 = start1 + (10 + math.hypot(10, 1) + 10) / FEED
    rows = layer_table(tp, 1.0)
    assert [r["layer"] for r in rows] == [0, 1]
    assert rows[0]["start_s"] == 0.0 and rows[0]["end_s"] == pytest.approx(end0)
    assert rows[0]["deposit_s"] == pytest.approx(20 / FEED) and rows[0]["first_line"] == 3
    assert rows[1]["start_s"] == pytest.approx(start1) and rows[1]["end_s"] == pytest.approx(start1 + 10 / FEED)
    # layer 1 (A), the travel and layer 0 (B) all come after layer 1's start and before layer 0's end
    assert rows[1]["interlayer_s"] == pytest.approx(start1 - end0) == pytest.approx(-(20 + math.hypot(10, 1)) / FEED)


def test_row_values_reach_vertices_through_their_arrival(gcode_file):
    tp = read_gcode(gcode_file(TWO_LAYERS), dialect="seed")
    deposit_rows = np.flatnonzero(tp.deposit)
    # inside each deposit row, on a boundary (belongs to the row that ends there), before and after
    times = np.array([1.0, 2.0, 4.0, 5.1, 5.5, -1.0, 99.0, 2.5])
    expected = deposit_rows[[0, 0, 1, 1, 2, 0, 2, 1]]  # 2.5 s is travel: the next deposit row is laid after
    assert np.array_equal(deposit_rows_at(tp, times), expected)
    values = np.arange(len(tp), dtype=float) * 10
    assert np.array_equal(row_values_on_vertices(tp, times, values), values[expected])
    with pytest.raises(ValueError, match="rows"):
        row_values_on_vertices(tp, times, values[:-1])


def test_gcode_lines_carry_deposit_text_deduplicated_and_capped(gcode_file, monkeypatch):
    text = "G90 G1 X0 Y0 Z0 F600\nM65\n" + "G1 X10 Y0 Z0\nG1 X0 Y0 Z0\n" * 3 + "M64\nG1 X0 Y5 Z0\nM65\n" \
        + "G1 X10 Y5 Z0 ; " + "long comment " * 20 + "\nG1 X0 Y5 Z0 (another)\nM64\n"
    source = text.splitlines()
    tp = read_gcode(gcode_file(text), dialect="seed")
    g = gcode_lines(tp)
    assert np.array_equal(g["lines"], tp.line) and np.array_equal(g["times"], tp.t_start)
    assert g["texts"][:2] == ["G1 X10 Y0 Z0", "G1 X0 Y0 Z0"]  # six rows, two distinct texts
    for row in range(len(tp)):
        k = g["text"][row]
        if not tp.deposit[row]:
            assert k == LINE_TRAVEL
        else:
            line = source[tp.line[row] - 1].strip()
            shown = g["texts"][k]
            assert shown == line if len(line) <= scene3d.MAX_LINE_CHARS else \
                shown == line[:scene3d.MAX_LINE_CHARS - 1] + "…"
    assert max(len(t) for t in g["texts"]) == scene3d.MAX_LINE_CHARS
    # over the text budget, later distinct lines keep their number and lose their text
    monkeypatch.setattr(scene3d, "MAX_LINE_TEXT_CHARS", len("G1 X10 Y0 Z0") + len("G1 X0 Y0 Z0"))
    g = gcode_lines(tp)
    assert g["texts"] == ["G1 X10 Y0 Z0", "G1 X0 Y0 Z0"]
    assert set(g["text"][tp.deposit].tolist()) == {0, 1, LINE_NO_TEXT}
    # over the row budget, every k-th row
    monkeypatch.setattr(scene3d, "MAX_LINE_ROWS", 4)
    g = gcode_lines(tp)
    step = int(np.ceil(len(tp) / 4))
    assert np.array_equal(g["lines"], tp.line[::step])


def test_report_in_headless_chromium(report):
    """The page loads with no console message of level warning or error and no request beyond
    the file; the sections show; the 3-D view draws, replays and answers the seed's keys."""
    sync_api = _playwright()
    summary, _ = report
    url = Path(summary["report_html"]).resolve().as_uri()
    with sync_api.sync_playwright() as p:
        browser = p.chromium.launch(executable_path=CHROMIUM,
                                    args=["--enable-unsafe-swiftshader", "--use-angle=swiftshader"])
        try:
            page = browser.new_page(viewport={"width": 1280, "height": 900})
            problems, requests = [], []
            page.on("console", lambda m: problems.append(f"{m.type}: {m.text}") if m.type in ("error", "warning")
                    else None)
            page.on("pageerror", lambda e: problems.append(f"page error: {e}"))
            page.on("request", lambda r: requests.append(r.url))
            page.goto(url)
            page.wait_for_function("document.getElementById('viewer').dataset.state === 'drawn'", timeout=20_000)
            assert requests == [url]
            for heading in ("Summary", "Toolpath", "Deposit", "Comparison with the CAD part", "Pores",
                            "Nozzle collisions", "3-D view"):
                assert page.get_by_role("heading", name=heading).is_visible()
            widths = page.eval_on_selector_all("img", "imgs => imgs.map(i => i.naturalWidth)")
            assert len(widths) == 4 and min(widths) > 0  # iso, top, deviation, collisions (no pores here)
            assert page.locator("figure.plot svg").count() >= 2

            def canvas_colours() -> int:
                data = page.eval_on_selector("#viewer-canvas", "c => c.toDataURL('image/png')")
                from io import BytesIO

                from PIL import Image

                image = Image.open(BytesIO(base64.b64decode(data.split(",", 1)[1]))).convert("RGB")
                return len(np.unique(np.asarray(image).reshape(-1, 3), axis=0))

            def viewer(key: str) -> str:
                return page.eval_on_selector("#viewer", f"v => v.dataset.{key}")

            full = canvas_colours()
            assert full > 50  # a shaded, coloured part, not a blank canvas
            duration = summary["info"]["duration_s"]
            canvas = page.locator("#viewer-canvas")
            canvas.focus()
            page.keyboard.press("Home")
            page.wait_for_function("document.getElementById('viewer').dataset.time === '0.000'", timeout=10_000)
            # the frame at t = 0 may reach the canvas a frame later on a loaded machine (a full
            # suite failed here once with equal counts; alone it passes): look again a while
            for _ in range(50):
                empty = canvas_colours()
                if empty < full:
                    break
                page.wait_for_timeout(100)
            assert empty < full  # nothing deposited at t = 0: only the CAD ghost and the clamp
            page.keyboard.press("5")
            page.wait_for_timeout(200)
            assert float(viewer("time")) == pytest.approx(duration / 2, abs=1e-3)
            page.keyboard.press(" ")
            assert viewer("playing") == "true"
            page.wait_for_function(f"parseFloat(document.getElementById('viewer').dataset.time) > {duration / 2 + 1}",
                                   timeout=10_000)
            page.keyboard.press(" ")
            assert viewer("playing") == "false"
            page.keyboard.press("End")
            page.select_option("#viewer-colour", "deviation_mm")
            page.wait_for_timeout(200)
            assert canvas_colours() > 20
            assert problems == []
        finally:
            browser.close()


def _browser(sync_api, p):
    return p.chromium.launch(executable_path=CHROMIUM, args=["--enable-unsafe-swiftshader", "--use-angle=swiftshader"])


def _open_viewer(page, url: str, problems: list) -> dict:
    """Load a report, wait for the first frame; returns the page's scene payload."""
    page.on("console", lambda m: problems.append(f"{m.type}: {m.text}") if m.type in ("error", "warning") else None)
    page.on("pageerror", lambda e: problems.append(f"page error: {e}"))
    page.goto(url)
    page.wait_for_function("document.getElementById('viewer').dataset.state === 'drawn'", timeout=20_000)
    return json.loads(page.eval_on_selector("#scene-data", "e => e.textContent"))


def _canvas(page) -> np.ndarray:
    """The 3-D view's pixels (RGB) once the next frames are drawn."""
    from io import BytesIO

    from PIL import Image

    page.evaluate("new Promise(r => requestAnimationFrame(() => requestAnimationFrame(r)))")
    data = page.eval_on_selector("#viewer-canvas", "c => c.toDataURL('image/png')")
    return np.asarray(Image.open(BytesIO(base64.b64decode(data.split(",", 1)[1]))).convert("RGB")).astype(int)


def _drawn(pixels: np.ndarray) -> np.ndarray:
    return (pixels < 250).any(axis=2)  # anything on the white background


def _dataset(page) -> dict:
    return page.eval_on_selector("#viewer", "v => ({...v.dataset})")


def _set_range(page, selector: str, value) -> None:
    page.eval_on_selector(selector, f"s => {{ s.value = '{value}'; s.dispatchEvent(new Event('input')); }}")


def _legend(page) -> tuple[bool, str, list[str], str]:
    """(shown, title, tick texts top to bottom, note) of the view's colour legend."""
    return page.eval_on_selector("#viewer-legend", """l => [!l.hidden && l.offsetParent !== null,
        l.querySelector('.legend-title').textContent,
        [...l.querySelectorAll('.legend-ticks span')].map(s => s.textContent),
        l.querySelector('.legend-note').textContent]""")


STANDARD_TITLES = {"arrival_s": "deposition time (s)", "deviation_mm": "deviation from CAD (mm)",
                   "layer": "layer number", "feed_mm_s": "feed (mm/s)",
                   "bead_area_mm2": "bead cross-section area (mm²)"}


def test_viewer_legend_scale_bar_clip_and_line(report):
    """Every colouring has its legend (words and unit, ticks spanning its range); the scale bar
    is a round length matching the drawn part; the Z clip hides what lies above a layer's top,
    as the replay does at that layer's end; the line under way is shown with its text."""
    sync_api = _playwright()
    summary, _ = report
    # the report times the program as the machine runs it (the default motion plan)
    tp = plan_process(read_gcode(DATA / "demo_block.gcode")).toolpath
    source = (DATA / "demo_block.gcode").read_text().splitlines()
    with sync_api.sync_playwright() as p:
        browser = _browser(sync_api, p)
        try:
            page = browser.new_page(viewport={"width": 1280, "height": 900})
            problems = []
            payload = _open_viewer(page, Path(summary["report_html"]).resolve().as_uri(), problems)

            # -- the legend, per colouring: the menu is the payload's fields plus one colour
            options = page.eval_on_selector_all("#viewer-colour option", "os => os.map(o => [o.value, o.text])")
            fields = {f["name"]: f for f in payload["fields"]}
            assert [v for v, _ in options] == ["arrival_s", "deviation_mm", "layer", "feed_mm_s", "bead_area_mm2",
                                               "solid"]
            for value, text in options[:-1]:
                page.select_option("#viewer-colour", value)
                shown, title, ticks, note = _legend(page)
                assert shown and title == text == STANDARD_TITLES[value] == fields[value]["title"]
                lo, hi = fields[value]["range"]

                def number(text: str) -> float:
                    # the tick's value, to the precision it is written with
                    return pytest.approx(float(text), abs=0.5 * 10 ** -len(text.partition(".")[2]))

                if hi > lo:
                    assert hi == number(ticks[0]) and lo == number(ticks[-1])  # top to bottom
                else:
                    assert len(ticks) == 1 and ticks[0].startswith("all ") and lo == number(ticks[0][4:])
            assert fields["arrival_s"]["range"] == [0.0, pytest.approx(tp.duration)]
            assert fields["layer"]["range"] == [0.0, float(len(tp.layer_z) - 1)]
            assert fields["feed_mm_s"]["range"] == [pytest.approx(750 / 60)] * 2  # F750 throughout
            assert fields["bead_area_mm2"]["range"] == [pytest.approx(2.5 * 0.75)] * 2  # rect 2.5 x 0.75
            assert fields["deviation_mm"]["range"][0] == -fields["deviation_mm"]["range"][1] < 0
            page.select_option("#viewer-colour", "deviation_mm")
            assert _legend(page)[3] == "+ = excess material, − = missing"
            page.select_option("#viewer-colour", "layer")
            _, _, ticks, note = _legend(page)
            assert ticks == ["7", "6", "5", "4", "3", "2", "1", "0"]  # whole layers, the lowest 0
            assert note == "of the path segment that laid each point; 0 = the lowest layer, a count (no unit)"
            page.select_option("#viewer-colour", "solid")
            assert not _legend(page)[0]

            # -- legend and scale bar stay off the part: no deposit pixel under either
            for box in page.locator("#viewer input[data-layer]").all():
                if box.get_attribute("data-layer") != "deposit":
                    box.uncheck()
            part = _drawn(_canvas(page))
            page.select_option("#viewer-colour", "arrival_s")
            canvas_box = page.locator("#viewer-canvas").bounding_box()
            for overlay in ("#viewer-legend", "#viewer-scale"):
                box = page.locator(overlay).bounding_box()
                x0, y0 = int(box["x"] - canvas_box["x"]), int(box["y"] - canvas_box["y"])
                assert not part[y0:y0 + int(box["height"]) + 1, x0:x0 + int(box["width"]) + 1].any(), overlay

            # -- scale bar: a round length; its pixels per mm are those of the part seen from the top
            # (the 20 x 20 mm block's top face, measured at its depth below the view's centre)
            page.click("button[data-view=top]")
            top = max(r["top_mm"] for r in summary["layers"])
            for wheel in (0, -300):
                if wheel:
                    page.locator("#viewer-canvas").hover()
                    page.mouse.wheel(0, wheel)
                drawn = _drawn(_canvas(page))
                d = _dataset(page)
                length, px, px_per_mm = float(d["scaleMm"]), float(d["scalePx"]), float(d["pxPerMm"])
                assert length / 10 ** np.floor(np.log10(length)) in (1.0, 2.0, 5.0)
                assert px == pytest.approx(length * px_per_mm, abs=1e-3) and 40 < px <= 120
                label = page.eval_on_selector("#viewer-scale", "s => [s.querySelector('.scale-label').textContent, "
                                                               "s.querySelector('.scale-bar').getBoundingClientRect().width]")
                assert label[0] == f"{length:g} mm" and label[1] == pytest.approx(px, abs=1)
                distance, target_z = float(d["distance"]), float(d["target"].split(",")[2])
                cols = np.flatnonzero(drawn.any(axis=0))
                measured = cols[-1] - cols[0] + 1
                assert measured == pytest.approx(20 * px_per_mm * distance / (distance + target_z - top), rel=0.03)
                if not wheel:
                    before = px_per_mm
            assert px_per_mm > 1.2 * before  # zoomed in: more pixels per mm, the bar re-chosen

            # -- Z clip: layer 3's top hides layers 4-7, as the replay at the end of layer 3 does
            page.click("button[data-view=iso]")
            page.select_option("#viewer-colour", "solid")
            full = _drawn(_canvas(page))
            _set_range(page, "#viewer-clip", 3)
            layer3 = summary["layers"][3]
            step = tp.layer_step
            d = _dataset(page)
            assert float(d["clipZ"]) == pytest.approx(layer3["top_mm"] + 0.05 * step) == payload["layers"][3]["clip_mm"]
            assert layer3["top_mm"] == pytest.approx(tp.layer_z[3] + 0.75)  # the bead's top
            assert d["clipLayer"] == "3"
            assert page.text_content("#viewer-clip-label") == f"layers 0–3 shown (Z ≤ {layer3['top_mm']:.2f} mm)"
            clipped = _drawn(_canvas(page))
            rows = lambda m: np.flatnonzero(m.any(axis=1))  # noqa: E731
            assert clipped.sum() < 0.95 * full.sum() and rows(clipped)[0] > rows(full)[0] + 10
            _set_range(page, "#viewer-clip", len(summary["layers"]) - 1)  # the top layer: all shown
            _set_range(page, "#viewer-time", layer3["end_s"])
            at_end_of_layer3 = _drawn(_canvas(page))
            assert (clipped ^ at_end_of_layer3).sum() < 0.03 * clipped.sum()
            assert _dataset(page)["clipZ"] == "none"
            page.locator("#viewer-canvas").focus()
            page.keyboard.press("End")
            assert np.array_equal(_drawn(_canvas(page)), full)

            # -- the line under way and its text, against the file read here
            canvas = page.locator("#viewer-canvas")
            deposit_rows = np.flatnonzero(tp.deposit & (tp.t_end - tp.t_start > 1.0))
            travel_rows = np.flatnonzero(~tp.deposit & (tp.t_end - tp.t_start > 0.1))
            for row in (deposit_rows[len(deposit_rows) // 2], travel_rows[len(travel_rows) // 2]):
                _set_range(page, "#viewer-time", (tp.t_start[row] + tp.t_end[row]) / 2)
                page.evaluate("new Promise(r => requestAnimationFrame(() => requestAnimationFrame(r)))")
                line = int(tp.line[row])
                text = source[line - 1].strip() if tp.deposit[row] else "(travel)"
                assert page.text_content("#viewer-line") == f"line {line}: {text}"
                assert _dataset(page)["line"] == str(line)
            canvas.focus()
            page.keyboard.press("PageDown")
            assert _dataset(page)["clipLayer"] == str(len(summary["layers"]) - 2)
            page.keyboard.press("PageUp")
            assert _dataset(page)["clipZ"] == "none" and "clipLayer" not in _dataset(page)
            assert problems == []
        finally:
            browser.close()


def test_report_of_a_part_with_a_pore(gcode_file, tmp_path):
    """Without CAD or nozzle: the deposit and pores sections only; the hollow box's cavity
    (8 x 8 x 2 mm) is drawn, plotted and listed."""
    width, size = 2.5, 12.5
    lines = ["G90 G1 X0 Y0 Z0 F600"]

    def full(z):
        return [cmd for k in range(6) for cmd in (f"G1 X{width / 2} Y{width / 2 + k * width} Z{z}", "M65",
                                                  f"G1 X{size - width / 2} Y{width / 2 + k * width} Z{z}", "M64")]

    lines += full(0)
    c0, c1 = width / 2, size - width / 2
    for z in (1, 2):
        lines += [f"G1 X{c0} Y{c0} Z{z}", "M65", f"G1 X{c1} Y{c0}", f"G1 X{c1} Y{c1}", f"G1 X{c0} Y{c1}",
                  f"G1 X{c0} Y{c0}", "M64"]
    lines += full(3)
    gcode = gcode_file("\n".join(lines) + "\n", name="hollow.gcode")
    proc = subprocess.run([sys.executable, "-m", "dmdvox.cli", "report", str(gcode), "--dialect", "seed",
                           "--height", "1", "--voxel", "0.25", "--out", str(tmp_path / "out"), "--json"],
                          capture_output=True, text=True, cwd=REPO, timeout=300)
    assert proc.returncode == 0, proc.stderr
    summary = json.loads(proc.stdout)
    assert summary["compare"] is None and summary["collide"] is None
    assert summary["simulate"]["pore_count"] == 1
    names = {Path(p).name for p in summary["outputs"]}
    assert {"hollow_pores.png", "hollow_pore_sizes.png", "hollow_report.html"} <= names
    from dmdvox.view.pictures import png_colour_bar_title

    assert png_colour_bar_title(tmp_path / "out" / "hollow_pores.png") == "pore volume (mm³)"
    assert not names & {"hollow_clearance.png", "hollow_layers.png", "hollow_collisions.png"}
    html = Path(summary["report_html"]).read_text()
    assert '<section id="compare">' not in html and '<section id="collide">' not in html
    cavity = (size - 2 * width) ** 2 * 2.0
    shown = float(re.search(r"<td>(\d+\.\d{4})</td><td>\d+\.\d{3}</td><td>\(6\.25, 6\.25, 2\.\d\d\)</td>", html)[1])
    assert shown == pytest.approx(cavity, rel=0.05)
    # the cavity is drawn as its walls, cut from the deposit's surface (not a sphere standing in)
    assert "1 pore (1 drawn as walls), coloured by pore volume" in html


@pytest.fixture(scope="module")
def two_layer_report(tmp_path_factory):
    """The two-layer program reported in this process with two colourings the report does not
    know: a per-row "standoff drift" and a per-vertex height, passed through ``extra_fields``."""
    from dmdvox.cli import _report_request, build_parser
    from dmdvox.reporting.build import report

    folder = tmp_path_factory.mktemp("two_layers")
    gcode = folder / "two.gcode"
    gcode.write_text(TWO_LAYERS)
    # timing from lengths and feeds alone: no acceleration
    args = build_parser().parse_args(["report", str(gcode), "--dialect", "seed", "--height", "1", "--voxel", "0.25",
                                      "--out", str(folder / "out"), "--json", "--accel", "0"])
    tp = read_gcode(gcode, dialect="seed")
    drift = ScalarField("drift_mm", "standoff drift", "mm", "coolwarm", symmetric=True, note="+ = nozzle too high")
    height = ScalarField("height_mm", "height", "mm", "magma")
    extra = [(drift, np.where(tp.layer == 1, 0.2, -0.05)), (height, lambda vertices, arrival: vertices[:, 2])]
    return report(_report_request(args), extra_fields=extra).summary


def test_per_layer_table_shows_the_closed_forms(two_layer_report):
    """The page's per-layer table: its numbers are the JSON's, which are the closed forms."""
    summary = two_layer_report
    assert_rows_equal(summary["layers"], two_layer_closed_forms(1.0))
    html = Path(summary["report_html"]).read_text()
    table = re.search(r'<details id="layer-times" open><summary>(.*?)</summary>.*?<table class="grid layer-table">'
                      r"(.*?)</table>", html, re.S)
    assert table[1] == "Per-layer times (2 layers): interlayer time 1.10 … 1.10 s"
    assert "<b>Interlayer time</b> = a layer's start − the end of the layer below" in html
    header = re.findall(r"<th>(.*?)</th>", table[2])
    assert header == ["layer", "Z (mm)", "start (s)", "end (s)", "depositing (s)", "deposited length (mm)",
                      "interlayer time (s)", "first line"]
    cells = [re.findall(r"<td>(.*?)</td>", row) for row in re.findall(r"<tr><td>.*?</tr>", table[2])]
    expected = [[f"{r['layer']}", f"{r['z_mm']:.3f}", f"{r['start_s']:.2f}", f"{r['end_s']:.2f}",
                 f"{r['deposit_s']:.2f}", f"{r['length_mm']:.2f}",
                 "–" if r["interlayer_s"] is None else f"{r['interlayer_s']:.2f}", str(r["first_line"])]
                for r in summary["layers"]]
    assert cells == expected == [["0", "0.000", "0.00", "2.00", "2.00", "20.00", "–", "3"],
                                 ["1", "1.000", "3.10", "6.10", "3.00", "30.00", "1.10", "8"]]


def test_extra_fields_reach_the_view(two_layer_report):
    """Colourings given to the report travel in the payload with their words, unit and range."""
    html = Path(two_layer_report["report_html"]).read_text()
    data = re.search(r'<script type="application/json" id="scene-data">(.*?)</script>', html, re.S)[1]
    payload = json.loads(data)
    fields = {f["name"]: f for f in payload["fields"]}
    assert list(fields) == ["arrival_s", "layer", "feed_mm_s", "bead_area_mm2", "drift_mm", "height_mm"]
    assert fields["drift_mm"]["title"] == "standoff drift (mm)" and fields["drift_mm"]["range"] == [-0.2, 0.2]
    deposit = payload["meshes"][0]
    assert deposit["name"] == "deposit"
    z = payload["lo"][2] + _decode(deposit["positions"], "<u2").reshape(-1, 3)[:, 2] / 65535 * payload["extent"][2]
    heights = _decode(deposit["scalars"]["height_mm"], "<f4")
    assert np.allclose(heights, z, atol=payload["extent"][2] / 65535 + 1e-5)  # each vertex's own Z
    drift = _decode(deposit["scalars"]["drift_mm"], "<f4")
    layer = _decode(deposit["scalars"]["layer"], "<f4")
    assert set(np.unique(layer)) == {0.0, 1.0}
    assert np.array_equal(drift, np.where(layer == 1, np.float32(0.2), np.float32(-0.05)))
    assert fields["height_mm"]["range"] == [pytest.approx(heights.min(), abs=1e-5),
                                            pytest.approx(heights.max(), abs=1e-5)]


def test_extra_field_legend_in_chromium(two_layer_report):
    """A colouring the viewer's script has never heard of gets its menu entry and legend."""
    sync_api = _playwright()
    with sync_api.sync_playwright() as p:
        browser = _browser(sync_api, p)
        try:
            page = browser.new_page(viewport={"width": 1280, "height": 900})
            problems = []
            payload = _open_viewer(page, Path(two_layer_report["report_html"]).resolve().as_uri(), problems)
            page.select_option("#viewer-colour", "drift_mm")
            shown, title, ticks, note = _legend(page)
            assert shown and title == "standoff drift (mm)" and note == "+ = nozzle too high"
            assert [float(t) for t in ticks] == pytest.approx([0.2, 0.1, 0.0, -0.1, -0.2])
            before = _canvas(page)
            page.select_option("#viewer-colour", "height_mm")
            assert _legend(page)[1] == "height (mm)"
            assert np.abs(_canvas(page) - before).max() > 60  # recoloured
            # the two layers' clip heights: each bead's top and a twentieth of the layer step
            assert [r["clip_mm"] for r in payload["layers"]] == pytest.approx([1.05, 2.05])
            assert problems == []
        finally:
            browser.close()


@pytest.mark.parametrize("argv, message", [
    (["--fixture", str(DATA / "demo_clamp.stl")], "--fixture needs --nozzle"),
    (["--dialect", "reprap"], "the program deposits nothing"),
], ids=["fixture-without-nozzle", "nothing-deposited"])
def test_report_refusals(tmp_path, argv, message):
    proc = subprocess.run([sys.executable, "-m", "dmdvox.cli", "report", str(DATA / "demo_block.gcode"), *argv,
                           "--out", str(tmp_path / "out")], capture_output=True, text=True, cwd=REPO, timeout=120)
    assert proc.returncode == 2 and message in proc.stderr and "Traceback" not in proc.stderr
    assert not (tmp_path / "out").exists()


def test_bead_area_per_row_from_the_slicer_comments(gcode_file):
    """Rows with ;WIDTH:/;HEIGHT: get their own cross-section, the others the bead's."""
    from dmdvox.process.profiles import BeadProfile
    from dmdvox.reporting.scene3d import row_bead_area

    tp = read_gcode(gcode_file(TWO_LAYERS), dialect="seed")
    bead = BeadProfile("ellipse", 2.5, 1.0)
    assert np.allclose(row_bead_area(tp, bead), np.pi / 4 * 2.5 * 1.0)
    width = np.full(len(tp), np.nan, np.float32)
    height = np.full(len(tp), np.nan, np.float32)
    width[3], height[3], height[4] = 3.0, 0.5, 2.0
    tp = dataclasses.replace(tp, width=width, height=height)
    assert np.allclose(row_bead_area(tp, bead), np.pi / 4 * np.array([2.5, 2.5, 2.5, 3.0 * 0.5, 2.5 * 2.0]))


def test_an_extra_field_replaces_a_standard_one_of_its_name(gcode_file):
    from dmdvox.process.profiles import BeadProfile
    from dmdvox.reporting.scene3d import BEAD_AREA, standard_fields

    tp = read_gcode(gcode_file(TWO_LAYERS), dialect="seed")
    vertices = np.array([[1.0, 0.0, 0.5], [5.0, 10.0, 1.5], [0.0, 15.0, 1.8]])
    arrival = np.array([1.0, 4.0, 5.5])
    own = dataclasses.replace(BEAD_AREA, note="from the deposit")
    fields = standard_fields(tp, BeadProfile("rect", 2.5, 1.0), vertices, arrival,
                             [(own, lambda v, a: v[:, 2] * 2.5)])
    assert [spec.name for spec, _ in fields] == ["arrival_s", "layer", "feed_mm_s", "bead_area_mm2"]
    spec, values = fields[3]
    assert spec.note == "from the deposit" and np.array_equal(values, vertices[:, 2] * 2.5)
    assert np.array_equal(fields[1][1], [0.0, 1.0, 1.0]) and np.array_equal(fields[2][1], [10.0, 10.0, 10.0])
    with pytest.raises(ValueError, match="2 values for 3 vertices"):
        standard_fields(tp, BeadProfile("rect", 2.5, 1.0), vertices, arrival, [(own, lambda v, a: v[:2, 2])])


# -- beads from the material (issues 12 and 13): speed and area, excess, growth, standoff, drift ----

RATE_G_MIN, DENSITY_G_CM3, BEAD_W = 10.0, 8.0, 2.0
Q = RATE_G_MIN / 60.0 / (DENSITY_G_CM3 / 1000.0)  # mm³/s of powder melted (catchment 1)
POWDER = ["--powder-rate", f"{RATE_G_MIN:g}", "--density", f"{DENSITY_G_CM3:g}", "--width", f"{BEAD_W:g}",
          "--profile", "rect"]
WALL_V = 10.0  # mm/s (F600)
WALL_H = Q / WALL_V / BEAD_W  # the growth of one rect bead per layer: A / w
WALL_STEP, WALL_LAYERS, WALL_S0 = 0.8, 8, 1.1  # a step below A / w: the wall outgrows its program
LOST_LINE_Z, LOST_LENGTH = 20.0, 5.0  # a last line far above the wall: its material never lands
# the first layer whose beads meet a standoff <= 0: s0 - k (h - dz) <= 0
WALL_CONTACT_LAYER = math.ceil(WALL_S0 / (WALL_H - WALL_STEP))


def wall_program() -> tuple[str, int]:
    """A single-bead wall of 20 mm lines, back and forth, and one short line programmed far
    above it; returns the text and the lost line's number."""
    lines = ["G90 G1 X0 Y0 Z0 F600"]
    for k in range(WALL_LAYERS):
        x0, x1 = (0, 20) if k % 2 == 0 else (20, 0)
        lines += [f"G1 X{x0} Y0 Z{k * WALL_STEP:.4f}", "M65", f"G1 X{x1} Y0 Z{k * WALL_STEP:.4f}", "M64"]
    lines += [f"G1 X5 Y0 Z{LOST_LINE_Z:g}", "M65", f"G1 X{5 + LOST_LENGTH:g} Y0 Z{LOST_LINE_Z:g}"]
    lost_line = len(lines)
    lines.append("M64")
    return "\n".join(lines) + "\n", lost_line


def _report_in_process(folder: Path, name: str, text: str, options: list[str]) -> tuple[dict, dict]:
    """Run the report in this process; returns its summary and the plots it drew (by PNG stem)."""
    from dmdvox.cli import _report_request, build_parser
    from dmdvox.reporting import figures
    from dmdvox.reporting.build import report

    gcode = folder / f"{name}.gcode"
    gcode.write_text(text)
    args = build_parser().parse_args(["report", str(gcode), "--dialect", "seed", *options, "--out",
                                      str(folder / "out"), "--json"])
    drawn = {}
    save = figures.Plot.save

    def keep(plot, png):
        drawn[Path(png).stem.removeprefix(f"{name}_")] = plot
        return save(plot, png)

    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(figures.Plot, "save", keep)
        summary = report(_report_request(args)).summary
    return summary, drawn


@pytest.fixture(scope="module")
def wall_report(tmp_path_factory):
    """The wall under the flow model at constant feed (so every bead is A = Q / v), the nozzle
    WALL_S0 above each programmed bead bottom."""
    text, lost_line = wall_program()
    summary, plots = _report_in_process(tmp_path_factory.mktemp("wall"), "wall", text,
                                        [*POWDER, "--accel", "0", "--voxel", "0.1", "--standoff", f"{WALL_S0:g}"])
    return summary, plots, lost_line


def _cells(html: str, table_class: str) -> list[list[str]]:
    table = re.search(rf'<table class="grid {table_class}">(.*?)</table>', html, re.S)[1]
    return [[unescape(c) for c in re.findall(r"<td>(.*?)</td>", row)] for row in re.findall(r"<tr><td>.*?</tr>", table)]


def test_wall_layers_on_the_page_are_the_closed_forms(wall_report):
    """Built top of layer k (k + 1) A/w, drift k (dz - A/w), standoff s0 - k (A/w - dz): in the
    JSON, in the page's table and in the plot."""
    summary, plots, _ = wall_report
    h, dz = WALL_H, WALL_STEP
    layers = summary["simulate"]["layers"]
    assert [r["layer"] for r in layers] == list(range(WALL_LAYERS))  # the lost line lays no layer
    k = np.arange(WALL_LAYERS)
    # rect beads stacked on rect beads: the height field solve is exact up to rounding
    assert [r["programmed_z_mm"] for r in layers] == pytest.approx(k * dz, abs=1e-9)
    assert [r["built_top_mm"]["mean"] for r in layers] == pytest.approx((k + 1) * h, abs=1e-6)
    assert [r["built_top_mm"]["min"] for r in layers] == pytest.approx((k + 1) * h, abs=1e-6)
    assert [r["built_top_mm"]["max"] for r in layers] == pytest.approx((k + 1) * h, abs=1e-6)
    assert [r["drift_mm"] for r in layers] == pytest.approx(k * (dz - h), abs=1e-6)
    assert [r["standoff_mm"] for r in layers] == pytest.approx(WALL_S0 - k * (h - dz), abs=1e-6)

    html = Path(summary["report_html"]).read_text()
    assert '<section id="growth">' in html and '<section id="material">' in html
    cells = _cells(html, "growth-table")
    assert cells == [[str(r["layer"]), f"{r['programmed_z_mm']:.3f}",
                      f"{r['built_top_mm']['mean'] + r['drift_mm']:.3f}", f"{r['built_top_mm']['mean']:.3f}",
                      f"{r['built_top_mm']['min']:.3f} … {r['built_top_mm']['max']:.3f}",
                      f"{round(r['drift_mm'], 3) + 0.0:+.3f}", f"{r['standoff_mm']:.3f}"] for r in layers]
    shown = np.array([[float(c.split(" … ")[0]) for c in row[1:]] for row in cells])
    expected = np.column_stack([k * dz, k * dz + h, (k + 1) * h, (k + 1) * h, k * (dz - h), WALL_S0 - k * (h - dz)])
    assert np.allclose(shown, expected, atol=5e-4 + 1e-9)

    # the plot draws the same numbers
    plot = plots["growth_layers"]
    lines = {line.get_label(): line for line in plot.axes.get_lines()}
    assert np.allclose(lines["built top (mean)"].get_ydata(), (k + 1) * h, atol=1e-6)
    bars = [c for c in plot.axes.containers if c.get_label() == "programmed bead (bottom to top)"][0]
    assert np.allclose([b.get_y() for b in bars], k * dz, atol=1e-9)
    assert np.allclose([b.get_y() + b.get_height() for b in bars], k * dz + h, atol=1e-6)
    drift_bars = plot.lower.containers[0]
    assert np.allclose([b.get_height() for b in drift_bars], k * (dz - h), atol=1e-6)
    assert plot.title in html


def test_wall_standoff_plot_steps_down_by_the_excess_growth(wall_report):
    """Every bead of layer k meets the standoff s0 - k (A/w - dz); the plot shows it over the
    layer's deposition time, the contact line at 0, and the lost line's pieces where their
    material was lost (s0 + its programmed Z above the wall's top)."""
    summary, plots, _ = wall_report
    plot = plots["standoff"]
    lines = {line.get_label(): line for line in plot.axes.get_lines()}
    t = np.asarray(lines["standoff met by the beads"].get_xdata(), float)
    s = np.asarray(lines["standoff met by the beads"].get_ydata(), float)
    drawn = np.isfinite(t)
    seen = np.zeros(drawn.size, bool)
    for row in summary["layers"][:WALL_LAYERS]:  # the per-layer times (layer_table) of the program
        inside = drawn & (t >= row["start_s"] - 1e-9) & (t <= row["end_s"] + 1e-9)
        assert inside.any()
        assert np.allclose(s[inside], WALL_S0 - row["layer"] * (WALL_H - WALL_STEP), atol=1e-6)
        seen |= inside
    assert seen[drawn].all()  # nothing drawn outside the wall's layers
    assert lines["nozzle touches the part"].get_ydata()[0] == 0.0
    assert lines[f"programmed standoff {WALL_S0:g} mm"].get_ydata()[0] == WALL_S0
    lost = [c for c in plot.axes.collections if c.get_label().startswith("material lost")][0]
    assert np.allclose(lost.get_offsets()[:, 1], WALL_S0 + LOST_LINE_Z - WALL_LAYERS * WALL_H, atol=1e-6)


def test_wall_contact_and_lost_material_are_called_out(wall_report):
    """The summary's cards and the growth section name the layer and line where the part reaches
    the nozzle, and the material lost with its line."""
    summary, _, lost_line = wall_report
    html = unescape(Path(summary["report_html"]).read_text())
    contact = summary["growth"]["first_contact"]
    first_line = {r["layer"]: r["first_line"] for r in summary["layers"]}
    assert contact["layer"] == WALL_CONTACT_LAYER and contact["line"] == first_line[WALL_CONTACT_LAYER]
    assert contact["standoff_mm"] == pytest.approx(WALL_S0 - WALL_CONTACT_LAYER * (WALL_H - WALL_STEP), abs=1e-6)
    lowest = WALL_S0 - (WALL_LAYERS - 1) * (WALL_H - WALL_STEP)  # the top layer's beads
    assert (f'<div class="card bad"><div class="card-title">Standoff</div>'
            f'<div class="card-value">{lowest:.2f} … {WALL_S0:.2f} mm</div>'
            f'<div class="card-note">the part reaches the nozzle at line {contact["line"]} '
            f'(layer {WALL_CONTACT_LAYER})</div>') in html
    assert f"The part grows into the nozzle: the standoff reaches {contact['standoff_mm']:.2f} mm at line " \
           f"{contact['line']} (layer {WALL_CONTACT_LAYER}" in html
    sim = summary["simulate"]
    lost = Q * LOST_LENGTH / WALL_V  # the line's material at constant feed
    assert sim["lost_volume_mm3"] == pytest.approx(lost, rel=1e-9)
    assert sim["lost_lines"] == [lost_line]
    share = 100 * lost / (Q * (WALL_LAYERS * 20 + LOST_LENGTH) / WALL_V)
    assert (f'<div class="card-title">Lost material</div><div class="card-value">{lost:,.3g} mm³</div>'
            f'<div class="card-note">{share:.2f} % of the delivered, on 1 line(s), first line {lost_line}</div>'
            ) in html
    assert f"{lost:,.3g} mm³ of material never reached the part" in html and f"on 1 line(s): {lost_line}." in html
    # the inputs say how the beads were made
    assert "<td>model</td><td>flow (each row's material landed on the part as it stands, mass conserved)</td>" in html
    assert (f"<td>material</td><td>powder {RATE_G_MIN:g} g/min, density {DENSITY_G_CM3:g} g/cm³, catchment 1: "
            f"Q = {Q:.4g} mm³/s;") in html
    assert "<td>motion</td><td>constant feed (--accel 0: the tool at F everywhere)</td>" in html
    assert f"<td>landing</td><td>standoff {WALL_S0:g} mm, max drop 2 mm" in html


def test_wall_colourings_drift_and_bead_height(wall_report):
    """Per vertex: the bead height A / w everywhere, the drift k (dz - A/w) of the layer that laid
    it; the Z clip at each layer's built top."""
    summary, _, _ = wall_report
    html = Path(summary["report_html"]).read_text()
    payload = json.loads(re.search(r'<script type="application/json" id="scene-data">(.*?)</script>', html, re.S)[1])
    fields = {f["name"]: f for f in payload["fields"]}
    assert list(fields) == ["arrival_s", "layer", "feed_mm_s", "bead_area_mm2", "bead_height_mm", "drift_mm"]
    deposit = payload["meshes"][0]["scalars"]
    assert deposit["bead_height_mm"] == pytest.approx(WALL_H, rel=1e-6)  # constant: travels as one number
    assert deposit["bead_area_mm2"] == pytest.approx(Q / WALL_V, rel=1e-6)
    drift = _decode(deposit["drift_mm"], "<f4").astype(float)
    layer = _decode(deposit["layer"], "<f4").astype(float)
    assert set(np.unique(layer)) == set(range(WALL_LAYERS))
    assert np.allclose(drift, layer * (WALL_STEP - WALL_H), atol=1e-5)
    m = (WALL_LAYERS - 1) * (WALL_H - WALL_STEP)
    assert fields["drift_mm"]["range"] == pytest.approx([-m, m], abs=1e-5)
    assert fields["drift_mm"]["note"] == "+ = part below the program, − = above"
    clip = [r["clip_mm"] for r in payload["layers"][:WALL_LAYERS]]
    assert clip == pytest.approx((np.arange(WALL_LAYERS) + 1) * WALL_H + 0.05 * WALL_STEP, abs=1e-6)


CORNER_F, LEAD_F, CORNER_ACCEL, CORNER_SCV = 10.0, 5.0, 50.0, 1.0  # mm/s, mm/s, mm/s², mm/s


def corner_program() -> str:
    """A lead-in at 5 mm/s, two 10 mm rows at 10 mm/s up to a 90° corner and two after it, a
    lead-out at 5 mm/s. Rows 3 and 4 (lines 5 and 6) meet at the corner; the stops are at the
    slow lead-in and lead-out."""
    return ("G90 G1 X0 Y0 Z0 F300\nM65\nG1 X5 Y0 Z0 F300\nG1 X15 Y0 Z0 F600\nG1 X25 Y0 Z0 F600\n"
            "G1 X25 Y10 Z0 F600\nG1 X25 Y20 Z0 F600\nG1 X25 Y25 Z0 F300\nM64\n")


@pytest.fixture(scope="module")
def corner_report(tmp_path_factory):
    return _report_in_process(tmp_path_factory.mktemp("corner"), "corner", corner_program(),
                              [*POWDER, "--accel", f"{CORNER_ACCEL:g}", "--square-corner-velocity", f"{CORNER_SCV:g}",
                               "--voxel", "0.1"])


def test_corner_rows_carry_the_largest_excess(corner_report):
    """At a 90° corner the tool slows from v to v_j (Klipper's rule: v_j = the square-corner
    velocity) while the powder keeps flowing: each side of the corner carries A0 (v - v_j)² / (2a)
    more than at its programmed speed (A0 = Q / v), more than anywhere else here; a stop from
    the lead-in's speed v_s carries A_s v_s² / (2a) = Q v_s / (2a)."""
    summary, _ = corner_report
    rows = summary["material"]["largest_excess"]
    a0 = Q / CORNER_F
    corner = a0 * (CORNER_F - CORNER_SCV) ** 2 / (2 * CORNER_ACCEL)
    stop = Q * LEAD_F / (2 * CORNER_ACCEL)
    assert stop < corner
    assert {rows[0]["line"], rows[1]["line"]} == {5, 6}
    assert [rows[0]["excess_mm3"], rows[1]["excess_mm3"]] == pytest.approx([corner, corner], rel=0.02)
    assert {rows[2]["line"], rows[3]["line"]} == {3, 8}
    assert [rows[2]["excess_mm3"], rows[3]["excess_mm3"]] == pytest.approx([stop, stop], rel=0.02)
    source = corner_program().splitlines()
    assert all(r["text"] == source[r["line"] - 1] for r in rows)
    # the page lists the same rows with the same numbers
    html = Path(summary["report_html"]).read_text()
    cells = _cells(html, "excess-table")
    assert [[c[0], c[1], c[-1]] for c in cells] == [[str(r["line"]), f"{r['excess_mm3']:.4f}",
                                                     f"<code>{r['text']}</code>"] for r in rows]


def test_corner_speed_and_area_plot(corner_report):
    """The planned speed's corners are the speeds of the plan in closed form: 0 at the stops,
    the lead-in's and the rows' F, v_j at the corner; the area is Q / v where the speed holds."""
    summary, plots = corner_report
    plot = plots["speed_area"]
    speed = {line.get_label(): line for line in plot.axes.get_lines()}["planned speed"]
    v = np.asarray(speed.get_ydata(), float)
    assert set(np.round(v[np.isfinite(v)], 9)) == {0.0, CORNER_SCV, LEAD_F, CORNER_F}
    area = {line.get_label(): line for line in plot.lower.get_lines()}["bead cross-section area"]
    a = np.asarray(area.get_ydata(), float)
    a = a[np.isfinite(a)]
    # the fast rows' cruise is the thinnest; below the floor (a quarter of a row's top speed) the
    # material goes to the stop's blob, which bounds the thickest piece
    assert a.min() == pytest.approx(Q / CORNER_F, rel=1e-9) and a.max() <= Q / (0.25 * LEAD_F) + 1e-9
    html = Path(summary["report_html"]).read_text()
    payload = json.loads(re.search(r'<script type="application/json" id="scene-data">(.*?)</script>', html, re.S)[1])
    mesh = payload["meshes"][0]
    heights = _decode(mesh["scalars"]["bead_height_mm"], "<f4").astype(float)
    x = payload["lo"][0] + _decode(mesh["positions"], "<u2").reshape(-1, 3)[:, 0] / 65535 * payload["extent"][0]
    y = payload["lo"][1] + _decode(mesh["positions"], "<u2").reshape(-1, 3)[:, 1] / 65535 * payload["extent"][1]
    # a rect bead stands Q / (v w): the fast rows' cruise the lowest, the lead-in (never faster
    # than its 5 mm/s) at least twice as high
    assert heights.min() == pytest.approx(Q / CORNER_F / BEAD_W, rel=1e-5)
    lead_in = (x < 4.0) & (np.abs(y) < BEAD_W)
    assert lead_in.any() and heights[lead_in].min() >= Q / LEAD_F / BEAD_W * (1 - 1e-5)
    assert heights.max() <= Q / (0.25 * LEAD_F) / BEAD_W * (1 + 1e-5)
    assert "<td>motion</td><td>acceleration 50 mm/s², square-corner velocity 1 mm/s (junction deviation" in html


def test_excess_of_e_rows_is_their_area_above_the_median(gcode_file):
    """E words meter each row: the excess is (A - A_median) L, A = E x filament area / L."""
    from dmdvox.deposit.simulate import row_table
    from dmdvox.process.flow import FlowSettings
    from dmdvox.process.plan import ProcessSettings
    from dmdvox.reporting.build import largest_excess, row_excess

    d = 1.75
    filament = math.pi * d * d / 4
    # three 10 mm rows at E per mm 0.03, 0.05, 0.04 (areas 3, 5 and 4 times 0.01 filament areas)
    text = ("M83\nG1 X0 Y0 Z0.3 F1200\nG1 X10 E0.3\nG1 X20 E0.5\nG1 X30 E0.4\n")
    tp = read_gcode(gcode_file(text), dialect="reprap")
    plan = plan_process(tp, ProcessSettings(width=0.5, flow=FlowSettings(filament_diameter_mm=d)))
    rows = row_table(plan, plan.lay(0.05))
    median = 0.04 * filament
    # (E is kept in single precision: rel 1e-6)
    assert row_excess(plan, rows) == pytest.approx([(0.03 * filament - median) * 10, (0.05 * filament - median) * 10,
                                                     0.0], rel=1e-6)
    listed = largest_excess(plan, rows)
    assert [r["line"] for r in listed] == [4]  # the only row above the median
    assert listed[0]["excess_mm3"] == pytest.approx(0.01 * filament * 10, rel=1e-6)


def test_cards_for_runaway_growth_and_steady_standoff():
    """The standoff card: runaway growth is bad, a drifting standoff watched, a steady one good."""
    from dmdvox.reporting.page import _verdict

    base = {"info": {"layers": 3, "duration_s": 10.0},
            "simulate": {"deposit_volume_mm3": 1.0, "pore_count": 0, "porosity_percent": 0.0,
                         "lost_volume_mm3": 0.0, "deposited_volume_mm3": 1.0, "layers": [{"drift_mm": 0.25}]},
            "growth": {"first_contact": None, "standoff_mm": {"min": 10.0, "max": 12.0, "final": 10.0}}}
    for trend, level, note in (("runaway", "bad", "runaway growth: final 10.00 mm"),
                               ("drifting", "watch", "drifting, final 10.00 mm; top layer drift +0.25 mm"),
                               ("settling", "good", "settling, final 10.00 mm; top layer drift +0.25 mm")):
        sections = {**base, "simulate": {**base["simulate"], "standoff_trend": trend}}
        html = unescape(_verdict(sections))
        assert (f'<div class="card {level}"><div class="card-title">Standoff</div><div class="card-value">10.00 … '
                f'12.00 mm</div><div class="card-note">{note}</div>') in html
        assert "Lost material" not in html


def test_material_colourings_in_chromium(wall_report):
    """The report of a program with material offers the material's colourings with their words
    and units; the drift's legend is symmetric about 0 with its sign note; the new sections show."""
    sync_api = _playwright()
    summary, _, _ = wall_report
    with sync_api.sync_playwright() as p:
        browser = _browser(sync_api, p)
        try:
            page = browser.new_page(viewport={"width": 1280, "height": 900})
            problems = []
            payload = _open_viewer(page, Path(summary["report_html"]).resolve().as_uri(), problems)
            for heading in ("Material and speed", "Built layers and standoff"):
                assert page.get_by_role("heading", name=heading).is_visible()
            options = page.eval_on_selector_all("#viewer-colour option", "os => os.map(o => [o.value, o.text])")
            assert options == [["arrival_s", "deposition time (s)"], ["layer", "layer number"],
                               ["feed_mm_s", "feed (mm/s)"],
                               ["bead_area_mm2", "bead cross-section area (mm²)"],
                               ["bead_height_mm", "bead height (mm)"], ["drift_mm", "drift from the program (mm)"],
                               ["solid", "one colour"]]
            page.select_option("#viewer-colour", "drift_mm")
            shown, title, ticks, note = _legend(page)
            lo, hi = {f["name"]: f for f in payload["fields"]}["drift_mm"]["range"]
            assert shown and title == "drift from the program (mm)"
            assert note == "+ = part below the program, − = above"
            assert lo == -hi and float(ticks[0]) == pytest.approx(hi, abs=0.01)
            assert float(ticks[-1]) == pytest.approx(lo, abs=0.01)
            drift = _canvas(page)
            page.select_option("#viewer-colour", "bead_height_mm")
            shown, title, ticks, note = _legend(page)
            assert shown and title == "bead height (mm)" and note == "of the bead piece that laid each point"
            assert len(ticks) == 1 and float(ticks[0][4:]) == pytest.approx(WALL_H, abs=0.01)  # "all 1.04"
            assert np.abs(_canvas(page) - drift).max() > 60  # recoloured
            assert page.locator("figure.plot svg").count() == 3  # speed and area, layers, standoff
            assert problems == []
        finally:
            browser.close()


def test_the_page_shows_every_warning_of_the_json_and_the_detected_dialect(tmp_path, monkeypatch):
    """The reader's warnings and the run's (lost material, the part growing into the nozzle) are
    all on the page, as in --json; under --dialect auto the inputs name the dialect it detected."""
    import contextlib
    import io

    from dmdvox import cli

    text, _ = wall_program()
    lines = text.splitlines()
    gcode = tmp_path / "wall.gcode"
    gcode.write_text("\n".join([*lines[:3], "G1 Xfoo", *lines[3:]]) + "\n")  # a reader warning
    monkeypatch.setenv("DMDVOX_CACHE", "off")
    stdout = io.StringIO()
    with contextlib.redirect_stdout(stdout), contextlib.redirect_stderr(io.StringIO()):
        code = cli.main(["report", str(gcode), *POWDER, "--accel", "0", "--voxel", "0.1", "--standoff",
                         f"{WALL_S0:g}", "--out", str(tmp_path / "out"), "--json"])
    assert code == 0
    summary = json.loads(stdout.getvalue())
    warnings = summary["warnings"]
    assert any(":4: word X has no number" in w for w in warnings)
    assert any("never reached the part" in w for w in warnings) and any("grows into the nozzle" in w for w in warnings)
    html = unescape(Path(summary["report_html"]).read_text())
    assert f"<summary>{len(warnings)} warning(s)</summary>" in html
    for warning in warnings:
        assert f"<li>{warning}</li>" in html
    assert "<td>dialect</td><td>seed</td>" in html


def test_the_first_collision_picture_shows_the_part_as_it_stood_then(tmp_path, monkeypatch):
    """The nozzle meets the clamp in the first layer: the picture shows that layer's part, not
    the finished block (the top of the part then: the first layer's bead top)."""
    import contextlib
    import io

    from dmdvox import cli
    from dmdvox.reporting import figures

    drawn = {}
    picture = figures.collision_picture

    def keep(surface, *args, **kwargs):
        drawn["surface"] = surface
        drawn["collisions"] = args[2]
        return picture(surface, *args, **kwargs)

    monkeypatch.setattr(figures, "collision_picture", keep)
    monkeypatch.setenv("DMDVOX_CACHE", "off")
    stdout = io.StringIO()
    with contextlib.redirect_stdout(stdout), contextlib.redirect_stderr(io.StringIO()):
        code = cli.main(["report", str(DATA / "demo_block.gcode"), "--nozzle", NOZZLE, "--fixture",
                         str(DATA / "demo_clamp.stl"), "--plate", "0", "--voxel", "0.25", "--out",
                         str(tmp_path / "out"), "--json"])
    assert code == 0
    summary = json.loads(stdout.getvalue())
    first = drawn["collisions"][0]
    tp = read_gcode(DATA / "demo_block.gcode")
    row = int(np.flatnonzero(tp.line == first["line"])[0])
    layer_top = tp.layer_z[tp.layer[row]] + 0.8  # the seed's 0.8 mm bead on its programmed bottom
    vertices = drawn["surface"][0]
    voxel = summary["simulate"]["voxel_mm"]
    assert vertices[:, 2].max() <= layer_top + voxel
    assert vertices[:, 2].max() < summary["simulate"]["bbox_mm"][1][2] - 0.8  # not the finished block
