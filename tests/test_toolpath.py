"""The G-code interpreter against hand-computed values, per dialect and per motion form."""

import hashlib
import json
import math
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from dmdvox.errors import DmdvoxError, GcodeError, InputFileError
from dmdvox.toolpath import read_gcode
from dmdvox.toolpath.geometry import linearized
from dmdvox.toolpath.model import ARC_CCW, ARC_CW, LINEAR, RAPID

from .conftest import DATA, REPO


def run_cli(*args, check_rc=None):
    proc = subprocess.run([sys.executable, "-m", "dmdvox.cli", *map(str, args)], capture_output=True, text=True,
                          cwd=REPO)
    if check_rc is not None:
        assert proc.returncode == check_rc, proc.stderr
    return proc


# ---- the seed ------------------------------------------------------------------------------

def test_seed_excerpt_columns_dwell_and_laser():
    tp = read_gcode(DATA / "seed_todcode_excerpt.gcode")
    assert tp.dialect == "seed"
    assert tp.meta["lines"] == 31
    # Line 5 positions the head (laser off, M64 on line 1); lines 8..31 deposit.
    assert len(tp) == 24 and tp.deposit.all()
    assert tp.line[0] == 8 and tp.line[-1] == 31
    np.testing.assert_allclose(tp.start[0], [8.4951, 0.135, 0.0])
    np.testing.assert_allclose(tp.end[0], [10.4263, 0.135, 0.0])
    # F750 mm/min; dwells G4P20000 and G4P50 are milliseconds in the Fadal dialect.
    np.testing.assert_allclose(tp.feed, 12.5)
    assert tp.t_start[0] == pytest.approx(20.05)
    pts = np.array([[8.4951, 0.135], [10.4263, 0.135], [12.6851, 1.4553], [6.8531, 1.385], [6.3717, 2.635],
                    [15.5004, 2.635]])
    expected = np.linalg.norm(np.diff(pts, axis=0), axis=1)
    np.testing.assert_allclose(tp.length[:5], expected)
    assert tp.duration == pytest.approx(20.05 + tp.length.sum() / 12.5)
    # The last line has no Z word: Z stays modal.
    np.testing.assert_allclose(tp.end[-1], [16.5385, 15.13, 0.0])


# ---- dialects ------------------------------------------------------------------------------

def test_seed_codes(gcode_file):
    tp = read_gcode(gcode_file("G90 G1 X0 Y0 Z0 F600\nM101\nG1 X10\nM102\nG1 X20\nM108\nG1 X30\nM64\nG1 X40\n"
                               "M103\nG1 X50\nM65\nG1 X60\n"), dialect="seed")
    assert tp.deposit.tolist() == [True, False, True, False, True, True]


def test_linuxcnc_spindle_and_io(gcode_file):
    text = ("G21 G90 G0 X0 Y0 Z0\nM3 S1000\nG1 X10 F600\nS0\nG1 X20\nS500\nG1 X30\nM5\nG1 X40\n"
            "M64 P2\nG1 X50\nM65 P2\nG1 X60\nM62 P1\nG4 P1\nG1 X70\nM63 P1\nG1 X80\n")
    tp = read_gcode(gcode_file(text), dialect="linuxcnc")
    # The G0 starts from an unknown position, so it positions the head without a row.
    assert tp.kind.tolist() == [LINEAR] * 8
    assert tp.deposit.tolist() == [True, False, True, False, True, False, True, False]
    # LinuxCNC dwell P is seconds; the G4 sits between the X60 and X70 rows.
    assert tp.t_start[6] - tp.t_end[5] == pytest.approx(1.0)
    np.testing.assert_allclose(tp.power[0:3], [1000, 0, 500])


def test_grbl_rapid_never_deposits(gcode_file):
    tp = read_gcode(gcode_file("G90 G0 X0 Y0 Z0\nM4 S800\nG0 X5\nG1 X10 F300\nS0\nG1 X15\nM5\nG1 X20\n"),
                    dialect="grbl")
    assert tp.kind.tolist() == [RAPID, LINEAR, LINEAR, LINEAR]
    assert tp.deposit.tolist() == [False, True, False, False]


def test_meltio_outputs(gcode_file):
    tp = read_gcode(gcode_file("G90 G1 X0 Y0 Z0 F600\nM64 P8\nG1 X10\nM65 P8\nG1 X20\nM64 P8\nG1 X30\n"
                               "M64 P9\nG1 X40\n"), dialect="meltio")
    assert tp.deposit.tolist() == [True, False, True, False]


def test_custom_dialect(gcode_file):
    path = gcode_file("G90 G1 X0 Y0 Z0 F600\nM200\nG1 X10\nM201\nG1 X20\n")
    tp = read_gcode(path, dialect="custom", laser_on="M200", laser_off="M201")
    assert tp.deposit.tolist() == [True, False]
    with pytest.raises(DmdvoxError, match="--laser-on"):
        read_gcode(path, dialect="custom", laser_on="Q5", laser_off="M201")
    with pytest.raises(DmdvoxError, match="needs both"):
        read_gcode(path, dialect="custom")


def test_unknown_dialect_is_a_clear_error(gcode_file):
    with pytest.raises(DmdvoxError, match="unknown dialect 'fanuc'"):
        read_gcode(gcode_file("G1 X1\n"), dialect="fanuc")


def test_reprap_absolute_e_with_retracts_and_g92(gcode_file):
    text = """M82
G90
G92 E0
G1 Z0.3 F1200
G1 X0 Y0
G1 X10 Y0 E1.0
G1 E0.2 F2400
G1 X20 Y0
G1 E1.0
G1 X20 Y10 E2.0
G92 E0
G1 X10 Y10 E0.5
"""
    tp = read_gcode(gcode_file(text))
    assert tp.dialect == "reprap" and tp.z_is_layer_top
    # Z0.3 and X0 Y0 only position the head (its start was unknown): no rows.
    assert tp.deposit.tolist() == [True, False, True, True]
    np.testing.assert_allclose(tp.start[0], [0, 0, 0.3])
    # Retract (0.8 of E at 40 mm/s) adds time without a row.
    gap = tp.t_start[1] - tp.t_end[0]
    assert gap == pytest.approx(0.8 / 40.0)
    assert tp.layer_z.tolist() == [0.3]


def test_reprap_relative_e(gcode_file):
    text = "G90\nM83\nG1 X0 Y0 Z0.2 F600\nG1 X5 E0.4\nG1 E-0.5\nG1 X10\nG1 E0.5\nG1 X15 E0.3\nG1 X20 E0\n"
    tp = read_gcode(gcode_file(text), dialect="reprap")
    assert tp.deposit.tolist() == [True, False, True, False]


def test_g0_runs_at_the_modal_feed_under_reprap_and_rapid_elsewhere(gcode_file):
    """Marlin moves G0 at F like G1 (Cura writes `G0 F600 ...` at layer changes); a CNC control
    rapids at its own rate whatever F says."""
    reprap = "M83\nG1 X0 Y0 Z0.3 F600\nG0 F600 X10\nG0 X20\nG1 X30 E1\n"
    tp = read_gcode(gcode_file(reprap), dialect="reprap")
    np.testing.assert_allclose(tp.t_end - tp.t_start, [1.0, 1.0, 1.0])  # 10 mm at 10 mm/s each
    # auto reads the file as the dialect it reports: G0 at F before the first E word too
    tp = read_gcode(gcode_file(reprap))
    assert tp.dialect == "reprap"
    np.testing.assert_allclose(tp.t_end - tp.t_start, [1.0, 1.0, 1.0])
    tp = read_gcode(gcode_file("M83\nG1 X0 Y0 Z0.3 F600\nG1 X5 E0.5\nG0 X15\n"))
    np.testing.assert_allclose(tp.t_end - tp.t_start, [0.5, 1.0])
    cnc = "G1 X0 Y0 Z0 F600\nG0 F600 X10\nM65\nG1 X20\n"
    tp = read_gcode(gcode_file(cnc), dialect="seed")
    np.testing.assert_allclose(tp.t_end - tp.t_start, [0.1, 1.0])  # the rapid at 6000 mm/min


def test_auto_tells_families_apart(gcode_file):
    assert read_gcode(gcode_file("G1 X0 Y0 Z0\nM65\nG1 X1\n")).dialect == "seed"
    assert read_gcode(gcode_file("G1 X0 Y0 Z0\nM64 P8\nG1 X1\n")).dialect == "meltio"
    assert read_gcode(gcode_file("G1 X0 Y0 Z0\nM3 S100\nG1 X1\n")).dialect == "linuxcnc"
    tp = read_gcode(gcode_file("G1 X0 Y0 Z0\nM64 P3\nG1 X1\nM65 P3\nG1 X2\n"))
    assert tp.deposit.tolist() == [True, False]


# ---- motion forms --------------------------------------------------------------------------

def test_units_relative_and_g92_offsets(gcode_file):
    text = "G20 G90\nG1 X0 Y0 Z0 F10\nG1 X1\nG91\nG1 X1 Y1\nG21 G90\nG92 X0 Y0\nG1 X10\n"
    tp = read_gcode(gcode_file(text))
    np.testing.assert_allclose(tp.end[0], [25.4, 0, 0])
    np.testing.assert_allclose(tp.end[1], [50.8, 25.4, 0])
    # G92 calls (50.8, 25.4) the origin, so X10 is machine X 60.8.
    np.testing.assert_allclose(tp.end[2], [60.8, 25.4, 0])
    # F10 in inch mode is 254 mm/min.
    assert tp.feed[0] == pytest.approx(254.0 / 60.0)


@pytest.mark.parametrize("plane, words, normal", [("G17", ("X", "Y", "I", "J"), 2), ("G18", ("Z", "X", "K", "I"), 1),
                                                  ("G19", ("Y", "Z", "J", "K"), 0)])
def test_quarter_arcs_in_every_plane(gcode_file, plane, words, normal):
    a, b, ia, ib = words
    # Start at (a=10, b=0) about the origin, quarter turn counter-clockwise to (a=0, b=10).
    text = f"{plane} G90 G1 X0 Y0 Z0 F600\nG1 {a}10\nG3 {a}0 {b}10 {ia}-10 {ib}0\n"
    tp = read_gcode(gcode_file(text))
    row = 1
    assert tp.kind[row] == ARC_CCW
    assert tp.length[row] == pytest.approx(10 * math.pi / 2, rel=1e-12)
    assert tp.arcs.normal_axis[0] == normal
    assert tp.arcs.sweep[0] == pytest.approx(math.pi / 2)
    mid = linearized(tp, 1e-4).end
    # Every chord end lies on the circle of radius 10 in the plane.
    axes = [i for i in range(3) if i != normal]
    on_arc = mid[np.abs(np.linalg.norm(mid[:, axes], axis=1) - 10) < 1e-9]
    assert len(on_arc) > 100


def test_cw_arc_r_form_both_branches(gcode_file):
    # Chord of 10 mm with R 5: half circle; R 7.0710678 (=5 sqrt 2): quarter (R>0) or three quarters (R<0).
    r = 5 * math.sqrt(2)
    tp = read_gcode(gcode_file(f"G90 G1 X0 Y0 Z0 F600\nG2 X10 Y0 R5\nG2 X0 Y0 R{r:.9f}\nG2 X10 Y0 R-{r:.9f}\n"))
    assert tp.kind.tolist() == [ARC_CW] * 3
    np.testing.assert_allclose(tp.length, [5 * math.pi, r * math.pi / 2, r * 3 * math.pi / 2], rtol=1e-6)
    # CW from (0,0) to (10,0) with R5 bulges to +Y (clockwise over the top).
    top = linearized(tp.select(np.array([True, False, False])), 1e-3).end
    assert top[:, 1].max() == pytest.approx(5.0, abs=1e-3)
    assert np.all(np.diff(tp.arcs.sweep) != 0) and np.all(tp.arcs.sweep < 0)


def test_full_circle_helix_and_turns(gcode_file):
    text = "G90 G17 G1 X10 Y0 Z0 F600\nG3 X10 Y0 I-10 J0\nG3 X10 Y0 Z6 I-10 J0 P3\n"
    tp = read_gcode(gcode_file(text))
    assert tp.length[0] == pytest.approx(2 * math.pi * 10, rel=1e-12)
    # A 3-turn helix rising 6 mm: length sqrt((3*2*pi*r)^2 + 6^2).
    assert tp.length[1] == pytest.approx(math.hypot(6 * math.pi * 10, 6.0), rel=1e-12)
    assert tp.arcs.sweep[1] == pytest.approx(6 * math.pi)
    pts = linearized(tp, 0.001)
    np.testing.assert_allclose(pts.length.sum(), tp.length.sum(), rtol=1e-4)


def test_absolute_arc_centres(gcode_file):
    tp = read_gcode(gcode_file("G90 G90.1 G1 X15 Y5 Z0 F600\nG3 X5 Y15 I5 J5\nG91.1\nG3 X-5 Y5 I-10 J0\n"))
    np.testing.assert_allclose(tp.arcs.centre[0, :2], [5, 5])
    np.testing.assert_allclose(tp.length[0], 10 * math.pi / 2)
    np.testing.assert_allclose(tp.arcs.centre[1, :2], [-5, 15])


def test_inverse_time_and_rapid_rate(gcode_file):
    tp = read_gcode(gcode_file("G90 G0 X0 Y0 Z0\nG0 X60\nG93 G1 X70 F30\nG94 G1 X80 F600\n"))
    assert tp.t_end[0] == pytest.approx(60 / 100.0)  # default rapid 6000 mm/min
    assert tp.t_end[1] - tp.t_start[1] == pytest.approx(2.0)  # F30 inverse time: 1/30 min
    assert tp.t_end[2] - tp.t_start[2] == pytest.approx(1.0)


def test_rotary_words_are_columns(gcode_file):
    tp = read_gcode(gcode_file("G90 G1 X0 Y0 Z0 A0 F600\nG1 X10 A90 B5\n"))
    np.testing.assert_allclose(tp.rotary[-1], [90, 5, 0])
    assert tp.meta["rotary_used"]


def test_layers_and_travel_rows(gcode_file):
    text = "G90 M83\nG1 X0 Y0 Z0.5 F600\nG1 X10 E1\nG1 Z1.0\nG1 X0 E1\nG1 Z1.5\nG1 X10 E1\n"
    tp = read_gcode(gcode_file(text))
    np.testing.assert_allclose(tp.layer_z, [0.5, 1.0, 1.5])
    assert tp.layer.tolist() == [0, 1, 1, 2, 2]
    assert tp.layer_step == pytest.approx(0.5)


def test_syntax_variants(gcode_file):
    text = "n10 g1x1.5y-2 z 0.25 f600*29\nN20 G1 X 2.5 (comment (x) Y 9) Y - 2 ; trailing\n% \n/G1 X3.5\n"
    tp = read_gcode(gcode_file(text))
    assert tp.meta["warnings"][0].endswith("checksum *29 does not match the line; line skipped")
    text_ok = "n10 g1x1.5y-2 z 0.25 f600\nN20 G1 X 2.5 (comment) Y - 2 ; trailing\n%\n/G1 X3.5\n"
    tp = read_gcode(gcode_file(text_ok))
    np.testing.assert_allclose(tp.end, [[2.5, -2, 0.25], [3.5, -2, 0.25]])


def test_valid_reprap_checksum(gcode_file):
    line = "N3 G1 X5 Y0 Z0"
    cs = 0
    for ch in line.encode():
        cs ^= ch
    tp = read_gcode(gcode_file(f"G1 X0 Y0 Z0\n{line}*{cs}\n"))
    assert len(tp) == 1 and not tp.meta["warnings"]


def test_unknown_codes_reported(gcode_file):
    tp = read_gcode(gcode_file("G90\nM104 S200\nG1 X0 Y0 Z0\nT1\nG54\nM104 S210\n"))
    assert tp.meta["unknown_codes"] == {"G54": 1, "M104": 2, "T": 1}


# Digit counts on both sides of the tokeniser's eight-bytes-at-a-time limits.
NUMBERS = ["0", "-0.5", ".5", "5.", "+3", "-  7.25", "1234567", "01234566", "001234565", "0.1234567", "0.12345678",
           "9999999.9999999", "1234567.12345678", "0000000000001.25", "100.000000000001"]


def test_numbers_parse_exactly(gcode_file):
    text = "G1 X-1 Y0 Z0\n" + "".join(f"G1 X{number}\n" for number in NUMBERS) + "; the end\n"
    tp = read_gcode(gcode_file(text))
    assert tp.end[:, 0].tolist() == [float(number.replace(" ", "")) for number in NUMBERS]


@pytest.mark.parametrize("number", NUMBERS)
def test_number_at_the_end_of_the_file(gcode_file, number):
    tp = read_gcode(gcode_file(f"G1 X-1 Y0 Z0\nG1 X{number}"))
    assert tp.end[:, 0].tolist() == [float(number.replace(" ", ""))]


# ---- bad input -----------------------------------------------------------------------------

def test_malformed_line_lenient_and_strict(gcode_file):
    path = gcode_file("G1 X0 Y0 Z0\nG1 X1 Yabc\nG1 X2\n")
    tp = read_gcode(path)
    assert len(tp) == 1 and tp.end[0, 0] == 2
    assert tp.meta["warnings"] == [f"{path}:2: word Y has no number"]
    with pytest.raises(GcodeError) as err:
        read_gcode(path, strict=True)
    assert str(err.value) == f"{path}:2: word Y has no number"


@pytest.mark.parametrize("text, message", [
    ("G1 X0 Y0 Z0\nG1 X" + "9" * 400 + "\n", "is not a finite number"),
    ("G1 X0 Y0 Z0\nG1 X1" + "0" * 12 + "\n", "beyond"),
    ("G1 X0 Y0 Z0\nG1 X1 X2\n", "appears twice"),
    ("G1 X0 Y0 Z0\nG2 X10 Y0 R2\n", "smaller than half the chord"),
    ("G1 X0 Y0 Z0\nG2 X10 Y0 I5.1 J0\n", "radii differ"),
    ("G1 X0 Y0 Z0\nG2 X10 Y0\n", "arc without a centre"),
    ("G1 X0 Y0 Z0\nG1 X1 Y1 \x01\n", "unexpected"),
])
def test_strict_errors(gcode_file, text, message):
    path = gcode_file(text)
    with pytest.raises(GcodeError, match=message) as err:
        read_gcode(path, strict=True)
    assert err.value.line == 2
    # Lenient: the same problem is a warning naming the line.
    assert any(w.startswith(f"{path}:2: ") for w in read_gcode(path).meta["warnings"])


def test_empty_binary_and_missing_files(tmp_path):
    empty = tmp_path / "empty.gcode"
    empty.write_bytes(b"")
    with pytest.raises(InputFileError, match="empty file"):
        read_gcode(empty)
    blank = tmp_path / "blank.gcode"
    blank.write_bytes(b"  \n\n \t\n")
    with pytest.raises(InputFileError, match="empty file"):
        read_gcode(blank)
    junk = tmp_path / "junk.gcode"
    junk.write_bytes(bytes(np.random.default_rng(1).integers(0, 256, 5000, dtype=np.uint8)))
    with pytest.raises(InputFileError, match="binary data"):
        read_gcode(junk)
    with pytest.raises(InputFileError, match="no such file"):
        read_gcode(tmp_path / "missing.gcode")


def test_cli_info_json_and_exit_codes(gcode_file, tmp_path):
    info = json.loads(run_cli("info", DATA / "seed_todcode_excerpt.gcode", "--json", check_rc=0).stdout)
    # the seed's file meters no material: its source and motion are said, no delivered volume
    assert set(info) == {"lines", "moves", "deposit_segments", "deposit_length_mm", "travel_length_mm", "layers",
                         "dialect", "bbox_mm", "duration_s", "unknown_codes", "warnings", "flow_source", "deposited_volume_mm3",
                         "motion", "dialect_evidence"}
    assert info["flow_source"] == "none" and info["deposited_volume_mm3"] == 0.0
    assert info["moves"] == 24 and info["layers"] == 1
    bad = gcode_file("G1 X0 Y0 Z0\nG1 Xnan\n")
    proc = run_cli("info", bad, "--strict", check_rc=2)
    assert proc.stderr.strip() == f"dmdvox: error: {bad}:2: word X has no number"
    assert "Traceback" not in proc.stderr
    proc = run_cli("info", tmp_path / "nope.gcode", "--json", check_rc=2)
    assert json.loads(proc.stdout)["exit_code"] == 2
    human = run_cli("info", DATA / "seed_todcode_excerpt.gcode", check_rc=0).stdout
    assert "deposit segments" in human and "24" in human


def test_info_summary_counts_arcs_exactly(gcode_file):
    from dmdvox.toolpath.summary import summarize

    # Laser on, a half circle of radius 5 bulging to +Y, then a travel.
    tp = read_gcode(gcode_file("G1 X0 Y0 Z1 F600\nM65\nG2 X10 Y0 I5 J0\nM64\nG1 X20\n"), dialect="seed")
    info = summarize(tp)
    assert info["deposit_length_mm"] == pytest.approx(5 * math.pi, rel=1e-12)
    assert info["travel_length_mm"] == pytest.approx(10.0)
    np.testing.assert_allclose(info["bbox_mm"], [[0, 0, 1], [10, 5, 1]], atol=1e-12)


# ---- large files: lines are tokenised in parallel, 64 KiB pieces at a time --------------------

def test_lines_across_piece_and_chunk_boundaries(gcode_file):
    lines = ["G90 G1 X0 Y0 Z0 F600"]
    rows = []  # (line, x, y) of each expected row
    for i in range(1, 120_000):
        if i % 9000 == 0:
            lines.append("(" + "a comment over several pieces " * 4000 + ")")
        elif i % 7000 == 0:
            lines.append("G1 X1 Yabc")
        elif i % 5000 == 0:
            lines.append("")
        else:
            lines.append(f"G1 X{i}.5 Y{i % 7}")
            rows.append((len(lines), i + 0.5, i % 7))
    path = gcode_file("\n".join(lines))  # no newline after the last line
    tp = read_gcode(path)
    line, x, y = np.array(rows).T
    assert tp.meta["lines"] == len(lines)
    assert tp.line.tolist() == line.tolist()
    assert tp.end[:, 0].tolist() == x.tolist() and tp.end[:, 1].tolist() == y.tolist()
    assert tp.meta["warnings"] == [f"{path}:{i + 1}: word Y has no number" for i in range(7000, 120_000, 7000)
                                   if i % 9000]


def test_same_result_for_any_thread_count(tmp_path):
    path = tmp_path / "big.gcode"
    xy = np.random.default_rng(3).uniform(0, 100, (80_000, 2))
    path.write_text("G90 G1 X0 Y0 Z0.3 F1200\nM83\n" + "".join(f"G1 X{x:.3f} Y{y:.3f} E0.05\n" for x, y in xy))
    script = ("import hashlib, sys; from dmdvox.toolpath import read_gcode; tp = read_gcode(sys.argv[1]); "
              "print(hashlib.sha256(b''.join(a.tobytes() for a in (tp.start, tp.end, tp.t_end, tp.line, tp.layer)))"
              ".hexdigest())")
    digests = {subprocess.run([sys.executable, "-c", script, str(path)], capture_output=True, text=True, check=True,
                              env={**os.environ, "NUMBA_NUM_THREADS": threads}).stdout
               for threads in ("1", "2")}
    tp = read_gcode(path)
    here = hashlib.sha256(b"".join(a.tobytes() for a in (tp.start, tp.end, tp.t_end, tp.line, tp.layer))).hexdigest()
    assert digests == {here + "\n"}


# ---- --strict refuses what the lenient reading drops or changes -----------------------------

@pytest.mark.parametrize("text, line, message", [
    # a deposit move before any absolute X, Y and Z: its material is not recorded (a program
    # that never gives Z is read on the plate instead: tests/test_reader_real.py)
    ("G90\nM65\nG1 X10 F600\nM64\nG1 Y0 Z1\n", 3, "unknown position"),
    # F0 and a negative feed keep the previous feed
    ("G90\nG1 X0 Y0 Z0 F600\nG1 X5 F0\n", 3, "not positive"),
    ("G90\nG1 X0 Y0 Z0 F600\nG1 X5 F-20\n", 3, "not positive"),
])
def test_strict_refuses_dropped_or_changed_data(gcode_file, text, line, message):
    path = gcode_file(text)
    lenient = read_gcode(path, dialect="seed")
    assert any(w.startswith(f"{path}:{line}: ") and message in w for w in lenient.meta["warnings"])
    with pytest.raises(GcodeError, match=message) as err:
        read_gcode(path, dialect="seed", strict=True)
    assert err.value.line == line


@pytest.mark.parametrize("dialect, code", [("seed", "M3 S500"), ("grbl", "M64"), ("meltio", "M101"),
                                           ("reprap", "M5"), ("linuxcnc", "M108")])
def test_strict_refuses_laser_codes_the_dialect_leaves_unexplained(gcode_file, dialect, code):
    path = gcode_file(f"G90\nG1 X0 Y0 Z0 F600\n{code}\nG1 X10\n")
    lenient = read_gcode(path, dialect=dialect)
    assert code.split()[0] in lenient.meta["unknown_codes"]
    with pytest.raises(GcodeError, match=f"{code.split()[0]} is a laser code that --dialect {dialect}") as err:
        read_gcode(path, dialect=dialect, strict=True)
    assert err.value.line == 3
    # auto explains every family: no error
    assert read_gcode(path, dialect="auto", strict=True).meta["unknown_codes"] == {}


def test_tool_centre_point_words_are_read_without_a_machine(gcode_file):
    # the words are program state in every dialect; a 3-axis machine has nothing to do with them
    text = "G90\nG43.4 H1\nM128\nTRAORI\n#TRAFO ON\nG1 X0 Y0 Z0 F600\nG1 X10\n#TRAFO OFF\nTRAFOOF\nM129\nG49\n"
    tp = read_gcode(gcode_file(text), strict=True)
    assert tp.meta["unknown_codes"] == {} and tp.meta["warnings"] == [] and len(tp) == 1
    # words that only begin like the '#' keywords stay errors; TRAORIX is a name like Klipper's
    # PRINT_START (an extended command), not the keyword
    for bad in ("#TRAFOON", "#TRAFO MAYBE", "#1=5"):
        with pytest.raises(GcodeError):
            read_gcode(gcode_file(f"G90\n{bad}\n"), strict=True)


def test_a_rotary_move_alone_is_a_timed_row_with_a_machine(gcode_file):
    # 3-axis (no machine): ignored as before, warned by the commands; with the trunnion: the tip
    # at X = 20 turns a quarter circle in its tip-feed time
    path = gcode_file("G90\nG1 X20 Y0 Z0 A0 C0 F600\nG1 C90\nG1 X30\n")
    flat = read_gcode(path)
    assert len(flat) == 1 and flat.meta["rotary_used"]
    five = read_gcode(path, machine=Path(__file__).resolve().parents[1] / "data/machines/trunnion-ac.toml")
    turn = five.line == 3
    assert turn.sum() > 1 and not five.meta["rotary_used"]
    length = np.linalg.norm(five.end[turn] - five.start[turn], axis=1).sum()
    assert length == pytest.approx(0.5 * np.pi * 20, rel=1e-4)
    assert five.t_end[turn][-1] - five.t_start[turn][0] == pytest.approx(length / 10.0)
    np.testing.assert_allclose(five.end[turn][-1], [0, 20, 0], atol=1e-9)
