"""`dmdvox thermal`: the thermal history of a planned program on its deposit.

:func:`thermal_history` builds the lattice and the beam (:mod:`.build`), runs the solver
(:mod:`.solver`) and measures, while it runs:

* per layer: its first G-code line, the interlayer temperature (the mean temperature of the layer's top cells, the
  column tops it laid, when the next layer starts), its peak (the highest temperature any of its
  cells reached) and the time from its end until that mean falls below ``interpass`` (None: not
  within the run);
* per deposit row, at its middle: the melt pool, the extent of the cells at or above the liquidus
  within ``POOL_REACH`` beam radii of the beam, along the row (length), across it (width) and
  in z (depth), cell edges included (0 when no cell is liquid);
* at the probe points, the temperature at every sample time;
* the energy balance at every sample time: absorbed, stored, lost.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from ..errors import DmdvoxError, ResourceError
from ..grid.sparse import SparseGrid
from ..memory import budget, budget_phrase
from ..process.plan import ProcessPlan
from .build import PlateSpec, beam_path, deposit_lattice, lattice_bytes, thermal_voxel
from .lattice import Lattice
from .materials import Material
from .solver import HeatSettings, HeatState, SourcePath, run, start

POOL_REACH = 4.0  # beam radii
DEFAULT_SAMPLE_S = 0.25


@dataclass(frozen=True)
class ThermalRequest:
    """What to heat: ``plan`` deposited as ``grid``, with ``material`` and ``settings``."""

    plan: ProcessPlan
    grid: SparseGrid
    material: Material
    settings: HeatSettings = HeatSettings()
    voxel: float | None = None  # thermal voxel (default a quarter of the bead width)
    plate: PlateSpec = PlateSpec()
    plate_top: float | None = None
    laser_power: float | None = None
    probes: tuple = ()
    interpass: float | None = None
    sample_s: float = DEFAULT_SAMPLE_S
    cool_s: float = 0.0  # run on after the program ends
    max_memory: int | None = None


@dataclass(frozen=True, eq=False)
class ThermalResult:
    """The run's results: per cell (lattice order), per layer, per row, per sample."""

    lattice: Lattice
    state: HeatState
    path: SourcePath
    layers: list[dict]
    pools: list[dict]
    samples: np.ndarray  # (s,) sample times
    probe_T: np.ndarray  # (s, p)
    energy: list[dict]
    probes: tuple
    material: Material
    settings: HeatSettings

    def summary(self) -> dict:
        st = self.state
        born = np.arange(len(self.lattice)) < st.n_born
        part = born & np.isfinite(self.lattice.birth)
        widths = [p["width_mm"] for p in self.pools]
        il = [row["interlayer_C"] for row in self.layers if row["interlayer_C"] is not None]
        worst = max(abs(e["balance_percent"]) for e in self.energy) if self.energy else 0.0
        return {
            "material": self.material.to_json(),
            "thermal_voxel_mm": self.lattice.voxel,
            "time_step_s": st.dt,
            "cells": len(self.lattice),
            "part_cells": int(np.count_nonzero(np.isfinite(self.lattice.birth))),
            "plate_cells": int(np.count_nonzero(~np.isfinite(self.lattice.birth) & (self.lattice.birth < 0))),
            "steps": int(round(st.time / st.dt)),  # from t = 0
            "duration_s": st.time,
            "absorptivity": self.settings.absorptivity,
            "beam_energy_J": self.path.energy,
            "absorbed_J": st.absorbed,
            "birth_heat_unpaid_J": st.unpaid,
            "boiled_J": st.boiled,
            "stored_J": st.stored - st.initial_stored,
            "lost_J": st.lost,
            "energy_balance_max_percent": worst,
            "max_peak_temperature_C": float(np.max(st.peak[part])) if part.any() else None,
            "max_interlayer_temperature_C": max(il) if il else None,
            "max_melt_pool_width_mm": max(widths) if widths else None,
            "layers": self.layers,
            "remelted_cells": int(np.count_nonzero(st.remelts[part] > 0)),
        }


# the heat options by their command-line names (``dmdvox thermal``, the cell file's [thermal] table)
OPTION_KEYS = ("material", "laser_power", "absorptivity", "beam_radius", "thermal_voxel", "plate_size",
               "plate_bottom", "preheat", "ambient", "convection", "emissivity", "interpass", "probe", "cool",
               "source", "goldak")


def thermal_request(plan: ProcessPlan, grid: SparseGrid, options: dict, plate_top: float | None = None,
                    max_memory: int | None = None) -> ThermalRequest:
    """A request from the heat options (:data:`OPTION_KEYS`; missing ones at their defaults)."""
    from .build import parse_plate_size
    from .materials import load_material

    unknown = sorted(set(options) - set(OPTION_KEYS))
    if unknown:
        raise DmdvoxError(f"[thermal]: unknown key {unknown[0]!r}; known: {', '.join(OPTION_KEYS)}")
    if options.get("material") is None:
        raise DmdvoxError("--material: the heat model needs the alloy: 316L, IN718, Ti64 or a TOML file")
    material = load_material(str(options["material"]))

    def number(key, default=None):
        value = options.get(key)
        if value is None:
            return default
        try:
            return float(value)
        except (TypeError, ValueError):
            raise DmdvoxError(f"--{key.replace('_', '-')}: {value!r} is not a number") from None

    cool = number("cool", 0.0)
    if not math.isfinite(cool) or cool < 0:
        raise DmdvoxError(f"--cool: {cool:g} s; give a time >= 0")
    radius = number("beam_radius")
    defaults = HeatSettings()
    settings = HeatSettings(
        absorptivity=number("absorptivity", defaults.absorptivity),
        beam_radius=plan.profile.width / 2 if radius is None else radius,
        ambient=number("ambient", defaults.ambient), preheat=number("preheat"),
        convection=number("convection", defaults.convection), emissivity=number("emissivity", defaults.emissivity),
        bottom=str(options.get("plate_bottom") or defaults.bottom),
        source=str(options.get("source") or defaults.source), goldak=_axes(options.get("goldak")))
    settings.validate()
    plate = options.get("plate_size")
    if plate is not None and not isinstance(plate, PlateSpec):
        plate = parse_plate_size(",".join(map(str, plate)) if isinstance(plate, (list, tuple)) else str(plate))
    return ThermalRequest(plan, grid, material, settings, voxel=number("thermal_voxel"),
                          plate=PlateSpec() if plate is None else plate, plate_top=plate_top,
                          laser_power=number("laser_power"), probes=tuple(options.get("probe") or ()),
                          interpass=number("interpass"), cool_s=cool, max_memory=max_memory)


def _axes(value):
    """``--goldak A_F,A_R,B,C`` (text or a list) as four numbers (None: the default)."""
    if value is None:
        return None
    parts = value.split(",") if isinstance(value, str) else list(value)
    try:
        return tuple(float(v) for v in parts)
    except (TypeError, ValueError):
        raise DmdvoxError(f"--goldak: {value!r}; give A_F,A_R,B,C, four semi-axes in mm > 0") from None


def thermal_history(request: ThermalRequest) -> ThermalResult:
    plan, grid = request.plan, request.grid
    settings = request.settings
    settings.validate()
    m, _ = thermal_voxel(grid, request.voxel, plan.profile.width)
    plate_top = request.plate_top
    if plate_top is None:
        bottoms = plan.layer_bottoms()
        plate_top = float(bottoms.min()) if bottoms.size else 0.0
    check_lattice_memory(grid, m, plate_top, request.plate, plan.profile.width, request.max_memory)
    tp = plan.toolpath
    lattice = deposit_lattice(grid, m, plate_top, request.plate, end=float(tp.duration))
    path = beam_path(plan, request.laser_power)
    until = float(tp.duration) + float(request.cool_s)
    return solve_history(lattice, request.material, settings, path, plan, until, request.probes,
                         request.interpass, request.sample_s)


def check_lattice_memory(grid: SparseGrid, m: int, plate_top: float, plate: PlateSpec, bead_width: float,
                         max_memory: int | None) -> None:
    """Refuse, before anything is allocated, a lattice beyond the budget, naming a thermal voxel
    that fits: its cells scale as 1 / voxel^3 (the box in x, y and z)."""
    need = lattice_bytes(grid, m, plate_top, plate)
    allowed = budget(max_memory)
    if need <= allowed:
        return
    v = grid.voxel
    fits = math.ceil(m * (need / allowed) ** (1 / 3) * 1.1) * v
    advice = f"give --thermal-voxel {fits:g} or coarser" if fits <= bead_width else \
        f"even --thermal-voxel {bead_width:g} (the bead width) would not fit"
    raise ResourceError(f"--thermal-voxel {m * v:g}: the thermal lattice needs up to {need / 2**30:.3g} GiB but "
                        f"{budget_phrase(max_memory)}; {advice}, a smaller --plate-size or raise {{max_memory_gib}}",
                        parameter="max_memory_gib")


def solve_history(lattice: Lattice, material: Material, settings: HeatSettings, path: SourcePath,
                  plan: ProcessPlan | None, until: float, probes=(), interpass: float | None = None,
                  sample_s: float = DEFAULT_SAMPLE_S) -> ThermalResult:
    """Run the solver to ``until`` with the measurements of the module docstring (``plan``
    gives the layers and rows; None: samples, probes and energy only)."""
    t_begin = 0.0
    state = start(lattice, material, settings, t_begin)
    if not math.isfinite(until) or until <= t_begin:
        raise DmdvoxError(f"the run ends at {until:g} s: nothing to heat")
    samples = list(np.arange(t_begin + sample_s, until, sample_s))
    layers_info, row_mid, first_lines = _layer_times(plan) if plan is not None else ([], {}, [])
    layer_starts = {t: k for k, (t, _) in enumerate(layers_info)}
    stops = sorted(set(samples) | set(layer_starts) | set(row_mid))
    probe_cells = lattice.index_of(np.asarray(probes, np.float64).reshape(-1, 3)) if len(probes) else np.zeros(0, np.int64)
    table = lattice.id_table()
    born_layer = _cell_layers(lattice, layers_info)
    layer_tops: dict[int, np.ndarray] = {}
    interlayer: dict[int, float] = {}
    cooled: dict[int, float] = {}
    pools: list[dict] = []
    sample_times: list[float] = []
    probe_rows: list[np.ndarray] = []
    energy: list[dict] = []
    sample_set = set(samples)

    def top_cells_of(layer: int) -> np.ndarray:
        tops = state.top.reshape(-1)
        tops = tops[tops >= 0]
        return tops[born_layer[tops] == layer]

    def on_stop(st: HeatState, stop: float) -> None:
        t = st.time
        k = layer_starts.get(stop)
        if k is not None and k > 0:
            tops = top_cells_of(k - 1)
            layer_tops[k - 1] = tops
            interlayer[k - 1] = float(np.mean(st.temperature_at(tops))) if tops.size else math.nan
        if stop in row_mid:
            pools.append(_melt_pool(st, table, path, plan, row_mid[stop], t))
        if stop in sample_set:
            sample_times.append(t)
            probe_rows.append(st.temperature_at(probe_cells))
            stored = st.stored - st.initial_stored
            lost = st.lost
            absorbed = st.absorbed
            energy.append({"time_s": t, "absorbed_J": absorbed, "stored_J": stored, "lost_J": lost,
                           "balance_percent": 100.0 * (absorbed - stored - lost) / absorbed if absorbed > 0 else 0.0})
            if interpass is not None:
                for k, (_, end) in enumerate(layers_info):
                    if k in cooled or t < end:
                        continue
                    tops = layer_tops.get(k)
                    if tops is None:
                        tops = layer_tops[k] = top_cells_of(k)
                    if tops.size and np.nanmean(st.temperature_at(tops)) < interpass:
                        cooled[k] = t - end

    run(state, path, until, stops, on_stop)
    layers = []
    for k, (t0, end) in enumerate(layers_info):
        cells = np.flatnonzero(born_layer == k)
        layers.append({"layer": k, "first_line": first_lines[k], "start_s": t0, "end_s": end,
                       "interlayer_C": _finite(interlayer.get(k)),
                       "peak_C": float(np.max(state.peak[cells])) if cells.size else None,
                       "cool_below_interpass_s": cooled.get(k) if interpass is not None else None})
    return ThermalResult(lattice=lattice, state=state, path=path, layers=layers, pools=pools,
                         samples=np.asarray(sample_times), probe_T=np.asarray(probe_rows).reshape(len(sample_times), -1),
                         energy=energy, probes=tuple(tuple(p) for p in probes), material=material, settings=settings)


def _finite(value):
    return None if value is None or not math.isfinite(value) else float(value)


def _layer_times(plan: ProcessPlan) -> tuple[list[tuple[float, float]], dict[float, int], list[int]]:
    """(start, end) of each layer that deposits, in time order, the middle time of every deposit
    row, and each layer's first G-code line (what the report names a hot layer by)."""
    tp = plan.toolpath
    rows = np.flatnonzero(tp.deposit & (tp.length > 0))
    if rows.size == 0:
        return [], {}, []
    layer = tp.layer[rows]
    starts, ends = [], []
    # layers in the order they are laid: a new layer starts where the layer index changes
    change = np.flatnonzero(np.r_[True, layer[1:] != layer[:-1]])
    bounds = np.r_[change, rows.size]
    for a, b in zip(bounds[:-1], bounds[1:]):
        starts.append(float(tp.t_start[rows[a]]))
        ends.append(float(tp.t_end[rows[b - 1]]))
    mids = {float(0.5 * (tp.t_start[r] + tp.t_end[r])): int(r) for r in rows}
    return list(zip(starts, ends)), mids, [int(tp.line[rows[a]]) for a in bounds[:-1]]


def _cell_layers(lattice: Lattice, layers_info) -> np.ndarray:
    """The layer during which each cell was born (-1: the plate, or before the first layer)."""
    if not layers_info:
        return np.full(len(lattice), -1, np.int64)
    starts = np.array([t for t, _ in layers_info])
    out = np.searchsorted(starts, lattice.birth, side="right") - 1
    out[~np.isfinite(lattice.birth)] = -1
    return out


def _melt_pool(st: HeatState, table: np.ndarray, path: SourcePath, plan: ProcessPlan, row: int, t: float) -> dict:
    tp = plan.toolpath
    lat = st.lattice
    where = path.position(t)[0]
    line = int(tp.line[row])
    out = {"row": row, "line": line, "time_s": t, "length_mm": 0.0, "width_mm": 0.0, "depth_mm": 0.0}
    if not np.all(np.isfinite(where)):
        return out
    u = (tp.end[row] - tp.start[row])[:2]
    norm = float(np.hypot(*u))
    u = u / norm if norm > 0 else np.array([1.0, 0.0])
    reach = POOL_REACH * st.settings.beam_radius
    lo = np.maximum(np.floor((where - reach - lat.origin) / lat.voxel).astype(np.int64), 0)
    hi = np.minimum(np.ceil((where + reach - lat.origin) / lat.voxel).astype(np.int64) + 1, np.asarray(lat.shape))
    if np.any(hi <= lo):
        return out
    ids = table[lo[0]:hi[0], lo[1]:hi[1], lo[2]:hi[2]].reshape(-1)
    ids = ids[(ids >= 0) & (ids < st.n_born)]
    T = st.temperature_at(ids)
    liquid = ids[T >= st.material.liquidus]
    if liquid.size == 0:
        return out
    c = lat.centres[liquid] - where
    a = c[:, 0] * u[0] + c[:, 1] * u[1]
    b = -c[:, 0] * u[1] + c[:, 1] * u[0]
    h = lat.voxel
    out.update(length_mm=float(a.max() - a.min() + h), width_mm=float(b.max() - b.min() + h),
               depth_mm=float(c[:, 2].max() - c[:, 2].min() + h))
    return out


__all__ = ["ThermalRequest", "ThermalResult", "check_lattice_memory", "thermal_history", "solve_history", "thermal_request", "OPTION_KEYS"]
