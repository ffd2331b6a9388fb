"""Area-uniform statistics of the CAD surface's deviation.

The deviation statistics sample the CAD surface where it crosses the lattice's edges
(:func:`.blocks.crossings`): every edge between two voxels whose CAD SDF changes sign holds one
surface point, found by linear interpolation of the SDF along the edge, and along that same
edge the deposit's SDF is interpolated too. A surface with unit normal n crosses
(|nx| + |ny| + |nz|) / voxel² edges per unit area, so each sample is weighted by
1 / (|nx| + |ny| + |nz|) to give area-uniform statistics without building a mesh.
"""

from __future__ import annotations

import numpy as np


def weighted_stats(values: np.ndarray, weights: np.ndarray | None = None) -> dict:
    """Mean, RMS and the 95th percentile of |value|, each weighted (weights default to 1)."""
    values = np.asarray(values, np.float64)
    if values.size == 0:
        return {"mean": 0.0, "rms": 0.0, "p95": 0.0}
    w = np.ones_like(values) if weights is None else np.asarray(weights, np.float64)
    total = w.sum()
    order = np.argsort(np.abs(values), kind="stable")
    cumulative = np.cumsum(w[order])
    p95 = float(np.abs(values[order[min(np.searchsorted(cumulative, 0.95 * total), values.size - 1)]]))
    return {"mean": float(np.dot(w, values) / total), "rms": float(np.sqrt(np.dot(w, values**2) / total)),
            "p95": p95}
