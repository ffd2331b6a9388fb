"""Interrupted runs: every file under its final name is complete (docs/BAD_INPUTS.md).

The commands run in a subprocess that is interrupted (SIGINT, as Ctrl-C) or killed (SIGKILL)
at a moment its output folder shows: a temporary file appearing (a write under way) or a
final file appearing (work between two writes).
"""

import csv
import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from dmdvox import progress
from dmdvox.grid.vdbio import read_vdb
from dmdvox.io.atomic import atomic_path, remove_stale_parts, write_text
from dmdvox.io.mesh import read_stl

from .conftest import DATA, REPO

DMDVOX = Path(sys.executable).with_name("dmdvox")
SIMULATE = ["simulate", DATA / "demo_block.gcode"]
COMPARE = ["compare", DATA / "demo_block.gcode", DATA / "demo_block.stl"]
SIMULATE_OUTPUTS = {"demo_block.vdb", "demo_block_surface.vtp", "demo_block_surface.stl", "demo_block_surface.ply",
                    "demo_block_simulate.json"}
COMPARE_OUTPUTS = {"demo_block_cad_deviation.vtp", "demo_block_deposit_deviation.vtp", "demo_block_compare.vti",
                   "demo_block_compare.vdb", "demo_block_layers.csv", "demo_block_cad_deviation.png",
                   "demo_block_compare.json"}


def temporary(name):
    """The moment a temporary file for output ``name`` exists: its write is under way."""
    return lambda names: any(n.startswith(f".{name}.part-") for n in names)


def final(name):
    return lambda names: name in names


def run_until(argv, out: Path, moment, sig) -> tuple[int, subprocess.CompletedProcess]:
    """Run the command and send ``sig`` as soon as its output folder satisfies ``moment``;
    return its PID and its result."""
    # A shell without job control starts background jobs with SIGINT ignored, and Python keeps
    # an ignored SIGINT ignored: give the command the default disposition a terminal gives it.
    proc = subprocess.Popen([str(DMDVOX), *map(str, argv), "--out", str(out)], cwd=REPO, stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True,
                            preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))
    try:
        deadline = time.monotonic() + 120
        while not moment(os.listdir(out) if out.is_dir() else []):
            assert proc.poll() is None, f"finished before the moment came: {proc.communicate()[1]}"
            assert time.monotonic() < deadline
            time.sleep(0.0005)
        proc.send_signal(sig)
        stdout, stderr = proc.communicate(timeout=60)
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.wait()
    return proc.pid, subprocess.CompletedProcess(proc.args, proc.returncode, stdout, stderr)


def vtk_arrays(path: Path) -> dict:
    """Point arrays of a VTK XML file and their tuple counts (empty if VTK cannot read it)."""
    import vtk

    vtk.vtkObject.GlobalWarningDisplayOff()
    reader = vtk.vtkXMLPolyDataReader() if path.suffix == ".vtp" else vtk.vtkXMLImageDataReader()
    reader.SetFileName(str(path))
    reader.Update()
    data = reader.GetOutput().GetPointData()
    return {data.GetArrayName(i): data.GetArray(i).GetNumberOfTuples() for i in range(data.GetNumberOfArrays())}


def assert_complete(path: Path) -> None:
    """Raise unless ``path`` is a whole output file of its kind."""
    data = path.read_bytes()
    if path.suffix == ".vdb":
        assert read_vdb(path).active_voxels > 0
    elif path.suffix == ".json":
        assert json.loads(data)["outputs"]
    elif path.suffix in (".vtp", ".vti"):
        arrays = vtk_arrays(path)
        expected = {"deviation_mm"} if path.suffix == ".vtp" else {"label", "deposit_sdf_mm", "cad_sdf_mm"}
        assert expected <= set(arrays) and min(arrays.values()) > 0, arrays
    elif path.suffix == ".stl":
        assert read_stl(path)[1].shape[0] > 0
    elif path.suffix == ".ply":
        header, _, body = data.partition(b"end_header\n")
        counts = dict(line.split()[1:3] for line in header.decode().splitlines() if line.startswith("element"))
        assert len(body) == int(counts["vertex"]) * 24 + int(counts["face"]) * 13  # float64 xyz; uchar + 3 int32
    elif path.suffix == ".png":
        assert data.startswith(b"\x89PNG") and data.endswith(b"IEND\xaeB`\x82")
    elif path.suffix == ".csv":
        rows = list(csv.reader(data.decode().splitlines()))
        assert rows[0] == ["layer", "z_mm", "void_mm3", "overbuild_mm3"] and len(rows) > 1
        assert all(len(row) == 4 for row in rows) and data.endswith(b"\n")
    else:
        raise AssertionError(f"unexpected output {path}")


def finals(out: Path) -> set[str]:
    return {n for n in os.listdir(out) if not n.startswith(".")}


def parts(out: Path) -> list[str]:
    return [n for n in os.listdir(out) if ".part-" in n]


@pytest.mark.parametrize("argv, expected, moment, done_before", [
    (SIMULATE, SIMULATE_OUTPUTS, temporary("demo_block.vdb"), set()),
    (SIMULATE, SIMULATE_OUTPUTS, final("demo_block.vdb"), {"demo_block.vdb"}),
    (SIMULATE, SIMULATE_OUTPUTS, temporary("demo_block_surface.vtp"), {"demo_block.vdb"}),
    (COMPARE, COMPARE_OUTPUTS, final("demo_block_cad_deviation.vtp"), {"demo_block_cad_deviation.vtp"}),
    (COMPARE, COMPARE_OUTPUTS, temporary("demo_block_cad_deviation.png"),
     {"demo_block_cad_deviation.vtp", "demo_block_deposit_deviation.vtp", "demo_block_compare.vti",
      "demo_block_compare.vdb", "demo_block_layers.csv"}),
], ids=["simulate-vdb-writing", "simulate-after-vdb", "simulate-vtp-writing", "compare-after-vtp",
        "compare-png-writing"])
def test_ctrl_c(tmp_path, argv, expected, moment, done_before):
    out = tmp_path / "out"
    _, proc = run_until(argv, out, moment, signal.SIGINT)
    written = finals(out)
    # nothing but the stage lines of the work done before the signal, then the one message
    stderr = progress.without_progress(proc.stderr)
    assert (proc.returncode, stderr, proc.stdout) == (130, "dmdvox: interrupted\n", ""), written
    assert parts(out) == []
    assert done_before <= written and written < expected
    for name in written:
        assert_complete(out / name)


@pytest.mark.parametrize("argv, expected, moment", [
    (SIMULATE, SIMULATE_OUTPUTS, temporary("demo_block.vdb")),
    (COMPARE, COMPARE_OUTPUTS, temporary("demo_block_cad_deviation.png")),
], ids=["simulate-vdb-writing", "compare-png-writing"])
def test_kill(tmp_path, argv, expected, moment):
    out = tmp_path / "out"
    pid, proc = run_until(argv, out, moment, signal.SIGKILL)
    assert proc.returncode == -signal.SIGKILL
    written = finals(out)
    assert written < expected
    for name in written:
        assert_complete(out / name)
    # A killed writer cannot clean up; its temporary file is named after it, and the next
    # write into the folder removes it.
    for name in parts(out):
        assert f".part-{name.split('.part-')[1].split('-')[0]}-{pid}-" in name
    write_text(out / "next.txt", "next run\n")
    assert parts(out) == []
    assert finals(out) == written | {"next.txt"}


HOLD = """
import sys, time
from dmdvox.io.atomic import atomic_path
with atomic_path(sys.argv[1]) as tmp:
    tmp.write_bytes(b"half")
    print(tmp, flush=True)
    time.sleep(120)
"""


def hold_temporary(target: Path) -> tuple[subprocess.Popen, Path]:
    """A writer process stopped in the middle of writing ``target``, and its temporary file."""
    proc = subprocess.Popen([sys.executable, "-c", HOLD, str(target)], cwd=REPO, stdout=subprocess.PIPE, text=True)
    return proc, Path(proc.stdout.readline().strip())


def test_stale_temporary_files_of_dead_writers_are_removed(tmp_path):
    dead, dead_part = hold_temporary(tmp_path / "a.vdb")
    live, live_part = hold_temporary(tmp_path / "b.vdb")
    try:
        dead.kill()
        dead.wait()
        assert dead_part.name.startswith(".a.vdb.part-") and f"-{dead.pid}-" in dead_part.name
        assert dead_part.read_bytes() == b"half"
        foreign = tmp_path / f".c.vdb.part-otherhost-{dead.pid}-abcdefgh.vdb"  # a shared folder's other host
        unrelated = tmp_path / ".d.vdb.part-notes"
        for path in (foreign, unrelated):
            path.write_bytes(b"keep")
        write_text(tmp_path / "e.json", "{}")
        assert not dead_part.exists()
        assert live_part.read_bytes() == b"half" and foreign.exists() and unrelated.exists()
        assert (tmp_path / "e.json").read_text() == "{}"
        assert remove_stale_parts(tmp_path) == []
    finally:
        live.kill()
        live.wait()
    assert remove_stale_parts(tmp_path) == [live_part]


def test_own_temporary_file_survives_a_sweep(tmp_path):
    with atomic_path(tmp_path / "x.bin") as tmp:
        tmp.write_bytes(b"1")
        assert f"-{os.getpid()}-" in tmp.name
        assert remove_stale_parts(tmp_path) == []
        write_text(tmp_path / "y.txt", "y")
        assert tmp.exists()
    assert (tmp_path / "x.bin").read_bytes() == b"1" and parts(tmp_path) == []


def test_error_inside_the_write_removes_the_temporary_file(tmp_path):
    with pytest.raises(KeyboardInterrupt):
        with atomic_path(tmp_path / "x.bin") as tmp:
            tmp.write_bytes(b"partial")
            raise KeyboardInterrupt
    assert os.listdir(tmp_path) == []


def test_a_symbolic_link_is_written_where_it_points(tmp_path):
    """data/ holds links to the samples inside the package: rewriting one keeps the link."""
    (tmp_path / "package").mkdir()
    (tmp_path / "package" / "sample.gcode").write_text("old")
    link = tmp_path / "sample.gcode"
    link.symlink_to(Path("package") / "sample.gcode")
    write_text(link, "new")
    assert link.is_symlink() and os.readlink(link) == str(Path("package") / "sample.gcode")
    assert (tmp_path / "package" / "sample.gcode").read_text() == "new"
    assert parts(tmp_path) == [] and parts(tmp_path / "package") == []


def test_sigterm_is_taken_as_ctrl_c(tmp_path):
    """A scheduler's or a container's stop (SIGTERM) ends the run as Ctrl-C does: one message,
    exit 143 (128 + 15, what a shell reports for it), no temporary file left."""
    out = tmp_path / "out"
    _, proc = run_until(SIMULATE, out, temporary("demo_block.vdb"), signal.SIGTERM)
    stderr = progress.without_progress(proc.stderr)
    assert (proc.returncode, stderr, proc.stdout) == (143, "dmdvox: terminated\n", "")
    assert parts(out) == [] and "demo_block.vdb" not in finals(out)
    for name in finals(out):
        assert_complete(out / name)


def _run_cli(argv) -> tuple[int, str, str]:
    import contextlib
    import io

    from dmdvox import cli

    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        code = cli.main([str(a) for a in argv])
    return code, out.getvalue(), err.getvalue()


def test_a_full_disk_is_exit_2_naming_the_file_with_nothing_partial_left(tmp_path, monkeypatch):
    import errno

    import dmdvox.grid.vdbio as vdbio

    def full_disk(path, **kwargs):
        Path(path).write_bytes(b"\0" * 4096)  # the writer got this far
        raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))

    monkeypatch.setattr(vdbio.openvdb, "write", full_disk)
    monkeypatch.setenv("DMDVOX_CACHE", "off")
    out = tmp_path / "out"
    code, stdout, stderr = _run_cli([*SIMULATE, "--out", out, "--voxel", "0.25", "--json"])
    assert code == 2 and "Traceback" not in stderr
    message = progress.without_progress(stderr).strip().splitlines()[-1]
    assert message.startswith(f"dmdvox: error: {out / 'demo_block.vdb'}: disk full"), message
    assert json.loads(stdout)["exit_code"] == 2
    assert parts(out) == [] and finals(out) == set()


def test_vtk_out_of_disk_space_is_a_full_disk(tmp_path):
    """VTK says a full disk by its error code, not by an exception."""
    import vtk

    from dmdvox.errors import DmdvoxError
    from dmdvox.io.mesh import write_vtk_xml

    class FullDiskWriter(vtk.vtkXMLPolyDataWriter):
        def Write(self):
            Path(self.GetFileName()).write_bytes(b"<VTKFile")  # the writer got this far
            return 0

        def GetErrorCode(self):
            return vtk.vtkErrorCode.OutOfDiskSpaceError

    with pytest.raises(DmdvoxError, match="box.vtp: disk full"):
        write_vtk_xml(FullDiskWriter(), vtk.vtkPolyData(), tmp_path / "box.vtp")
    assert os.listdir(tmp_path) == []


def test_a_rerun_into_the_same_folder_leaves_only_its_own_files(tmp_path, monkeypatch):
    monkeypatch.setenv("DMDVOX_CACHE", "off")
    out = tmp_path / "out"
    other = tmp_path / "other_part.gcode"
    other.write_text((DATA / "demo_block.gcode").read_text())
    mine = out / "notes.txt"  # not a run's: stays
    out.mkdir()
    mine.write_text("mine")
    results = []
    for program in (DATA / "demo_block.gcode", other):
        code, stdout, stderr = _run_cli(["simulate", program, "--out", out, "--voxel", "0.25", "--json"])
        assert code == 0, stderr
        results.append(json.loads(stdout))
    listed = {Path(p).name for p in results[-1]["outputs"]}
    assert all(name.startswith("other_part") for name in listed)
    assert finals(out) == listed | {"notes.txt"} and mine.read_text() == "mine"
    # the folder's run list names exactly the files of the last run
    assert set(json.loads((out / ".dmdvox-run.json").read_text())["files"]) == listed
    # a run refused before it writes leaves the last run's files (and their list) alone
    code, _, _ = _run_cli(["simulate", DATA / "demo_block.gcode", "--out", out, "--until", "nan"])
    assert code == 2
    assert finals(out) == listed | {"notes.txt"}
    assert set(json.loads((out / ".dmdvox-run.json").read_text())["files"]) == listed


def test_a_run_list_naming_files_outside_the_folder_removes_nothing_there(tmp_path, monkeypatch):
    from dmdvox.io.atomic import output_run

    outside = tmp_path / "precious.txt"
    outside.write_text("keep")
    out = tmp_path / "out"
    out.mkdir()
    (out / "link").symlink_to(outside)
    (out / ".dmdvox-run.json").write_text(json.dumps({"files": ["../precious.txt", str(outside), "link"]}))
    with output_run(out) as written:
        write_text(out / "a.txt", "a")
    assert outside.read_text() == "keep" and (out / "link").is_symlink()
    assert written == ["a.txt"] and json.loads((out / ".dmdvox-run.json").read_text())["files"] == ["a.txt"]
