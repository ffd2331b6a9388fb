"""The memory guard: every grid-building command refuses a request that would not fit before it
allocates, names a voxel size that would, and ``--max-memory`` moves the limit."""

import contextlib
import io
import math
import re
import subprocess
import sys

import pytest

from dmdvox import cli, progress
from dmdvox.io.mesh import box_mesh, write_stl

from .conftest import DATA, REPO

GCODE = str(DATA / "demo_block.gcode")
CAD = str(DATA / "demo_block.stl")
NOZZLE = "cone:tip=6,top=30,length=40"
COMMANDS = {
    "simulate": ["simulate", GCODE],
    "compare": ["compare", GCODE, CAD],
    "render": ["render", GCODE, "--size", "160x120", "--png"],  # the test appends the PNG path
    "collide": ["collide", GCODE, "--nozzle", NOZZLE],
    "study-sweep": ["study", "sweep", GCODE, "--set", "width=2.5"],
    "report": ["report", GCODE, "--cad", CAD, "--nozzle", NOZZLE, "--out"],  # the test appends the folder
}
SUGGESTION = re.compile(r"use --voxel ([0-9.]+) or larger")


def command(name, tmp_path) -> list[str]:
    argv = list(COMMANDS[name])
    if name == "render":
        return argv + [str(tmp_path / "moment.png")]
    return argv + [str(tmp_path / "report")] if name == "report" else argv


def run(argv) -> tuple[int, str]:
    """``cli.main`` in this process: exit code, stderr."""
    err = io.StringIO()
    with contextlib.redirect_stderr(err), contextlib.redirect_stdout(io.StringIO()):
        code = cli.main([str(a) for a in argv])
    return code, err.getvalue()


@pytest.fixture
def work(monkeypatch) -> dict:
    """Counts of the work a refusal must come before: grids built (deposit, CAD, nozzle,
    fixtures all go through GridBuilder) and bead primitives made (helix chords among them)."""
    import dmdvox.deposit.engine as engine
    from dmdvox.grid.build import GridBuilder

    counts = {"grids": 0, "primitives": 0}
    grid_init = GridBuilder.__init__
    build_primitives = engine.build_primitives

    def counting_grid(self, *args, **kwargs):
        counts["grids"] += 1
        grid_init(self, *args, **kwargs)

    def counting_primitives(*args, **kwargs):
        counts["primitives"] += 1
        return build_primitives(*args, **kwargs)

    monkeypatch.setattr(GridBuilder, "__init__", counting_grid)
    monkeypatch.setattr(engine, "build_primitives", counting_primitives)
    return counts


def suggested_voxel(stderr: str) -> float:
    match = SUGGESTION.search(stderr)
    assert match, stderr
    return float(match.group(1))


@pytest.mark.parametrize("name", list(COMMANDS))
def test_refused_with_a_voxel_that_fits(tmp_path, name):
    proc = subprocess.run([sys.executable, "-m", "dmdvox.cli", *command(name, tmp_path), "--voxel", "0.001"],
                          capture_output=True, text=True, cwd=REPO, timeout=120)
    assert proc.returncode == 2
    assert "Traceback" not in proc.stderr
    lines = progress.without_progress(proc.stderr).strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("dmdvox: error: ") and "--voxel 0.001: " in lines[0]
    if name in ("collide", "report"):  # the nozzle's grid, wide for clearance measurements, is checked first
        assert lines[0].startswith(f"dmdvox: error: --nozzle {NOZZLE}: --voxel 0.001: ")
    memory = re.search(r"needs about ([0-9.e+]+) GiB.* but ([0-9.e+]+) GiB is available", proc.stderr)
    assert float(memory.group(1)) > float(memory.group(2)) > 0
    if name == "compare":  # the CAD part's level set counts beside the deposit
        parts = re.search(r"the run needs about [0-9.e+]+ GiB \((.*)\) but", proc.stderr).group(1)
        assert [part.split()[0] for part in parts.split(", ")] == ["deposit", "CAD"]
    assert 0.001 < suggested_voxel(proc.stderr) < 0.1
    assert not (tmp_path / "moment.png").exists() and not (tmp_path / "report").exists()


@pytest.mark.parametrize("name", ["simulate", "compare", "render", "collide", "report", "study-sweep"])
def test_refused_before_any_work(tmp_path, name, work):
    argv = command(name, tmp_path)
    code, stderr = run([*argv, "--voxel", "0.001"])
    assert code == 2 and suggested_voxel(stderr) > 0.001
    # Building the refused grid would take hours; the refusal comes from the estimate alone.
    assert work["grids"] == 0


@pytest.mark.parametrize("name", list(COMMANDS))
def test_max_memory_moves_the_limit(tmp_path, name):
    argv = [*command(name, tmp_path), "--voxel", "0.375"]  # the coarsest the demo's 0.75 mm bead allows
    code, stderr = run([*argv, "--max-memory", "0.001"])
    assert code == 2
    # what --max-memory allows is not what the machine has available
    assert "but --max-memory allows 0.001 GiB" in stderr and "raise --max-memory" in stderr
    assert "available" not in stderr
    assert suggested_voxel(stderr) > 0.375
    code, stderr = run([*argv, "--max-memory", "4"])
    assert code == 0, stderr
    assert (tmp_path / "moment.png").exists() == (name == "render")


def test_suggested_voxel_fits_the_same_limit():
    code, stderr = run(["simulate", GCODE, "--max-memory", "0.01"])
    assert code == 2
    voxel = suggested_voxel(stderr)
    assert 0.125 < voxel < 1.0  # coarser than the default w/20, still a few voxels per bead
    code, stderr = run(["simulate", GCODE, "--max-memory", "0.01", "--voxel", voxel])
    assert code == 0, stderr


def test_collide_fixture_refused_before_the_deposit(tmp_path, work):
    plate = tmp_path / "plate.stl"
    write_stl(plate, *box_mesh((-5000, -5000, -20), (5000, 5000, -10)))  # a 10 m plate
    argv = ["collide", GCODE, "--nozzle", NOZZLE, "--fixture", plate]
    code, stderr = run(argv)
    assert code == 2 and f"--fixture {plate}: --voxel 0.125: the run needs about" in stderr
    assert re.search(r"GiB \(nozzle [0-9.e+-]+, fixture plate [0-9.e+-]+\) but", stderr), stderr
    assert suggested_voxel(stderr) > 0.125
    assert work == {"grids": 0, "primitives": 0}


def test_helix_of_millions_of_turns_refused_before_its_chords(tmp_path, work):
    """A helix is swept as chords; three lines once made 22 GB of them before any check."""
    path = tmp_path / "helix.gcode"
    path.write_text("G28\nM65\nG2 X0 Y0 Z5 I1 P9999999\n")
    argv = ["simulate", path, "--voxel", "0.5"]
    code, stderr = run(argv)
    assert code == 2 and work == {"grids": 0, "primitives": 0}
    # G28 homes to the origin; the helix turns about (1, 0, z), radius 1 mm, P = 9999999 full
    # turns (start = end in the plane). A chord spanning 2a of a circle of radius r strays
    # r (1 - cos a) from it, so chords within the tolerance t = min(0.01, voxel / 4) = 0.01 mm
    # span at most 2 acos(1 - t / r): ceil(2 pi P / (2 acos(1 - t / r))) chords.
    chords = math.ceil(2 * math.pi * 9_999_999 / (2 * math.acos(1 - 0.01 / 1.0)))
    assert f"dmdvox: error: {path}: the helical and spiral arcs make {chords:,d} chords of 0.01 mm" in stderr
    assert "check their P words" in stderr
    code, stderr = run([*argv, "--max-memory", "0.001"])
    assert code == 2 and "but --max-memory allows 0.001 GiB" in stderr
