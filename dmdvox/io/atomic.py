"""Atomic output files: written beside the target under a temporary name, renamed into place.

A file under its final name is always complete: an interrupted run leaves the previous file
or none, never a partial one.

* Ctrl-C (SIGINT) or an error: the temporary file is removed before the exception goes on
  (the CLI then exits 130, or 2/1 for errors).
* A killed process (SIGKILL, power loss) cannot clean up, so its temporary file stays, named
  ``.NAME.part-HOST-PID-`` and eight random characters (hidden; ``HOST`` and ``PID`` are the
  writer's). A process's first atomic write into that folder removes every such file whose
  writer, on this host, is no longer running (once per folder: a part's 2,048 image pieces
  would otherwise list their folder 2,048 times). Files of live writers, of other hosts (a
  shared folder) and of any other name are left alone.
* Ctrl-C is held while the temporary file is created, so no moment leaves it unnamed.
* A target that is a symbolic link is written where the link points, as ``open(target, "w")``
  would write it; renaming onto the link itself would replace the link with a file (the
  repository's data/ links to the samples in the package: regenerating a sample must keep the
  link).
* A full disk (ENOSPC, EDQUOT, or a writer that fails with no space left in the folder) is a
  :class:`DmdvoxError` naming the file, its temporary file removed: no truncated output.

A command's output folder lists the files its run wrote in ``.dmdvox-run.json``
(:func:`output_run`); the next run into that folder removes them before it writes, so that
files of two runs (another program's stem, a .vti that became slabs) never stand side by side.
"""

from __future__ import annotations

import contextlib
import errno
import json
import os
import shutil
import re
import signal
import socket
import tempfile
import threading
from pathlib import Path
from typing import Iterator

from ..errors import DmdvoxError

_PART = ".part-"
# ".NAME.part-HOST-PID-" then mkstemp's eight random characters and the suffix.
_PART_NAME = re.compile(r"\..+\.part-(?P<host>[A-Za-z0-9_]+)-(?P<pid>[0-9]+)-[a-z0-9_]{8}(\.[^.]*)?")


# folders this process has already swept of dead writers' temporary files
_SWEPT: set[str] = set()
RUN_LIST = ".dmdvox-run.json"
# below this many free bytes in its folder, a writer's failure is the disk's (OpenVDB and VTK
# report a short write without an errno)
_FULL_BYTES = 1 << 20
# the output folders of the runs under way (realpath -> files written there, in order), and the
# previous run's files in each, removed at the run's first write there
_RUNS: dict[str, list[str]] = {}
_PREVIOUS: dict[str, list] = {}


def _host() -> str:
    """This host's name as a temporary name may hold it (one token, no dashes or dots)."""
    return re.sub(r"[^A-Za-z0-9_]", "_", socket.gethostname()) or "host"


def _running(pid: int) -> bool:
    if pid == os.getpid():
        return True
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except (PermissionError, OverflowError):
        return True  # another user's process, or a number we cannot test: keep its file
    return True


def remove_stale_parts(folder: str | os.PathLike) -> list[Path]:
    """Remove temporary files left in ``folder`` by dead writers on this host; return them."""
    host = _host()
    removed = []
    try:
        entries = list(os.scandir(folder))
    except OSError:
        return removed
    for entry in entries:
        part = _PART_NAME.fullmatch(entry.name)
        if part is None or part["host"] != host or _running(int(part["pid"])):
            continue
        with contextlib.suppress(OSError):  # gone already, or not ours to remove: leave it
            os.unlink(entry.path)
            removed.append(Path(entry.path))
    return removed


@contextlib.contextmanager
def atomic_path(target: str | os.PathLike, suffix: str | None = None) -> Iterator[Path]:
    """Yield a temporary path in the target's folder; rename it onto ``target`` on success.

    ``suffix`` defaults to the target's own, for writers that choose a format by extension.
    Stale temporary files of dead writers in the folder are removed first (module docstring).
    """
    target = Path(target)
    if target.is_symlink():
        target = Path(os.path.realpath(target))
    folder = target.parent if str(target.parent) else Path(".")
    _clear_previous_run(target)
    tmp = None
    try:
        with _signals_held():
            # Ctrl-C cannot land between the file's creation and ``tmp`` naming it: it is held
            # until here, inside the ``try`` that removes the file.
            try:
                folder.mkdir(parents=True, exist_ok=True)
                swept = os.path.realpath(folder)
                if swept not in _SWEPT:
                    remove_stale_parts(folder)
                    _SWEPT.add(swept)
                fd, tmp_name = tempfile.mkstemp(prefix=f".{target.name}{_PART}{_host()}-{os.getpid()}-",
                                                suffix=target.suffix if suffix is None else suffix, dir=folder)
            except OSError as exc:
                raise DmdvoxError(f"{target}: cannot write output ({exc.strerror}); choose a writable --out folder") \
                    from exc
            tmp = Path(tmp_name)
            os.close(fd)
        # mkstemp creates 0600; results are ordinary files, so follow the umask like open() does.
        umask = os.umask(0)
        os.umask(umask)
        os.chmod(tmp, 0o666 & ~umask)
        yield tmp
        os.replace(tmp, target)
    except BaseException as exc:
        if tmp is not None:
            with contextlib.suppress(FileNotFoundError):
                tmp.unlink()
        if isinstance(exc, Exception) and not isinstance(exc, DmdvoxError) and _disk_full(exc, folder):
            raise DmdvoxError(f"{target}: disk full ({exc}); free space there or choose another --out folder; "
                              "the file was not written") from exc
        raise
    _record(target)


def _disk_full(exc: Exception, folder: Path) -> bool:
    if isinstance(exc, OSError) and exc.errno in (errno.ENOSPC, errno.EDQUOT):
        return True
    try:
        return shutil.disk_usage(folder).free < _FULL_BYTES
    except OSError:
        return False


def _clear_previous_run(target: Path) -> None:
    """Before a run's first write into its output folder, remove the previous run's files there."""
    real = os.path.realpath(target)
    for folder in [f for f in _PREVIOUS if real.startswith(f + os.sep)]:
        for name in _PREVIOUS.pop(folder):
            path = _inside(folder, name)
            if path is not None:
                with contextlib.suppress(OSError):
                    os.unlink(path)


def _record(target: Path) -> None:
    """Note ``target`` in the list of the run whose output folder holds it."""
    real = os.path.realpath(target)
    for folder, written in _RUNS.items():
        if real.startswith(folder + os.sep) and os.path.basename(real) != RUN_LIST:
            written.append(os.path.relpath(real, folder))


def _inside(folder: str, name: str) -> str | None:
    """``name`` (from a run list) as a path inside ``folder``, or None if it leads elsewhere."""
    if not isinstance(name, str) or os.path.isabs(name):
        return None
    path = os.path.join(folder, name)
    real = os.path.realpath(path)
    return path if real.startswith(folder + os.sep) and not os.path.islink(path) else None


@contextlib.contextmanager
def output_run(folder: str | os.PathLike | None) -> Iterator[list[str]]:
    """A command's run into its output ``folder`` (None: no folder, nothing done): the files the
    previous run listed in ``.dmdvox-run.json`` are removed before this run's first write there
    (a run refused before it writes leaves them; only regular files inside the folder: a list
    that names anything else is ignored), and the files this run writes are listed there on
    exit, whether the run finished or not, for the next run to remove. Yields the list of those
    files (relative to the folder) as it grows."""
    if folder is None:
        yield []
        return
    real = os.path.realpath(folder)
    run_list = Path(real) / RUN_LIST
    try:
        previous = json.loads(run_list.read_text(encoding="utf-8")).get("files", [])
    except (OSError, ValueError, AttributeError):
        previous = []
    _PREVIOUS[real] = previous if isinstance(previous, list) else []
    written = _RUNS.setdefault(real, [])
    try:
        yield written
    finally:
        _RUNS.pop(real, None)
        _PREVIOUS.pop(real, None)
        if written:  # a run that wrote nothing leaves the list (and the files) of the one before
            with contextlib.suppress(OSError, DmdvoxError):
                write_text(run_list, json.dumps({"files": sorted(set(written))}, indent=1))


@contextlib.contextmanager
def _signals_held() -> Iterator[None]:
    """SIGINT and SIGTERM held (delivered on exit). A signal mask would not do: it holds them
    for this thread only, and a process signal taken by one of numba's or OpenVDB's threads
    still raises KeyboardInterrupt here at the next bytecode. So the Python handlers are
    swapped for ones that only note the signal, and the noted ones are raised on exit."""
    if threading.current_thread() is not threading.main_thread():
        yield  # signal handlers run in the main thread only: nothing to hold here
        return
    noted: list[int] = []
    previous = {number: signal.signal(number, lambda signum, frame: noted.append(signum))
                for number in (signal.SIGINT, signal.SIGTERM)}
    try:
        yield
    finally:
        for number, handler in previous.items():
            signal.signal(number, handler)
        for number in noted:
            signal.raise_signal(number)


def write_bytes(target: str | os.PathLike, data: bytes) -> Path:
    with atomic_path(target) as tmp:
        tmp.write_bytes(data)
    return Path(target)


def write_text(target: str | os.PathLike, text: str) -> Path:
    return write_bytes(target, text.encode("utf-8"))
