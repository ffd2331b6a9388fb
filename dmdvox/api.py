"""dmdvox as a library: the command line's work as functions of typed values.

Each function takes the program (a G-code path, a :class:`~dmdvox.toolpath.model.Toolpath`
from :func:`read_gcode`, or a :class:`~dmdvox.process.plan.ProcessPlan` from :func:`plan`) and
keyword options named as the command line's, and returns a typed result whose ``to_json()`` is
the object ``--json`` prints (docs/API.md)::

    import dmdvox

    tp = dmdvox.read_gcode("data/demo_block.gcode")
    result = dmdvox.simulate(tp, voxel=0.25)
    result["deposit_volume_mm3"], result.grid, result.surface()   # a pyvista.PolyData

Process options (``profile``, ``width``, ``height``, ``exponent``, ``model``, and the
``flow``, ``motion`` and ``landing`` settings) go to :class:`~dmdvox.process.plan.ProcessSettings`
when the program is not already a plan. Memory limits are in GiB, as ``--max-memory``.
"""

from __future__ import annotations

from os import PathLike

from .build import Build
from .limits import PROCESS_KEYS, CheckRequest, CheckResult, read_cell
from .comparison.compare import CompareRequest, Comparison
from .collision.run import CollideRequest, Collisions, NozzleSettings
from .collision.run import collide as run_collide
from .defaults import CLEARANCE_MM, STANDOFF_MM
from .deposit.simulate import SimulateRequest, Simulation
from .changes import Diff, DiffRequest
from .changes import diff as run_diff
from .errors import DmdvoxError
from .process.flow import FlowSettings
from .process.landing import LandingSettings
from .process.plan import ProcessPlan, ProcessSettings, plan_process
from .process.planner import MotionSettings
from .reporting.build import Report, ReportRequest
from .toolpath import Toolpath, read_gcode

Program = str | PathLike | Toolpath | ProcessPlan


def plan(program: str | PathLike | Toolpath, settings: ProcessSettings | None = None, **options) -> ProcessPlan:
    """The program as the machine runs it: planned speeds, material per row, beads. ``options``
    are :class:`ProcessSettings` fields (not with ``settings``)."""
    if settings is not None and options:
        raise TypeError("give settings or ProcessSettings fields as keywords, not both")
    tp = program if isinstance(program, Toolpath) else read_gcode(program)
    settings = ProcessSettings(**options) if settings is None else settings
    settings.validate()
    return plan_process(tp, settings)


def _plan(program: Program, options: dict) -> ProcessPlan:
    if isinstance(program, ProcessPlan):
        if options:
            raise TypeError(f"the program is already planned: {', '.join(options)} cannot change it")
        return program
    return plan(program, **options)


def _bytes(max_memory_gib: float | None) -> int | None:
    return None if max_memory_gib is None else int(max_memory_gib * 2**30)


def simulate(program: Program, voxel: float | None = None, *, until: float | None = None,
             out_dir: str | PathLike | None = None, max_memory_gib: float | None = None,
             scheduler: str | None = None, **options) -> Simulation:
    """The beads swept into the sparse grid, with volume, pores and growth (``dmdvox simulate``):
    :meth:`Build.simulate` of a build of this one stage; ``options`` are :class:`Build`'s
    process settings."""
    return Build(program, voxel=voxel, until=until, max_memory_gib=max_memory_gib, scheduler=scheduler,
                 **options).simulate(out_dir)


def compare(program: Program, cad: str | PathLike, voxel: float | None = None, *,
            cad_offset: tuple[float, float, float] = (0.0, 0.0, 0.0), out_dir: str | PathLike | None = None,
            surfaces: bool = False, max_memory_gib: float | None = None, scheduler: str | None = None,
            **options) -> Comparison:
    """The deposit against the CAD part (``dmdvox compare``); ``surfaces`` makes the deviation
    maps (:meth:`Comparison.deviation_maps`) without writing files (:meth:`Build.compare`)."""
    return Build(program, voxel=voxel, max_memory_gib=max_memory_gib, scheduler=scheduler,
                 **options).compare(cad, cad_offset=cad_offset, surfaces=surfaces, out_dir=out_dir)


def collide(program: Program, nozzle: str, voxel: float | None = None, *, fixtures=(), plate: float | None = None,
            standoff: float = STANDOFF_MM, clearance: float = CLEARANCE_MM, max_memory_gib: float | None = None,
            **options) -> Collisions:
    """The nozzle (an STL or ``cone:tip=D,top=D,length=L``) along the program against the part as
    it grows, the fixtures (STL paths, ``PATH@dx,dy,dz`` to move one) and the plate
    (``dmdvox collide``)."""
    return run_collide(CollideRequest(_plan(program, options),
                                      NozzleSettings(nozzle, tuple(str(f) for f in fixtures), plate, standoff,
                                                     clearance),
                                      voxel=voxel, max_memory=_bytes(max_memory_gib)))


def report(program: Program, out_dir: str | PathLike, voxel: float | None = None, *, cad: str | PathLike | None = None,
           cad_offset: tuple[float, float, float] = (0.0, 0.0, 0.0), nozzle: str | None = None, fixtures=(),
           plate: float | None = None, standoff: float = STANDOFF_MM, clearance: float = CLEARANCE_MM,
           max_memory_gib: float | None = None, scheduler: str | None = None, thermal: dict | None = None,
           **options) -> Report:
    """One self-contained HTML page in ``out_dir`` (``dmdvox report``); ``thermal``, the heat
    options by their long names (``{"material": "316L", "laser_power": 1000}``), adds the heat
    stage and the page's Heat section (``--thermal``)."""
    nozzle_settings = None if nozzle is None else NozzleSettings(nozzle, tuple(str(f) for f in fixtures), plate,
                                                                 standoff, clearance)
    return Build(program, voxel=voxel, max_memory_gib=max_memory_gib, scheduler=scheduler, thermal=thermal,
                 **options).report(out_dir, cad=cad, cad_offset=cad_offset, nozzle=nozzle_settings)


# the cell file's [process] keys that are ProcessSettings fields (the others are the command
# line's material, motion and landing options: give them as FlowSettings, MotionSettings, LandingSettings)
_CELL_FIELDS = ("profile", "width", "height", "exponent", "model")


def check(program: Program, limits, voxel: float | None = None, *, cad: str | PathLike | None = None,
          cad_offset: tuple[float, float, float] | None = None, nozzle: str | None = None, fixtures=None,
          plate: float | None = None, standoff: float | None = None, clearance: float | None = None,
          junit: str | PathLike | None = None, max_memory_gib: float | None = None, scheduler: str | None = None,
          thermal: dict | None = None, **options) -> CheckResult:
    """Judge the program against ``limits`` (``dmdvox check``): a dict (name -> value, the
    ``[limits]`` keys) or a cell file, whose ``[part]``, ``[nozzle]`` and ``[process]`` tables
    fill what the arguments leave unset (of ``[process]``: ``voxel`` and the bead's ``profile``,
    ``width``, ``height``, ``exponent``, ``model``) and ``[thermal]`` (the heat options, for the
    thermal limits; ``thermal``, a dict of them, in its place). ``result.passed``; ``result.exit_code`` is
    the command's (0 or 3); ``junit`` writes the JUnit XML."""
    cell = {}
    if isinstance(limits, (str, PathLike)):
        read = read_cell(limits)
        limits, cell = read.limits, read.options
        thermal = read.thermal if thermal is None else thermal
        if not isinstance(program, ProcessPlan):
            other = sorted(k for k in cell if k in PROCESS_KEYS and k not in (*_CELL_FIELDS, "voxel"))
            if cell.get("machine", "none") != "none":
                other.append("[machine] file")
            if other:
                raise DmdvoxError(f"{read.path}: {', '.join(other)} are for the command line; in Python read the "
                                  "program with dmdvox.read_gcode(path, machine=...) and plan it with FlowSettings, "
                                  "MotionSettings or LandingSettings (dmdvox.plan)")
            options = {**{k: cell[k] for k in _CELL_FIELDS if k in cell}, **options}
    nozzle = cell.get("nozzle") if nozzle is None else nozzle
    settings = None
    if nozzle is not None:
        settings = NozzleSettings(nozzle, tuple(str(f) for f in (cell.get("fixture", ()) if fixtures is None
                                                                  else fixtures)),
                                  cell.get("plate") if plate is None else plate,
                                  cell.get("standoff", STANDOFF_MM) if standoff is None else standoff,
                                  cell.get("clearance", CLEARANCE_MM) if clearance is None else clearance)
    cad = cell.get("cad") if cad is None else cad
    build = Build(program, voxel=cell.get("voxel") if voxel is None else voxel, max_memory_gib=max_memory_gib,
                  scheduler=scheduler, thermal=thermal, **options)
    return build.check(limits, cad=cad, cad_offset=cell.get("cad_offset", (0.0, 0.0, 0.0)) if cad_offset is None
                       else cad_offset, nozzle=settings, junit=junit)


def diff(old: Program, new: Program, voxel: float | None = None, *, cad: str | PathLike | None = None,
         cad_offset: tuple[float, float, float] = (0.0, 0.0, 0.0), out_dir: str | PathLike | None = None,
         max_memory_gib: float | None = None, scheduler: str | None = None, **options) -> Diff:
    """What changing ``old`` into ``new`` does to the part (``dmdvox diff``): volume added and
    removed, the lines and layers responsible, and with ``cad`` the change of void and
    overbuild; ``options`` plan both programs alike."""
    return run_diff(DiffRequest(_plan(old, options), _plan(new, options), voxel=voxel,
                                cad=None if cad is None else str(cad), cad_offset=tuple(cad_offset), out_dir=out_dir,
                                max_memory=_bytes(max_memory_gib), scheduler=scheduler))


__all__ = ["Build", "CheckRequest", "CheckResult", "CollideRequest", "Collisions", "CompareRequest", "Comparison", "Diff",
           "DiffRequest", "FlowSettings", "LandingSettings", "MotionSettings", "NozzleSettings", "ProcessPlan",
           "ProcessSettings", "Program", "Report", "ReportRequest", "SimulateRequest", "Simulation", "Toolpath",
           "check", "collide", "compare", "diff", "plan", "read_gcode", "report", "simulate"]
