"""`dmdvox thermal`: its outputs and its refusals (exit 2 naming the option)."""

import json

import numpy as np
import pytest

from dmdvox.cli import main

from .test_thermal_build import WALL


@pytest.fixture(scope="module")
def wall_file(tmp_path_factory):
    path = tmp_path_factory.mktemp("thermal") / "wall.gcode"
    path.write_text(WALL)
    return path


def _run(capsys, *argv):
    code = main(["thermal", *map(str, argv), "--json"])
    return code, json.loads(capsys.readouterr().out)


def test_thermal_writes_fields_tables_and_exports(wall_file, tmp_path, capsys):
    out = tmp_path / "out"
    code, result = _run(capsys, wall_file, "--dialect", "seed", "--material", "316L", "--laser-power", "1000",
                        "--voxel", "0.3125", "--thermal-voxel", "0.625", "--probe", "5,0,0.4", "--interpass", "400",
                        "--out", out)
    assert code == 0, result
    assert result["thermal_voxel_mm"] == pytest.approx(0.625)
    # each step takes the beam where it is at the step's middle: eta P within a step's energy, and
    # the heat of the last bead's end cap, born as the beam stops, that no later beam pays
    unpaid = result["birth_heat_unpaid_J"]
    assert result["absorbed_J"] == pytest.approx(0.4 * result["beam_energy_J"] + unpaid, rel=1e-3)
    # at most the end cap's cells: born at the liquidus, nine 0.625 mm cells of 316L from 20 C hold
    # 9 * 0.244 mm^3 * 7.95e-6 kg/mm^3 * (~600 J/(kg K) * 1430 K + 2.7e5 J/kg) = 22 J
    assert 0.0 <= unpaid < 22.0
    assert result["energy_balance_max_percent"] < 0.5
    assert result["max_peak_temperature_C"] > 1450.0  # the beam melts what it lays
    assert len(result["layers"]) == 2 and result["layers"][0]["interlayer_C"] is not None
    # Rosenthal's width of a fast source, w = sqrt(8 / (pi e)) sqrt(eta P / (rho c U dT)) (REFERENCE.md
    # 8), 2.3 mm for 400 W absorbed at 10 mm/s in 316L (rho c ~ 4.8 J/(cm^3 K)); the lattice counts
    # whole 0.625 mm cells and the Gaussian spreads the beam
    w = np.sqrt(8 / (np.pi * np.e)) * np.sqrt(400.0 / (7950e-9 * 600.0 * 10.0 * 1430.0))
    assert 0.5 * w < result["max_melt_pool_width_mm"] < 2.0 * w
    names = {p.rsplit("/", 1)[-1] for p in result["outputs"]}
    assert {"wall_thermal.vdb", "wall_thermal.vti", "wall_layers.csv", "wall_melt_pool.csv", "wall_probes.csv",
            "wall_energy.csv", "wall_path.txt", "wall_path.crs"} <= names
    import pyvista

    image = pyvista.read(out / "wall_thermal.vti")
    for name in ("peak_temperature_C", "cooling_rate_C_s", "gradient_C_mm", "solidification_rate_mm_s"):
        assert name in image.point_data
    peak = np.asarray(image.point_data["peak_temperature_C"])
    assert np.nanmax(peak) == pytest.approx(result["max_peak_temperature_C"], rel=1e-6)
    # R = cooling rate / G where both exist
    rate, grad, r = (np.asarray(image.point_data[n]) for n in ("cooling_rate_C_s", "gradient_C_mm",
                                                                  "solidification_rate_mm_s"))
    ok = np.isfinite(r)
    assert ok.any() and np.allclose(r[ok], rate[ok] / grad[ok], rtol=1e-5)
    probes = (out / "wall_probes.csv").read_text().splitlines()
    assert probes[0].startswith("time_s,T_C_at_5_0_0.4") and len(probes) > 10
    crs = np.loadtxt(out / "wall_path.crs")
    assert crs.shape[1] == 5 and np.all(np.diff(crs[:, 0]) >= 0)
    # the 3DThesis file: its lines at power run the planned speeds (10 mm/s, less where the
    # planner accelerates)
    path = np.loadtxt(out / "wall_path.txt", skiprows=1)
    lit = (path[:, 0] == 1) & (path[:, 4] > 0)
    assert np.median(path[lit, 5]) == pytest.approx(10.0) and np.all(path[lit, 5] <= 10.0 + 1e-6)
    assert path[lit, 5].min() < 9.0


def test_thermal_feedback_lays_the_hot_layer_wider(wall_file, capsys):
    code, result = _run(capsys, wall_file, "--dialect", "seed", "--material", "316L", "--laser-power", "1000",
                        "--voxel", "0.3125", "--thermal-voxel", "0.625", "--thermal-feedback", "3d")
    assert code == 0, result
    fb = result["feedback"]
    # the second layer lies on the first at its interlayer temperature: f = sqrt(1430 / (1450 - T_il))
    t_il = result["layers"][0]["interlayer_C"]
    assert fb["max_width_factor"] == pytest.approx(np.sqrt((1450.0 - 20.0) / (1450.0 - t_il)), rel=1e-9)
    # the cross-sections keep their area (the fixed bead's round ends grow with the width)
    assert fb["hot_volume_mm3"] == pytest.approx(fb["cold_volume_mm3"], rel=0.05)


@pytest.mark.parametrize("options, option", [
    (["--material", "steel"], "--material"),
    (["--material", "316L", "--laser-power", "-5"], "--laser-power"),
    (["--material", "316L", "--laser-power", "500", "--absorptivity", "0"], "--absorptivity"),
    (["--material", "316L", "--laser-power", "500", "--absorptivity", "1.5"], "--absorptivity"),
    (["--material", "316L", "--laser-power", "500", "--thermal-voxel", "3"], "--thermal-voxel"),
    (["--material", "316L", "--laser-power", "500", "--plate-size", "10,10"], "--plate-size"),
    (["--material", "316L", "--laser-power", "500", "--emissivity", "2"], "--emissivity"),
])
def test_bad_inputs_exit_2_naming_the_option(wall_file, capsys, options, option):
    code, result = _run(capsys, wall_file, "--dialect", "seed", *options)
    assert code == 2
    assert result["error"].startswith(option)


def test_non_monotone_material_table_exits_2(wall_file, tmp_path, capsys):
    bad = tmp_path / "bad.toml"
    bad.write_text("t = [20.0, 10.0]\nk = [10.0, 20.0]\ncp = [500.0, 600.0]\ndensity = 8000.0\n"
                   "solidus = 1300.0\nliquidus = 1400.0\n")
    code, result = _run(capsys, wall_file, "--dialect", "seed", "--material", bad, "--laser-power", "500")
    assert code == 2 and "field 't'" in result["error"]


@pytest.mark.parametrize("options, option", [
    (["--source", "goldak", "--goldak", "1,2,1"], "--goldak"),
    (["--source", "goldak", "--goldak", "1,2,-1,1"], "--goldak"),
])
def test_goldak_refusals_name_the_option(wall_file, capsys, options, option):
    code, result = _run(capsys, wall_file, "--dialect", "seed", "--material", "316L", "--laser-power", "1000",
                        *options)
    assert code == 2, result
    assert result["error"].startswith(option), result["error"]


def test_goldak_source_runs_on_the_wall(wall_file, capsys):
    """The double ellipsoid on the wall: the balance closes, the beam's energy all absorbed
    (within a step's and the last end cap's), the wall melts."""
    code, result = _run(capsys, wall_file, "--dialect", "seed", "--material", "316L", "--laser-power", "1000",
                        "--voxel", "0.3125", "--thermal-voxel", "0.625", "--source", "goldak")
    assert code == 0, result
    assert result["absorbed_J"] == pytest.approx(0.4 * result["beam_energy_J"] + result["birth_heat_unpaid_J"],
                                                 rel=1e-3)
    assert result["energy_balance_max_percent"] < 0.5
    assert result["max_peak_temperature_C"] > 1450.0
