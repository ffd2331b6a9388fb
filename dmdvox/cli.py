"""dmdvox: predict what a DED toolpath builds, before anything is deposited.

Command-line entry point, kept thin: argument parsing, dispatch, and the mapping of errors to
exit codes (0 ok, 2 bad input or refused request, 1 internal error, 3 a `check` limit failed).
With --json exactly one JSON object goes to stdout; logs and warnings go to stderr.
"""

from __future__ import annotations

import argparse
import json
import math
import os
import re
import sys
import traceback

import numpy as np

from . import checks, progress
from .defaults import CLEARANCE_MM, STANDOFF_MM
from .errors import DmdvoxError


def _count(n: int, noun: str) -> str:
    return f"{n:,} {noun}{'' if n == 1 else 's'}"


def _add_gcode_options(p: argparse.ArgumentParser) -> None:
    from .toolpath.dialects import DIALECT_NAMES

    p.add_argument("gcode", help="G-code file")
    p.add_argument("--dialect", default="auto", choices=DIALECT_NAMES,
                   help="deposition rules (default auto: E words mean reprap, else M-code families)")
    p.add_argument("--laser-on", help="custom dialect: comma list of codes that start deposition, e.g. 'M65,M101'")
    p.add_argument("--laser-off", help="custom dialect: comma list of codes that stop deposition")
    p.add_argument("--strict", action="store_true", help="stop at the first malformed line (exit 2)")
    p.add_argument("--start", type=_offset, default=None, metavar="X,Y,Z",
                   help="where the tool stands before the first line (mm), for a program that never says it "
                        "(all G91, no G28/G92)")
    p.add_argument("--machine", default="none", metavar="FILE.toml",
                   help="five-axis machine file (docs/MACHINES.md, data/machines/); default none: 3-axis")
    p.add_argument("--json", action="store_true", help="print one JSON object on stdout")


def _toolpath(args):
    """The G-code options as a read toolpath; the reader's warnings are said (:func:`checks.check_toolpath`)."""
    from .toolpath.reader import read_gcode

    tp = read_gcode(args.gcode, dialect=args.dialect, strict=args.strict, laser_on=args.laser_on,
                    laser_off=args.laser_off, machine=args.machine, start=args.start,
                    plate_z=getattr(args, "plate", None))
    if args.dialect == "auto":
        progress.stage("dialect", f"{tp.dialect}, by {'; '.join(tp.meta['dialect_evidence']) or 'no laser code or E word'}")
    checks.check_toolpath(tp, args.strict)
    return tp


def _process_settings(args, flow_only: bool = False):
    """The process options as typed settings: material and motion (all that ``info`` takes with
    ``flow_only``), bead, model and landing."""
    from .process.flow import FlowSettings
    from .process.landing import DEFAULT_MAX_DROP_MM, LandingSettings, parse_catchment_profile
    from .process.plan import ProcessSettings
    from .process.planner import MotionSettings

    flow = FlowSettings(
        filament_diameter_mm=args.filament_diameter, powder_rate_g_min=args.powder_rate,
        density_g_cm3=args.density, catchment=args.catchment, wire_diameter_mm=args.wire_diameter,
        wire_feed_mm_min=args.wire_feed, strict=args.strict)
    motion = MotionSettings(accel_mm_s2=args.accel, junction_deviation_mm=args.junction_deviation,
                            square_corner_velocity_mm_s=args.square_corner_velocity,
                            travel_accel_mm_s2=args.travel_accel, retract_accel_mm_s2=args.retract_accel,
                            max_feed_mm_s=args.max_feed, max_axis_accel_mm_s2=args.max_axis_accel,
                            jerk_mm_s=args.jerk, jerk_rule=args.jerk_rule, accel_to_decel_mm_s2=args.accel_to_decel,
                            program_limits=not args.ignore_program_limits)
    if flow_only:
        return ProcessSettings(flow=flow, motion=motion)
    standoff = getattr(args, "standoff", None)
    profile = getattr(args, "catchment_profile", None)
    landing = LandingSettings(
        plate_z=getattr(args, "plate", None),
        max_drop_mm=DEFAULT_MAX_DROP_MM if args.max_drop is None else args.max_drop,
        fusion_depth_mm=args.fusion_depth, standoff_mm=STANDOFF_MM if standoff is None else standoff,
        catchment=None if profile is None else parse_catchment_profile(profile),
        bridge_span_mm=getattr(args, "bridge_span", None))
    return ProcessSettings(profile=args.profile, width=args.width, height=args.height, exponent=args.exponent,
                           model=args.model, flow=flow, motion=motion, landing=landing)


def _plan(args):
    """For the bead-laying commands: the program as the machine runs it; the plan's warnings go
    to stderr and into ``--json``."""
    from .process.plan import plan_process

    plan = plan_process(_toolpath(args), _process_settings(args))
    for warning in plan.warnings:
        checks.warn(warning)
    checks.require_voxel_resolves_bead(plan, getattr(args, "voxel", None))
    return plan


def _max_memory(args) -> int | None:
    """``--max-memory`` GiB as bytes (None: a share of what is free)."""
    return None if args.max_memory is None else int(args.max_memory * 2**30)


def cmd_info(args) -> dict:
    from .process.plan import plan_process
    from .toolpath.summary import format_summary, summarize

    tp = _toolpath(args)
    checks.warn_if_nothing_deposited(tp)
    plan = plan_process(tp, _process_settings(args, flow_only=True))
    for warning in plan.warnings:
        checks.warn(warning)
    info = summarize(plan.toolpath)
    info.update(plan.flow_json())
    if not args.json:
        print(format_summary(plan.toolpath, info))
    return info


def cmd_simulate(args) -> dict:
    from .deposit.simulate import SimulateRequest, describe, format_simulate, simulate

    plan = _plan(args)
    checks.require_deposit(plan.toolpath, args.until)
    heat = _heat_options(args, plan)
    if heat is not None and args.until is not None:
        raise DmdvoxError("--thermal heats the whole program: leave out --until")
    progress.stage("deposit", describe(plan))
    sim = simulate(SimulateRequest(plan, voxel=args.voxel, until=args.until, out_dir=args.out,
                                   max_memory=_max_memory(args), scheduler=args.scheduler))
    result = sim.to_json()
    if heat is not None:
        from .thermal.outputs import heat_deposit

        progress.stage("thermal", f"{heat['material']} on the deposit of {plan.toolpath.source}")
        _, result["thermal"] = heat_deposit(plan, sim.grid, sim["plate_z_mm"], heat, args.out, _max_memory(args))
        result["outputs"] = [*result["outputs"], *result["thermal"]["outputs"]]
    if not args.json:
        print(format_simulate(plan, result))
        if heat is not None:
            _print_heat(plan, result["thermal"])
    return result


def cmd_compare(args) -> dict:
    from .comparison.compare import CompareRequest, compare
    from .view.pictures import cad_deviation_picture

    plan = _plan(args)
    checks.require_deposit(plan.toolpath)
    result = compare(CompareRequest(plan, args.cad, cad_offset=args.cad_offset, voxel=args.voxel, out_dir=args.out,
                                    max_memory=_max_memory(args), scheduler=args.scheduler),
                     pictures=cad_deviation_picture).to_json()
    if not args.json:
        cad_v = result["cad_volume_mm3"]
        print(f"{plan.toolpath.source} vs {args.cad}: {result['model']} model, voxel {result['voxel_mm']:g} mm")
        print(f"  CAD volume       {cad_v:,.2f} mm^3")
        print(f"  deposit volume   {result['deposit_volume_mm3']:,.2f} mm^3")
        print(f"  void             {result['void_volume_mm3']:,.2f} mm^3 ({result['void_percent']:.2f} % of CAD), "
              f"max underfill {result['max_underfill_mm']:.3f} mm")
        print(f"  overbuild        {result['overbuild_volume_mm3']:,.2f} mm^3 ({result['overbuild_percent']:.2f} % of CAD), "
              f"max overbuild {result['max_overbuild_mm']:.3f} mm")
        dev = result["deviation_mm"]
        print(f"  CAD surface deviation (+ = excess material): mean {dev['mean']:+.3f}  rms {dev['rms']:.3f}  "
              f"p95 |dev| {dev['p95']:.3f} mm")
        print(f"  internal void    {result['internal_void_mm3']:,.2f} mm^3 ({result['porosity_percent']:.2f} % of CAD): "
              f"lack of fusion {result['lack_of_fusion_mm3']:,.2f}, cavities {result['cavity_mm3']:,.2f} mm^3; "
              f"{_count(result['pore_count'], 'pore')}, {_count(result['speck_count'], 'speck')}")
        for path in result["outputs"]:
            print(f"  wrote {path}")
    return result


def cmd_render(args) -> dict:
    from .view.render import moment, parse_size, render_moment

    plan = _plan(args)
    max_memory = _max_memory(args)
    tp = plan.toolpath
    checks.warn_if_before_first_deposit(tp, moment(tp, args.at, args.time), "--at" if args.at is not None else "--time")
    progress.stage("render", str(args.png))
    result = render_moment(plan, args.png, voxel=args.voxel, at=args.at, time_s=args.time, view=args.view,
                           size=parse_size(args.size), cad_path=args.cad, max_memory=max_memory)
    if not args.json:
        print(f"wrote {result['png']} (t = {result['time_s']:.2f} s)")
    return result


def _add_study_overlap(p: argparse.ArgumentParser) -> None:
    from .process.profiles import PROFILE_NAMES

    p.add_argument("--profile", default="parabola", choices=PROFILE_NAMES, help="bead cross-section (default parabola)")
    p.add_argument("--width", type=float, required=True, metavar="MM", help="bead width")
    p.add_argument("--height", type=float, default=None, metavar="MM",
                   help="bead height (with --area: from the area, the width and the profile)")
    p.add_argument("--area", type=float, default=None, metavar="MM2",
                   help="the beads' cross-section: the flow model lands them, mass conserved")
    p.add_argument("--model", default=None, choices=("union", "flow"),
                   help="union: beads where programmed, overlap lost; flow: beads land on the patch, mass "
                        "conserved (default: flow with --area, else union)")
    p.add_argument("--exponent", type=float, default=4.0, help="Lame profile exponent (default 4)")
    p.add_argument("--spacing", required=True, metavar="A:B:STEP", help="hatch spacings in mm (or one value)")
    p.add_argument("--layer-step", default=None, metavar="A:B:STEP",
                   help="layer steps in mm (or one value; default: the bead height)")
    p.add_argument("--layers", type=int, default=3, help="layers in each patch (default 3)")
    p.add_argument("--voxel", type=_voxel, default=None, metavar="MM",
                   help="voxel size (default: width/40, at most height/8)")
    p.add_argument("--scheduler", type=_scheduler, default=None, metavar="ADDR",
                   help="dask scheduler address (tcp://host:port); default: local processes")
    p.add_argument("--json", action="store_true", help="print one JSON object on stdout")
    p.add_argument("--csv", default=None, metavar="FILE", help="write the table as CSV")
    p.add_argument("--plot", default=None, metavar="FILE.png", help="plot porosity and waviness against overlap ratio")
    p.set_defaults(handler=cmd_study_overlap)


def cmd_study_overlap(args) -> dict:
    """``dmdvox study overlap``: one row per (spacing, layer step)."""
    from .io.atomic import write_text
    from .io.tables import rows_to_csv
    from .study.overlap import overlap_cases, overlap_study
    from .study.ranges import parse_range

    steps = None if args.layer_step is None else parse_range(args.layer_step, "--layer-step")
    cases = overlap_cases(args.profile, args.width, args.exponent, parse_range(args.spacing, "--spacing"), steps,
                          args.layers, height=args.height, area=args.area, model=args.model, voxel=args.voxel)
    study = overlap_study(cases, args.scheduler)
    if args.csv:
        write_text(args.csv, rows_to_csv(study.rows, study.keys))
    if args.plot:
        from .view.plots import plot_overlap

        plot_overlap(study.rows, cases[0].width, args.plot, study.union_rows)
    if not args.json:
        print("  ".join(f"{k:>22}" for k in study.keys))
        for row in study.rows:
            print("  ".join(f"{row[k]:22.4f}" for k in study.keys))
        for path in (args.csv, args.plot):
            if path:
                print(f"wrote {path}", file=sys.stderr)
    return study.to_json()


def _add_study_sweep(p: argparse.ArgumentParser) -> None:
    """Beyond the G-code and bead options of ``simulate``, which the caller adds."""
    from .study.sweep import SWEEPABLE

    p.add_argument("--set", action="append", default=[], metavar="NAME=A:B:STEP",
                   help=f"sweep an option ({', '.join(SWEEPABLE)}); repeat for a grid")
    p.add_argument("--cad", default=None, metavar="STL", help="compare each run with this CAD part")
    _add_cad_offset(p)
    p.add_argument("--until", type=float, default=None, metavar="S", help="the part as it stands at this time (s)")
    p.add_argument("--scheduler", type=_scheduler, default=None, metavar="ADDR",
                   help="dask scheduler address; default local processes")
    p.add_argument("--csv", default=None, metavar="FILE", help="write the table as CSV")
    p.set_defaults(handler=cmd_study_sweep)


def cmd_study_sweep(args) -> dict:
    """``dmdvox study sweep``: one row per run, swept options first."""
    from pathlib import Path

    from .io.atomic import write_text
    from .io.tables import rows_to_csv
    from .study.sweep import SweepCase, parse_set, sweep

    base = SweepCase(
        gcode=str(Path(args.gcode).resolve()), dialect=args.dialect, strict=bool(args.strict),
        laser_on=args.laser_on, laser_off=args.laser_off,
        # each run reads its own files: absolute paths, so a worker elsewhere finds them
        machine=args.machine if args.machine == "none" else str(Path(args.machine).resolve()),
        settings=_process_settings(args),
        voxel=None if args.voxel is None else float(args.voxel), until=args.until,
        cad=None if args.cad is None else str(Path(args.cad).resolve()), cad_offset=tuple(args.cad_offset),
        max_memory=_max_memory(args), start=args.start)
    study = sweep(base, [parse_set(text) for text in args.set], args.scheduler)
    keys = study.keys
    if args.csv:
        write_text(args.csv, rows_to_csv(study.rows, keys))
    if not args.json:
        print(",".join(keys))
        for row in study.rows:
            print(",".join(f"{row.get(k, '')}" for k in keys))
        if args.csv:
            print(f"wrote {args.csv}", file=sys.stderr)
    return study.to_json()


def _require_display(command: str) -> None:
    if not (os.environ.get("DISPLAY") or os.environ.get("WAYLAND_DISPLAY")):
        raise DmdvoxError(f"{command} opens an interactive window and there is no display (DISPLAY is not set); "
                          "run it on a desktop, or use `dmdvox render` for pictures")


def cmd_view(args) -> dict:
    from .view.interactive import build_replay

    _require_display("view")
    plan = _plan(args)
    replay = build_replay(plan, voxel=args.voxel, color=args.color, cad_path=args.cad, nozzle_spec=args.nozzle,
                          fixtures=args.fixture or [], standoff=args.standoff, max_memory=_max_memory(args))
    replay.show()
    return {"duration_s": plan.toolpath.duration, "triangles": replay.n_triangles, "collisions": len(replay.markers)}


def cmd_scene(args) -> dict:
    from .view.scene_app import run_scene

    _require_display("scene")
    return run_scene(args)


def cmd_demo(args) -> dict:
    from .demo import run_demo

    return run_demo(args)


def _nozzle(args):
    from .collision.run import NozzleSettings

    return NozzleSettings(args.nozzle, tuple(args.fixture or ()), plate=args.plate, standoff=args.standoff,
                          clearance=args.clearance)


def cmd_collide(args) -> dict:
    from .collision.run import CollideRequest, collide

    result = collide(CollideRequest(_plan(args), _nozzle(args), voxel=args.voxel, max_memory=_max_memory(args),
                                    strict=args.strict))
    if not args.json:
        print(result.text())
    return result.to_json()


def _report_request(args):
    from .reporting.build import ReportRequest

    if args.fixture and not args.nozzle:
        raise DmdvoxError("--fixture needs --nozzle: the report checks the nozzle against the fixtures")
    plan = _plan(args)
    return ReportRequest(plan, args.out, cad=args.cad, cad_offset=args.cad_offset,
                         nozzle=_nozzle(args) if args.nozzle else None, voxel=args.voxel,
                         max_memory=_max_memory(args), scheduler=args.scheduler, thermal=_heat_options(args, plan))


def cmd_report(args) -> dict:
    from .reporting.build import report

    result = report(_report_request(args))
    if not args.json:
        print(f"wrote {result.page} ({len(result['outputs'])} files under {args.out}/)")
    return result.to_json()


def _apply_cell(args):
    """The cell file's limits, and its options wherever the command line left one unset
    (``check``'s options default to None so that a given one is told from a default), read as
    the command line reads them (types, choices)."""
    from .limits import read_cell

    cell = read_cell(args.limits)
    for dest, (default, kind, choices, flag) in args.cell_options.items():
        if getattr(args, dest) is not None:
            continue
        if dest not in cell.options:
            setattr(args, dest, default)
            continue
        value = cell.options[dest]
        try:
            if flag:
                if not isinstance(value, bool):
                    raise ValueError("expected true or false")
            elif kind is not None and not isinstance(value, (list, tuple)):
                value = kind(value if isinstance(value, str) else str(value))
            if choices is not None and value not in choices:
                raise ValueError(f"choose one of {', '.join(map(str, choices))}")
        except (ValueError, TypeError, argparse.ArgumentTypeError) as exc:
            raise DmdvoxError(f"{cell.path}: {dest} = {value!r}: {exc}") from None
        setattr(args, dest, value)
    return cell


def cmd_check(args) -> dict:
    try:
        return _check(args)
    except DmdvoxError as exc:
        if args.junit:
            from .io.atomic import write_text
            from .limits import junit_error_xml

            try:
                write_text(args.junit, junit_error_xml(args.gcode, exc.worded(OPTION_OF_PARAMETER), type(exc).__name__))
            except OSError as write_error:
                raise DmdvoxError(f"{exc.worded(OPTION_OF_PARAMETER)} (and --junit {args.junit} could not be "
                                  f"written: {write_error})") from None
        raise


def _check(args) -> dict:
    from .limits import CheckRequest, check

    cell = _apply_cell(args)
    if args.fixture and not args.nozzle:
        raise DmdvoxError("--fixture needs --nozzle: the check runs the nozzle against the fixtures")
    result = check(CheckRequest(_plan(args), cell.limits, cad=args.cad, cad_offset=tuple(args.cad_offset),
                                nozzle=_nozzle(args) if args.nozzle else None, voxel=args.voxel,
                                max_memory=_max_memory(args), scheduler=args.scheduler, strict=args.strict,
                                junit=args.junit, thermal=cell.thermal))
    if not args.json:
        print(result.text())
    return result.to_json()


def cmd_diff(args) -> dict:
    from .changes import DiffRequest, diff
    from .process.plan import plan_process
    from .view.pictures import diff_picture

    old = _plan(args)
    new_args = argparse.Namespace(**{**vars(args), "gcode": args.new})
    new = plan_process(_toolpath(new_args), _process_settings(new_args))
    for warning in new.warnings:
        checks.warn(warning)
    checks.require_voxel_resolves_bead(new, args.voxel)
    checks.require_deposit(old.toolpath)
    checks.require_deposit(new.toolpath)
    result = diff(DiffRequest(old, new, voxel=args.voxel, cad=args.cad, cad_offset=tuple(args.cad_offset),
                              out_dir=args.out, max_memory=_max_memory(args), scheduler=args.scheduler),
                  pictures=diff_picture)
    if not args.json:
        print(result.text())
    return result.to_json()


def _add_thermal_options(p: argparse.ArgumentParser, stage: bool = False) -> None:
    """The heat model's options (docs/THERMAL.md); ``stage``: behind a ``--thermal`` flag that
    runs the heat after the deposit, on its grid (``simulate``, ``report``)."""
    g = p.add_argument_group("heat (docs/THERMAL.md)")
    if stage:
        g.add_argument("--thermal", action="store_true",
                       help="run the heat after the deposit, on its grid (the options of `dmdvox thermal`)")
    g.add_argument("--material", required=not stage, default=None, metavar="M",
                   help="316L, IN718, Ti64 or a TOML file of properties")
    g.add_argument("--laser-power", type=float, default=None, metavar="W",
                   help="beam power (default: the program's S words read as watts)")
    g.add_argument("--absorptivity", type=float, default=0.4, metavar="ETA",
                   help="fraction of the beam absorbed, in (0, 1] (default 0.4; powder DED 0.3-0.5, arc 0.7-0.85)")
    g.add_argument("--beam-radius", type=float, default=None, metavar="MM",
                   help="1/e^2 radius of the Gaussian beam (default half the bead width)")
    g.add_argument("--thermal-voxel", type=float, default=None, metavar="MM",
                   help="thermal cell edge, a whole number of deposit voxels (default a quarter of the bead width)")
    g.add_argument("--plate-size", default=None, metavar="X,Y,T",
                   help="plate extent and thickness in mm (default the footprint plus 5 mm a side, 10 mm thick)")
    g.add_argument("--plate-bottom", default="clamped", choices=("clamped", "adiabatic"),
                   help="plate bottom held at the preheat (clamped to a large table) or insulated")
    g.add_argument("--preheat", type=float, default=None, metavar="C", help="plate temperature at the start (default ambient)")
    g.add_argument("--ambient", type=float, default=20.0, metavar="C", help="surroundings (default 20)")
    g.add_argument("--convection", type=float, default=10.0, metavar="W_M2K",
                   help="film coefficient of every exposed face (default 10, still air)")
    g.add_argument("--emissivity", type=float, default=0.4, metavar="E", help="surface emissivity (default 0.4)")
    g.add_argument("--interpass", type=float, default=None, metavar="C",
                   help="report each layer's time to cool below this")
    g.add_argument("--probe", type=_offset, action="append", default=[], metavar="X,Y,Z",
                   help="temperature over time at this point (CSV); repeatable")
    g.add_argument("--cool", type=float, default=0.0, metavar="S", help="run on this long after the program ends")
    g.add_argument("--source", default="gaussian", choices=("gaussian", "goldak"),
                   help="the beam: a Gaussian on the surface (laser) or Goldak's double ellipsoid (arc, WAAM)")
    g.add_argument("--goldak", default=None, metavar="A_F,A_R,B,C",
                   help="the double ellipsoid's semi-axes in mm: front, rear, half width, depth "
                        "(default 1, 2, 1, 1 x the beam radius)")
    if stage:
        return
    g.add_argument("--thermal-feedback", default=None, choices=("3d", "wall"),
                   help="lay the beads again wider and lower on the hot part: width ~ (T_liquidus - T0)^-1/2 (3d) "
                        "or ^-1 (wall), T0 the layer below's interlayer temperature, area kept")


def cmd_thermal(args) -> dict:
    """``dmdvox thermal``: the deposit, then its thermal history on it."""
    from .deposit.simulate import SimulateRequest, describe, simulate
    from .thermal.materials import load_material
    from .thermal.outputs import heat_deposit

    material = load_material(args.material)
    plan = _plan(args)
    checks.require_deposit(plan.toolpath)
    options = _heat_options(args, plan)
    progress.stage("deposit", describe(plan))
    sim = simulate(SimulateRequest(plan, voxel=args.voxel, max_memory=_max_memory(args)))
    progress.stage("thermal", f"{material.name} on the deposit of {plan.toolpath.source}")
    result, summary = heat_deposit(plan, sim.grid, sim["plate_z_mm"], options, args.out, _max_memory(args))
    if args.thermal_feedback:
        from .thermal.feedback import fed_back, row_preheat, width_factor

        preheat = row_preheat(plan, result.layers, result.settings.plate_temperature)
        factor = width_factor(preheat, material.liquidus, result.settings.ambient, args.thermal_feedback)
        progress.stage("thermal", f"feedback: beads up to {factor.max():.3g} x wider, laid again")
        hot = simulate(SimulateRequest(fed_back(plan, factor), voxel=args.voxel, max_memory=_max_memory(args)))
        deposit = plan.toolpath.deposit
        summary["feedback"] = {"law": args.thermal_feedback,
                               "max_width_factor": float(factor[deposit].max()),
                               "cold_volume_mm3": sim["deposit_volume_mm3"],
                               "hot_volume_mm3": hot["deposit_volume_mm3"],
                               "cold_bbox_mm": sim["bbox_mm"], "hot_bbox_mm": hot["bbox_mm"],
                               "hot_growth_layers": hot.summary.get("growth_layers")}
    if not args.json:
        _print_heat(plan, summary)
    return summary


def _heat_options(args, plan) -> dict | None:
    """The heat options of the command line (None: no ``--thermal`` on a command where it is a
    flag), every one refused before the deposit is swept."""
    from .thermal.build import check_inputs
    from .thermal.run import OPTION_KEYS, thermal_request

    if not getattr(args, "thermal", True):
        given = [key for key in ("material", "laser_power", "thermal_voxel") if getattr(args, key) is not None]
        if given:
            raise DmdvoxError(f"--{given[0].replace('_', '-')} is a heat option: add --thermal to run the heat")
        return None
    options = {key: getattr(args, key) for key in OPTION_KEYS}
    check_inputs(plan.profile.width, args.thermal_voxel, args.laser_power)
    thermal_request(plan, None, options)
    return options


def _print_heat(plan, summary: dict) -> None:
    print(f"{plan.toolpath.source}: {summary['material']['name']}, thermal voxel {summary['thermal_voxel_mm']:g} mm, "
          f"{summary['cells']:,} cells, {summary['steps']:,} steps of {summary['time_step_s'] * 1e3:.3g} ms")
    print(f"  absorbed {summary['absorbed_J']:,.0f} J = stored {summary['stored_J']:,.0f} + lost "
          f"{summary['lost_J']:,.0f} (balance within {summary['energy_balance_max_percent']:.2g} %)")
    print(f"  peak {summary['max_peak_temperature_C']:.0f} C, interlayer up to "
          f"{summary['max_interlayer_temperature_C'] or float('nan'):.0f} C, melt pool up to "
          f"{summary['max_melt_pool_width_mm'] or 0.0:.2f} mm wide")
    for path in summary["outputs"]:
        print(f"  wrote {path}")


def _offset(text: str) -> tuple[float, float, float]:
    try:
        values = tuple(float(v) for v in text.split(","))
    except ValueError:
        values = ()
    if len(values) != 3 or not all(np.isfinite(values)):
        raise argparse.ArgumentTypeError(f"expected X,Y,Z in mm, got '{text}'")
    return values


# Below a nanometre a voxel is a corrupt number: 3e-150 mm overflowed the grid's memory estimate.
MIN_VOXEL_MM = 1e-6


def _voxel(text: str) -> float:
    """``--voxel``: a positive finite length (nan once reached the memory estimate as a traceback)."""
    try:
        value = float(text)
    except ValueError:
        value = math.nan
    if not (math.isfinite(value) and value >= MIN_VOXEL_MM):
        raise argparse.ArgumentTypeError(f"must be a positive finite length in mm (at least {MIN_VOXEL_MM:g}), "
                                         f"got '{text}'")
    return value


def _gib(text: str) -> float:
    """``--max-memory``: a positive finite number of GiB (a limit of 0, nan or inf means nothing)."""
    try:
        value = float(text)
    except ValueError:
        value = math.nan
    if not (math.isfinite(value) and value > 0):
        raise argparse.ArgumentTypeError(f"must be a positive finite number of GiB (e.g. 8), got '{text}'")
    return value


# dask's address forms: SCHEME://HOST:PORT (tcp, tls, ws, wss, ucx) or HOST:PORT; inproc:// names a
# scheduler in this process
_SCHEDULER = re.compile(r"^(?:(?:tcp|tls|ws|wss|ucx)://)?(?:\[[0-9A-Fa-f:.]+\]|[A-Za-z0-9_.-]+):\d{1,5}$|^inproc://\S+$")


def _scheduler(text: str) -> str:
    """``--scheduler``: a dask scheduler's address, checked before any work."""
    if not _SCHEDULER.match(text) or (":" in text and not text.startswith("inproc://")
                                      and int(text.rsplit(":", 1)[1]) > 65535):
        raise argparse.ArgumentTypeError(f"expected a dask scheduler address such as tcp://host:8786, got '{text}'")
    return text


def _add_bead_options(p: argparse.ArgumentParser, plate_and_standoff: bool = True) -> None:
    from .process.plan import MODELS
    from .process.profiles import PROFILE_NAMES

    p.add_argument("--profile", default="rect", choices=PROFILE_NAMES, help="bead cross-section (default rect)")
    p.add_argument("--width", type=float, default=None,
                   help="bead (melt-pool) width in mm (default: the slicer's ;WIDTH:, else for E-fed files what "
                        "the material fills at the layer height, else 2.5, the seed's track)")
    p.add_argument("--height", type=float, default=None,
                   help="bead height in mm, fixed bead only (default: the detected layer step; with material "
                        "the height follows from it)")
    p.add_argument("--exponent", type=float, default=4.0, help="Lame profile exponent (default 4)")
    p.add_argument("--voxel", type=_voxel, default=None,
                   help="voxel size in mm (default: min(width/20, height/4))")
    p.add_argument("--max-memory", type=_gib, default=None, metavar="GIB",
                   help="memory limit in GiB (default 80 %% of the available memory)")
    p.add_argument("--model", default=None, choices=MODELS,
                   help="fixed: one bead everywhere; union: each row's bead from its material, where programmed; "
                        "flow: those beads land on the part, mass conserved (default: flow when the material "
                        "gives the bead, union with only slicer width comments, else fixed)")
    _add_process_options(p)
    g = p.add_argument_group("landing (the flow model)")
    g.add_argument("--max-drop", type=float, default=None, metavar="MM",
                   help="material programmed more than this above the part never reaches it: reported lost "
                        "(default 2 mm, a powder nozzle's focal depth)")
    g.add_argument("--fusion-depth", type=float, default=None, metavar="MM",
                   help="deepest gap below a bead its melt fills; deeper gaps stay as lack of fusion "
                        "(default: the bead's height)")
    g.add_argument("--bridge-span", type=float, default=None, metavar="MM",
                   help="longest gap between supports a bead spans (sagging) instead of dropping into it "
                        "(default: 5 mm for extruded filament, one bead width for a powder or wire melt pool)")
    g.add_argument("--catchment-profile", default=None, metavar="gauss:eta0=E,focus=MM,sigma=MM",
                   help="catchment falling off as the standoff leaves the powder focus (instead of --catchment)")
    if plate_and_standoff:
        g.add_argument("--standoff", type=float, default=None, metavar="MM",
                       help=f"nozzle tip above the programmed bead bottom (default {STANDOFF_MM:g} mm, the seed's)")
        g.add_argument("--plate", type=float, default=None, metavar="Z",
                       help="substrate top (default: the lowest programmed bead bottom)")


def _add_process_options(p: argparse.ArgumentParser) -> None:
    """Material and motion: what the program delivers and how fast the machine really moves."""
    from .process.planner import DEFAULT_ACCEL_MM_S2, DEFAULT_JUNCTION_DEVIATION_MM

    g = p.add_argument_group("material (the first that applies: E words, powder, wire)")
    g.add_argument("--filament-diameter", type=float, default=None, metavar="MM",
                   help="E words: filament or wire diameter (default: the slicer's header, else 1.75)")
    g.add_argument("--powder-rate", type=float, default=None, metavar="G_MIN", help="powder mass flow while on")
    g.add_argument("--density", type=float, default=None, metavar="G_CM3", help="the alloy's density (powder)")
    g.add_argument("--catchment", type=float, default=1.0, metavar="ETA",
                   help="fraction of the powder the melt pool catches (default 1.0; DED: 0.3-0.9)")
    g.add_argument("--wire-diameter", type=float, default=None, metavar="MM", help="wire DED / WAAM wire diameter")
    g.add_argument("--wire-feed", type=float, default=None, metavar="MM_MIN", help="wire feed speed")
    g = p.add_argument_group("motion (what the machine does with F)")
    g.add_argument("--accel", type=float, default=None, metavar="MM_S2",
                   help="acceleration of every move, over the program's own M204/SET_VELOCITY_LIMIT (default: the "
                        f"program's, else {DEFAULT_ACCEL_MM_S2:g}; 0: constant feed, the tool at F everywhere)")
    g.add_argument("--junction-deviation", type=float, default=None, metavar="MM",
                   help="corner speed by the Grbl/Marlin rule (default: the program's M205 J, else "
                        f"{DEFAULT_JUNCTION_DEVIATION_MM:g}, or its classic jerk when it states one)")
    g.add_argument("--square-corner-velocity", type=float, default=None, metavar="MM_S",
                   help="corner speed by Klipper's rule instead: a 90-degree corner runs at this speed")
    g.add_argument("--travel-accel", type=float, default=None, metavar="MM_S2",
                   help="acceleration of moves that do not deposit (M204 T; default: the program's, else --accel)")
    g.add_argument("--retract-accel", type=float, default=None, metavar="MM_S2",
                   help="acceleration of retract-only moves (M204 R; default: the program's, else --accel)")
    g.add_argument("--max-feed", default=None, metavar="X,Y,Z,E",
                   help="top speed of each axis in mm/s (M203; default: the program's, else unlimited)")
    g.add_argument("--max-axis-accel", default=None, metavar="X,Y,Z,E",
                   help="acceleration of each axis in mm/s^2 (M201; default: the program's, else unlimited)")
    g.add_argument("--jerk", default=None, metavar="X,Y,Z,E",
                   help="Marlin's classic jerk of each axis in mm/s (M205 X Y Z E) instead of a junction deviation")
    g.add_argument("--jerk-rule", default=None, choices=("axis", "xy"),
                   help="classic jerk per axis (Marlin 1.1 and later, PrusaSlicer's estimate) or of the XY vector "
                        "(Marlin 1.0, Cura's estimate); default: xy for Cura's settings, else axis")
    g.add_argument("--accel-to-decel", type=float, default=None, metavar="MM_S2",
                   help="Klipper's max_accel_to_decel: the peak of short moves (default: the program's; Klipper: "
                        "half the acceleration)")
    g.add_argument("--ignore-program-limits", action="store_true",
                   help="ignore the program's own M201-M205, SET_VELOCITY_LIMIT and slicer machine settings")


CHECK_DESCRIPTION = """Run what the limits need (deposit, CAD comparison, nozzle collisions) and judge each.

The cell file (TOML) has a [limits] table whose keys are the JSON names they bound, maximums unless
the name says min: void_percent, overbuild_percent, deviation_mm.p95, max_underfill_mm,
max_overbuild_mm, porosity_percent, max_pore_diameter_mm, collisions, min_clearance_mm,
max_drift_mm, lost_volume_mm3, max_interlayer_temperature_C, max_peak_temperature_C,
max_melt_pool_width_mm. Tables [part] (cad, cad_offset), [process] (width, height,
profile, model, voxel, accel, ...), [machine] (file), [nozzle] (spec, fixtures, plate, standoff,
clearance) and [thermal] (material, laser_power, absorptivity, thermal_voxel, ...: the options of
`dmdvox thermal`) describe the cell; options given here override them.

exit codes: 0 every limit met, 3 a limit failed, 2 bad input or refused request, 1 internal error"""


def build_parser() -> argparse.ArgumentParser:
    from . import __version__

    parser = argparse.ArgumentParser(prog="dmdvox", description=__doc__.split("\n")[0],
                                     epilog="exit codes: 0 ok, 2 bad input or refused request, 1 internal error, "
                                            "3 a `check` limit failed")
    parser.add_argument("--version", action="version", version=f"dmdvox {__version__}")
    sub = parser.add_subparsers(dest="command", required=True, metavar="COMMAND")
    p = sub.add_parser("info", help="summarise a G-code program (moves, lengths, layers, time, material)")
    _add_gcode_options(p)
    _add_process_options(p)
    p.set_defaults(handler=cmd_info)
    p = sub.add_parser("simulate", help="sweep the beads into a sparse SDF grid; volume, pores, .vdb and surfaces")
    _add_gcode_options(p)
    _add_bead_options(p)
    p.add_argument("--until", type=float, default=None, metavar="S", help="the part as it stands at this time (s)")
    p.add_argument("--out", default=None, metavar="DIR", help="write .vdb, surfaces (.vtp .stl .ply) and JSON here")
    _add_scheduler(p, "sweep the part's slabs and search its voids in tiles")
    _add_thermal_options(p, stage=True)
    p.set_defaults(handler=cmd_simulate)
    p = sub.add_parser("compare", help="deposit vs CAD STL: void, overbuild, deviation maps (VTK), pores")
    _add_gcode_options(p)
    p.add_argument("cad", help="CAD part (STL, workpiece coordinates: machine coordinates on a 3-axis machine)")
    _add_bead_options(p)
    _add_cad_offset(p)
    p.add_argument("--out", default=None, metavar="DIR",
                   help="write deviation maps (.vtp), label and SDF fields (.vti or .vtm, .vdb), CSV and JSON here")
    _add_scheduler(p, "sweep the part's and the comparison's slabs")
    p.set_defaults(handler=cmd_compare)
    p = sub.add_parser("render", help="headless PNG of the part as it stands at a moment, coloured by arrival time")
    _add_gcode_options(p)
    _add_bead_options(p)
    p.add_argument("--at", type=float, default=None, metavar="FRACTION", help="moment as a fraction of the build")
    p.add_argument("--time", type=float, default=None, metavar="S", help="moment in seconds")
    p.add_argument("--png", required=True, metavar="FILE", help="picture to write")
    p.add_argument("--view", default="iso", choices=("iso", "top", "front"))
    p.add_argument("--size", default="1200x900", metavar="WxH")
    p.add_argument("--cad", default=None, metavar="STL", help="draw the CAD part translucent")
    p.set_defaults(handler=cmd_render)
    p = sub.add_parser("view", help="interactive replay: the deposit grows with time; the seed's keys")
    _add_gcode_options(p)
    _add_bead_options(p, plate_and_standoff=False)
    p.add_argument("--cad", default=None, metavar="STL", help="draw the CAD part translucent")
    p.add_argument("--nozzle", default=None,
                   help="nozzle STL (tip at the origin, axis +Z) or cone:tip=D,top=D,length=L; marks its collisions")
    p.add_argument("--fixture", action="append", default=[], metavar="STL[@dx,dy,dz]", help="fixture (needs --nozzle)")
    p.add_argument("--standoff", type=float, default=None, metavar="MM",
                   help=f"nozzle tip above the path point (default {STANDOFF_MM:g} with --nozzle, else 0)")
    p.add_argument("--color", default="time", choices=("time", "layer", "feed", "deposit"))
    p.set_defaults(handler=cmd_view)
    p = sub.add_parser("scene", help="the seed's interactive collision scene from a TOML or INI configuration")
    p.add_argument("config", help="scene file (.toml, or INI like the seed's scene.ini)")
    p.add_argument("--json", action="store_true", help="print the final positions as one JSON object")
    p.set_defaults(handler=cmd_scene)
    p = sub.add_parser("study", help="overlap-ratio studies and parameter sweeps (local processes or a dask cluster)")
    studies = p.add_subparsers(dest="study", required=True, metavar="STUDY")
    q = studies.add_parser("overlap", help="patches of parallel beads over spacing and layer step")
    _add_study_overlap(q)
    q = studies.add_parser("sweep", help="any simulate/compare option swept over a user's toolpath")
    _add_gcode_options(q)
    _add_bead_options(q)
    _add_study_sweep(q)
    p = sub.add_parser("demo", help="the whole pipeline on the shipped samples (deposit, compare, collide) "
                                    "in one HTML report")
    p.add_argument("--out", default="out/demo", metavar="DIR", help="folder for everything it writes (default out/demo)")
    p.add_argument("--json", action="store_true", help="print one JSON object on stdout")
    p.set_defaults(handler=cmd_demo)
    p = sub.add_parser("collide", help="check the nozzle against the growing part, fixtures and the plate along the path")
    _add_gcode_options(p)
    _add_bead_options(p, plate_and_standoff=False)
    _add_nozzle_options(p, required=True)
    p.set_defaults(handler=cmd_collide)
    p = sub.add_parser("report", help="one self-contained HTML page: toolpath, deposit, CAD comparison, pores, "
                                      "collisions, 3-D replay")
    _add_gcode_options(p)
    _add_bead_options(p, plate_and_standoff=False)
    p.add_argument("--cad", default=None, metavar="STL", help="compare with this CAD part (workpiece coordinates: machine coordinates on a 3-axis machine)")
    _add_cad_offset(p)
    _add_nozzle_options(p, required=False)
    p.add_argument("--out", required=True, metavar="DIR", help="folder for the page, its PNGs and the data files")
    _add_scheduler(p, "sweep the part's and the comparison's slabs")
    _add_thermal_options(p, stage=True)
    p.set_defaults(handler=cmd_report)
    p = sub.add_parser("check", help="pass or fail against the limits of a cell file (CI): exit 0 all met, "
                                     "3 any failed", description=CHECK_DESCRIPTION,
                       formatter_class=argparse.RawDescriptionHelpFormatter)
    _add_gcode_options(p)
    _add_bead_options(p, plate_and_standoff=False)
    p.add_argument("--cad", default=None, metavar="STL", help="the CAD part, for the comparison's limits")
    _add_cad_offset(p)
    _add_nozzle_options(p, required=False)
    p.add_argument("--limits", required=True, metavar="LIMITS.toml",
                   help="cell file: a [limits] table and, optionally, the cell's options (data/cells/demo_cell.toml)")
    p.add_argument("--junit", default=None, metavar="FILE.xml", help="write a JUnit XML report (one test per limit)")
    _add_scheduler(p, "sweep the part's and the comparison's slabs")
    # every option the cell file may set defaults to None, so that one given here overrides it
    cell_options = {a.dest: (a.default, a.type, a.choices, a.nargs == 0 and a.const is True) for a in p._actions
                    if a.dest not in ("help", "gcode", "limits", "junit", "json", "scheduler")}
    p.set_defaults(handler=cmd_check, cell_options=cell_options, **{dest: None for dest in cell_options})
    p = sub.add_parser("thermal", help="thermal history of the part as it is built: peak temperature, interlayer "
                                       "temperature, melt pool, G and R (docs/THERMAL.md)")
    _add_gcode_options(p)
    _add_bead_options(p)
    _add_thermal_options(p)
    p.add_argument("--out", default=None, metavar="DIR",
                   help="write the cell fields (.vdb, .vti), per-layer, melt-pool, probe and energy CSVs, path exports")
    p.set_defaults(handler=cmd_thermal)
    p = sub.add_parser("diff", help="what a program change does to the part: volume added and removed, the lines "
                                    "responsible, void and overbuild against the CAD")
    _add_gcode_options(p)
    p.add_argument("new", help="the changed G-code file (the first is the old one)")
    _add_bead_options(p)
    p.add_argument("--cad", default=None, metavar="STL", help="compare both with this CAD part")
    _add_cad_offset(p)
    p.add_argument("--out", default=None, metavar="DIR",
                   help="write the diff map (.vti or .vtm), the new surface's change (.vtp), a picture and the JSON")
    _add_scheduler(p, "sweep the parts' slabs")
    p.set_defaults(handler=cmd_diff)
    return parser


def _add_scheduler(p: argparse.ArgumentParser, what: str) -> None:
    p.add_argument("--scheduler", type=_scheduler, default=None, metavar="ADDR",
                   help=f"{what} on a dask.distributed cluster (tcp://host:port); the result is the local one")


def _add_cad_offset(p: argparse.ArgumentParser) -> None:
    p.add_argument("--cad-offset", type=_offset, default=(0.0, 0.0, 0.0), metavar="X,Y,Z",
                   help="move the CAD by this offset (mm) to align it with the toolpath")


def _add_nozzle_options(p: argparse.ArgumentParser, required: bool) -> None:
    p.add_argument("--nozzle", required=required,
                   help="nozzle STL (tip at the origin, axis +Z) or cone:tip=D,top=D,length=L")
    p.add_argument("--standoff", type=float, default=STANDOFF_MM, metavar="MM",
                   help=f"tip height above the programmed bead bottom (default {STANDOFF_MM:g} mm, the seed's)")
    p.add_argument("--fixture", action="append", default=[], metavar="STL[@dx,dy,dz]",
                   help="fixture mesh, optionally moved; repeatable")
    p.add_argument("--plate", type=float, default=None, metavar="Z",
                   help="build plate top at this Z (also the substrate the flow model lands on)")
    p.add_argument("--clearance", type=float, default=CLEARANCE_MM, metavar="MM",
                   help=f"report near misses closer than this (default {CLEARANCE_MM:g} mm)")


def _stream_closed(stream) -> bool:
    """Whether ``stream`` is a pipe whose reader has gone (``dmdvox info F | head -1``): Linux
    reports POLLERR on the write end of a pipe with no reader."""
    import select

    try:
        poller = select.poll()
        poller.register(stream.fileno(), select.POLLOUT)
        return any(events & select.POLLERR for _, events in poller.poll(0))
    except (AttributeError, ValueError, OSError):
        return False


def _say(text: str, stream) -> None:
    try:
        print(text, file=stream, flush=True)
    except (BrokenPipeError, ValueError):
        pass


def _quiet_stdout() -> None:
    """Point stdout at /dev/null so that Python's final flush of what is still buffered for a
    reader that went away does not complain."""
    try:
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
    except (AttributeError, ValueError, OSError):
        pass


# A value that starts with '-' and is a number or a comma list of them (--cad-offset -101.6,-101.6,0,
# --start -5,0,2, --max-memory -inf): argparse takes anything but a plain negative number for an option.
_NEGATIVE_VALUE = re.compile(r"^-(\d|\.\d|inf|nan)", re.IGNORECASE)


def _option_kinds(parser: argparse.ArgumentParser, valued: set, flags: set) -> None:
    for action in parser._actions:
        if isinstance(action, argparse._SubParsersAction):
            for sub in action.choices.values():
                _option_kinds(sub, valued, flags)
        elif action.option_strings:
            (valued if action.nargs is None else flags).update(action.option_strings)


def join_negative_values(parser: argparse.ArgumentParser, argv: list[str]) -> list[str]:
    """``argv`` with every option that takes one value and is followed by a negative number or
    tuple written ``--option=VALUE``, which argparse reads whatever the value looks like."""
    valued, flags = set(), set()
    _option_kinds(parser, valued, flags)
    valued -= flags  # a name that is a flag in some command is left alone
    out = []
    tokens = iter(argv)
    for token in tokens:
        if token == "--":
            out += [token, *tokens]
            break
        if token in valued:
            value = next(tokens, None)
            if value is not None and _NEGATIVE_VALUE.match(value):
                out.append(f"{token}={value}")
                continue
            out.append(token)
            if value is not None:
                out.append(value)
            continue
        out.append(token)
    return out


# The library's errors name its parameters (``DmdvoxError.parameters``); the command line says
# them as its options. One table: a parameter missing here would reach the user in Python's words
# (tests/test_errors.py checks that every parameter the library names is here, and every option
# is the parser's).
OPTION_OF_PARAMETER = {
    "voxel": "--voxel", "until": "--until", "max_memory_gib": "--max-memory",
    "profile": "--profile", "width": "--width", "height": "--height", "exponent": "--exponent", "model": "--model",
    "nozzle": "--nozzle", "fixtures": "--fixture", "plate": "--plate", "standoff": "--standoff",
    "clearance": "--clearance",
    "plate_z": "--plate", "max_drop_mm": "--max-drop", "standoff_mm": "--standoff", "fusion_depth_mm": "--fusion-depth",
    "bridge_span_mm": "--bridge-span",
    "filament_diameter_mm": "--filament-diameter", "powder_rate_g_min": "--powder-rate", "density_g_cm3": "--density",
    "catchment": "--catchment", "wire_diameter_mm": "--wire-diameter", "wire_feed_mm_min": "--wire-feed",
    "accel_mm_s2": "--accel", "junction_deviation_mm": "--junction-deviation",
    "square_corner_velocity_mm_s": "--square-corner-velocity", "travel_accel_mm_s2": "--travel-accel",
    "retract_accel_mm_s2": "--retract-accel", "accel_to_decel_mm_s2": "--accel-to-decel",
    "max_feed_mm_s": "--max-feed", "max_axis_accel_mm_s2": "--max-axis-accel", "jerk_mm_s": "--jerk",
    "jerk_rule": "--jerk-rule",
}


class Terminated(KeyboardInterrupt):
    """SIGTERM, taken as Ctrl-C is: the atomic writers remove their temporary files."""


def _terminate(signum, frame):
    raise Terminated()


def main(argv: list[str] | None = None) -> int:
    import contextlib
    import signal

    from .io.atomic import output_run

    parser = build_parser()
    args = parser.parse_args(join_negative_values(parser, list(sys.argv[1:] if argv is None else argv)))
    run = contextlib.ExitStack()
    want_json = getattr(args, "json", False)
    said = run.enter_context(checks.collect_warnings())  # this command's warnings, for --json
    run.enter_context(checks.warnings_on_stderr())
    run.enter_context(progress.to_stderr())  # the stage lines: the library logs them, the command shows them
    previous_term = signal.signal(signal.SIGTERM, _terminate) if _main_thread() else None
    try:
        checks.check_output_names(args)
        if args.command != "info":  # every other command reaches OpenVDB (grids, surfaces, level sets)
            checks.require_openvdb()
        progress.compile_notice(args.command)
        with output_run(getattr(args, "out", None)):
            result = args.handler(args)
    except DmdvoxError as exc:
        message = exc.worded(OPTION_OF_PARAMETER)
        _say(f"dmdvox: error: {message}", sys.stderr)
        if want_json:
            _say(json.dumps({"error": message, "exit_code": exc.exit_code}), sys.stdout)
        return exc.exit_code
    except Terminated:
        _say("dmdvox: terminated", sys.stderr)
        return 143
    except KeyboardInterrupt:
        _say("dmdvox: interrupted", sys.stderr)
        return 130
    except BrokenPipeError as exc:
        if _stream_closed(sys.stdout) or _stream_closed(sys.stderr):
            # The reader (e.g. `head`) went away: not an error of ours, and nothing left to say.
            _quiet_stdout()
            return 0
        return _internal_error(exc, want_json)
    except Exception as exc:  # an internal error: keep the traceback for the bug report
        return _internal_error(exc, want_json)
    finally:
        if previous_term is not None:
            signal.signal(signal.SIGTERM, previous_term)
        run.close()
    checks.merge_into(result, said)
    try:
        if want_json:
            print(json.dumps(result, allow_nan=False))
        sys.stdout.flush()
    except BrokenPipeError:
        _quiet_stdout()
    except (TypeError, ValueError) as exc:  # a result that is not JSON: ours to fix
        return _internal_error(exc, want_json)
    if args.command == "check" and not result["passed"]:
        from .limits import LIMIT_FAILED

        return LIMIT_FAILED
    return 0


def _main_thread() -> bool:
    import threading

    return threading.current_thread() is threading.main_thread()


def _internal_error(exc: BaseException, want_json: bool) -> int:
    try:
        traceback.print_exception(exc, file=sys.stderr)
    except (BrokenPipeError, ValueError):
        pass
    if want_json:
        _say(json.dumps({"error": f"internal error: {exc}", "exit_code": 1}), sys.stdout)
    return 1


if __name__ == "__main__":
    sys.exit(main())
