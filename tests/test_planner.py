"""Motion planner: closed forms of trapezoids, junctions and arcs, and invariants on random programs.

Expected values are closed forms (kinematics with constant acceleration, the junction-deviation
rule), never figures copied from the planner's output.
"""

import dataclasses
import math
import tempfile
from pathlib import Path

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings, strategies as st

from dmdvox.errors import DmdvoxError
from dmdvox.process.planner import (
    DEFAULT_ACCEL_MM_S2,
    DEFAULT_JUNCTION_DEVIATION_MM,
    DEFAULT_SQUARE_CORNER_VELOCITY_MM_S,
    MotionPlan,
    MotionSettings,
    apply_plan,
    junction_deviation_from_jerk,
    plan_motion,
    resolve_limits,
)
from dmdvox.toolpath import read_gcode

from .conftest import DATA

HEADER = "G90 G21 G17\nG1 X0 Y0 Z0 F600\nM65\n"  # seed dialect: M65 on, M64 off; G4 P in ms


def seed(gcode_file, body: str, header: str = HEADER):
    return read_gcode(gcode_file(header + body), dialect="seed")


def junction_rule(a: float, jd: float, phi: float) -> float:
    """Junction speed for a turn of ``phi`` radians between the directions (0 = straight on)."""
    s = math.sin((math.pi - phi) / 2)  # theta = pi - phi: angle to the outgoing direction's reverse
    return math.sqrt(a * jd * s / (1 - s))


# ---------------------------------------------------------------------------------------------
# single moves from rest to rest


@pytest.mark.parametrize("length, feed, accel", [
    (50.0, 10.0, 500.0),    # trapezoid: reaches F after 0.1 mm
    (2.0, 40.0, 500.0),     # F^2/a = 3.2 mm > 2 mm: a triangle
    (0.2, 10.0, 500.0),     # exactly F^2/a: the triangle just touches F
    (0.05, 10.0, 500.0),    # never reaches F
    (1e-3, 100.0, 200.0),   # a tiny move
    (30.0, 100.0, 100.0),   # long move at a slow acceleration
])
def test_single_move_closed_form(gcode_file, length, feed, accel):
    tp = seed(gcode_file, f"G1 X{length:.6f} F{feed * 60:.6f}\n")
    assert len(tp) == 1
    plan = plan_motion(tp, MotionSettings(accel_mm_s2=accel))
    f = float(np.float32(feed))  # the toolpath stores F as float32
    if length >= f * f / accel:
        expected_t = length / f + f / accel
        expected_peak = f
    else:
        expected_t = 2 * math.sqrt(length / accel)
        expected_peak = math.sqrt(accel * length)
    assert plan.v_entry[0] == 0.0 and plan.v_exit[0] == 0.0
    assert plan.v_cruise[0] == pytest.approx(expected_peak, rel=1e-12)
    assert plan.t_end[0] - plan.t_start[0] == pytest.approx(expected_t, rel=1e-12)
    assert plan.duration_s == pytest.approx(expected_t, rel=1e-12)
    # the triangle formula in its general form
    assert plan.v_cruise[0] <= math.sqrt((2 * accel * length) / 2) * (1 + 1e-12)


def test_triangle_with_nonzero_ends_closed_form(gcode_file):
    # A short row between two right-angle corners: enters and leaves at the corner speed and
    # peaks at sqrt((2 a L + v0^2 + v1^2) / 2) without reaching F.
    a, jd, f, short = 500.0, 0.05, 50.0, 0.5
    tp = seed(gcode_file, f"G1 X20 F3000\nG1 X20 Y{short}\nG1 X40 Y{short}\n")
    plan = plan_motion(tp, MotionSettings(accel_mm_s2=a, junction_deviation_mm=jd))
    vj = junction_rule(a, jd, math.pi / 2)
    assert plan.v_entry[1] == pytest.approx(vj, rel=1e-12)
    assert plan.v_exit[1] == pytest.approx(vj, rel=1e-12)
    peak = math.sqrt((2 * a * short + 2 * vj ** 2) / 2)
    assert peak < f
    assert plan.v_cruise[1] == pytest.approx(peak, rel=1e-12)
    assert plan.t_end[1] - plan.t_start[1] == pytest.approx(2 * (peak - vj) / a, rel=1e-12)
    # the long rows reach F: from rest to F, cruise, F down to the corner speed
    assert plan.v_cruise[0] == pytest.approx(f)
    expected0 = (20 - f ** 2 / (2 * a) - (f ** 2 - vj ** 2) / (2 * a)) / f + f / a + (f - vj) / a
    assert plan.t_end[0] - plan.t_start[0] == pytest.approx(expected0, rel=1e-12)


# ---------------------------------------------------------------------------------------------
# junctions


@pytest.mark.parametrize("jd", [0.01, DEFAULT_JUNCTION_DEVIATION_MM, 0.2])
@pytest.mark.parametrize("accel", [200.0, DEFAULT_ACCEL_MM_S2, 3000.0])
def test_right_angle_corner(gcode_file, accel, jd):
    tp = seed(gcode_file, "G1 X40 F6000\nG1 X40 Y40\n")  # 100 mm/s, long legs
    plan = plan_motion(tp, MotionSettings(accel_mm_s2=accel, junction_deviation_mm=jd))
    s = math.sin(math.radians(45))
    expected = math.sqrt(accel * jd * s / (1 - s))
    assert expected < 100.0
    assert plan.v_exit[0] == pytest.approx(expected, rel=1e-12)
    assert plan.v_entry[1] == plan.v_exit[0]


@pytest.mark.parametrize("turn_deg", [10.0, 30.0, 60.0, 120.0, 150.0, 170.0])
def test_junction_rule_at_other_angles(gcode_file, turn_deg):
    a, jd = 500.0, 0.05
    phi = math.radians(turn_deg)
    x, y = 40 + 40 * math.cos(phi), 40 * math.sin(phi)
    tp = seed(gcode_file, f"G1 X40 F30000\nG1 X{x:.9f} Y{y:.9f}\n")  # 500 mm/s: the rule binds
    plan = plan_motion(tp, MotionSettings(accel_mm_s2=a, junction_deviation_mm=jd))
    expected = junction_rule(a, jd, phi)
    assert expected < 500
    assert plan.v_exit[0] == pytest.approx(expected, rel=1e-7)


@pytest.mark.parametrize("scv, accel", [(DEFAULT_SQUARE_CORNER_VELOCITY_MM_S, 500.0), (5.0, 3000.0), (12.0, 800.0)])
def test_klipper_square_corner_velocity(gcode_file, scv, accel):
    tp = seed(gcode_file, "G1 X40 F6000\nG1 X40 Y40\nG1 X0 Y40\n")
    settings = MotionSettings(accel_mm_s2=accel, junction_deviation_mm=123.0, square_corner_velocity_mm_s=scv)
    plan = plan_motion(tp, settings)
    assert plan.v_exit[0] == pytest.approx(scv, rel=1e-12)
    assert plan.v_exit[1] == pytest.approx(scv, rel=1e-12)
    assert settings.effective_junction_deviation_mm == pytest.approx(scv ** 2 * (math.sqrt(2) - 1) / accel)
    assert settings.to_json()["square_corner_velocity_mm_s"] == scv


def test_marlin_jerk_conversion():
    assert junction_deviation_from_jerk(10.0, 500.0) == pytest.approx(0.4 * 100 / 500)


def test_reversal_stops(gcode_file):
    tp = seed(gcode_file, "G1 X40 F6000\nG1 X0\nG1 X40\n")
    plan = plan_motion(tp)
    assert plan.v_exit[0] == 0.0 and plan.v_entry[1] == 0.0
    assert plan.v_exit[1] == 0.0 and plan.v_entry[2] == 0.0


def test_straight_run_of_tiny_moves_reaches_feed_and_stops_in_time(gcode_file):
    a, f, step, count = 500.0, 20.0, 0.05, 400  # F reached after f^2/(2a) = 0.4 mm = 8 moves
    body = "F1200\n" + "".join(f"G1 X{step * (k + 1):.4f}\n" for k in range(count))
    tp = seed(gcode_file, body)
    assert len(tp) == count
    plan = plan_motion(tp, MotionSettings(accel_mm_s2=a))
    total = step * count
    x = np.cumsum(tp.length) - tp.length  # distance of each row's start from the program's start
    rest = total - x  # distance to the end
    expected = np.minimum.reduce([np.full(count, f), np.sqrt(2 * a * x), np.sqrt(2 * a * rest)])
    np.testing.assert_allclose(plan.v_entry, expected, rtol=1e-9, atol=1e-9)
    assert plan.v_cruise.max() == pytest.approx(f)
    # no slowing down in the middle; slowing down only within v^2/(2a) of the end
    slowing = np.flatnonzero(plan.v_exit < plan.v_entry)
    assert slowing.size > 0
    assert np.all(total - (x[slowing] + tp.length[slowing]) < f * f / (2 * a) + 1e-9)
    assert plan.v_exit[-1] == 0.0
    assert plan.duration_s == pytest.approx(total / f + f / a, rel=1e-9)


# ---------------------------------------------------------------------------------------------
# arcs


@pytest.mark.parametrize("radius", [0.5, 2.0, 8.0])
def test_arc_cruise_limited_by_centripetal_acceleration(gcode_file, radius):
    a = 500.0
    # full circle, entered from a line along its start tangent (G2 from (r,0) around the origin
    # starts going -Y): the junction is a straight continuation, limited by the arc's speed
    body = (f"G0 X{radius} Y{20 + radius} Z0\nG1 X{radius} Y0 F6000\nG2 X{radius} Y0 I{-radius} J0\n"
            f"G1 X{radius} Y-20\n")
    tp = read_gcode(gcode_file("G90 G17\n" + body), dialect="seed")
    arc_row = int(tp.arcs.segment[0])
    plan = plan_motion(tp, MotionSettings(accel_mm_s2=a))
    limit = math.sqrt(a * radius)
    assert limit < 100.0
    assert plan.v_cruise[arc_row] == pytest.approx(limit, rel=1e-12)
    assert plan.v_entry[arc_row] == pytest.approx(limit, rel=1e-12)  # tangent entry: only the arc limits
    assert plan.v_exit[arc_row] == pytest.approx(limit, rel=1e-12)
    assert plan.t_end[arc_row] - plan.t_start[arc_row] == pytest.approx(2 * math.pi * radius / limit, rel=1e-12)


def test_helix_tangent_and_curvature(gcode_file):
    # Quarter helix r = 5 around Z from (5, 0, 0) to (0, 5, h), entered along its exact start
    # tangent (0, r pi/2, h): a straight continuation. A helix of pitch c = h / (pi/2) per radian
    # has radius of curvature (r^2 + c^2) / r.
    a, r, h = 500.0, 5.0, 4.0
    sweep = math.pi / 2
    tangent = np.array([0.0, r * sweep, h]) / math.hypot(r * sweep, h)
    back = np.array([r, 0.0, 0.0]) - 10 * tangent
    body = (f"G0 X{back[0]:.12f} Y{back[1]:.12f} Z{back[2]:.12f}\nG1 X{r} Y0 Z0 F12000\n"
            f"G3 X0 Y{r} Z{h} I{-r} J0\n")
    tp = read_gcode(gcode_file("G90 G17\n" + body), dialect="seed")
    arc_row = int(tp.arcs.segment[0])
    plan = plan_motion(tp, MotionSettings(accel_mm_s2=a))
    c = h / sweep
    limit = math.sqrt(a * (r * r + c * c) / r)
    assert limit > math.sqrt(a * r)
    assert plan.v_entry[arc_row] == pytest.approx(limit, rel=1e-9)
    assert plan.v_cruise[arc_row] == pytest.approx(limit, rel=1e-9)


def test_zero_radius_arc_has_no_nan(gcode_file):
    tp = seed(gcode_file, "G1 X10\nG2 X10 Y0 I0 J0\nG1 X20\nG3 X20 Y0 Z3 I0 J0\nG1 X30\n")
    plan = plan_motion(tp)
    for name in ("v_entry", "v_cruise", "v_exit", "t_start", "t_end"):
        assert np.all(np.isfinite(getattr(plan, name))), name
    assert np.all(plan.t_end >= plan.t_start)
    rows = np.arange(len(tp))
    assert np.all(np.isfinite(plan.speed_at(rows, 0.5)))
    assert np.all(np.isfinite(plan.distance_at(rows, plan.t_end)))


# ---------------------------------------------------------------------------------------------
# full stops and gaps


def test_dwell_gap_kept_and_stops(gcode_file):
    tp = seed(gcode_file, "G1 X20 F600\nG4 P750\nG1 X40\n")
    assert tp.t_start[1] - tp.t_end[0] == pytest.approx(0.75)
    plan = plan_motion(tp)
    assert plan.t_start[1] - plan.t_end[0] == pytest.approx(0.75, abs=1e-12)
    assert plan.v_exit[0] == 0.0 and plan.v_entry[1] == 0.0
    a, f = DEFAULT_ACCEL_MM_S2, 10.0
    assert plan.duration_s == pytest.approx(2 * (20 / f + f / a) + 0.75, rel=1e-9)


def jd_junction(a: float, jd: float, u_prev, u_next) -> float:
    """The junction-deviation speed between two directions of X Y Z E (any length)."""
    u_prev, u_next = np.asarray(u_prev, float), np.asarray(u_next, float)
    cos_theta = -float(u_prev @ u_next) / (np.linalg.norm(u_prev) * np.linalg.norm(u_next))
    s = math.sqrt((1 - cos_theta) / 2)
    return math.sqrt(a * jd * s / (1 - s))


def trapezoid_time(length: float, feed: float, a: float, v0: float, v1: float) -> float:
    peak = min(feed, math.sqrt((2 * a * length + v0 * v0 + v1 * v1) / 2))
    return (peak - v0) / a + (length - (2 * peak ** 2 - v0 ** 2 - v1 ** 2) / (2 * a)) / peak + (peak - v1) / a


def test_retract_only_moves_run_with_acceleration(gcode_file):
    # A retract and a prime of 1 mm at 30 mm/s between two deposit rows: blocks of their own,
    # run from the junction with the row before (E reverses there: -u_in . u_out over X Y Z E),
    # through a full stop between them (E reverses again) to the junction with the row after.
    text = "G90\nM82\nG1 X0 Y0 Z0.3 F600\nG1 X20 E1\nG1 E0 F1800\nG1 E1\nG1 X40 E2 F600\n"
    tp = read_gcode(gcode_file(text), dialect="reprap")
    assert len(tp) == 2 and tp.deposit.all()
    assert tp.t_start[1] - tp.t_end[0] == pytest.approx(2 * 1 / 30)  # at constant feed
    a, jd = DEFAULT_ACCEL_MM_S2, DEFAULT_JUNCTION_DEVIATION_MM
    plan = plan_motion(tp)
    assert plan.retract_moves == 2
    row = (1.0, 0.0, 0.0, 1 / 20)  # 1 mm of filament over the 20 mm row
    v_out = jd_junction(a, jd, row, (0, 0, 0, -1))
    v_in = jd_junction(a, jd, (0, 0, 0, 1), row)
    assert plan.v_exit[0] == pytest.approx(v_out, rel=1e-12)
    assert plan.v_entry[1] == pytest.approx(v_in, rel=1e-12)
    expected = trapezoid_time(1.0, 30.0, a, v_out, 0.0) + trapezoid_time(1.0, 30.0, a, 0.0, v_in)
    assert plan.t_start[1] - plan.t_end[0] == pytest.approx(expected, rel=1e-12)
    assert plan.retract_s == pytest.approx(expected, rel=1e-12)


def test_retract_with_its_acceleration_and_a_dwell_kept(gcode_file):
    # M204 R sets the retract-only moves' acceleration; a dwell in the gap keeps it as the
    # reader timed it (with a full stop) and its E-only moves at constant feed.
    body = "G1 X0 Y0 Z0.3 F600\nG1 X20 E1\nG1 E0 F1800\nG1 E1\nG1 X40 E2 F600\n"
    tp = read_gcode(gcode_file("G90\nM82\nM204 P800 R200 T800\n" + body), dialect="reprap")
    plan = plan_motion(tp)
    assert plan.accel == 800.0 and plan.settings.retract_accel_mm_s2 == 200.0
    row = (1.0, 0.0, 0.0, 1 / 20)
    # a junction is run at the outgoing block's acceleration (200 into the retract, 800 out of
    # the prime) and no faster than the row's F (10 mm/s)
    v_out = jd_junction(200.0, DEFAULT_JUNCTION_DEVIATION_MM, row, (0, 0, 0, -1))
    v_in = min(jd_junction(800.0, DEFAULT_JUNCTION_DEVIATION_MM, (0, 0, 0, 1), row), 10.0)
    expected = trapezoid_time(1.0, 30.0, 200.0, v_out, 0.0) + trapezoid_time(1.0, 30.0, 200.0, 0.0, v_in)
    assert plan.t_start[1] - plan.t_end[0] == pytest.approx(expected, rel=1e-12)
    dwell = read_gcode(gcode_file("G90\nM82\n" + body.replace("G1 E1\n", "G4 P250\nG1 E1\n")), dialect="reprap")
    gap = dwell.t_start[1] - dwell.t_end[0]
    assert gap == pytest.approx(2 / 30 + 0.25)
    plan = plan_motion(dwell)
    assert plan.retract_moves == 0
    assert plan.t_start[1] - plan.t_end[0] == pytest.approx(gap, abs=1e-12)
    assert plan.v_exit[0] == 0.0 and plan.v_entry[1] == 0.0


@pytest.mark.parametrize("toggle, stops", [("", False), ("M64\n", True)])
def test_deposit_switch_forces_stop(gcode_file, toggle, stops):
    tp = seed(gcode_file, f"G1 X20 F600\n{toggle}G1 X40\n")
    plan = plan_motion(tp)
    if stops:
        assert tp.deposit[0] != tp.deposit[1]
        assert plan.v_exit[0] == 0.0 and plan.v_entry[1] == 0.0
    else:
        assert plan.v_exit[0] == pytest.approx(10.0)


def test_position_jump_stops(gcode_file):
    tp = seed(gcode_file, "G1 X20 F600\nG1 X40\n")
    start = tp.start.copy()
    start[1, 1] += 1.0  # row 1 no longer starts where row 0 ends
    jumped = dataclasses.replace(tp, start=start)
    assert plan_motion(tp).v_exit[0] == pytest.approx(10.0)
    plan = plan_motion(jumped)
    assert plan.v_exit[0] == 0.0 and plan.v_entry[1] == 0.0


def test_times_start_at_first_row_and_keep_tail(gcode_file):
    tp = seed(gcode_file, "G4 P2000\nG1 X20 F600\nG4 P500\n")
    assert tp.t_start[0] == pytest.approx(2.0)
    plan = plan_motion(tp)
    assert plan.t_start[0] == tp.t_start[0]
    assert plan.duration_s == pytest.approx(2.0 + 20 / 10 + 10 / DEFAULT_ACCEL_MM_S2 + 0.5, rel=1e-12)
    out = apply_plan(tp, plan)
    assert out.duration == plan.duration_s
    assert out.meta["motion"] == plan.to_json()
    assert out.meta["motion"]["accel_mm_s2"] == DEFAULT_ACCEL_MM_S2
    np.testing.assert_array_equal(out.t_end, plan.t_end)


# ---------------------------------------------------------------------------------------------
# constant feed


@pytest.mark.parametrize("name", ["demo_block.gcode", "prusa_block_20.gcode"])
def test_accel_zero_is_constant_feed_exactly(name):
    tp = read_gcode(DATA / name)
    plan = plan_motion(tp, MotionSettings(accel_mm_s2=0.0))
    assert plan.accel == 0.0
    np.testing.assert_array_equal(plan.t_start, tp.t_start)
    np.testing.assert_array_equal(plan.t_end, tp.t_end)
    feed = tp.feed.astype(np.float64)
    for v in (plan.v_entry, plan.v_cruise, plan.v_exit):
        np.testing.assert_array_equal(v, feed)
    assert plan.duration_s == tp.duration
    out = apply_plan(tp, plan)
    np.testing.assert_array_equal(out.t_end, tp.t_end)
    assert out.duration == tp.duration
    # and the accelerated plan of the same file is never shorter
    real = plan_motion(tp)
    assert real.duration_s >= tp.duration * (1 - 1e-7)
    assert real.duration_s > tp.duration


# ---------------------------------------------------------------------------------------------
# settings


@pytest.mark.parametrize("kwargs, option", [
    ({"accel_mm_s2": -1.0}, "--accel"),
    ({"accel_mm_s2": float("nan")}, "--accel"),
    ({"accel_mm_s2": "fast"}, "--accel"),
    ({"junction_deviation_mm": -0.1}, "--junction-deviation"),
    ({"junction_deviation_mm": float("inf")}, "--junction-deviation"),
    ({"square_corner_velocity_mm_s": -5.0}, "--square-corner-velocity"),
])
def test_settings_validation_names_the_option(kwargs, option):
    """The library names the setting; the command line's table turns it into the option."""
    from dmdvox.cli import OPTION_OF_PARAMETER

    with pytest.raises(DmdvoxError) as caught:
        MotionSettings(**kwargs).validate()
    assert caught.value.parameter == next(iter(kwargs)) and caught.value.parameter in str(caught.value)
    assert OPTION_OF_PARAMETER[caught.value.parameter] == option


def test_defaults_and_json():
    s = MotionSettings()
    s.validate()
    assert (s.accel_mm_s2, s.junction_deviation_mm, s.square_corner_velocity_mm_s) == (None, None, None)
    js = s.to_json()
    assert js["accel_mm_s2"] == 500.0 and js["effective_junction_deviation_mm"] == 0.05
    limits = resolve_limits(s, None)
    assert limits.settings.accel_mm_s2 == DEFAULT_ACCEL_MM_S2
    assert limits.settings.junction_deviation_mm == DEFAULT_JUNCTION_DEVIATION_MM
    assert limits.sources["accel_print"] == "default" and limits.sources["junction_deviation"] == "default"


def test_empty_toolpath(gcode_file):
    tp = seed(gcode_file, "G4 P1500\n")
    assert len(tp) == 0
    for accel in (0.0, 500.0):
        plan = plan_motion(tp, MotionSettings(accel_mm_s2=accel))
        assert len(plan.t_end) == 0
        assert plan.duration_s == pytest.approx(tp.duration)
        assert apply_plan(tp, plan).duration == pytest.approx(tp.duration)


def test_queries_broadcast(gcode_file):
    tp = seed(gcode_file, "G1 X20 F600\nG1 X20 Y20\n")
    plan = plan_motion(tp)
    d = np.linspace(0, 20, 7)
    out = plan.speed_at(np.arange(2)[:, None], d[None, :])
    assert out.shape == (2, 7)
    np.testing.assert_array_equal(out[1], plan.speed_at(1, d))
    assert plan.speed_at(0, 0.0).shape == ()
    assert plan.speed_at(0, 0.0) == 0.0
    assert plan.speed_at(0, 10.0) == pytest.approx(10.0)


# ---------------------------------------------------------------------------------------------
# invariants on random programs


@st.composite
def programs(draw):
    lines = ["G90 G21 G17", "G1 X0 Y0 Z0 F600", "M65"]
    x = y = z = 0.0
    on = True
    dx, dy, dz = 1.0, 0.0, 0.0
    for _ in range(draw(st.integers(1, 25))):
        op = draw(st.sampled_from(["line", "line", "line", "tiny", "again", "arc", "arc", "dwell", "toggle", "rapid",
                                   "feed"]))
        if op in ("line", "tiny", "rapid", "again"):
            if op != "again":  # "again": a collinear continuation of the last move
                scale = 0.02 if op == "tiny" else 15.0
                dx, dy = draw(st.floats(-scale, scale)), draw(st.floats(-scale, scale))
                dz = draw(st.sampled_from([0.0, 0.0, 0.5]))
            x, y, z = round(x + dx, 4), round(y + dy, 4), round(z + dz, 4)
            lines.append(f"{'G0' if op == 'rapid' else 'G1'} X{x:.4f} Y{y:.4f} Z{z:.4f}")
        elif op == "arc":
            r = draw(st.floats(0.1, 10.0))
            start_angle = draw(st.floats(0, 2 * math.pi))
            turn = draw(st.floats(0.1, 2 * math.pi - 0.1))
            ccw = draw(st.booleans())
            cx, cy = x - r * math.cos(start_angle), y - r * math.sin(start_angle)
            end_angle = start_angle + (turn if ccw else -turn)
            rise = draw(st.sampled_from([0.0, 0.0, 1.0]))
            i_off, j_off = cx - x, cy - y
            x, y, z = round(cx + r * math.cos(end_angle), 6), round(cy + r * math.sin(end_angle), 6), z + rise
            lines.append(f"{'G3' if ccw else 'G2'} X{x:.6f} Y{y:.6f} Z{z:.4f} I{i_off:.6f} J{j_off:.6f}")
        elif op == "dwell":
            lines.append(f"G4 P{draw(st.integers(1, 500))}")
        elif op == "toggle":
            on = not on
            lines.append("M65" if on else "M64")
        else:
            lines.append(f"F{draw(st.floats(60.0, 12000.0)):.3f}")
    return "\n".join(lines) + "\n"


motion_settings = st.builds(
    MotionSettings,
    accel_mm_s2=st.floats(20.0, 5000.0),
    junction_deviation_mm=st.floats(0.0, 0.5),
    square_corner_velocity_mm_s=st.one_of(st.none(), st.floats(0.0, 20.0)),
)


def read_text(text: str):
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "prog.gcode"
        path.write_text(text)
        return read_gcode(path, dialect="seed")


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(text=programs(), motion=motion_settings)
def test_plan_invariants(text, motion):
    tp = read_text(text)
    if len(tp) == 0:
        return
    plan = plan_motion(tp, motion)
    a = plan.accel
    length = tp.length
    feed = tp.feed.astype(np.float64)

    # never above the row's feed, and the cruise (peak) is the row's highest speed
    for v in (plan.v_entry, plan.v_cruise, plan.v_exit):
        assert np.all(v >= 0.0)
        assert np.all(v <= feed * (1 + 1e-12))
    assert np.all(plan.v_cruise >= np.maximum(plan.v_entry, plan.v_exit))
    # acceleration bound over each row
    assert np.all(np.abs(plan.v_exit ** 2 - plan.v_entry ** 2) <= 2 * a * length * (1 + 1e-9) + 1e-9)
    assert np.all(plan.v_cruise ** 2 <= (2 * a * length + plan.v_entry ** 2 + plan.v_exit ** 2) / 2 * (1 + 1e-9) + 1e-9)
    # continuity at every junction (stops are 0 on both sides), rest at both ends
    np.testing.assert_array_equal(plan.v_exit[:-1], plan.v_entry[1:])
    assert plan.v_entry[0] == 0.0 and plan.v_exit[-1] == 0.0
    # stops where the seed's deposition codes (M64/M65: the Fadal runs M-functions between blocks)
    # or the constant-feed timing pause; a switch to G0 without a code does not stop
    code_lines = np.array([k + 1 for k, line in enumerate(text.split("\n")) if line in ("M64", "M65")])
    coded = np.array([np.any((code_lines > a0) & (code_lines <= a1)) for a0, a1 in zip(tp.line[:-1], tp.line[1:])],
                     bool)
    pause = tp.t_start[1:] - tp.t_end[:-1] > 1e-9
    assert np.all(plan.v_exit[:-1][coded | pause] == 0.0)
    # arcs: cruise within the centripetal limit of the smaller radius (helices are straighter)
    planar = tp.end[tp.arcs.segment, 2] == tp.start[tp.arcs.segment, 2]
    rows = tp.arcs.segment[planar]
    r_min = np.minimum(tp.arcs.r_start, tp.arcs.r_end)[planar]
    assert np.all(plan.v_cruise[rows] ** 2 <= a * r_min * (1 + 1e-9) + 1e-9)

    # times: the first row where the toolpath starts it, gaps kept, never faster than F
    assert plan.t_start[0] == tp.t_start[0]
    np.testing.assert_allclose(plan.t_start[1:] - plan.t_end[:-1], tp.t_start[1:] - tp.t_end[:-1], atol=1e-9)
    planned = plan.t_end - plan.t_start
    constant = tp.t_end - tp.t_start
    assert np.all(planned >= constant * (1 - 1e-7) - 1e-12)
    assert plan.duration_s >= tp.duration * (1 - 1e-7)

    # time_at / distance_at / speed_at agree: integrating the speed over time gives the distance
    moving = np.flatnonzero(length > 1e-9)
    if moving.size == 0:
        return
    k = 2001
    frac = np.linspace(0.0, 1.0, k)
    times = plan.t_start[moving, None] + frac[None, :] * planned[moving, None]
    dist = plan.distance_at(moving[:, None], times)
    np.testing.assert_allclose(dist[:, 0], 0.0, atol=1e-9)
    np.testing.assert_allclose(dist[:, -1], length[moving], rtol=1e-9, atol=1e-9)
    assert np.all(np.diff(dist, axis=1) >= -1e-12)
    speed = plan.speed_at(moving[:, None], dist)
    integral = np.concatenate([np.zeros((moving.size, 1)),
                               np.cumsum(0.5 * (speed[:, 1:] + speed[:, :-1]) * np.diff(times, axis=1), axis=1)], axis=1)
    # the speed is piecewise linear in time: the trapezoid rule errs only at the 2 kinks
    dt = planned[moving] / (k - 1)
    tol = a * dt ** 2 + 1e-9 * (1 + length[moving])
    assert np.all(np.abs(integral - dist) <= tol[:, None] * 2)
    back = plan.time_at(moving[:, None], dist)
    # near rest the time is ill-conditioned in the distance (t ~ sqrt(2 s / a)): allow for the
    # rounding of the distance, then check the well-conditioned way round exactly
    atol = np.sqrt(2 * 4e-16 * (1 + length[moving]) / a) + 1e-9 * (1 + np.abs(times).max())
    assert np.all(np.abs(back - times) <= atol[:, None])
    grid = frac[None, :] * length[moving, None]
    np.testing.assert_allclose(plan.distance_at(moving[:, None], plan.time_at(moving[:, None], grid)), grid,
                               rtol=1e-9, atol=1e-9)
    # the speed at the ends is the entry and exit speed
    np.testing.assert_allclose(plan.speed_at(moving, 0.0), plan.v_entry[moving], rtol=1e-9, atol=1e-9)
    np.testing.assert_allclose(plan.speed_at(moving, length[moving]), plan.v_exit[moving], rtol=1e-9, atol=1e-9)


@settings(max_examples=25, deadline=None)
@given(text=programs())
def test_constant_feed_is_identity_on_random_programs(text):
    tp = read_text(text)
    plan = plan_motion(tp, MotionSettings(accel_mm_s2=0.0))
    np.testing.assert_array_equal(plan.t_start, tp.t_start)
    np.testing.assert_array_equal(plan.t_end, tp.t_end)
    assert isinstance(plan, MotionPlan)
