"""The seed's interactive scene as an API: posed bodies, moved or rotated by a step, the step
refused when it would make two bodies collide. The window itself belongs to the viewer.

Each object is voxelized once in its own frame (:func:`~dmdvox.collision.bodies.mesh_body`);
a move only changes its pose, and the check poses the moved object in every other object's
frame (relative rotation and translation) for the same node-pair SAT descent and voxel test
the toolpath check uses (:func:`dmdvox.collision.kernels.query_one`).
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from ..defaults import BAND_VOXELS
from .bodies import Body, mesh_body
from .kernels import query_one



@dataclass(frozen=True, eq=False)
class SceneObject:
    """A body and its pose: world = ``rotation @ local + position``."""

    name: str
    body: Body
    position: np.ndarray  # (3,) float64 mm
    rotation: np.ndarray  # (3, 3) float64, columns = the object's axes in the world
    color: tuple[float, float, float]

    @property
    def mesh(self) -> tuple[np.ndarray, np.ndarray]:
        return self.body.mesh

    @property
    def depth(self) -> int:
        """Octree depth: the block tree's levels plus the three inside an 8^3 block."""
        return int(self.body.level_shape.shape[0] - 1 + 3)

    @property
    def pivot(self) -> np.ndarray:
        """World centre of the mesh's bounding box: rotations turn about it."""
        v = self.body.mesh[0]
        return self.rotation @ (0.5 * (v.min(axis=0) + v.max(axis=0))) + self.position

    def world_vertices(self) -> np.ndarray:
        return self.body.mesh[0] @ self.rotation.T + self.position


def rotation_matrix(axis, degrees: float) -> np.ndarray:
    """Right-handed rotation about ``axis`` ('x', 'y', 'z' or a 3-vector) by ``degrees``."""
    if isinstance(axis, str):
        axis = {"x": (1.0, 0.0, 0.0), "y": (0.0, 1.0, 0.0), "z": (0.0, 0.0, 1.0)}[axis.lower()]
    a = np.asarray(axis, np.float64)
    a = a / np.linalg.norm(a)
    th = np.radians(degrees)
    k = np.array([[0.0, -a[2], a[1]], [a[2], 0.0, -a[0]], [-a[1], a[0], 0.0]])
    return np.eye(3) + np.sin(th) * k + (1.0 - np.cos(th)) * (k @ k)  # Rodrigues


class Scene:
    """Named objects on one voxel size; :meth:`move` and :meth:`rotate` refuse colliding steps.

    Steps are checked at their end pose (the seed's step-wise interaction), not swept.
    ``reach`` sizes the bands: :meth:`clearance` measures distances up to it.
    """

    def __init__(self, voxel: float = 0.25, reach: float = 1.0):
        self.voxel = float(voxel)
        self.reach = float(reach)
        self.objects: dict[str, SceneObject] = {}

    def add(self, name: str, vertices: np.ndarray, triangles: np.ndarray, position=(0.0, 0.0, 0.0), rotation=None,
            color=(0.7, 0.7, 0.7)) -> SceneObject:
        """Add a closed mesh (its coordinates are its local frame) at a pose."""
        if name in self.objects:
            raise ValueError(f"scene object {name!r} exists")
        # a distance d is read where the other body's surface voxels meet this SDF: d + a cell
        band = self.reach + BAND_VOXELS * self.voxel
        body = mesh_body(name, vertices, triangles, self.voxel, band)
        obj = SceneObject(name, body, np.asarray(position, np.float64).reshape(3).copy(),
                          np.eye(3) if rotation is None else np.asarray(rotation, np.float64).reshape(3, 3).copy(),
                          tuple(float(c) for c in color))
        self.objects[name] = obj
        return obj

    def clearance(self, a: str, b: str, reach: float | None = None) -> float:
        """``d`` between objects ``a`` and ``b`` (negative: penetration depth); +inf at or beyond
        ``reach`` (default and at most the scene's)."""
        reach = self.reach if reach is None else min(float(reach), self.reach)
        return self._d(self.objects[a], self.objects[b], reach)

    @staticmethod
    def _d(probe: SceneObject, target: SceneObject, reach: float) -> float:
        # the probe posed in the target's frame
        r = target.rotation.T @ probe.rotation
        t = target.rotation.T @ (probe.position - target.position)
        return float(query_one(target.body.kernel_args(), probe.body.kernel_args(), np.ascontiguousarray(r),
                               np.ascontiguousarray(t), np.inf, float(reach)))

    def colliding_with(self, candidate: SceneObject) -> list[str]:
        """Names of the other objects ``candidate`` (a pose of one of them) would collide with."""
        return [o.name for o in self.objects.values() if o.name != candidate.name and self._d(candidate, o, 0.0) < 0.0]

    def _try(self, candidate: SceneObject) -> bool:
        if self.colliding_with(candidate):
            return False
        self.objects[candidate.name] = candidate
        return True

    def move(self, name: str, translation) -> bool:
        """Translate ``name`` by ``translation`` (mm, world); False (object left in place) on collision."""
        obj = self.objects[name]
        return self._try(replace(obj, position=obj.position + np.asarray(translation, np.float64).reshape(3)))

    def rotate(self, name: str, axis, degrees: float) -> bool:
        """Turn ``name`` about its pivot by ``degrees`` about a world ``axis``; False on collision."""
        obj = self.objects[name]
        q = rotation_matrix(axis, degrees)
        pivot = obj.pivot
        rotation = q @ obj.rotation
        # keep the pivot fixed: rotation @ c + position == pivot
        local_centre = np.linalg.solve(obj.rotation, pivot - obj.position)
        return self._try(replace(obj, rotation=rotation, position=pivot - rotation @ local_centre))
