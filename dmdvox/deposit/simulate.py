"""`dmdvox simulate`: deposit a program's beads, analyse them, write the grid and its surface."""

from __future__ import annotations

import csv
import io
import json
import sys
import time
from dataclasses import dataclass, replace
from pathlib import Path

import numpy as np

from .. import __version__, progress
from ..errors import DmdvoxError, ParameterError, ResourceError
from ..grid.analysis import Porosity
from ..grid.sparse import BLOCK, SparseGrid
from ..process.beads import Beads
from ..process.plan import LaidBeads, ProcessPlan, ProcessSettings, plan_process
from ..process.planner import MotionSettings
from ..process.profiles import BeadProfile
from ..toolpath.model import Toolpath
from .cache import DepositCache
from .engine import Domain, deposit_beads
from ..summary import SummaryResult


def fixed_plan(tp: Toolpath, bead: BeadProfile) -> ProcessPlan:
    """The fixed bead ``bead`` along ``tp`` at its constant-feed timing (callers that build their
    own toolpaths and beads: tests, studies)."""
    settings = ProcessSettings(profile=bead.name, width=bead.width, height=bead.height, exponent=bead.exponent,
                               model="fixed", motion=MotionSettings(accel_mm_s2=0.0))
    return plan_process(tp, settings)


def _progress_callback():
    if not progress.bars():
        return None, None
    from tqdm import tqdm

    bar = tqdm(total=0, unit="chunk", desc="deposit", file=sys.stderr, leave=False)

    def update(done, total):
        bar.total = total
        bar.n = done
        bar.refresh()

    return update, bar


@dataclass(frozen=True)
class SimulateRequest:
    """What to simulate: the plan's beads swept at ``voxel`` (default: the plan's), the part as
    it stands at ``until`` (s; default: finished), outputs to ``out_dir`` (.vdb, surfaces, the
    row table and the JSON), within ``max_memory`` bytes (default: a share of what is free),
    the slabs on the dask cluster at ``scheduler`` (default: here); the deposit and its voids
    taken from and kept in the deposit cache (:mod:`.cache`) unless ``cache`` is False."""

    plan: ProcessPlan
    voxel: float | None = None
    until: float | None = None
    out_dir: str | Path | None = None
    max_memory: int | None = None
    scheduler: str | None = None
    cache: bool = True


@dataclass(frozen=True, eq=False)
class Simulation(SummaryResult):
    """A simulation's result: ``summary`` (the JSON ``--json`` prints, also readable as
    ``result[key]``), the deposit ``grid``, its ``porosity``, the ``beads`` swept and the
    beads as ``laid`` (landing included), and ``surface_mesh`` (vertices, triangles, arrival)
    when outputs were written; :meth:`surface` and :meth:`image` give PyVista objects."""

    summary: dict
    grid: SparseGrid
    porosity: Porosity
    beads: Beads
    laid: LaidBeads
    surface_mesh: tuple | None

    def surface(self):
        """The deposit's surface as ``pyvista.PolyData`` with ``arrival_s`` per vertex (the one
        written with the outputs, else meshed now)."""
        from ..grid.surface import surface_arrival, surface_mesh
        from ..io.pyvista import polydata

        if self.surface_mesh is not None:
            vertices, triangles, arrival = self.surface_mesh
        else:
            vertices, triangles = surface_mesh(self.grid)
            arrival = surface_arrival(self.grid, vertices)
        return polydata(vertices, triangles, {"arrival_s": arrival})

    def image(self, lo=None, hi=None):
        """The grid over the world box ``lo``..``hi`` (mm; default: the whole block table) as
        ``pyvista.ImageData`` with ``sdf_mm`` and ``arrival_s`` (inf: never deposited)."""
        return grid_image(self.grid, lo, hi)


def grid_image(grid: SparseGrid, lo=None, hi=None):
    """``grid`` over the world box ``lo``..``hi`` as ``pyvista.ImageData`` (whole blocks), with
    ``sdf_mm`` and ``arrival_s``; refused when the dense box would not fit in memory."""
    from ..io.pyvista import image_data
    from ..memory import budget, budget_phrase

    shape = np.array(grid.block.shape)
    lo_block = np.zeros(3, np.int64) if lo is None else np.clip(np.floor(
        grid.world_to_index(np.asarray(lo, np.float64).reshape(1, 3))[0] / BLOCK).astype(np.int64), 0, shape)
    hi_block = shape if hi is None else np.clip(np.ceil(
        (grid.world_to_index(np.asarray(hi, np.float64).reshape(1, 3))[0] + 1) / BLOCK).astype(np.int64), 0, shape)
    if np.any(hi_block <= lo_block):
        raise DmdvoxError(f"the box {lo}..{hi} holds no block of the grid")
    voxels = int(np.prod((hi_block - lo_block) * BLOCK))
    need = 16 * voxels  # two float32 arrays here and their copies in the VTK image
    if need > budget(None):
        raise ResourceError(f"the image of {lo}..{hi} holds {voxels:,} voxels ({need / 2**30:.3g} GiB) but "
                            f"{budget_phrase(None)}; give a smaller box (lo, hi in mm)")
    return image_data(grid.index_to_world(BLOCK * lo_block.reshape(1, 3))[0], grid.voxel,
                      {"sdf_mm": grid.dense_sdf(lo_block, hi_block), "arrival_s": grid.dense_arrival(lo_block, hi_block)})


def _sweep(beads: Beads, voxel: float, request: SimulateRequest, also_holds, outputs: bool) -> tuple[SparseGrid, dict]:
    progress_update, bar = _progress_callback()
    steps = ("porosity", "outputs") if outputs else ("porosity",)
    try:
        return deposit_beads(beads, voxel, max_memory=request.max_memory, progress=progress_update,
                             scheduler=request.scheduler, also_holds=also_holds, steps=steps)
    finally:
        if bar is not None:
            bar.close()


def simulate(request: SimulateRequest, *, extra_bounds=None, also_holds: dict[str, int] | None = None,
             outputs_after: bool = False) -> Simulation:
    """Lay the plan's beads, sweep them, analyse the deposit, and write the outputs when asked.
    ``extra_bounds`` widens the grid's block table (another grid on the same lattice: a CAD
    part); ``also_holds`` (name -> bytes) is what the caller holds beside the deposit, for the
    memory check; ``outputs_after``: the caller writes the outputs later (:func:`with_outputs`),
    so the memory check holds their work as with ``out_dir``."""
    from ..grid.analysis import deposit_bbox, porosity

    plan, until, out_dir, max_memory = request.plan, request.until, request.out_dir, request.max_memory
    tp = plan.toolpath
    voxel = plan.resolve_voxel(request.voxel)
    if until is not None and not np.isfinite(until):
        raise ParameterError(f"{{until}} must be a finite time in seconds, got {until}", "until")
    cache = DepositCache.from_environment() if request.cache else None
    # keyed on the plan before any bead is laid: a hit skips laying and landing too
    key = cache.plan_key(plan, voxel, until) if cache is not None else None
    timings = {}
    t = time.perf_counter()
    outputs_later = out_dir is not None or outputs_after
    steps = ("outputs",) if outputs_later else ()
    kept = cache.load(key, voxel, max_memory, also_holds, steps) if cache is not None else None
    if kept is not None and kept[3] is None:
        kept = None
    if kept is not None:
        grid, result_pores, memory_estimate, laid = kept
        beads = laid.beads
        timings["cache_load_s"] = time.perf_counter() - t
        progress.stage("deposit", f"laid, swept and searched before: {cache.path(key)}")
    else:
        t = time.perf_counter()
        laid = plan.lay(voxel, until=until, max_memory=max_memory)
        beads = laid.beads
        timings["beads_s"] = time.perf_counter() - t
        # the substrate closes voids from below; channels narrower than a quarter bead do not open them
        plate = laid.landing.plate_z if laid.landing is not None else plan.settings.landing.plate_z
        grid, sweep_timings = _sweep(beads, voxel, request, also_holds, outputs_later)
        timings.update(sweep_timings)
        memory_estimate = sweep_timings["memory_estimate_bytes"]
        t = time.perf_counter()
        progress.step("deposit", f"swept ({grid.active_voxels:,d} active voxels); searching the enclosed voids")
        result_pores = porosity(grid, plate_z=plate, bead_width=plan.profile.width, scheduler=request.scheduler)
        timings["porosity_s"] = time.perf_counter() - t
        if cache is not None:
            cache.store(key, grid, result_pores, laid)
    if extra_bounds is not None:
        grid, result_pores = widened(grid, result_pores, extra_bounds)
    outputs: list[str] = []
    surface = None
    bead = plan.profile
    stem = Path(tp.source).stem or "deposit"
    if out_dir is not None:
        outputs, surface, written = _write_files(plan, laid, grid, voxel, Path(out_dir))
        timings.update(written)
    pores = [{
        "volume_mm3": p.volume_mm3,
        "centroid_mm": [float(v) for v in p.centroid_mm],
        "bbox_mm": np.asarray(p.bbox_mm, float).tolist(),
        "equivalent_diameter_mm": p.equivalent_diameter_mm,
        "wide": p.wide,
    } for p in result_pores.pores]
    grid_volume = result_pores.deposit_volume_mm3
    delivered = laid.delivered_mm3 if plan.flow.from_material and plan.model != "fixed" else None
    summary = {
        "voxel_mm": voxel,
        "model": plan.model,
        "flow_source": plan.flow.source,
        "bead": {"profile": bead.name, "width_mm": bead.width, "height_mm": bead.height},
        "deposit_volume_mm3": grid_volume,
        "deposited_volume_mm3": delivered,
        "lost_volume_mm3": None if delivered is None else laid.lost_mm3,
        # against all the material delivered: what never reached the part shows here, and beside it
        "mass_balance_percent": None if not delivered else 100.0 * (grid_volume - delivered) / delivered,
        "lost_percent": None if not delivered else 100.0 * laid.lost_mm3 / delivered,
        "duration_s": tp.duration,
        "motion": plan.motion.to_json(),
        "active_voxels": int(grid.active_voxels),
        "memory_bytes": int(grid.memory_bytes),
        "memory_estimate_bytes": int(memory_estimate),
        "pore_count": len(pores),
        "pores": pores,
        "porosity_percent": result_pores.porosity_percent,
        "pore_volume_mm3": result_pores.pore_volume_mm3,
        "speck_count": result_pores.speck_count,
        "speck_volume_mm3": result_pores.speck_volume_mm3,
        "speck_floor_mm3": result_pores.speck_floor_mm3,
        "channel_mm": result_pores.channel_mm,
        "plate_z_mm": result_pores.plate_z if np.isfinite(result_pores.plate_z) else None,
        "bbox_mm": deposit_bbox(grid).tolist(),
        "warnings": list(plan.warnings),
        "outputs": outputs,
        "timings_s": {k: round(float(v), 4) for k, v in timings.items() if k.endswith("_s")},
    }
    if laid.landing is not None:
        growth = growth_summary(plan, laid)
        summary.update(growth)
        summary["warnings"] += growth_warnings(plan, growth, laid, delivered)
    if out_dir is not None:
        _write_summary(summary, Path(out_dir) / f"{stem}_simulate.json")
    return Simulation(summary, grid, result_pores, beads, laid, surface)


def _write_files(plan: ProcessPlan, laid, grid: SparseGrid, voxel: float, out: Path) -> tuple[list[str], tuple, dict]:
    """The deposit's files in ``out`` (VDB, surface as .vtp/.stl/.ply, the rows' CSV): their
    paths, the surface (vertices, triangles, arrival) and the time each took."""
    from ..grid.surface import surface_arrival, surface_mesh
    from ..grid.vdbio import write_vdb
    from ..io.atomic import write_text
    from ..io.mesh import write_ply, write_stl, write_vtp

    tp, bead = plan.toolpath, plan.profile
    stem = Path(tp.source).stem or "deposit"
    outputs = []
    timings = {}
    t = time.perf_counter()
    meta = {"profile": bead.name, "width_mm": bead.width, "height_mm": bead.height, "voxel_mm": voxel,
            "model": plan.model, "source": str(tp.source), "dmdvox_version": __version__}
    progress.step("deposit", f"writing {out / f'{stem}.vdb'}")
    outputs.append(str(write_vdb(grid, out / f"{stem}.vdb", meta)))
    timings["vdb_s"] = time.perf_counter() - t
    t = time.perf_counter()
    progress.step("deposit", "meshing the surface")
    vertices, triangles = surface_mesh(grid)
    arrival = surface_arrival(grid, vertices)
    progress.step("deposit", f"writing the surface ({len(triangles):,d} triangles) as .vtp, .stl and .ply")
    outputs.append(str(write_vtp(out / f"{stem}_surface.vtp", vertices, triangles,
                                 point_arrays={"arrival_s": np.where(np.isfinite(arrival), arrival, -1.0)})))
    outputs.append(str(write_stl(out / f"{stem}_surface.stl", vertices, triangles)))
    outputs.append(str(write_ply(out / f"{stem}_surface.ply", vertices, triangles)))
    outputs.append(str(write_text(out / f"{stem}_rows.csv", row_table_csv(plan, laid))))
    timings["surface_s"] = time.perf_counter() - t
    return outputs, (vertices, triangles, arrival), timings


def _write_summary(summary: dict, path: Path) -> None:
    from ..io.atomic import write_text

    summary["outputs"].append(str(path))
    write_text(path, json.dumps(summary, indent=2))


def with_outputs(simulation: Simulation, plan: ProcessPlan, out_dir: str | Path) -> Simulation:
    """``simulation`` (of ``plan``, swept without outputs) with the files ``simulate --out``
    writes written into ``out_dir``: the same files, the summary's ``outputs`` and the surface."""
    out = Path(out_dir)
    summary = json.loads(json.dumps(simulation.summary))
    outputs, surface, timings = _write_files(plan, simulation.laid, simulation.grid, summary["voxel_mm"], out)
    summary["outputs"] = list(summary["outputs"]) + outputs
    summary["timings_s"].update({k: round(float(v), 4) for k, v in timings.items()})
    _write_summary(summary, out / f"{Path(plan.toolpath.source).stem or 'deposit'}_simulate.json")
    return replace(simulation, summary=summary, surface_mesh=surface)


def widened(grid: SparseGrid, pores: Porosity, bounds) -> tuple[SparseGrid, Porosity]:
    """The deposit ``grid`` and its ``pores`` on a block table widened to hold ``bounds`` (lo, hi
    in mm: another grid on the same lattice, a CAD part); the deposit's own blocks keep their
    place in the widened table (Domain.widened)."""
    domain = Domain(grid.voxel, grid.origin, grid.block_shape, grid.band).widened(bounds)
    return (grid.widened(domain.origin, domain.block_shape),
            replace(pores, voids=pores.voids.widened(domain.origin)))


def growth_summary(plan: ProcessPlan, laid) -> dict:
    """The flow model's layers, standoff and lost material (see :func:`landing.growth_report`)."""
    from ..process.landing import growth_report

    programmed = laid.programmed
    tp = plan.toolpath
    return growth_report(programmed, laid.landing, tp.layer[programmed.row], tp.line[programmed.row], laid.lost())


LOST_WARNING_PERCENT = 1.0  # a loss above this share of the delivered material is a warning
MAX_LINES_NAMED = 10


def loss_reasons(plan: ProcessPlan, laid) -> list[tuple[str, float, list[int]]]:
    """(why, volume, lines) of the material that never reached the part, by the landing's reason
    (``Landing.reason``: fell off the part, beyond the bridge span)."""
    from ..process.landing import LOST_REASONS

    lost = laid.lost()
    line = plan.toolpath.line[laid.programmed.row]
    reason, volume = laid.landing.reason, laid.landing.lost_volume
    groups = [(LOST_REASONS.get(int(code), f"reason {int(code)}"), lost & (reason == code))
              for code in np.unique(reason[lost])]
    return [(why, float(volume[sel].sum()), [int(v) for v in np.unique(line[sel])]) for why, sel in groups if sel.any()]


def growth_warnings(plan: ProcessPlan, growth: dict, laid, delivered: float | None) -> list[str]:
    source = plan.toolpath.source
    out = []
    lost = growth["lost_volume_mm3"]
    if lost > 0 and delivered and 100.0 * lost / delivered > LOST_WARNING_PERCENT:
        for why, volume, lines in loss_reasons(plan, laid):
            named = ", ".join(map(str, lines[:MAX_LINES_NAMED])) + (", ..." if len(lines) > MAX_LINES_NAMED else "")
            out.append(f"{source}: {volume:.3g} mm^3 ({100.0 * volume / delivered:.2f} % of the {delivered:.4g} mm^3 "
                       f"delivered) never reached the part: {why}, on {len(lines)} lines: {named}")
    standoff = growth["standoff_mm"]
    if standoff is not None and standoff["min"] <= 0:
        crash = next((layer for layer in growth["layers"] if layer["standoff_mm"] <= 0), None)
        where = f" at layer {crash['layer']}" if crash else ""
        out.append(f"{source}: the part grows into the nozzle{where} (standoff {standoff['min']:.3g} mm): the programmed "
                   "layer step is smaller than what the beads build")
    if growth["standoff_trend"] == "runaway":
        out.append(f"{source}: runaway growth: the standoff moves further from its start every layer "
                   f"(final {standoff['final']:.3g} mm)")
    if growth["not_landed"]:
        out.append(f"{source}: {growth['not_landed']} bead elements are tilted off vertical: the flow model's height "
                   "field cannot land them; they are drawn where programmed")
    return out


# the flow model's keys (landing.growth_report)
GROWTH_KEYS = ("layers", "standoff_mm", "standoff_trend", "lost_lines", "lost_line_count", "not_landed")


def format_simulate(plan: ProcessPlan, result: dict) -> str:
    """The text ``dmdvox simulate`` prints without ``--json``."""
    bead = result["bead"]
    lines = [f"{plan.toolpath.source}: {result['model']} model, {bead['profile']} bead {bead['width_mm']:g} mm wide"
             + (f" x {bead['height_mm']:.3g} mm" if result["model"] == "fixed" else "")
             + f", voxel {result['voxel_mm']:g} mm"]
    lines.append(f"  deposit volume   {result['deposit_volume_mm3']:,.2f} mm^3")
    if result["deposited_volume_mm3"] is not None:
        lines.append(f"  material         {result['deposited_volume_mm3']:,.2f} mm^3 delivered ({result['flow_source']}), "
                     f"{result['lost_volume_mm3']:,.2f} lost ({result['lost_percent']:.2f} %); mass balance "
                     f"{result['mass_balance_percent']:+.2f} % of the delivered")
    lines.append(f"  duration         {result['duration_s']:,.1f} s (accel {result['motion']['accel_mm_s2']:g} mm/s^2)")
    if result.get("layers"):
        last = result["layers"][-1]
        standoff = result["standoff_mm"]
        lines.append(f"  layers           {len(result['layers'])}, last built top {last['built_top_mm']['mean']:.3f} mm "
                     f"(programmed {last['programmed_z_mm']:.3f} mm bottom), drift {last['drift_mm']:+.3f} mm")
        if standoff:
            lines.append(f"  standoff         {standoff['min']:.3f}..{standoff['max']:.3f} mm, final "
                         f"{standoff['final']:.3f} mm ({result['standoff_trend']})")
    lines.append(f"  active voxels    {result['active_voxels']:,d} ({result['memory_bytes'] / 2**20:,.1f} MiB)")
    lines.append(f"  pores            {result['pore_count']}  (porosity {result['porosity_percent']:.3f} %)")
    for pore in result["pores"][:10]:
        c = pore["centroid_mm"]
        lines.append(f"    {pore['volume_mm3']:.4f} mm^3 at ({c[0]:.2f}, {c[1]:.2f}, {c[2]:.2f}), "
                     f"d_eq {pore['equivalent_diameter_mm']:.3f} mm")
    lines += [f"  wrote {path}" for path in result["outputs"]]
    return "\n".join(lines)


def describe(plan: ProcessPlan) -> str:
    """One line on what a run lays: moves, model, material, bead."""
    bead = plan.profile
    tp = plan.toolpath
    text = f"{int(tp.deposit.sum()):,d} deposit moves, {plan.model} model"
    if plan.flow.from_material and plan.model != "fixed":
        return text + f", material from {plan.flow.source} ({plan.flow.deposited_volume_mm3:,.1f} mm^3), {bead.name} " \
                      f"bead {bead.width:g} mm wide, {bead.height:.3g} mm high (median)"
    return text + f", {bead.name} bead {bead.width:g} x {bead.height:g} mm"


ROW_COLUMNS = ("line", "row", "feature", "speed_start_mm_s", "speed_mid_mm_s", "speed_end_mm_s", "area_mm2",
               "width_mm", "height_mm", "volume_mm3", "bottom_mm", "top_mm", "standoff_start_mm",
               "standoff_end_mm", "lost")


def row_table(plan: ProcessPlan, laid) -> dict[str, np.ndarray]:
    """One entry per deposit row (``ROW_COLUMNS``): its source line, planned speeds at its start,
    middle and end, mean cross-section (area, width, height of its pieces weighted by length),
    material, where its beads stand (bottom and top: landed under the flow model, as programmed
    otherwise), the standoff its first and last piece met (flow model; NaN otherwise) and whether
    its material was lost."""
    from ..process.beads import CAP, SEGMENT

    tp = plan.toolpath
    rows = np.flatnonzero(tp.deposit)
    length = tp.length[rows]
    beads = laid.programmed
    landing = laid.landing
    pieces = np.flatnonzero(beads.kind != CAP)
    at = np.searchsorted(rows, beads.row[pieces])
    piece_len = np.where(beads.kind[pieces] == SEGMENT, np.linalg.norm(beads.p1[pieces] - beads.p0[pieces], axis=1),
                         np.abs(beads.p1[pieces, 0] * beads.p1[pieces, 2]))
    weight = np.bincount(at, piece_len, rows.size)
    safe = np.where(weight > 0, weight, 1.0)

    def mean(values):
        return np.bincount(at, piece_len * values, rows.size) / safe

    dz = landing.dz[pieces] if landing is not None else np.zeros(pieces.size)
    bottom = mean(beads.p0[pieces, 2] + dz)
    height = mean(beads.height[pieces])
    standoff_start = np.full(rows.size, np.nan)
    standoff_end = np.full(rows.size, np.nan)
    lost = np.zeros(rows.size, bool)
    if landing is not None:
        # pieces come in time order: a row's first and last piece
        standoff_end[at] = landing.standoff[pieces]
        standoff_start[at[::-1]] = landing.standoff[pieces][::-1]
        np.logical_or.at(lost, at, landing.lost[pieces])
    volume = plan.flow.volume[rows]
    area = np.divide(volume, length, out=np.zeros(rows.size), where=length > 0)
    if not plan.flow.from_material or plan.model == "fixed":
        area = mean(beads.width[pieces]) * height * plan.profile.area / (plan.profile.width * plan.profile.height)
    names = tp.meta.get("features", [])
    motion = plan.motion
    return {
        "line": tp.line[rows].astype(np.int64), "row": rows,
        "feature": np.array([names[f] if f < len(names) else "" for f in tp.feature[rows]], dtype=object),
        "speed_start_mm_s": motion.speed_at(rows, 0.0), "speed_mid_mm_s": motion.speed_at(rows, 0.5 * length),
        "speed_end_mm_s": motion.speed_at(rows, length), "area_mm2": area, "width_mm": mean(beads.width[pieces]),
        "height_mm": height, "volume_mm3": volume, "bottom_mm": bottom, "top_mm": bottom + height,
        "standoff_start_mm": standoff_start, "standoff_end_mm": standoff_end, "lost": lost,
    }


def row_table_csv(plan: ProcessPlan, laid) -> str:
    """:func:`row_table` as CSV (NaN where a column does not apply)."""
    table = row_table(plan, laid)
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    writer.writerow(ROW_COLUMNS)
    for k in range(table["row"].shape[0]):
        writer.writerow([v if isinstance(v, str) else int(v) if isinstance(v, (np.integer, np.bool_)) else f"{v:.6g}"
                         for v in (table[c][k] for c in ROW_COLUMNS)])
    return buffer.getvalue()
