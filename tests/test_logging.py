"""Issue 24: stage lines and progress go to the logger ``dmdvox``; the command line shows them on
stderr, the library shows nothing unless the application configures logging."""

from __future__ import annotations

import logging

import dmdvox
from dmdvox import cli, progress

from .conftest import DATA

DEMO = str(DATA / "demo_block.gcode")
DEMO_CAD = str(DATA / "demo_block.stl")


def test_the_library_logs_its_stages_and_prints_nothing(caplog, capsys):
    with caplog.at_level(logging.INFO, logger="dmdvox"):
        dmdvox.compare(DEMO, DEMO_CAD, 0.375)
    stages = [r.getMessage() for r in caplog.records if r.name == "dmdvox"]
    assert any(s.startswith("deposit: 232 deposit moves") for s in stages), stages
    assert any(s.startswith("compare: CAD level set") for s in stages), stages
    assert all(r.levelno == logging.INFO for r in caplog.records if r.name == "dmdvox")
    assert capsys.readouterr().err == ""


def test_a_notebook_silences_them(caplog, capsys):
    logger = logging.getLogger("dmdvox")
    with caplog.at_level(logging.WARNING, logger="dmdvox"):
        dmdvox.compare(DEMO, DEMO_CAD, 0.375)
        assert [r for r in caplog.records if r.name == "dmdvox"] == []
    assert capsys.readouterr().err == ""
    assert logger.handlers and all(isinstance(h, logging.NullHandler) for h in logger.handlers)


def test_the_cli_shows_them_on_stderr_and_puts_the_logger_back(caplog, capsys):
    logger = logging.getLogger("dmdvox")
    before = (logger.level, list(logger.handlers))
    with caplog.at_level(logging.INFO, logger="dmdvox"):
        assert cli.main(["compare", DEMO, DEMO_CAD, "--voxel", "0.375", "--json"]) == 0
    err = capsys.readouterr().err.splitlines()
    logged = [f"{progress.PREFIX}{r.getMessage()}" for r in caplog.records if r.name == "dmdvox"]
    # stderr is not a terminal here: the INFO stage lines, the DEBUG steps not shown
    assert [line for line in err if progress.is_progress_line(line)] == [
        line for line, r in zip(logged, [r for r in caplog.records if r.name == "dmdvox"])
        if r.levelno >= logging.INFO]
    assert any(line.startswith("dmdvox: compare: ") for line in err)
    assert (logger.level, list(logger.handlers)) == before


def test_steps_are_debug_and_bars_need_a_shown_logger(caplog, monkeypatch):
    with caplog.at_level(logging.DEBUG, logger="dmdvox"):
        progress.step("deposit", "meshing the surface")
        progress.stage("deposit", "swept")
    assert [(r.levelno, r.getMessage()) for r in caplog.records] == [
        (logging.DEBUG, "deposit: meshing the surface"), (logging.INFO, "deposit: swept")]

    class Terminal:
        def isatty(self):
            return True

    monkeypatch.setattr("sys.stderr", Terminal())
    logger = logging.getLogger("dmdvox")
    level = logger.level
    try:
        logger.setLevel(logging.WARNING)
        assert not progress.bars()  # silenced: no tqdm bar either
        logger.setLevel(logging.INFO)
        assert progress.bars()
    finally:
        logger.setLevel(level)
