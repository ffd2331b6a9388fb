"""Results as PyVista objects, for notebooks (PyVista is imported only here, when asked)."""

from __future__ import annotations

import numpy as np


def polydata(vertices: np.ndarray, triangles: np.ndarray, point_arrays: dict | None = None):
    """A triangle mesh as ``pyvista.PolyData`` with its per-vertex arrays."""
    import pyvista as pv

    triangles = np.asarray(triangles, np.int64).reshape(-1, 3)
    faces = np.column_stack([np.full(len(triangles), 3, np.int64), triangles]).ravel()
    mesh = pv.PolyData(np.asarray(vertices, np.float64), faces)
    for name, values in (point_arrays or {}).items():
        mesh.point_data[name] = np.asarray(values)
    return mesh


def image_data(origin, voxel: float, arrays: dict):
    """Voxel arrays of one shape (x, y, z order) as ``pyvista.ImageData``: voxel centres on the
    points, ``origin`` the first centre."""
    import pyvista as pv

    shape = next(iter(arrays.values())).shape
    image = pv.ImageData(dimensions=shape, spacing=(voxel,) * 3, origin=tuple(float(v) for v in origin))
    for name, values in arrays.items():
        image.point_data[name] = np.asarray(values).ravel(order="F")
    return image
