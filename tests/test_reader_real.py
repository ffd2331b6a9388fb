"""What real programs hold that hand-made ones do not (issue 22, "Reader gaps"), each on a minimal
reproduction: firmware codes whose letters are parameters, free text, generators' habits, files
that never give Z or start in G91, compressed programs, the slicers' filament comments, E words
that do not mean what the file's mode says."""

from __future__ import annotations

import math

import numpy as np
import pytest

from dmdvox.errors import GcodeError
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
    tp = read_gcode(path, dialect="linuxcnc")
    assert float(np.abs(tp.end[:, :2]).max()) == 20.0
    assert deposit_length(tp) == 20.0  # X0-X10 at Z0 and X10-X20 at the probed Z-5
    probe = (tp.start[:, 2] == 0.0) & (tp.end[:, 2] == -5.0)
    assert probe.sum() == 1 and not tp.deposit[probe].any()
    assert tp.t_end[probe][0] - tp.t_start[probe][0] == pytest.approx(5.0)  # 5 mm at F60


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
