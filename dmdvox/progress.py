"""What a long command says while it works: stage lines, counters, the compile notice.

Everything here goes to the logger ``dmdvox`` (:data:`LOGGER`); the library installs no handler
(a notebook sees nothing unless it configures :mod:`logging`, and silences a configured one with
``logging.getLogger("dmdvox").setLevel(logging.WARNING)``). The command line installs
:func:`to_stderr` for the length of a command, which writes each record as ``dmdvox: TEXT``.

* ``stage(name, detail)`` logs one short line at INFO, ``deposit: 232 segments, voxel 0.125
  mm``, which the CLI shows whether or not stderr is a terminal: a terminal user waiting on a
  phase with no count (a CAD level set, the pictures) learns what is going on, and a log shows
  where a run spent its time or stopped.
* ``step(name, detail)`` is a stage line at DEBUG: the phases within a long stage (the void
  search, each output file) that a user at a terminal watches go by, which a log does not need
  (its stage lines already show where a run stopped); the CLI shows DEBUG on a terminal only.
* ``counter(desc, unit)`` follows work with a count (slabs, tasks): a tqdm bar when stderr is a
  terminal and the logger shows INFO (:func:`bars`); otherwise a stage line at every tenth of
  the total, so that logs stay short.
* ``compile_notice(command)`` logs ``compiling kernels (first run only ...)`` once per process
  when numba's cache holds no machine code for a key kernel of the command: the first run after
  an install or an upgrade spends a minute compiling, and silence then looks like a hang. The
  test reads each kernel's cache index (a small pickle next to the source, which numba itself
  discards when the source changed): no compilation, about 0.1 ms a kernel.

Lines the CLI writes for these start with ``dmdvox: `` and never with ``dmdvox: error:``;
:func:`is_progress_line` tells them apart from the rest of stderr (warnings, errors).
"""

from __future__ import annotations

import contextlib
import importlib
import logging
import sys
from typing import Iterable, Iterator

PREFIX = "dmdvox: "
COMPILE_NOTICE = "compiling kernels (first run only; about a minute, cached for the next runs)"

# One or two kernels per family, each compiled only by the work it names: if its cache index is
# empty the family is compiled in this run. Names are "module:function".
_TOOLPATH = ("dmdvox.toolpath.gcode_kernel:interpret",)
_DEPOSIT = ("dmdvox.deposit.engine:_sweep_blocks", "dmdvox.grid.analysis:_leaf_fill")
_COMPARE = ("dmdvox.comparison.blocks:block_sums", "dmdvox.comparison.blocks:crossings")
_COLLIDE = ("dmdvox.collision.kernels:query",)
COMMAND_KERNELS = {
    "info": _TOOLPATH + ("dmdvox.toolpath.summary:_chord_lengths",),
    "simulate": _TOOLPATH + _DEPOSIT,
    "compare": _TOOLPATH + _DEPOSIT + _COMPARE,
    "render": _TOOLPATH + _DEPOSIT,
    "collide": _TOOLPATH + _DEPOSIT + _COLLIDE,
    "report": _TOOLPATH + _DEPOSIT + _COMPARE + _COLLIDE,
    "demo": _TOOLPATH + _DEPOSIT + _COMPARE + _COLLIDE,
    "view": _TOOLPATH + _DEPOSIT,
    "study": _TOOLPATH + _DEPOSIT,
    "check": _TOOLPATH + _DEPOSIT + _COMPARE + _COLLIDE,
    "diff": _TOOLPATH + _DEPOSIT + _COMPARE + ("dmdvox.changes:block_changes", "dmdvox.changes:changed_voxels"),
}

LOGGER = logging.getLogger("dmdvox")
LOGGER.addHandler(logging.NullHandler())  # a library's logger: no output until the application asks

_noticed = False


def _line(name: str, detail: str) -> str:
    return f"{name}{': ' + detail if detail else ''}"


def stage(name: str, detail: str = "") -> None:
    """One stage line at INFO: ``NAME: DETAIL``."""
    LOGGER.info("%s", _line(name, detail))


def step(name: str, detail: str = "") -> None:
    """A stage line at DEBUG (the CLI shows those on a terminal only)."""
    LOGGER.debug("%s", _line(name, detail))


def _stderr_is_terminal() -> bool:
    try:
        return sys.stderr.isatty()
    except (AttributeError, ValueError):
        return False


def bars() -> bool:
    """Whether counted work shows a tqdm bar: stderr is a terminal and the logger shows INFO."""
    return LOGGER.isEnabledFor(logging.INFO) and _stderr_is_terminal()


class _Stderr(logging.Handler):
    """``dmdvox: TEXT`` on whatever ``sys.stderr`` is at the time (tests and ``warm`` swap it)."""

    def emit(self, record: logging.LogRecord) -> None:
        try:
            print(f"{PREFIX}{record.getMessage()}", file=sys.stderr, flush=True)
        except (BrokenPipeError, ValueError):
            # stderr closed by the reader (or by the test harness): progress is not worth a failure
            pass


@contextlib.contextmanager
def to_stderr() -> Iterator[None]:
    """For the command line: the logger's records on stderr, DEBUG (the steps) on a terminal
    only; as it was on exit. Nested uses add nothing."""
    if any(isinstance(h, _Stderr) for h in LOGGER.handlers):
        yield
        return
    handler, level = _Stderr(), LOGGER.level
    LOGGER.addHandler(handler)
    LOGGER.setLevel(logging.DEBUG if _stderr_is_terminal() else logging.INFO)
    try:
        yield
    finally:
        LOGGER.removeHandler(handler)
        LOGGER.setLevel(level)


def is_progress_line(line: str) -> bool:
    """Whether a stderr line is one of this module's (not a warning, error or interruption)."""
    return line.startswith(PREFIX) and not line.startswith((f"{PREFIX}error:", f"{PREFIX}interrupted", f"{PREFIX}terminated"))


def without_progress(text: str) -> str:
    """``text`` (a command's stderr) without this module's lines."""
    return "".join(line for line in text.splitlines(keepends=True) if not is_progress_line(line))


class Counter:
    """Progress of counted work: ``update(done, total)``; ``close()`` at the end."""

    def __init__(self, desc: str, unit: str = "", total: int | None = None):
        self.desc = desc
        self.unit = unit
        self._bar = None
        self._tenth = -1
        if bars():
            from tqdm import tqdm

            self._bar = tqdm(total=total or 0, unit=unit or "it", desc=desc, file=sys.stderr, leave=False)

    def update(self, done: int, total: int) -> None:
        if self._bar is not None:
            self._bar.total = total
            self._bar.n = done
            self._bar.refresh()
            return
        tenth = int(10 * done / total) if total > 0 else 10
        if tenth > self._tenth:
            self._tenth = tenth
            stage(self.desc, f"{done:,d}/{total:,d}{' ' + self.unit if self.unit else ''}")

    def close(self) -> None:
        if self._bar is not None:
            self._bar.close()
            self._bar = None

    def __enter__(self) -> "Counter":
        return self

    def __exit__(self, *exc) -> None:
        self.close()


def counter(desc: str, unit: str = "", total: int | None = None) -> Counter:
    return Counter(desc, unit, total)


def _kernel(name: str):
    module, _, attr = name.partition(":")
    try:
        return getattr(importlib.import_module(module), attr)
    except (ImportError, AttributeError):
        return None  # renamed or moved: no notice rather than a failure


def is_cold(dispatcher) -> bool:
    """Whether numba's on-disk cache holds no machine code of ``dispatcher`` for this machine
    (its source changed since, it was never run, or it was compiled for another CPU)."""
    cache_file = getattr(getattr(dispatcher, "_cache", None), "_cache_file", None)
    if cache_file is None:
        return False  # not a cached numba function (or NUMBA_DISABLE_JIT): nothing to compile
    try:
        index = cache_file._load_index()  # {} when missing, stale or of another numba version
    except Exception:
        return False
    if not index:
        return True
    try:
        magic = dispatcher.targetctx.codegen().magic_tuple()
    except Exception:
        return False
    return not any(key[1] == magic for key in index)


def cold_kernels(names: Iterable[str]) -> list[str]:
    """Those of ``names`` (``module:function``) that would be compiled by this run."""
    return [n for n in names if (k := _kernel(n)) is not None and is_cold(k)]


def compile_notice(command: str) -> bool:
    """Print the compile notice (once per process) when a key kernel of ``command`` is cold."""
    global _noticed
    if _noticed or not cold_kernels(COMMAND_KERNELS.get(command, ())):
        return False
    _noticed = True
    stage(COMPILE_NOTICE)
    return True
