"""Atomic output files: written beside the target under a temporary name, renamed into place.

An interrupted run (Ctrl-C, a killed process) leaves either the previous file or none, never
a partial one.
"""

from __future__ import annotations

import contextlib
import os
import tempfile
from pathlib import Path
from typing import Iterator

from ..errors import DmdvoxError


@contextlib.contextmanager
def atomic_path(target: str | os.PathLike, suffix: str | None = None) -> Iterator[Path]:
    """Yield a temporary path in the target's folder; rename it onto ``target`` on success.

    ``suffix`` defaults to the target's own, for writers that choose a format by extension.
    """
    target = Path(target)
    folder = target.parent if str(target.parent) else Path(".")
    try:
        folder.mkdir(parents=True, exist_ok=True)
        fd, tmp_name = tempfile.mkstemp(
            prefix=f".{target.name}.part-", suffix=target.suffix if suffix is None else suffix, dir=folder
        )
    except OSError as exc:
        raise DmdvoxError(f"{target}: cannot write output ({exc.strerror}); choose a writable --out folder") from exc
    os.close(fd)
    tmp = Path(tmp_name)
    # mkstemp creates 0600; results are ordinary files, so follow the umask like open() does.
    umask = os.umask(0)
    os.umask(umask)
    os.chmod(tmp, 0o666 & ~umask)
    try:
        yield tmp
        os.replace(tmp, target)
    except BaseException:
        with contextlib.suppress(FileNotFoundError):
            tmp.unlink()
        raise


def write_bytes(target: str | os.PathLike, data: bytes) -> Path:
    with atomic_path(target) as tmp:
        tmp.write_bytes(data)
    return Path(target)


def write_text(target: str | os.PathLike, text: str) -> Path:
    return write_bytes(target, text.encode("utf-8"))
