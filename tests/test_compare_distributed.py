"""`compare --scheduler`: the deposit's and the comparison's slabs on a loopback dask cluster
(a scheduler and two workers started by the test) give the local run's JSON."""

import contextlib
import io
import json

from dmdvox import cli
from dmdvox.comparison import slabs

from .conftest import DATA


def compare_json(*extra) -> dict:
    out = io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(io.StringIO()):
        # the CAD moved by more than the band: void and overbuild measured beyond the bands too
        code = cli.main(["compare", str(DATA / "demo_block.gcode"), str(DATA / "demo_block.stl"), "--cad-offset",
                         "0.7,0,0", "--json", *extra])
    assert code == 0
    result = json.loads(out.getvalue())
    del result["timings_s"]
    return result


def test_distributed_compare_equals_local(dask_cluster, monkeypatch):
    # slabs of a few hundred blocks: the demo block is cut into several, each with its halo
    monkeypatch.setattr(slabs, "SLAB_BLOCKS", 300)
    local = compare_json()
    cut = []
    ranges = slabs.slab_ranges
    monkeypatch.setattr(slabs, "slab_ranges", lambda *grids: cut.append(ranges(*grids)) or cut[-1])
    remote = compare_json("--scheduler", dask_cluster)
    assert len(cut[0]) >= 3
    assert remote == local
    band = 3 * local["voxel_mm"]
    assert local["max_underfill_mm"] > band and local["max_overbuild_mm"] > band and local["deviation_mm"]["p95"] > 0


def report_json(out, *extra) -> dict:
    stdout = io.StringIO()
    with contextlib.redirect_stdout(stdout), contextlib.redirect_stderr(io.StringIO()):
        code = cli.main(["report", str(DATA / "demo_block.gcode"), "--cad", str(DATA / "demo_block.stl"), "--out",
                         str(out), "--json", *extra])
    assert code == 0
    result = json.loads(stdout.getvalue())
    return {key: value for key, value in result.items() if key not in ("report_html", "outputs")}


def test_distributed_report_equals_local(dask_cluster, monkeypatch, tmp_path):
    monkeypatch.setattr(slabs, "SLAB_BLOCKS", 300)
    local = report_json(tmp_path / "local")
    remote = report_json(tmp_path / "remote", "--scheduler", dask_cluster)
    assert remote == local
    assert local["compare"]["void_volume_mm3"] > 0
