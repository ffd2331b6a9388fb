"""Overlap study: closed forms for parabolic beads, the table on local processes vs dask."""

from __future__ import annotations

import argparse
import csv

import pytest

from dmdvox.errors import DmdvoxError
from dmdvox.cli import _add_study_overlap as add_overlap_options
from dmdvox.cli import cmd_study_overlap as run_study_overlap
from dmdvox.study.ranges import parse_range
from dmdvox.tasks import run_tasks
from dmdvox.study.overlap import ROW_KEYS, OverlapCase, beads_per_side, overlap_case

from .conftest import DEV_EXTRAS, free_port, require_module

W, H, VOXEL = 2.0, 1.0, 0.02
AREA = 2.0 / 3.0 * W * H  # parabola
TOL = 0.02


def _parabola(spacing: float, layer_step: float = H, layers: int = 1, voxel: float = VOXEL) -> dict:
    return overlap_case(OverlapCase("parabola", W, H, 4.0, spacing, layer_step, layers, voxel))


@pytest.mark.parametrize("d", [0.5, 1.0, 1.3, 1.7, 2.0])
def test_parabola_one_layer_overlapping(d):
    row = _parabola(d)
    assert row["mean_height_mm"] == pytest.approx(H * (1 - d * d / (3 * W * W)), abs=TOL)
    assert row["waviness_mm"] == pytest.approx(H * d * d / (W * W), abs=TOL)
    assert row["porosity_percent"] == pytest.approx(0.0, abs=1e-9)  # one layer: nothing below its top


@pytest.mark.parametrize("d", [2.3, 3.0])
def test_parabola_one_layer_apart(d):
    row = _parabola(d)
    assert row["mean_height_mm"] == pytest.approx(AREA / d, abs=TOL)
    # the valley reaches the substrate: peak-to-valley is the whole bead height
    assert row["waviness_mm"] == pytest.approx(H, abs=TOL)


def test_ratios_and_keys():
    row = _parabola(1.5, voxel=0.05)
    assert tuple(row) == ROW_KEYS
    assert all(type(v) is float for v in row.values())
    assert row["spacing_mm"] == 1.5 and row["layer_step_mm"] == H
    assert row["overlap_ratio"] == pytest.approx(0.25, abs=1e-12)
    assert row["flat_top_spacing_mm"] == pytest.approx(4.0 / 3.0, abs=1e-12)  # A / h = 2/3 w
    rect = overlap_case(OverlapCase("rect", 2.5, 0.8, 4.0, 2.0, 0.8, 1, 0.05))
    assert rect["flat_top_spacing_mm"] == pytest.approx(2.5, abs=1e-12)
    assert rect["overlap_ratio"] == pytest.approx(0.2, abs=1e-12)


def test_stacked_layers_touching_leave_the_lens_voids():
    # Parabolas at d = w, layer step = h: each layer touches the next only along lines, so below
    # the top layer each period holds d * h - A of void per layer interface.
    row = _parabola(W, layers=3, voxel=0.05)
    assert row["mean_height_mm"] == pytest.approx(2 * H + AREA / W, abs=TOL)
    void = 2 * (W * H - AREA)
    assert row["porosity_percent"] == pytest.approx(100 * void / (row["mean_height_mm"] * W), abs=1.0)
    # rectangles tile the plane: a dense block, flat on top
    rect = overlap_case(OverlapCase("rect", W, H, 4.0, W, H, 3, 0.05))
    assert rect["porosity_percent"] == pytest.approx(0.0, abs=0.01)
    assert rect["waviness_mm"] == pytest.approx(0.0, abs=0.01)
    assert rect["mean_height_mm"] == pytest.approx(3 * H, abs=0.01)


def test_patch_is_wide_enough():
    assert beads_per_side(2.0, 1.0) == 3  # never fewer than 3 per side (7 beads)
    assert beads_per_side(2.0, 0.2) == 6  # every bead that reaches the central period


def test_parse_range():
    assert parse_range("0.8:1.2:0.1", "--spacing") == [0.8, 0.9, 1.0, 1.1, 1.2]
    assert parse_range("1.5", "--spacing") == [1.5]
    for bad in ("1:0:0.1", "0:1:0", "a:b:c", "1:2"):
        with pytest.raises(DmdvoxError):
            parse_range(bad, "--spacing")


def _args(extra: str):
    p = argparse.ArgumentParser()
    add_overlap_options(p)
    return p.parse_args(("--profile parabola --width 2 --height 1 --layers 2 --voxel 0.05 " + extra).split())


def test_cli_writes_csv_and_plot(tmp_path):
    out_csv, out_png = tmp_path / "o.csv", tmp_path / "o.png"
    result = run_study_overlap(_args(f"--spacing 1.0:2.0:0.5 --layer-step 0.8:1.0:0.2 --json "
                                     f"--csv {out_csv} --plot {out_png}"))
    rows = result["rows"]
    assert [(r["spacing_mm"], r["layer_step_mm"]) for r in rows] == [
        (1.0, 0.8), (1.0, 1.0), (1.5, 0.8), (1.5, 1.0), (2.0, 0.8), (2.0, 1.0)]
    with out_csv.open() as fh:
        table = list(csv.DictReader(fh))
    assert tuple(table[0]) == ROW_KEYS
    assert [float(t["waviness_mm"]) for t in table] == [r["waviness_mm"] for r in rows]
    assert out_png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    # the same cases in-process: local processes change nothing
    assert rows == [overlap_case(c) for c in _cases(rows)]


def _cases(rows):
    return [OverlapCase("parabola", 2.0, 1.0, 4.0, r["spacing_mm"], r["layer_step_mm"], 2, 0.05) for r in rows]


def test_dask_cluster_gives_the_identical_table(dask_cluster):
    cases = _cases([{"spacing_mm": d, "layer_step_mm": s} for d in (1.0, 1.5, 2.5) for s in (0.8, 1.0)])
    local = run_tasks(overlap_case, cases)
    remote = run_tasks(overlap_case, cases, scheduler=dask_cluster)
    assert remote == local  # bit for bit, in parameter order
    result = run_study_overlap(_args(f"--spacing 1.0:2.0:0.5 --scheduler {dask_cluster} --json"))
    assert result["rows"] == run_study_overlap(_args("--spacing 1.0:2.0:0.5 --json"))["rows"]


def test_unreachable_scheduler_is_a_user_error(monkeypatch):
    require_module("distributed", "dask.distributed", DEV_EXTRAS)
    import dmdvox.tasks as execute

    monkeypatch.setattr(execute, "DASK_CONNECT_TIMEOUT_S", 1.0)  # fail fast: nothing listens there
    with pytest.raises(DmdvoxError, match="cannot reach"):
        run_tasks(overlap_case, _cases([{"spacing_mm": 1.0, "layer_step_mm": 1.0}]),
                  scheduler=f"tcp://127.0.0.1:{free_port()}")
