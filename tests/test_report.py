"""`dmdvox report`: one self-contained HTML page, checked as data and in headless Chromium."""

import base64
import json
import re
import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from dmdvox.report.scene3d import SceneMesh, decimate, scene_payload, vertex_normals
from dmdvox.toolpath.reader import read_gcode

from .conftest import DATA, REPO

CHROMIUM = shutil.which("chromium") or shutil.which("chromium-browser")
NOZZLE = "cone:tip=4,top=20,length=25"


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
    assert set(summary) == {"report_html", "info", "simulate", "compare", "collide", "outputs"}
    assert all(Path(p).is_file() for p in summary["outputs"])
    names = {Path(p).name for p in summary["outputs"]}
    assert {"demo_block_report.html", "demo_block_iso.png", "demo_block_top.png", "demo_block_cad_deviation.png",
            "demo_block_layers.png", "demo_block_clearance.png", "demo_block_collisions.png",
            "demo_block.vdb", "demo_block_compare.vti"} <= names
    # the same numbers as the separate commands give on the same inputs
    assert summary["info"]["layers"] == 8
    assert 0.1 < summary["compare"]["void_percent"] < 2.0
    assert summary["collide"]["first_collision_line"] is not None
    assert {c["obstacle"] for c in summary["collide"]["collisions"]} == {"fixture:demo_clamp"}


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
    payload = scene_payload([SceneMesh("deposit", vertices, triangles, (1, 1, 1), scalars={"arrival_s": arrival},
                                       timed=True)], tp, np.array([[1.0, 2.0, 3.0, 4.0]]), 12.7, None, None)
    lo, extent = np.array(payload["lo"]), np.array(payload["extent"])
    mesh = payload["meshes"][0]
    q = _decode(mesh["positions"], "<u2").reshape(-1, 3)
    assert np.all(np.abs(lo + q / 65535.0 * extent - vertices) <= 0.5 * extent / 65535.0 + 1e-12)
    assert np.array_equal(_decode(mesh["indices"], "<u4").reshape(-1, 3), triangles)
    assert np.allclose(_decode(mesh["scalars"]["arrival_s"], "<f4"), arrival, rtol=1e-6)
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


@pytest.mark.skipif(CHROMIUM is None, reason="Debian chromium is not installed (scripts/setup.sh installs it)")
def test_report_in_headless_chromium(report):
    """The page loads with no console message of level warning or error and no request beyond
    the file; the sections show; the 3-D view draws, replays and answers the seed's keys."""
    sync_api = pytest.importorskip("playwright.sync_api")
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
            page.wait_for_timeout(200)
            assert float(viewer("time")) == 0.0
            empty = canvas_colours()
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
    assert not names & {"hollow_clearance.png", "hollow_layers.png", "hollow_collisions.png"}
    html = Path(summary["report_html"]).read_text()
    assert '<section id="compare">' not in html and '<section id="collide">' not in html
    cavity = (size - 2 * width) ** 2 * 2.0
    shown = float(re.search(r"<td>(\d+\.\d{4})</td><td>\d+\.\d{3}</td><td>\(6\.25, 6\.25, 2\.\d\d\)</td>", html)[1])
    assert shown == pytest.approx(cavity, rel=0.05)


@pytest.mark.parametrize("argv, message", [
    (["--fixture", str(DATA / "demo_clamp.stl")], "--fixture needs --nozzle"),
    (["--dialect", "reprap"], "the program deposits nothing"),
], ids=["fixture-without-nozzle", "nothing-deposited"])
def test_report_refusals(tmp_path, argv, message):
    proc = subprocess.run([sys.executable, "-m", "dmdvox.cli", "report", str(DATA / "demo_block.gcode"), *argv,
                           "--out", str(tmp_path / "out")], capture_output=True, text=True, cwd=REPO, timeout=120)
    assert proc.returncode == 2 and message in proc.stderr and "Traceback" not in proc.stderr
    assert not (tmp_path / "out").exists()
