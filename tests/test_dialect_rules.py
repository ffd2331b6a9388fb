"""Laser rules with parameter conditions, what auto-detection went by, and the dialect's units
(issue 22: "Laser codes with parameters", "Units of the dialect named", M68 E, M428). Each test
is the minimal program of one finding; expected values are the programs' own geometry."""

from __future__ import annotations

import math

import numpy as np
import pytest

from dmdvox.errors import DmdvoxError
from dmdvox.limits import read_cell
from dmdvox.toolpath.model import ROW_FIELDS
from dmdvox.toolpath.reader import read_gcode

# GLOW's single-track program in miniature: M64 P2/P3 start the fume extractor and the argon,
# `M201 (SDC p)` sets the laser power (0: off), 25 mm lifts between the tracks, G4 P in seconds.
GLOW = ("G90 G21\nG1 X0 Y0 Z0 F600\nM64 P2 ; fume extractor\nM64 P3 ; argon\n"
        "M201 (SDC 0) ; power 0%M201 (EMON)\n"
        "G1 Z25\nG1 X2 Y2\nG1 Z0\nM201 (SDC 37.8)\nG1 Y12\nM201 (SDC 0)\nG4 P30\n"
        "G1 Z25\nG1 X5 Y2\nG1 Z0\nM201 (SDC 42.5)\nG1 Y12\nM201 (SDC 0)\n")
SDC_RULES = {"dialect": "custom", "laser_on": "M201 SDC>0", "laser_off": "M201 SDC=0"}


def test_parenthesised_parameter_switches_the_laser_and_gives_the_power(gcode_file):
    tp = read_gcode(gcode_file(GLOW), **SDC_RULES)
    # two 10 mm tracks deposit; the lifts, the travel and the M64 P2/P3 lines do not
    assert float(tp.length[tp.deposit].sum()) == pytest.approx(20.0)
    assert tp.line[tp.deposit].tolist() == [10, 17]
    assert tp.power[tp.deposit].tolist() == pytest.approx([37.8, 42.5])
    # `M201 (SDC 0)` matched the off rule: power 0 on the first lift
    assert tp.power[0] == 0.0


def test_power_is_nan_where_no_word_gives_it(gcode_file):
    tp = read_gcode(gcode_file("G1 X0 Y0 Z0 F600\nM65\nG1 X5\nM64\nG1 X9\nS300\nG1 X12\n"), dialect="seed")
    assert tp.deposit.tolist() == [True, False, False]
    assert np.isnan(tp.power[:2]).all() and tp.power[2] == 300.0


def test_dwell_between_tracks_is_seconds_under_custom_rules_of_a_linuxcnc_file(gcode_file):
    tp = read_gcode(gcode_file(GLOW), **SDC_RULES)
    after_first = int(np.flatnonzero(tp.line == 10)[0])
    # the rows after track 1 and before the next lift: none; the dwell is the gap before line 13's row
    gap = tp.t_start[after_first + 1] - tp.t_end[after_first]
    assert gap == pytest.approx(30.0)


def test_words_without_operator_are_equalities_and_m64_is_not_the_laser(gcode_file):
    # Arc One's welder: M42 P1 S1 on, M42 P1 S0 off; M42 P2 S1 is another output
    text = ("G90\nG1 X0 Y0 Z0 F600\nM64 P2\nG1 X1\nM42 P1 S1\nG1 X4\nM42 P2 S0\nG1 X9\nM42 P1 S0\nG1 X20\n"
            "M42 P2 S1\nG1 X30\n")
    tp = read_gcode(gcode_file(text), dialect="custom", laser_on="M42 P1 S1", laser_off="M42 P1 S0")
    assert tp.deposit.tolist() == [False, True, True, False, False]
    assert float(tp.length[tp.deposit].sum()) == pytest.approx(8.0)


@pytest.mark.parametrize("on,off,expected", [
    ("M3 S>0", "M3 S=0", [True, False, True]),
    ("M3 S>=500", "M3 S<500", [True, False, True]),
    ("M3 S!=0", "M3 S<=0", [True, False, True]),
    ("M3 S>600", "M3 S<=600", [False, False, True]),
])
def test_every_operator(gcode_file, on, off, expected):
    text = "G1 X0 Y0 Z0 F600\nM3 S500\nG1 X1\nM3 S0\nG1 X2\nM3 S700\nG1 X3\n"
    tp = read_gcode(gcode_file(text), dialect="custom", laser_on=on, laser_off=off)
    assert tp.deposit.tolist() == expected


def test_a_missing_s_is_the_s_in_force(gcode_file):
    # Grbl: `S800` alone, then `M3` without S turns the beam on at 800
    text = "G1 X0 Y0 Z0 F600\nS800\nM3\nG1 X5\nM5\nG1 X9\n"
    tp = read_gcode(gcode_file(text), dialect="custom", laser_on="M3 S>0", laser_off="M5")
    assert tp.deposit.tolist() == [True, False]
    assert tp.power[0] == 800.0


def test_analog_output_rule_reads_q_as_the_power(gcode_file):
    text = "G1 X0 Y0 Z0 F600\nM68 E2 Q40\nG1 X3\nM68 E2 Q0\nG1 X7\nM68 E1 Q50\nG1 X8\n"
    tp = read_gcode(gcode_file(text), dialect="custom", laser_on="M68 E=2 Q>0", laser_off="M68 E=2 Q=0")
    assert tp.deposit.tolist() == [True, False, False]
    assert tp.power[0] == 40.0


def test_a_parameter_after_a_semicolon_is_a_comment(gcode_file):
    text = "G1 X0 Y0 Z0 F600\nM201 ; (SDC 30)\nG1 X3\n"
    tp = read_gcode(gcode_file(text), **SDC_RULES)
    assert not tp.deposit.any()


def test_bad_rules_are_refused_naming_the_option():
    for bad in ("M201 SDC~0", "X1", "M3 S>", "M3 S>0 junk"):
        with pytest.raises(DmdvoxError, match="--laser-on: .*KEY OP VALUE"):
            read_gcode(__file__, dialect="custom", laser_on=bad, laser_off="M5")
    with pytest.raises(DmdvoxError, match="--laser-off: 5 is not a list of codes"):
        read_gcode(__file__, dialect="custom", laser_on="M3", laser_off=5)


def test_cell_file_rules(gcode_file, tmp_path):
    cell = tmp_path / "cell.toml"
    cell.write_text('[limits]\nporosity_percent = 1\n[process]\ndialect = "custom"\n'
                    'laser_on = "M201 SDC>0"\nlaser_off = "M201 SDC=0"\n')
    options = read_cell(cell).options
    tp = read_gcode(gcode_file(GLOW), dialect=options["dialect"], laser_on=options["laser_on"],
                    laser_off=options["laser_off"])
    assert float(tp.length[tp.deposit].sum()) == pytest.approx(20.0)


# ---- what auto-detection went by, and when it is weak ----------------------------------------------

def _info_json(path, *args):
    import contextlib
    import io
    import json

    from dmdvox.cli import main

    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        code = main(["info", str(path), *args, "--json"])
    return code, json.loads(out.getvalue()), err.getvalue()


def test_auto_says_its_evidence_in_the_json_and_the_log(gcode_file):
    code, out, err = _info_json(gcode_file(GLOW))
    assert code == 0
    assert out["dialect"] == "linuxcnc"
    assert out["dialect_evidence"] == ["line 3: M64 P2 (linuxcnc digital output)"]
    assert "dialect: linuxcnc, by line 3: M64 P2" in err


def test_weak_evidence_is_warned_every_move_and_lifts_deposit(gcode_file):
    code, out, _ = _info_json(gcode_file(GLOW))
    weak = [w for w in out["warnings"] if "weak evidence" in w]
    assert len(weak) == 1
    # six moves after the start, all deposit under M64 P2: four are 25 mm lifts (lines 6, 8, 13, 15)
    assert "every move deposits" in weak[0] and "4 vertical lifts" in weak[0] and "line 6" in weak[0]
    # all of the path deposits: 4 x 25 mm of lifts, 2 travels and 2 tracks of 10 mm
    assert out["deposit_length_mm"] == pytest.approx(100 + math.hypot(2, 2) + math.hypot(3, 10) + 20)


def test_deposit_state_that_never_changes_once_on_is_weak(gcode_file):
    text = "G1 X0 Y0 Z0 F600\nG0 X5\nM64 P2\nG1 X10\nG1 Y10\nG1 X0\n"
    tp = read_gcode(gcode_file(text))
    assert tp.deposit.tolist() == [False, True, True, True]
    assert any("the deposit state never changes once on" in w for w in tp.meta["warnings"])
    # switched off and on again between the tracks: no doubt
    tp = read_gcode(gcode_file("G1 X0 Y0 Z0 F600\nM64 P2\nG1 X10\nM65 P2\nG1 Y10\nM64 P2\nG1 X0\n"))
    assert tp.deposit.tolist() == [True, False, True]
    assert not any("weak evidence" in w for w in tp.meta["warnings"])


def test_an_e_inside_an_m_code_is_no_reprap_evidence(gcode_file):
    # LinuxCNC's analog output M68 E2 Q100: E is the output number
    text = "G90 G1 X0 Y0 Z0 F600\nM68 E2 Q100\nM3 S100\nG1 X10\nM5\nG1 X20\n"
    tp = read_gcode(gcode_file(text))
    assert tp.dialect == "linuxcnc"
    assert tp.meta["dialect_evidence"] == ["line 3: M3 (spindle/laser (M3/M4/M5: linuxcnc, grbl))"]
    assert tp.deposit.tolist() == [True, False]


# ---- auto behaves exactly as the dialect it reports ----------------------------------------------------

def _same_toolpath(a, b):
    for name in ROW_FIELDS:
        x, y = getattr(a, name), getattr(b, name)
        if x is None or y is None:
            assert x is None and y is None, name
            continue
        np.testing.assert_array_equal(x, y, err_msg=name)
    for name in ("segment", "centre", "normal_axis", "sweep", "r_start", "r_end", "length"):
        np.testing.assert_array_equal(getattr(a.arcs, name), getattr(b.arcs, name), err_msg=name)
    np.testing.assert_array_equal(a.layer_z, b.layer_z)
    assert (a.duration, a.dialect, a.z_is_layer_top) == (b.duration, b.dialect, b.z_is_layer_top)


@pytest.mark.parametrize("text,named", [
    # LinuxCNC: G4 P in seconds (auto read it as milliseconds before), G0 at the rapid rate
    ("G21 G90\nG0 X0 Y0 Z0\nM3 S1000\nG1 X10 F600\nG4 P2\nG0 X20\nG2 X30 Y0 I5 J0\nM5\nG1 X40\n", "linuxcnc"),
    # RepRap: G0 at F and Z the layer top before the first E word as after it
    ("M83\nG1 X0 Y0 Z0.3 F600\nG0 X10\nG4 P500\nG1 X30 E1\nG0 X40\nG1 X50 E1\n", "reprap"),
    ("G90 G1 X0 Y0 Z0 F600\nM64 P8\nG1 X10\nM64 P9\nG1 X20\nG4 P250\nM65 P8\n", "meltio"),
    ("G90 G1 X0 Y0 Z0 F600\nM65\nG1 X10\nG4 P250\nM64\nG1 X20\n", "seed"),
])
def test_auto_gives_the_named_dialects_toolpath(gcode_file, text, named):
    path = gcode_file(text)
    auto = read_gcode(path)
    assert auto.dialect == named
    _same_toolpath(auto, read_gcode(path, dialect=named))


def test_auto_reads_g4_p_in_the_unit_of_the_dialect_it_reports(gcode_file):
    tp = read_gcode(gcode_file("G90 G0 X0 Y0 Z0\nM3 S1000\nG1 X10 F600\nG4 P2\nG1 X20\nM5\n"))
    assert (tp.dialect, tp.meta["dwell_p_unit"]) == ("linuxcnc", "s")
    assert tp.t_start[1] - tp.t_end[0] == pytest.approx(2.0)


# ---- doubtful numbers ------------------------------------------------------------------------------------

def test_long_dwell_long_move_and_odd_feed_are_warned_once_each(gcode_file):
    text = ("G90 G1 X0 Y0 Z0 F600\nM3 S100\nG4 P700\nG1 X10\nG4 P900\nG1 X12000\nG1 X12001 F0.05\n"
            "G1 X12002\nG1 X12010 F200000\nM5\n")
    tp = read_gcode(gcode_file(text), dialect="linuxcnc")
    warnings = tp.meta["warnings"]
    dwell = [w for w in warnings if "a dwell of" in w]
    move = [w for w in warnings if "a move of" in w]
    feed = [w for w in warnings if "a feed of" in w]
    assert len(dwell) == len(move) == len(feed) == 1
    assert ":3: a dwell of 700 s" in dwell[0] and "2 such dwells" in dwell[0]
    assert ":6: a move of 12.0 m" in move[0] and "1 such move" in move[0]
    assert ":7: a feed of 0.05 mm/min" in feed[0] and "3 moves" in feed[0]
    # none of them in an ordinary program
    tp = read_gcode(gcode_file("G90 G1 X0 Y0 Z0 F600\nM3 S100\nG4 P5\nG1 X100\nM5\n"), dialect="linuxcnc")
    assert tp.meta["warnings"] == []


# ---- remapped and unsupported tool-centre-point codes ------------------------------------------------------

def test_m428_and_g43_5_get_a_hint_naming_what_to_do(gcode_file):
    text = "G21 G90\nM429\nG1 X0 Y0 Z0 F600\nM428 ;TCP:xyzac\nM3 S100\nG1 X10 A10\nM429\nG43.5 H1\nG1 X5\nM5\n"
    tp = read_gcode(gcode_file(text), dialect="linuxcnc")
    remap = [w for w in tp.meta["warnings"] if "LinuxCNC remaps" in w]
    assert len(remap) == 1 and "--machine" in remap[0] and "G43.4" in remap[0]
    assert any(":8: G43.5 (x1): tool-centre-point control" in w and "--machine" in w for w in tp.meta["warnings"])


def test_an_e_naming_an_output_beside_a_move_is_no_reprap_evidence(gcode_file):
    # LinuxCNC's laser demo: M67 E2 Q25 sets analog output 2 along the move
    text = "G90 G1 X0 Y0 Z0 F600\nM3 S100\nG1 X5 M67 E2 Q25\nG1 X10\nM5\n"
    tp = read_gcode(gcode_file(text))
    assert tp.dialect == "linuxcnc"
    assert not any("reprap" in e for e in tp.meta["dialect_evidence"])
    assert float(tp.length[tp.deposit].sum()) == pytest.approx(10.0)


def test_e_words_are_no_weak_evidence(gcode_file):
    tp = read_gcode(gcode_file("M83\nG1 X0 Y0 Z0.3 F600\nG1 X10 E1\nG1 Y10 E1\n"))
    assert tp.dialect == "reprap" and tp.deposit.all()
    assert not any("weak evidence" in w for w in tp.meta["warnings"])


@pytest.mark.parametrize("dialect", ["auto", "linuxcnc", "grbl"])
def test_m3_s1000_with_e_words_simulates_or_refuses(gcode_file, tmp_path, dialect):
    # the three-line program (a ZeroDivisionError once): exit 0, or 2 with a message
    import contextlib
    import io

    from dmdvox.cli import main

    path = gcode_file("G90 G1 X0 Y0 Z0 F600\nM3 S1000\nG1 X10 E1\n")
    err = io.StringIO()
    with contextlib.redirect_stdout(io.StringIO()), contextlib.redirect_stderr(err):
        code = main(["simulate", str(path), "--dialect", dialect, "--out", str(tmp_path / dialect)])
    assert code in (0, 2), err.getvalue()
    assert "Traceback" not in err.getvalue()
