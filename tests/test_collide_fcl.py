"""Cross-check against python-fcl: random static poses of a cone nozzle mesh and a rotated box
fixture; decisions must agree wherever the bodies are clearly apart (fcl distance > 1 voxel) or
clearly overlapping (still overlapping when the nozzle is shifted by a voxel along any axis)."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from dmdvox.collision import Cone
from dmdvox.collision.scene import Scene, rotation_matrix

from dmdvox.io.mesh import box_mesh

from .conftest import DEV_EXTRAS, require_module

try:
    import fcl
except ImportError:  # each test fails, naming the install step
    fcl = None


@pytest.fixture(autouse=True)
def _python_fcl():
    if fcl is None:
        require_module("fcl", "python-fcl", DEV_EXTRAS)

VOXEL = 0.2


def _fcl_object(vertices, triangles, rotation, position):
    model = fcl.BVHModel()
    model.beginModel(len(vertices), len(triangles))
    model.addSubModel(np.asarray(vertices, np.float64), np.asarray(triangles, np.int32))
    model.endModel()
    return fcl.CollisionObject(model, fcl.Transform(np.asarray(rotation, np.float64), np.asarray(position, np.float64)))


def _fcl_collides(a, b) -> bool:
    return fcl.collide(a, b, fcl.CollisionRequest(), fcl.CollisionResult()) > 0


def test_random_static_poses_agree_with_fcl():
    rng = np.random.default_rng(7)
    nozzle_mesh = Cone(3.0, 12.0, 15.0).mesh()
    box = box_mesh((-6.0, -4.0, -3.0), (6.0, 4.0, 3.0))
    fixture_rotation = rotation_matrix((1.0, 2.0, 0.5), 33.0)
    scene = Scene(voxel=VOXEL, reach=0.5)
    scene.add("fixture", *box, rotation=fixture_rotation)
    scene.add("nozzle", *nozzle_mesh, position=(100.0, 0.0, 0.0))
    fixture_fcl = _fcl_object(*box, fixture_rotation, np.zeros(3))
    checked_apart = checked_hit = 0
    for _ in range(150):
        rotation = rotation_matrix(rng.normal(size=3), rng.uniform(0.0, 180.0))
        position = rng.uniform(-12.0, 12.0, size=3)
        nozzle_fcl = _fcl_object(*nozzle_mesh, rotation, position)
        hits = _fcl_collides(nozzle_fcl, fixture_fcl)
        ours = scene.colliding_with(replace(scene.objects["nozzle"], position=position, rotation=rotation)) \
            == ["fixture"]
        if not hits:
            distance = fcl.distance(nozzle_fcl, fixture_fcl, fcl.DistanceRequest(), fcl.DistanceResult())
            if distance > VOXEL:
                assert not ours, (position, rotation, distance)
                checked_apart += 1
            continue
        shifted = [_fcl_collides(_fcl_object(*nozzle_mesh, rotation, position + s * VOXEL * np.eye(3)[axis]),
                                 fixture_fcl) for axis in range(3) for s in (-1.0, 1.0)]
        if all(shifted):
            assert ours, (position, rotation)
            checked_hit += 1
    # both outcomes are exercised
    assert checked_apart >= 20 and checked_hit >= 20, (checked_apart, checked_hit)
