"""Bad inputs through the CLI: a clear message, exit code 2, never a traceback (docs/BAD_INPUTS.md)."""

import subprocess
import sys

import pytest

from .conftest import DATA, REPO


def run(*args):
    proc = subprocess.run([sys.executable, "-m", "dmdvox.cli", *map(str, args)], capture_output=True, text=True,
                          cwd=REPO, timeout=120)
    assert "Traceback" not in proc.stderr
    return proc


@pytest.mark.parametrize("content, message", [
    (b"", "empty file"),
    (bytes(range(256)) * 20, "binary data"),
    (b"G1 X0 Y0 Z0\nG1 Xnan\n", "word X has no number"),
    (b"G1 X0 Y0 Z0\nG1 X" + b"9" * 400 + b"\n", "not a finite number"),
    (b"G1 X0 Y0 Z0\nG2 X10 Y0 R1\n", "smaller than half the chord"),
])
def test_bad_gcode_strict(tmp_path, content, message):
    path = tmp_path / "bad.gcode"
    path.write_bytes(content)
    proc = run("info", path, "--strict")
    assert proc.returncode == 2 and message in proc.stderr


def test_motion_before_position_is_known(tmp_path):
    path = tmp_path / "blind.gcode"
    path.write_text("M65\nG91\nG1 X10\nG90\nG1 X0 Y0 Z0\nG1 X5\n")
    proc = run("info", path, "--dialect", "seed", "--json")
    assert proc.returncode == 0
    assert "deposit move from an unknown position" in proc.stdout


@pytest.mark.parametrize("args, message", [
    (["--dialect", "fanuc"], "invalid choice"),
    (["--profile", "triangle"], "invalid choice"),
    (["--width", "-1"], "--width must be a positive finite length"),
    (["--voxel", "0.0001"], "use --voxel"),
])
def test_bad_options(args, message):
    proc = run("simulate", DATA / "demo_block.gcode", *args)
    assert proc.returncode == 2 and message in proc.stderr


def test_unwritable_output_folder(tmp_path):
    blocker = tmp_path / "file"
    blocker.write_text("not a folder")
    proc = run("simulate", DATA / "demo_block.gcode", "--voxel", "0.25", "--out", blocker / "out")
    assert proc.returncode == 2 and "cannot write output" in proc.stderr


@pytest.mark.parametrize("content, message", [
    (b"", "empty STL"),
    (b"\0" * 80 + (5).to_bytes(4, "little") + b"\0" * 60, "truncated"),
    (b"solid x\nendsolid x\n", "no triangles"),
])
def test_bad_cad(tmp_path, content, message):
    cad = tmp_path / "bad.stl"
    cad.write_bytes(content)
    proc = run("compare", DATA / "demo_block.gcode", cad, "--voxel", "0.25")
    assert proc.returncode == 2 and message in proc.stderr
