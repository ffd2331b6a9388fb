"""What the machine does with a program: planned motion, material per row, beads to lay.

:func:`plan_process` turns a :class:`~dmdvox.toolpath.model.Toolpath` and the run's
:class:`ProcessSettings` into a :class:`ProcessPlan`: the toolpath with its planned times, the
motion plan, the material of every row and each row's cross-section inputs. Its
:meth:`ProcessPlan.beads` gives the elements the deposit engine sweeps.

Bead models (``model`` in every JSON summary):

``fixed``
    one cross-section everywhere, ``--width`` x ``--height`` (the default height is the layer
    step), at the programmed positions: the bead of a program that says nothing about its
    material;
``union``
    the cross-section of each row from its material (or the slicer's ``;WIDTH:``/``;HEIGHT:``),
    at the programmed positions, joined by a geometric union (overlaps are lost);
``flow``
    the same cross-sections, landed on the part as it stands (:mod:`.landing`: mass conserved).

Default: ``flow`` when the material gives the bead, ``union`` when only slicer comments do,
``fixed`` otherwise; ``--model`` chooses another.
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass, field

import numpy as np

from ..errors import ParameterError, ResourceError
from ..memory import budget, budget_phrase
from ..toolpath.geometry import arc_chord_counts
from ..toolpath.model import Toolpath
from .beads import Beads, RowSections, build_beads, exact_arc_rows
from .flow import Flow, FlowSettings, material_flow
from .landing import Landing, LandingSettings, land
from .planner import MotionPlan, MotionSettings, apply_plan, plan_motion
from .profiles import BeadProfile, profile_area, profile_code

MODELS = ("fixed", "union", "flow")
DEFAULT_WIDTH_MM = 2.5  # the seed's track
SINGLE_LAYER_HEIGHT_RATIO = 0.4  # height/width when a one-layer program gives no layer step
DEFAULT_VOXELS_PER_WIDTH = 20.0  # w/voxel: closed-form volumes within 1 % (tests)
DEFAULT_CHORD_TOLERANCE_MM = 0.01
# The widest bead, in layer heights, that the material of a move may imply: real slicer and DED
# files stay under 12 (data/corpus/real measured); beyond 100 the E word is no extrusion line's
# (a prime on a vanishing move, a stripped G92) and the bead it implies would have no size.
MAX_IMPLIED_WIDTH_LAYERS = 100.0
PRIMITIVE_BYTES = 1280  # per chord: its segment and cap elements and their build's peak (measured 1.25 KB)


@dataclass(frozen=True)
class ProcessSettings:
    """The options that decide what a program deposits (all commands that lay beads share them).

    ``width``/``height`` are the user's explicit values (None: not given)."""

    profile: str = "rect"
    width: float | None = None
    height: float | None = None
    exponent: float = 4.0
    model: str | None = None
    flow: FlowSettings = field(default_factory=FlowSettings)
    motion: MotionSettings = field(default_factory=MotionSettings)
    landing: LandingSettings = field(default_factory=LandingSettings)

    def validate(self) -> None:
        profile_code(self.profile)
        if self.model is not None and self.model not in MODELS:
            raise ParameterError(f"{{model}}: unknown bead model {self.model!r}; choose one of {', '.join(MODELS)}",
                                 "model")
        self.flow.validate()
        self.motion.validate()
        self.landing.validate()


@dataclass(frozen=True, eq=False)
class ProcessPlan:
    """A program as the machine runs it: planned times, material, cross-section inputs."""

    toolpath: Toolpath  # with the planned times
    motion: MotionPlan
    flow: Flow
    sections: RowSections
    profile: BeadProfile  # the nominal bead: the fixed one, or the median section of a flow bead
    model: str
    settings: ProcessSettings
    warnings: list[str]

    def default_voxel(self) -> float:
        return default_voxel(self.profile)

    def resolve_voxel(self, voxel: float | None) -> float:
        """The voxel a stage sweeps at: ``voxel`` when given, else the bead's default; the one
        place every stage resolves it."""
        return self.default_voxel() if voxel is None else float(voxel)

    def row_area(self) -> np.ndarray:
        """Mean cross-section area (mm^2) of every row from its material (NaN without material or
        length)."""
        length = self.toolpath.length
        return np.divide(self.flow.volume, length, out=np.full(length.shape, np.nan),
                         where=(length > 0) & self.toolpath.deposit & self.flow.from_material)

    def layer_bottoms(self) -> np.ndarray:
        """The programmed bead bottom of every layer (``toolpath.layer_z`` is the path's Z, the
        layer top in slicer dialects)."""
        tp = self.toolpath
        rows = np.flatnonzero(tp.deposit)
        first = np.full(tp.layer_z.size, -1, np.int64)
        first[tp.layer[rows][::-1]] = rows[::-1]  # each layer's first deposit row
        shift = np.where(first >= 0, self.sections.bottom_shift[np.maximum(first, 0)], 0.0)
        return tp.layer_z + shift

    def lay(self, voxel: float, until: float | None = None, max_memory: int | None = None) -> "LaidBeads":
        """The elements to sweep at ``voxel`` (arcs chorded to a quarter voxel or 0.01 mm), landed
        on the part under the flow model, up to ``until`` seconds; refuses helices and spirals
        whose chords would not fit in memory."""
        programmed = self.programmed_beads(voxel, max_memory)
        landing = None
        beads = programmed
        if self.model == "flow":
            # extruded filament (E words in the reprap dialect, Z the layer top): the nozzle tip
            # stands the layer height above the programmed bead bottom and flattens the bead
            filament = self.flow.source == "e" and self.toolpath.dialect == "reprap" and self.toolpath.z_is_layer_top
            settings = dataclasses.replace(self.settings.landing, nominal_catchment=float(self.settings.flow.catchment),
                                           filament=filament)
            beads, landing = land(programmed, voxel, settings, nozzle=-self.sections.bottom_shift[programmed.row])
            programmed = landing.programmed
        if until is not None:
            beads = beads.until(until)
        return LaidBeads(beads=beads, programmed=programmed, landing=landing, until=until)

    def beads(self, voxel: float, until: float | None = None, max_memory: int | None = None) -> Beads:
        return self.lay(voxel, until, max_memory).beads

    def programmed_beads(self, voxel: float, max_memory: int | None = None) -> Beads:
        """The elements where the program puts them (no landing): what memory estimates use."""
        chord = chord_tolerance(voxel)
        check_chords(self.toolpath, chord, max_memory)
        # the fixed bead ignores whatever material the program meters
        flow = self.flow if self.model != "fixed" else no_flow(self.toolpath)
        return build_beads(self.toolpath, self.profile, self.sections, flow, self.motion, chord, min_piece=voxel)

    def to_json(self) -> dict:
        return {"model": self.model, **self.flow_json()}

    def flow_json(self) -> dict:
        """Material and motion (``info``): source, delivered volume, cross-section areas."""
        out = {**self.flow.to_json(), "motion": self.motion.to_json()}
        areas = row_areas(self)
        if areas.size and areas.max() > areas.min() * (1 + 1e-6):
            out["area_mm2"] = {"min": float(areas.min()), "median": float(np.median(areas)),
                               "max": float(areas.max())}
        return out


@dataclass(frozen=True, eq=False)
class LaidBeads:
    """The beads to sweep, the beads as programmed (before landing), and where they landed."""

    beads: Beads
    programmed: Beads
    landing: Landing | None
    until: float | None

    def lost(self) -> np.ndarray:
        """Programmed elements (started by ``until``) whose material never reached the part."""
        if self.landing is None:
            return np.zeros(len(self.programmed), bool)
        lost = self.landing.lost
        return lost if self.until is None else lost & (self.programmed.t0 < self.until)

    @property
    def lost_mm3(self) -> float:
        return float(self.programmed.volume[self.lost()].sum())

    @property
    def delivered_mm3(self) -> float:
        """Material that reached the nozzle's melt pool or was lost on the way, up to ``until``."""
        return float(self.beads.volume.sum()) + self.lost_mm3


def default_voxel(profile: BeadProfile) -> float:
    """A voxel that resolves the bead: width/20, but at least 4 voxels over the height."""
    return float(min(profile.width / DEFAULT_VOXELS_PER_WIDTH, profile.height / 4))


def chord_tolerance(voxel: float) -> float:
    return min(DEFAULT_CHORD_TOLERANCE_MM, voxel / 4)


def row_areas(plan: ProcessPlan) -> np.ndarray:
    """Mean cross-section area (mm^2) of the deposit rows that carry material."""
    area = plan.row_area()
    return area[np.isfinite(area) & plan.toolpath.deposit & (plan.flow.volume > 0)]


def check_chords(tp: Toolpath, chord: float, limit: int | None) -> None:
    """Refuse, before the beads are built, deposit arcs that would become more chords than fit:
    helices and spirals are swept as chords, one element each, and a P word of millions of
    turns makes billions of them."""
    arcs = np.flatnonzero(tp.deposit[tp.arcs.segment])
    chorded = np.setdiff1d(arcs, exact_arc_rows(tp))
    chords = arc_chord_counts(np.maximum(tp.arcs.r_start[chorded], tp.arcs.r_end[chorded]), tp.arcs.sweep[chorded],
                              chord).sum(dtype=np.float64)
    estimate = (np.count_nonzero(tp.deposit) - chorded.size + chords) * PRIMITIVE_BYTES
    if estimate > budget(limit):
        raise ResourceError(
            f"{tp.source}: the helical and spiral arcs make {chords:,.0f} chords of {chord:g} mm, about "
            f"{estimate / 2**30:.3g} GiB, but {budget_phrase(limit)}; check their P words "
            "(turns) and radii (or raise {max_memory_gib})", parameter="max_memory_gib")


def plan_process(tp: Toolpath, settings: ProcessSettings = ProcessSettings()) -> ProcessPlan:
    """Plan the motion, meter the material and size the beads of ``tp``."""
    settings.validate()
    motion = plan_motion(tp, settings.motion)
    tp = apply_plan(tp, motion)
    flow = material_flow(tp, settings.flow)
    model = settings.model or ("flow" if flow.from_material else "union" if flow.source == "comments" else "fixed")
    warnings = list(flow.warnings) if model != "fixed" else []  # the fixed bead does not use the material
    if model in ("union", "flow") and flow.source == "none":
        raise ParameterError(f"{{model}} {model}: {tp.source} says nothing about its material (no E words, no "
                             "slicer width comments); give {powder_rate_g_min} and {density_g_cm3}, or "
                             "{wire_diameter_mm} and {wire_feed_mm_min}, or use {model} fixed", "model",
                             also=("powder_rate_g_min", "density_g_cm3", "wire_diameter_mm", "wire_feed_mm_min"))
    if model == "flow" and not flow.from_material:
        raise ParameterError(f"{{model}} flow lands the material the program delivers, and {tp.source} meters "
                             "none (only slicer width comments); give a material source or use {model} union",
                             "model")
    if model == "fixed":
        sections, profile = _fixed_sections(tp, settings)
    else:
        if settings.height is not None and flow.from_material:
            raise ParameterError(f"{{height}}: with material from {flow.source!r} the bead height follows from "
                                 "the material, the width and the profile; drop {height} (or use {model} fixed)",
                                 "height", also=("model",))
        sections, profile = _material_sections(tp, settings, flow)
    return ProcessPlan(toolpath=tp, motion=motion, flow=flow, sections=sections, profile=profile, model=model,
                       settings=settings, warnings=warnings)


def _layer_height(tp: Toolpath, bead_width: float) -> float:
    return tp.layer_step if tp.layer_step > 0 else SINGLE_LAYER_HEIGHT_RATIO * bead_width


def _fixed_sections(tp: Toolpath, settings: ProcessSettings) -> tuple[RowSections, BeadProfile]:
    """Every row ``--width`` x ``--height`` (height: the layer step by default)."""
    width = DEFAULT_WIDTH_MM if settings.width is None else settings.width
    height = _layer_height(tp, float(width)) if settings.height is None else settings.height
    profile = BeadProfile(settings.profile, float(width), float(height), float(settings.exponent))
    n = len(tp)
    shift = -profile.height if tp.z_is_layer_top else 0.0
    return RowSections(np.full(n, profile.width), np.full(n, profile.height), np.full(n, shift)), profile


def _material_sections(tp: Toolpath, settings: ProcessSettings, flow: Flow) -> tuple[RowSections, BeadProfile]:
    """Per-row width (explicit, slicer comment, or what the material gives at the layer height)
    and, where the material does not set it, height (slicer comment or the layer step)."""
    n = len(tp)
    code = profile_code(settings.profile)
    k = profile_area(code, 1.0, 1.0, settings.exponent) if code != profile_code("arc") else math.pi / 4
    comment_h = tp.height.astype(np.float64)
    layer_h = np.where(np.isfinite(comment_h), comment_h, _layer_height(tp, DEFAULT_WIDTH_MM))
    if settings.width is not None:
        width = np.full(n, float(settings.width))
    else:
        width = tp.width.astype(np.float64)
        missing = ~np.isfinite(width)
        if flow.source == "e":
            # a slicer file without width comments: the width its material fills at the layer height
            length = tp.length
            area = np.divide(flow.volume, length, out=np.zeros(n), where=length > 0)
            width[missing] = area[missing] / (k * layer_h[missing])
            _refuse_implied_widths(tp, flow, missing & (width > MAX_IMPLIED_WIDTH_LAYERS * layer_h), width, layer_h)
            missing = ~np.isfinite(width) | (width <= 0)
        width[missing] = DEFAULT_WIDTH_MM
    fixed_h = np.full(n, np.nan)
    if not flow.from_material:
        explicit = settings.height
        fixed_h = np.where(np.isfinite(comment_h), comment_h, layer_h if explicit is None else explicit)
    shift = -layer_h if tp.z_is_layer_top else np.zeros(n)
    sections = RowSections(width, fixed_h, shift)
    dep = tp.deposit & (tp.length > 0)
    if flow.from_material:
        area = np.divide(flow.volume, tp.length, out=np.zeros(n), where=tp.length > 0)
        heights = area[dep] / (k * width[dep])
    else:
        heights = fixed_h[dep]
    w_nominal = float(np.median(width[dep])) if dep.any() else DEFAULT_WIDTH_MM
    h_nominal = float(np.median(heights)) if dep.any() else SINGLE_LAYER_HEIGHT_RATIO * w_nominal
    if code == profile_code("arc"):
        h_nominal = min(h_nominal, 0.5 * w_nominal)
    profile = BeadProfile(settings.profile, w_nominal, max(h_nominal, 1e-6 * w_nominal), float(settings.exponent))
    return sections, profile


def _refuse_implied_widths(tp: Toolpath, flow: Flow, wide: np.ndarray, width: np.ndarray,
                           layer_h: np.ndarray) -> None:
    """Refuse the moves whose material would make a bead wider than ``MAX_IMPLIED_WIDTH_LAYERS``
    layer heights (a 1 um move with E1 implied a 2.4 km bead, and the landing grid asked for
    a PiB): the first one's line, and how to give the width instead."""
    wide = np.flatnonzero(wide & tp.deposit)
    if wide.size == 0:
        return
    i = int(wide[0])
    raise ParameterError(
        f"{tp.source}:{int(tp.line[i])}: {flow.volume[i]:.3g} mm^3 of material on a {tp.length[i]:.3g} mm move "
        f"would make a bead {width[i]:.3g} mm wide at the {layer_h[i]:.3g} mm layer, more than "
        f"{MAX_IMPLIED_WIDTH_LAYERS:g} layer heights ({wide.size} such move{'s' if wide.size > 1 else ''}); "
        "check the E words there, or give {width} (the melt-pool width)", "width")


def fixed_beads(tp: Toolpath, profile: BeadProfile, chord: float = DEFAULT_CHORD_TOLERANCE_MM) -> Beads:
    """The fixed bead ``profile`` laid along ``tp`` as timed (no planning): for tests and studies
    that build their own toolpaths."""
    n = len(tp)
    shift = -profile.height if tp.z_is_layer_top else 0.0
    sections = RowSections(np.full(n, profile.width), np.full(n, profile.height), np.full(n, shift))
    return build_beads(tp, profile, sections, no_flow(tp), None, chord)


def no_flow(tp: Toolpath) -> Flow:
    """No material: the bead is drawn as given."""
    n = len(tp)
    return Flow("none", np.zeros(n), np.zeros(n), None, None, None, [])


__all__ = ["MODELS", "ProcessSettings", "ProcessPlan", "plan_process", "fixed_beads", "chord_tolerance", "row_areas"]
