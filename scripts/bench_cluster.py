#!/usr/bin/env python3
"""A loopback dask cluster against one local process (issue 26, "Work that spreads"): the seed's
100 x 100 x 50.4 mm block (scripts/bench_scale.py) at 0.1 mm, ``simulate`` and ``compare`` each in
its own process, once locally with one numba thread and once with ``--scheduler`` on a
scheduler and two single-thread workers started here, every port on 127.0.0.1 (README).

Prints per command: wall time both ways and their ratio, the client's peak RSS (its own
high-water mark, from wait4) both ways, whether the JSON (timings left out) is identical, and
the workers that ran the sweep's chunks and the void search's tiles (the scheduler's task
stream). No deposit cache: every run sweeps and searches its own.

    .venv/bin/python scripts/bench_cluster.py [--size 100] [--commands simulate,compare] [--out DIR]
"""

from __future__ import annotations

import argparse
import json
import os
import socket
import subprocess
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

from bench_scale import block_part  # noqa: E402

ENV = {**os.environ, "DMDVOX_CACHE": "off", "NUMBA_NUM_THREADS": "1", "OMP_NUM_THREADS": "1"}
TASKS = ("sweep_chunk", "exterior_step", "void_step")


def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def run(argv: list[str]) -> dict:
    """One dmdvox command in its own process: wall time, peak RSS, its JSON without timings."""
    t = time.perf_counter()
    proc = subprocess.Popen([sys.executable, "-m", "dmdvox.cli", *map(str, argv), "--json"], stdout=subprocess.PIPE,
                            stderr=subprocess.DEVNULL, text=True, env=ENV)
    stdout = proc.stdout.read()
    _, status, usage = os.wait4(proc.pid, 0)
    elapsed = time.perf_counter() - t
    if os.waitstatus_to_exitcode(status) != 0:
        raise SystemExit(f"dmdvox {' '.join(map(str, argv))} failed: {stdout[-2000:]}")
    result = json.loads(stdout)
    result.pop("timings_s", None)
    for part in result.values():
        if isinstance(part, dict):
            part.pop("timings_s", None)
    return {"seconds": elapsed, "peak_rss_gb": usage.ru_maxrss * 1024 / 1e9, "result": result}


def start_cluster(folder: Path) -> tuple[str, list[subprocess.Popen]]:
    dask = str(Path(sys.executable).with_name("dask"))
    port = free_port()
    address = f"tcp://127.0.0.1:{port}"
    log = open(folder / "cluster.log", "w")
    procs = [subprocess.Popen([dask, "scheduler", "--host", "127.0.0.1", "--port", str(port), "--dashboard-address",
                               "127.0.0.1:0", "--no-show"], stdout=log, stderr=log, env=ENV)]
    procs.append(subprocess.Popen([dask, "worker", address, "--host", "127.0.0.1", "--dashboard-address", "127.0.0.1:0",
                                   "--nthreads", "1", "--nworkers", "2", "--local-directory", str(folder / "worker")],
                                  stdout=log, stderr=log, env=ENV))
    from distributed import Client

    with Client(address, timeout=60) as client:
        client.wait_for_workers(2, timeout=120)
    return address, procs


def stop(procs: list[subprocess.Popen]) -> None:
    for proc in reversed(procs):
        proc.terminate()
        try:
            proc.wait(timeout=30)
        except subprocess.TimeoutExpired:
            proc.kill()
            proc.wait()


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--size", type=float, default=100.0, help="block side (mm); 63 layers of 0.8 mm")
    parser.add_argument("--commands", default="simulate,compare")
    parser.add_argument("--out", default=None, help="keep the part and the logs here (default: a temporary folder)")
    args = parser.parse_args()
    from distributed import Client, get_task_stream

    print(f"load average {os.getloadavg()[0]:.1f} on {os.cpu_count()} cores")
    with tempfile.TemporaryDirectory() as tmp:
        folder = Path(args.out or tmp)
        folder.mkdir(parents=True, exist_ok=True)
        gcode, stl = block_part(folder, args.size)
        address, procs = start_cluster(folder)
        try:
            for command in args.commands.split(","):
                argv = [command, gcode, *([stl] if command == "compare" else []), "--voxel", "0.1"]
                local = run(argv)
                with Client(address, timeout=60) as client, get_task_stream(client) as stream:
                    remote = run([*argv, "--scheduler", address])
                workers = {}
                for task in stream.data:
                    kind = task["key"].split("-")[0]
                    if kind in TASKS:
                        workers.setdefault(kind, {}).setdefault(task["worker"], 0)
                        workers[kind][task["worker"]] += 1
                print(f"{command} {args.size:g} mm block at 0.1 mm "
                      f"({local['result'].get('active_voxels', local['result'].get('deposit', {}).get('active_voxels'))}"
                      " active voxels)")
                print(f"  local, 1 thread      {local['seconds']:7.1f} s   client peak RSS {local['peak_rss_gb']:6.2f} GB")
                print(f"  cluster, 2 x 1 thread {remote['seconds']:6.1f} s   client peak RSS "
                      f"{remote['peak_rss_gb']:6.2f} GB")
                print(f"  speed ratio {local['seconds'] / remote['seconds']:.2f}x, client memory ratio "
                      f"{remote['peak_rss_gb'] / local['peak_rss_gb']:.2f}, identical JSON: "
                      f"{local['result'] == remote['result']}")
                for kind in TASKS:
                    spread = ", ".join(f"{n} on {w}" for w, n in sorted(workers.get(kind, {}).items()))
                    print(f"  {kind:<13} {spread or 'none'}")
        finally:
            stop(procs)


if __name__ == "__main__":
    main()
