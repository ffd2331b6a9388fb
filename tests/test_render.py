"""`dmdvox render`: headless pictures of the part at a moment of the build."""

import subprocess
import sys

import numpy as np
import pytest
from PIL import Image

from dmdvox.view.pictures import image_is_blank

from .conftest import DATA, REPO


def render(tmp_path, name, *extra):
    png = tmp_path / f"{name}.png"
    proc = subprocess.run([sys.executable, "-m", "dmdvox.cli", "render", str(DATA / "demo_block.gcode"), "--png",
                           str(png), "--size", "400x300", *extra], capture_output=True, text=True, cwd=REPO)
    assert proc.returncode == 0, proc.stderr
    return png


def part_pixels(png):
    rgb = np.asarray(Image.open(png).convert("RGB")).astype(int)
    # viridis colours the part; the background is white and the frame grey.
    spread = rgb.max(axis=2) - rgb.min(axis=2)
    return int(np.count_nonzero(spread > 40))


def test_half_build_shows_less_than_the_full_part(tmp_path):
    full = render(tmp_path, "full")
    half = render(tmp_path, "half", "--at", "0.5")
    start = render(tmp_path, "start", "--time", "0")
    assert Image.open(full).size == (400, 300)
    assert not image_is_blank(full) and not image_is_blank(half)
    # Same camera for every moment: the half-built block covers fewer coloured pixels.
    assert part_pixels(half) < 0.9 * part_pixels(full)
    assert part_pixels(start) < part_pixels(half)


def test_top_and_front_views_differ(tmp_path):
    top = np.asarray(Image.open(render(tmp_path, "top", "--view", "top")))
    front = np.asarray(Image.open(render(tmp_path, "front", "--view", "front")))
    assert np.abs(top.astype(int) - front.astype(int)).mean() > 5


@pytest.mark.parametrize("args, message", [(["--at", "1.5"], "--at"), (["--at", "0.5", "--time", "3"], "not both"),
                                           (["--size", "big"], "--size")])
def test_bad_requests(tmp_path, args, message):
    proc = subprocess.run([sys.executable, "-m", "dmdvox.cli", "render", str(DATA / "demo_block.gcode"), "--png",
                           str(tmp_path / "x.png"), *args], capture_output=True, text=True, cwd=REPO)
    assert proc.returncode == 2 and message in proc.stderr
