"""The deepest point of a region, beyond the narrow band, by branch and bound on blocks.

Underfill depth is the largest distance from a void voxel (inside the CAD, outside the deposit)
to the deposit; overbuild depth the largest distance from an overbuild voxel to the CAD. Within
the other grid's narrow band its SDF is that distance (:func:`.blocks.block_sums`); beyond it
the SDF is clamped and the distance is measured exactly, against the other solid's surface
(a :class:`.distance.MeshDistance`), but only where it can matter:

1. every block holding such a far voxel is bounded: the distance is 1-Lipschitz, so no voxel
   of the block lies farther than ``d(centre) + half its diagonal``;
2. blocks are visited by descending bound, their far voxels measured one by one, and the
   search stops when the next bound cannot beat the deepest voxel found.

The result is the exact maximum over the region's voxel centres, with a distance query per
bounded block and per voxel of the few deepest blocks: no array over the region or the box.
"""

from __future__ import annotations

import numpy as np
from numba import njit, prange

from ..grid.sparse import BLOCK_VOXELS, block_sdf_into

# a voxel is "far" when the other grid's SDF is clamped there (within float32 of the band)
_EDGE = 1.0 - 1e-6
# half the diagonal of an 8^3 block, in voxels, from its centre (3.5, 3.5, 3.5) to a corner voxel
_HALF_DIAGONAL = float(np.sqrt(3.0) * 3.5)


@njit(parallel=True, cache=True)
def _far_voxels(region, target, blocks):
    """Per block, its voxels inside ``region`` where ``target``'s SDF is clamped (outside it, at
    or beyond its band): (m, 512) flags. Void: region = CAD, target = deposit; overbuild: region
    = deposit, target = CAD."""
    m = blocks.shape[0]
    out = np.zeros((m, BLOCK_VOXELS), np.bool_)
    edge = np.float32(target.band * _EDGE)
    for b in prange(m):
        r8 = np.empty(BLOCK_VOXELS, np.float32)
        t8 = np.empty(BLOCK_VOXELS, np.float32)
        block_sdf_into(region, blocks[b, 0], blocks[b, 1], blocks[b, 2], r8)
        block_sdf_into(target, blocks[b, 0], blocks[b, 1], blocks[b, 2], t8)
        for v in range(BLOCK_VOXELS):
            if r8[v] < 0.0 and t8[v] >= edge:
                out[b, v] = True
    return out


def deepest(region, target, blocks: np.ndarray, origin: np.ndarray, voxel: float, distance,
            at_least: float) -> float:
    """The largest distance (mm) from a voxel centre of ``region`` where ``target``'s SDF is
    clamped to the target's surface, ``distance(points) -> (n,)`` being that exact distance;
    ``at_least`` when no such voxel lies deeper (the depth already found within the band).

    ``blocks`` are the candidate blocks (those :func:`.blocks.block_sums` flagged)."""
    if blocks.shape[0] == 0:
        return at_least
    far = _far_voxels(region, target, blocks)
    has = far.any(axis=1)
    blocks, far = blocks[has], far[has]
    if blocks.shape[0] == 0:
        return at_least
    centres = origin + voxel * (8.0 * blocks + 3.5)
    bound = distance(centres) + _HALF_DIAGONAL * voxel
    best = at_least
    local = np.stack(np.unravel_index(np.arange(BLOCK_VOXELS), (8, 8, 8)), axis=1)
    for b in np.argsort(-bound, kind="stable"):
        if bound[b] <= best:
            break
        points = origin + voxel * (8.0 * blocks[b] + local[far[b]])
        best = max(best, float(distance(points).max()))
    return best
