"""The memory budget every command checks before it allocates (bottom floor, like errors)."""

from __future__ import annotations

import os
from collections.abc import Mapping

import numpy as np

from .errors import ResourceError

BUDGET_SHARE = 0.8  # of the available memory, unless --max-memory says otherwise


def available_memory() -> int:
    """Bytes the system can give without swapping (MemAvailable), else its physical memory."""
    try:
        with open("/proc/meminfo") as fh:
            for line in fh:
                if line.startswith("MemAvailable:"):
                    return int(line.split()[1]) * 1024
    except OSError:
        pass
    return int(os.sysconf("SC_PAGE_SIZE") * os.sysconf("SC_PHYS_PAGES"))


def budget(limit: int | None) -> int:
    """The bytes a command may use: ``--max-memory`` when given, else a share of what is free."""
    return limit if limit is not None else int(available_memory() * BUDGET_SHARE)


def budget_phrase(limit: int | None) -> str:
    """How a refusal names the budget: what ``--max-memory`` allows is not what is available."""
    allowed = budget(limit)
    if limit is not None:
        return f"--max-memory allows {allowed / 2**30:.3g} GiB"
    return f"{allowed / 2**30:.3g} GiB is available"


def check_memory(parts: Mapping[str, int], voxel: float, limit: int | None) -> None:
    """Refuse a run that would hold ``parts`` (name -> bytes: the deposit, a CAD part, the
    nozzle...) together beyond the budget, naming a voxel size that would fit."""
    total = int(sum(parts.values()))
    if total <= budget(limit):
        return
    # Active voxels scale as 1/voxel^2 (surface area times a band of fixed voxel count).
    suggested = voxel * np.sqrt(total / budget(limit)) * 1.1
    named = [f"{name} {size / 2**30:.3g}" for name, size in parts.items() if size > 0]
    breakdown = f" ({', '.join(named)})" if len(named) > 1 else ""
    what = "the grid" if len(parts) == 1 else "the run"
    raise ResourceError(
        f"--voxel {voxel:g}: {what} needs about {total / 2**30:.3g} GiB{breakdown} but {budget_phrase(limit)}; "
        f"use --voxel {np.ceil(suggested * 1000) / 1000:g} or larger (or raise --max-memory)"
    )
