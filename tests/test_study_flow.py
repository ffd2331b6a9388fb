"""The overlap study under the flow model (issue 13): layers grow by A / d, heavy overlap leaves
lack of fusion, and the geometric union runs beside it."""

import json
import subprocess
import sys

import pytest

from dmdvox.study.overlap import OverlapCase, overlap_case

from .conftest import REPO

W, AREA = 2.0, 4.0 / 3.0  # the parabola of height 1 mm


@pytest.mark.parametrize("ratio", [0.5, 2 / 3, 1.0, 1.2])
def test_flow_patch_grows_by_area_over_spacing(ratio):
    d = ratio * W
    row = overlap_case(OverlapCase("parabola", W, 1.0, 4.0, d, 1.0, 3, W / 40, model="flow", area=AREA))
    assert row["layer_height_mm"] == pytest.approx(AREA / d, rel=0.01)
    assert row["mean_height_mm"] == pytest.approx(3 * AREA / d, rel=0.01)
    # Beads that overlap or touch leave no gap deeper than the melt reaches. At d = w the tracks'
    # flanks touch on a plane through voxel centres: cells on that seam weigh half a cell each
    # (a few cells per period, under 0.1 % of the section), nothing else may be empty.
    if ratio < 1.0:
        assert row["lack_of_fusion_percent"] == 0.0
    else:
        assert row["lack_of_fusion_percent"] < 0.1


def test_heavy_overlap_lifts_the_toe_off_the_layer_below():
    # At d = 0.3 w a bead rests mostly on the one before it: the gap under its far edge is deeper
    # than the melt reaches, and voids stay there (and push the layer above A / d).
    d = 0.3 * W
    row = overlap_case(OverlapCase("parabola", W, 1.0, 4.0, d, 1.0, 3, W / 40, model="flow", area=AREA))
    assert row["lack_of_fusion_percent"] > 1.0
    empty_share = row["lack_of_fusion_percent"] / 100
    assert row["mean_height_mm"] * (1 - empty_share) == pytest.approx(3 * AREA / d, rel=0.02)


def test_flow_study_runs_the_union_beside_it(tmp_path):
    proc = subprocess.run(
        [sys.executable, "-m", "dmdvox.cli", "study", "overlap", "--width", "2", "--area", str(AREA), "--spacing",
         "1.0:2.0:1.0", "--layers", "2", "--voxel", "0.1", "--plot", str(tmp_path / "p.png"), "--json"],
        capture_output=True, text=True, cwd=REPO)
    assert proc.returncode == 0, proc.stderr
    out = json.loads(proc.stdout)
    assert out["model"] == "flow" and len(out["rows"]) == len(out["union_rows"]) == 2
    flow, union = out["rows"][0], out["union_rows"][0]
    # the union loses the overlap: a thinner layer than the material makes
    assert union["mean_height_mm"] < flow["mean_height_mm"]
    assert (tmp_path / "p.png").stat().st_size > 0
