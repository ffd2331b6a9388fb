"""`dmdvox check` with the thermal limits and a [thermal] table."""

import json

from dmdvox.cli import main
from dmdvox.limits import LIMIT_FAILED

from .test_thermal_build import WALL


def test_thermal_limits_fail_where_the_part_is_too_hot(tmp_path, capsys):
    gcode = tmp_path / "wall.gcode"
    gcode.write_text(WALL)
    cell = tmp_path / "cell.toml"
    cell.write_text('[limits]\nmax_peak_temperature_C = 1000.0\nmax_melt_pool_width_mm = 100.0\n'
                    'max_interlayer_temperature_C = 5000.0\n'
                    '[process]\ndialect = "seed"\nvoxel = 0.3125\n'
                    '[thermal]\nmaterial = "316L"\nlaser_power = 1000.0\nthermal_voxel = 0.625\n')
    code = main(["check", str(gcode), "--limits", str(cell), "--json"])
    result = json.loads(capsys.readouterr().out)
    assert code == LIMIT_FAILED, result
    verdicts = {item["name"]: item for item in result["limits"]}
    peak = verdicts["max_peak_temperature_C"]
    # the beam melts the wall: above the liquidus, in both layers
    assert peak["verdict"] == "fail" and peak["value"] > 1450.0 and peak["layers"] == [0, 1]
    assert verdicts["max_melt_pool_width_mm"]["verdict"] == "pass", verdicts
    assert verdicts["max_interlayer_temperature_C"]["verdict"] == "pass"
    assert "thermal" in result["runs"]


def test_thermal_limit_without_the_table_is_refused(tmp_path, capsys):
    gcode = tmp_path / "wall.gcode"
    gcode.write_text(WALL)
    cell = tmp_path / "cell.toml"
    cell.write_text('[limits]\nmax_peak_temperature_C = 1000.0\n[process]\ndialect = "seed"\n')
    assert main(["check", str(gcode), "--limits", str(cell), "--json"]) == 2
    assert "[thermal]" in json.loads(capsys.readouterr().out)["error"]
