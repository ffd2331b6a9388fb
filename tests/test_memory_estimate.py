"""The deposit's memory estimate (from the block footprint, before any voxel work) against the
peak RSS a run reaches: within 2x either way on parts where the grid and its construction
dominate, a solid block and a thin-walled box at 0.1 mm.

Each part runs in a fresh process: the imports, the toolpath and a small warm-up deposit (numba
loading, or on a cold cache compiling, its kernels) come first; the peak RSS is then reset
(``/proc/self/clear_refs``), the RSS is the baseline, and the measured figure is the peak RSS of
the deposit minus it.
"""

import json
import subprocess
import sys

import pytest

from .conftest import DATA, REPO

# The seed's track: 2.5 x 0.8 mm rect beads at 1.25 mm spacing, 0.8 mm layers, constant feed.
CHILD = r"""
import json, sys, tempfile
from pathlib import Path

from dmdvox.deposit.engine import deposit_beads, estimate_memory, plan_deposit
from dmdvox.deposit.simulate import fixed_plan
from dmdvox.process.profiles import BeadProfile
from dmdvox.toolpath import read_gcode

W, STEP, SPACING, VOXEL = 2.5, 0.8, 1.25, 0.1


def solid(side, layers):
    # zigzag hatch, alternating x and y
    n = int(round((side - W) / SPACING)) + 1
    lines = ["G90 G21", "F750"]
    for k in range(layers):
        for t in range(n):
            off = W / 2 + SPACING * t
            a, b = (W / 2, side - W / 2) if t % 2 == 0 else (side - W / 2, W / 2)
            (x0, y0), (x1, y1) = ((a, off), (b, off)) if k % 2 == 0 else ((off, a), (off, b))
            lines += [f"G0 X{x0:.4f} Y{y0:.4f} Z{k * STEP:.4f}", "M65", f"G1 X{x1:.4f} Y{y1:.4f}", "M64"]
    return lines


def box(side, layers):
    # two concentric square tracks per layer
    lines = ["G90 G21", "F750"]
    for k in range(layers):
        for t in range(2):
            a, b = W / 2 + t * SPACING, side - W / 2 - t * SPACING
            lines += [f"G0 X{a:.4f} Y{a:.4f} Z{k * STEP:.4f}", "M65", f"G1 X{b:.4f} Y{a:.4f}",
                      f"G1 X{b:.4f} Y{b:.4f}", f"G1 X{a:.4f} Y{b:.4f}", f"G1 X{a:.4f} Y{a:.4f}", "M64"]
    return lines


def beads(lines):
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "part.gcode"
        path.write_text("\n".join(lines) + "\n")
        tp = read_gcode(path, dialect="seed")
    return fixed_plan(tp, BeadProfile("rect", W, STEP)).beads(VOXEL)


def status(field):
    with open("/proc/self/status") as fh:
        return next(int(line.split()[1]) * 1024 for line in fh if line.startswith(field + ":"))


kind, side, layers = sys.argv[1], float(sys.argv[2]), int(sys.argv[3])
part = beads((solid if kind == "solid" else box)(side, layers))
deposit_beads(beads(box(20.0, 3)), VOXEL)
plan = plan_deposit(part, VOXEL)
estimate = estimate_memory(plan.prims, plan.domain, plan.footprint)
del plan
# The high-water mark from here on: a kernel compiled above (a cold numba cache) must not count.
with open("/proc/self/clear_refs", "w") as fh:
    fh.write("5")
base = status("VmRSS")
grid, _ = deposit_beads(part, VOXEL)
peak = status("VmHWM")
print(json.dumps({"estimate": estimate, "measured": peak - base, "grid": grid.memory_bytes}))
"""


@pytest.mark.parametrize("kind, side, layers", [("solid", 60.0, 13), ("box", 100.0, 25)])
def test_estimate_within_2x_of_the_peak(kind, side, layers):
    proc = subprocess.run([sys.executable, "-c", CHILD, kind, str(side), str(layers)], capture_output=True, text=True,
                          cwd=REPO, timeout=300)
    assert proc.returncode == 0, proc.stderr
    run = json.loads(proc.stdout)
    assert run["measured"] > 100 * 2**20  # the deposit, not the interpreter, makes the figure
    assert 0.5 <= run["estimate"] / run["measured"] <= 2.0, run


# A whole `simulate --out` run: the sweep, the void search, the .vdb, the surface and its files.
# The figure is the run's peak RSS above the interpreter's baseline, measured in the child after
# it has imported everything the run uses (VTK's ~180 MB among it) and run a small part once
# (numba loading its kernels): the memory check compares its estimate with what is free while
# the interpreter already runs, so the baseline is not the run's to estimate.
RUN_CHILD = r"""
import contextlib, io, json, sys, tempfile
from pathlib import Path

import vtk  # noqa: F401  (imported by the first VTK writer: part of the baseline)

from dmdvox import cli


def status(field):
    with open("/proc/self/status") as fh:
        return next(int(line.split()[1]) * 1024 for line in fh if line.startswith(field + ":"))


def simulate(argv, out):
    stdout = io.StringIO()
    with contextlib.redirect_stdout(stdout), contextlib.redirect_stderr(io.StringIO()):
        code = cli.main(["simulate", *argv, "--out", out, "--json"])
    assert code == 0, stdout.getvalue()
    return json.loads(stdout.getvalue())


with tempfile.TemporaryDirectory() as tmp:
    simulate([sys.argv[1], "--dialect", "seed", "--voxel", "0.25"], str(Path(tmp) / "warm"))
    with open("/proc/self/clear_refs", "w") as fh:
        fh.write("5")
    base = status("VmRSS")
    result = simulate(sys.argv[2:], str(Path(tmp) / "run"))
    peak = status("VmHWM")
print(json.dumps({"estimate": result["memory_estimate_bytes"], "measured": peak - base,
                  "grid": result["memory_bytes"], "active": result["active_voxels"]}))
"""


def _seed_part(path, lines):
    path.write_text("\n".join(["G90 G21", "F750", *lines]) + "\n")
    return path


def _wall(path, length, layers, step):
    # one bead per layer, back and forth
    lines = []
    for k in range(layers):
        a, b = (0.0, length) if k % 2 == 0 else (length, 0.0)
        lines += [f"G0 X{a:.4f} Y0 Z{k * step:.4f}", "M65", f"G1 X{b:.4f} Y0", "M64"]
    return _seed_part(path, lines)


def _block(path, side, layers, width, step, spacing):
    # zigzag hatch, alternating x and y: a solid block
    n = int(round((side - width) / spacing)) + 1
    lines = []
    for k in range(layers):
        for t in range(n):
            off = width / 2 + spacing * t
            a, b = (width / 2, side - width / 2) if t % 2 == 0 else (side - width / 2, width / 2)
            (x0, y0), (x1, y1) = ((a, off), (b, off)) if k % 2 == 0 else ((off, a), (off, b))
            lines += [f"G0 X{x0:.4f} Y{y0:.4f} Z{k * step:.4f}", "M65", f"G1 X{x1:.4f} Y{y1:.4f}", "M64"]
    return _seed_part(path, lines)


def _first_layers(source, path, layers):
    """A slicer file cut after its first ``layers`` layers (its header, so its own bead, kept)."""
    lines = source.read_text().split("\n")
    starts = [i for i, line in enumerate(lines) if line.startswith(";LAYER_CHANGE")]
    path.write_text("\n".join(lines[:starts[layers]]) + "\n")
    return path


def _parts(tmp):
    return {
        "thin wall": [_wall(tmp / "wall.gcode", 60.0, 24, 0.5), "--dialect", "seed", "--width", "1.0",
                      "--height", "0.5", "--voxel", "0.05"],
        "solid block": [_block(tmp / "block.gcode", 24.0, 8, 1.5, 0.6, 1.2), "--dialect", "seed", "--width", "1.5",
                        "--height", "0.6", "--voxel", "0.06"],
        "sparse infill": [_first_layers(DATA / "corpus" / "holeplate_prusa_25.gcode", tmp / "infill.gcode", 4),
                          "--voxel", "0.04"],
        "five-axis": [DATA / "tube_trunnion.gcode", "--machine", DATA / "machines" / "trunnion-ac.toml",
                      "--width", "1.2", "--voxel", "0.06"],
        # no --voxel: the file's own default (a twentieth of its 0.6 mm bead)
        "slicer file, default voxel": [_first_layers(DATA / "corpus" / "lbracket_prusa_25.gcode", tmp / "slicer.gcode",
                                                     2)],
    }


@pytest.mark.parametrize("name", ["thin wall", "solid block", "sparse infill", "five-axis",
                                  "slicer file, default voxel"])
def test_run_estimate_within_0_7x_to_2x_of_the_peak(tmp_path, monkeypatch, name):
    monkeypatch.setenv("DMDVOX_CACHE", "off")
    argv = [str(a) for a in _parts(tmp_path)[name]]
    proc = subprocess.run([sys.executable, "-c", RUN_CHILD, str(DATA / "demo_block.gcode"), *argv],
                          capture_output=True, text=True, cwd=REPO, timeout=600)
    assert proc.returncode == 0, proc.stderr
    run = json.loads(proc.stdout)
    assert run["measured"] > 100 * 2**20, run  # the run, not the interpreter, makes the figure
    assert 0.7 <= run["estimate"] / run["measured"] <= 2.0, run
