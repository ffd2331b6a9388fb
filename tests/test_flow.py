"""Beads from the material the program delivers (issue 12), against closed forms.

Every expected value is computed here from the inputs (E advance and filament cross-section,
powder rate / density, feed, acceleration, junction deviation), not taken from the program.
"""

import math

import numpy as np
import pytest

from dmdvox.deposit.simulate import SimulateRequest, simulate
from dmdvox.errors import DmdvoxError
from dmdvox.process.flow import FlowSettings
from dmdvox.process.plan import ProcessSettings, plan_process
from dmdvox.process.planner import MotionSettings
from dmdvox.toolpath import read_gcode

RATE_G_MIN = 10.0
DENSITY = 8.0
Q = RATE_G_MIN / 60.0 / (DENSITY / 1000.0)  # mm^3/s delivered by the powder options below
POWDER = FlowSettings(powder_rate_g_min=RATE_G_MIN, density_g_cm3=DENSITY)


def plan(path, dialect="seed", profile="rect", width=2.5, accel=0.0, jd=0.05, flow=POWDER, model=None):
    tp = read_gcode(path, dialect=dialect)
    settings = ProcessSettings(profile=profile, width=width, model=model, flow=flow,
                               motion=MotionSettings(accel_mm_s2=accel, junction_deviation_mm=jd))
    return plan_process(tp, settings)


def slab_area(grid, x):
    """Cross-section area (mm^2) of the deposit in the voxel plane nearest ``x``."""
    i = int(round((x - grid.origin[0]) / grid.voxel))
    sdf = grid.dense_sdf()[i]
    return float(np.clip(0.5 - sdf / grid.voxel, 0.0, 1.0).sum() * grid.voxel**2)


# ---- the reader: material per row -----------------------------------------------------------

def test_retracts_and_their_primes_deliver_nothing(gcode_file):
    # relative E: 0.5 mm, a 1 mm retract, a 1 mm prime, 0.25 mm, then a prime longer than the retract
    text = ("M83\nG1 X0 Y0 Z0.3 F1200\nG1 X10 E0.5\nG1 E-1\nG1 X20 Y5 F6000\nG1 E1\nG1 X30 E0.25\n"
            "G1 E-0.5\nG1 X40 E0.75\n")
    tp = read_gcode(gcode_file(text), dialect="reprap")
    np.testing.assert_allclose(tp.e_material[tp.deposit], [0.5, 0.25, 0.25])
    assert tp.deposit.tolist() == [True, False, True, True]  # the travel move has no E


def test_slicer_width_and_header_diameter(gcode_file):
    text = (";WIDTH:0.45\nM83\nG1 X0 Y0 Z0.3 F1200\nG1 X10 E0.4\n;WIDTH:0.6\nG1 X20 E0.4\n"
            "; filament_diameter = 2.85\n")
    tp = read_gcode(gcode_file(text), dialect="reprap")
    np.testing.assert_allclose(tp.width[tp.deposit], [0.45, 0.6])
    assert tp.meta["filament_diameter_mm"] == 2.85


# ---- E-fed beads ----------------------------------------------------------------------------

@pytest.mark.parametrize("width", [0.4, 0.8, 1.6])
def test_straight_e_bead_holds_its_filament(gcode_file, width):
    # Every mm^3 the extruder pushes is in the grid, whatever the width; the width is ;WIDTH:.
    e = 2.0
    text = f"; filament_diameter = 1.75\nM83\nG1 X0 Y0 Z0.3 F1200\n;WIDTH:{width}\nG1 X20 Y0 E{e}\n"
    p = plan(gcode_file(text), dialect="reprap", width=None, profile="parabola", flow=FlowSettings())
    assert p.flow.source == "e" and p.model == "flow"
    result = simulate(SimulateRequest(p))  # the default voxel: w/20, but 4 over the height
    delivered = e * math.pi * 1.75**2 / 4
    assert result["deposited_volume_mm3"] == pytest.approx(delivered, rel=1e-9)
    assert result["deposit_volume_mm3"] == pytest.approx(delivered, rel=0.01)
    (_, y0, _), (_, y1, _) = result["bbox_mm"]
    assert y1 - y0 == pytest.approx(width, abs=2 * result["voxel_mm"])


def test_e_source_without_diameter_warns_and_strict_refuses(gcode_file):
    path = gcode_file("M83\nG1 X0 Y0 Z0.3 F1200\nG1 X10 E0.5\n")
    p = plan(path, dialect="reprap", flow=FlowSettings())
    assert p.flow.filament_diameter_mm == 1.75 and p.flow.diameter_source == "default"
    assert any("1.75 mm assumed" in w for w in p.warnings)
    with pytest.raises(DmdvoxError, match="--filament-diameter"):
        plan(path, dialect="reprap", flow=FlowSettings(strict=True))


# ---- rate sources ---------------------------------------------------------------------------

def test_powder_bead_at_constant_speed(gcode_file):
    # Mid-bead area Q / F; the whole bead Q x laser-on time.
    feed = 600.0
    p = plan(gcode_file(f"G90 G0 X0 Y0 Z0\nM65\nG1 X20 F{feed}\nM64\n"), width=2.5)
    result = simulate(SimulateRequest(p, voxel=0.05))
    on_time = 20.0 / (feed / 60.0)
    assert result["deposited_volume_mm3"] == pytest.approx(Q * on_time, rel=1e-9)
    assert result["deposit_volume_mm3"] == pytest.approx(Q * on_time, rel=0.005)
    assert slab_area(result.grid, 10.0) == pytest.approx(Q / (feed / 60.0), rel=0.01)


def test_wire_rate(gcode_file):
    flow = FlowSettings(wire_diameter_mm=1.0, wire_feed_mm_min=6700.0)
    p = plan(gcode_file("G90 G0 X0 Y0 Z0\nM65\nG1 X20 F600\nM64\n"), flow=flow, width=6.0)
    # REFERENCE.md section 5: d 1 mm, WFS 6.7 m/min, v 600 mm/min: 8.77 mm^2
    assert p.flow.rate_mm3_s / 10.0 == pytest.approx(math.pi / 4 * 6700 / 600, rel=1e-12)
    assert p.flow.rate_mm3_s / 10.0 == pytest.approx(8.77, abs=0.005)


def _corner_and_straight(gcode_file, accel, jd, feed, profile):
    corner = plan(gcode_file(f"G90 G0 X0 Y0 Z0\nM65\nG1 X30 F{feed}\nG1 Y30\nM64\n"), accel=accel, jd=jd,
                  profile=profile)
    straight = plan(gcode_file(f"G90 G0 X0 Y0 Z0\nM65\nG1 X30 F{feed}\nG1 X60\nM64\n"), accel=accel, jd=jd,
                    profile=profile)
    return corner, straight


@pytest.mark.parametrize("accel", [50.0, 20.0])
@pytest.mark.parametrize("profile", ["rect", "parabola"])
def test_corner_excess_material(gcode_file, profile, accel):
    # A 90-degree corner run at the junction speed v_j adds A0 (v - v_j)^2 / a against a straight
    # path of the same length (REFERENCE.md section 5), and the grid holds it. The ramp pieces
    # beside the corner are cut where the surface under them changes; a stretch shorter than a
    # cell holds no cell centre, and drawn where programmed (inside the first leg it overlaps)
    # its material vanished: -4 % before it went with its neighbours.
    jd, feed = 0.05, 1200.0
    v = feed / 60.0
    s = math.sin(math.pi / 4)
    v_j = math.sqrt(accel * jd * s / (1 - s))
    corner, straight = _corner_and_straight(gcode_file, accel, jd, feed, profile)
    assert corner.motion.v_exit[0] == pytest.approx(v_j, rel=1e-9)
    expected = Q / v * (v - v_j) ** 2 / accel
    a = simulate(SimulateRequest(corner, voxel=0.1))
    b = simulate(SimulateRequest(straight, voxel=0.1))
    assert a["deposited_volume_mm3"] - b["deposited_volume_mm3"] == pytest.approx(expected, rel=1e-6)
    assert a["deposit_volume_mm3"] - b["deposit_volume_mm3"] == pytest.approx(expected, rel=0.02)


def test_full_stop_and_dwell(gcode_file):
    # A stop in a straight line adds A0 v^2 / a; a dwell of t with the laser on adds Q t.
    accel, feed, dwell = 100.0, 1200.0, 0.5
    v = feed / 60.0
    stopped = plan(gcode_file(f"G90 G0 X0 Y0 Z0\nM65\nG1 X30 F{feed}\nG4 P{dwell * 1000:g}\nG1 X60\nM64\n"),
                   accel=accel)
    straight = plan(gcode_file(f"G90 G0 X0 Y0 Z0\nM65\nG1 X30 F{feed}\nG1 X60\nM64\n"), accel=accel)
    assert stopped.motion.v_exit[0] == 0.0
    expected = Q / v * v**2 / accel + Q * dwell
    a = simulate(SimulateRequest(stopped, voxel=0.1))
    b = simulate(SimulateRequest(straight, voxel=0.1))
    assert a["deposited_volume_mm3"] - b["deposited_volume_mm3"] == pytest.approx(expected, rel=1e-6)
    assert a["deposit_volume_mm3"] - b["deposit_volume_mm3"] == pytest.approx(expected, rel=0.02)


def test_slow_ends_collect_in_caps_without_spikes(gcode_file):
    # At a low acceleration the last stretch before a stop is slow: its material collects in the
    # cap; every piece stays within FLOOR_RATIO of the cruise area, and mass is conserved.
    from dmdvox.process.beads import CAP, FLOOR_RATIO

    p = plan(gcode_file("G90 G0 X0 Y0 Z0\nM65\nG1 X20 F1200\nM64\n"), accel=20.0)
    laid = p.lay(0.1)
    beads = laid.programmed
    pieces = beads.kind != CAP
    cruise_h = beads.height[pieces].min()
    assert beads.height[pieces].max() <= cruise_h / FLOOR_RATIO * (1 + 1e-9)
    assert beads.volume.sum() == pytest.approx(Q * p.toolpath.duration, rel=1e-9)


# ---- bad inputs -------------------------------------------------------------------------------

@pytest.mark.parametrize("settings, option", [
    (FlowSettings(powder_rate_g_min=-1.0, density_g_cm3=8.0), "--powder-rate"),
    (FlowSettings(powder_rate_g_min=10.0, density_g_cm3=0.0), "--density"),
    (FlowSettings(powder_rate_g_min=10.0), "--density"),
    (FlowSettings(filament_diameter_mm=175.0), "--filament-diameter"),
    (FlowSettings(wire_diameter_mm=1.0), "--wire-feed"),
    (FlowSettings(powder_rate_g_min=10.0, density_g_cm3=8.0, catchment=1.5), "--catchment"),
])
def test_bad_flow_inputs_name_the_option(settings, option):
    """The library names its parameter; the command line's table turns it into the option."""
    from dmdvox.cli import OPTION_OF_PARAMETER
    with pytest.raises(DmdvoxError) as caught:
        settings.validate()
    assert OPTION_OF_PARAMETER[caught.value.parameter] == option
    assert caught.value.parameter in str(caught.value)


def test_e_and_powder_together_are_refused(gcode_file):
    path = gcode_file("M83\nG1 X0 Y0 Z0.3 F1200\nG1 X10 E0.5\n")
    with pytest.raises(DmdvoxError, match="twice"):
        plan(path, dialect="reprap")
