"""The memory budget every command checks before it allocates (bottom floor, like errors)."""

from __future__ import annotations

import os

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


def check_memory(estimate: int, voxel: float, limit: int | None) -> None:
    """Refuse a grid of ``estimate`` bytes beyond the budget, with a voxel size that would fit."""
    allowed = budget(limit)
    if estimate <= allowed:
        return
    # Active voxels scale as 1/voxel^2 (surface area times a band of fixed voxel count).
    suggested = voxel * np.sqrt(estimate / allowed) * 1.1
    raise ResourceError(
        f"--voxel {voxel:g}: the grid needs about {estimate / 2**30:.3g} GiB but {allowed / 2**30:.3g} GiB is "
        f"available; use --voxel {np.ceil(suggested * 1000) / 1000:g} or larger (or raise --max-memory)"
    )
