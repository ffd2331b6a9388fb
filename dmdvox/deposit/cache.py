"""A deposit swept once serves the commands after it: `simulate`, then `compare`, then `report`
on the same program sweep its beads and search its voids once, not three times (on a 100 mm
block at 0.1 mm that is about 30 s a command).

What is kept: the deposit's grid, its voids and the beads as laid and landed, in one
uncompressed ``.npz`` (no pickles: a file planted in the folder cannot run code), named by a
SHA-256 key over everything that determines them, known before any bead is laid
(:meth:`DepositCache.plan_key`: the planned program and its settings, the voxel size, ``until``),
so that a hit skips laying and landing too, and the code itself (the hash of every source file of the installed
package, numpy's and numba's versions). A changed program, option or dmdvox gives another key,
so an entry is never stale, only unused; the folder keeps the most recently used entries up to
:data:`~dmdvox.defaults.CACHE_MAX_BYTES` and drops the rest. An entry that cannot be read is
said on stderr, removed and swept again; so is one whose bytes no longer match the SHA-256
kept beside it (``KEY.sha256``, written when the entry was): an edited or damaged entry is
never trusted, however well it loads.

Only deposits of :data:`~dmdvox.defaults.CACHE_MIN_ACTIVE_VOXELS` or more are kept (below that
the sweep takes about as long as the file). ``DMDVOX_CACHE`` names the folder (default
``$XDG_CACHE_HOME/dmdvox/deposits``, else ``~/.cache/dmdvox/deposits``); ``DMDVOX_CACHE=off``
turns the cache off.
"""

from __future__ import annotations

import dataclasses
import hashlib
import json
import os
import shutil
import sys
import zipfile
from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path

import numba
import numpy as np

from .. import __version__
from ..defaults import CACHE_MAX_BYTES, CACHE_MIN_ACTIVE_VOXELS
from ..errors import DmdvoxError
from ..grid.analysis import Porosity, porosity_of
from ..grid.enclosure import Voids
from ..grid.sparse import SparseGrid
from ..io.atomic import atomic_path, write_text
from ..memory import after_sweep, check_memory
from ..process.beads import Beads
from ..process.landing import Landing
from ..process.plan import LaidBeads, ProcessPlan

FORMAT = 1  # the layout of an entry; a new layout is a new key
ENVIRONMENT = "DMDVOX_CACHE"
OFF = ("off", "0", "no", "false")


def _warn(text: str) -> None:
    print(f"dmdvox: {text}", file=sys.stderr, flush=True)


@lru_cache(maxsize=1)
def code_fingerprint() -> str:
    """SHA-256 over the package's source files (path and bytes) and the numeric libraries'
    versions: what a change of the code that sweeps or searches must change."""
    package = Path(__file__).resolve().parents[1]
    digest = hashlib.sha256(f"dmdvox {__version__} numpy {np.__version__} numba {numba.__version__}".encode())
    for path in sorted(package.rglob("*.py")):
        digest.update(str(path.relative_to(package)).encode() + b"\0")
        digest.update(path.read_bytes() + b"\0")
    return digest.hexdigest()


def file_digest(path: Path) -> str:
    """SHA-256 of a file's bytes, read in pieces (an entry may be GBs)."""
    digest = hashlib.sha256()
    with open(path, "rb") as fh:
        for piece in iter(lambda: fh.read(1 << 24), b""):
            digest.update(piece)
    return digest.hexdigest()


def _arrays_and_values(obj) -> tuple[dict[str, np.ndarray], dict]:
    arrays, values = {}, {}
    for f in dataclasses.fields(obj):
        value = getattr(obj, f.name)
        if isinstance(value, np.ndarray):
            arrays[f.name] = value
        else:
            values[f.name] = value
    return arrays, values


def _digest_into(digest, obj) -> None:
    """Feed ``obj`` (arrays, dataclasses, containers, scalars) into ``digest``, field by field.
    A value known only by its repr (an object's address in it) gives another key each run: a
    miss, never a wrong entry."""
    if isinstance(obj, np.ndarray):
        array = np.ascontiguousarray(obj)
        digest.update(f"array {array.dtype.str} {array.shape}".encode())
        if array.dtype.hasobject:
            digest.update(repr(array.tolist()).encode())
        elif array.size:
            digest.update(memoryview(array).cast("B"))
    elif dataclasses.is_dataclass(obj) and not isinstance(obj, type):
        digest.update(f"{type(obj).__qualname__}(".encode())
        for f in dataclasses.fields(obj):
            digest.update(f.name.encode() + b"=")
            _digest_into(digest, getattr(obj, f.name))
        digest.update(b")")
    elif isinstance(obj, dict):
        digest.update(f"dict {len(obj)}".encode())
        for k in sorted(obj, key=str):
            digest.update(str(k).encode() + b":")
            _digest_into(digest, obj[k])
    elif isinstance(obj, (list, tuple)):
        digest.update(f"seq {len(obj)}".encode())
        for item in obj:
            _digest_into(digest, item)
    else:
        digest.update(f"{type(obj).__name__} {obj!r}".encode())


def _laid_members(laid: LaidBeads) -> tuple[dict, dict]:
    """The laid beads as the entry's arrays (``laid.``) and its header's values."""
    parts = {"beads": laid.beads, "programmed": laid.programmed}
    values = {"until": laid.until, "landing": None}
    if laid.landing is not None:
        parts["landing"] = laid.landing
        parts["landing_programmed"] = laid.landing.programmed
    arrays = {}
    for name, part in parts.items():
        part_arrays, part_values = _arrays_and_values(part)
        part_values.pop("programmed", None)
        arrays.update({f"laid.{name}.{k}": v for k, v in part_arrays.items()})
        values[name] = part_values
    return arrays, values


def _laid_from(values: dict, members: dict) -> LaidBeads:
    def arrays(name):
        prefix = f"laid.{name}."
        return {k[len(prefix):]: v for k, v in members.items() if k.startswith(prefix)}

    landing = None
    if values["landing"] is not None:
        landing = Landing(**values["landing"], **arrays("landing"),
                          programmed=Beads(**values["landing_programmed"], **arrays("landing_programmed")))
    return LaidBeads(beads=Beads(**values["beads"], **arrays("beads")),
                     programmed=Beads(**values["programmed"], **arrays("programmed")), landing=landing,
                     until=values["until"])


@dataclass(frozen=True)
class DepositCache:
    """The entries in ``folder``, kept up to ``max_bytes``, for deposits of at least
    ``min_active_voxels``."""

    folder: Path
    max_bytes: int = CACHE_MAX_BYTES
    min_active_voxels: int = CACHE_MIN_ACTIVE_VOXELS

    @classmethod
    def from_environment(cls) -> DepositCache | None:
        """The cache ``DMDVOX_CACHE`` names (module docstring); None when it is off."""
        setting = os.environ.get(ENVIRONMENT)
        if setting is not None:
            return None if setting.strip().lower() in OFF else cls(Path(setting).expanduser())
        base = os.environ.get("XDG_CACHE_HOME") or Path.home() / ".cache"
        return cls(Path(base) / "dmdvox" / "deposits")

    def plan_key(self, plan: ProcessPlan, voxel: float, until: float | None) -> str:
        """The entry's name before any bead is laid: the planned program (its toolpath, motion,
        material, sections, bead, model and settings), the voxel, ``until`` and the code; an entry
        under it holds the laid beads too (:meth:`store` with ``laid``), so a hit skips laying and
        landing."""
        digest = hashlib.sha256(json.dumps({"format": FORMAT, "code": code_fingerprint(), "voxel": float(voxel),
                                            "until": None if until is None else float(until)}).encode())
        for name in ("toolpath", "motion", "flow", "sections", "profile", "model", "settings"):
            digest.update(name.encode() + b"\0")
            _digest_into(digest, getattr(plan, name))
        return "plan-" + digest.hexdigest()

    def path(self, key: str) -> Path:
        return self.folder / f"{key}.npz"

    def checksum_path(self, key: str) -> Path:
        return self.folder / f"{key}.sha256"

    def load(self, key: str, voxel: float, max_memory: int | None, also_holds: dict[str, int] | None = None,
             steps=()) -> tuple | None:
        """The grid, porosity and laid beads (None if the entry has none) kept under ``key``, and
        the run's estimated peak, as ``(grid, porosity, peak, laid)``; or None. The
        memory check runs before the arrays are read, as it would on the sweep's estimate: the
        entry's size and what the ``steps`` after it hold for its leaves
        (:func:`~dmdvox.memory.after_sweep`)."""
        path = self.path(key)
        try:
            size = path.stat().st_size
        except OSError:
            return None
        try:
            kept = self.checksum_path(key).read_text(encoding="ascii").strip()
        except (OSError, UnicodeError):
            kept = None
        try:
            if kept != file_digest(path):
                _warn(f"the cached deposit {path} does not match its checksum (edited or damaged); "
                      "removing it and sweeping again")
                self._remove(key)
                return None
        except OSError:
            return None
        try:
            with np.load(path, allow_pickle=False) as entry:
                after = after_sweep(entry["grid.leaf_coord"].shape[0], steps) if steps else 0
                parts = {"deposit": size + after, **(also_holds or {})}
                check_memory(parts, voxel, max_memory)
                header = json.loads(str(entry["header"]))
                if header["format"] != FORMAT or header["key"] != key:
                    raise ValueError("its header names another entry")
                members = {name: entry[name] for name in entry.files if name != "header"}
            grid = SparseGrid(**header["grid"], **{k[5:]: v for k, v in members.items() if k.startswith("grid.")})
            voids = Voids(**header["voids"], **{k[6:]: v for k, v in members.items() if k.startswith("voids.")})
            result = porosity_of(voids, header["deposit_volume_mm3"])
            laid = _laid_from(header["laid"], members) if header.get("laid") else None
        except (OSError, ValueError, KeyError, TypeError, zipfile.BadZipFile) as exc:
            _warn(f"the cached deposit {path} cannot be read ({exc}); removing it and sweeping again")
            self._remove(key)
            return None
        os.utime(path)  # recently used: the last to be dropped
        return grid, result, int(sum(parts.values())), laid

    def store(self, key: str, grid: SparseGrid, result: Porosity, laid: LaidBeads | None = None) -> Path | None:
        """Keep ``grid`` and ``result`` (and the ``laid`` beads) under ``key`` when the deposit is
        large enough to be worth it and the disk has room; a failure to write is said, never fatal."""
        if grid.active_voxels < self.min_active_voxels:
            return None
        grid_arrays, grid_values = _arrays_and_values(grid)
        void_arrays, void_values = _arrays_and_values(result.voids)
        header = {"format": FORMAT, "key": key, "grid": grid_values, "voids": void_values,
                  "deposit_volume_mm3": result.deposit_volume_mm3}
        laid_arrays = {}
        if laid is not None:
            laid_arrays, header["laid"] = _laid_members(laid)
        members = {"header": np.array(json.dumps(header)),
                   **{f"grid.{k}": v for k, v in grid_arrays.items()},
                   **{f"voids.{k}": v for k, v in void_arrays.items()}, **laid_arrays}
        size = sum(v.nbytes for v in members.values())
        target = self.path(key)
        try:
            self.folder.mkdir(parents=True, exist_ok=True)
            if size > self.max_bytes or shutil.disk_usage(self.folder).free < 2 * size:
                return None
            with atomic_path(target) as tmp:
                with open(tmp, "wb") as fh:
                    np.savez(fh, **members)
                digest = file_digest(tmp)
            # after the entry: an entry without its checksum (a run stopped between the two) is
            # not trusted
            write_text(self.checksum_path(key), digest + "\n")
        except (OSError, DmdvoxError) as exc:
            _warn(f"the deposit could not be kept in {self.folder} for the next command ({exc}); "
                  f"set {ENVIRONMENT} to a writable folder, or to 'off'")
            return None
        self._trim(keep=target)
        return target

    def _remove(self, key: str) -> None:
        self.path(key).unlink(missing_ok=True)
        self.checksum_path(key).unlink(missing_ok=True)

    def _trim(self, keep: Path) -> None:
        """Drop the least recently used entries beyond ``max_bytes``."""
        entries = []
        for entry in os.scandir(self.folder):
            if entry.name.endswith(".npz") and entry.path != str(keep):
                try:
                    stat = entry.stat()
                except OSError:
                    continue
                entries.append((stat.st_mtime, stat.st_size, entry.path))
        total = sum(size for _, size, _ in entries) + keep.stat().st_size
        for _, size, path in sorted(entries):
            if total <= self.max_bytes:
                break
            self._remove(Path(path).stem)
            total -= size


__all__ = ["DepositCache", "code_fingerprint"]
