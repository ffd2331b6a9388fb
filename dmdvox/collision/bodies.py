"""Collision bodies: a :class:`SparseGrid` (SDF + arrival) and the octree of its block tree.

Every body, the deposited part, a fixture, the nozzle or a scene object, is the same thing: a
sparse grid in the body's own frame, and its :func:`~dmdvox.grid.tree.block_tree` flattened for
the numba kernels (levels concatenated in C order). Static bodies carry arrival 0 inside, so
one time-aware query serves the growing part and the fixtures alike.

Meshes are voxelized with OpenVDB (:func:`dmdvox.grid.levelset.mesh_grid`, on a domain that
covers the mesh plus the band); the parametric cone nozzle gets its exact analytic SDF.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from pathlib import Path

import numba as nb
import numpy as np

from ..grid.levelset import mesh_area, surface_memory
from ..errors import DmdvoxError
from ..grid.build import GridBuilder
from ..grid.sparse import SparseGrid, popcount64
from ..grid.tree import block_tree
from .kernels import BOX_PAD_MM, BodyView

DENSE_SLAB_VOXELS = 1 << 24  # analytic bodies are evaluated in x-slabs of at most this many voxels


@dataclass(frozen=True, eq=False)
class Body:
    """A grid in the body's frame plus its flattened block tree and its convex hull points."""

    name: str
    grid: SparseGrid
    occupancy: np.ndarray  # (n_nodes,) uint8, all tree levels concatenated (C order per level)
    min_arrival: np.ndarray  # (n_nodes,) float32
    level_offset: np.ndarray  # (n_levels + 1,) int64
    level_shape: np.ndarray  # (n_levels, 3) int64
    hull: np.ndarray  # (m, 3) float64 convex hull vertices (body frame): lowest point for the plate
    rank_prefix: np.ndarray  # (n_leaf, 8) int64 active voxels of a leaf before each mask word
    node_box: np.ndarray  # (n_nodes above level 0, 6) float64 material box per node, see _node_boxes
    sdf_top: float  # the largest value a sample lookup gives: the band or an active value above it
    mesh: tuple[np.ndarray, np.ndarray] | None = field(default=None)  # (vertices, triangles) if known

    @property
    def voxel(self) -> float:
        return self.grid.voxel

    @property
    def band(self) -> float:
        return self.grid.band

    def kernel_args(self) -> BodyView:
        """The body as the kernels read it (see :mod:`dmdvox.collision.kernels`)."""
        g = self.grid
        geo = np.array([g.origin[0], g.origin[1], g.origin[2], g.voxel, g.band, self.sdf_top], np.float64)
        return BodyView(self.occupancy, self.min_arrival, self.level_offset, self.level_shape, g.block,
                        g.leaf_active, g.leaf_inside, g.sdf_offset, g.sdf, g.arr_offset, g.arrival,
                        g.leaf_octant_arrival, g.tile_arrival, geo, self.rank_prefix, self.node_box)


@nb.njit(cache=True, parallel=True)
def _word_popcounts(masks):
    out = np.empty(masks.shape, np.int64)
    for n in nb.prange(masks.shape[0]):
        for w in range(masks.shape[1]):
            out[n, w] = popcount64(masks[n, w])
    return out


@nb.njit(cache=True)
def _node_boxes(occupancy, min_arrival, level_offset, level_shape, origin, h):
    """Per tree node above level 0, the box (centre x, y, z, half extents x, y, z; body frame, mm)
    of its material: the union of the cubes of its descendants that a descent stops at (level-0
    nodes, and FULL nodes, which probes do not split), those with material (minimum arrival
    finite); the cube itself for a FULL node. Half extents -1 when it has none.

    Every such cube below a node lies in the node's box, so two boxes apart on a separating axis
    put all their descendants' cubes apart on it (see :func:`dmdvox.collision.kernels._descend`);
    ``BOX_PAD_MM`` keeps that true under the rounding of the box centres (1e-13 mm) where a cube
    touches its node's box.
    """
    n_levels = level_shape.shape[0]
    base = level_offset[1]
    out = np.empty((level_offset[n_levels] - base, 6), np.float64)  # lo, hi until the end
    corner = origin - 0.5 * h
    for level in range(1, n_levels):
        nx, ny, nz = level_shape[level, 0], level_shape[level, 1], level_shape[level, 2]
        cx, cy, cz = level_shape[level - 1, 0], level_shape[level - 1, 1], level_shape[level - 1, 2]
        span = 8.0 * (1 << level) * h
        for i in range(nx):
            for j in range(ny):
                for k in range(nz):
                    n = level_offset[level] + (i * ny + j) * nz + k
                    box = out[n - base]
                    box[:3] = np.inf
                    box[3:] = -np.inf
                    if occupancy[n] == 0 or not (min_arrival[n] < np.inf):
                        continue
                    if occupancy[n] == 2:
                        box[0], box[1], box[2] = corner[0] + i * span, corner[1] + j * span, corner[2] + k * span
                        box[3], box[4], box[5] = box[0] + span, box[1] + span, box[2] + span
                        continue
                    for c in range(8):
                        ci, cj, ck = 2 * i + (c >> 2), 2 * j + ((c >> 1) & 1), 2 * k + (c & 1)
                        if ci >= cx or cj >= cy or ck >= cz:
                            continue
                        m = level_offset[level - 1] + (ci * cy + cj) * cz + ck
                        if occupancy[m] == 0 or not (min_arrival[m] < np.inf):
                            continue
                        if level == 1:
                            for a in range(3):
                                lo = corner[a] + (ci if a == 0 else (cj if a == 1 else ck)) * 0.5 * span
                                box[a] = min(box[a], lo)
                                box[3 + a] = max(box[3 + a], lo + 0.5 * span)
                        else:
                            for a in range(6):
                                box[a] = min(box[a], out[m - base, a]) if a < 3 else max(box[a], out[m - base, a])
    for n in range(out.shape[0]):
        box = out[n]
        if box[0] <= box[3]:
            for a in range(3):
                lo, hi = box[a], box[3 + a]
                box[a] = 0.5 * (lo + hi)
                box[3 + a] = 0.5 * (hi - lo) + BOX_PAD_MM
        else:
            box[:3] = 0.0
            box[3:] = -1.0
    return out


def _hull_points(points: np.ndarray) -> np.ndarray:
    from scipy.spatial import ConvexHull, QhullError

    points = np.asarray(points, np.float64).reshape(-1, 3)
    try:
        return np.ascontiguousarray(points[ConvexHull(points).vertices])
    except (QhullError, ValueError):
        return np.ascontiguousarray(points)  # flat or tiny point sets: every point is a hull point


def body_from_grid(name: str, grid: SparseGrid, hull_points: np.ndarray | None = None,
                   mesh: tuple[np.ndarray, np.ndarray] | None = None) -> Body:
    """Flatten ``grid``'s block tree. Without ``hull_points`` the hull comes from the corners of
    the blocks holding material (conservative: lower than the true solid by under a block)."""
    tree = block_tree(grid)
    levels = tree.levels
    occupancy = np.ascontiguousarray(np.concatenate([lv.occupancy.ravel() for lv in levels]), np.uint8)
    min_arrival = np.ascontiguousarray(np.concatenate([lv.min_arrival.ravel() for lv in levels]), np.float32)
    sizes = np.array([lv.occupancy.size for lv in levels], np.int64)
    level_offset = np.zeros(len(levels) + 1, np.int64)
    np.cumsum(sizes, out=level_offset[1:])
    level_shape = np.array([lv.occupancy.shape for lv in levels], np.int64).reshape(-1, 3)
    if hull_points is None:
        solid = np.argwhere((levels[0].occupancy > 0) & np.isfinite(levels[0].min_arrival))
        if solid.shape[0] == 0:
            hull_points = np.zeros((0, 3))
        else:
            corners = np.array([[a, b, c] for a in (0, 1) for b in (0, 1) for c in (0, 1)])
            lo, hi = tree.node_bounds(0, solid)
            hull_points = np.where(corners[None, :, :] == 0, lo[:, None, :], hi[:, None, :]).reshape(-1, 3)
    hull = _hull_points(hull_points) if len(hull_points) else np.zeros((0, 3), np.float64)
    counts = _word_popcounts(grid.leaf_active)
    rank_prefix = np.zeros_like(counts)
    np.cumsum(counts[:, :-1], axis=1, out=rank_prefix[:, 1:])
    node_box = _node_boxes(occupancy, min_arrival, level_offset, level_shape, np.asarray(grid.origin, np.float64),
                           float(grid.voxel))
    sdf_top = max(float(np.float32(grid.band)), float(grid.sdf.max()) if grid.sdf.size else -np.inf)
    return Body(name=name, grid=grid, occupancy=occupancy, min_arrival=min_arrival, level_offset=level_offset,
                level_shape=level_shape, hull=hull, rank_prefix=rank_prefix, node_box=node_box, sdf_top=sdf_top,
                mesh=mesh)


def domain(lo, hi, voxel: float, margin: float, anchor=None) -> tuple[np.ndarray, tuple[int, int, int]]:
    """Origin and block shape of a grid covering ``lo..hi`` plus ``margin``; with ``anchor`` (another
    grid's origin) the voxel centres sit on that grid's lattice, so both grids share it."""
    lo = np.asarray(lo, np.float64) - margin - voxel
    hi = np.asarray(hi, np.float64) + margin + voxel
    anchor = np.zeros(3) if anchor is None else np.asarray(anchor, np.float64)
    origin = anchor + np.floor((lo - anchor) / voxel) * voxel
    blocks = np.maximum(1, np.ceil((hi - origin) / voxel / 8.0)).astype(np.int64)
    return origin, tuple(int(b) for b in blocks)


def mesh_body(name: str, vertices: np.ndarray, triangles: np.ndarray, voxel: float, band: float,
              anchor=None) -> Body:
    """Voxelize a closed mesh (its own coordinates are the body frame) with OpenVDB."""
    from ..grid.levelset import mesh_grid

    vertices = np.asarray(vertices, np.float64)
    band = max(float(band), 3.0 * voxel)
    origin, blocks = domain(vertices.min(axis=0), vertices.max(axis=0), voxel, band, anchor)
    grid = mesh_grid(vertices, triangles, voxel, origin, blocks, band, {"source": name})
    if grid.n_leaf == 0:
        raise DmdvoxError(f"{name}: the mesh encloses no voxel at {voxel:g} mm (is it closed? use a smaller --voxel)")
    return body_from_grid(name, grid, hull_points=vertices, mesh=(vertices, np.asarray(triangles, np.int64)))


def mesh_memory(vertices: np.ndarray, triangles: np.ndarray, voxel: float, band: float) -> int:
    """Bytes :func:`mesh_body` needs for this mesh, known before it allocates anything."""
    vertices = np.asarray(vertices, np.float64)
    band = max(float(band), 3.0 * voxel)
    _, blocks = domain(vertices.min(axis=0), vertices.max(axis=0), voxel, band)
    return surface_memory(mesh_area(vertices, triangles), voxel, band, float(np.prod(blocks, dtype=np.float64)))


# -- the parametric cone nozzle ------------------------------------------------------------------

@dataclass(frozen=True)
class Cone:
    """Coaxial truncated cone: tip (diameter ``tip``) at z = 0, top (``top``) at z = ``length``."""

    tip: float
    top: float
    length: float

    def sdf(self, x: np.ndarray, y: np.ndarray, z: np.ndarray) -> np.ndarray:
        """Exact signed distance (float64), the capped-cone formula of I. Quilez."""
        r1, r2, hh = 0.5 * self.tip, 0.5 * self.top, 0.5 * self.length
        qx = np.hypot(x, y)
        qy = z - hh  # the formula's cone is centred on its mid-height
        ca_x = qx - np.minimum(qx, np.where(qy < 0.0, r1, r2))
        ca_y = np.abs(qy) - hh
        k2x, k2y = r2 - r1, 2.0 * hh
        f = np.clip(((r2 - qx) * k2x + (hh - qy) * k2y) / (k2x * k2x + k2y * k2y), 0.0, 1.0)
        cb_x = qx - r2 + k2x * f
        cb_y = qy - hh + k2y * f
        sign = np.where((cb_x < 0.0) & (ca_y < 0.0), -1.0, 1.0)
        return sign * np.sqrt(np.minimum(ca_x * ca_x + ca_y * ca_y, cb_x * cb_x + cb_y * cb_y))

    def mesh(self, segments: int = 96) -> tuple[np.ndarray, np.ndarray]:
        """A closed triangle mesh (rings of ``segments`` vertices and two centre points)."""
        a = np.linspace(0.0, 2.0 * np.pi, segments, endpoint=False)
        ring = np.stack([np.cos(a), np.sin(a)], 1)
        bottom = np.column_stack([0.5 * self.tip * ring, np.zeros(segments)])
        top = np.column_stack([0.5 * self.top * ring, np.full(segments, self.length)])
        vertices = np.vstack([bottom, top, [[0.0, 0.0, 0.0]], [[0.0, 0.0, self.length]]])
        s = np.arange(segments)
        n = (s + 1) % segments
        cb, ct = 2 * segments, 2 * segments + 1
        side = np.concatenate([np.column_stack([s, n, segments + n]), np.column_stack([s, segments + n, segments + s])])
        caps = np.concatenate([np.column_stack([np.full(segments, cb), n, s]),
                               np.column_stack([np.full(segments, ct), segments + s, segments + n])])
        return vertices, np.ascontiguousarray(np.concatenate([side, caps]), np.int64)


def cone_body(cone: Cone, voxel: float, band: float, name: str = "nozzle") -> Body:
    """The cone's exact SDF sampled on its own grid (nozzle frame: tip at the origin, axis +Z)."""
    band = max(float(band), 3.0 * voxel)
    r = 0.5 * max(cone.tip, cone.top)
    origin, blocks = domain((-r, -r, 0.0), (r, r, cone.length), voxel, band)
    builder = GridBuilder(voxel, origin, blocks, band)
    ny, nz = 8 * blocks[1], 8 * blocks[2]
    y = origin[1] + voxel * np.arange(ny)
    z = origin[2] + voxel * np.arange(nz)
    step = max(1, DENSE_SLAB_VOXELS // (512 * ny * nz))
    for bx0 in range(0, blocks[0], step):
        bx1 = min(blocks[0], bx0 + step)
        x = origin[0] + voxel * np.arange(8 * bx0, 8 * bx1)
        sdf = cone.sdf(x[:, None, None], y[None, :, None], z[None, None, :]).astype(np.float32)
        arrival = np.where(sdf < 0, np.float32(0.0), np.float32(np.inf))
        builder.add_dense(sdf, arrival, (bx0, 0, 0))
    vertices, triangles = cone.mesh()
    return body_from_grid(name, builder.finish({"source": "cone"}), hull_points=vertices, mesh=(vertices, triangles))


_CONE = re.compile(r"^cone:(.*)$")


def parse_cone(spec: str) -> Cone:
    """``cone:tip=D,top=D,length=L`` (mm) -> :class:`Cone`; errors name ``--nozzle``."""
    m = _CONE.match(spec.strip())
    if m is None:
        raise DmdvoxError(f"--nozzle {spec!r}: expected an STL file or cone:tip=D,top=D,length=L")
    values = {}
    for part in filter(None, m.group(1).split(",")):
        key, _, text = part.partition("=")
        try:
            values[key.strip()] = float(text)
        except ValueError:
            raise DmdvoxError(f"--nozzle {spec!r}: {part!r} is not KEY=NUMBER") from None
    need = {"tip", "top", "length"}
    if set(values) != need:
        raise DmdvoxError(f"--nozzle {spec!r}: give exactly tip=, top= and length= (mm), got {sorted(values)}")
    if not all(np.isfinite(v) and v >= 0 for v in values.values()) or values["length"] <= 0 \
            or max(values["tip"], values["top"]) <= 0:
        raise DmdvoxError(f"--nozzle {spec!r}: diameters must be >= 0 (not both 0) and the length > 0")
    return Cone(values["tip"], values["top"], values["length"])


def nozzle_mesh(spec: str) -> tuple[np.ndarray, np.ndarray]:
    """The nozzle's triangle mesh from ``--nozzle`` (tip at the origin, axis +Z)."""
    from ..io.mesh import read_stl

    if spec.strip().startswith("cone:"):
        return parse_cone(spec).mesh()
    if not Path(spec).is_file():
        raise DmdvoxError(f"--nozzle {spec!r}: no such file (give an STL or cone:tip=D,top=D,length=L)")
    return read_stl(spec)


def nozzle_body(spec: str, voxel: float, band: float) -> Body:
    """The nozzle from ``--nozzle``: an STL (tip at its origin, axis +Z) or ``cone:...`` (its
    exact SDF)."""
    if spec.strip().startswith("cone:"):
        return cone_body(parse_cone(spec), voxel, band)
    return mesh_body("nozzle", *nozzle_mesh(spec), voxel, band)


def parse_fixture(spec: str) -> tuple[str, Path, tuple[float, float, float]]:
    """``STL[@dx,dy,dz]`` -> (name = file stem, path, offset); errors name ``--fixture``."""
    text, at, offset_text = spec.rpartition("@") if "@" in spec else (spec, "", "")
    offset = (0.0, 0.0, 0.0)
    if at:
        try:
            values = tuple(float(v) for v in offset_text.split(","))
        except ValueError:
            values = ()
        if len(values) != 3 or not all(np.isfinite(values)):
            raise DmdvoxError(f"--fixture {spec!r}: expected STL@dx,dy,dz with three numbers in mm")
        offset = values
    path = Path(text)
    if not path.is_file():
        raise DmdvoxError(f"--fixture {spec!r}: no such file {text!r}")
    return path.stem, path, offset


@dataclass(frozen=True, eq=False)
class Fixture:
    """A ``--fixture STL[@dx,dy,dz]`` read and moved into place: ``spec`` as given (for messages),
    ``name`` from the file stem (``stem#2`` for a second file of the same stem)."""

    spec: str
    name: str
    vertices: np.ndarray
    triangles: np.ndarray


def load_fixtures(specs) -> list[Fixture]:
    """Every ``--fixture``, read once for all that uses it (memory estimate, bodies, pictures)."""
    from ..io.mesh import read_stl

    fixtures = []
    seen: dict[str, int] = {}
    for spec in specs or []:
        name, path, offset = parse_fixture(spec)
        seen[name] = seen.get(name, 0) + 1
        if seen[name] > 1:
            name = f"{name}#{seen[name]}"
        vertices, triangles = read_stl(path)
        fixtures.append(Fixture(spec, name, vertices + np.asarray(offset, np.float64), triangles))
    return fixtures
