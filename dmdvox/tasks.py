"""One task runner for every stage: in this process, on local processes, or on a dask cluster.

Tasks are pure functions of picklable parameters, so where they run does not change what they
return: the deposit's slabs, the comparison's slabs and the studies' cases give identical
results in-process, on local processes and on a cluster (tests compare them bit for bit).

:func:`map_tasks` yields the results in task order as they arrive, holding only those that
came early, so a caller that merges them one by one (a grid builder) never holds them all.

* ``processes=0``: one after the other in this process (numba threads inside each task); the
  default for stages whose tasks are already parallel kernels.
* ``processes=None`` or ``N``: a ``spawn`` process pool (numba's thread pool is not safe to
  ``fork`` once the parent has used it; a fresh interpreter costs well under a second), each
  worker with an equal share of the cores for numba's threads.
* ``scheduler='tcp://host:port'``: a running dask.distributed scheduler (see the README: ``dask
  scheduler`` and ``dask worker``); dask is imported only then, so it stays an optional
  dependency (``pip install "dask[distributed]"``).
"""

from __future__ import annotations

import multiprocessing
import os
from concurrent.futures import ProcessPoolExecutor, as_completed
from typing import Callable, Iterable, Iterator, Sequence

from .errors import DependencyError, DmdvoxError

DASK_CONNECT_TIMEOUT_S = 10.0


def _set_numba_threads(threads: int) -> None:
    import numba

    numba.set_num_threads(max(1, min(threads, numba.config.NUMBA_NUM_THREADS)))


def _in_order(completed: Iterable[tuple[int, object]], n: int) -> Iterator:
    """Results arriving as ``(index, result)`` in any order, yielded in index order; only the
    ones that came before their turn are held."""
    early: dict[int, object] = {}
    turn = 0
    for index, result in completed:
        early[index] = result
        while turn in early:
            yield early.pop(turn)
            turn += 1
    if turn != n:
        raise DmdvoxError(f"{n - turn} of {n} tasks returned no result")


def _local(func: Callable, params: Sequence, processes: int | None) -> Iterator[tuple[int, object]]:
    cores = os.cpu_count() or 1
    workers = max(1, min(len(params), cores if processes is None else processes))
    context = multiprocessing.get_context("spawn")
    with ProcessPoolExecutor(max_workers=workers, mp_context=context, initializer=_set_numba_threads,
                             initargs=(max(1, cores // workers),)) as pool:
        futures = {pool.submit(func, p): k for k, p in enumerate(params)}
        for future in as_completed(futures):
            yield futures.pop(future), future.result()


def _dask(func: Callable, params: Sequence, scheduler: str) -> Iterator[tuple[int, object]]:
    try:
        from distributed import Client
        from distributed import as_completed as dask_completed
    except ImportError:
        raise DependencyError('--scheduler needs dask.distributed: pip install "dask[distributed]"') from None
    try:
        client = Client(scheduler, timeout=DASK_CONNECT_TIMEOUT_S)
    except (OSError, TimeoutError) as exc:
        raise DmdvoxError(f"--scheduler {scheduler}: cannot reach a dask scheduler ({exc}); "
                          "start one with `dask scheduler` and workers with `dask worker ADDRESS`") from None
    with client:
        # pure=False: tasks are deterministic, but dask must not merge equal parameter sets
        # into one key when the caller asked for them twice (rows stay one per parameter set).
        futures = client.map(func, params, pure=False)
        index = {f.key: k for k, f in enumerate(futures)}
        for future in dask_completed(futures):
            result = future.result()
            future.release()  # the worker may drop it: the caller merges it now
            yield index[future.key], result


def map_tasks(func: Callable, params: Sequence, *, scheduler: str | None = None, processes: int | None = 0,
              desc: str | None = None) -> Iterator:
    """``func(p) for p in params``, in order, run as the module docstring says; with ``desc``
    a progress counter on stderr (callers with their own progress leave it out). ``func`` must
    be a module-level function (it is pickled by reference)."""
    from .progress import counter

    params = list(params)
    if not params:
        return
    if scheduler:
        completed = _dask(func, params, scheduler)
    elif processes == 0:
        completed = ((k, func(p)) for k, p in enumerate(params))
    else:
        completed = _local(func, params, processes)
    if desc is None:
        yield from _in_order(completed, len(params))
        return
    # a bar on a terminal, a line per tenth of the tasks in a log
    with counter(desc, "tasks", len(params)) as bar:
        bar.update(0, len(params))
        for done, result in enumerate(_in_order(completed, len(params)), 1):
            bar.update(done, len(params))
            yield result


def run_tasks(func: Callable, params: Sequence, scheduler: str | None = None, *, workers: int | None = None,
              desc: str = "study") -> list:
    """``[func(p) for p in params]`` on local processes (``workers``, default one per core) or
    on the cluster at ``scheduler``: the studies' runner."""
    return list(map_tasks(func, params, scheduler=scheduler, processes=workers, desc=desc))
