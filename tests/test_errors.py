"""Issue 24, "errors in the caller's words": the library's errors name its parameters (``voxel``,
``max_drop_mm``), the command line's its options (``--voxel``, ``--max-drop``), from one table."""

from __future__ import annotations

import ast
import dataclasses
import json
import pickle
import re

import pytest

import dmdvox
from dmdvox import cli
from dmdvox.errors import DmdvoxError, GcodeError, ParameterError, ResourceError
from dmdvox.process.flow import FlowSettings
from dmdvox.process.landing import LandingSettings
from dmdvox.process.planner import MotionSettings

from .conftest import DATA, REPO

DEMO = str(DATA / "demo_block.gcode")
TABLE = cli.OPTION_OF_PARAMETER


def run(argv, capsys) -> tuple[int, dict, str]:
    code = cli.main([str(a) for a in argv])
    out, err = capsys.readouterr()
    return code, json.loads(out), err


@pytest.mark.parametrize("call, parameter, start", [
    (lambda: dmdvox.simulate(DEMO, -1.0), "voxel", "voxel must be a positive number of mm, got -1.0"),
    (lambda: dmdvox.plan(DEMO, model="blob"), "model", "model: unknown bead model 'blob'; choose one of "),
    # was a TypeError: the error's parameter given positionally to DmdvoxError
    (lambda: dmdvox.plan(DEMO, profile="blob"), "profile", "profile: unknown bead profile 'blob'; choose one of "),
    (lambda: dmdvox.plan(DEMO, profile="rect", width=-2.0, height=1.0, model="fixed"), "width",
     "width must be a positive finite length in mm, got -2.0"),
    (lambda: dmdvox.plan(DEMO, landing=LandingSettings(max_drop_mm=-1.0)), "max_drop_mm",
     "max_drop_mm must be a positive distance in mm, got -1.0"),
    (lambda: dmdvox.plan(DEMO, flow=FlowSettings(powder_rate_g_min=10.0)), "density_g_cm3",
     "powder_rate_g_min and density_g_cm3 go together"),
    (lambda: dmdvox.plan(DEMO, motion=MotionSettings(accel_mm_s2=-5.0)), "accel_mm_s2",
     "accel_mm_s2: -5 is not >= 0; give an acceleration"),
    (lambda: dmdvox.collide(DEMO, "cone:tip=4,top=20,length=25", clearance=-1.0), "clearance",
     "clearance must be a non-negative number of mm, got -1"),
], ids=["voxel", "model", "profile", "width", "max_drop", "powder", "accel", "clearance"])
def test_the_library_names_its_parameters(call, parameter, start):
    with pytest.raises(ParameterError) as caught:
        call()
    assert caught.value.parameter == parameter
    assert str(caught.value).startswith(start)
    assert "--" not in str(caught.value)  # no option of the command line in a library message


@pytest.mark.parametrize("argv, message", [
    (["simulate", DEMO, "--accel", "-5"], "--accel: -5 is not >= 0; give an acceleration"),
    (["simulate", DEMO, "--max-drop", "-1"], "--max-drop must be a positive distance in mm, got -1.0"),
    (["simulate", DEMO, "--powder-rate", "10"], "--powder-rate and --density go together"),
    (["simulate", DEMO, "--voxel", "2"], "--voxel 2: coarser than half the bead (rect 2.5 mm wide, 0.75 mm high), "
                                         "which it cannot resolve; use --voxel 0.375 or finer"),
    (["collide", DEMO, "--nozzle", "cone:tip=4,top=20,length=25", "--clearance=-1"],
     "--clearance must be a non-negative number of mm, got -1"),
], ids=["accel", "max-drop", "powder", "coarse-voxel", "clearance"])
def test_the_command_line_names_its_options(argv, message, capsys):
    code, result, err = run([*argv, "--json"], capsys)
    assert code == 2 and result == {"error": result["error"], "exit_code": 2}
    assert result["error"].startswith(message), result["error"]
    assert f"\ndmdvox: error: {message}" in f"\n{err}" and "Traceback" not in err
    assert "{" not in result["error"]  # every parameter the message names was worded


def test_a_refusal_on_memory_names_both_ways(capsys):
    with pytest.raises(ResourceError) as caught:
        dmdvox.simulate(DEMO, 0.001, max_memory_gib=0.01)
    assert caught.value.parameter == "voxel" and str(caught.value).startswith("voxel 0.001: ")
    assert "or larger (or raise max_memory_gib)" in str(caught.value)
    code, result, _ = run(["simulate", DEMO, "--voxel", "0.001", "--max-memory", "0.01", "--json"], capsys)
    assert code == 2 and result["error"].startswith("--voxel 0.001: ") and result["error"].endswith(
        "or larger (or raise --max-memory)")


def test_the_helix_refusal_words_the_budget_both_ways(tmp_path, capsys):
    """The budget's phrase names max_memory_gib as a parameter: every refusal that quotes it
    words it (the helix check once printed '{max_memory_gib} allows')."""
    path = tmp_path / "helix.gcode"
    path.write_text("G28\nM65\nG2 X0 Y0 Z5 I1 P9999999\n")
    with pytest.raises(ResourceError) as caught:
        dmdvox.simulate(dmdvox.read_gcode(path, dialect="seed"), 0.5, max_memory_gib=0.001)
    message = str(caught.value)
    assert "{" not in message and "but max_memory_gib allows 0.001 GiB" in message
    assert message.endswith("(or raise max_memory_gib)")
    code, result, _ = run(["simulate", path, "--dialect", "seed", "--voxel", "0.5", "--max-memory", "0.001",
                           "--json"], capsys)
    assert code == 2 and "but --max-memory allows 0.001 GiB" in result["error"]
    assert result["error"].endswith("(or raise --max-memory)")


def test_the_parameter_travels_with_the_error():
    error = ParameterError("{voxel} 0.5 is too coarse; use {voxel} 0.25", "voxel")
    assert str(error) == "voxel 0.5 is too coarse; use voxel 0.25"
    assert error.worded({"voxel": "--voxel"}) == "--voxel 0.5 is too coarse; use --voxel 0.25"
    back = pickle.loads(pickle.dumps(error))  # raised on a dask worker, read by the caller
    assert type(back) is ParameterError and back.parameter == "voxel" and str(back) == str(error)
    assert back.worded(TABLE) == error.worded(TABLE)
    gcode = pickle.loads(pickle.dumps(GcodeError("a.gcode", 3, "word X has no number")))
    assert (gcode.path, gcode.line, str(gcode)) == ("a.gcode", 3, "a.gcode:3: word X has no number")
    wrapped = error.prefixed("{nozzle} cone: ", also=("nozzle",))
    assert wrapped.worded(TABLE) == "--nozzle cone: --voxel 0.5 is too coarse; use --voxel 0.25"
    plain = DmdvoxError("a {brace} that names no parameter")
    assert str(plain) == plain.worded(TABLE) == "a {brace} that names no parameter"


def _named_in_the_source() -> set[str]:
    """Every parameter the package's errors name: ``{name}`` in a message's text, and the names
    given as ``parameter``/``also`` or to the validating helpers (``_positive(value, "name", ...)``)."""
    names = set()
    for path in sorted((REPO / "dmdvox").rglob("*.py")):
        tree = ast.parse(path.read_text(), str(path))
        for node in ast.walk(tree):
            if not isinstance(node, ast.Call):
                continue
            func = node.func.attr if isinstance(node.func, ast.Attribute) else getattr(node.func, "id", "")
            if func not in ("ParameterError", "ResourceError", "DmdvoxError", "prefixed", "_positive", "_positive_mm",
                            "_in_range", "_axes", "_finite_number"):
                continue
            texts = [c.value for a in node.args[:1] for c in ast.walk(a) if isinstance(c, ast.Constant)
                     and isinstance(c.value, str)]
            if func in ("ParameterError", "ResourceError", "DmdvoxError", "prefixed"):
                names |= {m for t in texts for m in re.findall(r"\{([a-z_][a-z0-9_]*)\}", t)}
            constants = [a.value for a in node.args[0 if func.startswith("_") else 1:] if isinstance(a, ast.Constant) and isinstance(a.value, str)]
            for keyword in node.keywords:
                if keyword.arg in ("parameter", "also"):
                    constants += [c.value for c in ast.walk(keyword.value) if isinstance(c, ast.Constant)]
            names |= {c for c in constants if re.fullmatch(r"[a-z_][a-z0-9_]*", c)}
    return names - {"mm", "g/min", "g/cm^3", "mm/min"}  # the helpers' unit arguments


def test_one_table_holds_every_parameter_and_only_real_options():
    named = _named_in_the_source()
    assert {"voxel", "model", "max_drop_mm", "accel_mm_s2", "clearance"} <= named  # the walk finds them
    assert named - set(TABLE) == set()
    parser = cli.build_parser()
    options = {o for sub in parser._subparsers._group_actions[0].choices.values() for a in sub._actions
               for o in a.option_strings}
    assert set(TABLE.values()) - options == set()


@pytest.mark.parametrize("settings", [FlowSettings, MotionSettings, LandingSettings])
def test_every_refused_setting_is_in_the_table(settings):
    for field in dataclasses.fields(settings):
        if field.type in ("bool", "GaussCatchment | None"):
            continue
        for bad in (-1.0, float("nan"), "x"):
            try:
                settings(**{field.name: bad}).validate()
            except ParameterError as exc:
                assert set(exc.parameters) <= set(TABLE), (field.name, exc.parameters)
            except (TypeError, ValueError):
                pass  # a comparison of a string: not a value this field takes
