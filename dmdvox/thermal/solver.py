"""The heat solver: explicit finite volumes with element birth, on a :class:`~.lattice.Lattice`.

Model
    Each cell holds its enthalpy per volume H (J/mm^3); T and k follow from H through the
    material's tables (latent heat over the melting range, :mod:`.materials`). Every step:

    * cells whose birth time has come are born at the liquidus (``birth_temperature``); the
      enthalpy they bring above the ambient is drawn from the beam (the absorbed power melts the
      material it adds: the beam's flux pays that first), so absorbed = stored + lost holds;
    * conduction between face neighbours, conductance ``2 k_a k_b / (k_a + k_b) * voxel`` (the
      harmonic mean: the series resistance of two half cells);
    * every face exposed at that moment (no neighbour, or one not yet born) loses
      ``h (T - T_amb) + eps sigma (T^4 - T_amb^4)`` per area;
    * the plate's bottom faces: clamped at ``bottom_temperature`` through half a cell, or
      adiabatic;
    * the beam: absorbed power ``eta P`` as a Gaussian ``exp(-2 r^2 / r_b^2)`` on the tops of
      the columns within 3 r_b of the source, normalised so the cells get exactly eta P dt; or
      (``source="goldak"``, arc processes) Goldak's double ellipsoid (:func:`goldak_density`)
      in the cells of those columns down to twice its depth, each at its centre's depth below
      its column's top face, normalised the same way; no cell is heated past the boiling point.

Time step (stated criterion)
    explicit (forward Euler) is stable when no cell gives away more than it holds in a step:
    ``dt <= C_min / G_max`` with ``C_min = min_T(rho cp) voxel^3`` (latent heat only adds
    capacity) and ``G_max = k_max voxel * 7`` (five neighbours and a clamped bottom, the largest
    sum of a cell's conductances) or ``5 k_max voxel + (h + 4 eps sigma T_max^3) voxel^2`` for an
    exposed face; the solver takes ``cfl`` (0.9) times that bound.

Determinism: one thread, cells in birth order, fixed steps: the same inputs give the same bits.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Callable

import numpy as np

from ..errors import DmdvoxError
from . import kernels
from .lattice import Lattice
from .materials import STEFAN_BOLTZMANN, Material

BOTTOM_MODES = ("clamped", "adiabatic")
SOURCES = ("gaussian", "goldak")
# Goldak's semi-axes over the beam radius (front, rear, half width, depth): the rear twice the
# front, as Goldak, Chakravarti and Bibby (1984) found for arc welds
GOLDAK_DEFAULT = (1.0, 2.0, 1.0, 1.0)
T_MAX_FOR_STABILITY_C = 3000.0  # the radiation term of the time step's bound is linearised here


@dataclass(frozen=True)
class HeatSettings:
    """The heat options; temperatures in C."""

    absorptivity: float = 0.4  # REFERENCE.md 8: powder DED 0.3-0.5
    beam_radius: float = 1.25  # mm, 1/e^2 radius of the Gaussian
    ambient: float = 20.0
    preheat: float | None = None  # the plate's initial temperature (default: ambient)
    convection: float = 10.0  # W/(m^2 K): still air
    emissivity: float = 0.4  # oxidised steel 0.3-0.6
    bottom: str = "clamped"
    birth_temperature: float | None = None  # default: the liquidus
    threshold: float | None = None  # "time above" this (default: the solidus)
    cfl: float = 0.9
    source: str = "gaussian"  # or "goldak": the double ellipsoid of arc processes
    goldak: tuple[float, float, float, float] | None = None  # (a_f, a_r, b, c) mm; None: GOLDAK_DEFAULT x beam radius

    @property
    def goldak_axes(self) -> tuple[float, float, float, float]:
        """(a_f, a_r, b, c) mm of the double ellipsoid."""
        if self.goldak is not None:
            return tuple(float(v) for v in self.goldak)
        return tuple(f * self.beam_radius for f in GOLDAK_DEFAULT)

    def validate(self) -> None:
        def finite(name, option, value):
            if value is None or not math.isfinite(float(value)):
                raise DmdvoxError(f"{option}: {value!r} is not a finite number")
            return float(value)

        eta = finite("absorptivity", "--absorptivity", self.absorptivity)
        if not 0.0 < eta <= 1.0:
            raise DmdvoxError(f"--absorptivity: {eta:g} is outside (0, 1]; give the fraction of the beam absorbed "
                              "(powder DED 0.3-0.5, arc 0.7-0.85)")
        if finite("beam_radius", "--beam-radius", self.beam_radius) <= 0.0:
            raise DmdvoxError(f"--beam-radius: {self.beam_radius:g} mm must be > 0")
        if finite("convection", "--convection", self.convection) < 0.0:
            raise DmdvoxError(f"--convection: {self.convection:g} W/(m^2 K) is negative; give >= 0")
        eps = finite("emissivity", "--emissivity", self.emissivity)
        if not 0.0 <= eps <= 1.0:
            raise DmdvoxError(f"--emissivity: {eps:g} is outside [0, 1]")
        for option, value in (("--ambient", self.ambient), ("--preheat", self.preheat)):
            if value is not None and finite(option, option, value) <= -273.15:
                raise DmdvoxError(f"{option}: {value:g} C is below absolute zero")
        if self.bottom not in BOTTOM_MODES:
            raise DmdvoxError(f"--plate-bottom: {self.bottom!r}; choose one of {', '.join(BOTTOM_MODES)}")
        if self.source not in SOURCES:
            raise DmdvoxError(f"--source: {self.source!r}; choose one of {', '.join(SOURCES)}")
        if self.goldak is not None:
            if len(self.goldak) != 4 or not all(math.isfinite(float(v)) and float(v) > 0 for v in self.goldak):
                raise DmdvoxError(f"--goldak: {self.goldak!r}; give A_F,A_R,B,C, four semi-axes in mm > 0")
        if not 0.0 < self.cfl <= 1.0:
            raise DmdvoxError(f"cfl {self.cfl:g} must lie in (0, 1]")

    @property
    def plate_temperature(self) -> float:
        return float(self.ambient if self.preheat is None else self.preheat)


@dataclass(frozen=True, eq=False)
class SourcePath:
    """The beam as pieces linear in time: during ``t0[i] .. t1[i]`` it moves from ``p0[i]`` to
    ``p1[i]`` (mm) with power ``power[i]`` (W, before absorption). Pieces are in time order and
    do not overlap; between them the beam is off."""

    t0: np.ndarray  # (m,) float64
    t1: np.ndarray  # (m,) float64
    p0: np.ndarray  # (m, 3) float64
    p1: np.ndarray  # (m, 3) float64
    power: np.ndarray  # (m,) float64 W
    row: np.ndarray | None = None  # (m,) int64 toolpath row of each piece

    def __len__(self) -> int:
        return int(self.t0.shape[0])

    @property
    def energy(self) -> float:
        """Beam energy (J) before absorption."""
        return float(np.sum(self.power * (self.t1 - self.t0)))

    def position(self, t) -> np.ndarray:
        """(n, 3) positions at times ``t`` (NaN where the beam is off)."""
        t = np.atleast_1d(np.asarray(t, np.float64))
        i = np.searchsorted(self.t1, t, side="right")
        out = np.full((t.size, 3), np.nan)
        ok = (i < len(self)) & (self.t0[np.minimum(i, len(self) - 1)] <= t)
        g = i[ok]
        span = self.t1[g] - self.t0[g]
        f = np.divide(t[ok] - self.t0[g], span, out=np.zeros(g.size), where=span > 0)
        out[ok] = self.p0[g] + f[:, None] * (self.p1[g] - self.p0[g])
        return out

    @staticmethod
    def line(p0, p1, speed: float, power: float, t0: float = 0.0) -> "SourcePath":
        """One straight pass at constant speed (the closed forms' source)."""
        p0 = np.asarray(p0, np.float64).reshape(1, 3)
        p1 = np.asarray(p1, np.float64).reshape(1, 3)
        duration = float(np.linalg.norm(p1 - p0)) / speed
        return SourcePath(np.array([t0]), np.array([t0 + duration]), p0, p1, np.array([float(power)]))

    @staticmethod
    def still(p, t0: float, t1: float, power: float) -> "SourcePath":
        p = np.asarray(p, np.float64).reshape(1, 3)
        return SourcePath(np.array([float(t0)]), np.array([float(t1)]), p, p.copy(), np.array([float(power)]))


@dataclass
class HeatState:
    """The solver's state (mutable while it runs; per-cell arrays in lattice order)."""

    lattice: Lattice
    material: Material
    settings: HeatSettings
    dt: float
    time: float
    n_born: int
    H: np.ndarray
    T: np.ndarray
    k: np.ndarray
    peak: np.ndarray
    time_above: np.ndarray
    cooling_rate: np.ndarray  # C/s at the last liquidus crossing (NaN: never solidified)
    gradient: np.ndarray  # C/mm at that crossing
    solidified_at: np.ndarray  # s
    remelts: np.ndarray
    energy: np.ndarray  # kernels.E_* accumulators (J)
    initial_stored: float
    h_ambient: float
    top: np.ndarray = field(repr=False, default=None)

    @property
    def stored(self) -> float:
        """Energy held above the ambient by the cells that exist (J)."""
        vol = self.lattice.voxel ** 3
        return float(kernels.stored_energy(self.H, self.n_born, vol, self.h_ambient, self.lattice.dz))

    @property
    def absorbed(self) -> float:
        """What the cells received from the beam (J): its flux and the heat of the material born."""
        return float(self.energy[kernels.E_SOURCE] + self.energy[kernels.E_BIRTH])

    @property
    def unpaid(self) -> float:
        """The heat of the material born that the beam has not paid yet (J): the cells born when
        the beam is off (a bead's end cap arrives as the beam stops) wait for its next flux;
        what remains at the program's end is counted in ``absorbed`` beyond eta P t."""
        return float(self.energy[kernels.E_DEBT])

    @property
    def lost(self) -> float:
        """Convection, radiation, the clamped bottom and evaporation at the boiling point (J)."""
        return float(self.energy[kernels.E_CONVECTION] + self.energy[kernels.E_RADIATION]
                     + self.energy[kernels.E_BOTTOM] + self.energy[kernels.E_BOILING])

    @property
    def boiled(self) -> float:
        """What the beam put beyond the boiling point (J), lost as evaporation (in ``lost``)."""
        return float(self.energy[kernels.E_BOILING])

    @property
    def solidification_rate(self) -> np.ndarray:
        """R = cooling rate / G (mm/s) at the last liquidus crossing."""
        with np.errstate(divide="ignore", invalid="ignore"):
            return np.where(self.gradient > 0, self.cooling_rate / self.gradient, np.nan)

    def temperature(self) -> np.ndarray:
        """T (C) of every cell now (NaN: not born). ``T`` is the kernel's copy from the start of
        the last step, kept for its events."""
        out = np.full(len(self.lattice), np.nan)
        out[:self.n_born] = self.material.tables().temperature(self.H[:self.n_born])
        return out

    def temperature_at(self, cells: np.ndarray) -> np.ndarray:
        """T now of cells (NaN where not born or no cell)."""
        cells = np.asarray(cells, np.int64)
        out = np.full(cells.shape, np.nan)
        ok = (cells >= 0) & (cells < self.n_born)
        out[ok] = self.material.tables().temperature(self.H[cells[ok]])
        return out


def goldak_density(points, power: float, a_f: float, a_r: float, b: float, c: float) -> np.ndarray:
    """Goldak's double ellipsoid (W/mm^3) at ``points`` (n, 3) from the source: x along the travel
    (ahead > 0), y across, z the depth below the surface (>= 0):
    ``6 sqrt(3) f Q / (a b c pi^1.5) exp(-3 x^2/a^2 - 3 y^2/b^2 - 3 z^2/c^2)``, a and f the front's
    (a_f, f_f = 2 a_f / (a_f + a_r)) ahead and the rear's behind; its integral over the solid is
    Q = ``power``."""
    p = np.asarray(points, np.float64).reshape(-1, 3)
    front = p[:, 0] >= 0
    a = np.where(front, a_f, a_r)
    f = np.where(front, 2 * a_f, 2 * a_r) / (a_f + a_r)
    return 6 * math.sqrt(3) * f * power / (a * b * c * math.pi ** 1.5) * np.exp(
        -3 * (p[:, 0] / a) ** 2 - 3 * (p[:, 1] / b) ** 2 - 3 * (p[:, 2] / c) ** 2)


def stable_time_step(material: Material, voxel: float, settings: HeatSettings) -> float:
    """The explicit step (s): ``cfl * C_min / G_max`` (module docstring)."""
    k = material.max_conductivity
    c = material.min_heat_capacity * voxel ** 3
    t_k = T_MAX_FOR_STABILITY_C + 273.15
    surface = (settings.convection * 1e-6 + 4.0 * settings.emissivity * STEFAN_BOLTZMANN * 1e-6 * t_k ** 3) * voxel ** 2
    g = max(7.0 * k * voxel, 5.0 * k * voxel + surface)
    return settings.cfl * c / g


def start(lattice: Lattice, material: Material, settings: HeatSettings, t_begin: float = 0.0,
          dt: float | None = None) -> HeatState:
    """The state at ``t_begin``: cells born before it (the plate) at the plate temperature."""
    settings.validate()
    tables = material.tables()
    n = len(lattice)
    h_plate = float(tables.enthalpy(settings.plate_temperature))
    h_ambient = float(tables.enthalpy(settings.ambient))
    H = np.full(n, h_plate)
    T = np.full(n, settings.plate_temperature)
    k = np.interp(T, tables.t0 + tables.dt * np.arange(tables.k_of_t.size), tables.k_of_t)
    n_born = int(np.searchsorted(lattice.birth, t_begin, side="right"))
    top = np.full(lattice.shape[:2], -1, np.int32)
    if n_born:
        ijk = lattice.ijk[:n_born]
        order = np.lexsort((ijk[:, 2], ijk[:, 1], ijk[:, 0]))  # the last of each column is its top
        cols = ijk[order, 0].astype(np.int64) * lattice.shape[1] + ijk[order, 1]
        last = np.r_[cols[1:] != cols[:-1], True]
        top.reshape(-1)[cols[last]] = order[last].astype(np.int32)
    state = HeatState(
        lattice=lattice, material=material, settings=settings,
        dt=stable_time_step(material, lattice.voxel, settings) if dt is None else float(dt),
        time=float(t_begin), n_born=n_born, H=H, T=T, k=k, peak=T.copy(), time_above=np.zeros(n),
        cooling_rate=np.full(n, np.nan), gradient=np.full(n, np.nan), solidified_at=np.full(n, np.nan),
        remelts=np.zeros(n, np.int32), energy=np.zeros(kernels.N_ENERGY), initial_stored=0.0, h_ambient=h_ambient,
        top=top)
    state.peak[n_born:] = -np.inf
    state.initial_stored = state.stored
    state._solid = (T < material.solidus).astype(np.uint8)  # type: ignore[attr-defined]
    state._seg = 0  # type: ignore[attr-defined]
    return state


def run(state: HeatState, path: SourcePath, until: float, stops=(), on_stop: Callable | None = None) -> HeatState:
    """Step ``state`` to ``until`` (s) under the beam ``path``, calling ``on_stop(state, stop)`` at
    each time of ``stops`` (reached to within a step before it: the solver never shortens its
    step)."""
    m = state.material
    s = state.settings
    tables = m.tables()
    lat = state.lattice
    if len(path) and np.any(path.power < 0):
        raise DmdvoxError(f"--laser-power: a negative power ({path.power.min():g} W); give W >= 0")
    seg_power = np.ascontiguousarray(path.power * s.absorptivity, np.float64)
    t_birth = m.liquidus if s.birth_temperature is None else float(s.birth_temperature)
    h_birth = float(tables.enthalpy(t_birth))
    threshold = m.solidus if s.threshold is None else float(s.threshold)
    h_boil = math.inf if m.boiling is None else float(tables.enthalpy(m.boiling))
    goldak = np.array(s.goldak_axes if s.source == "goldak" else (0.0, 0.0, 0.0, 0.0), np.float64)
    t_amb_k4 = (s.ambient + 273.15) ** 4
    stops = sorted(float(t) for t in stops if state.time <= float(t) <= until)
    targets = stops + [float(until)]
    for target in targets:
        # a stop is reached from below (the state there has not seen what starts at the stop: the
        # next layer's beam), the end from above
        remaining = (target - state.time) / state.dt
        last = target is targets[-1]
        steps = int(math.ceil(remaining - 1e-9)) if last else int(math.floor(remaining + 1e-9))
        if steps > 0:
            state.n_born, state._seg = kernels.advance(  # type: ignore[attr-defined]
                steps, state.time, state.dt, lat.voxel, lat.origin, lat.ijk, lat.birth, lat.neighbour,
                state.n_born, state.top, state.H, state.T, state.k, state.peak, state.time_above,
                state.cooling_rate, state.gradient, state.solidified_at, state.remelts, state._solid,  # type: ignore[attr-defined]
                path.t0, path.t1, path.p0, path.p1, seg_power, state._seg, float(s.beam_radius),  # type: ignore[attr-defined]
                tables.h0, tables.dh, tables.t_of_h, tables.k_of_h,
                h_birth, state.h_ambient, t_birth, m.liquidus, m.solidus, threshold,
                s.convection * 1e-6, s.emissivity * STEFAN_BOLTZMANN * 1e-6, t_amb_k4, float(s.ambient),
                s.bottom == "clamped", s.plate_temperature, state.energy, h_boil, goldak, lat.dz)
            state.time += steps * state.dt
        if on_stop is not None and not last:
            on_stop(state, target)
    return state


__all__ = ["HeatSettings", "SourcePath", "HeatState", "stable_time_step", "start", "run", "goldak_density",
           "BOTTOM_MODES", "SOURCES", "GOLDAK_DEFAULT"]
