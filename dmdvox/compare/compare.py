"""`dmdvox compare`: the deposit against the CAD part, on one grid.

The CAD STL becomes an OpenVDB level set on the deposit grid's own transform (same voxel
lattice, same block table), so every comparison is voxel against voxel:

* void (inside CAD, outside deposit) and overbuild (inside deposit, outside CAD) volumes from
  the sub-voxel occupancies of both SDFs: per voxel ``max(0, f_cad - f_dep)`` and
  ``max(0, f_dep - f_cad)`` with ``f = clamp(0.5 - sdf / voxel, 0, 1)`` (exact where one
  surface does not cross the other inside a voxel);
* max underfill / overbuild depth: the largest distance from a void (overbuild) voxel to the
  deposit (CAD): the other grid's SDF inside its narrow band, beyond it an exact Euclidean
  distance transform to the nearest voxel centre of the other solid (to half a voxel);
* signed surface deviation, positive = excess material: on the CAD surface, how far the
  deposit surface lies outside it (negative: the deposit falls short, underfill); on the
  deposit surface, how far it lies outside the CAD surface (negative: inside the CAD).
  Within the other grid's narrow band the value is its SDF (trilinear), beyond it the exact
  distance to the other surface. The statistics sample the CAD surface where it crosses the
  lattice's edges, weighted to be uniform by area (:mod:`.sampling`), so they need no mesh;
  the maps (``--out``) carry the same values on both surfaces' meshes;
* a per-layer table of void and overbuild, and the deposit's pores flagged inside or outside
  the CAD.
"""

from __future__ import annotations

import csv
import io
import json
import time
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from numba import njit, prange
from scipy import ndimage

from .. import checks, progress
from ..deposit.engine import union_distance
from ..deposit.simulate import GROWTH_KEYS, RUN_OBJECTS, describe, simulate_plan
from ..process.plan import ProcessPlan
from ..errors import DmdvoxError, InputFileError
from ..grid.build import GridBuilder
from ..grid.enclosure import occupancy_sdf
from ..grid.sparse import SparseGrid
from ..toolpath.model import Toolpath
from ..vdb import openvdb
from .edt import max_squared_distance
from .sampling import edge_crossings, trilinear, weighted_stats

LABEL_OUTSIDE = 0
LABEL_BOTH = 1
LABEL_VOID = 2
LABEL_OVERBUILD = 3
LABEL_PORE = 4
LABEL_NAMES = {LABEL_OUTSIDE: "outside both", LABEL_BOTH: "inside both", LABEL_VOID: "void (CAD only)",
               LABEL_OVERBUILD: "overbuild (deposit only)", LABEL_PORE: "pore"}
MAX_DENSE_VOXELS = 64_000_000  # the volume map and the distance transforms run on dense arrays
# The CAD's narrow band: the occupancies need |sdf| < voxel / 2 only, and every distance beyond
# the band is measured exactly (EDT, mesh distance); OpenVDB's level set costs a third less
# than at the deposit's 3 voxels.
CAD_BAND_VOXELS = 2.0


def load_cad(path: str | Path, offset=(0.0, 0.0, 0.0)) -> tuple[np.ndarray, np.ndarray, list[str]]:
    """The CAD mesh in machine coordinates, and warnings about its quality."""
    from ..io.mesh import read_stl

    vertices, triangles = read_stl(path)
    vertices = vertices + np.asarray(offset, np.float64)
    warnings = []
    corners = vertices[triangles]
    area2 = np.linalg.norm(np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0]), axis=1)
    degenerate = area2 <= 1e-12 * max(1.0, float(np.ptp(vertices, axis=0).max()) ** 2)
    if degenerate.any():
        warnings.append(f"{path}: {int(degenerate.sum())} degenerate (zero-area) triangles ignored")
        triangles = triangles[~degenerate]
    if triangles.shape[0] == 0:
        raise InputFileError(f"{path}: STL has only degenerate triangles")
    edges = np.sort(np.concatenate([triangles[:, [0, 1]], triangles[:, [1, 2]], triangles[:, [2, 0]]]), axis=1)
    _, counts = np.unique(edges, axis=0, return_counts=True)
    open_edges = int(np.count_nonzero(counts != 2))
    if open_edges:
        warnings.append(f"{path}: mesh is not watertight ({open_edges} edges not shared by exactly two "
                        "triangles); inside/outside may be wrong near the holes")
    return vertices, triangles, warnings


def cad_grid(vertices: np.ndarray, triangles: np.ndarray, like: SparseGrid) -> SparseGrid:
    """Voxelize the CAD mesh with OpenVDB on ``like``'s transform and block table."""
    from ..grid.vdbio import _transform

    transform = _transform(like.voxel, like.origin)
    level_set = openvdb.FloatGrid.createLevelSetFromPolygons(
        np.ascontiguousarray(vertices, np.float64), triangles=np.ascontiguousarray(triangles, np.int32),
        transform=transform, halfWidth=float(like.band / like.voxel))
    builder = GridBuilder(like.voxel, like.origin, like.block.shape, like.band)
    if level_set.activeVoxelCount():
        (imin, jmin, kmin), (imax, jmax, kmax) = level_set.evalActiveVoxelBoundingBox()
        shape = np.array(like.block.shape)
        lo = np.clip(np.floor_divide([imin, jmin, kmin], 8), 0, shape)
        hi = np.clip(np.floor_divide([imax, jmax, kmax], 8) + 1, 0, shape)
        ny, nz = int(hi[1] - lo[1]), int(hi[2] - lo[2])
        step = max(1, (1 << 24) // max(1, 512 * ny * nz))
        for x0 in range(int(lo[0]), int(hi[0]), step):
            x1 = min(int(hi[0]), x0 + step)
            sdf = np.empty((8 * (x1 - x0), 8 * ny, 8 * nz), np.float32)
            level_set.copyToArray(sdf, (8 * x0, 8 * int(lo[1]), 8 * int(lo[2])))
            # The CAD is there from the start: arrival 0 inside.
            arrival = np.where(sdf < 0, np.float32(0.0), np.float32(np.inf))
            builder.add_dense(sdf, arrival, (x0, int(lo[1]), int(lo[2])))
    return builder.finish({"source": "cad"})


@njit(parallel=True, cache=True)
def _volume_slices(dep, cad, voxel):
    """Per z slice (in voxels): CAD, void and overbuild occupancy sums; and whether any void
    (overbuild) voxel lies beyond the deposit's (CAD's) band."""
    nx, ny, nz = dep.shape
    cad_x = np.zeros((nx, nz))
    void_x = np.zeros((nx, nz))
    over_x = np.zeros((nx, nz))
    for i in prange(nx):
        for j in range(ny):
            for l in range(nz):
                fd = min(1.0, max(0.0, 0.5 - dep[i, j, l] / voxel))
                fc = min(1.0, max(0.0, 0.5 - cad[i, j, l] / voxel))
                cad_x[i, l] += fc
                if fc > fd:
                    void_x[i, l] += fc - fd
                else:
                    over_x[i, l] += fd - fc
    return cad_x.sum(axis=0), void_x.sum(axis=0), over_x.sum(axis=0)


@njit(parallel=True, cache=True)
def _region_max(region_sdf, target_sdf, band):
    """Largest ``target_sdf`` over the voxels inside ``region_sdf`` and outside the target (the
    distance to the target, exact within its band, clamped at ``band`` beyond)."""
    nx, ny, nz = region_sdf.shape
    best = np.zeros(nx)
    for i in prange(nx):
        for j in range(ny):
            for l in range(nz):
                if region_sdf[i, j, l] < 0.0 and target_sdf[i, j, l] >= 0.0:
                    best[i] = max(best[i], target_sdf[i, j, l])
    return best.max()


def _max_distance(region_sdf: np.ndarray, target_sdf: np.ndarray, band: float, voxel: float) -> float:
    """Largest distance from the region (inside ``region_sdf``, outside the target) to the
    target: the target's SDF within its band; beyond it, where the SDF is clamped, the exact
    distance transform to the nearest target voxel centre, less half a voxel."""
    near = _region_max(region_sdf, target_sdf, np.float32(band))
    if near < band - 1e-6 * voxel:
        return float(near)
    far = max_squared_distance(target_sdf, region_sdf, np.float32(band))
    return float(max(near, np.sqrt(far) * voxel - 0.5 * voxel))


def _layer_table(bottoms: np.ndarray, z_world: np.ndarray, voxel: float, void_z: np.ndarray,
                 over_z: np.ndarray) -> list[dict]:
    """Void and overbuild per layer; a voxel slice straddling a layer boundary is split by length.

    Layer k spans from its bead bottom to the next layer's (the first from below the part, the
    last to above it)."""
    if bottoms.size == 0:
        return []
    edges = np.concatenate([[-np.inf], bottoms[1:], [np.inf]])
    lo = np.maximum((z_world - voxel / 2)[:, None], edges[None, :-1])
    hi = np.minimum((z_world + voxel / 2)[:, None], edges[None, 1:])
    share = np.clip(hi - lo, 0.0, None) / voxel  # (slices, layers)
    void = void_z @ share
    over = over_z @ share
    return [{"layer": int(k), "z_mm": round(float(bottoms[k]), 9), "void_mm3": float(void[k]), "overbuild_mm3": float(over[k])}
            for k in range(bottoms.size)]


def _pore_mask(deposit_inside: np.ndarray) -> np.ndarray:
    """Outside-the-deposit voxels not connected to the domain boundary."""
    labels, n = ndimage.label(~deposit_inside)
    if n == 0:
        return np.zeros_like(deposit_inside)
    border = np.unique(np.concatenate([labels[[0, -1]].ravel(), labels[:, [0, -1]].ravel(),
                                       labels[:, :, [0, -1]].ravel()]))
    enclosed = np.ones(n + 1, bool)
    enclosed[border] = False
    enclosed[0] = False
    return enclosed[labels]


class _BeadUnionDistance:
    """The deposit's exact outside distance by brute force over its primitives, used only while
    that costs less than indexing the deposit's surface mesh."""

    MAX_EVALUATIONS = 200_000_000

    def __init__(self, beads):
        from ..deposit.engine import build_primitives

        self.beads = beads
        self.prims = build_primitives(beads)

    def affordable(self, n_points: int) -> bool:
        return n_points * len(self.prims) <= self.MAX_EVALUATIONS

    def __call__(self, points: np.ndarray) -> np.ndarray:
        return union_distance(self.prims, self.beads.code, self.beads.exponent, points)


def _exact_beyond_band(points: np.ndarray, sdf: np.ndarray, band: float, voxel: float, other_mesh,
                       exact_outside=None) -> np.ndarray:
    """``sdf`` (the other solid's SDF sampled at ``points``) with its clamped values replaced
    by exact distances.

    Inside the other grid's narrow band its SDF is the distance (trilinear, second-order
    accurate at the surface); beyond the band it is clamped, so those points are measured
    exactly: outside the other solid by ``exact_outside`` when given and affordable (the
    deposit's union of bead primitives: exact there, and far cheaper than indexing its fine
    surface for a few points), otherwise against the other surface's triangles
    (``other_mesh()``, built only when needed)."""
    from .distance import MeshDistance

    sdf = np.array(sdf, np.float64)
    far = np.abs(sdf) >= band - voxel
    if exact_outside is not None:
        outside = far & (sdf > 0)
        if outside.any() and exact_outside.affordable(int(outside.sum())):
            sdf[outside] = exact_outside(points[outside])
        far &= ~outside
    if far.any():
        distance = MeshDistance(*other_mesh()).query(points[far])[0]
        sdf[far] = np.where(sdf[far] < 0, -distance, distance)
    return sdf


@dataclass(frozen=True, eq=False)
class CompareDetail:
    """What a comparison computed beyond its JSON summary, for pictures and reports: the deposit
    grid and its ``simulate`` summary, the CAD mesh as placed, and both surfaces as (vertices,
    triangles, deviation_mm)."""

    deposit: SparseGrid
    simulate: dict
    cad_mesh: tuple
    cad_surface: tuple | None
    deposit_surface: tuple | None


def _dense_voxels_at_least(tp: Toolpath, cad_bounds, v: float) -> int:
    """A lower bound of the comparison volume, known before depositing: the deposit grid spans
    at least the CAD part and the deposit path, plus its margin of a band and two voxels a side.
    0 when the voxel is invalid (the deposit says so)."""
    from ..deposit.engine import BAND_VOXELS

    if not (np.isfinite(v) and v > 0):
        return 0
    lo, hi = cad_bounds
    if tp.deposit.any():
        path = tp.deposit_bbox()
        lo, hi = np.minimum(lo, path[0]), np.maximum(hi, path[1])
    return int(np.prod(np.ceil((hi - lo) / v) + 1 + 2 * (BAND_VOXELS + 2), dtype=np.float64))


def check_comparison_fits(tp: Toolpath, cad_bounds, voxel: float) -> None:
    """Refuse, before depositing, a comparison whose dense volume would exceed its limit."""
    _check_dense_volume(_dense_voxels_at_least(tp, cad_bounds, voxel), voxel)


def _check_dense_volume(n_dense: int, v: float) -> None:
    if n_dense > MAX_DENSE_VOXELS:
        raise DmdvoxError(f"--voxel {v:g}: the comparison volume has {n_dense:,d} voxels (limit "
                          f"{MAX_DENSE_VOXELS:,d}); use a voxel of at least "
                          f"{v * (n_dense / MAX_DENSE_VOXELS) ** (1 / 3) * 1.05:.3g} mm")


def compare(plan: ProcessPlan, cad_path: str | Path, voxel: float | None = None, cad_offset=(0.0, 0.0, 0.0),
            out_dir: str | Path | None = None, max_memory: int | None = None,
            simulate_out_dir: str | Path | None = None) -> dict:
    """Deposit the plan's beads and compare; ``simulate_out_dir`` also writes the deposit's own
    outputs (as ``simulate --out``) from the same run, listed first in ``outputs``. Returns the
    JSON summary."""
    return compare_detail(plan, cad_path, voxel, cad_offset, out_dir, max_memory, simulate_out_dir)[0]


def compare_detail(plan: ProcessPlan, cad_path: str | Path, voxel: float | None = None, cad_offset=(0.0, 0.0, 0.0),
                   out_dir: str | Path | None = None, max_memory: int | None = None,
                   simulate_out_dir: str | Path | None = None) -> tuple[dict, CompareDetail]:
    """:func:`compare`, also returning its :class:`CompareDetail` (the surfaces only when
    ``out_dir`` is given: the statistics do not need them)."""
    from ..grid.surface import surface_mesh

    tp, bead = plan.toolpath, plan.profile
    voxel = plan.default_voxel() if voxel is None else float(voxel)
    timings = {}
    t = time.perf_counter()
    cad_vertices, cad_triangles, warnings = load_cad(cad_path, cad_offset)
    for warning in warnings:
        checks.warn(warning)
    bounds = (cad_vertices.min(axis=0), cad_vertices.max(axis=0))
    # before the volume check: a CAD part in another frame is also what makes that volume huge
    apart = checks.warn_if_apart(tp, bead, cad_path, *bounds, offset=cad_offset)
    if apart:
        warnings.append(apart)
    check_comparison_fits(tp, bounds, voxel)
    progress.stage("deposit", describe(plan))
    sim = simulate_plan(plan, voxel=voxel, max_memory=max_memory, extra_bounds=bounds, out_dir=simulate_out_dir)
    deposit: SparseGrid = sim["grid"]
    timings.update(sim["timings_s"])
    timings["simulate_s"] = time.perf_counter() - t

    v = deposit.voxel
    v3 = v**3
    _check_dense_volume(int(np.prod(deposit.block.shape, dtype=np.int64)) * 512, v)
    t = time.perf_counter()
    progress.stage("compare", f"CAD level set on the deposit's {v:g} mm voxels")
    cad_level_set = cad_index_level_set(cad_vertices, cad_triangles, deposit)
    cad_sdf = np.empty(tuple(8 * np.asarray(deposit.block.shape)), np.float32)
    cad_level_set.copyToArray(cad_sdf, (0, 0, 0))
    cad_sdf *= np.float32(v)
    timings["cad_level_set_s"] = time.perf_counter() - t

    t = time.perf_counter()
    progress.stage("compare", "void, overbuild and their depths")
    dep_sdf = deposit.dense_sdf()
    # occupancy as the void analysis counts it: a gap thinner than a voxel, which the deposit
    # now keeps, weighs its thickness rather than the quarter voxel the planar estimate gives it
    cad_z, void_z, over_z = _volume_slices(occupancy_sdf(dep_sdf, v), cad_sdf, v)
    cad_volume = float(cad_z.sum() * v3)
    void_volume = float(void_z.sum() * v3)
    over_volume = float(over_z.sum() * v3)
    z_world = deposit.origin[2] + v * np.arange(dep_sdf.shape[2])
    layers = _layer_table(plan.layer_bottoms(), z_world, v, void_z * v3, over_z * v3)
    max_underfill = _max_distance(cad_sdf, dep_sdf, deposit.band, v)
    cad_band = CAD_BAND_VOXELS * v
    max_overbuild = _max_distance(dep_sdf, cad_sdf, cad_band, v)
    timings["volumes_s"] = time.perf_counter() - t

    t = time.perf_counter()
    progress.stage("compare", "surface deviation")
    # the deposit's surface: the one simulate wrote with --out, else meshed only if needed
    deposit_mesh = _Lazy(lambda: sim["surface"][:2] if sim["surface"] is not None else surface_mesh(deposit))
    exact_outside = _BeadUnionDistance(sim["beads"])
    # Positive = excess material: a CAD surface point inside the deposit, a deposit surface
    # point outside the CAD.
    index_points, dep_at_cad, weights = edge_crossings(cad_sdf, dep_sdf)
    cad_deviation = -_exact_beyond_band(deposit.origin + v * index_points, dep_at_cad, deposit.band, v,
                                        deposit_mesh, exact_outside)
    deviation_stats = weighted_stats(cad_deviation, weights)
    timings["deviation_s"] = time.perf_counter() - t

    pores = []
    centroids = np.array([p.centroid_mm for p in sim["porosity"].pores], float).reshape(-1, 3)
    inside_cad = trilinear(cad_sdf, deposit.world_to_index(centroids), cad_band) < 0
    for info, inside in zip(sim["pores"], inside_cad):
        pores.append({**info, "inside_cad": bool(inside)})

    cad_volume_safe = cad_volume if cad_volume > 0 else float("nan")
    summary = {
        "model": sim["model"],
        "flow_source": sim["flow_source"],
        "cad_volume_mm3": cad_volume,
        "deposit_volume_mm3": sim["deposit_volume_mm3"],
        "deposited_volume_mm3": sim["deposited_volume_mm3"],
        "lost_volume_mm3": sim["lost_volume_mm3"],
        "mass_balance_percent": sim["mass_balance_percent"],
        "void_volume_mm3": void_volume,
        "overbuild_volume_mm3": over_volume,
        "void_percent": 100.0 * void_volume / cad_volume_safe,
        "overbuild_percent": 100.0 * over_volume / cad_volume_safe,
        "max_underfill_mm": max_underfill,
        "max_overbuild_mm": max_overbuild,
        "deviation_mm": deviation_stats,
        "layers": layers,
        "pore_count": len(pores),
        "pores": pores,
        "porosity_percent": sim["porosity_percent"],
        "outputs": list(sim["outputs"]),
        "voxel_mm": v,
        "warnings": warnings + [w for w in sim["warnings"] if w not in warnings],
        "timings_s": {},
    }
    for key in GROWTH_KEYS:
        if key in sim:
            summary["growth_layers" if key == "layers" else key] = sim[key]
    cad_surface = dep_surface = None
    if out_dir is not None:
        t = time.perf_counter()
        progress.stage("compare", f"deviation maps and files in {out_dir}")
        points, triangles = _level_set_mesh(cad_level_set)
        cad_surface_vertices = deposit.origin + v * points
        cad_surface = (cad_surface_vertices, triangles,
                       -_exact_beyond_band(cad_surface_vertices, trilinear(dep_sdf, points, float(deposit.band)),
                                           deposit.band, v, deposit_mesh, exact_outside))
        dep_vertices, dep_triangles = deposit_mesh()
        dep_at_points = trilinear(cad_sdf, deposit.world_to_index(dep_vertices), cad_band)
        dep_surface = (dep_vertices, dep_triangles,
                       _exact_beyond_band(dep_vertices, dep_at_points, cad_band, v,
                                          _Lazy(lambda: (cad_vertices, cad_triangles))))
        timings["surfaces_s"] = time.perf_counter() - t
        t = time.perf_counter()
        summary["outputs"] += _write_outputs(
            Path(out_dir), Path(tp.source).stem or "deposit", summary, deposit, dep_sdf, cad_sdf, cad_surface,
            dep_surface)
        timings["outputs_s"] = time.perf_counter() - t
    summary["timings_s"] = {k: round(float(val), 4) for k, val in timings.items()}
    if out_dir is not None:
        from ..io.atomic import write_text

        write_text(Path(summary["outputs"][-1]), json.dumps(summary, indent=2))
    simulated = {k: v for k, v in sim.items() if k not in RUN_OBJECTS}
    return summary, CompareDetail(deposit, simulated, (cad_vertices, cad_triangles), cad_surface, dep_surface)


class _Lazy:
    """A value computed on first call and kept (a surface mesh needed only for a few far points)."""

    def __init__(self, make):
        self._make = make
        self._value = None

    def __call__(self):
        if self._value is None:
            self._value = self._make()
        return self._value


def cad_index_level_set(vertices: np.ndarray, triangles: np.ndarray, like: SparseGrid):
    """The CAD mesh as an OpenVDB level set in ``like``'s index space (voxel (0, 0, 0) at
    ``like.origin``, unit voxels, half width ``CAD_BAND_VOXELS``): index space keeps float32
    precise however far the part is from the machine origin, and the dense copy starts at
    index 0."""
    index_vertices = (np.asarray(vertices, np.float64) - like.origin) / like.voxel
    return openvdb.FloatGrid.createLevelSetFromPolygons(
        np.ascontiguousarray(index_vertices), triangles=np.ascontiguousarray(triangles, np.int32),
        transform=openvdb.createLinearTransform(1.0), halfWidth=CAD_BAND_VOXELS)


def _level_set_mesh(level_set) -> tuple[np.ndarray, np.ndarray]:
    """Zero surface of an index-space level set: (index-space points, outward triangles), as
    :func:`dmdvox.grid.surface.surface_mesh` orients them."""
    points, tris, quads = level_set.convertToPolygons(0.0, 0.0)
    tris = np.asarray(tris, np.int64).reshape(-1, 3)
    quads = np.asarray(quads, np.int64).reshape(-1, 4)
    triangles = np.concatenate([tris[:, ::-1], quads[:, [0, 2, 1]], quads[:, [0, 3, 2]]])
    return np.asarray(points, np.float64), np.ascontiguousarray(triangles)


def _write_outputs(out: Path, stem: str, summary: dict, deposit: SparseGrid, dep_sdf, cad_sdf, cad_surface,
                   dep_surface) -> list[str]:
    from ..io.atomic import write_text
    from ..io.mesh import write_vtp
    from ..io.vtk_image import write_voxels

    outputs = []
    cv, ct, cdev = cad_surface
    dv, dt, ddev = dep_surface
    outputs.append(str(write_vtp(out / f"{stem}_cad_deviation.vtp", cv, ct, point_arrays={"deviation_mm": cdev})))
    outputs.append(str(write_vtp(out / f"{stem}_deposit_deviation.vtp", dv, dt, point_arrays={"deviation_mm": ddev})))
    dep_inside = dep_sdf < 0
    cad_inside = cad_sdf < 0
    label = np.full(dep_sdf.shape, LABEL_OUTSIDE, np.uint8)
    label[dep_inside & cad_inside] = LABEL_BOTH
    label[cad_inside & ~dep_inside] = LABEL_VOID
    label[dep_inside & ~cad_inside] = LABEL_OVERBUILD
    label[_pore_mask(dep_inside)] = LABEL_PORE
    outputs += [str(p) for p in write_voxels(
        out / f"{stem}_compare.vti", deposit.origin, deposit.voxel,
        {"label": label, "deposit_sdf_mm": dep_sdf, "cad_sdf_mm": cad_sdf})]
    from ..view.pictures import render_surface

    outputs.append(str(render_surface(
        out / f"{stem}_cad_deviation.png", cv, ct, scalars=cdev, scalar_name="deviation_mm",
        title=f"{stem}: CAD surface deviation")))
    buffer = io.StringIO()
    writer = csv.DictWriter(buffer, fieldnames=["layer", "z_mm", "void_mm3", "overbuild_mm3"], lineterminator="\n")
    writer.writeheader()
    writer.writerows(summary["layers"])
    outputs.append(str(write_text(out / f"{stem}_layers.csv", buffer.getvalue())))
    outputs.append(str(out / f"{stem}_compare.json"))
    return outputs
