"""The material each toolpath row delivers, from the first source that applies.

Sources, in order (``Flow.source``):

``e``
    E words (the reprap dialect, and ``auto`` once E appears): the row's E advance that is
    material (retracts and the re-primes that repay them deliver nothing, see the G-code
    kernel) times the filament (or wire) cross-section ``pi d^2 / 4``. The diameter comes from
    ``--filament-diameter``, else the slicer's own header or settings comment, else 1.75 mm
    with a warning (an error under ``--strict``).
``powder``
    Powder DED: ``--powder-rate G_MIN`` is the powder mass flow while the beam is on,
    ``--density G_CM3`` the alloy's density, ``--catchment ETA`` the fraction of the powder the
    melt pool catches (1.0 by default: the delivered rate is then an upper bound; measured DED
    catchment is 0.3-0.9). Volume rate ``Q = ETA * rate / density``.
``wire``
    Wire DED / WAAM: ``Q = pi d^2 / 4 * feed`` from ``--wire-diameter`` and ``--wire-feed``.
``area``
    A cross-section area given directly (``study overlap --area``): each row carries that area
    times its length.
``comments``
    No material source, but slicer ``;WIDTH:`` / ``;HEIGHT:`` comments: the bead is that width
    and height wherever they are given.
``none``
    The bead is the fixed cross-section of ``--width`` and ``--height``, as before.

For a rate source the material does not depend on the travel speed: a row delivers ``Q`` times
its (planned) duration, and where the tool slows, more material lands per mm. A beam-on dwell
before a row (``Toolpath.dwell_on``) delivers ``Q t`` at that point.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from ..errors import DmdvoxError, ParameterError
from ..toolpath.model import Toolpath

DEFAULT_FILAMENT_DIAMETER_MM = 1.75
# Beyond these the number is a typo or a unit mix-up (inch, g/s), not a machine setting.
FILAMENT_DIAMETER_RANGE_MM = (0.1, 5.0)
WIRE_DIAMETER_RANGE_MM = (0.1, 6.0)
WIRE_FEED_RANGE_MM_MIN = (1.0, 100_000.0)
POWDER_RATE_RANGE_G_MIN = (0.01, 1000.0)
DENSITY_RANGE_G_CM3 = (0.5, 25.0)

SOURCES = ("e", "powder", "wire", "area", "comments", "none")


def _in_range(value, bounds, option: str, unit: str) -> float:
    try:
        x = float(value)
    except (TypeError, ValueError):
        raise ParameterError(f"{{{option}}} must be a number of {unit}, got {value!r}", option) from None
    lo, hi = bounds
    if not math.isfinite(x) or x <= 0.0:
        raise ParameterError(f"{{{option}}} must be a positive number of {unit}, got {value!r}", option)
    if not lo <= x <= hi:
        raise ParameterError(f"{{{option}}} {x:g} {unit} is outside {lo:g}..{hi:g} {unit}: check the value and its "
                             "unit", option)
    return x


@dataclass(frozen=True)
class FlowSettings:
    """The material options of a run (all optional; see the module docstring)."""

    filament_diameter_mm: float | None = None
    powder_rate_g_min: float | None = None
    density_g_cm3: float | None = None
    catchment: float = 1.0
    wire_diameter_mm: float | None = None
    wire_feed_mm_min: float | None = None
    strict: bool = False

    def validate(self) -> None:
        if self.filament_diameter_mm is not None:
            _in_range(self.filament_diameter_mm, FILAMENT_DIAMETER_RANGE_MM, "filament_diameter_mm", "mm")
        if (self.powder_rate_g_min is None) != (self.density_g_cm3 is None):
            raise ParameterError("{powder_rate_g_min} and {density_g_cm3} go together: the volume rate is catchment x "
                                 "rate / density",
                                 "powder_rate_g_min" if self.powder_rate_g_min is None else "density_g_cm3",
                                 also=("powder_rate_g_min", "density_g_cm3"))
        if self.powder_rate_g_min is not None:
            _in_range(self.powder_rate_g_min, POWDER_RATE_RANGE_G_MIN, "powder_rate_g_min", "g/min")
            _in_range(self.density_g_cm3, DENSITY_RANGE_G_CM3, "density_g_cm3", "g/cm^3")
        catchment = float(self.catchment)
        if not (math.isfinite(catchment) and 0.0 < catchment <= 1.0):
            raise ParameterError(f"{{catchment}} is the fraction of the powder the melt pool catches, in (0, 1]; "
                                 f"got {self.catchment!r}", "catchment")
        if (self.wire_diameter_mm is None) != (self.wire_feed_mm_min is None):
            raise ParameterError("{wire_diameter_mm} and {wire_feed_mm_min} go together: the volume rate is "
                                 "pi d^2 / 4 x feed",
                                 "wire_diameter_mm" if self.wire_diameter_mm is None else "wire_feed_mm_min",
                                 also=("wire_diameter_mm", "wire_feed_mm_min"))
        if self.wire_diameter_mm is not None:
            _in_range(self.wire_diameter_mm, WIRE_DIAMETER_RANGE_MM, "wire_diameter_mm", "mm")
            _in_range(self.wire_feed_mm_min, WIRE_FEED_RANGE_MM_MIN, "wire_feed_mm_min", "mm/min")
            if self.powder_rate_g_min is not None:
                raise ParameterError("give either powder ({powder_rate_g_min}, {density_g_cm3}) or wire "
                                     "({wire_diameter_mm}, {wire_feed_mm_min})", "wire_diameter_mm",
                                     also=("powder_rate_g_min", "density_g_cm3", "wire_feed_mm_min"))

    @property
    def rate_source(self) -> str | None:
        if self.powder_rate_g_min is not None:
            return "powder"
        if self.wire_diameter_mm is not None:
            return "wire"
        return None

    @property
    def rate_mm3_s(self) -> float:
        """The volume rate of a rate source, mm^3/s."""
        if self.powder_rate_g_min is not None:
            # g/min -> g/s; g/cm^3 -> g/mm^3
            return float(self.catchment) * self.powder_rate_g_min / 60.0 / (self.density_g_cm3 / 1000.0)
        if self.wire_diameter_mm is not None:
            return math.pi * self.wire_diameter_mm**2 / 4.0 * self.wire_feed_mm_min / 60.0
        raise ValueError("no rate source")

    def to_json(self) -> dict:
        return {k: v for k, v in self.__dict__.items() if v is not None and k != "strict"}


@dataclass(frozen=True, eq=False)
class Flow:
    """Material per row. ``volume`` (mm^3) is what each deposit row delivers while moving,
    ``dwell_volume`` what collects at its start point during a beam-on dwell before it."""

    source: str
    volume: np.ndarray  # (n,) float64
    dwell_volume: np.ndarray  # (n,) float64
    rate_mm3_s: float | None  # rate sources
    filament_diameter_mm: float | None  # E source
    diameter_source: str | None  # "option", "header" or "default"
    warnings: list[str] = field(default_factory=list)

    @property
    def from_material(self) -> bool:
        """Whether the bead's size comes from the material (else from --width/--height or comments)."""
        return self.source in ("e", "powder", "wire", "area")

    @property
    def deposited_volume_mm3(self) -> float:
        return float(self.volume.sum() + self.dwell_volume.sum())

    def to_json(self) -> dict:
        out = {"flow_source": self.source, "deposited_volume_mm3": self.deposited_volume_mm3}
        if self.rate_mm3_s is not None:
            out["rate_mm3_s"] = self.rate_mm3_s
        if self.filament_diameter_mm is not None:
            out["filament_diameter_mm"] = self.filament_diameter_mm
            out["filament_diameter_source"] = self.diameter_source
        return out


def given_area(tp: Toolpath, area_mm2: float) -> Flow:
    """Every deposit row carries ``area_mm2`` times its length (a study's given cross-section)."""
    volume = np.where(tp.deposit, float(area_mm2) * tp.length, 0.0)
    return Flow("area", volume, np.zeros(len(tp)), None, None, None, [])


def material_flow(tp: Toolpath, settings: FlowSettings) -> Flow:
    """The material of every row of ``tp`` (planned times, for rate sources)."""
    settings.validate()
    n = len(tp)
    zeros = np.zeros(n, np.float64)
    has_e = tp.dialect == "reprap" and bool(np.any(tp.e_material > 0))
    if has_e:
        if settings.rate_source is not None:
            raise DmdvoxError(f"{tp.source}: the program meters its material with E words; "
                              f"--{settings.rate_source} options would meter it twice: drop them")
        diameter, where, warnings = _filament_diameter(tp, settings)
        volume = tp.e_material.astype(np.float64) * (math.pi * diameter**2 / 4.0)
        return Flow("e", volume, zeros, None, diameter, where, warnings)
    if settings.rate_source is not None:
        q = settings.rate_mm3_s
        volume = np.where(tp.deposit, q * (tp.t_end - tp.t_start), 0.0)
        dwell = q * tp.dwell_on.astype(np.float64)
        return Flow(settings.rate_source, volume, dwell, q, None, None, [])
    has_comments = bool(np.any(np.isfinite(tp.width[tp.deposit]) | np.isfinite(tp.height[tp.deposit])))
    return Flow("comments" if has_comments else "none", zeros, zeros, None, None, None, [])


def _filament_diameter(tp: Toolpath, settings: FlowSettings) -> tuple[float, str, list[str]]:
    if settings.filament_diameter_mm is not None:
        return float(settings.filament_diameter_mm), "option", []
    header = tp.meta.get("filament_diameter_mm")
    if header is not None:
        lo, hi = FILAMENT_DIAMETER_RANGE_MM
        if not lo <= header <= hi:
            raise DmdvoxError(f"{tp.source}: the header's filament diameter {header:g} mm is outside {lo:g}..{hi:g} "
                              "mm; give the real one with --filament-diameter")
        return float(header), "header", []
    message = (f"{tp.source}: E words meter the material but no filament diameter is given (no "
               f"--filament-diameter, none in the file's header); {DEFAULT_FILAMENT_DIAMETER_MM:g} mm assumed")
    if settings.strict:
        raise DmdvoxError(message.replace("assumed", "would be assumed: give --filament-diameter (--strict)"))
    return DEFAULT_FILAMENT_DIAMETER_MM, "default", [message]
