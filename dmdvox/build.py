"""One build, computed once: a program, its settings and each stage's result.

A :class:`Build` owns the program and the settings that decide what it deposits, resolved once
(the plan, the voxel), and computes each stage the first time it is asked for, keeping the
result: the deposit is swept and its voids searched once, however many analyses read it; each
CAD part becomes a level set once, however many times it is compared, checked or reported::

    import dmdvox

    build = dmdvox.Build("data/demo_block.gcode", voxel=0.25)
    build.deposit.deposit_volume_mm3        # swept here
    build.compare("data/demo_block.stl")    # the same deposit against the CAD part
    build.report("out")                     # neither swept nor compared again
    build.check({"max_void_percent": 2.0}, cad="data/demo_block.stl")

The functions of :mod:`dmdvox.api` (``dmdvox.simulate``, ``compare``, ``report``, ``check``) are
a build of one stage; the command line's commands too. Warnings said while a build computes go
to stderr as always and into the build's own list (:attr:`Build.warnings`), which every result
it returns carries in its ``warnings``: two builds in one process do not mix theirs.
"""

from __future__ import annotations

from contextlib import contextmanager
from dataclasses import replace
from functools import cached_property
from os import PathLike
from pathlib import Path

from . import checks, progress
from .collision.run import Collisions, NozzleSettings, collide_part, prepare_collide
from .comparison.compare import CompareRequest, Comparison, compare as run_compare, with_surfaces
from .comparison.compare import with_outputs as comparison_with_outputs
from .defaults import CLEARANCE_MM, STANDOFF_MM
from .deposit.simulate import SimulateRequest, Simulation, describe, simulate as run_simulate
from .deposit.simulate import with_outputs as simulation_with_outputs
from .errors import DmdvoxError
from .limits import LIMITS, CheckRequest, CheckResult, check_limits
from .limits import check as run_check
from .process.flow import FlowSettings
from .process.landing import LandingSettings
from .process.plan import ProcessPlan, ProcessSettings, plan_process
from .process.planner import MotionSettings
from .reporting.build import Report, ReportRequest
from .reporting.build import report as run_report
from .toolpath import Toolpath, read_gcode

Program = str | PathLike | Toolpath | ProcessPlan


def _bytes(max_memory_gib: float | None) -> int | None:
    return None if max_memory_gib is None else int(max_memory_gib * 2**30)


def _with_warnings(result, warnings: list[str]):
    """``result`` (a result with a ``summary``) whose ``warnings`` also hold ``warnings``, each once."""
    merged = list(result.summary.get("warnings") or [])
    merged += [w for w in warnings if w not in merged]
    return replace(result, summary={**result.summary, "warnings": merged})


class Build:
    """A program, its settings resolved once, and each stage computed once when first asked for.

    Parameters
    ----------
    program : str, PathLike, Toolpath or ProcessPlan
        The G-code file, the program read (:func:`dmdvox.read_gcode`), or planned
        (:func:`dmdvox.plan`; then no process setting may be given).
    voxel : float, optional
        Edge of the deposit's voxels in mm; default: the bead's (:meth:`ProcessPlan.resolve_voxel`).
    until : float, optional
        The part as it stands at this time in seconds (default: finished); only the deposit
        stages (:attr:`deposit`, :meth:`simulate`) take it.
    settings : ProcessSettings, optional
        The process settings whole, in place of the fields below.
    profile, width, height, exponent, model
        The bead (:class:`ProcessSettings` fields; None: its default).
    flow, motion, landing : FlowSettings, MotionSettings, LandingSettings, optional
        The material, motion and landing settings (default: their defaults).
    max_memory_gib : float, optional
        The memory every stage keeps within, in GiB (default: a share of what is free).
    scheduler : str, optional
        The dask scheduler's address for the sweep's and the comparison's slabs (default: here).
    cache : bool
        Take the deposit from (and keep it in) the deposit cache (:mod:`dmdvox.deposit.cache`).
    thermal : dict, optional
        The heat options by their long names (``{"material": "316L"}``) for :attr:`thermal`,
        the report's Heat section and the thermal limits.

    Attributes
    ----------
    warnings : list of str
        Every warning said while the build computed, in order, each once.

    Notes
    -----
    A build keeps what it computed for the stages after: the deposit, each comparison, and the
    OpenVDB form of each grid it converted (about the grid's own size); drop the build to free them.
    """

    def __init__(self, program: Program, *, voxel: float | None = None, until: float | None = None,
                 settings: ProcessSettings | None = None, profile: str | None = None, width: float | None = None,
                 height: float | None = None, exponent: float | None = None, model: str | None = None,
                 flow: FlowSettings | None = None, motion: MotionSettings | None = None,
                 landing: LandingSettings | None = None, max_memory_gib: float | None = None,
                 scheduler: str | None = None, cache: bool = True, thermal: dict | None = None):
        fields = {k: v for k, v in (("profile", profile), ("width", width), ("height", height),
                                    ("exponent", exponent), ("model", model), ("flow", flow), ("motion", motion),
                                    ("landing", landing)) if v is not None}
        if isinstance(program, ProcessPlan) and (fields or settings is not None):
            raise TypeError(f"the program is already planned: {', '.join(fields) or 'settings'} cannot change it")
        if settings is not None and fields:
            raise TypeError("give settings or ProcessSettings fields as keywords, not both")
        self.program = program
        if isinstance(program, ProcessPlan):
            settings = program.settings
        self.settings = ProcessSettings(**fields) if settings is None else settings
        self.until = until
        self.max_memory = _bytes(max_memory_gib)
        self.scheduler = scheduler
        self.cache = cache
        self.thermal_options = thermal
        self._voxel = voxel
        self.warnings: list[str] = []
        self._simulations: dict = {}
        self._comparisons: dict = {}
        self._converted: dict = {}  # the grids' OpenVDB forms (dmdvox.grid.vdbio.reusing)

    @contextmanager
    def _collecting(self):
        """The warnings said inside into :attr:`warnings`; the collections around the build (the
        command's, for ``--json``) get them too (:func:`dmdvox.checks.collect_warnings`)."""
        with checks.collect_warnings() as said:
            try:
                yield
            finally:
                self.warnings += [w for w in said if w not in self.warnings]

    @contextmanager
    def _reusing(self):
        """Every grid converted to OpenVDB once for the whole build (:func:`dmdvox.grid.vdbio.reusing`;
        imported when used: OpenVDB loads only for the stages that need it)."""
        from .grid.vdbio import reusing

        with reusing(self._converted):
            yield

    def _result(self, result):
        return _with_warnings(result, self.warnings)

    # -- settings, resolved once -----------------------------------------------------------------

    @cached_property
    def plan(self) -> ProcessPlan:
        """The program as the machine runs it (:class:`ProcessPlan`): planned motion, material, beads."""
        with self._collecting():
            if isinstance(self.program, ProcessPlan):
                # planned by the caller, who said its warnings: kept, not said again
                plan = self.program
                tp = plan.toolpath
                checks.record(tp.meta.get("warnings", []))
                if tp.meta.get("rotary_used"):
                    checks.record([f"{tp.source}: {checks.ROTARY_WARNING}"])
                checks.record(plan.warnings)
            else:
                tp = self.program if isinstance(self.program, Toolpath) else read_gcode(self.program)
                for warning in tp.meta.get("warnings", []):
                    checks.warn(warning)
                checks.check_toolpath(tp)
                self.settings.validate()
                plan = plan_process(tp, self.settings)
                for warning in plan.warnings:
                    checks.warn(warning)
        return plan

    @cached_property
    def voxel(self) -> float:
        """The voxel every stage sweeps at, in mm."""
        checks.require_voxel_resolves_bead(self.plan, self._voxel)
        return self.plan.resolve_voxel(self._voxel)

    # -- the deposit -----------------------------------------------------------------------------

    def _swept(self, for_outputs: bool) -> Simulation:
        """The deposit swept once; ``for_outputs``: the first sweep is for a run that writes its
        files (its memory estimate holds their work too)."""
        if None not in self._simulations:
            plan = self.plan
            with self._collecting():
                checks.require_deposit(plan.toolpath, self.until)
                progress.stage("deposit", describe(plan))
                self._simulations[None] = run_simulate(SimulateRequest(
                    plan, voxel=self.voxel, until=self.until, max_memory=self.max_memory, scheduler=self.scheduler,
                    cache=self.cache), outputs_after=for_outputs)
        return self._simulations[None]

    @property
    def deposit(self) -> Simulation:
        """The beads swept into the sparse grid, with volume, pores and growth (``dmdvox simulate``
        without files): :class:`~dmdvox.deposit.simulate.Simulation`."""
        return self._result(self._swept(False))

    @property
    def voids(self):
        """The deposit's enclosed voids and pores (:class:`~dmdvox.grid.analysis.Porosity`)."""
        return self._swept(False).porosity

    def simulate(self, out_dir: str | PathLike | None = None) -> Simulation:
        """The deposit, with the files ``dmdvox simulate --out`` writes in ``out_dir`` when given.

        Parameters
        ----------
        out_dir : str or PathLike, optional
            The folder for the grid (.vdb), its surface (.vtp, .stl, .ply), the row table and
            the JSON.

        Returns
        -------
        Simulation
            :attr:`deposit`, with ``outputs`` and ``surface_mesh`` when files were written.
        """
        if out_dir is None:
            return self.deposit
        key = str(Path(out_dir))
        if key not in self._simulations:
            swept = self._swept(True)
            with self._collecting(), self._reusing():
                self._simulations[key] = simulation_with_outputs(swept, self.plan, out_dir)
        return self._result(self._simulations[key])

    @cached_property
    def thermal(self):
        """The heat stage on the deposit (``--thermal``): (:class:`~dmdvox.thermal.run.ThermalResult`,
        its summary as ``dmdvox thermal --json`` prints it, no file written); needs ``thermal``."""
        from .thermal.outputs import heat_deposit

        if not (self.thermal_options or {}).get("material"):
            raise DmdvoxError("the heat stage needs the heat options: Build(..., thermal={'material': '316L', ...})")
        swept = self._swept(False)
        with self._collecting():
            progress.stage("thermal", f"{self.thermal_options['material']} on the deposit of "
                                      f"{self.plan.toolpath.source}")
            return heat_deposit(self.plan, swept.grid, swept["plate_z_mm"], self.thermal_options, None,
                                self.max_memory)

    # -- the analyses ----------------------------------------------------------------------------

    def _finished(self, stage: str) -> None:
        if self.until is not None:
            raise DmdvoxError(f"{stage} takes the finished part: make the Build without until")

    def compare(self, cad: str | PathLike, *, cad_offset=(0.0, 0.0, 0.0), surfaces: bool = False,
                out_dir: str | PathLike | None = None, pictures=None) -> Comparison:
        """The deposit against the CAD part (``dmdvox compare``), once per part and offset.

        Parameters
        ----------
        cad : str or PathLike
            The CAD part's STL.
        cad_offset : tuple of 3 float
            Where the part moves to meet the program (mm).
        surfaces : bool
            Also the deviation maps on both surfaces (:meth:`Comparison.deviation_maps`).
        out_dir : str or PathLike, optional
            The folder for the files ``dmdvox compare --out`` writes (maps, fields, layer table, JSON).
        pictures : callable, optional
            ``pictures(out_dir, stem, cad_surface)`` draws beside the files and returns their paths.

        Returns
        -------
        Comparison
            The same deposit as :attr:`deposit`, widened to the part's blocks.
        """
        self._finished("compare")
        offset = tuple(float(v) for v in cad_offset)
        key = (str(Path(cad).resolve()), offset)
        if key not in self._comparisons:
            swept = self._swept(False)
            with self._collecting(), self._reusing():
                self._comparisons[key] = run_compare(CompareRequest(
                    self.plan, Path(cad), cad_offset=offset, voxel=self.voxel, max_memory=self.max_memory,
                    scheduler=self.scheduler, cache=self.cache), simulation=swept)
        comparison = self._comparisons[key]
        if out_dir is not None:
            with self._collecting(), self._reusing():
                comparison = comparison_with_outputs(comparison, self.plan, out_dir, pictures=pictures)
        elif surfaces:
            if comparison.cad_surface is None:
                with self._collecting(), self._reusing():
                    self._comparisons[key] = comparison = with_surfaces(comparison, self.plan)
        return self._result(comparison)

    def collide(self, nozzle: str, fixtures=(), *, plate: float | None = None, standoff: float = STANDOFF_MM,
                clearance: float = CLEARANCE_MM, strict: bool = False) -> Collisions:
        """The nozzle along the program against the deposit as it grows, the fixtures and the
        plate (``dmdvox collide``).

        Parameters
        ----------
        nozzle : str
            An STL, or ``cone:tip=D,top=D,length=L`` (mm).
        fixtures : sequence of str
            Fixture STLs (``PATH@dx,dy,dz`` moves one).
        plate : float, optional
            The plate's top Z (mm); None: no plate.
        standoff, clearance : float
            The nozzle tip's height above the programmed point, and the near-miss distance (mm).
        strict : bool
            Refuse rotary words the machine does not model.

        Returns
        -------
        Collisions
        """
        from .collision.bodies import load_fixtures

        self._finished("collide")
        settings = NozzleSettings(nozzle, tuple(str(f) for f in fixtures), plate, standoff, clearance)
        plan = self.plan
        with self._collecting():
            loaded = load_fixtures(list(settings.fixtures))
            prepare_collide(plan.toolpath, settings.nozzle, loaded, self.voxel, settings.clearance, self.max_memory,
                            strict=strict)
        grid = self._swept(False).grid if plan.toolpath.deposit.any() else None
        with self._collecting():
            check, labels = collide_part(plan.toolpath, grid, settings, loaded, self.voxel)
        return Collisions(check, labels, self.voxel, float(settings.standoff), str(plan.toolpath.source))

    def report(self, out_dir: str | PathLike, *, cad: str | PathLike | None = None, cad_offset=(0.0, 0.0, 0.0),
               nozzle: NozzleSettings | None = None, extra_fields=()) -> Report:
        """One self-contained HTML page in ``out_dir`` (``dmdvox report``) from this build's
        deposit and comparison; the Heat section with the build's ``thermal`` options.

        Parameters
        ----------
        out_dir : str or PathLike
            The page's folder (the deposit's files in ``simulate/``, the comparison's in ``compare/``).
        cad : str or PathLike, optional
            The CAD part's STL, compared (:meth:`compare`) and shown.
        cad_offset : tuple of 3 float
            Where the part moves to meet the program (mm).
        nozzle : NozzleSettings, optional
            The nozzle, fixtures and plate checked along the path.
        extra_fields : sequence
            More colourings of the 3-D view (:func:`dmdvox.reporting.build.report`).

        Returns
        -------
        Report
        """
        from .view.pictures import cad_deviation_picture

        self._finished("report")
        out = Path(out_dir)
        plan = self.plan
        request = ReportRequest(plan, out, cad=None if cad is None else str(cad), cad_offset=tuple(cad_offset),
                                nozzle=nozzle, voxel=self.voxel, max_memory=self.max_memory,
                                scheduler=self.scheduler, thermal=self.thermal_options)
        with self._collecting():
            checks.require_deposit(plan.toolpath)
        if cad is None:
            simulation = self.simulate(out / "simulate")
            with self._collecting(), self._reusing():
                result = run_report(request, extra_fields, simulation=simulation)
        else:
            comparison = self.compare(cad, cad_offset=cad_offset)
            # one conversion of each grid to OpenVDB for the deposit's file, its surface and the fields
            with self._collecting(), self._reusing():
                # the deposit's files from the comparison's (widened) grid, as simulate_out_dir writes them
                simulation = simulation_with_outputs(comparison.simulation, plan, out / "simulate")
                comparison = comparison_with_outputs(comparison, plan, out / "compare", simulation=simulation,
                                                     pictures=cad_deviation_picture)
                result = run_report(request, extra_fields, comparison=comparison)
        return self._result(result)

    def check(self, limits: dict, *, cad: str | PathLike | None = None, cad_offset=(0.0, 0.0, 0.0),
              nozzle: NozzleSettings | None = None, junit: str | PathLike | None = None,
              strict: bool = False) -> CheckResult:
        """Judge the build against ``limits`` (``dmdvox check``) on its deposit and comparison.

        Parameters
        ----------
        limits : dict
            Limit name -> value (the cell file's ``[limits]`` keys, :data:`dmdvox.limits.LIMITS`).
        cad : str or PathLike, optional
            The CAD part, for the limits that need it.
        cad_offset : tuple of 3 float
            Where the part moves to meet the program (mm).
        nozzle : NozzleSettings, optional
            The nozzle, for the collision limits.
        junit : str or PathLike, optional
            Write the JUnit XML report there.
        strict : bool
            Refuse rotary words the machine does not model.

        Returns
        -------
        CheckResult
            ``passed``, and the verdict of every limit.
        """
        self._finished("check")
        runs = {LIMITS[name].run for name in check_limits(limits, "limits")}
        plan = self.plan
        request = CheckRequest(plan, limits, cad=None if cad is None else str(cad), cad_offset=tuple(cad_offset),
                               nozzle=nozzle, voxel=self.voxel, max_memory=self.max_memory, scheduler=self.scheduler,
                               strict=strict, junit=junit, thermal=self.thermal_options)
        # nothing deposited: the check refuses it in its own words
        deposits = bool(plan.toolpath.deposit.any())
        comparison = None
        if deposits and cad is not None and ("compare" in runs or "deposit" in runs):
            comparison = self.compare(cad, cad_offset=cad_offset)
        simulation = self._swept(False) if deposits else None
        with self._collecting():
            result = run_check(request, simulation=simulation, comparison=comparison)
        return self._result(result)


__all__ = ["Build", "Program"]
