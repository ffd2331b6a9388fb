"""`dmdvox diff`: the demo block against a copy with its last hatch line moved off the part."""

import json
import math
from pathlib import Path

import numpy as np
import pytest

from dmdvox.cli import main
from dmdvox.process.profiles import RECT, revolved_volume

from .conftest import DATA

DEMO = DATA / "demo_block.gcode"
W, H = 2.5, 0.75  # the demo's rect bead: the seed's track, the layer step
R = W / 2
VOXEL = 0.25
MOVED_LINE = 267  # the top layer's last hatch line, x = 18.75 from y = 1.25 to 18.75
LENGTH = 17.5


def moved_copy(tmp_path: Path) -> tuple[Path, int]:
    """The demo with its last hatch line laid 5 mm further in x (beyond the block, which ends at
    x = 20): the laser off to travel there, on for the line. Returns the copy and the line's
    number in it."""
    lines = DEMO.read_text().splitlines()
    assert lines[MOVED_LINE - 1] == "G1 X18.7500 Y18.7500 Z5.2500" and lines[MOVED_LINE - 2] == "G1 X18.7500 Y1.2500 Z5.2500"
    new = lines[:MOVED_LINE - 1] + ["M64", "G0 X23.7500 Y1.2500 Z5.2500", "M65", "G1 X23.7500 Y18.7500 Z5.2500"]
    path = tmp_path / "demo_moved.gcode"
    path.write_text("\n".join(new + lines[MOVED_LINE:]) + "\n")
    return path, MOVED_LINE + 3


def test_diff_finds_the_moved_line_and_its_volume(capsys, tmp_path):
    new, new_line = moved_copy(tmp_path)
    out = tmp_path / "out"
    code = main(["diff", str(DEMO), str(new), "--voxel", str(VOXEL), "--cad", str(DATA / "demo_block.stl"),
                 "--out", str(out), "--json"])
    assert code == 0
    result = json.loads(capsys.readouterr().out)

    # Added: the moved bead alone, 5 mm from the part: the rect swept along the line plus its two
    # round ends (the profile revolved).
    added = W * H * LENGTH + revolved_volume(RECT, W, H)
    # Removed: what no other bead covers of the old line. Its neighbour (x = 17.5) covers x <= 18.75
    # and the link before it keeps the disc at its start (18.75, 1.25), so what goes is the strip
    # 18.75 <= x <= 20 along it but the quarter of that disc inside it (r L - pi r^2 / 4), and the
    # disc at its end (18.75, 18.75) beyond y = 18.75 but the half-lens shared with the neighbour's
    # end disc r = 1.25 away (pi r^2 / 2 - pi r^2 / 4 + ... : r^2 (pi / 2 - (pi / 3 - sqrt(3) / 4))),
    # all of it one layer high (the layer below only touches).
    removed = H * (R * LENGTH - math.pi * R**2 / 4 + R**2 * (math.pi / 2 - (math.pi / 3 - math.sqrt(3) / 4)))
    # The sub-voxel occupancy is exact for faces (linear in the SDF) but the voxel on a convex edge
    # counts half of itself where a quarter is material: at most v^2 / 4 per mm of edge. Both
    # solids have their top and bottom rims as edges: 2 L and a circle of radius r each.
    tolerance = VOXEL**2 / 4 * (4 * LENGTH + 4 * math.pi * R)
    assert result["added_mm3"] == pytest.approx(added, abs=tolerance)
    assert result["removed_mm3"] == pytest.approx(removed, abs=tolerance)
    assert result["net_mm3"] == pytest.approx(result["new_deposit_volume_mm3"] - result["old_deposit_volume_mm3"],
                                              rel=1e-6)

    # Located: the added material on the moved line of the copy, the removed on the old line.
    top = result["added_lines"][0]
    assert (top["line"], top["layer"]) == (new_line, 7)
    assert top["volume_mm3"] >= 0.99 * result["added_mm3"]
    top = result["removed_lines"][0]
    assert (top["line"], top["layer"]) == (MOVED_LINE, 7)
    assert top["volume_mm3"] >= 0.98 * result["removed_mm3"]
    assert result["added_unplaced_mm3"] == result["removed_unplaced_mm3"] == 0

    # Against the CAD box (0..20 mm): what went was inside it (void), what came is outside (overbuild).
    cad = result["cad"]
    assert cad["void_volume_mm3"]["change"] == pytest.approx(result["removed_mm3"], rel=0.02)
    assert cad["overbuild_volume_mm3"]["change"] == pytest.approx(result["added_mm3"], rel=0.02)

    # The map: occupancy change summed over the lattice is the net change; the picture shows it.
    import pyvista as pv

    from dmdvox.view.pictures import image_is_blank

    stem = "demo_block_vs_demo_moved"
    image = pv.read(out / f"{stem}_diff.vti")
    change = np.asarray(image.point_data["occupancy_change"], np.float64)
    assert change.clip(0).sum() * VOXEL**3 == pytest.approx(result["added_mm3"], rel=1e-5)
    assert -change.clip(None, 0).sum() * VOXEL**3 == pytest.approx(result["removed_mm3"], rel=1e-5)
    labels = np.asarray(image.point_data["label"])
    added_points = image.points[labels == 2]
    assert added_points[:, 0].min() >= 22.5 - VOXEL and added_points[:, 0].max() <= 25 + VOXEL
    assert not image_is_blank(out / f"{stem}_diff.png")
    assert str(out / f"{stem}_diff.json") in result["outputs"]


def test_a_large_lattice_is_written_as_pieces(tmp_path, monkeypatch):
    # Past the single-image size the map is a .vtm of pieces over the occupied regions only;
    # pieces share their boundary planes, so each voxel is counted once by its position. The
    # changed blocks are placed a few at a time here (as a large change is), with the same lines.
    import pyvista as pv

    import dmdvox
    from dmdvox import changes

    monkeypatch.setattr(changes, "SINGLE_VTI_VOXELS", 0)
    monkeypatch.setattr(changes, "CHUNK_BLOCKS", 2)
    new, new_line = moved_copy(tmp_path)
    result = dmdvox.diff(DEMO, new, voxel=0.5, out_dir=tmp_path / "out")
    assert result["changed_blocks"] > 2
    for side, line in (("added", new_line), ("removed", MOVED_LINE)):
        rows = result[f"{side}_lines"]
        assert rows[0]["line"] == line
        assert sum(row["volume_mm3"] for row in rows) + result[f"{side}_unplaced_mm3"] == pytest.approx(
            result[f"{side}_mm3"], rel=1e-9)
    vtm = next(Path(p) for p in result["outputs"] if p.endswith(".vtm"))
    seen = {}
    for block in pv.read(vtm):
        change = np.asarray(block.point_data["occupancy_change"], np.float64)
        for point, value in zip(np.round(block.points[change != 0] / 0.5).astype(np.int64), change[change != 0]):
            seen[tuple(point)] = value
    values = np.array(list(seen.values()))
    assert values.clip(0).sum() * 0.5**3 == pytest.approx(result["added_mm3"], rel=1e-5)
    assert -values.clip(None, 0).sum() * 0.5**3 == pytest.approx(result["removed_mm3"], rel=1e-5)
