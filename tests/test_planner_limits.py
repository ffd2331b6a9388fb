"""The program's own machine limits, read as the firmware reads them: M201/M203/M204/M205,
Klipper's SET_VELOCITY_LIMIT, PrusaSlicer's machine settings; per-axis limits, classic jerk,
stops by dialect, the command line over the program. Expected values are closed forms."""

import math

import pytest

from dmdvox.process.planner import MotionSettings, plan_motion
from dmdvox.toolpath import read_gcode


def reprap(gcode_file, text: str):
    """A Marlin program: its limit codes, then G28 (the position known at 0), then the moves."""
    codes = "".join(line + "\n" for line in text.splitlines() if not line.startswith(("G", ";")))
    moves = "".join(line + "\n" for line in text.splitlines() if line.startswith(("G", ";")))
    return read_gcode(gcode_file("G90\nM83\n" + codes + "G28\n" + moves), dialect="reprap")


def rest_to_rest(length: float, feed: float, a: float) -> float:
    return length / feed + feed / a if length >= feed * feed / a else 2 * math.sqrt(length / a)


def test_limit_codes_read_in_program_order(gcode_file):
    # M201/M203/M205 X Y Z E, M204 P R T and S, M205 J, each in force from its line on
    from dmdvox.toolpath import motion_codes as M

    tp = read_gcode(gcode_file("G90\nM83\nM201 X9000 Y8000 Z400 E5000\nM203 X500 Y500 Z12 E120\n"
                               "M204 P1000 R800 T2000\nM205 X10 Y9 Z0.4 E4.5\nM205 J0.02\nG28\nG1 X0 Y0 Z0.2 F600\n"
                               "M204 S700\nG1 X30 E1 F1200\n"), dialect="reprap")
    pm = tp.meta["program_motion"]
    first, last = pm.values[pm.values_at([8])[0]], pm.values[-1]
    assert list(first[M.AMAX_X:M.AMAX_X + 4]) == [9000, 8000, 400, 5000]
    assert list(first[M.VMAX_X:M.VMAX_X + 4]) == [500, 500, 12, 120]
    assert list(first[[M.ACCEL_PRINT, M.ACCEL_RETRACT, M.ACCEL_TRAVEL]]) == [1000, 800, 2000]
    assert list(first[M.JERK_X:M.JERK_X + 4]) == [10, 9, 0.4, 4.5] and first[M.JD] == 0.02
    assert list(last[[M.ACCEL_PRINT, M.ACCEL_RETRACT, M.ACCEL_TRAVEL]]) == [700, 800, 700]  # S: print and travel
    assert pm.sources["max_feed_z"] == "M203 line 4" and pm.sources["junction_deviation"] == "M205 line 7"


def test_m204_per_row_and_axis_limits(gcode_file):
    # M204 P sets the print acceleration from its line on; a Z cap of 12 mm/s and 400 mm/s^2
    # (here from the command line, the same limits M203/M201 give): a pure Z move at F6000 runs
    # at 12 mm/s with 400 mm/s^2, from rest to rest.
    tp = reprap(gcode_file, "M204 P1000 T2000\nG1 X0 Y0 Z0.2 F600\nG1 X30 E1 F1200\nG1 Z5 F6000\n")
    limits = MotionSettings(junction_deviation_mm=0.0, max_feed_mm_s=(500, 500, 12, 120),
                            max_axis_accel_mm_s2=(9000, 9000, 400, 5000))
    plan = plan_motion(tp, limits)
    assert plan.accel == 1000.0
    assert plan.row_accel[1] == 1000.0 and plan.row_accel[2] == 400.0
    assert plan.v_cruise[2] == pytest.approx(12.0)
    assert plan.t_end[1] - plan.t_start[1] == pytest.approx(rest_to_rest(30.0, 20.0, 1000.0), rel=1e-9)
    assert plan.t_end[2] - plan.t_start[2] == pytest.approx(rest_to_rest(4.8, 12.0, 400.0), rel=1e-9)
    assert plan.sources["accel_print"] == "M204 line 3" and plan.sources["max_feed_z"] == "--max-feed"
    # the command line overrides the program
    cli = plan_motion(tp, MotionSettings(accel_mm_s2=3000.0, junction_deviation_mm=0.0))
    assert cli.row_accel[1] == 3000.0 and cli.sources["accel_print"] == "--accel"
    ignored = plan_motion(tp, MotionSettings(program_limits=False, junction_deviation_mm=0.0))
    assert ignored.accel == 500.0 and ignored.v_cruise[2] == pytest.approx(math.sqrt(500 * 4.8))


def test_prusaslicer_machine_settings_when_no_codes(gcode_file):
    tp = reprap(gcode_file, "G1 X0 Y0 Z0.2 F600\nG1 X30 E1 F1200\nG1 Z5 F6000\n"
                            "; machine_max_acceleration_extruding = 800,1250\n; machine_max_feedrate_z = 12,12\n"
                            "; machine_max_acceleration_z = 500,200\n")
    plan = plan_motion(tp, MotionSettings(junction_deviation_mm=0.0))
    assert plan.accel == 800.0  # the first, "normal mode" value
    assert plan.v_cruise[2] == pytest.approx(12.0) and plan.row_accel[2] == 500.0
    assert plan.sources["accel_print"] == "; machine_max_acceleration_extruding"


def test_klipper_set_velocity_limit(gcode_file):
    # ACCEL 1000, ACCEL_TO_DECEL 250: a 2 mm move at F6000 from rest to rest peaks where the
    # triangle of the smoothed acceleration does, v^2 = a_d L, and accelerates at a.
    tp = reprap(gcode_file, "SET_VELOCITY_LIMIT VELOCITY=80 ACCEL=1000 ACCEL_TO_DECEL=250 SQUARE_CORNER_VELOCITY=5\n"
                            "G1 X0 Y0 Z0.2 F600\nG4 P10\nG1 X2 E0.1 F6000\nG4 P10\nG1 X102 E1 F6000\n")
    plan = plan_motion(tp)
    peak = math.sqrt(250.0 * 2.0)
    assert plan.v_cruise[1] == pytest.approx(peak, rel=1e-12)
    assert plan.t_end[1] - plan.t_start[1] == pytest.approx(2 * peak / 1000 + (2 - peak ** 2 / 1000) / peak, rel=1e-12)
    assert plan.v_cruise[2] == pytest.approx(80.0)  # VELOCITY caps F6000 = 100 mm/s
    assert plan.settings.effective_junction_deviation_mm == pytest.approx(25 * (math.sqrt(2) - 1) / 1000)


def test_classic_jerk_corner(gcode_file):
    # M205 X10 Y10 without J: Marlin's classic jerk. A 90-degree corner at 50 mm/s: X goes from
    # 50 to 0, Y from 0 to 50; each change must stay within 10 mm/s: the corner runs at 10.
    tp = reprap(gcode_file, "M205 X10 Y10 Z0.4 E5\nM204 P1000\nG1 X0 Y0 Z0.2 F600\nG4 P10\n"
                            "G1 X40 E1 F3000\nG1 X40 Y40 E1\n")
    plan = plan_motion(tp)
    assert plan.junction == "classic jerk per axis"
    assert plan.v_exit[1] == pytest.approx(10.0, rel=1e-9)
    assert plan.v_entry[1] == pytest.approx(10.0, rel=1e-9)  # a start from rest runs at the safe speed
    # the XY-vector rule of Marlin 1.0 (Cura's estimate): |dv| = 50 sqrt 2 -> 10 sqrt 2 / ... at jerk 10
    xy = plan_motion(tp, MotionSettings(jerk_rule="xy"))
    assert xy.v_exit[1] == pytest.approx(50.0 * 10.0 / (50.0 * math.sqrt(2)), rel=1e-9)


@pytest.mark.parametrize("dialect, body, stops", [
    ("linuxcnc", "M3 S1000\nG1 X10 F600\nM5\nG1 X20\n", True),        # M5 breaks blending
    ("linuxcnc", "M62 P0\nG1 X10 F600\nM63 P0\nG1 X20\n", False),    # synchronised with motion
    ("linuxcnc", "M64 P0\nG1 X10 F600\nM65 P0\nG1 X20\n", True),     # immediate output
])
def test_stops_by_dialect(gcode_file, dialect, body, stops):
    tp = read_gcode(gcode_file("G90 G21\nG1 X0 Y0 Z0 F600\n" + body), dialect=dialect)
    plan = plan_motion(tp)
    assert (plan.v_exit[-2] == 0.0) == stops


def test_extrusion_switch_does_not_stop(gcode_file):
    # Marlin switches the extrusion with the E axis's motion: a straight travel after a deposit
    # row runs through at F.
    tp = reprap(gcode_file, "G1 X0 Y0 Z0.2 F600\nG1 X20 E1\nG1 X40\n")
    assert tp.deposit[1] and not tp.deposit[2]
    assert plan_motion(tp).v_exit[1] == pytest.approx(10.0)


def test_m201_of_another_dialect_is_not_a_limit(gcode_file):
    # a DED cell's M201 (SDC 40) is a laser power, not an acceleration
    tp = read_gcode(gcode_file("G90\nG1 X0 Y0 Z0 F600\nM201 (SDC 40)\nG1 X10\nM201 X10 Y10\nG1 X20\n"),
                    dialect="custom", laser_on="M64", laser_off="M65")
    assert plan_motion(tp).accel == 500.0
