"""The warm-up's two processes: what each runs, and numba's cache files read and written under a lock."""

import fcntl
from pathlib import Path

import pytest

from dmdvox import warm


def test_the_parts_run_every_command_once_and_the_shared_kernels_first(tmp_path):
    cmds = warm.commands(tmp_path)
    first, comparing, others = warm.split(cmds)
    assert sorted(map(tuple, first + comparing + others)) == sorted(map(tuple, cmds))
    # alone first: up to the first simulate (the interpreter and the deposit kernels)
    assert first == cmds[:len(first)] and first[-1][0] == "simulate"
    assert all(argv[0] in ("info", "simulate") for argv in first)
    assert {argv[0] for argv in comparing} == {"compare", "diff"}
    assert not any(argv[0] in ("compare", "diff") for argv in others)
    # report calls both parts' kernels: last, after the collision ones in its own part
    assert [argv[0] for argv in others].count("report") == 1 and others[-1][0] == "report"
    assert "collide" in [argv[0] for argv in others]


def _held(lock: Path) -> bool:
    """Whether another open file description holds ``lock`` (flock locks are per description,
    so this process's own second open conflicts too)."""
    with open(lock, "a") as f:
        try:
            fcntl.flock(f, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except BlockingIOError:
            return True
        return False


@pytest.mark.parametrize("method", ["save", "load"])
def test_numba_cache_reads_and_writes_hold_the_lock(tmp_path, monkeypatch, method):
    from numba.core.caching import IndexDataCacheFile

    lock = tmp_path / "numba-cache.lock"
    seen = []

    def original(self, *args):
        seen.append((args, _held(lock)))
        return "result"

    # both restored after the test: the lock wraps both
    monkeypatch.setattr(IndexDataCacheFile, "save", IndexDataCacheFile.save)
    monkeypatch.setattr(IndexDataCacheFile, "load", IndexDataCacheFile.load)
    monkeypatch.setattr(IndexDataCacheFile, method, original)
    assert warm.lock_numba_cache_io(str(lock))
    assert getattr(IndexDataCacheFile, method)(None, "key", "data") == "result"
    assert seen == [(("key", "data"), True)]
    assert not _held(lock)  # released on return
