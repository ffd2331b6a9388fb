"""Issue 14, "loud when wrong": clean failures, stage lines, and warnings on doubtful inputs.

Each warning is checked where the user sees it: on stderr (``warning: ...``) and in the
``warnings`` list of the command's ``--json`` object.
"""

from __future__ import annotations

import importlib
import json
import os
import subprocess
import sys
import textwrap
from pathlib import Path

import numpy as np
import pytest

from dmdvox import checks, cli, progress
from dmdvox.checks import ROTARY_WARNING

from .conftest import DATA, REPO, copy_numba_cache, numba_cache_folder

DEMO = str(DATA / "demo_block.gcode")
DEMO_CAD = str(DATA / "demo_block.stl")
NOZZLE = "cone:tip=4,top=20,length=25"
COARSE = ["--voxel", "0.375"]
# An L of two beads, seed dialect (M65 on, M64 off), F600 = 10 mm/s.
L_PROGRAM = """G90 G21
G0 X0 Y0 Z0
M65
G1 X10 Y0 Z0 F600
G1 X10 Y5{rotary}
M64
"""


def run(argv, capsys) -> tuple[int, dict | None, str]:
    """``cli.main`` in this process: exit code, the JSON object (with --json), stderr."""
    code = cli.main([str(a) for a in argv])
    out, err = capsys.readouterr()
    return code, (json.loads(out) if "--json" in argv and out.strip() else None), err


def warnings_on_stderr(err: str) -> list[str]:
    return [line.removeprefix("warning: ") for line in err.splitlines() if line.startswith("warning: ")]


# -- clean failures ---------------------------------------------------------------------------------

@pytest.mark.parametrize("argv, option, suffix", [
    (["render", DEMO, "--png", "{tmp}/x.jpg"], "--png", ".png"),
    (["study", "overlap", "--width", "2", "--height", "1", "--spacing", "1.5", "--plot", "{tmp}/p.svg"],
     "--plot", ".png"),
    (["study", "overlap", "--width", "2", "--height", "1", "--spacing", "1.5", "--csv", "{tmp}/t.txt"],
     "--csv", ".csv"),
    (["study", "sweep", DEMO, "--set", "width=2.5", "--csv", "{tmp}/t.json"], "--csv", ".csv"),
], ids=["render-png", "overlap-plot", "overlap-csv", "sweep-csv"])
def test_output_extension_refused_before_any_work(tmp_path, capsys, monkeypatch, argv, option, suffix):
    """Today `render --png x.jpg` deposits the whole part, then fails with a traceback (exit 1)."""
    import dmdvox.tasks
    import dmdvox.toolpath.reader

    work = []
    monkeypatch.setattr(dmdvox.toolpath.reader, "read_gcode", lambda *a, **k: work.append("read"))
    monkeypatch.setattr(dmdvox.tasks, "run_tasks", lambda *a, **k: work.append("tasks"))
    argv = [a.replace("{tmp}", str(tmp_path)) for a in argv]
    code, _, err = run(argv, capsys)
    assert code == 2 and work == []
    assert err.startswith(f"dmdvox: error: {option} {argv[-1]}: ") and f"ending in {suffix}" in err
    assert "Traceback" not in err and os.listdir(tmp_path) == []


def closed_reader_run(argv) -> subprocess.CompletedProcess:
    """The command with stdout a pipe whose reader has already gone (`dmdvox ... | head -0`)."""
    read_end, write_end = os.pipe()
    os.close(read_end)
    try:
        return subprocess.run([sys.executable, "-m", "dmdvox.cli", *map(str, argv)], stdout=write_end,
                              stderr=subprocess.PIPE, text=True, cwd=REPO, timeout=300)
    finally:
        os.close(write_end)


@pytest.mark.parametrize("argv", [
    ["info", DEMO], ["info", DEMO, "--json"],
    ["simulate", DEMO, *COARSE], ["compare", DEMO, DEMO_CAD, *COARSE, "--json"],
], ids=["info", "info-json", "simulate", "compare-json"])
def test_stdout_closed_early_is_no_error(argv):
    """Today `dmdvox info F | head -1` ends in a BrokenPipeError traceback (exit 1)."""
    proc = closed_reader_run(argv)
    assert proc.returncode == 0, proc.stderr
    assert "Traceback" not in proc.stderr and "BrokenPipe" not in proc.stderr and "Exception ignored" not in proc.stderr


def test_a_broken_pipe_that_is_not_stdout_stays_an_internal_error(monkeypatch, capsys):
    """Only a reader that went away is quiet: a broken pipe elsewhere (a worker, a socket) is a bug."""
    def broken(args):
        raise BrokenPipeError("a worker's pipe")

    monkeypatch.setattr(cli, "cmd_info", broken)
    code = cli.main(["info", DEMO])
    err = capsys.readouterr().err
    assert code == 1 and "Traceback" in err and "a worker's pipe" in err


NUMPY_2 = """
import sys
import numba.np.numpy_support  # numba reads the real version first: only dmdvox's check is fooled
import numpy
numpy.__version__ = "2.1.0"  # what pip would bring in without scripts/constraints.txt
{body}
print("pyopenvdb loaded:", "pyopenvdb" in sys.modules)
"""


def numpy2_run(body: str) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-c", NUMPY_2.format(body=textwrap.dedent(body))], capture_output=True,
                          text=True, cwd=REPO, timeout=120)


def test_numpy_2_refused_at_start_up_before_pyopenvdb_loads():
    """numpy >= 2 makes Debian's pyopenvdb 10 crash (exit 139, no message)."""
    proc = numpy2_run("""
        from dmdvox.cli import main
        code = main(["simulate", "{demo}"])
        print("exit", code)
    """.replace("{demo}", DEMO))
    assert "exit 2" in proc.stdout and "pyopenvdb loaded: False" in proc.stdout, proc.stderr
    assert 'dmdvox: error: numpy 2.1.0 is installed' in proc.stderr and 'pip install "numpy<2"' in proc.stderr
    assert "Traceback" not in proc.stderr


def test_numpy_2_refused_by_the_openvdb_import_shim():
    proc = numpy2_run("""
        from dmdvox.errors import DependencyError
        try:
            import dmdvox.vdb
        except DependencyError as exc:
            print("refused:", exc)
    """)
    assert 'refused: numpy 2.1.0 is installed' in proc.stdout and 'pip install "numpy<2"' in proc.stdout
    assert "pyopenvdb loaded: False" in proc.stdout


NO_BINDING = """
import sys, sysconfig
sys.modules["openvdb"] = sys.modules["pyopenvdb"] = None  # both imports fail: no binding installed
from dmdvox.cli import main
print("exit", main([{argv}]))
print("site", sysconfig.get_paths()["purelib"])
"""


@pytest.mark.parametrize("command", ["simulate", "demo"])
def test_a_missing_openvdb_binding_is_refused_with_the_two_ways_to_get_it(command):
    """A wheel cannot bring the binding: the refusal, before any work, names Debian's package with
    the link into this environment, and OpenVDB >= 12's own module."""
    argv = f'"simulate", {DEMO!r}' if command == "simulate" else '"demo", "--out", "unwritten"'
    proc = subprocess.run([sys.executable, "-c", NO_BINDING.format(argv=argv)], capture_output=True, text=True,
                          cwd=REPO, timeout=120)
    assert "exit 2" in proc.stdout, proc.stderr
    site = proc.stdout.split("site ", 1)[1].strip()
    err = " ".join(proc.stderr.split())
    assert "dmdvox: error: OpenVDB's Python binding is not importable" in err and "Traceback" not in err
    assert "sudo apt-get install python3-openvdb" in err
    assert "ln -s /usr/lib/python3/dist-packages/pyopenvdb.cpython-311-" in err and f" {site}/ " in err
    assert "pip install openvdb" in err and "conda install -c conda-forge openvdb" in err
    assert "dmdvox: deposit" not in err and not (REPO / "unwritten").exists()


def test_numpy_2_still_runs_info():
    """`info` never touches OpenVDB: it keeps working."""
    proc = numpy2_run("""
        from dmdvox.cli import main
        print("exit", main(["info", "{demo}", "--json"]))
    """.replace("{demo}", DEMO))
    assert "exit 0" in proc.stdout and "pyopenvdb loaded: False" in proc.stdout, proc.stderr


def test_numpy_version_rule():
    assert checks.numpy_refusal("1.26.4") is None
    assert 'pip install "numpy<2"' in checks.numpy_refusal("2.0.0")


# -- stage lines and the compile notice -------------------------------------------------------------

@pytest.mark.parametrize("argv, stages", [
    (["simulate", DEMO, *COARSE], ["dialect", "deposit"]),
    (["compare", DEMO, DEMO_CAD, *COARSE, "--json"], ["dialect", "deposit", "compare"]),
    (["collide", DEMO, *COARSE, "--nozzle", NOZZLE, "--json"], ["dialect", "deposit", "collide"]),
], ids=["simulate", "compare", "collide"])
def test_stage_lines_on_stderr_when_it_is_not_a_terminal(argv, stages):
    proc = subprocess.run([sys.executable, "-m", "dmdvox.cli", *argv], capture_output=True, text=True, cwd=REPO,
                          timeout=300)
    assert proc.returncode == 0, proc.stderr
    lines = [line for line in proc.stderr.splitlines() if progress.is_progress_line(line)]
    named = [line.removeprefix(progress.PREFIX).split(":")[0] for line in lines]
    assert [s for s in named if s != progress.COMPILE_NOTICE.split(":")[0]][:len(stages)] == stages, lines
    # the stage lines leave --json's stdout alone
    if "--json" in argv:
        json.loads(proc.stdout)


def _on_a_terminal(argv) -> tuple[int, str]:
    """Run the CLI with stdout and stderr on a pseudo-terminal; its exit code and output."""
    import pty

    master, slave = pty.openpty()
    proc = subprocess.Popen([sys.executable, "-m", "dmdvox.cli", *argv], stdin=slave, stdout=slave, stderr=slave,
                            cwd=REPO, env={**os.environ, "DMDVOX_CACHE": "off"})
    os.close(slave)
    chunks = []
    while True:
        try:
            chunk = os.read(master, 65536)
        except OSError:  # EIO: the child closed the terminal
            break
        if not chunk:
            break
        chunks.append(chunk)
    os.close(master)
    return proc.wait(timeout=300), b"".join(chunks).decode(errors="replace").replace("\r\n", "\n")


def test_a_terminal_sees_the_phases_after_the_first_stage_line(tmp_path):
    """The README promises progress on a terminal: after the deposit's stage line, the void
    search, the .vdb and the surface each say when they start (a log keeps its short form)."""
    argv = ["simulate", DEMO, *COARSE, "--out", str(tmp_path / "out")]
    code, text = _on_a_terminal(argv)
    assert code == 0, text
    stages = [line for line in text.splitlines() if progress.is_progress_line(line)]
    # the reader's dialect line (auto says what it read the file as) comes before the deposit's
    first = next(i for i, line in enumerate(stages) if line.startswith("dmdvox: deposit: "))
    assert stages[first].startswith("dmdvox: deposit: 232 deposit moves"), stages
    assert all(line.startswith("dmdvox: dialect: ") for line in stages[:first]), stages
    later = "\n".join(stages[first + 1:])
    for phase in ("searching the enclosed voids", f"writing {tmp_path / 'out' / 'demo_block.vdb'}",
                  "meshing the surface", "writing the surface"):
        assert phase in later, stages
    piped = subprocess.run([sys.executable, "-m", "dmdvox.cli", *argv], capture_output=True, text=True, cwd=REPO,
                           timeout=300, env={**os.environ, "DMDVOX_CACHE": "off"})
    assert piped.returncode == 0 and "searching the enclosed voids" not in piped.stderr


def test_counter_prints_a_line_per_tenth_in_a_log(capsys):
    with progress.to_stderr(), progress.counter("sweep", "tasks", 50) as bar:  # as the CLI shows them
        for done in range(51):
            bar.update(done, 50)
    lines = capsys.readouterr().err.splitlines()
    assert lines[0] == "dmdvox: sweep: 0/50 tasks" and lines[-1] == "dmdvox: sweep: 50/50 tasks"
    assert len(lines) == 11  # 0, 5, 10, ... 50


def test_cold_cache_is_detected_without_compiling(tmp_path, monkeypatch):
    """The notice's test: a cached kernel is cold until its first call has written its index."""
    (tmp_path / "kernel_mod.py").write_text("from numba import njit\n\n@njit(cache=True)\ndef twice(x):\n"
                                            "    return 2 * x\n")
    monkeypatch.syspath_prepend(str(tmp_path))
    module = importlib.import_module("kernel_mod")
    assert progress.is_cold(module.twice)
    assert module.twice.signatures == []  # the test compiled nothing
    assert module.twice(3) == 6
    assert not progress.is_cold(module.twice)
    # a plain function is never cold (nothing to compile)
    assert not progress.is_cold(lambda x: x)


@pytest.mark.parametrize("cold, expected", [(True, 1), (False, 0)])
def test_compile_notice_once_when_a_kernel_is_cold(monkeypatch, capsys, cold, expected):
    monkeypatch.setattr(progress, "_noticed", False)
    monkeypatch.setattr(progress, "is_cold", lambda dispatcher: cold)
    code, _, err = run(["info", DEMO, "--json"], capsys)
    assert code == 0 and err.count(progress.COMPILE_NOTICE) == expected
    code, _, err = run(["info", DEMO, "--json"], capsys)
    assert code == 0 and err.count(progress.COMPILE_NOTICE) == 0  # once per process


def test_compile_notice_on_a_really_cold_cache(tmp_path, gcode_file):
    """End to end: a numba cache (NUMBA_CACHE_DIR) that holds no machine code for a key kernel of
    `info` (the summary's chord lengths) makes `info` say it compiles; the second run, from the
    cache the first wrote, does not. The rest of the new cache is a copy of this process's: a
    wholly empty one would take two minutes compiling the G-code interpreter for the same notice
    (any cold key kernel gives it; test_cold_cache_is_detected_without_compiling)."""
    from dmdvox.toolpath import summary

    path = gcode_file(L_PROGRAM.format(rotary=""))
    cache = tmp_path / "numba-cache"
    cold = f"{Path(summary.__file__).stem}._chord_lengths-"
    copy_numba_cache(cache, skip=cold)
    summary_cache = numba_cache_folder(Path(summary.__file__).resolve().parent, str(cache))
    assert not list(summary_cache.glob(cold + "*"))
    env = {**os.environ, "NUMBA_CACHE_DIR": str(cache)}

    def info():
        return subprocess.run([sys.executable, "-m", "dmdvox.cli", "info", str(path), "--json"], capture_output=True,
                              text=True, cwd=REPO, env=env, timeout=600)

    first = info()
    written = {f.suffix for f in summary_cache.glob(cold + "*")}  # what the first run compiled, it cached
    second = info()
    assert [first.returncode, second.returncode] == [0, 0]
    assert [first.stderr.count(progress.COMPILE_NOTICE), second.stderr.count(progress.COMPILE_NOTICE)] == [1, 0]
    assert written == {".nbi", ".nbc"}


# -- doubtful inputs --------------------------------------------------------------------------------

def test_cad_away_from_the_deposit_suggests_an_offset(tmp_path, capsys):
    """The CAD box 10 x 10 x 3 mm with its corner at (50, 50, 10); the demo deposit's box is the
    path box (1.25..18.75 in x and y, z 0..5.25) widened by half the 2.5 mm track and raised by
    the 0.75 mm bead: 0..20 x 0..20 x 0..6, centre (10, 10), bottom 0. Centring the CAD (centre
    (55, 55)) and putting its bottom on 0 moves it by (-45, -45, -10)."""
    from dmdvox.io.mesh import box_mesh, write_stl

    cad = tmp_path / "far.stl"
    write_stl(cad, *box_mesh((50.0, 50.0, 10.0), (60.0, 60.0, 13.0)))
    code, result, err = run(["compare", DEMO, cad, *COARSE, "--json"], capsys)
    assert code == 0
    text = next(w for w in result["warnings"] if "do not overlap" in w)
    assert "--cad-offset=-45,-45,-10 " in text and text in warnings_on_stderr(err)
    # with an offset already given, the suggestion is the whole offset
    code, result, _ = run(["compare", DEMO, cad, *COARSE, "--cad-offset", "0,0,100", "--json"], capsys)
    assert any("--cad-offset=-45,-45,-10 " in w for w in result["warnings"])
    # following the suggestion, no warning
    code, result, err = run(["compare", DEMO, cad, *COARSE, "--cad-offset=-45,-45,-10", "--json"], capsys)
    assert code == 0 and not any("do not overlap" in w for w in result["warnings"]) and "do not overlap" not in err


def test_report_says_so_too(tmp_path, capsys):
    code, result, err = run(["report", DEMO, *COARSE, "--cad", DEMO_CAD, "--cad-offset", "100,0,0",
                             "--out", tmp_path / "report", "--json"], capsys)
    assert code == 0
    assert any("do not overlap" in w and "--cad-offset=0,0,0 " in w for w in result["warnings"])
    assert any("do not overlap" in w for w in warnings_on_stderr(err))


def test_info_warns_about_a_program_that_deposits_nothing(gcode_file, capsys):
    path = gcode_file("G90\nG0 X0 Y0 Z0\nG1 X10 F600\nM30\n")
    code, result, err = run(["info", path, "--json"], capsys)
    assert code == 0 and result["deposit_segments"] == 0
    text = f"{path}: the program deposits nothing under dialect"
    assert any(w.startswith(text) for w in result["warnings"])
    assert any(w.startswith(text) and "check --dialect" in w for w in warnings_on_stderr(err))


@pytest.mark.parametrize("command", ["simulate", "compare"])
def test_commands_that_need_a_deposit_refuse_and_say_why(gcode_file, capsys, command):
    # the G0 from an unknown position only sets it: one move, a travel
    path = gcode_file("G90\nG0 X0 Y0 Z0\nG1 X10 F600\nM30\n")
    argv = [command, path, *([DEMO_CAD] if command == "compare" else []), *COARSE]
    code, _, err = run(argv, capsys)
    assert code == 2
    # after the stage line naming what auto went by
    assert err.startswith("dmdvox: dialect: auto, by no laser code or E word\n")
    assert f"\ndmdvox: error: {path}: the program deposits nothing under dialect 'auto' (1 move, none" in err
    assert "check --dialect" in err and "Traceback" not in err


def test_until_before_the_first_deposit(capsys):
    """The demo's first bead starts after `G1 Z0 F750` from Z5: 5 mm at 750 mm/min from rest to
    rest at the default 500 mm/s^2, L / v + v / a = 0.425 s (the rapid before it starts from an
    unknown position and takes no time)."""
    v = 750.0 / 60.0
    first = 5.0 / v + v / 500.0
    code, _, err = run(["simulate", DEMO, "--until", "0.3"], capsys)
    assert code == 2
    assert f"--until 0.3: that is before the first deposit, which starts at {first:.3f} s (line 8)" in err
    assert "check --dialect" not in err
    assert run(["simulate", DEMO, *COARSE, "--until", str(first + 0.5)], capsys)[0] == 0


def test_render_before_the_first_deposit_says_the_picture_is_empty(tmp_path, capsys):
    code, result, err = run(["render", DEMO, *COARSE, "--time", "0.2", "--size", "160x120",
                             "--png", tmp_path / "t.png", "--json"], capsys)
    assert code == 0
    # L / v + v / a of the 5 mm approach at F750 and the default 500 mm/s^2
    assert any("before the first deposit, at 0.425 s" in w for w in result["warnings"])


ROTARY_COMMANDS = {
    "info": ["info", "{gcode}"],
    "simulate": ["simulate", "{gcode}", *COARSE],
    "compare": ["compare", "{gcode}", DEMO_CAD, *COARSE],
    "render": ["render", "{gcode}", *COARSE, "--size", "160x120", "--png", "{tmp}/r.png"],
    "collide": ["collide", "{gcode}", *COARSE, "--nozzle", NOZZLE],
    "report-nozzle": ["report", "{gcode}", *COARSE, "--nozzle", NOZZLE, "--out", "{tmp}/report"],
    "study-sweep": ["study", "sweep", "{gcode}", "--set", "width=2.5", *COARSE],
}


def rotary_argv(gcode_file, tmp_path, name):
    path = gcode_file(L_PROGRAM.format(rotary=" A15"))
    return path, [a.replace("{gcode}", str(path)).replace("{tmp}", str(tmp_path)) for a in ROTARY_COMMANDS[name]]


@pytest.mark.parametrize("name", list(ROTARY_COMMANDS))
def test_rotary_words_warned_by_every_command(gcode_file, tmp_path, capsys, name):
    path, argv = rotary_argv(gcode_file, tmp_path, name)
    code, result, err = run([*argv, "--json"], capsys)
    assert code == 0, err
    expected = f"{path}: {ROTARY_WARNING}"
    assert expected in result["warnings"] and warnings_on_stderr(err).count(expected) == 1


@pytest.mark.parametrize("name", [n for n in ROTARY_COMMANDS if n != "report-nozzle"])
def test_rotary_words_refused_under_strict(gcode_file, tmp_path, capsys, name):
    """The warning drops the A/B/C motion: --strict refuses the program, before any work."""
    _, argv = rotary_argv(gcode_file, tmp_path, name)
    code, _, err = run([*argv, "--strict"], capsys)
    assert code == 2 and ROTARY_WARNING in err and "--strict" in err
    assert "dmdvox: deposit" not in err and not (tmp_path / "r.png").exists()


def test_report_rotary_words_without_nozzle_and_under_strict(gcode_file, tmp_path, capsys):
    path = gcode_file(L_PROGRAM.format(rotary=" A15"))
    argv = ["report", path, *COARSE, "--out", tmp_path / "report"]
    code, result, err = run([*argv, "--json"], capsys)
    assert code == 0 and f"{path}: {ROTARY_WARNING}" in result["warnings"]
    code, _, err = run([*argv, "--strict"], capsys)
    assert code == 2 and ROTARY_WARNING in err


def test_every_command_json_has_a_warnings_list(capsys):
    path = DEMO
    code, result, _ = run(["simulate", path, *COARSE, "--json"], capsys)
    assert code == 0 and result["warnings"] == []


def test_dialect_that_misreads_the_laser_codes_is_warned(capsys):
    """The demo block switches its laser with M65 (on) and M64 (off), without P: the seed's
    codes. LinuxCNC's M64/M65 need an output number P and mean on/off the other way round, so
    `--dialect linuxcnc` deposits only the 8 links between tracks (40 of the 2240 mm)."""
    code, result, err = run(["info", DEMO, "--dialect", "linuxcnc", "--json"], capsys)
    assert code == 0 and result["deposit_length_mm"] == pytest.approx(40.0)
    doubt = [w for w in result["warnings"] if "--dialect linuxcnc" in w]
    assert doubt and "seed" in doubt[0] and "2240" in doubt[0] and "40" in doubt[0]
    assert doubt[0] in warnings_on_stderr(err)
    # the right dialect (or auto) says nothing
    code, result, _ = run(["info", DEMO, "--dialect", "seed", "--json"], capsys)
    assert not any("dialect" in w for w in result["warnings"])


def test_deposit_box_and_offset_arithmetic():
    class Bead:
        width, height = 2.0, 0.5

    class Path:
        z_is_layer_top = True

        def deposit_bbox(self):
            return np.array([[0.0, 0.0, 0.5], [10.0, 4.0, 2.0]])

    box = checks.deposit_box(Path(), Bead())
    # slicer Z is the bead top: the material reaches one bead height below the lowest path point
    np.testing.assert_allclose(box, [[-1.0, -1.0, 0.0], [11.0, 5.0, 2.0]])
    offset = checks.suggested_cad_offset(box, (100.0, 100.0, 50.0), (110.0, 104.0, 52.0), offset=(1.0, 2.0, 3.0))
    np.testing.assert_allclose(offset, [1.0 + 5.0 - 105.0, 2.0 + 2.0 - 102.0, 3.0 + 0.0 - 50.0])
