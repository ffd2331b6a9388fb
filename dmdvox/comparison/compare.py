"""`dmdvox compare`: the deposit against the CAD part, on one lattice, sparse throughout.

The CAD STL becomes a sparse level set on the deposit grid's own lattice and block table
(:func:`dmdvox.grid.levelset.like_grid`), so every comparison is voxel against voxel, and every
pass walks the blocks of the two sparse trees (:mod:`.blocks`), never an array over the box:

* void (inside CAD, outside deposit) and overbuild (inside deposit, outside CAD) volumes from
  the sub-voxel occupancies of both SDFs: per voxel ``max(0, f_cad - f_dep)`` and
  ``max(0, f_dep - f_cad)`` with ``f = clamp(0.5 - sdf / voxel, 0, 1)`` (exact where one
  surface does not cross the other inside a voxel);
* max underfill / overbuild depth: the largest distance from a void (overbuild) voxel to the
  deposit (CAD): the other grid's SDF inside its narrow band; beyond it the exact distance to
  the other surface, searched block by block (:mod:`.depth`);
* signed surface deviation, positive = excess material: on the CAD surface, how far the
  deposit surface lies outside it (negative: the deposit falls short, underfill); on the
  deposit surface, how far it lies outside the CAD surface (negative: inside the CAD).
  Within the other grid's narrow band the value is its SDF (trilinear), beyond it the exact
  distance to the other surface. The statistics sample the CAD surface where it crosses the
  lattice's edges, weighted to be uniform by area (:mod:`.sampling`), so they need no mesh;
  the maps (``--out``) carry the same values on both surfaces' meshes;
* a per-layer table of void and overbuild: a voxel plane holding a layer boundary gives each
  layer the part of its void (overbuild) that lies on that layer's side of the boundary (from
  which side of the voxel the deposit (CAD) surface leaves it empty);
* the part's internal void: the deposit's enclosed voids (:mod:`dmdvox.grid.enclosure`) weighed
  by the CAD's occupancy of their voxels, split into lack of fusion (slivers between beads)
  and cavities (voids a channel-width ball fits in: sparse infill, a missing line);
  ``porosity_percent`` is that void as a percentage of the CAD volume, and each pore says how
  much of it lies inside the CAD.

With ``--out``: the surfaces' deviation maps (``.vtp``), the label and both SDFs as sparse
OpenVDB grids (``_compare.vdb``) and as VTK image blocks covering only the occupied regions
(one ``.vti`` when small, else a ``.vtm`` of pieces), the per-layer CSV and the JSON summary.
"""

from __future__ import annotations

import csv
import io
import json
import time
from dataclasses import dataclass, replace
from pathlib import Path

import numpy as np

from .. import checks, progress
from ..deposit.engine import union_distance
from ..deposit.simulate import GROWTH_KEYS, SimulateRequest, Simulation, describe, simulate, widened
from ..defaults import BAND_VOXELS
from ..errors import DmdvoxError, InputFileError, InputWarning
from ..grid.levelset import like_grid, mesh_area, surface_memory
from ..grid.sparse import BLOCK
from ..grid.sparse import SparseGrid
from ..process.plan import ProcessPlan
from .blocks import LABEL_NAMES
from .depth import deepest
from .slabs import SLAB_BLOCKS, block_passes
from .sampling import weighted_stats
from ..summary import SummaryResult


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
        low, high = _volume_range(vertices, triangles)
        largest = max(abs(low), abs(high))
        # An open sheet (one flat facet, say) measures 0 from every corner: no volume at all.
        if largest == 0 or not high - low <= OPEN_VOLUME_SPREAD * largest:
            raise InputFileError(
                f"{path}: the mesh is open ({open_edges} edges not shared by exactly two triangles: holes, or a "
                f"truncated file) and encloses no definite volume (from {low:,.6g} to {high:,.6g} mm^3 as measured "
                "from the corners of its box); close its holes (repair the STL) or export it again")
        warnings.append(f"{path}: mesh is not watertight ({open_edges} edges not shared by exactly two "
                        f"triangles; its volume holds to {100 * (high - low) / largest:.2g} %); "
                        "inside/outside may be wrong near the holes")
    return vertices, triangles, warnings


# An open mesh's enclosed volume depends on the point it is measured from by at most this
# fraction for its holes to be small defects rather than missing faces (a 20 x 20 x 6 mm box
# missing one of its 12 triangles: 17 %; one 0.6 mm^2 facet of one meshed 10 x 10 a face: 0.17 %).
OPEN_VOLUME_SPREAD = 0.01


def _volume_range(vertices: np.ndarray, triangles: np.ndarray) -> tuple[float, float]:
    """The smallest and largest signed volume of the mesh's triangle cones from a corner of its
    box. Each cone's volume is affine in its apex p: V(p) = V(0) - p . N / 6, N the sum of the
    triangles' doubled area vectors, which is zero for a closed mesh (the same volume from
    everywhere) and the holes' own (reversed) area otherwise."""
    corners = vertices[triangles]
    centre = (vertices.min(axis=0) + vertices.max(axis=0)) / 2
    a, b, c = corners[:, 0] - centre, corners[:, 1] - centre, corners[:, 2] - centre
    volume = float(np.einsum("ij,ij->", a, np.cross(b, c))) / 6.0
    area = np.cross(b - a, c - a).sum(axis=0)
    reach = float(np.abs(area) @ (vertices.max(axis=0) - vertices.min(axis=0))) / 12.0
    return volume - reach, volume + reach


def plane_cuts(bottoms: np.ndarray, z_world: np.ndarray, voxel: float) -> np.ndarray:
    """For every voxel plane (centres ``z_world``), the height (0..1 from its bottom) of the
    first layer boundary strictly inside it, -1 where none is. Layer k spans from its bead
    bottom to the next layer's (the first from below the part, the last to above it)."""
    cut = np.full(z_world.shape, -1.0)
    edges = np.asarray(bottoms, np.float64)[1:]
    if edges.size == 0:
        return cut
    lo = z_world - voxel / 2
    first = np.searchsorted(edges, lo, side="right")  # the first boundary above the plane's bottom
    inside = first < edges.size
    above = np.where(inside, edges[np.minimum(first, edges.size - 1)], np.inf)
    inside &= above < lo + voxel
    cut[inside] = (above[inside] - lo[inside]) / voxel
    return cut


def _layer_table(bottoms: np.ndarray, z_world: np.ndarray, voxel: float, cut: np.ndarray, void_low, void_high,
                 over_low, over_high) -> list[dict]:
    """Void and overbuild per layer (mm^3 per plane given below and above its cut)."""
    if bottoms.size == 0:
        return []
    edges = np.asarray(bottoms, np.float64)[1:]
    lo = z_world - voxel / 2
    below = np.searchsorted(edges, np.where(cut >= 0, lo, z_world), side="right")
    above = np.where(cut >= 0, below + 1, below)
    n = bottoms.size
    void = np.bincount(below, void_low, n) + np.bincount(above, void_high, n)
    over = np.bincount(below, over_low, n) + np.bincount(above, over_high, n)
    return [{"layer": int(k), "z_mm": round(float(bottoms[k]), 9), "void_mm3": float(void[k]),
             "overbuild_mm3": float(over[k])} for k in range(n)]


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
    sdf = np.array(sdf, np.float64)
    far = np.abs(sdf) >= band - voxel
    sdf[far] = _exact_distances(points[far], sdf[far], other_mesh, exact_outside)
    return sdf


def _exact_distances(points: np.ndarray, clamped: np.ndarray, other_mesh, exact_outside=None) -> np.ndarray:
    """The exact signed distances at ``points`` where the other solid's SDF was ``clamped``
    (its sign kept), as :func:`_exact_beyond_band` measures them."""
    from .distance import MeshDistance

    exact = np.array(clamped, np.float64)
    far = np.ones(exact.shape, bool)
    if exact_outside is not None:
        outside = exact > 0
        if outside.any() and exact_outside.affordable(int(outside.sum())):
            exact[outside] = exact_outside(points[outside])
            far &= ~outside
    if far.any():
        distance = MeshDistance(*other_mesh()).query(points[far])[0]
        exact[far] = np.where(exact[far] < 0, -distance, distance)
    return exact


@dataclass(frozen=True)
class CompareRequest:
    """What to compare: the plan's deposit (swept at ``voxel``, default the plan's) against the
    CAD STL at ``cad`` moved by ``cad_offset`` (mm); outputs to ``out_dir`` (deviation maps,
    label and SDF fields, the per-layer CSV and the JSON) and the deposit's own outputs (as
    ``simulate --out``) to ``simulate_out_dir``; within ``max_memory`` bytes; the slabs on the
    dask cluster at ``scheduler`` (the same numbers as here); ``surfaces``: the deviation maps
    (:meth:`Comparison.deviation_maps`) also without outputs."""

    plan: ProcessPlan
    cad: str | Path
    cad_offset: tuple[float, float, float] = (0.0, 0.0, 0.0)
    voxel: float | None = None
    out_dir: str | Path | None = None
    simulate_out_dir: str | Path | None = None
    max_memory: int | None = None
    scheduler: str | None = None
    surfaces: bool = False  # the deviation maps on both surfaces even without out_dir
    cache: bool = True  # the deposit from (and into) the deposit cache (deposit/cache.py)


@dataclass(frozen=True, eq=False)
class Comparison(SummaryResult):
    """A comparison's result: ``summary`` (the JSON ``--json`` prints, also readable as
    ``result[key]``), the ``simulation`` of the deposit, the ``cad`` grid on its lattice, the
    CAD mesh as placed, and both surfaces as (vertices, triangles, deviation_mm) when outputs
    were written (the statistics do not need them)."""

    summary: dict
    simulation: Simulation
    cad: SparseGrid
    cad_mesh: tuple
    cad_surface: tuple | None
    deposit_surface: tuple | None

    @property
    def deposit(self) -> SparseGrid:
        return self.simulation.grid

    def deviation_maps(self):
        """The CAD's and the deposit's surfaces as ``pyvista.PolyData`` with ``deviation_mm``
        per vertex (+ = excess material), as the ``.vtp`` maps hold them."""
        from ..io.pyvista import polydata

        if self.cad_surface is None:
            raise DmdvoxError("the deviation maps are made with out_dir or surfaces=True in the CompareRequest")
        return tuple(polydata(v, t, {"deviation_mm": d}) for v, t, d in (self.cad_surface, self.deposit_surface))


def compare(request: CompareRequest, *, pictures=None, also_holds: dict[str, int] | None = None,
            simulation: Simulation | None = None) -> Comparison:
    """Deposit the plan's beads and compare them with the CAD part. ``pictures(out_dir, stem,
    cad_surface)`` draws what the caller wants beside the files (the comparison draws nothing
    itself) and returns the paths, listed before the JSON, which is written last.
    ``also_holds`` (name -> bytes) is what the caller holds beside, for the memory check.
    ``simulation``: the plan's deposit swept before at the request's voxel (a
    :class:`dmdvox.Build`'s), widened here to the CAD's blocks instead of swept again."""
    plan, cad_path, cad_offset = request.plan, request.cad, request.cad_offset
    out_dir, max_memory, scheduler = request.out_dir, request.max_memory, request.scheduler
    voxel = request.voxel
    from ..grid.surface import surface_mesh
    from .distance import MeshDistance

    tp = plan.toolpath
    voxel = plan.resolve_voxel(voxel)
    timings = {}
    t = time.perf_counter()
    cad_vertices, cad_triangles, warnings = load_cad(cad_path, cad_offset)
    for warning in warnings:
        checks.warn(warning, InputWarning)
    bounds = (cad_vertices.min(axis=0), cad_vertices.max(axis=0))
    apart = checks.warn_if_apart(tp, plan.profile, cad_path, *bounds, offset=cad_offset)
    if apart:
        warnings.append(apart)
    holds = {"CAD": cad_memory(cad_vertices, cad_triangles, voxel), **(also_holds or {})}
    if simulation is None:
        progress.stage("deposit", describe(plan))
        sim = simulate(SimulateRequest(plan, voxel=voxel, out_dir=request.simulate_out_dir, max_memory=max_memory,
                                       scheduler=scheduler, cache=request.cache), extra_bounds=bounds,
                       also_holds=holds)
    else:
        if simulation.grid.voxel != voxel or request.simulate_out_dir is not None:
            raise DmdvoxError("a given simulation must be swept at the comparison's voxel, with no simulate_out_dir")
        grid, pores = widened(simulation.grid, simulation.porosity, bounds)
        # the summary's grid is the widened one, as when the sweep is widened to the CAD (simulate's extra_bounds)
        sim = replace(simulation, grid=grid, porosity=pores,
                      summary={**simulation.summary, "memory_bytes": int(grid.memory_bytes)})
    deposit = sim.grid
    timings.update(sim.summary["timings_s"])
    timings["simulate_s"] = time.perf_counter() - t

    v = deposit.voxel
    t = time.perf_counter()
    progress.stage("compare", f"CAD level set on the deposit's {v:g} mm voxels")
    cad = like_grid(cad_vertices, cad_triangles, deposit, {"source": str(cad_path)})
    timings["cad_level_set_s"] = time.perf_counter() - t

    t = time.perf_counter()
    progress.stage("compare", "void, overbuild, their depths and the surface deviation")
    nz = 8 * deposit.block.shape[2]
    z_world = deposit.origin[2] + v * np.arange(nz)
    bottoms = plan.layer_bottoms()
    cut = plane_cuts(bottoms, z_world, v)
    passes = block_passes(deposit, cad, cut, scheduler)
    per_plane = passes.per_plane
    cad_volume = float(per_plane[0].sum())
    void_volume = float(per_plane[1].sum() + per_plane[2].sum())
    over_volume = float(per_plane[3].sum() + per_plane[4].sum())
    layers = _layer_table(bottoms, z_world, v, cut, *per_plane[1:])
    timings["block_passes_s"] = time.perf_counter() - t

    t = time.perf_counter()
    # the deposit's surface: the one simulate wrote with --out, else meshed only if needed
    deposit_mesh = _Lazy(lambda: sim.surface_mesh[:2] if sim.surface_mesh is not None else surface_mesh(deposit))
    exact_outside = _BeadUnionDistance(sim.beads)
    dep_view, cad_view = deposit.view(), cad.view()
    max_underfill = deepest(cad_view, dep_view, passes.far_under, deposit.origin, v,
                            _OutsideDistance(exact_outside, deposit_mesh), passes.under)
    cad_distance = MeshDistance(cad_vertices, cad_triangles)
    max_overbuild = deepest(dep_view, cad_view, passes.far_over, deposit.origin, v,
                            lambda points: cad_distance.query(points)[0], passes.over)
    # Positive = excess material: a CAD surface point inside the deposit, a deposit surface
    # point outside the CAD.
    dep_at_cad = passes.deviation.copy()
    dep_at_cad[passes.far] = _exact_distances(passes.far_points, dep_at_cad[passes.far], deposit_mesh, exact_outside)
    deviation_stats = weighted_stats(-dep_at_cad, passes.weights)
    timings["depths_s"] = time.perf_counter() - t

    # The part's internal void: each enclosed void weighed by the CAD's occupancy of its
    # voxels; slivers between beads are lack of fusion, voids a channel-width ball fits in are
    # cavities (sparse infill, a missing line).
    voids = sim.porosity.voids
    in_cad = voids.volume_where(lambda ijk: np.clip(0.5 - cad.value_at_index(ijk) / v, 0.0, 1.0))
    pores = [{**info, "inside_cad_mm3": float(in_cad[k]), "inside_cad": bool(in_cad[k] > 0.5 * info["volume_mm3"])}
             for k, info in enumerate(sim.summary["pores"])]
    # the pores pore_count counts: specks (below the speck floor) apart, as in simulate
    lack_of_fusion = float(in_cad[~voids.wide & ~voids.speck].sum())
    cavities = float(in_cad[voids.wide & ~voids.speck].sum())

    cad_volume_safe = cad_volume if cad_volume > 0 else float("nan")
    if not apart:
        misaligned = checks.warn_if_misaligned(tp, plan.profile, cad_path, *bounds, cad_offset,
                                               100.0 * void_volume / cad_volume_safe,
                                               100.0 * over_volume / cad_volume_safe)
        if misaligned:
            warnings.append(misaligned)
    summary = {
        "model": sim.summary["model"],
        "flow_source": sim.summary["flow_source"],
        "cad_volume_mm3": cad_volume,
        "deposit_volume_mm3": sim.summary["deposit_volume_mm3"],
        "deposited_volume_mm3": sim.summary["deposited_volume_mm3"],
        "lost_volume_mm3": sim.summary["lost_volume_mm3"],
        "mass_balance_percent": sim.summary["mass_balance_percent"],
        "lost_percent": sim.summary["lost_percent"],
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
        "porosity_percent": 100.0 * (lack_of_fusion + cavities) / cad_volume_safe,
        "internal_void_mm3": lack_of_fusion + cavities,
        "lack_of_fusion_mm3": lack_of_fusion,
        "cavity_mm3": cavities,
        "deposit_porosity_percent": sim.summary["porosity_percent"],
        "speck_count": sim.summary["speck_count"],
        "outputs": list(sim.summary["outputs"]),
        "voxel_mm": v,
        "active_voxels": {"deposit": int(deposit.active_voxels), "cad": int(cad.active_voxels)},
        "memory_bytes": {"deposit": int(deposit.memory_bytes), "cad": int(cad.memory_bytes)},
        "warnings": warnings + [w for w in sim.summary["warnings"] if w not in warnings],
        "timings_s": {},
    }
    for key in GROWTH_KEYS:
        if key in sim.summary:
            summary["growth_layers" if key == "layers" else key] = sim.summary[key]
    cad_surface = dep_surface = None
    if out_dir is not None or request.surfaces:
        cad_surface, dep_surface = _surfaces_and_files(summary, timings, sim, cad, (cad_vertices, cad_triangles),
                                                       deposit_mesh, exact_outside, out_dir, pictures,
                                                       Path(tp.source).stem or "deposit")
    summary["timings_s"] = {k: round(float(val), 4) for k, val in timings.items()}
    if out_dir is not None:
        _write_summary(summary)
    return Comparison(summary, sim, cad, (cad_vertices, cad_triangles), cad_surface, dep_surface)


def with_outputs(comparison: Comparison, plan: ProcessPlan, out_dir: str | Path, *,
                 simulation: Simulation | None = None, pictures=None) -> Comparison:
    """``comparison`` (of ``plan``, made without outputs) with its deviation maps and the files ``compare
    --out`` writes written into ``out_dir``, as :func:`compare` with ``out_dir`` makes them;
    ``simulation``: its deposit with the files ``simulate --out`` wrote (the outputs listed
    first, its surface the deposit's)."""
    sim = comparison.simulation if simulation is None else simulation
    summary = json.loads(json.dumps(comparison.summary))
    summary["outputs"] = list(sim.summary["outputs"])
    mapped = _with_maps(comparison, plan, sim, summary, out_dir, pictures)
    _write_summary(mapped.summary)
    return mapped


def with_surfaces(comparison: Comparison, plan: ProcessPlan) -> Comparison:
    """``comparison`` (of ``plan``, made without surfaces) with both surfaces' deviation maps, as
    :func:`compare` with ``surfaces`` makes them; no file written."""
    if comparison.cad_surface is not None:
        return comparison
    return _with_maps(comparison, plan, comparison.simulation, json.loads(json.dumps(comparison.summary)), None, None)


def _with_maps(comparison: Comparison, plan: ProcessPlan, sim: Simulation, summary: dict, out_dir, pictures) -> Comparison:
    """``comparison`` on deposit ``sim`` with both surfaces' deviation maps (and with ``out_dir``
    their files), ``summary`` taking the paths and timings."""
    from ..grid.surface import surface_mesh

    timings = dict(summary["timings_s"])
    deposit_mesh = _Lazy(lambda: sim.surface_mesh[:2] if sim.surface_mesh is not None else surface_mesh(sim.grid))
    cad_surface, dep_surface = _surfaces_and_files(summary, timings, sim, comparison.cad, comparison.cad_mesh,
                                                   deposit_mesh, _BeadUnionDistance(sim.beads), out_dir, pictures,
                                                   Path(plan.toolpath.source).stem or "deposit")
    summary["timings_s"] = {k: round(float(val), 4) for k, val in timings.items()}
    return replace(comparison, summary=summary, simulation=sim, cad_surface=cad_surface, deposit_surface=dep_surface)


def _surfaces_and_files(summary: dict, timings: dict, sim: Simulation, cad: SparseGrid, cad_mesh: tuple,
                        deposit_mesh, exact_outside, out_dir, pictures, stem: str) -> tuple[tuple, tuple]:
    """Both surfaces with their deviation, and with ``out_dir`` the files but the JSON (their
    paths added to ``summary``, the JSON's last); returns (cad_surface, deposit_surface)."""
    from ..grid.surface import surface_mesh

    deposit, v = sim.grid, sim.grid.voxel
    cad_vertices, cad_triangles = cad_mesh
    t = time.perf_counter()
    progress.stage("compare", "deviation maps" + (f" and files in {out_dir}" if out_dir is not None else ""))
    cad_surface_vertices, cad_surface_triangles = surface_mesh(cad)
    cad_surface = (cad_surface_vertices, cad_surface_triangles,
                   -_exact_beyond_band(cad_surface_vertices, deposit.trilinear(cad_surface_vertices),
                                       deposit.band, v, deposit_mesh, exact_outside))
    dep_vertices, dep_triangles = deposit_mesh()
    dep_surface = (dep_vertices, dep_triangles,
                   _exact_beyond_band(dep_vertices, cad.trilinear(dep_vertices), cad.band, v,
                                      _Lazy(lambda: (cad_vertices, cad_triangles))))
    timings["surfaces_s"] = time.perf_counter() - t
    if out_dir is not None:
        t = time.perf_counter()
        summary["outputs"] += write_outputs(Path(out_dir), stem, summary, deposit, cad, sim.porosity, cad_surface,
                                            dep_surface)
        if pictures is not None:
            summary["outputs"] += [str(p) for p in pictures(Path(out_dir), stem, cad_surface)]
        summary["outputs"].append(str(Path(out_dir) / f"{stem}_compare.json"))
        timings["outputs_s"] = time.perf_counter() - t
    return cad_surface, dep_surface


def cad_memory(vertices: np.ndarray, triangles: np.ndarray, voxel: float) -> int:
    """Bytes the comparison holds beside the deposit: the CAD part's level set, its surface's
    crossings (about 1.5 per surface voxel, 16 B each kept, 40 B in the slab making them) and a
    slab of both grids in copy (:mod:`.slabs`)."""
    band = BAND_VOXELS * voxel
    vertices = np.asarray(vertices, np.float64)
    blocks = float(np.prod(np.ceil((vertices.max(axis=0) - vertices.min(axis=0) + 2 * band) / (BLOCK * voxel)) + 1))
    area = mesh_area(vertices, triangles)
    grid = surface_memory(area, voxel, band, blocks)
    crossings = 1.5 * area / voxel**2
    slab = min(2 * grid, 2 * SLAB_BLOCKS * BLOCK**3 * 8)
    return int(grid + crossings * 16 + min(crossings, SLAB_BLOCKS * BLOCK**2) * 40 + slab)


class _OutsideDistance:
    """Exact distance to the deposit from points outside it: its bead union by brute force while
    that is cheap, else its surface mesh (built on first need)."""

    def __init__(self, beads, mesh):
        self.beads = beads
        self.mesh = mesh
        self.index = None

    def __call__(self, points: np.ndarray) -> np.ndarray:
        from .distance import MeshDistance

        if self.beads.affordable(len(points)):
            return self.beads(points)
        if self.index is None:
            self.index = MeshDistance(*self.mesh())
        return self.index.query(points)[0]


def _write_summary(summary: dict) -> None:
    """The comparison's JSON, at the last of its outputs (written last, once the summary is whole)."""
    from ..io.atomic import write_text

    write_text(Path(summary["outputs"][-1]), json.dumps(summary, indent=2))


class _Lazy:
    """A value computed on first call and kept (a surface mesh needed only for a few far points)."""

    def __init__(self, make):
        self._make = make
        self._value = None

    def __call__(self):
        if self._value is None:
            self._value = self._make()
        return self._value


def write_outputs(out: Path, stem: str, summary: dict, deposit: SparseGrid, cad: SparseGrid, porosity, cad_surface,
                  dep_surface) -> list[str]:
    """The comparison's files but its JSON (module docstring, written by the caller once the
    summary is complete); returns their paths."""
    from ..io.atomic import write_text
    from ..io.mesh import write_vtp
    from .fields import write_fields

    outputs = []
    cv, ct, cdev = cad_surface
    dv, dt, ddev = dep_surface
    outputs.append(str(write_vtp(out / f"{stem}_cad_deviation.vtp", cv, ct, point_arrays={"deviation_mm": cdev})))
    outputs.append(str(write_vtp(out / f"{stem}_deposit_deviation.vtp", dv, dt, point_arrays={"deviation_mm": ddev})))
    outputs += [str(p) for p in write_fields(out, stem, deposit, cad, porosity)]
    buffer = io.StringIO()
    writer = csv.DictWriter(buffer, fieldnames=["layer", "z_mm", "void_mm3", "overbuild_mm3"], lineterminator="\n")
    writer.writeheader()
    writer.writerows(summary["layers"])
    outputs.append(str(write_text(out / f"{stem}_layers.csv", buffer.getvalue())))
    return outputs


__all__ = ["compare", "load_cad", "CompareRequest", "Comparison", "LABEL_NAMES"]
