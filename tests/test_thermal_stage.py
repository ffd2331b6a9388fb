"""`--thermal` on `simulate` and `report`, and the [thermal] table through `dmdvox.api.check`:
the heat stage on the deposit's own grid gives what `dmdvox thermal` gives on the same program."""

import json

import numpy as np
import pytest

import dmdvox.api
from dmdvox.cli import main

from .test_thermal_build import WALL

HEAT = ["--material", "316L", "--laser-power", "1000", "--thermal-voxel", "0.625"]
SAME = ("thermal_voxel_mm", "time_step_s", "cells", "part_cells", "plate_cells", "steps", "absorbed_J", "stored_J",
        "lost_J", "max_peak_temperature_C", "max_interlayer_temperature_C", "max_melt_pool_width_mm", "layers",
        "remelted_cells")


@pytest.fixture(scope="module")
def wall_file(tmp_path_factory):
    path = tmp_path_factory.mktemp("stage") / "wall.gcode"
    path.write_text(WALL)
    return path


def _run(capsys, *argv):
    code = main([*map(str, argv), "--json"])
    return code, json.loads(capsys.readouterr().out)


@pytest.fixture(scope="module")
def thermal_alone(wall_file):
    """`dmdvox thermal` on the wall (the reference the stage must equal)."""
    import contextlib
    import io

    out = io.StringIO()
    with contextlib.redirect_stdout(out):
        code = main(["thermal", str(wall_file), "--dialect", "seed", "--voxel", "0.3125", *HEAT, "--json"])
    assert code == 0
    return json.loads(out.getvalue())


def test_simulate_thermal_equals_the_thermal_command(wall_file, thermal_alone, tmp_path, capsys):
    out = tmp_path / "sim"
    code, result = _run(capsys, "simulate", wall_file, "--dialect", "seed", "--voxel", "0.3125", "--thermal", *HEAT,
                        "--out", out)
    assert code == 0, result
    heat = result["thermal"]
    for key in SAME:
        assert heat[key] == thermal_alone[key], key
    # the deposit's own keys stay, and the heat's files are among the command's outputs
    assert result["deposit_volume_mm3"] > 0
    names = {p.rsplit("/", 1)[-1] for p in heat["outputs"]}
    assert {"wall_thermal.vdb", "wall_thermal.vti", "wall_layers.csv", "wall_melt_pool.csv"} <= names
    assert set(heat["outputs"]) <= set(result["outputs"])
    assert all((out / name).exists() for name in names)
    # absorbed = stored + lost (the thermal tests' balance)
    assert heat["absorbed_J"] == pytest.approx(heat["stored_J"] + heat["lost_J"], rel=5e-3)


@pytest.mark.parametrize("options, option", [
    (["--material", "316L"], "--material"),  # a heat option without --thermal
    (["--thermal"], "--material"),
    (["--thermal", *HEAT, "--until", "1"], "--thermal"),
    (["--thermal", "--material", "316L", "--laser-power", "-5"], "--laser-power"),
])
def test_simulate_thermal_refusals_exit_2_naming_the_option(wall_file, capsys, options, option):
    code, result = _run(capsys, "simulate", wall_file, "--dialect", "seed", *options)
    assert code == 2, result
    assert result["error"].startswith(option), result["error"]


def test_api_check_passes_the_thermal_table_on(wall_file, thermal_alone, tmp_path):
    cell = tmp_path / "cell.toml"
    cell.write_text('[limits]\nmax_peak_temperature_C = 1000.0\nmax_interlayer_temperature_C = 5000.0\n'
                    '[process]\nvoxel = 0.3125\n'
                    '[thermal]\nmaterial = "316L"\nlaser_power = 1000.0\nthermal_voxel = 0.625\n')
    plan = dmdvox.api.plan(dmdvox.api.read_gcode(str(wall_file), dialect="seed"))
    result = dmdvox.api.check(plan, str(cell))
    summary = result.to_json()
    assert "thermal" in summary["runs"] and not result.passed
    values = {item["name"]: item["value"] for item in summary["limits"]}
    assert values["max_peak_temperature_C"] == thermal_alone["max_peak_temperature_C"]
    assert values["max_interlayer_temperature_C"] == thermal_alone["max_interlayer_temperature_C"]


@pytest.fixture(scope="module")
def heat_report(wall_file, tmp_path_factory):
    import contextlib
    import io

    out_dir = tmp_path_factory.mktemp("heat_report")
    out = io.StringIO()
    with contextlib.redirect_stdout(out):
        code = main(["report", str(wall_file), "--dialect", "seed", "--voxel", "0.3125", "--thermal", *HEAT,
                     "--interpass", "400", "--out", str(out_dir), "--json"])
    assert code == 0, out.getvalue()
    summary = json.loads(out.getvalue())
    return summary, (out_dir / "wall_report.html").read_text()


def test_report_thermal_equals_the_thermal_command(heat_report, thermal_alone):
    summary, _ = heat_report
    for key in SAME:
        if key != "layers":  # --interpass adds the time to cool below it
            assert summary["thermal"][key] == thermal_alone[key], key
    assert [r["interlayer_C"] for r in summary["thermal"]["layers"]] == \
        [r["interlayer_C"] for r in thermal_alone["layers"]]
    names = {p.rsplit("/", 1)[-1] for p in summary["outputs"]}
    assert {"wall_thermal.vdb", "wall_heat_layers.png", "wall_melt_pool.png", "wall_peak_temperature.png"} <= names


def test_report_heat_section_shows_the_json(heat_report, wall_file):
    summary, page = heat_report
    heat = summary["heat"]
    assert '<section id="heat"><h2>Heat</h2>' in page
    assert f"{heat['max_peak_temperature_C']:,.0f} °C" in page
    assert f"{heat['max_melt_pool_width_mm']:.3f} mm" in page
    assert f"{heat['max_time_above_solidus_s']:.3f} s" in page
    assert f"{heat['boiled_J']:,.1f} J boiled off at the boiling point" in page
    # two tracks: layer 0 on lines 6-7 (G1 Z0, G1 X10), layer 1 on lines 11-13 (G1 Z0.75 ... G1 X10): the
    # lines of the program (WALL) that lay material
    text = wall_file.read_text().splitlines()
    for row in heat["layers"]:
        first, last = row["lines"]
        assert text[first - 1].startswith("G1") and text[last - 1].startswith("G1")
        assert f"<td>{row['layer']}</td><td>{first} … {last}</td>" in page
    assert [r["layer"] for r in heat["layers"]] == [0, 1]
    # the hottest layer by interlayer temperature: the one laid on the hot first track (only layer 0
    # has a next layer, so it leads), and the per-layer table shows each interlayer value
    assert heat["hottest_by"] == "interlayer_C" and heat["hottest_layers"][0]["layer"] == 0
    assert f"{heat['layers'][0]['interlayer_C']:,.0f} °C" in page
    # the time above the solidus is no longer than the run, and positive (the beam melts the wall)
    assert 0 < heat["max_time_above_solidus_s"] <= heat["duration_s"]
    assert heat["max_peak_temperature_C"] >= heat["liquidus_C"]


def test_every_surface_vertex_takes_its_nearest_part_cell(wall_file):
    """The report's heat colourings: every surface vertex of the wall gets the value of its
    nearest part cell (brute-force nearest, ties allowed), wherever it lies from the cells."""
    from dmdvox.deposit.simulate import SimulateRequest, simulate
    from dmdvox.grid.surface import surface_mesh
    from dmdvox.thermal.outputs import at_points, cell_fields, heat_deposit

    plan = dmdvox.api.plan(dmdvox.api.read_gcode(str(wall_file), dialect="seed"))
    sim = simulate(SimulateRequest(plan, voxel=0.3125))
    result, _ = heat_deposit(plan, sim.grid, sim["plate_z_mm"],
                             {"material": "316L", "laser_power": 1000.0, "thermal_voxel": 0.625})
    vertices = np.asarray(surface_mesh(sim.grid)[0], np.float64)
    peak = cell_fields(result)["peak_temperature_C"]
    got = at_points(result, peak, vertices)
    lat = result.lattice
    part = np.flatnonzero(np.isfinite(lat.birth) & (np.arange(len(lat)) < result.state.n_born))
    d = np.linalg.norm(vertices[:, None, :] - lat.centres[part][None], axis=2)
    nearest = np.isclose(d, d.min(axis=1, keepdims=True), rtol=0, atol=1e-6)
    assert np.all(np.isfinite(got))
    assert all(np.any(peak[part[row]] == value) for row, value in zip(nearest, got))
    # the plate is not the part: the plate's corner takes a part cell's value
    assert at_points(result, peak, lat.origin[None])[0] in peak[part]


def test_heat_layers_name_their_first_line(heat_report, wall_file):
    """Each heat layer carries the G-code line its first deposit row comes from: the first G1
    after each M65 (the seed dialect's material on), lines 8 and 14 of WALL; the CSV and the page
    say so."""
    summary, page = heat_report
    text = wall_file.read_text().splitlines()
    on = [i for i, line in enumerate(text) if line.startswith("M65")]
    expect = [next(j for j in range(i, len(text)) if text[j].startswith("G1")) + 1 for i in on]
    assert expect == [8, 14]
    assert [r["first_line"] for r in summary["thermal"]["layers"]] == expect
    csv = next(p for p in summary["outputs"] if p.endswith("wall_layers.csv"))
    with open(csv) as f:
        rows = f.read().splitlines()
    assert rows[0].split(",")[:2] == ["layer", "first_line"]
    assert [int(r.split(",")[1]) for r in rows[1:]] == expect
    assert [r["lines"][0] for r in summary["heat"]["layers"]] == expect
    # the 3-D view offers the peak temperature and the cooling rate as colourings
    assert '"peak_temperature_C"' in page and '"cooling_rate_C_s"' in page
