"""`dmdvox check`: the demo cell's limits, judged; exit codes, JSON verdicts, JUnit XML."""

import json
from xml.etree import ElementTree

import pytest

from dmdvox.limits import LIMIT_FAILED, LIMITS
from dmdvox.cli import main

from .conftest import DATA, demo_void_percent

CELL = DATA / "cells" / "demo_cell.toml"
DEMO = str(DATA / "demo_block.gcode")


def run(capsys, *argv):
    code = main(list(argv))
    out = capsys.readouterr()
    return code, json.loads(out.out), out.err


def junit(path):
    """(testsuite element, {name: failure message or None}) of a JUnit XML file."""
    root = ElementTree.parse(path).getroot()
    suite = root.find("testsuite")
    cases = {}
    for case in suite.findall("testcase"):
        failure = case.find("failure")
        cases[case.get("name")] = None if failure is None else failure.get("message")
    return suite, cases


def test_demo_cell_fails_on_the_clamp(capsys, tmp_path):
    # The cell file's nozzle at 12.7 mm over the bead bottom meets the clamp (14 mm tall, 2.25 mm
    # from the first tracks' ends); every other limit holds.
    report = tmp_path / "report.xml"
    code, result, _ = run(capsys, "check", DEMO, "--limits", str(CELL), "--junit", str(report), "--json")
    assert code == LIMIT_FAILED == 3
    verdicts = {item["name"]: item for item in result["limits"]}
    assert [name for name, item in verdicts.items() if item["verdict"] == "fail"] == ["collisions", "min_clearance_mm"]
    assert result["passed"] is False and result["failed"] == 2
    # the colliding lines are those `dmdvox collide` finds on the same cell
    code, collide, _ = run(capsys, "collide", DEMO, "--nozzle", "cone:tip=8,top=40,length=30", "--fixture",
                           str(DATA / "demo_clamp.stl"), "--voxel", "0.375", "--width", "2.5", "--height", "0.75",
                           "--json")
    lines = sorted({c["line"] for c in collide["collisions"]})
    assert verdicts["collisions"]["lines"] == lines and verdicts["collisions"]["value"] == len(lines) > 0
    assert 6 in lines  # the plunge onto the first track, at (1.25, 1.25), beside the clamp
    assert set(lines) <= set(verdicts["min_clearance_mm"]["lines"])
    assert verdicts["void_percent"]["verdict"] == "pass"
    # at the cell's 0.375 mm voxel (the coarsest the 0.75 mm bead allows) the void's slivers, each
    # under a voxel wide, read 12 % low (0.505 %; 0.506 % at 0.25 mm)
    assert verdicts["void_percent"]["value"] == pytest.approx(demo_void_percent(), rel=0.15)
    suite, cases = junit(report)
    assert suite.get("tests") == "8" and suite.get("failures") == "2"
    assert set(cases) == set(verdicts)
    assert cases["collisions"].startswith(f"collisions = {len(lines)} > 0")
    assert cases["void_percent"] is None


def test_command_line_overrides_the_cell_and_the_limits_pass(capsys, tmp_path):
    # The nozzle raised to 40 mm above the bead bottom clears the 14 mm clamp by 26 mm.
    report = tmp_path / "report.xml"
    code, result, _ = run(capsys, "check", DEMO, "--limits", str(CELL), "--standoff", "40", "--junit", str(report),
                          "--json")
    assert code == 0
    assert result["passed"] is True and result["failed"] == 0
    assert all(item["verdict"] == "pass" and not item["lines"] and not item["layers"] for item in result["limits"])
    clearance = next(item for item in result["limits"] if item["name"] == "min_clearance_mm")
    assert clearance["value"] is None or clearance["value"] >= 0.5
    suite, cases = junit(report)
    assert suite.get("failures") == "0" and len(cases) == 8 and set(cases.values()) == {None}


def test_a_failing_limit_says_where(capsys, tmp_path):
    # The demo's void (0.57 % in closed form) against a 0.1 % limit: the layer of the worst void
    # is the one the comparison's per-layer table gives.
    limits = tmp_path / "tight.toml"
    limits.write_text("[limits]\nvoid_percent = 0.1\ndeviation_mm.p95 = 1.0\n")
    code, result, _ = run(capsys, "check", DEMO, "--limits", str(limits), "--cad", str(DATA / "demo_block.stl"),
                          "--voxel", "0.375", "--json")
    assert code == 3
    void = next(item for item in result["limits"] if item["name"] == "void_percent")
    assert void["verdict"] == "fail" and void["limit"] == 0.1 and void["kind"] == "max"
    code, compare, _ = run(capsys, "compare", DEMO, str(DATA / "demo_block.stl"), "--voxel", "0.375", "--json")
    worst = max(compare["layers"], key=lambda row: row["void_mm3"])["layer"]
    assert void["layers"] == [worst]
    assert void["value"] == pytest.approx(compare["void_percent"], rel=1e-9)
    p95 = next(item for item in result["limits"] if item["name"] == "deviation_mm.p95")
    assert p95["verdict"] == "pass" and p95["value"] == pytest.approx(compare["deviation_mm"]["p95"], rel=1e-9)


@pytest.mark.parametrize("text, argv, words", [
    ("[limits]\nvoid_percnt = 1\n", [], ["void_percnt", *LIMITS]),
    ("[limits]\nvoid_percent = 1\n", [], ["void_percent", "--cad"]),
    ("[limits]\ncollisions = 0\n", [], ["collisions", "--nozzle"]),
    ("[limits]\nmax_drift_mm = 0.1\n", [], ["max_drift_mm", "flow"]),
    ("[limits]\nvoid_percent = 'low'\n", ["--cad", str(DATA / "demo_block.stl")], ["void_percent", "number"]),
    ("[process]\nwidht = 2\n[limits]\nporosity_percent = 1\n", [], ["widht", "width"]),
    ("[process]\nwidth = 'wide'\n[limits]\nporosity_percent = 1\n", [], ["width", "wide"]),
    ("[process]\nprofile = 'square'\n[limits]\nporosity_percent = 1\n", [], ["profile", "rect"]),
    ("[limits]\n", [], ["no limit"]),
    ("[part]\ncad_offset = 'left'\n[limits]\nporosity_percent = 1\n", [], ["cad_offset", "[x, y, z]"]),
])
def test_bad_limits_are_refused(capsys, tmp_path, text, argv, words):
    limits = tmp_path / "limits.toml"
    limits.write_text(text)
    code, result, err = run(capsys, "check", DEMO, "--limits", str(limits), "--voxel", "0.375", *argv, "--json")
    assert code == 2 and result["exit_code"] == 2
    for word in words:
        assert word in result["error"]


def test_help_documents_exit_code_3(capsys):
    with pytest.raises(SystemExit):
        main(["check", "--help"])
    text = capsys.readouterr().out
    assert "3 a limit failed" in text and "[limits]" in text


def test_flow_limits_read_the_growth(capsys, tmp_path):
    # A sliced block under the flow model (E words): drift per layer and lost material as
    # `simulate --json` reports them; the layers whose |drift| exceeds the limit are named.
    gcode = str(DATA / "prusa_block_20.gcode")
    code, sim, _ = run(capsys, "simulate", gcode, "--voxel", "0.1", "--json")
    assert sim["model"] == "flow" and code == 0
    drifts = {row["layer"]: abs(row["drift_mm"]) for row in sim["layers"]}
    bound = sorted(drifts.values())[len(drifts) // 2]  # the median: some layers pass, some fail
    limits = tmp_path / "flow.toml"
    limits.write_text(f"[limits]\nmax_drift_mm = {bound!r}\nlost_volume_mm3 = 1.0\n")
    code, result, _ = run(capsys, "check", gcode, "--limits", str(limits), "--voxel", "0.1", "--json")
    assert code == 3
    drift, lost = result["limits"]
    assert drift["value"] == pytest.approx(max(drifts.values()), rel=1e-12) and drift["verdict"] == "fail"
    assert drift["layers"] == sorted(k for k, d in drifts.items() if d > bound) != []
    assert lost["value"] == sim["lost_volume_mm3"] and lost["verdict"] == "pass"
