"""`dmdvox demo`: the whole pipeline on the shipped samples."""

import json
import subprocess
import sys
from pathlib import Path

from .conftest import REPO


def test_demo_runs_the_pipeline(tmp_path):
    proc = subprocess.run([sys.executable, "-m", "dmdvox.cli", "demo", "--out", str(tmp_path / "demo"), "--json"],
                          capture_output=True, text=True, cwd=REPO, timeout=300)
    assert proc.returncode == 0, proc.stderr
    summary = json.loads(proc.stdout)
    # The seed block: round track ends leave the CAD box's corners a little short.
    assert 0.1 < summary["void_percent"] < 2.0 and summary["overbuild_percent"] < 0.1
    # The clamp at x in [-6, -1] is too tall for the cone at the first layer's track ends (x = 1.25).
    assert summary["collisions"] and all(c["obstacle"] == "fixture:demo_clamp" for c in summary["collisions"])
    assert all(c["position_mm"][0] < 3.0 for c in summary["collisions"])
    names = {Path(p).name for p in summary["outputs"]}
    assert {"demo_block.vdb", "demo_block_compare.vti", "demo_block_half.png", "demo_block_iso.png",
            "demo_block_report.html", "demo_summary.json"} <= names
    assert all(Path(p).exists() for p in summary["outputs"])
