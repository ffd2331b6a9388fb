"""Collision detection: the nozzle along the toolpath against the growing part, fixtures and
the build plate, and an interactive scene of posed bodies (see :mod:`.kernels` for the method)."""

from .bodies import Body, Cone, body_from_grid, cone_body, mesh_body, nozzle_body, parse_cone, parse_fixture
from .path import Obstacle, PathCheck, check_toolpath, sample_poses
from .run import CollideRequest, Collisions, NozzleSettings, collide, format_collide

__all__ = ["Body", "CollideRequest", "Collisions", "Cone", "NozzleSettings", "Obstacle", "PathCheck",
           "body_from_grid", "check_toolpath", "collide", "cone_body", "format_collide", "mesh_body", "nozzle_body",
           "parse_cone", "parse_fixture", "sample_poses"]
