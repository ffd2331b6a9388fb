"""`dmdvox study sweep`: one ``simulate`` (or, with a CAD part, ``compare``) run per point of
a grid of option values, each run an independent task (local processes or dask).

Each task reads the G-code itself, so on a cluster the file (and the CAD part) must be at the
same path on every worker (a shared or copied folder). Rows hold the swept values and the
run's scalar results (lists such as the pores are left out; run the point alone for them).
Timings are left out too: they vary run to run, and rows must not.
"""

from __future__ import annotations

import itertools
from dataclasses import dataclass, replace

from ..errors import DmdvoxError
from ..process.plan import ProcessSettings
from .ranges import parse_range

# Swept names and where each lives in a run's settings (``ProcessSettings`` and its parts)
SETTINGS_FIELDS = {
    "width": ("width",), "height": ("height",), "exponent": ("exponent",), "profile": ("profile",),
    "model": ("model",),
    "accel": ("motion", "accel_mm_s2"), "junction_deviation": ("motion", "junction_deviation_mm"),
    "filament_diameter": ("flow", "filament_diameter_mm"), "powder_rate": ("flow", "powder_rate_g_min"),
    "density": ("flow", "density_g_cm3"), "catchment": ("flow", "catchment"),
    "wire_diameter": ("flow", "wire_diameter_mm"), "wire_feed": ("flow", "wire_feed_mm_min"),
    "max_drop": ("landing", "max_drop_mm"), "fusion_depth": ("landing", "fusion_depth_mm"),
    "standoff": ("landing", "standoff_mm"),
}
RUN_FIELDS = ("voxel", "until")
TEXT = ("profile", "model")
SWEEPABLE = tuple(SETTINGS_FIELDS) + RUN_FIELDS


@dataclass(frozen=True)
class SweepCase:
    """Everything one run needs (plain values and frozen settings: it is pickled to the workers)."""

    gcode: str
    dialect: str
    strict: bool
    laser_on: str | None
    laser_off: str | None
    machine: str | None
    settings: ProcessSettings
    voxel: float | None
    until: float | None
    cad: str | None
    cad_offset: tuple[float, float, float]
    max_memory: int | None
    start: tuple[float, float, float] | None = None  # the reader's --start

    def value(self, name: str):
        """The case's value of a swept name."""
        if name in RUN_FIELDS:
            return getattr(self, name)
        path = SETTINGS_FIELDS[name]
        target = self.settings
        for part in path:
            target = getattr(target, part)
        return target

    def with_value(self, name: str, value) -> "SweepCase":
        if name in RUN_FIELDS:
            return replace(self, **{name: value})
        path = SETTINGS_FIELDS[name]
        if len(path) == 1:
            return replace(self, settings=replace(self.settings, **{path[0]: value}))
        part = getattr(self.settings, path[0])
        return replace(self, settings=replace(self.settings, **{path[0]: replace(part, **{path[1]: value})}))

    def plan(self):
        from ..process.plan import plan_process
        from ..toolpath import read_gcode

        tp = read_gcode(self.gcode, dialect=self.dialect, strict=self.strict, laser_on=self.laser_on,
                        laser_off=self.laser_off, machine=self.machine, start=self.start,
                        plate_z=self.settings.landing.plate_z)
        return plan_process(tp, self.settings)


def parse_set(text: str) -> tuple[str, list]:
    """``name=A:B:STEP``, ``name=V`` or ``name=V1,V2,...`` (``profile=rect,parabola``)."""
    name, sep, values = str(text).partition("=")
    name = name.strip().replace("-", "_")
    if not sep or name not in SWEEPABLE:
        raise DmdvoxError(f"--set {text!r}: expected NAME=VALUES with NAME one of {', '.join(SWEEPABLE)}")
    if name in TEXT:
        return name, [v.strip() for v in values.split(",") if v.strip()]
    if "," in values:
        return name, [v for part in values.split(",") for v in parse_range(part, f"--set {name}")]
    return name, parse_range(values, f"--set {name}")


def sweep_case(case: SweepCase) -> dict:
    """One run: read, plan, deposit (and compare); the scalar results."""
    from ..deposit.simulate import SimulateRequest, simulate

    plan = case.plan()
    if case.cad is not None:
        from ..comparison.compare import CompareRequest, compare

        # each case is swept once: kept, it would only push out the deposits the user's commands share
        result = compare(CompareRequest(plan, case.cad, cad_offset=case.cad_offset, voxel=case.voxel,
                                        max_memory=case.max_memory, cache=False)).summary
    else:
        result = simulate(SimulateRequest(plan, voxel=case.voxel, until=case.until, max_memory=case.max_memory,
                                          cache=False)).summary
    bead = plan.profile
    row = {"profile": bead.name, "width_mm": bead.width, "height_mm": bead.height}
    row.update({k: float(v) if isinstance(v, float) else v for k, v in result.items()
                if isinstance(v, (int, float)) and not isinstance(v, bool)})
    return row


def refuse_what_would_not_fit(cases: list[SweepCase]) -> None:
    """Every run's memory estimated here, before any worker starts, so that a sweep that would
    not fit is refused at once (the runs check again themselves); the program's doubtful points
    (rotary words, nothing to deposit, --until before the first bead, a CAD part away from the
    deposit) are said here once, not by every worker."""
    from .. import checks
    from ..comparison.compare import load_cad
    from ..deposit.engine import plan_deposit

    first = cases[0]
    plan = first.plan()
    tp = plan.toolpath
    for warning in tp.meta.get("warnings", []):
        checks.warn(warning)
    checks.check_toolpath(tp, first.strict)
    cad_bounds = None
    if first.cad is not None:
        vertices = load_cad(first.cad, first.cad_offset)[0]
        cad_bounds = (vertices.min(axis=0), vertices.max(axis=0))
        checks.warn_if_apart(tp, plan.profile, first.cad, *cad_bounds, offset=first.cad_offset)
    for case in cases:
        if case is not first:
            plan = case.plan()
        checks.require_deposit(tp, case.until)
        voxel = plan.resolve_voxel(case.voxel)
        # the beads as programmed (their landing moves them, it does not make them many more)
        beads = plan.programmed_beads(voxel, max_memory=case.max_memory)
        plan_deposit(beads if case.until is None else beads.until(case.until), voxel, max_memory=case.max_memory,
                     extra_bounds=cad_bounds)


def sweep_cases(base: SweepCase, axes: list[tuple[str, list]]) -> list[SweepCase]:
    """One case per point of the grid of ``axes`` ((name, values), as :func:`parse_set` gives
    them), the last axis fastest."""
    names = [name for name, _ in axes]
    if len(set(names)) != len(names):
        raise DmdvoxError("--set: each option may be swept once")
    if base.cad is not None and "until" in names:
        raise DmdvoxError("--set until: compare runs the whole program; drop --cad or the until sweep")
    cases = []
    for values in itertools.product(*(v for _, v in axes)):
        case = base
        for name, value in zip(names, values):
            case = case.with_value(name, value)
        case.settings.validate()
        cases.append(case)
    return cases


@dataclass(frozen=True)
class SweepStudy:
    """One row per run: the swept values (``set_NAME``) first, then the run's scalar results."""

    rows: list[dict]

    @property
    def keys(self) -> list[str]:
        return list(dict.fromkeys(k for row in self.rows for k in row))

    def to_json(self) -> dict:
        return {"rows": self.rows}


def sweep(base: SweepCase, axes: list[tuple[str, list]], scheduler: str | None = None) -> SweepStudy:
    """Every point of the grid as a task (local processes, or the dask cluster at ``scheduler``),
    after refusing at once what would not fit."""
    from ..tasks import run_tasks

    cases = sweep_cases(base, axes)
    refuse_what_would_not_fit(cases)
    names = [name for name, _ in axes]
    results = run_tasks(sweep_case, cases, scheduler, desc="sweep")
    return SweepStudy([{**{f"set_{n}": c.value(n) for n in names}, **r} for c, r in zip(cases, results)])
