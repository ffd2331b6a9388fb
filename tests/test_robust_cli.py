"""Options, cell files and meshes that once ended in a traceback (exit 1) or a confident wrong
number: each is now refused with exit 2 and a message naming the option, key or triangle
(issue 22, "Tracebacks" and "Doubtful requests"). Run in process (``cli.main``) to stay fast."""

import numpy as np
import pytest

from dmdvox import cli
from dmdvox.errors import InputWarning
from dmdvox.io.mesh import box_mesh

from .conftest import DATA

TINY = "G21 G90\nG0 X0 Y0 Z0\nM3 S1000\nG1 X5 Y0 F600\nG1 X5 Y5\nM5\n"


def run(capsys, *argv):
    """``dmdvox ARGV`` in this process: (exit code, stdout, stderr); argparse's refusals exit 2."""
    try:
        code = cli.main([str(a) for a in argv])
    except SystemExit as exc:
        code = exc.code
    out, err = capsys.readouterr()
    assert "Traceback" not in err, err
    return code, out, err


@pytest.fixture
def tiny(tmp_path):
    path = tmp_path / "tiny.gcode"
    path.write_text(TINY)
    return path


# -- item 1: exit 2 naming the option or key -----------------------------------------------------

@pytest.mark.parametrize("value", ["nan", "inf", "0", "-1", "-inf", "abc"])
def test_max_memory_must_be_positive_and_finite(capsys, tiny, value):
    code, _, err = run(capsys, "simulate", tiny, "--voxel", "0.25", f"--max-memory={value}")
    assert code == 2
    assert "--max-memory: must be a positive finite number of GiB" in err and f"'{value}'" in err


@pytest.mark.parametrize("command", [["simulate"], ["compare", DATA / "demo_block.stl"], ["report", "--out", "o"],
                                     ["diff", DATA / "demo_block.gcode"]])
def test_scheduler_address_is_checked_first(capsys, tiny, command):
    code, _, err = run(capsys, command[0], tiny, *command[1:], "--scheduler", "notanaddress")
    assert code == 2 and "--scheduler: expected a dask scheduler address" in err and "'notanaddress'" in err


@pytest.mark.parametrize("address, ok", [("tcp://10.0.0.5:8786", True), ("localhost:8786", True),
                                         ("tls://[::1]:8786", True), ("inproc://10.0.0.5/123/1", True),
                                         ("tcp://host", False), ("host:99999", False), ("tcp://:8786", False),
                                         ("http://host:80", False), ("", False)])
def test_scheduler_address_forms(address, ok):
    if ok:
        assert cli._scheduler(address) == address
    else:
        with pytest.raises(cli.argparse.ArgumentTypeError):
            cli._scheduler(address)


def test_study_overlap_scheduler_is_checked(capsys):
    code, _, err = run(capsys, "study", "overlap", "--width", "2", "--spacing", "1", "--scheduler", "x")
    assert code == 2 and "--scheduler" in err


@pytest.mark.parametrize("cell, message", [
    ("limits = 5\n", "limits must be a table ([limits] and its keys below), got 5"),
    ('process = "x"\n[limits]\nporosity_percent = 1\n', "process must be a table ([process] and its keys below)"),
    ("[limits]\nporosity_percent = 1\n[process]\nwidth = [2.5]\n", "[process] width must be a finite number, got [2.5]"),
    ("[limits]\nporosity_percent = 1\n[nozzle]\nplate = [0]\n", "[nozzle] plate must be a finite number, got [0]"),
    ("[limits]\nvoid_percent = 1\n[part]\ncad = 42\n", "[part] cad must be a string, got 42"),
    ("[limits]\nporosity_percent = 1\n[machine]\nfile = ['a']\n", "[machine] file must be a string, got ['a']"),
    ("[limits]\nporosity_percent = 1\n[process]\nstrict = 1\n", "[process] strict must be true or false, got 1"),
    ("[limits]\nporosity_percent = 1\n[process]\nprofile = 3\n", "[process] profile must be a string, got 3"),
    ("[limits]\nporosity_percent = 1\n[process]\nvoxel = nan\n", "[process] voxel must be a finite number, got nan"),
    ("[limits]\nporosity_percent = 1\n[process]\nwidth = true\n", "[process] width must be a finite number, got True"),
    ("[limits]\nporosity_percent = 1\n[process]\naccel = {a = 1}\n", "[process] accel must be a finite number"),
    ("[limits]\nporosity_percent = 1\n[nozzle]\nfixtures = [1, 2]\n", "[nozzle] fixtures must be a string or a list"),
    ("[limits]\nporosity_percent = 1\n[part]\ncad_offset = [1, 2, 'x']\n", "[part] cad_offset must be [x, y, z] in mm"),
    ("[limits]\nporosity_percent = 1\n[part]\ncad_offset = 3\n", "[part] cad_offset must be [x, y, z] in mm, got 3"),
    ("[limits]\nporosity_percent = 1\n[process]\nmax_memory = 0\n", "max_memory = 0: must be a positive finite"),
    ("[limits]\nporosity_percent = 1\n[process]\nmax_memory = -2.5\n", "max_memory = -2.5: must be a positive"),
])
def test_cell_file_types(capsys, tmp_path, tiny, cell, message):
    path = tmp_path / "cell.toml"
    path.write_text(cell)
    code, _, err = run(capsys, "check", tiny, "--limits", path, "--voxel", "0.25")
    assert code == 2 and f"dmdvox: error: {path}: " in err and message in err, err


def test_cell_file_of_the_right_types_reads(tmp_path):
    from dmdvox.limits import read_cell

    path = tmp_path / "cell.toml"
    path.write_text("[limits]\nporosity_percent = 1\n[part]\ncad = 'part.stl'\ncad_offset = [1, -2, 0.5]\n"
                    "[process]\nwidth = 2\nheight = 0.5\nstrict = false\nprofile = 'rect'\nmax_memory = 4\n"
                    "[nozzle]\nfixtures = 'clamp.stl@1,2,3'\nplate = -1\n")
    cell = read_cell(path)
    assert cell.options == {"cad": str(tmp_path / "part.stl"), "cad_offset": (1.0, -2.0, 0.5), "width": 2,
                            "height": 0.5, "strict": False, "profile": "rect", "max_memory": 4,
                            "fixture": [str(tmp_path / "clamp.stl") + "@1,2,3"], "plate": -1}


def _ascii_stl(vertices, triangles) -> str:
    facets = "".join("facet normal 0 0 0\n outer loop\n" + "".join(f"  vertex {x!r} {y!r} {z!r}\n"
                                                                    for x, y, z in vertices[t])
                     + " endloop\nendfacet\n" for t in triangles)
    return f"solid box\n{facets}endsolid box\n"


def test_stl_with_a_far_vertex_names_its_triangle(capsys, tmp_path):
    vertices, triangles = box_mesh((0, 0, 0), (20, 20, 6))
    corners = vertices[triangles].copy()
    corners[6, 2] = (1e30, 0.0, 6.0)  # the 7th triangle's last corner: once "only degenerate triangles"
    text = _ascii_stl(corners.reshape(-1, 3), [[3 * k, 3 * k + 1, 3 * k + 2] for k in range(12)])
    cad = tmp_path / "far.stl"
    cad.write_text(text)
    code, _, err = run(capsys, "compare", DATA / "demo_block.gcode", cad, "--voxel", "0.25")
    assert code == 2
    assert f"{cad}: triangle 7 (of 12) has a vertex coordinate 1e+30 mm, out of range" in err
    assert "degenerate" not in err


def test_stl_within_range_is_read(tmp_path):
    from dmdvox.io.mesh import MAX_COORDINATE_MM, read_stl

    vertices, triangles = box_mesh((0, 0, 0), (MAX_COORDINATE_MM, 1, 1))
    path = tmp_path / "long.stl"
    path.write_text(_ascii_stl(vertices, triangles))
    v, t = read_stl(path)
    assert v.max() == MAX_COORDINATE_MM and t.shape == (12, 3)


# -- item 2: a voxel that cannot resolve the bead ------------------------------------------------

@pytest.mark.parametrize("voxel", ["1e9", "10", "0.376"])
def test_voxel_coarser_than_half_the_bead_is_refused(capsys, voxel):
    # the demo's bead: 2.5 mm wide, 0.75 mm high (its layer step): half the height is 0.375 mm;
    # --voxel 1e9 once gave 5e26 mm^3, --voxel 10 2.2 times the volume
    code, out, err = run(capsys, "simulate", DATA / "demo_block.gcode", "--voxel", voxel, "--json")
    assert code == 2
    assert f"--voxel {float(voxel):g}: coarser than half the bead (rect 2.5 mm wide, 0.75 mm high)" in err
    assert "use --voxel 0.375 or finer (default 0.125)" in err


@pytest.mark.parametrize("width, height, largest", [(2.0, 1.0, 0.5), (0.8, 3.0, 0.4)])
def test_voxel_of_half_the_bead_is_accepted(capsys, tiny, width, height, largest):
    bead = ["--width", width, "--height", height]
    code, out, _ = run(capsys, "simulate", tiny, *bead, "--voxel", largest, "--json")
    assert code == 0 and cli.json.loads(out)["voxel_mm"] == largest
    code, _, err = run(capsys, "simulate", tiny, *bead, "--voxel", largest * 1.001)
    assert code == 2 and f"use --voxel {largest:g} or finer" in err


def test_voxel_of_a_cell_file_is_held_to_the_bead(capsys, tmp_path, tiny):
    cell = tmp_path / "cell.toml"
    cell.write_text("[limits]\nporosity_percent = 1\n[process]\nwidth = 2\nheight = 1\nvoxel = 0.6\n")
    code, _, err = run(capsys, "check", tiny, "--limits", cell)
    assert code == 2 and "--voxel 0.6: coarser than half the bead (rect 2 mm wide, 1 mm high)" in err



# -- item 3: a CAD part far off, an open mesh ---------------------------------------------------

def test_comparison_far_off_is_warned_with_the_offset(capsys):
    # the CAD box moved 19 mm in x still overlaps the deposit's by a millimetre: no "do not
    # overlap" warning, and 95 % void once passed silently
    code, out, err = run(capsys, "compare", DATA / "demo_block.gcode", DATA / "demo_block.stl", "--voxel", "0.25",
                         "--cad-offset", "19,0,0", "--json")
    result = cli.json.loads(out)
    assert code == 0 and result["void_percent"] > 90
    warning = next(w for w in result["warnings"] if "hardly coincide" in w)
    assert warning.startswith(f"{DATA / 'demo_block.stl'}: void {result['void_percent']:.1f} % and overbuild ")
    # the deposit spans x 0..20 (tracks 1.25..18.75 and half the 2.5 mm bead), the CAD 19..39
    assert "(x 19.00..39.00, y 0.00..20.00, z 0.00..6.00 mm) and the deposit (x 0.00..20.00," in warning
    assert warning.endswith("--cad-offset=0,0,0 centres it on the deposit in x and y and puts its bottom on the "
                            "deposit's")
    assert f"warning: {warning}" in err


def test_misalignment_threshold():
    from dmdvox import checks

    class Bead:
        width, height = 2.0, 1.0

    class Path:
        z_is_layer_top = False
        deposit = [True]

        def deposit_bbox(self):
            return [[0.0, 0.0, 0.0], [10.0, 10.0, 1.0]]

    lo, hi = (100.0, 0.0, 0.0), (112.0, 12.0, 2.0)
    with checks.collect_warnings() as said, pytest.warns(InputWarning):
        assert checks.warn_if_misaligned(Path(), Bead(), "p.stl", lo, hi, (0, 0, 0), 50.0, 10.0) is None
        assert checks.warn_if_misaligned(Path(), Bead(), "p.stl", lo, hi, (0, 0, 0), float("nan"), float("nan")) is None
        text = checks.warn_if_misaligned(Path(), Bead(), "p.stl", lo, hi, (1, 0, 0), 10.0, 50.1)
    # deposit box -1..11 in x and y (centre 5), CAD centres 106 and 6: -101 on top of the given 1, -1
    assert text.startswith("p.stl: void 10.0 % and overbuild 50.1 % of the CAD volume") and "--cad-offset=-100,-1,0" in text
    assert said == [text]


def _fine_box(lo, hi, n):
    """A closed box of 6 n^2 quads (12 n^2 triangles), facing outward."""
    lo, hi = np.asarray(lo, float), np.asarray(hi, float)
    index, triangles = {}, []

    def vertex(point):
        return index.setdefault(tuple(point), len(index))

    for k in range(3):
        u, v = (k + 1) % 3, (k + 2) % 3
        su, sv = np.linspace(lo[u], hi[u], n + 1), np.linspace(lo[v], hi[v], n + 1)
        for side, value in ((1, hi[k]), (-1, lo[k])):
            for i in range(n):
                for j in range(n):
                    quad = []
                    for a, b in ((i, j), (i + 1, j), (i + 1, j + 1), (i, j + 1)):
                        p = np.empty(3)
                        p[k], p[u], p[v] = value, su[a], sv[b]
                        quad.append(vertex(p))
                    if side < 0:
                        quad.reverse()
                    triangles += [[quad[0], quad[1], quad[2]], [quad[0], quad[2], quad[3]]]
    return np.array(list(index), float), np.array(triangles, np.int64)


def test_volume_of_an_open_mesh_from_its_box_corners():
    from dmdvox.comparison.compare import _volume_range

    vertices, triangles = box_mesh((0, 0, 0), (20, 20, 6))
    assert _volume_range(vertices, triangles) == pytest.approx((2400.0, 2400.0))
    # without its first triangle (half the bottom, 200 mm^2): seen from the centre the missing
    # cone (height 3) is 200 mm^3; from the box's corners the hole adds 0 to 400 mm^3
    assert _volume_range(vertices, triangles[1:]) == pytest.approx((2000.0, 2400.0))


def test_open_mesh_refused_and_a_small_hole_warned(capsys, tmp_path):
    from dmdvox.comparison.compare import load_cad
    from dmdvox.errors import InputFileError
    from dmdvox.io.mesh import write_stl

    vertices, triangles = box_mesh((0, 0, 0), (20, 20, 6))
    holed = tmp_path / "holed.stl"
    write_stl(holed, vertices, triangles[1:])
    with pytest.raises(InputFileError, match=r"holed.stl: the mesh is open \(3 edges not shared by exactly two "
                                             r"triangles: holes, or a truncated file\) and encloses no definite "
                                             r"volume \(from 2,000 to 2,400 mm\^3"):
        load_cad(holed)
    vertices, triangles = _fine_box((0, 0, 0), (20, 20, 6), 10)
    assert _volume_of(vertices, triangles) == pytest.approx(2400.0)
    fine = tmp_path / "fine.stl"
    # without a 2 x 0.6 / 2 mm^2 facet of the x = 20 face: its cone from the centre is 0.6 x 10 / 3 =
    # 2 mm^3, and from the corners the volume is 2,396 to 2,400 mm^3, a spread of 4 / 2,400
    write_stl(fine, vertices, triangles[1:])
    _, t, warnings = load_cad(fine)
    assert t.shape[0] == triangles.shape[0] - 1
    assert warnings == [f"{fine}: mesh is not watertight (3 edges not shared by exactly two triangles; its volume "
                        "holds to 0.17 %); inside/outside may be wrong near the holes"]


def _volume_of(vertices, triangles):
    c = vertices[triangles]
    return float(np.einsum("ij,ij->", c[:, 0], np.cross(c[:, 1], c[:, 2]))) / 6


# -- item 4: negative values of options --------------------------------------------------------

def _commands(parser, prefix=()):
    """(argv prefix with placeholder positionals, subparser) of every command."""
    import argparse

    for action in parser._actions:
        if isinstance(action, argparse._SubParsersAction):
            for name, sub in action.choices.items():
                yield from _commands(sub, (*prefix, name))
            return
    positionals = [a for a in parser._actions if not a.option_strings and a.dest != "help"]
    yield [*prefix, *(f"{a.dest}.x" for a in positionals)], parser


def parse(argv):
    parser = cli.build_parser()
    return parser.parse_args(cli.join_negative_values(parser, [str(a) for a in argv]))


@pytest.mark.parametrize("command", [["compare", "p.gcode", "p.stl"], ["report", "p.gcode", "--out", "o"],
                                     ["check", "p.gcode", "--limits", "c.toml"], ["diff", "p.gcode", "q.gcode"],
                                     ["study", "sweep", "p.gcode"]])
def test_cad_offset_with_a_negative_first_value(command):
    # argparse took "-101.6,-101.6,0" for an option: "expected one argument"
    assert parse([*command, "--cad-offset", "-101.6,-101.6,0"]).cad_offset == (-101.6, -101.6, 0.0)
    assert parse([*command, "--cad-offset", "-.5,2,-1e3"]).cad_offset == (-0.5, 2.0, -1000.0)


def test_negative_values_reach_the_option_types(capsys):
    args = parse(["simulate", "p.gcode", "--plate", "-2.5", "--until", "-1", "--standoff", "-3"])
    assert (args.plate, args.until, args.standoff) == (-2.5, -1.0, -3.0)
    code, _, err = run(capsys, "simulate", "p.gcode", "--max-memory", "-inf")
    assert code == 2 and "--max-memory: must be a positive finite number of GiB" in err
    # a flag stays a flag, a file named like a negative number after "--" stays a positional
    args = parse(["simulate", "--strict", "--", "-5.gcode"])
    assert args.strict and args.gcode == "-5.gcode"


def test_every_option_of_every_command_takes_a_negative_tuple(capsys):
    parser = cli.build_parser()
    checked = 0
    for prefix, sub in _commands(parser):
        for action in sub._actions:
            if not action.option_strings or action.nargs is not None:
                continue
            for value in ("-1.5,-2,0", "-7", "-inf"):
                try:
                    parser.parse_args(cli.join_negative_values(parser, [*prefix, action.option_strings[-1], value]))
                except SystemExit:
                    pass
                err = capsys.readouterr().err
                assert "expected one argument" not in err, (prefix, action.option_strings, value, err)
                checked += 1
    assert checked > 300


# -- item 5: check's JUnit report on bad input ----------------------------------------------------

@pytest.mark.parametrize("case", ["cell", "gcode", "voxel"])
def test_check_on_bad_input_writes_one_junit_error(capsys, tmp_path, tiny, case):
    from xml.etree import ElementTree

    cell = tmp_path / "cell.toml"
    cell.write_text("limits = 5\n" if case == "cell" else "[limits]\nporosity_percent = 1\n")
    gcode = tmp_path / "missing.gcode" if case == "gcode" else tiny
    extra = ["--voxel", "9", "--width", "2", "--height", "1"] if case == "voxel" else []
    report = tmp_path / "report.xml"
    code, out, err = run(capsys, "check", gcode, "--limits", cell, "--junit", report, *extra, "--json")
    assert code == 2
    message = cli.json.loads(out)["error"]
    assert f"dmdvox: error: {message}" in err
    suites = ElementTree.parse(report).getroot()
    assert (suites.tag, suites.get("tests"), suites.get("errors"), suites.get("failures")) == ("testsuites", "1", "1", "0")
    [suite] = suites
    assert (suite.get("tests"), suite.get("errors"), suite.get("failures")) == ("1", "1", "0")
    [testcase] = suite
    assert testcase.get("classname") == f"dmdvox.check.{gcode.stem}" and testcase.get("name") == "input"
    [error] = testcase
    assert error.tag == "error" and error.get("message") == message == error.text
    assert {"cell": "limits must be a table", "gcode": "missing.gcode", "voxel": "--voxel 9: coarser"}[case] in message


def test_check_that_runs_writes_no_error_case(capsys, tmp_path, tiny):
    from xml.etree import ElementTree

    cell = tmp_path / "cell.toml"
    cell.write_text("[limits]\nporosity_percent = 1\n")
    report = tmp_path / "report.xml"
    code, _, _ = run(capsys, "check", tiny, "--limits", cell, "--junit", report, "--voxel", "0.25")
    assert code == 0
    suites = ElementTree.parse(report).getroot()
    assert suites.get("tests") == "1" and suites.find(".//error") is None and suites.find(".//testcase").get(
        "name") == "porosity_percent"


# -- what the command-line fuzz found (tests/test_fuzz.py) ----------------------------------------

@pytest.mark.parametrize("command", [["compare", DATA / "demo_block.stl"], ["report", "--out", "o"],
                                     ["simulate"], ["study", "overlap", "--width", "1", "--spacing", "0.8"]])
def test_voxel_nan_is_refused(capsys, tiny, command):
    # compare and report once reached the memory estimate with it: int(nan), a traceback
    argv = [*command[:1], *([] if command[0] == "study" else [tiny]), *command[1:], "--voxel", "nan"]
    code, _, err = run(capsys, *argv)
    assert code == 2 and "--voxel: must be a positive finite length in mm (at least 1e-06), got 'nan'" in err


@pytest.mark.parametrize("command", [["simulate"], ["collide", "--nozzle", "cone:tip=4,top=20,length=25"]])
def test_voxel_below_a_nanometre_is_refused(capsys, tiny, command):
    # 3e-150 mm overflowed the memory estimate (OverflowError, a traceback)
    code, _, err = run(capsys, command[0], tiny, *command[1:], "--voxel", "3.127220352537384e-150")
    assert code == 2 and "--voxel: must be a positive finite length in mm (at least 1e-06)" in err


def test_output_file_that_is_a_folder_or_empty(capsys, tmp_path, tiny):
    folder = tmp_path / "o.png"
    folder.mkdir()
    # an existing folder: IsADirectoryError from the atomic rename, a traceback
    code, _, err = run(capsys, "render", tiny, "--voxel", "0.25", "--png", folder)
    assert code == 2 and f"--png {folder}: that is a folder; give the name of the file to write" in err
    # an empty name: Path('').with_suffix() in the message itself raised
    code, _, err = run(capsys, "study", "overlap", "--width", "1", "--spacing", "0.8", "--csv", "")
    assert code == 2 and "--csv : the table is written as CSV; give a file name ending in .csv (e.g. out.csv)" in err
