"""`dmdvox collide`: the nozzle along the G-code against the growing part, fixtures and plate."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .. import checks, progress
from ..defaults import BAND_VOXELS, CLEARANCE_MM, STANDOFF_MM
from ..errors import ParameterError
from ..process.plan import ProcessPlan
from ..toolpath.model import Toolpath
from .bodies import Body, Fixture, body_from_grid, load_fixtures, mesh_body, mesh_memory, nozzle_body, nozzle_mesh
from .path import Obstacle, PathCheck, check_toolpath


def _positive(name: str, value, allow_zero: bool = False) -> float:
    value = float(value)
    if not np.isfinite(value) or value < 0 or (value == 0 and not allow_zero):
        raise ParameterError(f"{{{name}}} must be a {'non-negative' if allow_zero else 'positive'} number of mm, "
                             f"got {value:g}", name)
    return value


def build_obstacles(tp: Toolpath, part_grid, fixtures: list[Fixture], plate: float | None,
                    voxel: float) -> list[Obstacle]:
    """The part (when the program deposits), the fixtures on the part's lattice, the plate."""
    obstacles = []
    anchor = None
    if part_grid is not None:
        obstacles.append(Obstacle("part", body_from_grid("part", part_grid)))
        anchor = part_grid.origin
    for fixture in fixtures:
        body = mesh_body(fixture.name, fixture.vertices, fixture.triangles, voxel, BAND_VOXELS * voxel, anchor=anchor)
        obstacles.append(Obstacle(f"fixture:{fixture.name}", body))
    if plate is not None:
        z = float(plate)
        if not np.isfinite(z):
            raise ParameterError(f"{{plate}} must be a finite Z in mm, got {plate}", "plate")
        obstacles.append(Obstacle("plate", plate_z=z))
    return obstacles


def check_bodies_fit(nozzle_spec: str, fixtures: list[Fixture], voxel: float, reach: float,
                     max_memory: int | None) -> dict[str, int]:
    """Refuse, before any grid is built, nozzle and fixture grids that would not fit in memory
    together; returns their bytes by name, for the deposit's check to add to its own."""
    from ..errors import ResourceError
    from ..memory import check_memory

    bodies = [(f"{{nozzle}} {nozzle_spec}", "nozzle", nozzle_mesh(nozzle_spec), _nozzle_band(voxel, reach))]
    bodies += [(f"{{fixtures}} {f.spec}", f"fixture {f.name}", (f.vertices, f.triangles), BAND_VOXELS * voxel)
               for f in fixtures]
    sizes = {option: mesh_memory(vertices, triangles, voxel, band) for option, _, (vertices, triangles), band in bodies}
    parts = {name: sizes[option] for option, name, _, _ in bodies}
    try:
        check_memory(parts, voxel, max_memory)
    except ResourceError as exc:
        raise exc.prefixed(f"{max(sizes, key=sizes.get)}: ", also=("nozzle", "fixtures")) from None
    return parts


def _nozzle_band(voxel: float, reach: float) -> float:
    """Wide enough to measure distances up to ``reach`` against obstacles of band
    ``BAND_VOXELS`` voxels (plus two voxels for the trilinear cells)."""
    return reach + (BAND_VOXELS + 2.0) * voxel


def nozzle_for(spec: str, voxel: float, reach: float) -> Body:
    """The nozzle body, its band from :func:`_nozzle_band`."""
    return nozzle_body(spec, voxel, _nozzle_band(voxel, reach))


@dataclass(frozen=True)
class NozzleSettings:
    """The nozzle and what it may hit: ``nozzle`` an STL (tip at the origin, axis +Z) or
    ``cone:tip=D,top=D,length=L``; ``fixtures`` STL paths, each optionally moved
    (``PATH@dx,dy,dz``); the build plate's top at ``plate`` (Z, none: no plate); the tip
    ``standoff`` mm above the programmed bead bottom; near misses closer than ``clearance``."""

    nozzle: str
    fixtures: tuple[str, ...] = ()
    plate: float | None = None
    standoff: float = STANDOFF_MM
    clearance: float = CLEARANCE_MM

    def __post_init__(self) -> None:
        if not self.nozzle:
            raise ParameterError("{nozzle} is required: an STL (tip at the origin, axis +Z) or "
                                 "cone:tip=D,top=D,length=L", "nozzle")
        if not np.isfinite(float(self.standoff)):
            raise ParameterError(f"{{standoff}} must be a finite number of mm, got {self.standoff}", "standoff")
        _positive("clearance", self.clearance, allow_zero=True)
        if self.plate is not None and not np.isfinite(float(self.plate)):
            raise ParameterError(f"{{plate}} must be a finite Z in mm, got {self.plate}", "plate")


@dataclass(frozen=True)
class CollideRequest:
    """The nozzle along the plan's path, against the part as it grows (swept at ``voxel``,
    default the plan's), the fixtures and the plate, within ``max_memory`` bytes; ``strict``
    refuses rotary words the machine does not model."""

    plan: ProcessPlan
    nozzle: NozzleSettings
    voxel: float | None = None
    max_memory: int | None = None
    strict: bool = False


@dataclass(frozen=True, eq=False)
class Collisions:
    """A collision check's result: the :class:`~.path.PathCheck` (collisions, near misses,
    clearance along the path), the obstacles' labels, and the check's voxel and standoff."""

    check: PathCheck
    obstacles: list[str]
    voxel: float
    standoff: float
    source: str

    def to_json(self) -> dict:
        return self.check.as_dict()

    def __getitem__(self, key: str):
        return self.check.as_dict()[key]

    def text(self) -> str:
        """The human report: which lines collide, with what, where and how deep."""
        return format_collide(self.check, self.source, self.voxel, self.standoff, self.obstacles)


def collide(request: CollideRequest) -> Collisions:
    """Check the nozzle along the whole program (module docstring)."""
    from ..deposit.engine import deposit_beads
    from ..deposit.simulate import describe

    plan, nozzle = request.plan, request.nozzle
    tp = plan.toolpath
    voxel = plan.resolve_voxel(None if request.voxel is None else _positive("voxel", request.voxel))
    fixtures = load_fixtures(list(nozzle.fixtures))
    bodies = prepare_collide(tp, nozzle.nozzle, fixtures, voxel, nozzle.clearance, request.max_memory,
                             strict=request.strict)
    part_grid = None
    if tp.deposit.any():
        # the part as it really grows: under the flow model a part that outgrows its program
        # meets the nozzle
        progress.stage("deposit", describe(plan))
        part_grid = deposit_beads(plan.lay(voxel, max_memory=request.max_memory).beads, voxel,
                                  max_memory=request.max_memory, also_holds=bodies)[0]
    check, labels = collide_part(tp, part_grid, nozzle, fixtures, voxel)
    return Collisions(check, labels, voxel, float(nozzle.standoff), str(tp.source))


def prepare_collide(tp: Toolpath, nozzle_spec: str, fixtures: list[Fixture], voxel: float, clearance: float,
                    max_memory: int | None, strict: bool = False) -> dict[str, int]:
    """What every command that checks the nozzle does before building any grid: warn of rotary
    words the machine does not model (an error under ``strict``), and refuse nozzle or fixture
    grids that would not fit; returns their bytes by name (:func:`check_bodies_fit`)."""
    checks.check_toolpath(tp, strict)
    return check_bodies_fit(nozzle_spec, fixtures, voxel, clearance + voxel, max_memory)


def collide_part(tp: Toolpath, part_grid, nozzle: NozzleSettings, fixtures: list[Fixture],
                 voxel: float) -> tuple[PathCheck, list[str]]:
    """Check ``tp`` against the deposit already built (``part_grid``, None when nothing is
    deposited), the fixtures and the plate; returns the check and the obstacles' labels."""
    progress.stage("collide", f"the nozzle along {len(tp):,d} moves against "
                              f"{'the part, ' if part_grid is not None else ''}{len(fixtures)} fixture(s)"
                              f"{' and the plate' if nozzle.plate is not None else ''}")
    obstacles = build_obstacles(tp, part_grid, fixtures, nozzle.plate, voxel)
    # measure a voxel beyond the near-miss threshold so that misses just under it are resolved
    reach = nozzle.clearance + voxel
    check = check_toolpath(tp, nozzle_for(nozzle.nozzle, voxel, reach), obstacles, standoff=nozzle.standoff,
                           clearance=nozzle.clearance, step=0.5 * voxel, reach=reach)
    return check, [o.label for o in obstacles]


def format_collide(check: PathCheck, source: str, voxel: float, standoff: float, obstacles: list[str]) -> str:
    """The human report: which lines collide, with what, where and how deep."""
    out = [f"{source}: {check.poses_checked:,d} nozzle poses checked (voxel {voxel:g} mm, standoff {standoff:g} mm) "
           f"against {', '.join(obstacles) if obstacles else 'no obstacle'}"]
    if check.collisions:
        lines = sorted({c["line"] for c in check.collisions})
        out.append(f"  COLLISION on {len(lines)} line(s): {', '.join(str(n) for n in lines[:20])}"
                   f"{' ...' if len(lines) > 20 else ''} (first: line {check.first_collision_line})")
        for c in check.collisions[:50]:
            x, y, z = c["position_mm"]
            out.append(f"    line {c['line']:>6d}  t {c['time_s']:9.3f} s  tip ({x:.3f}, {y:.3f}, {z:.3f})  "
                       f"{c['obstacle']:<20s} depth {'>= ' if c.get('depth_capped') else ''}{c['depth_mm']:.3f} mm"
                       f"{' (the measuring limit)' if c.get('depth_capped') else ''}")
        if len(check.collisions) > 50:
            out.append(f"    ... {len(check.collisions) - 50} more (use --json)")
    else:
        out.append("  no collision")
    if check.min_clearance_mm is None:
        out.append(f"  min clearance    > {check.reach_mm:.3f} mm (no obstacle within the measuring reach)")
    else:
        out.append(f"  min clearance    {check.min_clearance_mm:.3f} mm")
    if check.near_misses:
        out.append(f"  near misses      {len(check.near_misses)}")
        for m in check.near_misses[:20]:
            out.append(f"    line {m['line']:>6d}  t {m['time_s']:9.3f} s  {m['obstacle']:<20s} "
                       f"{m['distance_mm']:.3f} mm")
    return "\n".join(out)
