"""docs/API.md runs as written (issue 17): its Python blocks, in order, in one namespace, from a
directory that sees the repository's data; and the values they print are the command line's."""

import json
import re
import subprocess
import sys

import numpy as np
import pytest

from .conftest import REPO

BLOCK = re.compile(r"```python\n(.*?)```", re.S)


@pytest.fixture(scope="module")
def namespace(tmp_path_factory):
    work = tmp_path_factory.mktemp("api")
    (work / "data").symlink_to(REPO / "data")
    blocks = BLOCK.findall((REPO / "docs" / "API.md").read_text())
    assert len(blocks) >= 6
    scope: dict = {}
    with pytest.MonkeyPatch.context() as patch:
        patch.chdir(work)
        for number, code in enumerate(blocks):
            exec(compile(code, f"docs/API.md block {number + 1}", "exec"), scope)
    scope["work"] = work
    return scope


def test_the_examples_give_what_the_command_line_prints(namespace):
    proc = subprocess.run([sys.executable, "-m", "dmdvox.cli", "simulate", "data/demo_block.gcode", "--voxel", "0.375",
                           "--json"], capture_output=True, text=True, cwd=REPO)
    assert proc.returncode == 0, proc.stderr
    cli = json.loads(proc.stdout)
    api = namespace["sim"].to_json()
    for key in ("deposit_volume_mm3", "active_voxels", "pore_count", "porosity_percent", "bbox_mm"):
        assert api[key] == cli[key], key


def test_the_examples_results_are_typed_and_consistent(namespace):
    import pyvista as pv

    sim, comparison = namespace["sim"], namespace["comparison"]
    assert isinstance(namespace["surface"], pv.PolyData) and isinstance(namespace["corner"], pv.ImageData)
    # the image covers the box 0..6 mm in whole 8^3 blocks of the grid (at most a block more a side)
    corner, voxel = namespace["corner"], sim.grid.voxel
    first = np.array(corner.origin)
    last = first + voxel * (np.array(corner.dimensions) - 1)
    assert np.all(first <= 0.0) and np.all(first > -8 * voxel) and np.all(last >= 6.0) and np.all(last < 6.0 + 8 * voxel)
    assert np.all(np.array(corner.dimensions) % 8 == 0)
    # its samples are the grid's values at those points
    points = np.asarray(corner.points)
    assert np.allclose(corner.point_data["sdf_mm"], sim.grid.trilinear(points), atol=1e-6)
    # every surface vertex was deposited at a time within the program as the machine runs it
    arrival = namespace["surface"].point_data["arrival_s"]
    assert arrival.min() >= 0 and arrival.max() <= sim["duration_s"]  # the planned motion
    assert comparison.deposit is comparison.simulation.grid
    assert comparison["deposit_volume_mm3"] == pytest.approx(sim["deposit_volume_mm3"])
    assert namespace["half"]["deposit_volume_mm3"] < sim["deposit_volume_mm3"]
    assert namespace["again"].to_json()["deposit_volume_mm3"] == sim["deposit_volume_mm3"]
    assert (namespace["work"] / "out" / "api_report" / namespace["page"].page.name).is_file()


def test_the_check_and_diff_examples(namespace):
    # the dict's limits hold on the demo; the cell's clamp fails it, as `dmdvox check` exits 3
    assert namespace["verdict"].passed and namespace["verdict"].exit_code == 0
    cell = namespace["cell"]
    failed = {item["name"] for item in cell["limits"] if item["verdict"] == "fail"}
    assert cell.exit_code == 3 and failed == {"collisions", "min_clearance_mm"}
    assert (namespace["work"] / "out" / "check.xml").is_file()
    # the shortened line removes material only, all of it on that line of the old program
    change = namespace["change"]
    assert change["added_mm3"] == 0 and change["removed_mm3"] > 0
    assert change["removed_lines"][0]["line"] == 267 and change["removed_lines"][0]["layer"] == 7
