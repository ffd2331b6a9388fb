"""The simulate summary's accounting: the mass balance against all the material delivered,
the lost share beside it, and a loss above 1 % a warning naming its lines and why."""

import pytest

from dmdvox.deposit.simulate import SimulateRequest, simulate
from dmdvox.process.landing import LandingSettings

from .test_landing import FEED, Q, flow_plan

# two 20 mm rows of powder at constant feed; the second 5 mm above the first one's plate level
TWO_ROWS = "G90 G0 X0 Y0 Z0\nM65\nG1 X20 F600\nM64\nG0 X0 Y10 Z{z}\nM65\nG1 X20 F600\nM64\n"


def test_lost_row_shows_in_the_mass_balance_and_is_named(gcode_file):
    # The second row lands more than --max-drop (2 mm) below its programmed height: lost. Each
    # row delivers Q L / v; half of what is delivered never reaches the part.
    row = Q * 20 / (FEED / 60)
    p = flow_plan(gcode_file(TWO_ROWS.format(z=5)), profile="rect", landing=LandingSettings(max_drop_mm=2.0))
    result = simulate(SimulateRequest(p, voxel=0.1))
    assert result["deposited_volume_mm3"] == pytest.approx(2 * row, rel=1e-9)
    assert result["lost_volume_mm3"] == pytest.approx(row, rel=1e-9)
    assert result["lost_percent"] == pytest.approx(50.0, rel=1e-9)
    # the grid holds the first row only: against all the delivered material, -50 %
    assert result["mass_balance_percent"] == pytest.approx(-50.0, abs=1.0)
    assert result["mass_balance_percent"] == pytest.approx(
        100 * (result["deposit_volume_mm3"] - 2 * row) / (2 * row), rel=1e-12)
    warning = [w for w in result["warnings"] if "never reached the part" in w]
    assert len(warning) == 1
    assert "50.00 %" in warning[0] and "on 1 lines: 7" in warning[0]


def test_no_loss_no_warning(gcode_file):
    # the second row on the plate beside the first: everything lands, the balance is the grid's
    p = flow_plan(gcode_file(TWO_ROWS.format(z=0)), profile="rect", landing=LandingSettings(max_drop_mm=2.0))
    result = simulate(SimulateRequest(p, voxel=0.1))
    assert result["lost_percent"] == 0.0
    assert result["mass_balance_percent"] == pytest.approx(0.0, abs=1.0)
    assert not [w for w in result["warnings"] if "never reached the part" in w]
