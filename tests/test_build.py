"""dmdvox.Build (issue 24): one build, each stage computed once, counted on the real stage
functions (wrapped), and the same numbers as the stages run one by one without reuse."""

from collections import Counter

import numpy as np
import pytest

import dmdvox
from dmdvox.comparison import compare as compare_module
from dmdvox.comparison.compare import CompareRequest, compare
from dmdvox.deposit import simulate as simulate_module
from dmdvox.deposit.simulate import SimulateRequest, simulate
from dmdvox.grid import vdbio
from dmdvox.io.mesh import read_stl, write_stl
from dmdvox.limits import CheckRequest, check
from dmdvox.process import plan as plan_module

from .conftest import DATA

GCODE = DATA / "prusa_block_20.gcode"  # E words: the flow model, so the beads are landed
CAD = DATA / "slicer_block.stl"
VOXEL = 0.1
LIMITS = {"void_percent": 50.0, "max_drift_mm": 10.0}


def _without_timings(summary: dict) -> dict:
    return {k: v for k, v in summary.items() if k != "timings_s"}


def _same(a, b, path="") -> None:
    """Equal JSON values (floats to 1e-12 relative, NaN equal to NaN)."""
    if isinstance(a, dict):
        assert set(a) == set(b), path
        for key in a:
            _same(a[key], b[key], f"{path}.{key}")
    elif isinstance(a, list):
        assert len(a) == len(b), path
        for k, (x, y) in enumerate(zip(a, b)):
            _same(x, y, f"{path}[{k}]")
    elif isinstance(a, float) and isinstance(b, float):
        assert a == pytest.approx(b, rel=1e-12, abs=0.0, nan_ok=True), path
    else:
        assert a == b, path


class Counts:
    """Calls of the stage functions, by wrapping the real ones."""

    def __init__(self, monkeypatch):
        self.calls = Counter()
        self.converted = Counter()  # id(grid) -> level sets built from it

        def counted(name, function):
            def wrapper(*args, **kwargs):
                self.calls[name] += 1
                return function(*args, **kwargs)
            return wrapper

        monkeypatch.setattr(simulate_module, "deposit_beads", counted("sweep", simulate_module.deposit_beads))
        monkeypatch.setattr(plan_module, "land", counted("land", plan_module.land))
        monkeypatch.setattr(plan_module, "build_beads", counted("beads", plan_module.build_beads))
        monkeypatch.setattr(compare_module, "like_grid", counted("cad_level_set", compare_module.like_grid))
        build_openvdb = vdbio.build_openvdb

        def convert(grid, world=True, arrival=True, sdf=True):
            if sdf:
                self.converted[id(grid)] += 1
            return build_openvdb(grid, world, arrival, sdf)

        monkeypatch.setattr(vdbio, "build_openvdb", convert)


@pytest.fixture(scope="module")
def other_cad(tmp_path_factory):
    """The block's CAD moved up two voxels: another part, of the same volume on the lattice."""
    vertices, triangles = read_stl(CAD)
    path = tmp_path_factory.mktemp("cad") / "moved.stl"
    write_stl(path, vertices + np.array([0.0, 0.0, 2 * VOXEL]), triangles)
    return path


def test_simulate_compare_report_check_compute_each_stage_once(monkeypatch, tmp_path, other_cad):
    counts = Counts(monkeypatch)
    build = dmdvox.Build(GCODE, voxel=VOXEL)
    sim = build.deposit
    assert build.plan.model == "flow"
    cmp = build.compare(CAD)
    page = build.report(tmp_path / "page", cad=CAD)
    verdict = build.check(LIMITS, cad=CAD)
    assert counts.calls == {"sweep": 1, "land": 1, "beads": 1, "cad_level_set": 1}
    assert counts.converted and max(counts.converted.values()) == 1
    assert page.page.is_file() and verdict["passed"]
    assert build.deposit.grid is sim.grid and build.compare(CAD).cad is cmp.cad

    # another CAD part: compared on the same deposit, its own level set
    moved = build.compare(other_cad)
    assert counts.calls == {"sweep": 1, "land": 1, "beads": 1, "cad_level_set": 2}
    assert moved.cad is not cmp.cad and moved["cad_volume_mm3"] == pytest.approx(cmp["cad_volume_mm3"], rel=1e-6)


def test_the_build_gives_the_numbers_of_the_stages_run_alone():
    """Each result equals the stage run by itself with its own sweep (no reuse), timings aside."""
    build = dmdvox.Build(GCODE, voxel=VOXEL)
    plan = build.plan
    _same(_without_timings(build.deposit.to_json()),
          _without_timings(simulate(SimulateRequest(plan, voxel=VOXEL)).to_json()))
    _same(_without_timings(build.compare(CAD).to_json()),
          _without_timings(compare(CompareRequest(plan, CAD, voxel=VOXEL)).to_json()))
    _same(build.check(LIMITS, cad=CAD).to_json(),
          check(CheckRequest(plan, LIMITS, cad=str(CAD), voxel=VOXEL)).to_json())


def test_the_one_stage_functions_are_builds(monkeypatch):
    counts = Counts(monkeypatch)
    result = dmdvox.compare(GCODE, CAD, VOXEL)
    assert counts.calls == {"sweep": 1, "land": 1, "beads": 1, "cad_level_set": 1}
    assert result["voxel_mm"] == VOXEL


def test_settings_are_checked_once_in_the_callers_words():
    with pytest.raises(TypeError, match="already planned"):
        dmdvox.Build(dmdvox.plan(GCODE), model="fixed")
    with pytest.raises(dmdvox.errors.DmdvoxError, match="voxel"):
        dmdvox.Build(GCODE, voxel=5.0).deposit
    with pytest.raises(dmdvox.errors.DmdvoxError, match="until"):
        dmdvox.Build(GCODE, voxel=VOXEL, until=1.0).compare(CAD)
