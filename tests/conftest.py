import importlib
import math
import os
import shutil
import socket
import subprocess
import sys
import tempfile
from pathlib import Path

import pytest

# Headless rendering for every test that draws.
os.environ.setdefault("VTK_DEFAULT_OPENGL_WINDOW", "vtkEGLRenderWindow")
# No test reads or fills the user's deposit cache; tests/test_deposit_cache.py turns one on.
os.environ["DMDVOX_CACHE"] = "off"

REPO = Path(__file__).resolve().parents[1]
DATA = REPO / "data"


def numba_cache_folder(source_dir: Path, root: str | None) -> Path:
    """Where numba keeps the machine code of the kernels defined in ``source_dir``: beside the
    sources, or under ``root`` (NUMBA_CACHE_DIR) in a folder named after the source folder."""
    if not root:
        return source_dir / "__pycache__"
    from numba.core.caching import UserProvidedCacheLocator

    return Path(root) / UserProvidedCacheLocator.get_suitable_cache_subpath(str(source_dir / "any.py"))


def copy_numba_cache(into: Path, skip: str = "") -> None:
    """Copy dmdvox's compiled kernels from the cache this process uses (NUMBA_CACHE_DIR or beside
    the sources) into a cache rooted at ``into``, leaving out the files whose names start with
    ``skip``."""
    root = os.environ.get("NUMBA_CACHE_DIR")
    for source_dir in sorted({p.parent for p in (REPO / "dmdvox").rglob("*.py")}):
        here = numba_cache_folder(source_dir, root)
        kernels = [f for f in here.glob("*.nb[ic]") if not (skip and f.name.startswith(skip))] if here.is_dir() else []
        if kernels:
            there = numba_cache_folder(source_dir, str(into))
            there.mkdir(parents=True, exist_ok=True)
            for f in kernels:
                shutil.copy2(f, there / f.name)


# Under pytest-xdist (make test) each worker gets its own numba cache, a copy of the kernels setup
# compiled. numba saves a new signature of a kernel by rewriting the kernel's index and then its
# data file, each atomically but not the pair: two processes adding different signatures of one
# kernel at the same time can both take the same data file, leaving an index entry that points at
# the other signature's machine code. Kernels setup did not compile are then compiled once per
# worker instead. The subprocesses a test starts inherit the variable, so they share their
# worker's cache, one at a time.
_WORKER_NUMBA_CACHE = None
if os.environ.get("PYTEST_XDIST_WORKER"):
    _WORKER_NUMBA_CACHE = Path(tempfile.mkdtemp(prefix=f"dmdvox-numba-{os.environ['PYTEST_XDIST_WORKER']}-"))
    copy_numba_cache(_WORKER_NUMBA_CACHE)
    os.environ["NUMBA_CACHE_DIR"] = str(_WORKER_NUMBA_CACHE)
    if "numba" in sys.modules:
        sys.modules["numba"].config.reload_config()


def pytest_unconfigure(config):
    if _WORKER_NUMBA_CACHE is not None:
        shutil.rmtree(_WORKER_NUMBA_CACHE, ignore_errors=True)


def demo_void_percent() -> float:
    """The void of the demo block in its CAD box, in percent of the box, in closed form.

    data/demo_block.gcode (scripts/make_demo_part.py): 8 layers of rect beads 2.5 mm wide and
    0.75 mm high (the layer step: layers stack with no gap), each layer a zigzag of 15 tracks
    1.25 mm apart from 1.25 to 18.75 mm, joined at alternate ends by 1.25 mm links; the CAD box
    is 20 x 20 x 6 mm. Every vertex of the path is the bead revolved (a disc of r = 1.25 mm), so
    a layer covers the square except
    * at its 4 corners, beyond the quarter circle about the last track end: r^2 (1 - pi/4) each;
    * at the 14 places on the end walls (7 a side) where two track ends 1.25 mm = r apart are not
      linked: the strip between them and the wall, outside both discs: r^2 - 2 (pi r^2 / 4) +
      r^2 (pi/3 - sqrt(3)/4) (their lens, half of it on the wall's side) = r^2 (1 - pi/6 - sqrt(3)/4).
    """
    r, h, layers, side = 1.25, 0.75, 8, 20.0
    per_layer = 4 * r**2 * (1 - math.pi / 4) + 14 * r**2 * (1 - math.pi / 6 - math.sqrt(3) / 4)
    return 100.0 * layers * h * per_layer / (side * side * layers * h)


DEMO_MAX_UNDERFILL_MM = 1.25 * (math.sqrt(2) - 1)  # the box corner to the last track end's disc


@pytest.fixture
def gcode_file(tmp_path):
    """Write G-code text to a file and return its path."""
    counter = iter(range(1_000_000))

    def make(text: str, name: str | None = None) -> Path:
        path = tmp_path / (name or f"prog{next(counter)}.gcode")
        path.write_text(text)
        return path

    return make


INSTALL = "scripts/setup.sh installs it (make test runs it)"


def require_module(name: str, what: str, install: str = INSTALL):
    """Import ``name`` or fail the test: CI installs every dependency, so a missing one is a
    broken install, not a reason to skip."""
    try:
        return importlib.import_module(name)
    except ImportError as exc:
        pytest.fail(f"{what} is not importable ({exc}); {install}", pytrace=False)


def require_tool(names: tuple[str, ...], what: str, install: str = INSTALL) -> str:
    """The path of the first of ``names`` on PATH, or fail the test (see :func:`require_module`)."""
    for name in names:
        path = shutil.which(name)
        if path:
            return path
    pytest.fail(f"{what} ({' or '.join(names)}) is not on PATH; {install}", pytrace=False)


DEV_EXTRAS = 'scripts/setup.sh installs it with the dev extras (pip install -e ".[dev]")'


def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


@pytest.fixture
def dask_cluster(tmp_path):
    Client = require_module("distributed", "dask.distributed", DEV_EXTRAS).Client

    dask_cli = str(Path(sys.executable).with_name("dask"))
    port = free_port()
    address = f"tcp://127.0.0.1:{port}"
    logs = [open(tmp_path / name, "w") for name in ("scheduler.log", "worker.log")]
    procs = [subprocess.Popen([dask_cli, "scheduler", "--host", "127.0.0.1", "--port", str(port),
                               "--dashboard-address", "127.0.0.1:0", "--no-show"], stdout=logs[0], stderr=logs[0])]
    try:
        procs.append(subprocess.Popen([dask_cli, "worker", address, "--host", "127.0.0.1", "--nthreads", "1",
                                       "--nworkers", "2", "--dashboard-address", "127.0.0.1:0", "--local-directory",
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
