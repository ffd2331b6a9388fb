"""The memory budget every command checks before it allocates (bottom floor, like errors)."""

from __future__ import annotations

import os
from collections.abc import Iterable, Mapping

import numpy as np

from .errors import ResourceError

BUDGET_SHARE = 0.8  # of the available memory, unless --max-memory says otherwise


# What a run holds after its sweep, per leaf of the deposit grid (a block the surface's band
# crosses), beside the deposit itself. Peak RSS of `simulate` on five parts (thin wall, solid
# block, sparse infill, five-axis tube, slicer file: tests/test_memory_estimate.py) follows the
# leaves, not the bounding box:
# * the void search (grid.enclosure): per work block (every leaf, and outside tiles the channel
#   rule reaches) its state, depth, labels and clearance distances (uint8, float32, uint16,
#   float64 per voxel) and its 27 neighbours;
# * the outputs: OpenVDB's copy of the grid (an sdf and an arrival leaf of 512 float32 with their
#   masks) while the .vdb is written and the surface meshed, and the surface mesh (about 37
#   vertices a leaf, 33-41 over the five parts: a band of 6 voxels around the surface spans 1.75
#   block layers of 8), each vertex with its position and arrival (float64) and two triangles
#   (int64 indices and VTK offsets).
POROSITY_LEAF_BYTES = 512 * (1 + 4 + 2 + 8) + 27 * 8
VDB_LEAF_BYTES = 2 * (512 * 4 + 3 * 64 + 96)
SURFACE_VERTICES_PER_LEAF = 37
SURFACE_VERTEX_BYTES = 3 * 8 + 8 + 2 * (3 * 8 + 8)
OUTPUTS_LEAF_BYTES = VDB_LEAF_BYTES + SURFACE_VERTICES_PER_LEAF * SURFACE_VERTEX_BYTES
# the steps a run may take after its sweep, and what each holds per leaf at its peak
AFTER_SWEEP = {"porosity": POROSITY_LEAF_BYTES, "outputs": OUTPUTS_LEAF_BYTES}


def after_sweep(leaves: float, steps: Iterable[str]) -> int:
    """Bytes the run holds beside its deposit grid at the peak of the later ``steps`` (names of
    :data:`AFTER_SWEEP`; one at a time: each frees its work before the next) for a grid of
    ``leaves`` leaves."""
    return int(leaves * max([0] + [AFTER_SWEEP[step] for step in steps]))


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
        return f"{{max_memory_gib}} allows {allowed / 2**30:.3g} GiB"
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
        f"{{voxel}} {voxel:g}: {what} needs about {total / 2**30:.3g} GiB{breakdown} but {budget_phrase(limit)}; "
        f"use {{voxel}} {np.ceil(suggested * 1000) / 1000:g} or larger (or raise {{max_memory_gib}})",
        parameter="voxel", also=("max_memory_gib",))
