"""Run study tasks on local processes or on a dask.distributed cluster, results in task order.

Tasks are pure functions of picklable parameters, so where they run does not change what they
return: local processes and a cluster give identical tables (tests compare them bit for bit).

Local runs use a ``spawn`` process pool: numba's thread pool is not safe to ``fork`` once the
parent has used it, and a fresh interpreter costs well under a second. Each worker gets an
equal share of the cores for numba's threads, so workers x threads never exceeds the machine.

``scheduler='tcp://host:port'`` sends the tasks to a running dask scheduler (see the README:
``dask scheduler`` and ``dask worker``); dask is imported only then, so it stays an optional
dependency (``pip install "dask[distributed]"``).
"""

from __future__ import annotations

import multiprocessing
import os
from concurrent.futures import ProcessPoolExecutor, as_completed
from typing import Callable, Sequence

from ..errors import DependencyError, DmdvoxError

DASK_CONNECT_TIMEOUT_S = 10.0


def _set_numba_threads(threads: int) -> None:
    import numba

    numba.set_num_threads(max(1, min(threads, numba.config.NUMBA_NUM_THREADS)))


def _run_local(func: Callable, params: Sequence, workers: int | None, bar) -> list:
    cores = os.cpu_count() or 1
    workers = max(1, min(len(params), cores if workers is None else workers))
    results: list = [None] * len(params)
    context = multiprocessing.get_context("spawn")
    with ProcessPoolExecutor(max_workers=workers, mp_context=context, initializer=_set_numba_threads,
                             initargs=(max(1, cores // workers),)) as pool:
        futures = {pool.submit(func, p): k for k, p in enumerate(params)}
        for done, future in enumerate(as_completed(futures), 1):
            results[futures[future]] = future.result()
            bar.update(done, len(results))
    return results


def _run_dask(func: Callable, params: Sequence, scheduler: str, bar) -> list:
    try:
        from distributed import Client, as_completed as dask_completed
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
        results: list = [None] * len(params)
        for done, future in enumerate(dask_completed(futures), 1):
            results[index[future.key]] = future.result()
            bar.update(done, len(results))
    return results


def run_tasks(func: Callable, params: Sequence, scheduler: str | None = None, *, workers: int | None = None,
              desc: str = "study") -> list:
    """``[func(p) for p in params]``, run in parallel: on local processes (``workers``, default
    one per core) or, with ``scheduler`` (``tcp://host:port``), on a dask.distributed cluster.

    ``func`` must be a module-level function (it is pickled by reference).
    """
    params = list(params)
    if not params:
        return []
    from ..progress import counter

    # a bar on a terminal, a line per tenth of the tasks in a log
    with counter(desc, "tasks", len(params)) as bar:
        bar.update(0, len(params))
        if scheduler:
            return _run_dask(func, params, scheduler, bar)
        return _run_local(func, params, workers, bar)
