"""Fuzzing the input readers: G-code (``read_gcode``) and meshes (``read_stl``, ``load_cad``).

Whatever the bytes, a reader either returns a well-formed result or raises a ``DmdvoxError``
whose message names the file (and, for G-code, the line at fault); never another exception.
The runs are derandomized (the same cases every time). ``DMDVOX_FUZZ_SCALE=20`` multiplies
every test's case count for a long run (docs/FUZZING.md).
"""

import json
import math
import os
import struct
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from dmdvox import cli
from dmdvox.comparison.compare import load_cad
from dmdvox.errors import DmdvoxError, GcodeError
from dmdvox.io.mesh import MAX_COORDINATE_MM, read_stl
from dmdvox.toolpath import read_gcode
from dmdvox.toolpath.dialects import DIALECT_NAMES
from dmdvox.toolpath.model import ARC_CCW, ARC_CW, RAPID

from .conftest import DATA, REPO

SCALE = float(os.environ.get("DMDVOX_FUZZ_SCALE", "1"))
# No deadline: a wall-clock limit fails on a loaded machine (cases stalled over a second with two
# cores shared four ways) and passes a slow reader on a fast one. Work that once grew without
# bound (turns, chords) is held by counts in its own tests.
DEADLINE = None


def fuzz_settings(examples: int):
    return settings(max_examples=max(1, int(examples * SCALE)), deadline=DEADLINE, derandomize=True,
                    database=None, suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])


@pytest.fixture(scope="module")
def work(tmp_path_factory) -> Path:
    """One folder for the module's generated files (hypothesis cannot use per-test ``tmp_path``)."""
    return tmp_path_factory.mktemp("fuzz")


def put(work: Path, data: bytes, name: str) -> Path:
    path = work / name
    path.write_bytes(data)
    return path


# -- checks -------------------------------------------------------------------------------------

def check_gcode(path: Path, data: bytes, **options):
    """Read ``path``; check the toolpath, or that the error names the file (and a real line)."""
    try:
        tp = read_gcode(path, **options)
    except GcodeError as exc:
        lines = data.count(b"\n") + 1
        assert 1 <= exc.line <= lines, (exc.line, lines)
        assert str(exc).startswith(f"{path}:{exc.line}: ")
        assert exc.reason
        return None
    except DmdvoxError as exc:
        assert str(exc).startswith(f"{path}: "), str(exc)
        return None
    check_toolpath(tp, path, data)
    return tp


def check_toolpath(tp, path: Path, data: bytes) -> None:
    n = len(tp)
    for name, shape, dtype in (("start", (n, 3), np.float64), ("end", (n, 3), np.float64),
                               ("deposit", (n,), np.bool_), ("kind", (n,), np.uint8), ("feed", (n,), np.float32),
                               ("power", (n,), np.float32), ("t_start", (n,), np.float64),
                               ("t_end", (n,), np.float64), ("line", (n,), np.int32), ("layer", (n,), np.int32),
                               ("rotary", (n, 3), np.float32)):
        a = getattr(tp, name)
        assert a.shape == shape and a.dtype == dtype, (name, a.shape, a.dtype)
    for name in ("start", "end", "feed", "t_start", "t_end", "rotary", "layer_z"):
        assert np.all(np.isfinite(getattr(tp, name))), name
    # power is NaN until a word gives it (the Toolpath docstring), and then finite
    assert np.all(np.isfinite(tp.power[~np.isnan(tp.power)])), "power"
    assert tp.meta["lines"] == data.count(b"\n") + (not data.endswith(b"\n"))
    if n:
        assert tp.t_start[0] >= 0.0
        assert np.all(tp.t_end >= tp.t_start)
        assert np.all(tp.t_start[1:] >= tp.t_end[:-1])
        assert np.all(np.diff(tp.line) >= 0) and tp.line[0] >= 1 and tp.line[-1] <= tp.meta["lines"]
        assert np.all(tp.feed >= 0.0)
        assert set(np.unique(tp.kind)) <= {0, 1, 2, 3}
        assert not np.any(tp.deposit & (tp.kind == RAPID))
    assert math.isfinite(tp.duration) and tp.duration >= (tp.t_end[-1] if n else 0.0)
    assert np.all(np.diff(tp.layer_z) > 0)
    assert np.all((tp.layer >= -1) & (tp.layer < len(tp.layer_z)))
    assert np.all(tp.layer[tp.deposit] >= 0)
    arcs = tp.arcs
    m = len(arcs)
    assert arcs.centre.shape == (m, 3) and arcs.sweep.shape == (m,) and arcs.length.shape == (m,)
    assert np.all((arcs.segment >= 0) & (arcs.segment < n))
    assert np.all(np.isin(tp.kind[arcs.segment], (ARC_CW, ARC_CCW)))
    assert np.count_nonzero(tp.kind >= ARC_CW) == m
    for name in ("centre", "sweep", "r_start", "r_end", "length"):
        assert np.all(np.isfinite(getattr(arcs, name))), name
    assert np.all(arcs.length >= 0) and np.all(arcs.r_start >= 0) and np.all(arcs.r_end >= 0)
    assert np.all(np.isfinite(tp.length)) and np.all(tp.length >= 0)
    assert np.all(np.isfinite(tp.deposit_bbox()))
    for warning in tp.meta["warnings"]:
        assert warning.startswith(f"{path}:")


def check_mesh(path: Path, reader):
    try:
        result = reader(path)
    except DmdvoxError as exc:
        assert str(exc).startswith(f"{path}: "), str(exc)
        return None
    vertices, triangles = result[0], result[1]
    assert vertices.ndim == 2 and vertices.shape[1] == 3 and vertices.dtype == np.float64
    assert triangles.ndim == 2 and triangles.shape[1] == 3 and triangles.dtype == np.int64
    assert triangles.shape[0] >= 1
    assert np.all(np.abs(vertices) <= MAX_COORDINATE_MM)
    assert triangles.min() >= 0 and triangles.max() < vertices.shape[0]
    if reader is load_cad:
        assert all(w.startswith(f"{path}: ") for w in result[2])
    return result


# -- G-code strategies --------------------------------------------------------------------------

CASE = st.sampled_from((str.upper, str.lower))
NUMBER = st.one_of(
    st.integers(-100_000, 100_000).map(str),
    st.floats(-1e4, 1e4, allow_nan=False).map(lambda v: f"{v:.4f}"),
    st.floats(-1e9, 1e9, allow_nan=False).map(lambda v: f"{v:.0f}"),
    st.sampled_from(["", "-", "+", ".", "-.", "+.5", "- 3", " 7", "nan", "NaN", "inf", "-inf", "Infinity",
                     "1e400", "1e5", "1E-3", "9" * 400, "0." + "0" * 30 + "1", "0." + "0" * 320 + "1", "1" * 25, "123456789.123456789",
                     "-0", "0", "1.2.3", "0x10", "99999999", "10000001", "1,5", "3.", ".25", "+-1"]),
)
G_CODES = st.sampled_from([f"G{g}" for g in (0, 1, 2, 3, 4, 10, 17, 18, 19, 20, 21, 28, 38.2, 40, 53, 54, 61, 64,
                                                80, 90, 90.1, 91, 91.1, 92, 92.1, 93, 94, 95, 99, -1, 1000)]
                          + [f"G0{g}" for g in range(4)] + ["G", "G1.5"])
M_CODES = st.sampled_from([f"M{m}" for m in (0, 2, 3, 4, 5, 30, 62, 63, 64, 65, 82, 83, 101, 102, 103, 104, 106,
                                                107, 108, 109, 140, 190, -3, 99999)])
LETTER_WORD = st.builds(lambda letter, number: letter + number,
                        st.sampled_from(list("XYZIJKREFSPNABCTQDHLOUVW")), NUMBER)
WORD = st.one_of(G_CODES, M_CODES, LETTER_WORD, LETTER_WORD)
SEPARATOR = st.sampled_from(["", " ", " ", "  ", "\t", " \t "])
DECORATION = st.sampled_from(["", "", "", "(comment)", "(unterminated", "; comment", "(nested (x))", "*",
                              "*12", "*abc", "%", "/", "N10 ", "n7 ", "12 34 ", "\x00", "\x7f", "é", "\ufeff",
                              ")", "((", "G1 ; X10"])
ENDING = st.sampled_from(["\n", "\n", "\n", "\r\n", "\r", ""])


@st.composite
def soup_line(draw):
    words = draw(st.lists(WORD, max_size=8))
    sep = draw(SEPARATOR)
    text = draw(CASE)(draw(DECORATION) + sep.join(words) + draw(DECORATION))
    if draw(st.integers(0, 9)) == 0:  # a RepRap checksum, right or wrong
        checksum = 0
        for byte in text.encode("utf-8"):
            checksum ^= byte
        text += f"*{checksum if draw(st.booleans()) else checksum ^ 1}"
    return text + draw(ENDING)


# Most lines need a known position to become rows; a prefix gives one (or not) and a laser.
SOUP_PREFIX = st.sampled_from(["", "G28\n", "G28\nM65\n", "G1 X0 Y0 Z0\nM3 S100\n", "G92\nM64 P8\n"])
soup_program = st.builds(lambda prefix, lines: (prefix + "".join(lines)).encode("utf-8"),
                         SOUP_PREFIX, st.lists(soup_line(), min_size=1, max_size=30))
dialect_options = st.sampled_from(DIALECT_NAMES).map(
    lambda d: {"dialect": d, **({"laser_on": "M65,M101", "laser_off": "M64"} if d == "custom" else {})})

# Structurally valid programs: moves with sensible numbers, in every dialect's vocabulary.
coord = st.floats(-300, 300, allow_nan=False).map(lambda v: f"{v:.3f}")
small = st.floats(0.01, 50, allow_nan=False).map(lambda v: f"{v:.3f}")
valid_line = st.one_of(
    st.builds(lambda g, x, y, z: f"{g} X{x} Y{y} Z{z}", st.sampled_from(["G0", "G1", "G01", ""]), coord, coord, coord),
    st.builds(lambda g, x, y, f: f"{g} X{x} Y{y} F{f}", st.sampled_from(["G1", "G0"]), coord, coord,
              st.integers(1, 20000)),
    st.builds(lambda g, x, y, i, j: f"{g} X{x} Y{y} I{i} J{j}", st.sampled_from(["G2", "G3"]), coord, coord,
              small, small),
    st.builds(lambda g, x, y, r: f"{g} X{x} Y{y} R{r}", st.sampled_from(["G2", "G3"]), coord, coord, small),
    st.builds(lambda g, i, p: f"{g} I{i} P{p}", st.sampled_from(["G2", "G3"]), small, st.integers(1, 4)),
    st.builds(lambda x, e: f"G1 X{x} E{e}", coord, small),
    st.builds(lambda e: f"G1 E-{e}", small),
    st.builds(lambda p: f"G4 P{p}", st.integers(0, 2000)),
    st.sampled_from(["G17", "G18", "G19", "G20", "G21", "G90", "G91", "G90.1", "G91.1", "G92 X0 Y0 Z0", "G92 E0",
                     "G92", "G28", "G28 X", "G94", "M82", "M83", "M3 S1000", "M4 S500", "M5", "S0", "S800",
                     "M62 P1", "M63 P1", "M64 P8", "M65 P8", "M64 P9", "M64", "M65", "M101", "M102", "M103",
                     "M108", "M64 P2", "M65 P2", "T1", "M104 S200", "; layer", "(note)"]),
    st.builds(lambda f, x: f"G93 G1 X{x} F{f}\nG94", st.integers(1, 600), coord),
)
valid_program = st.lists(valid_line, min_size=1, max_size=40).map(
    lambda lines: ("G21 G90 G1 X0 Y0 Z0 F1200\n" + "\n".join(lines) + "\n").encode("ascii"))


# -- G-code tests -------------------------------------------------------------------------------

@fuzz_settings(2500)
@given(st.binary(min_size=1, max_size=3000), st.booleans())
def test_gcode_random_bytes(work, data, strict):
    check_gcode(put(work, data, "bytes.gcode"), data, strict=strict)


@fuzz_settings(3500)
@given(soup_program, dialect_options, st.booleans())
def test_gcode_token_soup(work, data, options, strict):
    check_gcode(put(work, data, "soup.gcode"), data, strict=strict, **options)


@fuzz_settings(2000)
@given(valid_program, dialect_options, st.booleans())
def test_gcode_valid_programs(work, data, options, strict):
    tp = check_gcode(put(work, data, "valid.gcode"), data, strict=strict, **options)
    if not strict:
        # A text program never fails as a whole when lenient: bad lines become warnings.
        assert tp is not None


# -- mesh strategies and tests ------------------------------------------------------------------

STL_RECORD = np.dtype([("normal", "<f4", (3,)), ("v", "<f4", (3, 3)), ("attr", "<u2")])
finite32 = st.floats(-1e6, 1e6, width=32, allow_nan=False)
any32 = st.one_of(finite32, finite32, st.floats(width=32))


@st.composite
def binary_stl(draw):
    m = draw(st.integers(0, 12))
    values = draw(st.lists(any32, min_size=9 * m, max_size=9 * m))
    body = b"".join(struct.pack("<3f", 0, 0, 1) + struct.pack("<9f", *values[9 * i:9 * i + 9]) + b"\0\0"
                    for i in range(m))
    header = draw(st.sampled_from([b"binary", b"solid part", b"  solid", b""])).ljust(80, b" ")
    count = draw(st.one_of(st.just(m), st.integers(0, 2**32 - 1), st.integers(max(0, m - 2), m + 2)))
    data = header + struct.pack("<I", count) + body
    cut = draw(st.one_of(st.just(len(data)), st.integers(0, len(data))))
    return data[:cut] + draw(st.sampled_from([b"", b"", b"\0", b"junk"]))


STL_TOKEN = st.sampled_from(["nan", "inf", "-inf", "1e400", "-1e400", "abc", "-", "", "1_0", "0x10", "1.5.2",
                             "facet", "vertex", "endloop", "\x00", "é", "1e-400", "3", "-2.5"])


@st.composite
def ascii_stl(draw):
    m = draw(st.integers(0, 8))
    corners = draw(st.lists(st.floats(-1e3, 1e3, allow_nan=False), min_size=9 * m, max_size=9 * m))
    lines = ["solid part"]
    for i in range(m):
        lines += ["facet normal 0 0 1", " outer loop"]
        lines += [f"  vertex {corners[9 * i + 3 * k]!r} {corners[9 * i + 3 * k + 1]!r} {corners[9 * i + 3 * k + 2]!r}"
                  for k in range(3)]
        lines += [" endloop", "endfacet"]
    lines.append("endsolid part")
    tokens = "\n".join(lines).split(" ")
    for _ in range(draw(st.integers(0, 4))):
        if tokens:
            tokens[draw(st.integers(0, len(tokens) - 1))] = draw(STL_TOKEN)
    text = draw(st.sampled_from([" ", "  ", "\t"])).join(tokens)
    text = draw(st.sampled_from([str, str, str.upper]))(text)
    data = text.encode("utf-8")
    cut = draw(st.one_of(st.just(len(data)), st.integers(0, len(data))))
    return data[:cut]


@pytest.mark.parametrize("reader", [read_stl, load_cad], ids=["read_stl", "load_cad"])
@fuzz_settings(400)
@given(data=st.binary(max_size=600))
def test_mesh_random_bytes(work, reader, data):
    check_mesh(put(work, data, "bytes.stl"), reader)


@pytest.mark.parametrize("reader", [read_stl, load_cad], ids=["read_stl", "load_cad"])
@fuzz_settings(700)
@given(data=binary_stl())
def test_mesh_binary_stl(work, reader, data):
    result = check_mesh(put(work, data, "binary.stl"), reader)
    m = struct.unpack("<I", data[80:84])[0] if len(data) >= 84 else None
    if reader is read_stl and m is not None and len(data) == 84 + 50 * m:
        # A size that matches its count is read as binary: every triangle kept, unless some
        # corner is not finite or beyond the coordinate range.
        corners = np.frombuffer(data, STL_RECORD, m, 84)["v"].astype(np.float64)
        assert (result is not None) == (m > 0 and bool(np.all(np.abs(corners) <= MAX_COORDINATE_MM)))
        if result is not None:
            assert result[1].shape[0] == m


@pytest.mark.parametrize("reader", [read_stl, load_cad], ids=["read_stl", "load_cad"])
@fuzz_settings(700)
@given(data=ascii_stl())
def test_mesh_ascii_stl(work, reader, data):
    check_mesh(put(work, data, "ascii.stl"), reader)


# -- a few through the command line ------------------------------------------------------------

SOUP = (b"G1 X0 Y0 Z0\nM65\nG1 X1e400 Y-\nG2 X5 R0.1 P-3\n(unterminated\nG1 X10 *99\ng-1.5 x1\nG4 P-500\n"
        b"G1 X2\n")


@pytest.mark.parametrize("argv, content, message", [
    (["info", "--json"], bytes(range(256)) * 8, "binary data"),
    (["info", "--json", "--strict"], SOUP, ":3: word Y has no number"),
    (["simulate", "--json", "--strict"], b"G1 X0 Y0 Z0\nM65\nG1 X" + b"9" * 400 + b"\n", ":3: word X is not a finite"),
    (["info", "--json", "--dialect", "reprap"], b"\n\n \t \n", "empty file"),
])
def test_cli_in_process_bad_gcode(tmp_path, capsys, argv, content, message):
    path = tmp_path / "fuzz.gcode"
    path.write_bytes(content)
    code = cli.main([argv[0], str(path), *argv[1:]])
    out, err = capsys.readouterr()
    assert code == 2
    assert f"dmdvox: error: {path}" in err and message in err and "Traceback" not in err
    assert json.loads(out)["exit_code"] == 2 and str(path) in json.loads(out)["error"]


def test_cli_in_process_lenient_soup(tmp_path, capsys):
    path = tmp_path / "soup.gcode"
    path.write_bytes(SOUP)
    assert cli.main(["info", str(path), "--json"]) == 0
    out, err = capsys.readouterr()
    info = json.loads(out)
    # Lines 3 to 8 are skipped (X1e400 is X1 and E400: no exponents in G-code); line 7's x1 is a
    # word of the unknown code g-1.5, which moves nothing (only G0-G3 do). Line 9 deposits from
    # X0 to X2.
    assert info["moves"] == 1 and info["deposit_length_mm"] == 2.0
    # 600 mm/min from rest to rest at the default 500 mm/s^2: L / v + v / a; the negative dwell is no time
    assert info["duration_s"] == pytest.approx(2.0 / 10.0 + 10.0 / 500.0)
    assert info["unknown_codes"] == ["G-1.5"]
    for line, message in ((3, "word Y has no number"), (4, "arc P (turns) must be a positive integer, got -3"),
                          (5, "comment '(' without ')'"), (6, "checksum *99 does not match the line"),
                          (8, "dwell of -0.5 s is negative; line skipped")):
        assert f"warning: {path}:{line}: {message}" in err
    assert f"{path}:7:" not in err


@pytest.mark.parametrize("content, message", [
    (b"\0" * 80 + struct.pack("<I", 3) + b"\0" * 100, "truncated or not an STL"),
    (b"solid x\n vertex 1 2 nan\n vertex 1 2 3\n vertex 0 0 0\nendsolid\n", "non-finite"),
    (b"solid x\n vertex 1 2 abc\n vertex 1 2 3\n vertex 0 0 0\nendsolid\n", "bad vertex coordinate"),
    (b"solid x\n vertex 1 1 1\n vertex 1 1 1\n vertex 1 1 1\nendsolid\n", "only degenerate"),
    # one flat facet: open, and 0 mm^3 from every corner of its box (was a ZeroDivisionError)
    (b"solid x\n vertex 0 0 0\n vertex 1 0 0\n vertex 0 1 0\nendsolid\n", "encloses no definite volume"),
])
def test_cli_in_process_bad_cad(tmp_path, capsys, content, message):
    cad = tmp_path / "fuzz.stl"
    cad.write_bytes(content)
    code = cli.main(["compare", str(DATA / "demo_block.gcode"), str(cad), "--voxel", "0.25", "--json"])
    out, err = capsys.readouterr()
    assert code == 2 and f"dmdvox: error: {cad}: " in err and message in err and "Traceback" not in err
    # the error is stderr's last line (the reader's dialect stage line may come before it)
    assert json.loads(out) == {"error": err.strip().splitlines()[-1].removeprefix("dmdvox: error: "),
                               "exit_code": 2}


def test_cli_subprocess_junk(tmp_path):
    gcode = tmp_path / "junk.gcode"
    gcode.write_bytes(SOUP)
    stl = tmp_path / "junk.stl"
    stl.write_bytes(b"solid " + bytes(range(256)) * 4)
    for argv, message in ((["info", gcode, "--strict"], f"{gcode}:3: word Y"),
                          (["compare", DATA / "demo_block.gcode", stl, "--voxel", "0.25"], f"{stl}: ")):
        proc = subprocess.run([sys.executable, "-m", "dmdvox.cli", *map(str, argv)], capture_output=True, text=True,
                              cwd=REPO, timeout=120)
        assert proc.returncode == 2, proc.stderr
        assert "Traceback" not in proc.stderr and message in proc.stderr


# -- what the fuzzing found ---------------------------------------------------------------------

def test_negative_dwell_is_refused(tmp_path):
    path = tmp_path / "dwell.gcode"
    path.write_bytes(b"G28\nM65\nG1 X10\nG4 P-5000\nG1 X20\n")
    tp = read_gcode(path, dialect="seed")  # G4 P in ms
    np.testing.assert_array_equal(tp.t_start, [0.0, 1.0])  # 10 mm at 600 mm/min: 1 s each, no dwell
    assert tp.meta["warnings"] == [f"{path}:4: dwell of -5 s is negative; line skipped"]
    with pytest.raises(GcodeError, match=r":4: dwell of -5 s is negative"):
        read_gcode(path, dialect="seed", strict=True)


def test_feed_too_small_for_finite_times_is_refused(tmp_path):
    path = tmp_path / "feed.gcode"
    tiny = "0." + "0" * 305 + "1"  # a long move over this feed once took infinitely long
    path.write_text(f"G28\nM65\nG1 X9999999 F{tiny}\nG1 X0\nG93 G1 X1 F{tiny}\n")
    tp = read_gcode(path, dialect="seed")
    np.testing.assert_allclose(tp.t_end, [9999999 / 10.0, 2 * 9999999 / 10.0])  # the default 600 mm/min
    assert tp.meta["warnings"] == [
        f"{path}:3: feed F1e-306 is below 1e-06 (corrupt number?); previous feed kept",
        f"{path}:5: G93 inverse-time move without a positive F word (at least 1e-06)",
        f"{path}:3: a move of 10000.0 m (over 10 m; 2 such moves): check the units (G20 inch, G21 mm) and the "
        "program's words"]


def test_arc_of_millions_of_turns_has_its_box_at_once(tmp_path, monkeypatch):
    from dmdvox.toolpath import geometry

    path = tmp_path / "turns.gcode"
    # A P word near the 1e7 limit once built 40 million extreme points for the box (9 s, 2 GB).
    path.write_bytes(b"G28\nM65\nG2 X0 Y0 I1 P9999999\n")
    evaluated = []
    arc_points = geometry.arc_points

    def counting(tp, arc, fractions):
        evaluated.append(np.size(fractions))
        return arc_points(tp, arc, fractions)

    monkeypatch.setattr(geometry, "arc_points", counting)
    box = read_gcode(path).deposit_bbox()
    # the extremes lie on the first or the last turn: four quarter angles from each end, and the
    # two ends, whatever the number of turns
    assert evaluated and sum(evaluated) <= 2 * 4 + 2
    np.testing.assert_allclose(box, [[0.0, -1.0, 0.0], [2.0, 1.0, 0.0]], atol=1e-9)


def test_box_of_a_many_turn_spiral(tmp_path):
    """Only the first and last turns can hold a spiral's extremes: the box equals the one through
    every turn's quarter points, and dense sampling."""
    from dmdvox.toolpath.geometry import arc_points

    path = tmp_path / "spiral.gcode"
    path.write_bytes(b"G28\nM65\nG2 X-0.5 Y0 Z3 I1 P50\n")  # radius 1 to 1.5 over 50 turns, rising
    tp = read_gcode(path)
    assert len(tp.arcs) == 1 and tp.arcs.r_end[0] == pytest.approx(1.5)
    box = tp.deposit_bbox()
    sweep = tp.arcs.sweep[0]  # clockwise from angle pi (the start is left of the centre)
    quarters = np.arange(np.ceil((np.pi + sweep) / (np.pi / 2)), np.floor(np.pi / (np.pi / 2)) + 1)
    every_turn = arc_points(tp, 0, np.concatenate([[0.0, 1.0], (quarters * np.pi / 2 - np.pi) / sweep]))
    assert len(quarters) > 190
    np.testing.assert_allclose(box, [every_turn.min(axis=0), every_turn.max(axis=0)], atol=1e-12)
    dense = arc_points(tp, 0, np.linspace(0.0, 1.0, 400_001))
    # A spiral's true extremes sit a little off the quarter points (radius changing): microns here.
    np.testing.assert_allclose(box, [dense.min(axis=0), dense.max(axis=0)], atol=1e-5)


# -- every option of every command, with random values ---------------------------------------------

FUZZ_PROGRAM = "G21 G90\nG0 X0 Y0 Z0\nM3 S1000\nG1 X4 Y0 F600\nG1 X4 Y3\nM5\n"
# output options: names inside the test's folder only (a random "/" must not write to the root)
OUTPUT_DESTS = {"out", "png", "csv", "plot", "junit"}
OUTPUT_VALUE = st.sampled_from(["o", "o.png", "o.csv", "o.xml", "o.txt", "sub/o.png", "missing/dir/o.xml", "",
                                "é.png", "x" * 300 + ".png", "prog.gcode", "o.PNG", "."])
FILE_VALUE = st.sampled_from(["prog.gcode", "part.stl", "cell.toml", "missing.stl", "missing.gcode", ".", "",
                              "empty.stl", "part.stl@1,2,3", "part.stl@-1,nan,0", "part.stl@", "none",
                              "cone:tip=4,top=20,length=25", "cone:tip=-1,top=2,length=3", "cone:",
                              "machine.toml", "scene.toml", "é"])
FILE_DESTS = {"gcode", "new", "cad", "machine", "nozzle", "fixture", "limits", "config"}
NASTY = st.sampled_from([
    "nan", "-nan", "inf", "-inf", "0", "-0", "-1", "-7.5", "1e308", "-1e308", "1e-300", "1e400", "3", "0.5", "0.25",
    "0.1", "2", "1000000", "abc", "", " ", "1,2,3", "-1,-2,-3", "1,2", "1,2,3,4", "nan,0,0", "1e9,0,0", "1,,2",
    "x", "é", "0x10", "1:2:0.5", "2:1:0.5", "0:0:0", "1:2:-1", "1:1e9:1e-9", "1:2", "0.8", "none",
    "gauss:eta0=0.5,focus=1,sigma=1", "gauss:eta0=nan,focus=1,sigma=1", "gauss:", "100x100", "0x0", "64x64",
    "99999x99999", "-5x5", "M3", "M3,M5", "M201 SDC>0", ",", "width=1:1.2:0.2", "voxel=0", "voxel=nan",
    "height=0.4", "nosuch=1", "width=", "=1", "tcp://127.0.0.1:1", "1e-9", "-1e-9", "12345678901234567890"])
FUZZ_VALUE = st.one_of(NASTY, NASTY, NASTY,
                       st.floats().map(repr), st.integers(-10**12, 10**12).map(str),
                       st.lists(st.floats(-1e3, 1e3).map(lambda v: f"{v:g}"), min_size=1, max_size=4).map(",".join),
                       st.text(st.characters(blacklist_characters="\x00", blacklist_categories=("Cs",)), max_size=6))
# the bead every run starts from (drawn options given after it override it): a tiny part, fast;
# the memory limit refuses at once a drawn voxel fine enough to take minutes (a 160 MB surface)
FUZZ_BEAD = ["--voxel", "0.25", "--width", "1", "--height", "0.5", "--max-memory", "0.05"]
# "view" and "scene" need a display and are refused at once here; "demo" runs the shipped samples
# (minutes), whatever its options
FUZZ_COMMANDS = ("info", "simulate", "compare", "render", "collide", "report", "check", "diff", "view", "scene",
                 "study overlap", "study sweep")


def _subparser(command: str):
    import argparse

    parser = cli.build_parser()
    for word in command.split():
        action = next(a for a in parser._actions if isinstance(a, argparse._SubParsersAction))
        parser = action.choices[word]
    return parser


FUZZ_OPTIONS = {command: [a for a in _subparser(command)._actions if a.option_strings and a.dest != "help"]
                for command in FUZZ_COMMANDS}
exercised: dict[tuple[str, str], int] = {}


@pytest.fixture(scope="module")
def cli_work(tmp_path_factory):
    """A folder with the files the options name, as the working folder; studies' tasks run in
    this process (their pool would start a fresh interpreter per run)."""
    from dmdvox import tasks
    from dmdvox.io.mesh import box_mesh, write_stl

    work = tmp_path_factory.mktemp("cli-fuzz")
    (work / "prog.gcode").write_text(FUZZ_PROGRAM)
    write_stl(work / "part.stl", *box_mesh((-0.5, -0.5, 0.0), (4.5, 3.5, 0.5)))
    (work / "empty.stl").write_bytes(b"")
    (work / "cell.toml").write_text("[limits]\nporosity_percent = 1\n")
    (work / "machine.toml").write_text("[machine]\nname = 'x'\n")
    (work / "scene.toml").write_text("voxel = 0.5\n")
    patch = pytest.MonkeyPatch()
    patch.chdir(work)
    patch.setattr(tasks, "_local", lambda func, params, processes: ((k, func(p)) for k, p in enumerate(params)))
    yield work
    patch.undo()


@st.composite
def fuzz_argv(draw, command: str, focus: str | None = None):
    parser = _subparser(command)
    argv = command.split()
    for action in parser._actions:
        if not action.option_strings and action.dest != "help":
            argv.append(draw(st.one_of(st.just({"gcode": "prog.gcode", "new": "prog.gcode", "cad": "part.stl",
                                                "config": "scene.toml"}.get(action.dest, "prog.gcode")),
                                       FILE_VALUE)))
    options = FUZZ_OPTIONS[command]
    names = {o for a in options for o in a.option_strings}
    argv += [word for pair in zip(FUZZ_BEAD[::2], FUZZ_BEAD[1::2]) if pair[0] in names for word in pair]
    required = {"--png": "o.png", "--out": "o", "--limits": "cell.toml", "--nozzle": "cone:tip=4,top=20,length=25",
                "--spacing": "0.8", "--width": "1"}
    argv += [word for name, value in required.items() if name in names for word in (name, value)]
    if command == "render":
        argv += ["--size", "64x64"]
    chosen = [a for a in options if a.option_strings[-1] == focus]
    for action in chosen + draw(st.lists(st.sampled_from(options), max_size=3 - len(chosen))):
        name = draw(st.sampled_from(action.option_strings))
        exercised[command, action.option_strings[-1]] = exercised.get((command, action.option_strings[-1]), 0) + 1
        if action.nargs == 0:
            argv.append(name)
            continue
        if action.dest in OUTPUT_DESTS:
            value = draw(OUTPUT_VALUE)
        elif action.dest in FILE_DESTS:
            value = draw(FILE_VALUE)
        elif action.choices is not None:
            value = draw(st.one_of(st.sampled_from(sorted(map(str, action.choices))), FUZZ_VALUE))
        else:
            value = draw(FUZZ_VALUE)
        argv += draw(st.sampled_from([[name, value], [f"{name}={value}"]]))
    return argv


def check_cli_run(argv, capsys):
    """``dmdvox ARGV`` in process: never exit 1 nor a traceback; with --json one JSON object."""
    try:
        code = cli.main(list(argv))
        parsed = True
    except SystemExit as exc:  # argparse: a refused option (2)
        code, parsed = exc.code, False
    out, err = capsys.readouterr()
    assert code in (0, 2, 3) and "Traceback" not in err, (argv, code, err[-3000:])
    if parsed and "--json" in argv and "--help" not in argv:
        result = json.loads(out)
        assert isinstance(result, dict) and (code == 0 or result.get("exit_code") == code or code == 3), (argv, out)


@pytest.mark.parametrize("command", FUZZ_COMMANDS)
def test_cli_options_at_random(cli_work, capsys, command):
    @fuzz_settings(6 if command == "report" else 20)
    @given(argv=fuzz_argv(command))
    def run(argv):
        check_cli_run(argv, capsys)

    run()


@pytest.mark.parametrize("command, option", [(c, a.option_strings[-1]) for c in FUZZ_COMMANDS
                                             for a in FUZZ_OPTIONS[c]])
def test_cli_each_option(cli_work, capsys, command, option):
    """Every option of every command in at least one run, with random others beside it."""
    drawn_before = exercised.get((command, option), 0)

    @fuzz_settings(1)
    @given(argv=fuzz_argv(command, option))
    def run(argv):
        check_cli_run(argv, capsys)

    run()
    # Checked in the same test so that it holds however pytest-xdist spreads the file.
    assert exercised.get((command, option), 0) > drawn_before, (command, option)
