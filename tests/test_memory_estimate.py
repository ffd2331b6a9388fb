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

from .conftest import REPO

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
