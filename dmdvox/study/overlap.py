"""Overlap study: a patch of parallel beads per (spacing, layer step), measured at its centre.

The patch
    ``layers`` layers of ``n`` parallel beads along +X, bead k of every layer at
    ``y = (k - n // 2) * spacing`` and layer l at ``z = l * layer_step`` (Z is the bead bottom;
    the substrate is the plane z = 0), deposited with the same engine as ``simulate``, under
    one of two models:

    * ``union`` (geometric): every bead at its programmed position, the profile at ``--width``
      x ``--height``, joined by a geometric union: overlap is lost, nothing is redistributed;
    * ``flow`` (mass conserved, :mod:`dmdvox.process.landing`): every bead carries the area
      ``--area`` (default: the profile's own) and lands on the patch as it stands, so overlap
      goes up, layers grow by ``A / d`` whatever the programmed step, and gaps deeper than the
      melt reaches stay as lack of fusion. Rows add ``layer_height_mm`` (the mean growth per
      layer of the central bead over the layers above the first) and
      ``lack_of_fusion_percent`` (the empty fraction below the top: voids between beads).

    A bead reaches only ``w / 2`` to each side, so the central period ``|y| <= d / 2`` only sees
    beads with ``|k| d <= (w + d) / 2``; the patch has at least that many beads on each side
    (and never fewer than 3), so it is free of lateral edge effects by construction. Along X
    the window ``|x| <= w / 8`` is one bead width away from where each bead's straight part ends
    (the round end caps begin there), so the ends cannot reach it either.

Measurements (over the window: ``|x| <= w / 8`` and one bead period ``|y| <= d / 2``)
    * top surface: per voxel column the highest zero crossing of the SDF, linearly
      interpolated between the voxel centres around it (sub-voxel); a column without material
      has its top on the substrate (z = 0). Heights are above the substrate.
    * ``mean_height_mm``: the top surface averaged over the window. The section is the same at
      every x of the window, so the SDF is first averaged along x into one (y, z) section; the
      profile across Y is then integrated over exactly one period (linear interpolation
      between columns, walls placed sub-voxel), which removes the bias of a period that is not
      a whole number of voxels.
    * ``waviness_mm``: peak-to-valley of that profile. Where beads meet, the valley is a cusp
      between voxel columns; the extreme sample is refined by intersecting the secants on
      either side of it (exact for a cusp, off by O(voxel^2 * curvature) at a smooth extreme).
    * ``porosity_percent``: the empty fraction of the volume between the substrate and the top
      surface, ``100 * empty / (empty + filled)`` over the window. The empty length of a column
      is where the SDF, linearly interpolated along Z, is positive below its top. These voids
      (lack of fusion between beads and layers) run along the beads and open at the patch ends,
      so they are not enclosed pores; the enclosed-pore analysis of ``simulate`` would not see
      them.
    * ``overlap_ratio = 1 - d / w`` and ``flat_top_spacing_mm = A / h`` (the spacing at which
      the flat-top model of Suryakumar et al. 2011 fills each layer exactly).

Tasks (:func:`overlap_case`) are pure functions of an :class:`OverlapCase`: same case, same
row, bit for bit, wherever they run (the engine's result does not depend on the thread count).
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass

import numpy as np

from ..deposit.engine import deposit, deposit_beads
from ..process.beads import RowSections, build_beads, section_height
from ..process.flow import given_area
from ..process.landing import LandingSettings, land
from ..process.profiles import BeadProfile, profile_code
from ..errors import DmdvoxError
from ..grid.enclosure import dense_empty_fraction
from ..grid.sparse import BLOCK, SparseGrid
from ..toolpath.model import NO_FEATURE, LINEAR, ArcTable, Toolpath

MIN_BEADS_PER_SIDE = 3
FLOW_SETTLING_WIDTHS = 2.0
WINDOW_HALF_LENGTH_WIDTHS = 1 / 8  # window |x| <= w/8: a few dozen voxel columns at w/voxel = 40..100
END_CLEARANCE_WIDTHS = 1.0  # straight bead beyond the window on each side, in bead widths
DEFAULT_VOXELS_PER_WIDTH = 40.0  # default voxel w/40 (but <= h/8): heights within ~0.01 w
MIN_VOXELS_PER_HEIGHT = 8.0
PERIOD_SAMPLES = 1024  # points of the one-period integral of the interpolated profile
FEED_MM_S = 10.0  # arrival times only order the beads; their value does not enter a measurement

ROW_KEYS = ("spacing_mm", "layer_step_mm", "overlap_ratio", "flat_top_spacing_mm", "mean_height_mm",
            "waviness_mm", "porosity_percent")
FLOW_ROW_KEYS = ROW_KEYS + ("area_mm2", "layer_height_mm", "lack_of_fusion_percent")
MODELS = ("union", "flow")


@dataclass(frozen=True)
class OverlapCase:
    """One point of an overlap study: the bead, the spacing, the layer step, the patch, the voxel."""

    profile: str
    width: float
    height: float
    exponent: float
    spacing: float
    layer_step: float
    layers: int
    voxel: float
    model: str = "union"
    area: float | None = None  # flow model: the beads' cross-section (default: the profile's own)

    def __post_init__(self) -> None:
        for name in ("spacing", "layer_step", "voxel"):
            value = getattr(self, name)
            if not (math.isfinite(value) and value > 0):
                raise DmdvoxError(f"--{name.replace('_', '-')} must be a positive number of mm, got {value}")
        if self.layers < 1:
            raise DmdvoxError(f"--layers must be at least 1, got {self.layers}")
        if self.model not in MODELS:
            raise DmdvoxError(f"--model: the overlap study runs {' or '.join(MODELS)}, got {self.model!r}")
        if self.area is not None and not (math.isfinite(self.area) and self.area > 0):
            raise DmdvoxError(f"--area must be a positive cross-section in mm^2, got {self.area}")

    @property
    def bead(self) -> BeadProfile:
        return BeadProfile(self.profile, self.width, self.height, self.exponent)

    @property
    def bead_area(self) -> float:
        return self.bead.area if self.area is None else float(self.area)


def default_study_voxel(bead: BeadProfile) -> float:
    """The study's default voxel: w/40, but at least 8 voxels over the bead height.

    Finer than ``simulate``'s w/20 because heights and waviness are read off one section; at
    w/40 the parabola's closed forms are met within about 0.01 w (tests use w/100).
    """
    return float(min(bead.width / DEFAULT_VOXELS_PER_WIDTH, bead.height / MIN_VOXELS_PER_HEIGHT))


def beads_per_side(width: float, spacing: float, model: str = "union") -> int:
    """Beads on each side of the central one: all that can reach the central period, at least 3;
    under the flow model also the ones it takes for the layer to reach its steady height (each
    bead rests on the ones before it, as far back as two widths)."""
    reach = math.ceil((width + spacing) / (2 * spacing))
    if model == "flow":
        reach += math.ceil(FLOW_SETTLING_WIDTHS * width / spacing)
    return max(MIN_BEADS_PER_SIDE, reach)


def patch_toolpath(case: OverlapCase) -> Toolpath:
    """The patch as a toolpath: deposit rows only, layer by layer, beads in +Y order, all along +X."""
    w = case.width
    side = beads_per_side(w, case.spacing, case.model)
    x_end = (WINDOW_HALF_LENGTH_WIDTHS + END_CLEARANCE_WIDTHS) * w
    ys = np.arange(-side, side + 1, dtype=np.float64) * case.spacing
    zs = np.arange(case.layers, dtype=np.float64) * case.layer_step
    zz, yy = np.meshgrid(zs, ys, indexing="ij")
    n = zz.size
    start = np.column_stack([np.full(n, -x_end), yy.ravel(), zz.ravel()])
    end = start.copy()
    end[:, 0] = x_end
    duration = 2 * x_end / FEED_MM_S
    t_start = np.arange(n, dtype=np.float64) * duration
    return Toolpath(
        start=start,
        end=end,
        deposit=np.ones(n, np.bool_),
        kind=np.full(n, LINEAR, np.uint8),
        feed=np.full(n, FEED_MM_S, np.float32),
        power=np.ones(n, np.float32),
        t_start=t_start,
        t_end=t_start + duration,
        line=np.arange(1, n + 1, dtype=np.int32),
        layer=np.repeat(np.arange(case.layers, dtype=np.int32), ys.size),
        rotary=np.zeros((n, 3), np.float32),
        arcs=ArcTable.empty(),
        layer_z=zs,
        e_material=np.zeros(n, np.float32),
        dwell_on=np.zeros(n, np.float32),
        width=np.full(n, np.nan, np.float32),
        height=np.full(n, np.nan, np.float32),
        feature=np.full(n, NO_FEATURE, np.uint8),
        source="overlap-study",
        dialect="seed",
    )


def _window_sdf(grid: SparseGrid, x_half: float, y_half: float) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Dense SDF (float32) of the blocks around |x| <= x_half, |y| <= y_half, all of z above the
    substrate; with the world x, y of its columns and z of its voxel layers (float64)."""
    lo_world = np.array([-x_half, -y_half, 0.0])
    hi_world = np.array([x_half, y_half, 0.0])
    lo_index = np.floor(grid.world_to_index(lo_world)).astype(np.int64)
    hi_index = np.ceil(grid.world_to_index(hi_world)).astype(np.int64)
    lo_block = np.maximum(lo_index // BLOCK, 0)
    hi_block = np.minimum(hi_index // BLOCK + 1, grid.block_shape)
    lo_block[2] = max(0, int(lo_index[2] // BLOCK))  # the substrate's block and everything above it
    hi_block[2] = grid.block_shape[2]
    sdf = grid.dense_sdf(lo_block, hi_block)
    first = lo_block * BLOCK
    axes = [grid.origin[a] + grid.voxel * (first[a] + np.arange(sdf.shape[a], dtype=np.float64)) for a in range(3)]
    return sdf, axes[0], axes[1], axes[2]


def column_profiles(section: np.ndarray, z: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Per column j of a (ny, nz) section, from the substrate up (``z`` ascending, uniform,
    starting at or below 0): the top surface height, the empty length between z = 0 and it,
    and whether the column holds material at all.

    The top is where the SDF, linear between voxel centres along Z, crosses zero; the empty
    length sums the cells' empty fractions: both are sub-voxel.
    """
    voxel = float(z[1] - z[0])
    k0 = int(np.searchsorted(z, -0.5 * voxel))  # the voxel layer on the substrate plane
    s = section[:, k0:]
    inside = s <= 0.0
    has = inside.any(axis=1)
    k_top = s.shape[1] - 1 - np.argmax(inside[:, ::-1], axis=1)
    below = np.take_along_axis(s, k_top[:, None], axis=1)[:, 0]
    above = np.take_along_axis(s, np.minimum(k_top + 1, s.shape[1] - 1)[:, None], axis=1)[:, 0]
    # below <= 0 < above: the crossing is below / (below - above) of a voxel up from k_top.
    rise = np.where(above > below, below / np.where(above > below, below - above, 1.0), 0.0)
    top = np.where(has, z[k0 + k_top] + rise * voxel, 0.0)

    # Empty length below k_top: the cells' empty fractions as the pore analysis counts them
    # (grid/enclosure.py), cut by the substrate plane: linear interpolation between samples
    # misses a void thinner than a voxel (0 % at a 0.2 mm voxel where 5.7 % is there).
    frac = dense_empty_fraction(section, voxel, z, 0.0)[:, k0:]
    below_top = np.arange(s.shape[1])[None, :] < k_top[:, None]
    empty = np.where(has, voxel * np.sum(frac * below_top, axis=1), 0.0)
    return top, empty, has


def with_walls(section: np.ndarray, y: np.ndarray, top: np.ndarray, empty: np.ndarray,
               has: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Profiles across Y with the edges of the material placed sub-voxel.

    Where a column with material meets one without (d > w), the top may drop by several layers
    at once: a wall. Linear interpolation between the two columns would put it half a voxel
    out on average, biasing the mean and the porosity by ~(wall height) * voxel / 2 per wall.
    The wall sits at the outermost material, found per voxel row from the SDF's zero crossing
    between the two columns (linear in Y); the profiles step down there.

    The wall passes through the cells of the column beside it, so their empty fractions are
    partly the air beyond the wall, which the profile already leaves out: that column's empty
    length is the one on its centre line (where the SDF, linear between voxel centres along Z,
    is positive below its top) instead.
    """
    ys, tops, empties = [y], [top], [empty.copy()]
    step = float(y[1] - y[0])
    for j in np.flatnonzero(has[:-1] != has[1:]):
        solid, void = (j, j + 1) if has[j] else (j + 1, j)
        a = section[solid]
        b = section[void]
        empties[0][solid] = _centre_line_empty(a, top[solid], step)
        rows = (a <= 0.0) & (b > 0.0)
        reach = float(np.max(a[rows] / (a[rows] - b[rows]))) * step  # from the solid column outwards
        edge = y[solid] + (reach if void > solid else -reach)
        outside = edge + (1e-9 if void > solid else -1e-9) * step
        ys += [np.array([edge, outside])]
        tops += [np.array([top[solid], 0.0])]
        empties += [np.array([empty[solid], 0.0])]
    y_all = np.concatenate(ys)
    order = np.argsort(y_all, kind="stable")
    return y_all[order], np.concatenate(tops)[order], np.concatenate(empties)[order]


def _centre_line_empty(column: np.ndarray, top: float, voxel: float) -> float:
    """Length of the centre line of a column (SDF samples one voxel apart from z = 0 up) where
    the SDF, linear between samples, is positive below ``top``."""
    lo, hi = column[:-1].astype(np.float64), column[1:].astype(np.float64)
    z_lo = voxel * np.arange(len(lo), dtype=np.float64)
    both = (lo > 0.0) & (hi > 0.0)
    crossing = (lo > 0.0) != (hi > 0.0)
    # positive share of a segment whose ends differ in sign
    share = np.where(crossing, np.maximum(lo, hi) / np.where(crossing, np.abs(hi - lo), 1.0), 0.0)
    length = np.where(both, 1.0, share) * voxel
    return float(np.sum(length * (z_lo + voxel <= top + 1e-12 * voxel)))


def _period_mean(y: np.ndarray, f: np.ndarray, period: float) -> float:
    """Mean over |y| <= period / 2 of the piecewise-linear interpolant of samples f(y)."""
    u = (np.arange(PERIOD_SAMPLES, dtype=np.float64) + 0.5) / PERIOD_SAMPLES
    return float(np.mean(np.interp(period * (u - 0.5), y, f)))


def _refined_min(y: np.ndarray, f: np.ndarray, lo: float, hi: float) -> float:
    """Minimum of f over lo <= y <= hi, refined between samples by the secants on either side."""
    candidates = np.flatnonzero((y >= lo) & (y <= hi))
    candidates = candidates[(candidates >= 2) & (candidates <= len(y) - 3)]
    m = int(candidates[np.argmin(f[candidates])])
    best = float(f[m])
    # The extreme between samples lies towards the lower neighbour: lines through the two samples
    # on each side of that interval.
    if f[m - 1] < f[m + 1]:
        left, right = (m - 2, m - 1), (m, m + 1)
    else:
        left, right = (m - 1, m), (m + 1, m + 2)
    sl = (f[left[1]] - f[left[0]]) / (y[left[1]] - y[left[0]])
    sr = (f[right[1]] - f[right[0]]) / (y[right[1]] - y[right[0]])
    if sl >= sr:  # not a valley between the two lines (parallel or opening downwards)
        return best
    y_cross = (f[right[0]] - f[left[1]] + sl * y[left[1]] - sr * y[right[0]]) / (sl - sr)
    if not y[left[1]] <= y_cross <= y[right[0]]:
        return best
    return min(best, float(f[left[1]] + sl * (y_cross - y[left[1]])))


def measure(grid: SparseGrid, width: float, spacing: float) -> dict:
    """Top-surface mean and peak-to-valley, and porosity below it, over the central window."""
    v = grid.voxel
    x_half = WINDOW_HALF_LENGTH_WIDTHS * width
    # Secants reach two columns beyond the period; a few more keep the interpolation inside.
    y_half = 0.5 * spacing + 4 * v
    sdf, x, y, z = _window_sdf(grid, x_half, y_half)
    # The section is the same at every x of the window; averaging it over the window's columns
    # rather than trusting one column only guards against a stray end effect.
    section = sdf[np.abs(x) <= x_half + 1e-9 * v].mean(axis=0, dtype=np.float64)
    top, empty, has = column_profiles(section, z)
    half = 0.5 * spacing + 1e-9 * v
    # The profile is periodic: extremes over a closed period are its extremes anywhere.
    peak = -_refined_min(y, -top, -half, half)
    valley = max(_refined_min(y, top, -half, half), 0.0)  # no top lies below the substrate
    k0 = int(np.searchsorted(z, -0.5 * v))
    y_w, top_w, empty_w = with_walls(section[:, k0:], y, top, empty, has)
    mean_height = _period_mean(y_w, top_w, spacing)
    mean_empty = _period_mean(y_w, empty_w, spacing)
    return {
        "mean_height_mm": mean_height,
        "waviness_mm": peak - valley,
        "porosity_percent": 100.0 * mean_empty / mean_height if mean_height > 0 else 0.0,
    }


def overlap_case(case: OverlapCase) -> dict:
    """Simulate one patch and measure it: one row of the study (a plain dict of floats)."""
    bead = case.bead
    tp = patch_toolpath(case)
    row = {
        "spacing_mm": float(case.spacing),
        "layer_step_mm": float(case.layer_step),
        "overlap_ratio": 1.0 - case.spacing / bead.width,
    }
    if case.model == "union":
        grid, _ = deposit(tp, bead, case.voxel)
        row["flat_top_spacing_mm"] = bead.area / bead.height
        row.update(measure(grid, bead.width, case.spacing))
        return {key: float(row[key]) for key in ROW_KEYS}
    beads, _ = _landed_patch(tp, case)
    grid, _ = deposit_beads(beads, case.voxel)
    area = case.bead_area
    height = float(section_height(bead.code, np.array([bead.width]), np.array([area]), bead.exponent)[0])
    row["flat_top_spacing_mm"] = area / height
    row.update(measure(grid, bead.width, case.spacing))
    row["area_mm2"] = area
    row["layer_height_mm"] = row["mean_height_mm"]
    if case.layers > 1:
        # growth per layer above the first, which lands on the flat substrate
        first_layer_done = float(tp.t_end[tp.layer == 0].max())
        first, _ = deposit_beads(beads.until(first_layer_done), case.voxel)
        row["layer_height_mm"] = (row["mean_height_mm"] - measure(first, bead.width, case.spacing)["mean_height_mm"]) / (
            case.layers - 1)
    row["lack_of_fusion_percent"] = row["porosity_percent"]
    return {key: float(row[key]) for key in FLOW_ROW_KEYS}


def _landed_patch(tp: Toolpath, case: OverlapCase):
    """The patch's beads carrying the case's area, landed on the substrate at z = 0."""
    bead = case.bead
    n = len(tp)
    sections = RowSections(np.full(n, bead.width), np.full(n, np.nan), np.zeros(n))
    chord = min(0.01, case.voxel / 4)
    beads = build_beads(tp, bead, sections, given_area(tp, case.bead_area), None, chord)
    # a study patch is a geometric experiment: however far a layer drops, it reaches the patch
    settings = LandingSettings(plate_z=0.0, max_drop_mm=math.inf)
    return land(beads, case.voxel, settings)


def overlap_cases(profile: str, width: float, exponent: float, spacings, steps, layers: int, *,
                  height: float | None = None, area: float | None = None, model: str | None = None,
                  voxel: float | None = None) -> list[OverlapCase]:
    """The study's cases, spacing-major then layer step: beads of ``height``, or under the flow
    model of cross-section ``area`` (their height follows from it); ``steps`` None: the bead
    height; ``voxel`` None: :func:`default_study_voxel`."""
    model = model or ("flow" if area is not None else "union")
    if area is not None:
        if model == "union":
            raise DmdvoxError("--area sets the material the flow model lands; the union model takes --height")
        if height is not None:
            raise DmdvoxError("--area and --height both set the bead's height: give one")
        height = float(section_height(profile_code(profile), np.array([float(width)]), np.array([float(area)]),
                                      exponent)[0])
    elif height is None:
        raise DmdvoxError("give --height (or --area for a flow study)")
    bead = BeadProfile(profile, width, height, exponent)
    steps = [bead.height] if steps is None else steps
    voxel = default_study_voxel(bead) if voxel is None else float(voxel)
    return [OverlapCase(bead.name, bead.width, bead.height, bead.exponent, float(d), float(s), int(layers), voxel,
                        model=model, area=area)
            for d in spacings for s in steps]


@dataclass(frozen=True)
class OverlapStudy:
    """The study's table: one row per case (``ROW_KEYS``, or ``FLOW_ROW_KEYS`` under the flow
    model) and, for a flow study, the geometric union of the same beads beside it."""

    model: str
    rows: list[dict]
    union_rows: list[dict] | None = None

    @property
    def keys(self) -> tuple[str, ...]:
        return FLOW_ROW_KEYS if self.model == "flow" else ROW_KEYS

    def to_json(self) -> dict:
        out = {"model": self.model, "rows": self.rows}
        if self.union_rows is not None:
            out["union_rows"] = self.union_rows
        return out


def overlap_study(cases: list[OverlapCase], scheduler: str | None = None) -> OverlapStudy:
    """Every case as a task, on local processes or on the dask cluster at ``scheduler``."""
    from ..tasks import run_tasks

    flow = cases[0].model == "flow"
    # a flow study also runs the geometric union of the same beads, for the plot and the JSON
    union_cases = [dataclasses.replace(c, model="union", area=None) for c in cases] if flow else []
    results = run_tasks(overlap_case, cases + union_cases, scheduler, desc="overlap study")
    return OverlapStudy(cases[0].model, results[:len(cases)], results[len(cases):] if flow else None)
