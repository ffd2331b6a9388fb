"""`dmdvox demo`: the whole pipeline on the shipped samples."""

import json
import subprocess
import sys
from pathlib import Path

import pytest

from dmdvox import progress

from .conftest import REPO, demo_void_percent


def test_demo_runs_the_pipeline(tmp_path):
    proc = subprocess.run([sys.executable, "-m", "dmdvox.cli", "demo", "--out", str(tmp_path / "demo"), "--json"],
                          capture_output=True, text=True, cwd=REPO, timeout=300)
    assert proc.returncode == 0, proc.stderr
    summary = json.loads(proc.stdout)
    # The seed block: round track ends leave the CAD box's corners and the wall between unlinked
    # track ends short (closed form in conftest). Those notches are 0.15 mm deep, little more
    # than the 0.125 mm voxel, so the sub-voxel occupancy errs here to first order: measured
    # 5 % low at 0.125 mm, 2.3 % low at 0.0625 mm.
    assert summary["void_percent"] == pytest.approx(demo_void_percent(), rel=0.08)
    # Nothing sticks out: the track ends reach the box's faces exactly, and faces on voxel
    # centres (0, 20 and 6 mm are multiples of 0.125 mm) get exact occupancies.
    assert summary["overbuild_percent"] == pytest.approx(0.0, abs=1e-6)
    # the demo says what it is doing (stderr is a pipe here: stage lines)
    stages = [line for line in proc.stderr.splitlines() if progress.is_progress_line(line)]
    assert any(line.startswith("dmdvox: demo: 1/2 report") for line in stages)
    assert any(line.startswith("dmdvox: deposit: ") for line in stages)
    assert any(line.startswith("dmdvox: demo: 2/2 picture") for line in stages)
    # The clamp at x in [-6, -1] is too tall for the cone at the first layer's track ends (x = 1.25).
    assert summary["collisions"] and all(c["obstacle"] == "fixture:demo_clamp" for c in summary["collisions"])
    assert all(c["position_mm"][0] < 3.0 for c in summary["collisions"])
    names = {Path(p).name for p in summary["outputs"]}
    assert {"demo_block.vdb", "demo_block_compare.vti", "demo_block_half.png", "demo_block_iso.png",
            "demo_block_report.html", "demo_summary.json"} <= names
    assert all(Path(p).exists() for p in summary["outputs"])
    _check_demo_heat(summary, names)


def _check_demo_heat(summary, names):
    """The demo's heat: a 1 kW beam along every deposit row for the planner's time on it, 0.4
    absorbed; the balance closes; 316L melts but does not pass its boiling point; the page shows it."""
    import numpy as np

    import dmdvox.api
    from dmdvox.demo import DATA, HEAT
    from dmdvox.thermal.materials import load_material

    heat = summary["thermal"]
    tp = dmdvox.api.plan(dmdvox.api.read_gcode(str(DATA / "demo_block.gcode"))).toolpath
    rows = tp.deposit & (tp.length > 0)
    on = float(np.sum(tp.t_end[rows] - tp.t_start[rows]) + np.sum(tp.dwell_on[rows]))
    assert heat["beam_energy_J"] == pytest.approx(HEAT["laser_power"] * on, rel=1e-6)
    assert heat["absorbed_J"] == pytest.approx(0.4 * heat["beam_energy_J"] + heat["birth_heat_unpaid_J"], rel=1e-3)
    assert heat["energy_balance_max_percent"] < 0.5
    steel = load_material("316L")
    assert steel.liquidus < heat["max_peak_temperature_C"] <= steel.boiling + 1e-6
    assert heat["thermal_voxel_mm"] == pytest.approx(2.5 / 4) and heat["part_cells"] > 0  # a quarter bead
    assert {"demo_block_heat_layers.png", "demo_block_peak_temperature.png", "demo_block_thermal.vdb"} <= names
    page = Path(summary["report_html"]).read_text()
    assert '<section id="heat"><h2>Heat</h2>' in page
    assert f"{heat['max_peak_temperature_C']:,.0f} °C" in page
