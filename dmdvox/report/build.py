"""`dmdvox report`: every analysis that applies, in one self-contained HTML page.

The toolpath summary always; the deposit (volume, pores, pictures); the comparison with the
CAD part when ``--cad`` is given; the nozzle's collisions and clearance when ``--nozzle`` is.
One deposit serves them all. Pictures and plots are written as PNG beside the page and embedded
in it (plots as SVG), so the page can be mailed alone and the PNGs used in slides.
"""

from __future__ import annotations

import sys
from dataclasses import dataclass, replace
from pathlib import Path

import numpy as np

from ..errors import DmdvoxError

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


def run_report(args, extra_fields=()) -> dict:
    """The `report` command: returns the JSON dict (summary and files written).

    ``extra_fields`` adds colourings to the 3-D view: ``(ScalarField, values)`` items, the
    values one per toolpath row or a callable giving one per surface vertex (see
    :func:`dmdvox.report.scene3d.standard_fields`); the view's menu and legend follow from the
    field's name, words and unit, with no change to the page's script."""
    from ..collide.bodies import load_fixtures, nozzle_mesh
    from ..collide.run import collide_part, nozzle_options, prepare_collide
    from ..compare.compare import compare_detail
    from ..deposit.simulate import describe, plan_from_args, simulate_plan
    from ..grid.surface import surface_arrival
    from ..toolpath.summary import summarize
    from ..view.pictures import cad_deviation_picture, render_surface
    from . import figures
    from .page import write_page
    from .scene3d import (ARRIVAL, BEAD_AREA, DEVIATION, LAYER, MAX_SURFACE_TRIANGLES, SceneMesh, decimate,
                          field_range, layer_table, scene_payload, standard_fields)

    if args.fixture and not args.nozzle:
        raise DmdvoxError("--fixture needs --nozzle: the report checks the nozzle against the fixtures")
    out = Path(args.out)
    plan, max_memory = plan_from_args(args)
    tp, bead = plan.toolpath, plan.profile
    if not tp.deposit.any():
        raise DmdvoxError(f"{tp.source}: the program deposits nothing (no deposit moves under dialect "
                          f"'{tp.meta.get('dialect', args.dialect)}'); check --dialect or --laser-on")
    voxel = plan.default_voxel() if args.voxel is None else float(args.voxel)
    fixtures = load_fixtures(args.fixture)
    standoff = clearance = None
    if args.nozzle:
        standoff, clearance = nozzle_options(args)
        prepare_collide(tp, args.nozzle, fixtures, voxel, clearance, max_memory)
    stem = Path(tp.source).stem or "deposit"
    info = summarize(tp)
    outputs: list[str] = []
    sections: dict = {"info": info}

    log = (lambda text: print(f"report: {text}", file=sys.stderr)) if not args.json else (lambda text: None)
    cad_mesh = None
    if args.cad:
        log("depositing and comparing with the CAD part")
        log(describe(plan))
        result, detail = compare_detail(plan, args.cad, voxel=voxel, cad_offset=args.cad_offset,
                                        out_dir=out / "compare", max_memory=max_memory,
                                        simulate_out_dir=out / "simulate", pictures=cad_deviation_picture)
        grid = detail.deposit
        vertices, triangles, deviation = detail.deposit_surface
        arrival = surface_arrival(grid, vertices)
        cad_mesh = detail.cad_mesh
        outputs += result["outputs"]
        sections["compare"] = {k: v for k, v in result.items() if k not in ("outputs", "timings_s")}
        sections["simulate"] = _simulate_part(detail.simulate)
    else:
        log("depositing")
        log(describe(plan))
        result = simulate_plan(plan, voxel=voxel, out_dir=out / "simulate", max_memory=max_memory)
        grid = result["grid"]
        outputs += result["outputs"]
        sections["simulate"] = _simulate_part(result)
        vertices, triangles, arrival = result["surface"]
        deviation = None
    arrival = np.where(np.isfinite(arrival), arrival, tp.duration)
    # the colourings are computed on the full surface: decimation keeps each vertex's nearest value
    if plan.flow.from_material:
        # the material's own cross-section per row, in place of the width x height of the comments
        extra_fields = [(BEAD_AREA, plan.row_area()), *extra_fields]
    fields = standard_fields(tp, bead, vertices, arrival, extra_fields)
    if deviation is not None:
        fields.insert(1, (DEVIATION, np.asarray(deviation, np.float64)))
    # One decimated surface serves the pictures and the 3-D view: at picture resolution it looks
    # the same as the full one and renders in a fraction of the time.
    scalars = {spec.name: values for spec, values in fields}
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
    if args.cad:
        pictures["deviation"] = next(p for p in outputs if p.endswith("_cad_deviation.png"))
    pores = sections["simulate"]["pores"]
    pore_mesh = figures.pore_geometry(grid, pores) if pores else None
    if pores:
        pictures["pores"] = figures.pore_picture(pore_mesh, surface, len(pores), out / f"{stem}_pores.png",
                                                 PICTURE_SIZE)

    # name -> (PNG, SVG, caption)
    plots: dict[str, tuple[str, str, str]] = {}
    if args.cad and sections["compare"]["layers"]:
        plots["layers"] = figures.layer_plot(sections["compare"]["layers"], out / f"{stem}_layers.png")
    if pores:
        plots["pores"] = figures.pore_plot(pores, out / f"{stem}_pore_sizes.png")

    markers = np.zeros((0, 4))
    nozzle = None
    if args.nozzle:
        log("checking the nozzle along the path")
        check, _ = collide_part(tp, grid, args.nozzle, fixtures, args.plate, voxel, standoff=standoff,
                                clearance=clearance)
        sections["collide"] = check.as_dict()
        nozzle = nozzle_mesh(args.nozzle)
        markers = np.array([[*c["position_mm"], c["time_s"]] for c in check.collisions], float).reshape(-1, 4)
        plots["clearance"] = figures.clearance_plot(check.pose_time_s, check.pose_clearance_mm, check.reach_mm,
                                                    clearance, check.collisions, out / f"{stem}_clearance.png")
        if check.collisions:
            pictures["collisions"] = figures.collision_picture(
                surface, [(f.vertices, f.triangles) for f in fixtures], nozzle, check.collisions, voxel,
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
    payload = scene_payload(meshes, tp, markers, standoff, nozzle, specs, sections["layers"])

    inputs = ReportInputs(str(tp.source), str(tp.meta.get("dialect", args.dialect)), args.cad,
                          tuple(args.cad_offset), args.nozzle, standoff, tuple(args.fixture or []), args.plate,
                          bead.name, bead.width, bead.height, voxel)
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
        "outputs": outputs + [str(page)],
    }
    if not args.json:
        print(f"wrote {page} ({len(summary['outputs'])} files under {out}/)")
    return summary


def _simulate_part(result: dict) -> dict:
    keep = ("voxel_mm", "deposit_volume_mm3", "active_voxels", "memory_bytes", "pore_count", "pores",
            "porosity_percent", "bbox_mm")
    return {k: result[k] for k in keep}
