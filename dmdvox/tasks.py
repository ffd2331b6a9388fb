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

import itertools
import multiprocessing
import os
from collections.abc import Callable, Iterable, Iterator, Sequence, Sized
from concurrent.futures import ProcessPoolExecutor, as_completed

from .errors import DependencyError, DmdvoxError

DASK_CONNECT_TIMEOUT_S = 10.0


def _set_numba_threads(threads: int) -> None:
    import numba

    numba.set_num_threads(max(1, min(threads, numba.config.NUMBA_NUM_THREADS)))


def _in_order(completed: Iterable[tuple[int, object]], n: int | None) -> Iterator:
    """Results arriving as ``(index, result)`` in any order, yielded in index order; only the
    ones that came before their turn are held. ``n``: how many there must be, when known."""
    early: dict[int, object] = {}
    turn = 0
    for index, result in completed:
        early[index] = result
        while turn in early:
            yield early.pop(turn)
            turn += 1
    if early or (n is not None and turn != n):
        raise RuntimeError(f"task results {sorted(early)} came without those before them ({turn} of {n} merged)")


def _local(func: Callable, params: Sequence, processes: int | None) -> Iterator[tuple[int, object]]:
    cores = os.cpu_count() or 1
    workers = max(1, min(len(params), cores if processes is None else processes))
    context = multiprocessing.get_context("spawn")
    with ProcessPoolExecutor(max_workers=workers, mp_context=context, initializer=_set_numba_threads,
                             initargs=(max(1, cores // workers),)) as pool:
        futures = {pool.submit(func, p): k for k, p in enumerate(params)}
        for future in as_completed(futures):
            yield futures.pop(future), future.result()


def _client(scheduler: str):
    try:
        from distributed import Client
    except ImportError:
        raise DependencyError('--scheduler needs dask.distributed: pip install "dask[distributed]"') from None
    try:
        return Client(scheduler, timeout=DASK_CONNECT_TIMEOUT_S)
    except (OSError, TimeoutError, ValueError) as exc:  # ValueError: an address dask cannot parse
        raise DmdvoxError(f"--scheduler {scheduler}: cannot reach a dask scheduler ({exc}); "
                          "start one with `dask scheduler` and workers with `dask worker ADDRESS`") from None


def cluster_threads(scheduler: str) -> int:
    """The threads the cluster at ``scheduler`` runs tasks on now (its workers' summed), at least
    1: for callers that cut their work so that every worker gets some."""
    with _client(scheduler) as client:
        return max(1, sum(client.nthreads().values()))


def _dask(func: Callable, params: Iterable, scheduler: str) -> Iterator[tuple[int, object]]:
    client = _client(scheduler)
    from distributed import as_completed as dask_completed

    with client:
        # A window of tasks in flight, refilled as results come: the client never holds every
        # task's parameters (a slab of a grid each) nor every result at once.
        window = max(2, 2 * sum(client.nthreads().values()))
        pending = iter(enumerate(params))
        index = {}

        def submit(count: int) -> list:
            futures = []
            for k, p in itertools.islice(pending, count):
                # pure=False: tasks are deterministic, but dask must not merge equal parameter
                # sets into one key when the caller asked for them twice
                future = client.submit(func, p, pure=False)
                index[future.key] = k
                futures.append(future)
            return futures

        running = dask_completed(submit(window))
        for future in running:
            result = future.result()
            k = index.pop(future.key)
            future.release()  # the worker may drop it: the caller merges it now
            for more in submit(1):
                running.add(more)
            yield k, result


def map_tasks(func: Callable, params: Iterable, *, scheduler: str | None = None, processes: int | None = 0,
              desc: str | None = None, total: int | None = None) -> Iterator:
    """``func(p) for p in params``, in order, run as the module docstring says; with ``desc``
    a progress counter on stderr (callers with their own progress leave it out). ``func`` must
    be a module-level function (it is pickled by reference). In this process and on a cluster
    ``params`` may be a generator, drawn as tasks are started (``total``: its length, for the
    counter)."""
    from .progress import counter

    if total is None and isinstance(params, Sized):
        total = len(params)
    if scheduler:
        results = _in_order(_dask(func, params, scheduler), total)
    elif processes == 0:
        results = (func(p) for p in params)
    else:
        params = list(params)
        total = len(params)
        results = _in_order(_local(func, params, processes), total) if params else iter(())
    if desc is None or not total:
        yield from results
        return
    # a bar on a terminal, a line per tenth of the tasks in a log
    with counter(desc, "tasks", total) as bar:
        bar.update(0, total)
        for done, result in enumerate(results, 1):
            bar.update(done, total)
            yield result


def run_tasks(func: Callable, params: Sequence, scheduler: str | None = None, *, workers: int | None = None,
              desc: str = "study") -> list:
    """``[func(p) for p in params]`` on local processes (``workers``, default one per core) or
    on the cluster at ``scheduler``: the studies' runner."""
    return list(map_tasks(func, params, scheduler=scheduler, processes=workers, desc=desc))
