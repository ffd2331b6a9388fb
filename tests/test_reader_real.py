"""What real programs hold that hand-made ones do not (issue 22, "Reader gaps"), each on a minimal
reproduction: firmware codes whose letters are parameters, free text, generators' habits, files
that never give Z or start in G91, compressed programs, the slicers' filament comments, E words
that do not mean what the file's mode says."""

from __future__ import annotations

import math

import numpy as np
import pytest

from dmdvox.errors import DmdvoxError, GcodeError
from dmdvox.toolpath.reader import read_gcode


def deposit_length(tp) -> float:
    return float(tp.length[tp.deposit].sum())


# ---- item 1: only G0-G3 move the tool; every other code's words are its parameters -------------

PRUSA_HEADER = """M73 P0 R32
M201 X10000 Y10000 Z400 E5000
M203 X200 Y200 Z12 E120
M204 P1250 R1250 T1250
M205 X10 Y10 Z0.2 E4.5
M205 S0 T0
M862.3 P "COREONE"
M862.6 P"Input shaper"
M862.1 P0.4 A0 F0
M486 AShape-Box
M115 U6.1.3+7898
M555 X118.75 Y94.75 W32 H16.5
M104 T0 S170
M84 E
G90
M83
G28 W
G29 P9 X10 Y-4 W32 H4
"""


def test_machine_limit_codes_do_not_move_the_tool(gcode_file):
    # The header of stock PrusaSlicer output, then a half circle (G2, centre 5 mm away) and a
    # line: M73's R after the arc is a remaining time, not a radius of the modal G2.
    path = gcode_file(PRUSA_HEADER + "G1 X10 Y10 Z0.2 F1200\nG2 X20 Y10 I5 J0 E1\nM73 P10 R31\nG1 X30 Y10 E1\n")
    for strict in (False, True):
        tp = read_gcode(path, strict=strict)
        assert tp.dialect == "reprap"
        assert tp.meta["warnings"] == []
        assert len(tp) == 3  # from home to the start, the arc, the line
        assert deposit_length(tp) == pytest.approx(5 * math.pi + 10, rel=1e-12)
        assert float(tp.end[:, 0].max()) == 30.0 and float(tp.end[:, 2].max()) == pytest.approx(0.2)
        assert "T" not in tp.meta["unknown_codes"]  # M104 T0: the tool of the temperature, no tool change


def test_free_text_lines_read_without_warnings(gcode_file):
    text = ("PRINT_START EXTRUDER=215 BED=60\nprint_start bed=70 extruder=210\n_CLEAN_NOZZLE\n"
            "EXCLUDE_OBJECT_DEFINE NAME=cube CENTER=10,10 POLYGON=[[0,0],[1,1]]\nGET_POSITION\n"
            "M117 1% layer 0 / 25\nM118 X: done; Y\nM291 P\"Insert filament, then press OK\" S2\n"
            "(a comment) ; and another\nM83\nG1 X0 Y0 Z0.2 F600\nG1 X10 E1 ; printing\nprint_end\n")
    path = gcode_file(text)
    for strict in (False, True):
        tp = read_gcode(path, strict=strict)
        assert tp.meta["warnings"] == []
        assert deposit_length(tp) == 10.0


def test_two_feed_words_the_last_counts_warned_once(gcode_file):
    # The WAAM ArcOne generator writes "G1 F380.9 F381.2 X47.063 Y42.943" after each pause.
    path = gcode_file("G90 G1 X0 Y0 Z0 F600\nM3 S1\nG1 F300 F600 X10\nG1 X20\nG1 F100 F1200 X40\nM5\n")
    tp = read_gcode(path, dialect="linuxcnc")
    np.testing.assert_allclose(tp.feed, [10.0, 10.0, 20.0])  # mm/s: the second F of each line
    assert tp.meta["warnings"] == [f"{path}:3: two F words on one line: the last one is the feed "
                                   "(2 lines; the first is line 3)"]


def test_rs274_m_codes_leave_axis_words_to_the_motion_but_not_e(gcode_file):
    # LinuxCNC: "X5 M3 S100" moves in the modal G1; "M68 E2 Q100" sets analog output 2, it does
    # not extrude (auto used to switch to reprap on that E).
    path = gcode_file("G90 G0 X0 Y0 Z0\nG1 F600\nX5 M3 S100\nM68 E2 Q100\nG1 X10\nM5\nG1 X12\n")
    tp = read_gcode(path)
    assert tp.dialect == "linuxcnc"
    assert deposit_length(tp) == 10.0


def test_codes_that_own_their_axis_words(gcode_file):
    # G10 L20 sets a work offset, G52 a local one, G29 levels the bed: their X Y Z move nothing.
    # G38.2 / G31 probe: a feed move that deposits nothing.
    path = gcode_file("G90 G0 X0 Y0 Z0\nM3 S1\nG1 X10 F600\nG10 L20 P1 X50 Y50\nG52 X100\nG29 X30 Y30\n"
                      "G38.2 Z-5 F60\nG1 X20\nM5\n")
    tp = read_gcode(path, dialect="linuxcnc", plate_z=-5.0)
    assert float(np.abs(tp.end[:, :2]).max()) == 20.0
    assert deposit_length(tp) == 20.0  # X0-X10 at Z0 and X10-X20 at the probed Z-5
    probe = (tp.start[:, 2] == 0.0) & (tp.end[:, 2] == -5.0)
    assert probe.sum() == 1 and not tp.deposit[probe].any()
    assert tp.t_end[probe][0] - tp.t_start[probe][0] == pytest.approx(5.0)  # 5 mm at F60
    # a probe down to Z-11.8 in touches the plate (here Z 0) and stops; G92 Z0 zeroes Z there, so
    # every touch-off and pierce cycle cuts at the same height (the Mach3 plasma file's cycles)
    cycle = "G0 Z5\nG31 Z-300 F600\nG92 Z0\nG0 Z1\nM3 S1\nG1 X{x} F600\nM5\n"
    tp = read_gcode(gcode_file("G90 G0 X0 Y0 Z0\n" + cycle.format(x=10) + cycle.format(x=20)), dialect="linuxcnc")
    assert list(tp.layer_z) == [1.0] and deposit_length(tp) == 20.0


def test_malformed_motion_lines_still_refused(gcode_file):
    # The firmware's own syntax is not checked after an M-code, but a motion line still is.
    path = gcode_file("G90 G1 X0 Y0 Z0 F600\nG90 G1 X1 Yabc\n")
    with pytest.raises(GcodeError, match="word Y has no number"):
        read_gcode(path, strict=True)


# ---- item 3: .gcode.gz -----------------------------------------------------------------------

def test_gzip_program_read_as_its_text(gcode_file, tmp_path, monkeypatch):
    import gzip

    from dmdvox.errors import InputFileError
    from dmdvox.toolpath import reader

    text = "G90 M83\nG1 X0 Y0 Z0.2 F600\n" + "".join(f"G1 X{10 * (k % 2)} Y{k} E0.5\n" for k in range(1, 50))
    plain = gcode_file(text)
    packed = tmp_path / "part.gcode.gz"
    packed.write_bytes(gzip.compress(text.encode(), mtime=0))
    a, b = read_gcode(plain), read_gcode(packed)
    np.testing.assert_array_equal(a.start, b.start)
    np.testing.assert_array_equal(a.deposit, b.deposit)
    assert deposit_length(b) == pytest.approx(49 * math.sqrt(101.0))
    # a decompressed size above the limit is refused, saying the limit and what to do
    monkeypatch.setattr(reader, "MAX_GUNZIP_BYTES", 100)
    with pytest.raises(InputFileError, match=r"decompresses to more than 100 bytes.*gunzip"):
        read_gcode(packed)
    monkeypatch.undo()
    # a truncated download
    cut = tmp_path / "cut.gcode.gz"
    cut.write_bytes(packed.read_bytes()[:-30])
    with pytest.raises(InputFileError, match="not a readable gzip file"):
        read_gcode(cut)


# ---- item 4: every major slicer's filament-diameter comment ------------------------------------

CURA_SETTINGS = (";SETTING_3 {\"global_quality\": \"[general]\\\\nversion = 4\\\\n[values]\\\\nlayer_height = 0.2\\\\n\", \"ext\n"
                 ";SETTING_3 ruder_quality\": [\"[general]\\\\nversion = 4\\\\n[values]\\\\nmaterial_dia\n"
                 ";SETTING_3 meter = 2.85\\\\nmachine_nozzle_tip_outer_diameter = 1.6\\\\n\"]}\n")


@pytest.mark.parametrize("header, diameter", [
    ("; filament_diameter = 1.75\n", 1.75),  # PrusaSlicer, Slic3r, Orca (their config block)
    (";EXTRUDER_TRAIN.0.MATERIAL.DIAMETER:2.85\n", 2.85),  # Cura, Griffin header
    (CURA_SETTINGS, 2.85),  # Cura: the settings block, the key cut across two lines
    (";   nozzleDiameter,0.40000\n;   filamentDiameter,1.75000\n", 1.75),  # Simplify3D 4 and 5
    (";   filamentDiameters,2.85|2.85\n", 2.85),
    (";Filament Diameter #1: 1.750\n;Filament Diameter #2: 2.850\n", 1.75),  # ideaMaker: the first extruder
    ("; >   > Filament diameter = 3 [mm]\n; fiber_dia_mm = 2.85\n", 2.85),  # KISSlicer
    ("(<setting> dimension Filament_Diameter_(mm): 1.82 </setting>)\n", 1.82),  # Skeinforge
    ("; nozzle_diameter = 0.4\n;SETTING_3 machine_nozzle_tip_outer_diameter = 1.6\n", None),  # no filament's
])
def test_filament_diameter_from_each_slicer(gcode_file, header, diameter):
    tp = read_gcode(gcode_file(header + "M83\nG1 X0 Y0 Z0.2 F600\nG1 X10 E1\n"))
    assert tp.meta["filament_diameter_mm"] == diameter


# ---- item 2: LinuxCNC parameters, expressions and o-words --------------------------------------

def test_parameters_said_once_when_they_do_not_decide_the_path(gcode_file):
    # The plasma wrench's shape: an assignment, a feed from a HAL pin, the torch with its '$0'.
    path = gcode_file("#<holes> = 4 (holes)\nG20\nF#<_hal[plasmac.cut-feed-rate]> (from the cut table)\n"
                      "G0 X1 Y0 Z0\nM3 $0 S1\nG1 X2\nM5 $0\n#1=5\nG1 F#1 X3\n")
    tp = read_gcode(path, dialect="linuxcnc")
    assert deposit_length(tp) == pytest.approx(25.4)
    said = [w for w in tp.meta["warnings"] if "parameters and expressions are not supported" in w]
    assert said == tp.meta["warnings"] and len(said) == 1
    assert said[0].startswith(f"{path}:1: ") and "(4 lines; the first is line 1)" in said[0]
    with pytest.raises(GcodeError, match="parameters and expressions are not supported") as err:
        read_gcode(path, dialect="linuxcnc", strict=True)
    assert err.value.line == 1


@pytest.mark.parametrize("text, line", [
    ("G0 X0 Y0 Z0\nG1 X[1+2] F600\n", 2),
    ("G0 X0 Y0 Z0\nG1 Y - #<width> F600\n", 2),
    ("g21\ng10 l20 p0 x-[#<_hal[kins.x-rot-point]>+#<_hal[kins.x-offset]>] y0\ng0 x0 y0 z0\n", 2),  # the offset
    ("#<r> = 5\nG0 X0 Y0 Z0\nG2 X10 Y0 R#<r>\n", 3),
    ("o100 sub\nG1 X1 Y1 Z1\no100 endsub\no100 call\n", 1),
    ("G0 X0 Y0 Z0\no<loop> while [#1 LT 3]\nG1 X1\no<loop> endwhile\n", 2),
])
def test_expressions_that_decide_the_path_are_refused(gcode_file, text, line):
    path = gcode_file(text)
    with pytest.raises(GcodeError, match="parameters and expressions are not supported") as err:
        read_gcode(path, dialect="linuxcnc")
    assert err.value.line == line


def test_a_program_number_is_no_o_word(gcode_file):
    tp = read_gcode(gcode_file("O1000 (part)\nG0 X0 Y0 Z0\nM3 S1\nG1 X5 F600\nM5\n"), strict=True)
    assert deposit_length(tp) == 5.0


# ---- item 5: programs that never give Z -------------------------------------------------------

def test_a_program_without_z_runs_at_the_plate(gcode_file):
    # A laser or plasma program: X and Y only (inch), no Z anywhere.
    path = gcode_file("G20 G90\nG0 X1 Y1\nM3 S1\nG1 X2 F10\nG3 X2 Y1 I-0.5 J0\nM5\n")
    tp = read_gcode(path, dialect="linuxcnc")
    assert deposit_length(tp) == pytest.approx(25.4 * (1 + math.pi))
    assert np.all(tp.start[:, 2] == 0.0) and list(tp.layer_z) == [0.0]
    np.testing.assert_array_equal(tp.start[0], [0.0, 0.0, 0.0])  # the rapid from the work origin is a row
    assert tp.meta["warnings"] == [f"{path}: the program never gives Z: its moves are taken at Z = 0 (0, no --plate "
                                   "given), from X0 Y0; give --start X,Y,Z if the tool stands elsewhere"]
    on_plate = read_gcode(path, dialect="linuxcnc", plate_z=3.0)
    assert np.all(on_plate.start[:, 2] == 3.0) and "Z = 3 (the plate's (--plate))" in on_plate.meta["warnings"][0]


# ---- item 6: a G91 program from an unknown start ----------------------------------------------

G91_WALL = "G91\nM3 S1\nG1 X10 F600\nG1 Y10\nG1 Z1\nG1 X-10\nM5\n"


def test_relative_program_from_an_unknown_start_names_the_cause(gcode_file):
    from dmdvox import checks

    path = gcode_file(G91_WALL)
    tp = read_gcode(path, dialect="linuxcnc")
    assert len(tp) == 0
    assert any("4 relative (G91) moves start from a position the program never gives" in w and "--start X,Y,Z" in w
               for w in tp.meta["warnings"])
    assert "--start X,Y,Z" in checks._nothing_deposited(tp) and "--dialect" not in checks._nothing_deposited(tp)
    placed = read_gcode(path, dialect="linuxcnc", start=(5.0, 5.0, 1.0))
    assert deposit_length(placed) == 31.0 and placed.meta["warnings"] == []
    np.testing.assert_array_equal(placed.end[-1], [5.0, 15.0, 2.0])


def test_start_option_on_the_command_line_and_in_a_cell_file(gcode_file, tmp_path, capsys):
    import json

    from dmdvox.cli import main
    from dmdvox.limits import read_cell

    path = gcode_file(G91_WALL)
    assert main(["info", str(path), "--dialect", "linuxcnc", "--start", "5,5,1", "--json"]) == 0
    assert json.loads(capsys.readouterr().out)["deposit_length_mm"] == 31.0
    assert main(["info", str(path), "--dialect", "linuxcnc", "--start", "-5,5,1", "--json"]) == 0
    assert json.loads(capsys.readouterr().out)["deposit_length_mm"] == 31.0
    cell = tmp_path / "cell.toml"
    cell.write_text("[limits]\nporosity_percent = 5\n[process]\nstart = [5, 5, 1]\n")
    assert read_cell(cell).options["start"] == (5.0, 5.0, 1.0)
    cell.write_text("[limits]\nporosity_percent = 5\n[process]\nstart = 5\n")
    with pytest.raises(DmdvoxError, match=r"\[process\] start must be \[x, y, z\] in mm"):
        read_cell(cell)
    with pytest.raises(SystemExit) as bad:  # argparse refuses it: exit 2, naming the option
        main(["info", str(path), "--start", "5,5", "--json"])
    assert bad.value.code == 2 and "argument --start: expected X,Y,Z" in capsys.readouterr().err


# ---- item 7: E words that do not mean what the file's mode says -------------------------------

def test_stripped_e_resets_are_said(gcode_file):
    # Ten layers of five 10 mm moves whose absolute E restarts each layer without a G92 E0 (a
    # post-processor took them out): only the first layer feeds material.
    lines = ["M82", "G90 G1 X0 Y0 Z0.2 F600"]
    for k in range(10):
        lines += [f"G1 Z{0.2 * (k + 1):.1f}"] + [f"G1 X{10 * ((j + 1) % 2)} E{0.5 * (j + 1)}" for j in range(5)]
    tp = read_gcode(gcode_file("\n".join(lines) + "\n"))
    assert deposit_length(tp) == 50.0
    total = 50.0 + 9 * (0.2 + 40.0)  # each later layer: its Z step, and four moves (the first is where it stands)
    assert [w for w in tp.meta["warnings"] if "only" in w] == [
        f"{tp.source}: its E words feed material on only {100 * 50 / total:.0f} % of the path (50.0 of {total:.1f} mm); "
        "the rest is read as travel. If a post-processor stripped the E resets (G92 E0), or E is relative without an "
        "M83, the deposit is wrong: check the file's E words"]


KIRI = "G90\nG1 X0 Y0 Z0.2 F600\n" + "".join(f"G1 X{10 * ((j + 1) % 2)} E{(0.5, 0.5, 0.3)[j % 3]}\n" for j in range(30))


def test_relative_e_without_m83_is_read_as_relative_and_said(gcode_file):
    # Kiri:Moto writes increments and no M83 (the printer is set to relative E): read as absolute
    # E rises on a third of the words and falls on a third, and nothing deposits.
    path = gcode_file(KIRI)
    tp = read_gcode(path)
    assert deposit_length(tp) == 300.0
    assert [w for w in tp.meta["warnings"] if "relative" in w] == [
        f"{path}: the file sets no E mode (no M82 or M83) and, read as absolute, E falls on 33 % of its 30 E words and "
        "rises on only 33 %: they are increments (relative E): E is read as relative; add M83 at its start to say so "
        "(or M82 if it really is absolute)"]
    with pytest.raises(Exception, match="--strict refuses to guess: add M83"):
        read_gcode(path, strict=True)
    said_absolute = read_gcode(gcode_file("M82\n" + KIRI))
    assert deposit_length(said_absolute) < 300.0
    assert any("yet the file says M82" in w for w in said_absolute.meta["warnings"])


def test_g90_keeps_the_e_mode_of_m83(gcode_file):
    # Marlin ("G90 ... unless overridden by M83") and Klipper: G90 sets the axes absolute, M83's
    # relative E stays; G91 makes E relative too until G90.
    tp = read_gcode(gcode_file("M83\nG90\nG1 X0 Y0 Z0.2 F600\nG1 X10 E1\nG1 X20 E1\nM82\nG91\nG1 X10 E1\nG90\n"
                               "G1 X40 E1.5\n"))
    # both M83 moves deposit (E 0 -> 1 -> 2), the G91 one (E 2 -> 3), not the G90 one after M82 (3 -> 1.5)
    assert deposit_length(tp) == 30.0


def test_analog_output_e_is_no_extrusion_on_motion_lines(gcode_file):
    # LinuxCNC's laser vector test: M67 E2 Q.. on the motion line sets analog output 2 along it.
    tp = read_gcode(gcode_file("G90 G0 X0 Y0 Z0\nM3 S1\nG1 X3 F600 M67 E2 Q50\nG1 X7 M67 E2 Q0\nM5\n"))
    assert tp.dialect != "reprap" and deposit_length(tp) == 7.0


def test_a_plunge_with_the_beam_on_is_no_layer(gcode_file):
    # The Mach3 plasma program pierces with the torch on (G01 Z0.06 after M03), then cuts at that
    # height: one layer, as in the reference reader (layers are deposit moves that stay at one Z).
    tp = read_gcode(gcode_file("G90 G0 X0 Y0 Z5\nM3 S1\nG1 Z1 F600\nG1 X10\nG1 Y10\nM5\n"), dialect="linuxcnc")
    assert deposit_length(tp) == 24.0 and list(tp.layer_z) == [1.0]
    np.testing.assert_array_equal(tp.layer, [0, 0, 0])


def test_remapped_tcp_codes_get_a_hint(gcode_file):
    path = gcode_file("M429\nG0 X0 Y0 Z0 A0 C0\nM428 ;TCP:xyzac\nM3 S600\nG1 X10 F600\nM429\nM5\n")
    said = [w for w in read_gcode(path, dialect="linuxcnc").meta["warnings"] if "M428" in w]
    assert len(said) == 1 and said[0].startswith(f"{path}:1: M429: ") and "G43.4" in said[0]


def test_study_sweep_reads_with_the_start(gcode_file):
    from dmdvox.process.plan import ProcessSettings
    from dmdvox.study.sweep import SweepCase

    case = SweepCase(gcode=str(gcode_file(G91_WALL)), dialect="linuxcnc", strict=False, laser_on=None,
                     laser_off=None, machine="none", settings=ProcessSettings(), voxel=None, until=None, cad=None,
                     cad_offset=(0.0, 0.0, 0.0), max_memory=None, start=(5.0, 5.0, 1.0))
    tp = case.plan().toolpath
    assert deposit_length(tp) == 31.0


# ---- G28 from a known place is a trip: PrusaSlicer's end G-code homes X across the bed ---------

def test_homing_from_a_known_place_is_a_travel_at_the_modal_feed(gcode_file):
    # PrusaSlicer's estimator times `G28 X0` as a G1 to X0 at the modal feed (here the retract's
    # 2400 mm/min); before, the tool arrived at 0 in no time and waam_prusa_10_layers.gcode
    # came out 8.3 s (12.6 %) short of the slicer's estimate.
    tp = read_gcode(gcode_file("G21\nG90\nM82\nG28\nG1 Z1 F600\nG1 X30 Y40 F6000\n"
                               "G1 X60 E5 F1200\nG1 E3 F2400\nG28 X0\n"), dialect="reprap")
    home = tp.line == 9
    assert home.sum() == 1
    assert not tp.deposit[home].any() and tp.kind[home][0] == 0
    np.testing.assert_allclose(tp.start[home][0], [60, 40, 1])
    np.testing.assert_allclose(tp.end[home][0], [0, 40, 1])
    assert tp.feed[home][0] == pytest.approx(2400 / 60)
    assert tp.t_end[home][0] - tp.t_start[home][0] == pytest.approx(60 / 40)
    # the first G28, from nowhere known, is no row
    assert tp.line.min() == 5


def test_homing_with_the_beam_on_deposits_nothing(gcode_file):
    tp = read_gcode(gcode_file("G21\nG90\nG0 X0 Y0 Z0\nM3 S1000\nG1 X20 F600\nG28\n"), dialect="linuxcnc")
    home = tp.line == 6
    assert home.sum() == 1 and not tp.deposit[home].any()
    assert deposit_length(tp) == pytest.approx(20.0)
    np.testing.assert_allclose(tp.end[home][0], [0, 0, 0])


# ---- M3 S1000 plus E words (issue 22, "Tracebacks"): exit 2 naming the line, or a right answer ---

TINY_E_MOVE = "G90 G1 X0 Y0 Z0 F600\nM3 S1000\nG1 X0.000001 E1\n"


def _simulate(path, tmp_path, *args):
    import contextlib
    import io
    import json

    from dmdvox.cli import main

    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        code = main(["simulate", str(path), *args, "--out", str(tmp_path / "out"), "--json"])
    return code, json.loads(out.getvalue()), err.getvalue()


@pytest.mark.parametrize("dialect", ["auto", "reprap"])
def test_e_on_a_vanishing_move_is_refused_naming_its_line(gcode_file, tmp_path, dialect):
    # 2.4 mm^3 on a 1 um move implied a bead 2.4e6 mm wide; the landing grid then asked for
    # 1 PiB and the run ended in a MemoryError traceback (exit 1)
    code, out, err = _simulate(gcode_file(TINY_E_MOVE), tmp_path, "--dialect", dialect)
    assert code == 2, err
    assert "Traceback" not in err
    assert ".gcode:3: " in out["error"] and "--width" in out["error"] and "1e-06 mm move" in out["error"]


def test_e_on_a_vanishing_move_with_a_width_keeps_its_material(gcode_file, tmp_path):
    # with the melt-pool width given the drop is laid where the tool stood, all of it:
    # 1 mm of 1.75 mm filament (the diameter assumed, and warned)
    code, out, err = _simulate(gcode_file(TINY_E_MOVE), tmp_path, "--width", "2.5", "--voxel", "0.25")
    assert code == 0, err
    assert out["deposited_volume_mm3"] == pytest.approx(math.pi * 1.75**2 / 4, rel=1e-9)
    assert out["lost_volume_mm3"] == 0.0


@pytest.mark.parametrize("dialect", ["auto", "reprap", "linuxcnc", "grbl"])
def test_m3_s1000_with_e_words_never_ends_in_a_traceback(gcode_file, tmp_path, dialect):
    code, out, err = _simulate(gcode_file("G90 G1 X0 Y0 Z0 F600\nM3 S1000\nG1 X10 E1\n"), tmp_path,
                               "--dialect", dialect)
    assert code == 0, err
    if out["flow_source"] == "e":  # E words meter the material: 1 mm of 1.75 mm filament, all laid
        assert out["deposited_volume_mm3"] == pytest.approx(math.pi * 1.75**2 / 4, rel=1e-9)
    # --laser-power is a heat option: without --thermal it is refused by name, not ignored
    code, out, err = _simulate(gcode_file("G90 G1 X0 Y0 Z0 F600\nM3 S1000\nG1 X10 E1\n"), tmp_path,
                               "--dialect", dialect, "--laser-power", "1000")
    assert code == 2 and "--laser-power" in out["error"] and "--thermal" in out["error"]


def test_implied_widths_hold_the_material_or_are_refused(tmp_path):
    # fuzz-like: any move length and E word under M3 S0/S1/S1000, in the dialects that read E
    from hypothesis import given, settings
    from hypothesis import strategies as st

    from dmdvox.errors import ParameterError
    from dmdvox.process.plan import (DEFAULT_WIDTH_MM, MAX_IMPLIED_WIDTH_LAYERS, ProcessSettings, _layer_height,
                                     plan_process)

    path = tmp_path / "fuzz.gcode"

    @settings(max_examples=60, deadline=None)
    @given(length=st.floats(1e-9, 50.0), e=st.floats(-3.0, 3.0), s=st.sampled_from([0, 1, 1000]),
           dialect=st.sampled_from(["auto", "reprap"]))
    def check(length, e, s, dialect):
        path.write_text(f"G90 G1 X0 Y0 Z0.5 F600\nM3 S{s}\nG1 X{length:.9f} E{e:.6f}\n"
                        f"G1 X{length + 10:.9f} E{e + 1:.6f}\n")
        tp = read_gcode(path, dialect=dialect)
        try:
            plan = plan_process(tp, ProcessSettings(model="flow"))
        except ParameterError as err:  # a refusal names the line, or says the program meters nothing
            assert ("layer heights" in str(err) and ".gcode:3: " in str(err)) or "says nothing about its material" \
                in str(err), err
            return
        tp = plan.toolpath
        dep = tp.deposit & (tp.length > 0) & (plan.flow.volume > 0)
        layer = _layer_height(tp, DEFAULT_WIDTH_MM)
        w = plan.sections.width[dep]
        assert np.all(w <= MAX_IMPLIED_WIDTH_LAYERS * layer * (1 + 1e-12))
        # the width is what the material fills at the layer height (rect: A = w h)
        np.testing.assert_allclose(w * layer * tp.length[dep], plan.flow.volume[dep], rtol=1e-9)

    check()
