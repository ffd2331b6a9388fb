"""`dmdvox check`: pass or fail a program against the limits of a cell, for CI.

A cell file (TOML, ``data/cells/demo_cell.toml``) holds a ``[limits]`` table and, optionally, the
options that describe the cell, so one file replaces a long command line:

* ``[limits]``: keys are the JSON names they bound (:data:`LIMITS`); each is a maximum unless its
  name says ``min``. ``deviation_mm.p95`` may be written as a dotted key, as the JSON nests it;
* ``[part]``: ``cad`` (STL), ``cad_offset`` ([x, y, z] mm);
* ``[process]``: the bead, material, motion and landing options of ``simulate`` by their long
  names (``width``, ``height``, ``profile``, ``model``, ``voxel``, ``accel``, ...), ``dialect`` and
  ``start`` ([x, y, z] mm, the reader's ``--start``);
* ``[machine]``: ``file`` (a machine TOML, docs/MACHINES.md);
* ``[nozzle]``: ``spec`` (an STL or ``cone:tip=D,top=D,length=L``), ``fixtures`` (a list of
  ``STL[@dx,dy,dz]``), ``plate``, ``standoff``, ``clearance``.
* ``[thermal]``: the heat options of ``dmdvox thermal`` by their long names (``material``,
  ``laser_power``, ``absorptivity``, ``thermal_voxel``, ...), for the thermal limits.

Paths in the file are relative to the file's folder. The command line overrides the file.

:func:`check` runs what the limits need, once: the deposit (with the CAD comparison when a limit
needs it), the nozzle along the path on that same deposit, and judges each limit with where it
fails: the layer of the worst void or overbuild (the comparison's per-layer table), the layers
of the pores, the colliding lines, the lines closer than the clearance, the layers whose drift
exceeds, the lines whose material was lost.
"""

from __future__ import annotations

import json
import math
import tomllib
from dataclasses import dataclass, field, replace
from pathlib import Path
from xml.etree import ElementTree

import numpy as np

from . import progress
from .collision.bodies import load_fixtures
from .collision.run import NozzleSettings, collide_part, prepare_collide
from .comparison.compare import CompareRequest, Comparison, compare
from .deposit.simulate import SimulateRequest, Simulation, describe, simulate
from .errors import DmdvoxError, InputFileError
from .process.plan import ProcessPlan
from .summary import SummaryResult

# exit code of a check whose limits are not all met (0 all met; 1 and 2 as every command)
LIMIT_FAILED = 3


@dataclass(frozen=True)
class Limit:
    """One limit the ``[limits]`` table may set: the run that measures it (``compare``,
    ``deposit``: the comparison when a CAD part is given, else the deposit alone; ``collide``;
    ``flow``: the flow model's growth), the option it needs, and what it bounds."""

    name: str
    run: str
    needs: str | None
    what: str

    @property
    def minimum(self) -> bool:
        return "min" in self.name.split("_")


LIMITS = {limit.name: limit for limit in (
    Limit("void_percent", "compare", "--cad", "void (CAD not filled) in % of the CAD volume"),
    Limit("overbuild_percent", "compare", "--cad", "overbuild (material outside the CAD) in % of the CAD volume"),
    Limit("deviation_mm.p95", "compare", "--cad", "95th percentile of |surface deviation| from the CAD (mm)"),
    Limit("max_underfill_mm", "compare", "--cad", "deepest void below the CAD surface (mm)"),
    Limit("max_overbuild_mm", "compare", "--cad", "thickest overbuild beyond the CAD surface (mm)"),
    Limit("porosity_percent", "deposit", None, "internal void in % of the CAD volume (of the deposit without --cad)"),
    Limit("max_pore_diameter_mm", "deposit", None, "largest pore's equivalent diameter (mm)"),
    Limit("collisions", "collide", "--nozzle", "lines where the nozzle hits the part, a fixture or the plate"),
    Limit("min_clearance_mm", "collide", "--nozzle", "closest approach of the nozzle to an obstacle (mm)"),
    Limit("max_drift_mm", "flow", None, "largest |drift| of a layer's built top from the program (mm)"),
    Limit("lost_volume_mm3", "flow", None, "material that never reached the part (mm^3)"),
    Limit("max_interlayer_temperature_C", "thermal", "[thermal]", "hottest interlayer temperature (C)"),
    Limit("max_peak_temperature_C", "thermal", "[thermal]", "highest temperature a cell of the part reached (C)"),
    Limit("max_melt_pool_width_mm", "thermal", "[thermal]", "widest melt pool along the path (mm)"),
)}

# the cell file's option tables: key -> the command line's destination (its long option)
PROCESS_KEYS = ("profile", "width", "height", "exponent", "voxel", "model", "max_memory", "dialect", "laser_on",
                "laser_off", "strict", "start", "filament_diameter", "powder_rate", "density", "catchment", "wire_diameter",
                "wire_feed", "accel", "junction_deviation", "square_corner_velocity", "max_drop", "fusion_depth",
                "catchment_profile", "bridge_span")
SECTIONS = {
    "limits": None,
    "part": {"cad": "cad", "cad_offset": "cad_offset"},
    "process": {key: key for key in PROCESS_KEYS},
    "machine": {"file": "machine"},
    "nozzle": {"spec": "nozzle", "fixtures": "fixture", "plate": "plate", "standoff": "standoff",
               "clearance": "clearance"},
}
_PATHS = {"cad", "machine"}
# what each option key holds in the file (checked in one place, :func:`_typed`); every other
# option is a number
_TEXT_KEYS = {"profile", "model", "dialect", "laser_on", "laser_off", "catchment_profile", "cad", "machine",
              "nozzle"}
_FLAG_KEYS = {"strict"}


@dataclass(frozen=True)
class Cell:
    """A cell file read: its ``limits`` (name -> value) and its ``options`` (the command line's
    destination -> value, paths made absolute)."""

    path: str
    limits: dict[str, float]
    options: dict = field(default_factory=dict)
    thermal: dict | None = None  # the [thermal] table: the heat options (dmdvox.thermal.run.OPTION_KEYS)


def _flatten(table: dict, prefix: str = "") -> dict:
    out = {}
    for key, value in table.items():
        name = f"{prefix}{key}"
        if isinstance(value, dict):
            out.update(_flatten(value, f"{name}."))
        else:
            out[name] = value
    return out


def check_limits(limits: dict, source: str) -> dict[str, float]:
    """``limits`` (nested as TOML gives dotted keys, or flat) as name -> float; an unknown name
    or a value that is not a number is refused, naming it and the known ones."""
    if not isinstance(limits, dict):
        raise DmdvoxError(f"{source}: the limits must be a table of name = value, got {limits!r}")
    out = {}
    for name, value in _flatten(limits).items():
        if name not in LIMITS:
            raise DmdvoxError(f"{source}: unknown limit {name!r}; known limits: {', '.join(LIMITS)}")
        if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
            raise DmdvoxError(f"{source}: limit {name} must be a number, got {value!r}")
        out[name] = float(value)
    if not out:
        raise DmdvoxError(f"{source}: no limit set; give a [limits] table with some of: {', '.join(LIMITS)}")
    return out


def _resolve(folder: Path, text: str) -> str:
    """A path of the cell file, relative to its folder (``cone:`` specs and ``none`` kept)."""
    if text.startswith("cone:") or text == "none":
        return text
    path, at, move = text.partition("@")
    return str((folder / path).resolve()) + at + move


def _typed(source: str, section: str, key: str, dest: str, value):
    """``value`` of ``[section] key`` if it has the type the key takes, else refused naming it:
    text, true/false, a number, the fixtures (a text or a list of texts), ``cad_offset`` and
    ``start`` ([x, y, z])."""
    def refuse(what: str):
        raise DmdvoxError(f"{source}: [{section}] {key} must be {what}, got {value!r}")

    if dest in _TEXT_KEYS:
        if not isinstance(value, str):
            refuse("a string")
    elif dest in _FLAG_KEYS:
        if not isinstance(value, bool):
            refuse("true or false")
    elif dest == "fixture":
        value = value if isinstance(value, list) else [value]
        if not all(isinstance(v, str) for v in value):
            refuse("a string or a list of strings (STL[@dx,dy,dz])")
    elif dest in ("cad_offset", "start"):
        if not (isinstance(value, list) and len(value) == 3 and all(_is_number(v) for v in value)):
            refuse("[x, y, z] in mm")
        value = tuple(float(v) for v in value)
    elif not _is_number(value):
        refuse("a finite number")
    return value


def _is_number(value) -> bool:
    return isinstance(value, (int, float)) and not isinstance(value, bool) and math.isfinite(value)


def read_cell(path: str | Path) -> Cell:
    """Read a cell file (module docstring)."""
    path = Path(path)
    try:
        data = tomllib.loads(path.read_text())
    except FileNotFoundError:
        raise InputFileError(f"{path}: no such limits file") from None
    except (OSError, UnicodeDecodeError) as exc:
        raise InputFileError(f"{path}: cannot read it ({exc})") from None
    except tomllib.TOMLDecodeError as exc:
        raise InputFileError(f"{path}: not valid TOML ({exc})") from None
    for section in data:
        if section not in SECTIONS and section != "thermal":
            raise DmdvoxError(f"{path}: unknown table [{section}]; known: {', '.join(f'[{s}]' for s in SECTIONS)}")
        if not isinstance(data[section], dict):
            raise DmdvoxError(f"{path}: {section} must be a table ([{section}] and its keys below), "
                              f"got {data[section]!r}")
    limits = check_limits(data.get("limits", {}), str(path))
    folder = path.resolve().parent
    options = {}
    for section, keys in SECTIONS.items():
        if keys is None:
            continue
        for key, value in data.get(section, {}).items():
            dest = keys.get(key.replace("-", "_"))
            if dest is None:
                raise DmdvoxError(f"{path}: unknown key {key!r} in [{section}]; known: {', '.join(keys)}")
            value = _typed(str(path), section, key, dest, value)
            if dest in _PATHS or dest == "nozzle":
                value = _resolve(folder, value)
            elif dest == "fixture":
                value = [_resolve(folder, v) for v in value]
            options[dest] = value
    thermal = None
    if "thermal" in data:
        from .thermal.run import OPTION_KEYS

        thermal = {key.replace("-", "_"): value for key, value in data["thermal"].items()}
        for key in thermal:
            if key not in OPTION_KEYS:
                raise DmdvoxError(f"{path}: unknown key {key!r} in [thermal]; known: {', '.join(OPTION_KEYS)}")
        if str(thermal.get("material", "")).lower().endswith(".toml"):
            thermal["material"] = _resolve(folder, str(thermal["material"]))
    return Cell(str(path), limits, options, thermal)


@dataclass(frozen=True)
class CheckRequest:
    """What to check: the plan against ``limits`` (name -> value, :data:`LIMITS`), with the CAD
    STL ``cad`` (moved by ``cad_offset``) and the ``nozzle`` when the limits need them; the
    deposit swept at ``voxel`` (default: the plan's), within ``max_memory`` bytes, its slabs on
    the dask cluster at ``scheduler``; ``strict`` refuses rotary words the machine does not
    model; ``junit``: write a JUnit XML report there."""

    plan: ProcessPlan
    limits: dict
    cad: str | Path | None = None
    cad_offset: tuple[float, float, float] = (0.0, 0.0, 0.0)
    nozzle: NozzleSettings | None = None
    voxel: float | None = None
    max_memory: int | None = None
    scheduler: str | None = None
    strict: bool = False
    junit: str | Path | None = None
    thermal: dict | None = None  # the heat options, for the thermal limits


@dataclass(frozen=True, eq=False)
class CheckResult(SummaryResult):
    """A check's verdicts: ``summary`` (the JSON ``--json`` prints, also readable as
    ``result[key]``), and the runs it made (``simulation``, ``comparison``, ``collisions``; None
    when no limit needed them; ``collisions`` as ``dmdvox collide --json`` prints it)."""

    summary: dict
    simulation: Simulation
    comparison: Comparison | None = None
    collisions: dict | None = None  # the collision check's JSON

    @property
    def passed(self) -> bool:
        return self.summary["passed"]

    @property
    def exit_code(self) -> int:
        return 0 if self.passed else LIMIT_FAILED

    def text(self) -> str:
        s = self.summary
        out = [f"{s['gcode']}: {'PASS' if s['passed'] else 'FAIL'} ({s['failed']} of {len(s['limits'])} limits "
               f"failed; voxel {s['voxel_mm']:g} mm)"]
        for item in s["limits"]:
            out.append(f"  {item['verdict'].upper():<4s}  {item['message']}")
        out += [f"  wrote {path}" for path in s["outputs"]]
        return "\n".join(out)

    def junit_xml(self) -> str:
        """One testsuite, one testcase per limit, a ``failure`` with the message where it fails."""
        s = self.summary
        suites = ElementTree.Element("testsuites", name="dmdvox check", tests=str(len(s["limits"])),
                                     failures=str(s["failed"]))
        suite = ElementTree.SubElement(suites, "testsuite", name=f"dmdvox check {Path(s['gcode']).name}",
                                       tests=str(len(s["limits"])), failures=str(s["failed"]), errors="0")
        for item in s["limits"]:
            case = ElementTree.SubElement(suite, "testcase", classname=f"dmdvox.check.{Path(s['gcode']).stem}",
                                          name=item["name"])
            if item["verdict"] == "fail":
                failure = ElementTree.SubElement(case, "failure", message=item["message"], type="limit")
                failure.text = json.dumps({k: item[k] for k in ("value", "limit", "lines", "layers")})
        return ElementTree.tostring(suites, encoding="unicode", xml_declaration=True) + "\n"


def junit_error_xml(gcode: str, message: str, kind: str) -> str:
    """The JUnit report of a check that could not run (bad input, a refused request): one test
    case with an ``error``, so that CI shows why instead of a missing report."""
    name = Path(str(gcode)).name
    suites = ElementTree.Element("testsuites", name="dmdvox check", tests="1", failures="0", errors="1")
    suite = ElementTree.SubElement(suites, "testsuite", name=f"dmdvox check {name}", tests="1", failures="0",
                                   errors="1")
    case = ElementTree.SubElement(suite, "testcase", classname=f"dmdvox.check.{Path(name).stem}", name="input")
    error = ElementTree.SubElement(case, "error", message=message, type=kind)
    error.text = message
    return ElementTree.tostring(suites, encoding="unicode", xml_declaration=True) + "\n"


def _layer_of_z(plan: ProcessPlan, z: float) -> int:
    bottoms = plan.layer_bottoms()
    return int(max(0, np.searchsorted(bottoms, z, side="right") - 1)) if bottoms.size else 0


def _worst_layer(layers: list[dict], key: str) -> list[int]:
    worst = max(layers, key=lambda row: row[key], default=None)
    return [worst["layer"]] if worst is not None and worst[key] > 0 else []


def _measure(name: str, limit: float, plan: ProcessPlan, deposit: dict, comparison: dict | None,
             collisions: dict | None, thermal: dict | None = None) -> tuple[float | None, list[int], list[int]]:
    """(value, lines, layers where it fails) of limit ``name`` from the runs' JSON."""
    if name in ("max_interlayer_temperature_C", "max_peak_temperature_C"):
        key = "interlayer_C" if name == "max_interlayer_temperature_C" else "peak_C"
        hot = [row["layer"] for row in thermal["layers"] if row[key] is not None and row[key] > limit]
        return thermal[name], [], hot
    if name == "max_melt_pool_width_mm":
        return thermal[name], sorted({p["line"] for p in thermal["pools"] if p["width_mm"] > limit}), []
    if name in ("void_percent", "max_underfill_mm"):
        return comparison[name], [], _worst_layer(comparison["layers"], "void_mm3")
    if name in ("overbuild_percent", "max_overbuild_mm"):
        return comparison[name], [], _worst_layer(comparison["layers"], "overbuild_mm3")
    if name == "deviation_mm.p95":
        layers = comparison["layers"]
        worst = max(layers, key=lambda row: row["void_mm3"] + row["overbuild_mm3"], default=None)
        return comparison["deviation_mm"]["p95"], [], [] if worst is None else [worst["layer"]]
    if name in ("porosity_percent", "max_pore_diameter_mm"):
        source = comparison if comparison is not None else deposit
        pores = [p for p in source["pores"] if p.get("inside_cad", True)]
        if name == "porosity_percent":
            failing = pores
            value = source["porosity_percent"]
        else:
            failing = [p for p in pores if p["equivalent_diameter_mm"] > limit]
            value = max((p["equivalent_diameter_mm"] for p in pores), default=0.0)
        return value, [], sorted({_layer_of_z(plan, p["centroid_mm"][2]) for p in failing})
    if name == "collisions":
        lines = sorted({c["line"] for c in collisions["collisions"]})
        return len(lines), lines, []
    if name == "min_clearance_mm":
        close = [c["line"] for c in collisions["collisions"]]
        close += [m["line"] for m in collisions["near_misses"] if m["distance_mm"] < limit]
        return collisions["min_clearance_mm"], sorted(set(close)), []
    if name == "max_drift_mm":
        layers = deposit.get("growth_layers", deposit.get("layers", []))
        value = max((abs(row["drift_mm"]) for row in layers), default=0.0)
        return value, [], [row["layer"] for row in layers if abs(row["drift_mm"]) > limit]
    if name == "lost_volume_mm3":
        return deposit["lost_volume_mm3"], list(deposit.get("lost_lines", [])), []
    raise AssertionError(name)


def _verdict(limit: Limit, value, bound: float, reach: float | None) -> tuple[str, str]:
    """("pass" or "fail", the message)."""
    sign = ">=" if limit.minimum else "<="
    if value is None and limit.name == "min_clearance_mm":
        return "pass", f"{limit.name} > {reach:g} (nothing within reach) {sign} {bound:g}: {limit.what}"
    if value is None or not math.isfinite(value):
        return "fail", f"{limit.name} could not be measured (limit {bound:g}): {limit.what}"
    ok = value >= bound if limit.minimum else value <= bound
    return ("pass" if ok else "fail"), f"{limit.name} = {value:.6g} {sign if ok else ('<' if limit.minimum else '>')} " \
                                      f"{bound:g}: {limit.what}"


def check(request: CheckRequest, *, simulation=None, comparison=None) -> CheckResult:
    """Run what the limits need and judge each (module docstring). ``simulation`` and
    ``comparison`` are the request's deposit and CAD comparison computed before (a
    :class:`dmdvox.Build`'s), used in place of running them again."""
    plan = request.plan
    limits = {LIMITS[name]: value for name, value in check_limits(request.limits, "limits").items()}
    runs = {limit.run for limit in limits}
    for limit in limits:
        if limit.needs == "--cad" and request.cad is None:
            raise DmdvoxError(f"limit {limit.name} needs the CAD part: give --cad STL (or [part] cad in the cell file)")
        if limit.needs == "--nozzle" and request.nozzle is None:
            raise DmdvoxError(f"limit {limit.name} needs the nozzle: give --nozzle (or [nozzle] spec in the cell file)")
        if limit.needs == "[thermal]" and not (request.thermal or {}).get("material"):
            raise DmdvoxError(f"limit {limit.name} needs the heat model: give a [thermal] table in the cell file "
                              "with material = \"316L\" (and laser_power, absorptivity, ...; docs/THERMAL.md)")
    if "flow" in runs and plan.model != "flow":
        names = ", ".join(limit.name for limit in limits if limit.run == "flow")
        raise DmdvoxError(f"limit {names} measures the flow model's growth, but this run uses the {plan.model} model: "
                          "give --model flow with the material (E words, --powder-rate or --wire-feed)")
    if not plan.toolpath.deposit.any():
        raise DmdvoxError(f"{plan.toolpath.source}: the program deposits nothing; check --dialect or --laser-on")
    voxel = plan.resolve_voxel(request.voxel)
    nozzle = None
    bodies: dict[str, int] = {}
    fixtures = []
    if "collide" in runs:
        nozzle = request.nozzle
        clearance = limits.get(LIMITS["min_clearance_mm"])
        if clearance is not None:
            # near misses are listed up to the clearance: the limit's lines are among them
            nozzle = replace(nozzle, clearance=max(nozzle.clearance, clearance))
        fixtures = load_fixtures(list(nozzle.fixtures))
        bodies = prepare_collide(plan.toolpath, nozzle.nozzle, fixtures, voxel, nozzle.clearance, request.max_memory,
                                 strict=request.strict)
    if "compare" in runs or (request.cad is not None and "deposit" in runs):
        if comparison is None:
            comparison = compare(CompareRequest(plan, request.cad, cad_offset=tuple(request.cad_offset), voxel=voxel,
                                                max_memory=request.max_memory, scheduler=request.scheduler),
                                 also_holds=bodies, simulation=simulation)
        simulation = comparison.simulation
    else:
        comparison = None
        if simulation is None:
            progress.stage("deposit", describe(plan))
            simulation = simulate(SimulateRequest(plan, voxel=voxel, max_memory=request.max_memory,
                                                  scheduler=request.scheduler), also_holds=bodies)
    collisions = None
    reach = None
    if nozzle is not None:
        path_check, _ = collide_part(plan.toolpath, simulation.grid, nozzle, fixtures, voxel)
        collisions = path_check.as_dict()
        reach = path_check.reach_mm
    thermal = None
    if "thermal" in runs:
        from .thermal.run import thermal_history, thermal_request

        progress.stage("thermal", str(request.thermal["material"]))
        heat = thermal_history(thermal_request(plan, simulation.grid, request.thermal, simulation["plate_z_mm"],
                                               request.max_memory))
        thermal = {**heat.summary(), "pools": heat.pools}
    items = []
    compare_json = comparison.to_json() if comparison is not None else None
    deposit_json = simulation.to_json()
    for limit, bound in limits.items():
        value, lines, layers = _measure(limit.name, bound, plan, deposit_json, compare_json, collisions, thermal)
        verdict, message = _verdict(limit, value, bound, reach)
        failing = verdict == "fail"
        items.append({"name": limit.name, "value": None if value is None or not math.isfinite(value) else value,
                      "limit": bound, "kind": "min" if limit.minimum else "max", "verdict": verdict,
                      "lines": lines if failing else [], "layers": layers if failing else [], "message": message})
    failed = sum(item["verdict"] == "fail" for item in items)
    summary = {
        "gcode": str(plan.toolpath.source),
        "passed": failed == 0,
        "failed": failed,
        "limits": items,
        "runs": ["compare" if comparison is not None else "simulate"] + (["collide"] if collisions is not None else [])
                + (["thermal"] if thermal is not None else []),
        "voxel_mm": voxel,
        "model": plan.model,
        "warnings": list((comparison or simulation).summary["warnings"]),
        "outputs": [],
    }
    result = CheckResult(summary, simulation, comparison, collisions)
    if request.junit is not None:
        from .io.atomic import write_text

        summary["outputs"].append(str(write_text(Path(request.junit), result.junit_xml())))
    return result


__all__ = ["Cell", "CheckRequest", "CheckResult", "LIMITS", "LIMIT_FAILED", "check", "junit_error_xml", "read_cell"]
