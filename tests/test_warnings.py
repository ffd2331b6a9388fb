"""Issue 24, "compute, then present": warnings are DmdvoxWarnings through Python's ``warnings``
module, collected per run (per command, per build) by ``checks.collect_warnings``."""

from __future__ import annotations

import json
import subprocess
import sys
import threading
import warnings

import pytest

import dmdvox
from dmdvox import checks, cli
from dmdvox.errors import DmdvoxWarning, InputWarning, PhysicsWarning

from .conftest import DATA, REPO

DEMO = str(DATA / "demo_block.gcode")
DEMO_CAD = str(DATA / "demo_block.stl")


def said_by_python(block) -> list[tuple[type, str]]:
    """What ``block()`` said through the warnings module, every occurrence."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        block()
    return [(w.category, str(w.message)) for w in caught]


def test_the_family():
    assert issubclass(InputWarning, DmdvoxWarning) and issubclass(PhysicsWarning, DmdvoxWarning)
    assert issubclass(DmdvoxWarning, UserWarning)
    assert dmdvox.DmdvoxWarning is DmdvoxWarning and dmdvox.InputWarning is InputWarning


def test_a_collection_keeps_its_own_and_nested_ones_reach_the_outer():
    def run():
        with checks.collect_warnings() as outer:
            checks.warn("a", InputWarning)
            with checks.collect_warnings() as inner:
                checks.warn("a", InputWarning)  # new to the inner list, already said by the outer run
                checks.warn("b", PhysicsWarning)
                checks.warn("b", PhysicsWarning)
                assert checks.collected() == ["a", "b"]  # the run's: the outermost list
            checks.warn("c")
        run.lists = outer, inner

    assert said_by_python(run) == [(InputWarning, "a"), (PhysicsWarning, "b"), (DmdvoxWarning, "c")]
    outer, inner = run.lists
    assert outer == ["a", "b", "c"] and inner == ["a", "b"]
    assert checks.collected() == []  # nothing is kept outside a collection


def test_outside_a_collection_python_decides(recwarn):
    warnings.simplefilter("always")
    checks.warn("x")
    checks.warn("x")
    assert [str(w.message) for w in recwarn] == ["x", "x"]
    warnings.simplefilter("ignore", DmdvoxWarning)  # what a notebook does to silence them
    checks.warn("y")
    assert [str(w.message) for w in recwarn] == ["x", "x"]


def test_threads_each_collect_their_own():
    both_inside = threading.Barrier(2)
    lists = {}

    def work(name):
        with checks.collect_warnings() as said:
            both_inside.wait()  # the two collections are open at once
            for i in range(50):
                checks.warn(f"{name} {i}")
            both_inside.wait()
        lists[name] = said

    with warnings.catch_warnings():
        warnings.simplefilter("ignore", DmdvoxWarning)
        threads = [threading.Thread(target=work, args=(n,)) for n in ("left", "right")]
        for t in threads:
            t.start()
        for t in threads:
            t.join()
    assert lists == {n: [f"{n} {i}" for i in range(50)] for n in ("left", "right")}


def test_two_api_calls_in_a_row_each_see_only_their_own():
    """The module-level list kept every warning since the process started: a second call saw the
    first one's, and only the CLI cleared it."""
    with pytest.warns(InputWarning, match="hardly coincide"):
        with checks.collect_warnings() as first:
            far = dmdvox.compare(DEMO, DEMO_CAD, 0.375, cad_offset=(19.0, 0.0, 0.0))
    with checks.collect_warnings() as second:
        near = dmdvox.compare(DEMO, DEMO_CAD, 0.375)
    assert [w for w in first if "hardly coincide" in w] == [w for w in far.to_json()["warnings"]
                                                              if "hardly coincide" in w]
    assert len([w for w in first if "hardly coincide" in w]) == 1
    assert second == [] and near.to_json()["warnings"] == []


def cli_run(argv, capsys) -> tuple[dict, list[str]]:
    assert cli.main(argv) == 0
    out, err = capsys.readouterr()
    return json.loads(out), [line.removeprefix("warning: ") for line in err.splitlines() if line.startswith("warning: ")]


@pytest.mark.parametrize("program", ["tube_trunnion.gcode", "corpus/lbracket_cura_25.gcode"])
def test_the_cli_json_warnings_are_what_it_says_every_run(program, capsys):
    """``--json`` lists each warning the command said on stderr, once and in order, in this
    process's every run (Python's default filter says a warning once per process) and as a fresh
    process does."""
    argv = ["info", str(DATA / program), "--json"]
    result, on_stderr = cli_run(argv, capsys)
    again, on_stderr_again = cli_run(argv, capsys)
    assert result["warnings"] and result["warnings"] == on_stderr == again["warnings"] == on_stderr_again
    fresh = subprocess.run([sys.executable, "-m", "dmdvox", *argv], capture_output=True, text=True, cwd=REPO,
                           timeout=600)
    assert fresh.returncode == 0 and json.loads(fresh.stdout) == result
    # the reader's own warnings come first, as the reader gives them
    reader = dmdvox.read_gcode(str(DATA / program)).meta["warnings"]
    assert result["warnings"][:len(reader)] == reader
