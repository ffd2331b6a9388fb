"""`dmdvox report`: every analysis that applies, in one self-contained HTML page.

The toolpath summary always; the deposit (volume, pores, pictures); when the beads come from
the material, the planned speed and bead cross-section along the path, a bead height map and the
rows with the most excess material; under the flow model, the programmed against the built
layers, the standoff along the path and a drift map; the comparison with the CAD part when
``--cad`` is given; the nozzle's collisions and clearance when ``--nozzle`` is.
One deposit serves them all. Pictures and plots are written as PNG beside the page and embedded
in it (plots as SVG), so the page can be mailed alone and the PNGs used in slides.
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from pathlib import Path

import numpy as np

from ..collision.run import NozzleSettings
from ..errors import DmdvoxError
from ..process.plan import ProcessPlan
from ..summary import SummaryResult

PICTURE_SIZE = (1200, 900)


@dataclass(frozen=True)
class ReportInputs:
    """What the page says it was made from (the "Inputs" table)."""

    gcode: str
    dialect: str
    cad: str | None
    cad_offset: tuple
    nozzle: str | None
    standoff: float | None
    fixtures: tuple
    plate: float | None
    profile: str
    width: float
    height: float
    voxel: float
    model: str = "fixed"
    material: str = ""  # the material source in words, "" when the bead is fixed
    motion: str = ""
    landing: str = ""  # the flow model's landing settings in words, "" for the other models


@dataclass(frozen=True)
class ReportRequest:
    """One page for the plan: its deposit swept at ``voxel`` (default: the plan's), compared
    with the CAD STL ``cad`` moved by ``cad_offset`` when given, the nozzle checked
    (:class:`~dmdvox.collision.run.NozzleSettings`) when given; everything written to
    ``out_dir``; within ``max_memory`` bytes; the slabs on the dask cluster at ``scheduler``."""

    plan: ProcessPlan
    out_dir: str | Path
    cad: str | None = None
    cad_offset: tuple[float, float, float] = (0.0, 0.0, 0.0)
    nozzle: NozzleSettings | None = None
    voxel: float | None = None
    max_memory: int | None = None
    scheduler: str | None = None
    thermal: dict | None = None  # the heat options (dmdvox.thermal.run.OPTION_KEYS): the Heat section


@dataclass(frozen=True)
class Report(SummaryResult):
    """The page written and its summary (the JSON ``--json`` prints)."""

    summary: dict

    @property
    def page(self) -> Path:
        return Path(self.summary["report_html"])


def report(request: ReportRequest, extra_fields=(), *, simulation=None, comparison=None) -> Report:
    """Write the page (module docstring).

    ``simulation`` (without a CAD part) or ``comparison`` (with one) is the request's deposit or
    comparison computed before with its files in the page's ``simulate`` (and ``compare``)
    folder (a :class:`dmdvox.Build`'s), used in place of running it again.

    ``extra_fields`` adds colourings to the 3-D view: ``(ScalarField, values)`` items, the
    values one per toolpath row or a callable giving one per surface vertex (see
    :func:`dmdvox.reporting.scene3d.standard_fields`); the view's menu and legend follow from the
    field's name, words and unit, with no change to the page's script."""
    from .. import checks

    with checks.collect_warnings():  # the page lists the run's warnings, the caller's run or this one
        return _report(request, extra_fields, simulation, comparison)


def _report(request: ReportRequest, extra_fields, simulation, comparison) -> Report:
    from .. import checks, progress
    from ..collision.bodies import load_fixtures, nozzle_mesh
    from ..collision.run import collide_part, prepare_collide
    from ..comparison.compare import CompareRequest, compare
    from ..deposit.simulate import SimulateRequest, describe, row_table, simulate
    from ..grid.surface import surface_arrival
    from ..toolpath.summary import summarize
    from ..view.pictures import cad_deviation_picture, decimate, render_surface
    from . import figures
    from .page import write_page
    from .scene3d import (ARRIVAL, BEAD_HEIGHT, DEVIATION, DRIFT, LAYER, MAX_SURFACE_TRIANGLES, SceneMesh,
                          field_range, layer_table, scene_payload, standard_fields)

    plan, nozzle_settings, max_memory = request.plan, request.nozzle, request.max_memory
    out = Path(request.out_dir)
    tp, bead = plan.toolpath, plan.profile
    if not tp.deposit.any():
        raise DmdvoxError(f"{tp.source}: the program deposits nothing (no deposit moves under dialect "
                          f"'{tp.dialect}'); check --dialect or --laser-on")
    voxel = plan.resolve_voxel(request.voxel)
    fixtures = load_fixtures(list(nozzle_settings.fixtures)) if nozzle_settings is not None else []
    standoff = clearance = None
    bodies: dict[str, int] = {}
    if nozzle_settings is not None:
        standoff, clearance = nozzle_settings.standoff, nozzle_settings.clearance
        bodies = prepare_collide(tp, nozzle_settings.nozzle, fixtures, voxel, clearance, max_memory)
    stem = Path(tp.source).stem or "deposit"
    info = summarize(tp)
    outputs: list[str] = []
    sections: dict = {"info": info}

    def log(text: str) -> None:
        progress.stage("report", text)

    cad_mesh = None
    if request.cad:
        log("depositing and comparing with the CAD part")
        if comparison is None:
            comparison = compare(CompareRequest(plan, request.cad, cad_offset=request.cad_offset, voxel=voxel,
                                                out_dir=out / "compare", simulate_out_dir=out / "simulate",
                                                max_memory=max_memory, scheduler=request.scheduler),
                                 pictures=cad_deviation_picture, also_holds=bodies)
        grid = comparison.deposit
        vertices, triangles, deviation = comparison.deposit_surface
        # the comparison's deposit surface is the one simulate wrote (simulate_out_dir), with its arrival
        sim_surface = comparison.simulation.surface_mesh
        arrival = sim_surface[2] if sim_surface is not None and sim_surface[0] is vertices else \
            surface_arrival(grid, vertices)
        cad_mesh = comparison.cad_mesh
        outputs += comparison["outputs"]
        sections["compare"] = {k: v for k, v in comparison.summary.items() if k not in ("outputs", "timings_s")}
        sections["simulate"] = _simulate_part(comparison.simulation.summary)
        simulate_warnings = comparison.simulation["warnings"]
        laid = comparison.simulation.laid
        voids = comparison.simulation.porosity.voids
    else:
        log("depositing")
        if simulation is None:
            progress.stage("deposit", describe(plan))
            simulation = simulate(SimulateRequest(plan, voxel=voxel, out_dir=out / "simulate", max_memory=max_memory,
                                                  scheduler=request.scheduler), also_holds=bodies)
        grid = simulation.grid
        outputs += simulation["outputs"]
        sections["simulate"] = _simulate_part(simulation.summary)
        simulate_warnings = simulation["warnings"]
        laid = simulation.laid
        voids = simulation.porosity.voids
        vertices, triangles, arrival = simulation.surface_mesh
        deviation = None
    heat_summary = None
    heat_fields = []
    if request.thermal is not None:
        from ..thermal.outputs import at_points, cell_fields, heat_deposit
        from .scene3d import COOLING_RATE, PEAK_TEMPERATURE

        log("heat on the deposit")
        swept = comparison.simulation if request.cad else simulation
        heat, heat_summary = heat_deposit(plan, grid, swept["plate_z_mm"], request.thermal, out / "thermal",
                                          max_memory)
        outputs += heat_summary["outputs"]
        cells = cell_fields(heat)
        heat_fields = [(PEAK_TEMPERATURE, lambda v, a: at_points(heat, cells["peak_temperature_C"], v)),
                       (COOLING_RATE, lambda v, a: at_points(heat, cells["cooling_rate_C_s"], v))]
    # lost material, a part growing into the nozzle, runaway growth: said on stderr and in --json too
    for warning in simulate_warnings:
        checks.warn(warning)
    arrival = np.where(np.isfinite(arrival), arrival, tp.duration)
    material = plan.flow.from_material and plan.model != "fixed"
    growth = laid.landing is not None and bool(sections["simulate"].get("layers"))
    rows = row_table(plan, laid) if material else None
    # the colourings are computed on the full surface: decimation keeps each vertex's nearest value
    # the material's own cross-section, in place of the width x height of the comments, and how
    # high it stands and where it landed: bead piece by bead piece, since a row's changes along it
    own_fields = piece_fields(laid, growth) if material else []
    if material:
        sections["material"] = {"largest_excess": largest_excess(plan, rows), "flow": plan.flow_json(),
                                "basis": "programmed speed" if plan.flow.rate_mm3_s is not None else "median area"}
    if growth:
        sections["growth"] = {"first_contact": first_contact(plan, laid), "standoff_mm": standoff_range(laid)}
    fields = standard_fields(tp, bead, vertices, arrival, [*own_fields, *heat_fields, *extra_fields])
    if deviation is not None:
        fields.insert(1, (DEVIATION, np.asarray(deviation, np.float64)))
    # One decimated surface serves the pictures and the 3-D view: at picture resolution it looks
    # the same as the full one and renders in a fraction of the time.
    scalars = {spec.name: values for spec, values in fields}
    pores = sections["simulate"]["pores"]
    # the pores' walls from the full surface: decimation would thin a small pore's wall away
    pore_mesh = figures.pore_geometry(voids, (vertices, triangles), pores) if pores else None
    vertices, triangles, scalars = decimate(vertices, triangles, scalars, MAX_SURFACE_TRIANGLES)
    surface = (vertices, triangles)
    sections["layers"] = layer_table(tp, bead.height)

    log("pictures")
    # name -> PNG; the page captions each with the title it was drawn with
    pictures: dict[str, str] = {}
    context = [(cad_mesh[0], cad_mesh[1], "lightgray", 0.25)] if cad_mesh is not None else []
    for view in ("iso", "top"):
        pictures[view] = str(render_surface(
            out / f"{stem}_{view}.png", vertices, triangles, scalars=scalars["arrival_s"], scalar_name="arrival_s",
            clim=(0.0, max(tp.duration, 1e-9)), cmap="viridis", view=view, size=PICTURE_SIZE,
            title=f"{Path(tp.source).name}: deposit coloured by deposition time, {view} view", context_meshes=context))
    if request.cad:
        pictures["deviation"] = next(p for p in outputs if p.endswith("_cad_deviation.png"))
    maps = [("bead_height", BEAD_HEIGHT, "bead height from the material")] if material else []
    if growth:
        maps.append(("drift", DRIFT, "drift from the program (+ = part below the program)"))
    for name, spec, what in maps:
        # an extra field of the same name takes our colouring's place: its values are not ours to title
        if any(known is spec for known, _ in fields):
            values = scalars[spec.name]
            lo, hi = field_range(spec, values)
            if not hi > lo:  # one value everywhere: a range around it, so the bar still reads it
                lo, hi = lo - max(abs(lo), 1.0) * 1e-3, hi + max(abs(hi), 1.0) * 1e-3
            pictures[name] = str(render_surface(
                out / f"{stem}_{name}.png", vertices, triangles, scalars=values, scalar_name=spec.name,
                clim=(lo, hi), cmap=spec.colormap, view="iso", size=PICTURE_SIZE, bar_title=spec.title,
                title=f"{Path(tp.source).name}: deposit coloured by {what}, iso view", context_meshes=context))
    if pores:
        pictures["pores"] = figures.pore_picture(pore_mesh, surface, len(pores), out / f"{stem}_pores.png",
                                                 PICTURE_SIZE)

    # name -> (PNG, SVG, caption)
    plots: dict[str, tuple[str, str, str]] = {}
    if request.cad and sections["compare"]["layers"]:
        plots["layers"] = figures.layer_plot(sections["compare"]["layers"], out / f"{stem}_layers.png")
    if pores:
        plots["pores"] = figures.pore_plot(pores, out / f"{stem}_pore_sizes.png")
    if material:
        plots["speed_area"] = figures.speed_area_figure(*speed_area_series(plan, laid)).save(
            out / f"{stem}_speed_area.png")
    if growth:
        plots["growth_layers"] = figures.growth_layers_figure(sections["simulate"]["layers"]).save(
            out / f"{stem}_growth_layers.png")
        landing = plan.settings.landing
        plots["standoff"] = figures.standoff_figure(
            *standoff_series(laid), landing.standoff_mm,
            None if landing.catchment is None else landing.catchment.focus).save(out / f"{stem}_standoff.png")

    if heat_summary is not None:
        sections["heat"] = heat_section(plan, heat, heat_summary)
        liquidus = heat.material.liquidus
        plots["heat_layers"] = figures.heat_layers_figure(heat_summary["layers"], liquidus).save(
            out / f"{stem}_heat_layers.png")
        if heat.pools:
            plots["melt_pool"] = figures.melt_pool_figure(heat.pools).save(out / f"{stem}_melt_pool.png")
        part = np.flatnonzero(np.isfinite(heat.lattice.birth) & np.isfinite(heat.state.peak))
        plots["peak_map"] = figures.peak_map_figure(heat.lattice.ijk[part, :2].astype(np.int64),
                                                    heat.state.peak[part], heat.lattice.origin, heat.lattice.voxel,
                                                    liquidus).save(out / f"{stem}_peak_temperature.png")

    markers = np.zeros((0, 4))
    nozzle = None
    if nozzle_settings is not None:
        log("checking the nozzle along the path")
        check, _ = collide_part(tp, grid, nozzle_settings, fixtures, voxel)
        sections["collide"] = check.as_dict()
        nozzle = nozzle_mesh(nozzle_settings.nozzle)
        markers = np.array([[*c["position_mm"], c["time_s"]] for c in check.collisions], float).reshape(-1, 4)
        plots["clearance"] = figures.clearance_plot(check.pose_time_s, check.pose_clearance_mm, check.reach_mm,
                                                    clearance, check.collisions, out / f"{stem}_clearance.png")
        if check.collisions:
            log("the part at the first collision")
            at_collision = _surface_at(laid.beads, check.collisions[0]["time_s"], voxel, max_memory,
                                       MAX_SURFACE_TRIANGLES)
            pictures["collisions"] = figures.collision_picture(
                at_collision, [(f.vertices, f.triangles) for f in fixtures], nozzle, check.collisions, voxel,
                out / f"{stem}_collisions.png", PICTURE_SIZE)

    log("3-D view")
    meshes = [SceneMesh("deposit", vertices, triangles, (0.69, 0.77, 0.87), 1.0, scalars, timed=True, capped=True,
                        clipped=True)]
    if pore_mesh is not None:
        # inside the part (seen with the deposit switched off); each wall appears when the
        # material around it is laid
        wall_arrival = surface_arrival(grid, pore_mesh[0])
        meshes.append(SceneMesh("pores", pore_mesh[0], pore_mesh[1], (0.85, 0.1, 0.45), 1.0,
                                {"arrival_s": np.where(np.isfinite(wall_arrival), wall_arrival, tp.duration)},
                                timed=True, solid=True, clipped=True))
    if cad_mesh is not None:
        meshes.append(SceneMesh("CAD", cad_mesh[0], cad_mesh[1], (0.6, 0.6, 0.6), 0.25, clipped=True))
    meshes += [SceneMesh(f"fixture {f.name}", f.vertices, f.triangles, (0.87, 0.72, 0.53), 0.6) for f in fixtures]
    # colour limits from the full-resolution values, so they do not depend on the decimation
    specs = []
    for spec, values in fields:
        if spec is ARRIVAL:
            spec = replace(spec, range=(0.0, max(tp.duration, 1e-9)))
        elif spec is LAYER:
            spec = replace(spec, range=(0.0, float(max(len(tp.layer_z) - 1, 0))))
        elif spec is DEVIATION:
            finite = np.isfinite(values)
            # the 99th percentile: a few stray vertices far off must not wash out the map
            m = float(np.percentile(np.abs(values[finite]), 99)) if finite.any() else 0.0
            spec = replace(spec, range=(-(m or 1e-3), m or 1e-3))
        else:
            spec = replace(spec, range=field_range(spec, values))
        specs.append(spec)
    payload = scene_payload(meshes, tp, markers, standoff, nozzle, specs,
                            built_layers(sections["layers"], sections["simulate"].get("layers") if growth else None))

    # every warning the run's --json will list (the reader's, the plan's, each command's), each once
    sections["warnings"] = list(dict.fromkeys([*info["warnings"], *checks.collected()]))
    # the dialect the program was read with: under auto, the one detected
    inputs = ReportInputs(str(tp.source), tp.dialect, request.cad, tuple(request.cad_offset),
                          None if nozzle_settings is None else nozzle_settings.nozzle, standoff,
                          () if nozzle_settings is None else nozzle_settings.fixtures,
                          None if nozzle_settings is None else nozzle_settings.plate,
                          bead.name, bead.width, bead.height, voxel, *process_words(plan))
    outputs += sorted(set(pictures.values()) - set(outputs)) + [png for png, _, _ in plots.values()]
    page = write_page(out / f"{stem}_report.html", inputs, sections, pictures, plots, payload)
    summary = {
        "report_html": str(page),
        "info": info,
        "simulate": {k: v for k, v in sections["simulate"].items() if k != "pores"},
        "compare": {k: v for k, v in sections["compare"].items() if k not in ("layers", "pores")}
        if "compare" in sections else None,
        "collide": sections.get("collide"),
        "layers": sections["layers"],
        "material": sections.get("material"),
        "growth": sections.get("growth"),
        "thermal": heat_summary,
        "heat": sections.get("heat"),
        "outputs": outputs + [str(page)],
    }
    return Report(summary)


HOTTEST_LAYERS = 5


def heat_section(plan, heat, summary: dict) -> dict:
    """The page's Heat section: the run's totals, the per-layer table with the G-code lines each
    layer spans, the hottest layers (by interlayer temperature, else peak) and the longest time a
    cell of the part spent above the solidus."""
    tp = plan.toolpath
    rows = np.flatnonzero(tp.deposit & (tp.length > 0))
    layers = []
    for row in summary["layers"]:
        inside = rows[(tp.t_start[rows] >= row["start_s"]) & (tp.t_end[rows] <= row["end_s"])]
        lines = [row["first_line"], int(tp.line[inside].max())] if inside.size else None
        layers.append({**row, "lines": lines})
    key = "interlayer_C" if any(r["interlayer_C"] is not None for r in layers) else "peak_C"
    ranked = sorted((r for r in layers if r[key] is not None), key=lambda r: (-r[key], r["layer"]))
    part = np.isfinite(heat.lattice.birth) & (np.arange(len(heat.lattice)) < heat.state.n_born)
    above = heat.state.time_above[part]
    keep = ("thermal_voxel_mm", "time_step_s", "cells", "part_cells", "plate_cells", "steps", "duration_s",
            "absorptivity", "beam_energy_J", "absorbed_J", "stored_J", "lost_J", "boiled_J",
            "energy_balance_max_percent",
            "max_peak_temperature_C", "max_interlayer_temperature_C", "max_melt_pool_width_mm", "remelted_cells")
    return {**{k: summary[k] for k in keep}, "material": summary["material"]["name"],
            "liquidus_C": heat.material.liquidus, "solidus_C": heat.material.solidus,
            "max_time_above_solidus_s": float(above.max()) if above.size else 0.0,
            "layers": layers, "hottest_layers": ranked[:HOTTEST_LAYERS], "hottest_by": key}


def _surface_at(beads, time_s: float, voxel: float, max_memory: int | None, max_triangles: int):
    """(vertices, triangles) of the part as it stands at ``time_s`` (its beads up to then, swept
    again), decimated to ``max_triangles``; empty before the first bead."""
    from ..deposit.engine import deposit_beads
    from ..grid.surface import surface_mesh
    from ..view.pictures import decimate

    shown = beads.until(time_s)
    if len(shown) == 0:
        return np.zeros((0, 3)), np.zeros((0, 3), np.int64)
    vertices, triangles = surface_mesh(deposit_beads(shown, voxel, max_memory=max_memory)[0])
    return decimate(vertices, triangles, {}, max_triangles)[:2]


def _simulate_part(result: dict) -> dict:
    keep = ("voxel_mm", "deposit_volume_mm3", "active_voxels", "memory_bytes", "pore_count", "pores",
            "porosity_percent", "bbox_mm", "model", "flow_source", "deposited_volume_mm3", "lost_volume_mm3",
            "mass_balance_percent", "motion")
    # the flow model's growth (layers, standoff, lost lines) only where it ran
    growth = ("layers", "standoff_mm", "standoff_trend", "lost_lines", "lost_line_count", "not_landed")
    return {k: result.get(k) for k in keep} | {k: result[k] for k in growth if k in result}


MAX_EXCESS_ROWS = 10


def row_excess(plan, rows: dict) -> np.ndarray:
    """Per deposit row (``rows`` from ``row_table``): the material it carries beyond what it would
    hold at its programmed speed (mm^3).

    For a rate source (powder, wire) a row at its programmed speed F would hold ``Q L / F``; it
    delivers ``Q`` times its planned duration plus any beam-on dwell before it, so a slowdown
    (corner, stop, short move, arc limit) shows as excess. E words meter each row's material
    themselves: the excess is what lies above the program's median cross-section, ``(A - A_med) L``."""
    tp = plan.toolpath
    index = rows["row"]
    length = np.asarray(tp.length, np.float64)[index]
    delivered = rows["volume_mm3"] + plan.flow.dwell_volume[index]
    q = plan.flow.rate_mm3_s
    if q is not None:
        feed = np.asarray(tp.feed, np.float64)[index]
        held = np.divide(q * length, feed, out=np.full(index.size, np.nan), where=feed > 0)
    else:
        carrying = (length > 0) & (rows["volume_mm3"] > 0)
        held = (float(np.median(rows["area_mm2"][carrying])) if carrying.any() else 0.0) * length
    return delivered - held


def largest_excess(plan, rows: dict, count: int = MAX_EXCESS_ROWS) -> list[dict]:
    """The ``count`` deposit rows with the most :func:`row_excess`, largest first, with their
    G-code line and text (rows with none left out)."""
    from .scene3d import read_lines

    excess = row_excess(plan, rows)
    # below a millionth of the largest row's material an excess is rounding of the summed times
    floor = 1e-6 * max(float(np.max(rows["volume_mm3"], initial=0.0)), 1e-12)
    ranked = np.where(np.isfinite(excess) & (excess > floor), excess, -np.inf)
    order = np.argsort(-ranked, kind="stable")[:count]
    order = order[np.isfinite(ranked[order])]
    tp = plan.toolpath
    index = rows["row"][order]
    texts = read_lines(tp.source, np.unique(rows["line"][order]))
    return [{"line": int(rows["line"][k]), "text": texts.get(int(rows["line"][k]), ""),
             "excess_mm3": float(excess[k]), "volume_mm3": float(rows["volume_mm3"][k]),
             "length_mm": float(tp.length[r]), "feed_mm_s": float(tp.feed[r]),
             "speed_start_mm_s": float(rows["speed_start_mm_s"][k]), "speed_mid_mm_s": float(rows["speed_mid_mm_s"][k]),
             "speed_end_mm_s": float(rows["speed_end_mm_s"][k]), "area_mm2": float(rows["area_mm2"][k])}
            for k, r in zip(order, index)]


def _pieces(laid) -> np.ndarray:
    """The landed pieces (caps are joints) whose material reached the part, in time order."""
    from ..process.beads import CAP

    landing = laid.landing
    return np.flatnonzero((laid.programmed.kind != CAP) & landing.landed & ~landing.lost)


def piece_lengths(beads, pieces: np.ndarray) -> np.ndarray:
    """Length (mm) along the path of each of ``pieces`` (segments and arc beads)."""
    from ..process.beads import SEGMENT

    return np.where(beads.kind[pieces] == SEGMENT, np.linalg.norm(beads.p1[pieces] - beads.p0[pieces], axis=1),
                    np.abs(beads.p1[pieces, 0] * beads.p1[pieces, 2]))


def section_area(laid, pieces: np.ndarray) -> np.ndarray:
    """Cross-section area (mm²) of bead pieces, from their width and height and the profile's
    shape (``A = k w h``). Not volume over length: at joints and run ends a piece leaves part of
    its material to the cap there."""
    from ..process.profiles import ARC, profile_area

    beads = laid.programmed
    w, h = beads.width[pieces], beads.height[pieces]
    if beads.code == ARC:  # a circular segment: not proportional to w h
        a = 0.5 * w
        r = (a * a + h * h) / (2.0 * np.maximum(h, 1e-300))
        return r * r * np.arccos(np.clip((r - h) / r, -1.0, 1.0)) - (r - h) * a
    return profile_area(beads.code, 1.0, 1.0, beads.exponent) * w * h


def piece_fields(laid, growth: bool) -> list:
    """The 3-D view's colourings of beads from the material, per vertex from the bead piece that
    laid it (:func:`~dmdvox.reporting.scene3d.element_values_on_vertices`): cross-section area (the
    material a piece carries over its length), height and, under the flow model, drift
    (programmed top minus built top: the piece's landing offset, negated)."""
    from ..process.beads import CAP
    from .scene3d import BEAD_HEIGHT, DRIFT, MATERIAL_AREA, element_values_on_vertices

    beads = laid.programmed
    drawn = beads.kind != CAP
    if laid.landing is not None:
        drawn &= ~laid.landing.lost
    pieces = np.flatnonzero(drawn)
    length = piece_lengths(beads, pieces)
    # a zero-length piece lays nothing a vertex could take its value from
    pieces, length = pieces[length > 0], length[length > 0]
    t0, t1 = beads.t0[pieces], beads.t1[pieces]
    values = {MATERIAL_AREA: section_area(laid, pieces), BEAD_HEIGHT: beads.height[pieces]}
    if growth:
        values[DRIFT] = -laid.landing.dz[pieces]
    return [(spec, lambda vertices, arrival, v=v: element_values_on_vertices(t0, t1, v, arrival))
            for spec, v in values.items()]


def standoff_range(laid) -> dict | None:
    """{min, max, final} of the standoff the bead pieces met (mm). Caps are left out: a run's end
    cap is landed after the pieces it ends, so its standoff is measured to its own bead's top."""
    pieces = _pieces(laid)
    if pieces.size == 0:
        return None
    standoff = laid.landing.standoff[pieces]
    return {"min": float(standoff.min()), "max": float(standoff.max()), "final": float(standoff[-1])}


def first_contact(plan, laid) -> dict | None:
    """Where the part first reaches the nozzle (a bead piece meeting a standoff <= 0): line,
    layer and time; None when it never does."""
    pieces = _pieces(laid)
    hit = pieces[laid.landing.standoff[pieces] <= 0]
    if hit.size == 0:
        return None
    k = hit[np.argmin(laid.programmed.t0[hit])]
    row = int(laid.programmed.row[k])
    tp = plan.toolpath
    return {"line": int(tp.line[row]), "layer": int(tp.layer[row]), "time_s": float(laid.programmed.t0[k]),
            "standoff_mm": float(laid.landing.standoff[k])}


def speed_area_series(plan, laid) -> tuple[tuple, tuple, tuple]:
    """For :func:`figures.speed_area_figure`, against build time over the deposit rows: the planned
    speed (exact: the trapezoid's four corners a row), the programmed feed, and the bead's
    cross-section area piece by piece (the material a piece carries over its length: ``Q / v``
    along a ramp for a rate source; the material of a stop's last crawl is in its cap, not here)."""
    from ..process.beads import CAP
    from .figures import polyline_series, step_series

    tp, motion = plan.toolpath, plan.motion
    index = np.flatnonzero(tp.deposit & (tp.length > 0))
    t0, t1 = motion.t_start[index], motion.t_end[index]
    v0, vc, v1 = motion.v_entry[index], motion.v_cruise[index], motion.v_exit[index]
    if motion.accel > 0:
        t_acc = np.clip((vc - v0) / motion.accel, 0.0, t1 - t0)
        t_dec = np.clip((vc - v1) / motion.accel, 0.0, t1 - t0 - t_acc)
    else:
        t_acc = t_dec = np.zeros(index.size)
    speed = polyline_series(np.column_stack([t0, t0 + t_acc, t1 - t_dec, t1]), np.column_stack([v0, vc, vc, v1]))
    feed = step_series(t0, t1, tp.feed[index])
    beads = laid.programmed
    pieces = np.flatnonzero(beads.kind != CAP)
    pieces = pieces[piece_lengths(beads, pieces) > 0]
    area = step_series(beads.t0[pieces], beads.t1[pieces], section_area(laid, pieces))
    return speed, feed, area


def standoff_series(laid) -> tuple[tuple, tuple]:
    """For :func:`figures.standoff_figure`: the standoff each landed piece met, against build time,
    and (time, standoff) of the pieces whose material was lost."""
    from ..process.beads import CAP
    from .figures import step_series

    beads, landing = laid.programmed, laid.landing
    pieces = _pieces(laid)
    lost = np.flatnonzero((beads.kind != CAP) & landing.lost)
    return (step_series(beads.t0[pieces], beads.t1[pieces], landing.standoff[pieces]),
            (beads.t0[lost], landing.standoff[lost]))


def built_layers(layers: list[dict], growth_layers: list[dict] | None) -> list[dict]:
    """The layer table for the 3-D view's Z clip: under the flow model each layer's top is the
    highest its beads were built, not the programmed one (a part that outgrows its program would
    otherwise be cut inside the layer)."""
    if not growth_layers:
        return layers
    built = {r["layer"]: r["built_top_mm"]["max"] for r in growth_layers}
    return [{**r, "top_mm": built.get(r["layer"], r["top_mm"])} for r in layers]


MODEL_WORDS = {"fixed": "fixed (one cross-section everywhere, where programmed)",
               "union": "union (each row's cross-section from its material, where programmed)",
               "flow": "flow (each row's material landed on the part as it stands, mass conserved)"}


def process_words(plan) -> tuple[str, str, str, str]:
    """(model, material, motion, landing) in words for the page's inputs table."""
    flow, settings = plan.flow, plan.settings
    f = settings.flow
    if plan.model == "fixed" or not flow.from_material:
        material = {"comments": "the slicer's ;WIDTH: / ;HEIGHT: comments"}.get(flow.source, "")
    elif flow.source == "powder":
        material = (f"powder {f.powder_rate_g_min:g} g/min, density {f.density_g_cm3:g} g/cm³, catchment "
                    f"{f.catchment:g}: Q = {flow.rate_mm3_s:.4g} mm³/s")
    elif flow.source == "wire":
        material = (f"wire Ø {f.wire_diameter_mm:g} mm fed at {f.wire_feed_mm_min:g} mm/min: "
                    f"Q = {flow.rate_mm3_s:.4g} mm³/s")
    elif flow.source == "e":
        material = f"E words, filament Ø {flow.filament_diameter_mm:g} mm (from the {flow.diameter_source})"
    else:
        material = f"{flow.source}"
    if material and flow.from_material and plan.model != "fixed":
        material += f"; {flow.deposited_volume_mm3:,.1f} mm³ delivered"
    m = plan.motion.settings
    if float(m.accel_mm_s2) == 0.0:
        motion = "constant feed (--accel 0: the tool at F everywhere)"
    elif m.square_corner_velocity_mm_s is not None:
        motion = (f"acceleration {m.accel_mm_s2:g} mm/s², square-corner velocity {m.square_corner_velocity_mm_s:g} "
                  f"mm/s (junction deviation {m.effective_junction_deviation_mm:.3g} mm)")
    else:
        motion = f"acceleration {m.accel_mm_s2:g} mm/s², junction deviation {m.junction_deviation_mm:g} mm"
    landing = ""
    if plan.model == "flow":
        g = settings.landing
        landing = (f"standoff {g.standoff_mm:g} mm, max drop {g.max_drop_mm:g} mm, fusion depth "
                   + ("the bead's height" if g.fusion_depth_mm is None else f"{g.fusion_depth_mm:g} mm")
                   + ("" if g.plate_z is None else f", plate Z = {g.plate_z:g} mm"))
        if g.catchment is not None:
            c = g.catchment
            landing += f", catchment profile gauss η0 = {c.eta0:g}, focus {c.focus:g} mm, σ = {c.sigma:g} mm"
    return MODEL_WORDS.get(plan.model, plan.model), material, motion, landing
