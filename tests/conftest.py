import os
import socket
import subprocess
import sys
from pathlib import Path

import pytest

# Headless rendering for every test that draws.
os.environ.setdefault("VTK_DEFAULT_OPENGL_WINDOW", "vtkEGLRenderWindow")

REPO = Path(__file__).resolve().parents[1]
DATA = REPO / "data"


@pytest.fixture
def gcode_file(tmp_path):
    """Write G-code text to a file and return its path."""
    counter = iter(range(1_000_000))

    def make(text: str, name: str | None = None) -> Path:
        path = tmp_path / (name or f"prog{next(counter)}.gcode")
        path.write_text(text)
        return path

    return make


def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


@pytest.fixture
def dask_cluster(tmp_path):
    pytest.importorskip("distributed")
    from distributed import Client

    dask_cli = str(Path(sys.executable).with_name("dask"))
    port = free_port()
    address = f"tcp://127.0.0.1:{port}"
    logs = [open(tmp_path / name, "w") for name in ("scheduler.log", "worker.log")]
    procs = [subprocess.Popen([dask_cli, "scheduler", "--host", "127.0.0.1", "--port", str(port),
                               "--dashboard-address", ":0", "--no-show"], stdout=logs[0], stderr=logs[0])]
    try:
        procs.append(subprocess.Popen([dask_cli, "worker", address, "--host", "127.0.0.1", "--nthreads", "1",
                                       "--nworkers", "2", "--dashboard-address", ":0", "--local-directory",
                                       str(tmp_path / "worker")], stdout=logs[1], stderr=logs[1]))
        with Client(address, timeout=30) as client:
            client.wait_for_workers(2, timeout=60)
        yield address
    finally:
        for proc in reversed(procs):
            proc.terminate()
        for proc in reversed(procs):
            try:
                proc.wait(timeout=20)
            except subprocess.TimeoutExpired:
                proc.kill()
                proc.wait()
        for log in logs:
            log.close()
