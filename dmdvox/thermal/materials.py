"""Alloys for the heat model: temperature-dependent conductivity and heat capacity, density,
melting range and latent heat; built in (``316L``, ``IN718``, ``Ti64``) or read from a TOML file.

Units in the tables are the handbooks' (C, W/(m K), J/(kg K), kg/m^3, J/kg); :class:`Material`
converts them to the solver's mm, J, s. The enthalpy per volume ``H(T) = rho (int cp dT + L f(T))``
with the liquid fraction ``f`` rising linearly from the solidus to the liquidus carries the latent
heat: the solver steps H and reads T back (:meth:`Material.tables`). Density is the room
temperature value, constant: the deposit's volume is the solid's, and a constant density keeps the
mass the geometry holds.

Sources (docs/THERMAL.md lists them with the tables):

* 316L: Kim, "Thermophysical properties of stainless steels", ANL-75-55, Argonne (1975):
  k = 9.248 + 0.01571 T (solid), 12.41 + 0.003279 T (liquid), T in K; cp = 462 + 0.134 T (solid),
  775 J/(kg K) liquid; latent heat 2.7e5 J/kg; solidus/liquidus 1375/1450 C.
* Boiling points (the beam's clamp, docs/THERMAL.md): 316L 3090 K, IN718 3188 K, Ti-6Al-4V
  3315 K, the values the DebRoy group's heat and fluid flow models of AM use (e.g. Mukherjee et
  al., "Dimensionless numbers in additive manufacturing", J. Appl. Phys. 121 (2017) 064904),
  rounded to whole C: a limit of the model, not a measured property of a given heat.
* IN718 and Ti-6Al-4V: Mills, "Recommended values of thermophysical properties for selected
  commercial alloys", Woodhead (2002), the recommended-value tables (rounded).
"""

from __future__ import annotations

import math
import tomllib
from dataclasses import dataclass
from functools import cached_property
from pathlib import Path

import numpy as np

from ..errors import DmdvoxError, InputFileError

STEFAN_BOLTZMANN = 5.670374419e-8  # W/(m^2 K^4)
KELVIN = 273.15
# The solver's enthalpy tables span this range (C); a cell leaving it means a broken run.
TABLE_T_MIN_C = -100.0
TABLE_T_MAX_C = 4000.0
TABLE_POINTS = 16384


def _kim_316l() -> dict:
    t_c = np.array([20.0, 200, 400, 600, 800, 1000, 1200, 1375, 1450, 1600, 2000, 2500])
    t_k = t_c + KELVIN
    solid = t_c <= 1375.0
    k = np.where(solid, 9.248 + 0.01571 * t_k, 12.41 + 0.003279 * t_k)
    cp = np.where(solid, 462.0 + 0.134 * t_k, 775.0)
    return {"name": "316L", "source": "Kim 1975, ANL-75-55 (correlations tabulated)", "density": 7950.0,
            "solidus": 1375.0, "liquidus": 1450.0, "latent_heat": 2.7e5, "boiling": 2817.0,
            "t": t_c.tolist(), "k": np.round(k, 2).tolist(), "cp": np.round(cp, 1).tolist()}


BUILT_IN = {
    "316L": _kim_316l(),
    "IN718": {
        "name": "IN718", "source": "Mills 2002, Inconel 718 recommended values (rounded)", "density": 8190.0,
        "solidus": 1260.0, "liquidus": 1336.0, "latent_heat": 2.1e5, "boiling": 2915.0,
        "t": [25.0, 100, 200, 300, 400, 500, 600, 700, 800, 900, 1000, 1100, 1200, 1260, 1336, 1500, 2500],
        "k": [11.4, 12.5, 14.0, 15.5, 17.0, 18.5, 20.0, 21.5, 23.0, 24.5, 26.0, 27.5, 29.0, 29.7, 29.6, 31.0, 31.0],
        "cp": [435.0, 455, 479, 497, 515, 537, 558, 579, 600, 620, 640, 655, 670, 680, 720, 720, 720],
    },
    "Ti64": {
        "name": "Ti64", "source": "Mills 2002, Ti-6Al-4V recommended values (rounded)", "density": 4420.0,
        "solidus": 1604.0, "liquidus": 1660.0, "latent_heat": 2.86e5, "boiling": 3042.0,
        "t": [25.0, 100, 200, 300, 400, 500, 600, 700, 800, 900, 995, 1100, 1200, 1300, 1400, 1500, 1604, 1660,
              2000, 2500],
        "k": [7.0, 7.45, 8.75, 10.15, 11.35, 12.6, 14.2, 15.5, 17.8, 20.2, 19.3, 21.0, 22.9, 23.7, 24.6, 25.8, 27.0,
              33.4, 34.6, 34.6],
        "cp": [546.0, 562, 584, 606, 629, 651, 673, 694, 714, 734, 641, 660, 678, 696, 714, 732, 750, 830, 830, 830],
    },
}
NAMES = tuple(BUILT_IN)


@dataclass(frozen=True, eq=False)
class Material:
    """One alloy: property tables against temperature (C; linear between points, constant
    beyond), handbook units. ``source`` names where the values come from."""

    name: str
    t: np.ndarray  # (m,) float64 C, strictly increasing
    k: np.ndarray  # (m,) float64 W/(m K)
    cp: np.ndarray  # (m,) float64 J/(kg K), without the latent heat
    density: float  # kg/m^3
    solidus: float  # C
    liquidus: float  # C
    latent_heat: float  # J/kg
    source: str = ""
    boiling: float | None = None  # C: no cell is heated beyond it (None: no limit)

    def validate(self, where: str) -> None:
        """Refuse tables the solver cannot use; ``where`` names the material in messages."""
        for name in ("t", "k", "cp"):
            a = getattr(self, name)
            if a.ndim != 1 or a.size < 1:
                raise DmdvoxError(f"{where}: field '{name}' needs at least one value")
            if not np.all(np.isfinite(a)):
                raise DmdvoxError(f"{where}: field '{name}' has a value that is not a finite number")
        if not (self.t.size == self.k.size == self.cp.size):
            raise DmdvoxError(f"{where}: fields 't', 'k' and 'cp' must have the same length "
                              f"({self.t.size}, {self.k.size}, {self.cp.size})")
        if np.any(np.diff(self.t) <= 0):
            bad = int(np.flatnonzero(np.diff(self.t) <= 0)[0])
            raise DmdvoxError(f"{where}: field 't' must increase strictly (the temperature of each row of the "
                              f"table), but {self.t[bad]:g} C is followed by {self.t[bad + 1]:g} C")
        if self.t[0] <= -KELVIN:
            raise DmdvoxError(f"{where}: field 't' starts at {self.t[0]:g} C, below absolute zero")
        for name in ("k", "cp"):
            a = getattr(self, name)
            if np.any(a <= 0):
                raise DmdvoxError(f"{where}: field '{name}' has a value <= 0 ({a.min():g}); give positive values")
        for name in ("density", "solidus", "liquidus", "latent_heat"):
            value = getattr(self, name)
            if not math.isfinite(value):
                raise DmdvoxError(f"{where}: field '{name}' is not a finite number")
        if self.density <= 0:
            raise DmdvoxError(f"{where}: field 'density' is {self.density:g}; give the density in kg/m^3 (> 0)")
        if self.latent_heat < 0:
            raise DmdvoxError(f"{where}: field 'latent_heat' is {self.latent_heat:g}; give J/kg >= 0")
        if self.liquidus < self.solidus:
            raise DmdvoxError(f"{where}: field 'liquidus' ({self.liquidus:g} C) is below 'solidus' "
                              f"({self.solidus:g} C)")
        if self.boiling is not None and not (math.isfinite(self.boiling)
                                             and self.liquidus < self.boiling <= TABLE_T_MAX_C):
            raise DmdvoxError(f"{where}: field 'boiling' ({self.boiling:g} C) must lie above 'liquidus' "
                              f"({self.liquidus:g} C) and at most {TABLE_T_MAX_C:g} C")
        if self.solidus <= TABLE_T_MIN_C or self.liquidus >= TABLE_T_MAX_C:
            raise DmdvoxError(f"{where}: fields 'solidus' and 'liquidus' must lie between {TABLE_T_MIN_C:g} and "
                              f"{TABLE_T_MAX_C:g} C")

    # -- in the solver's units (mm, J, s) --------------------------------------------------------
    @property
    def rho_mm3(self) -> float:
        """Density in kg/mm^3."""
        return self.density * 1e-9

    def conductivity(self, t_c) -> np.ndarray:
        """W/(mm K) at ``t_c`` (C)."""
        return np.interp(t_c, self.t, self.k) * 1e-3

    def heat_capacity(self, t_c) -> np.ndarray:
        """Volumetric sensible heat capacity rho cp, J/(mm^3 K), at ``t_c`` (C)."""
        return np.interp(t_c, self.t, self.cp) * self.rho_mm3

    def liquid_fraction(self, t_c) -> np.ndarray:
        t_c = np.asarray(t_c, np.float64)
        if self.liquidus > self.solidus:
            return np.clip((t_c - self.solidus) / (self.liquidus - self.solidus), 0.0, 1.0)
        return (t_c >= self.liquidus).astype(np.float64)

    def enthalpy(self, t_c) -> np.ndarray:
        """H(T) per volume (J/mm^3) from 0 at 0 C: sensible heat (trapezoids on a fine grid, exact
        for the piecewise-linear cp) plus rho L f(T)."""
        grid = self._t_grid()
        h = self._sensible(grid)
        return np.interp(np.asarray(t_c, np.float64), grid, h) + self.rho_mm3 * self.latent_heat * \
            self.liquid_fraction(t_c)

    def _t_grid(self) -> np.ndarray:
        return np.linspace(TABLE_T_MIN_C, TABLE_T_MAX_C, TABLE_POINTS)

    def _sensible(self, grid: np.ndarray) -> np.ndarray:
        c = self.heat_capacity(grid)
        h = np.concatenate([[0.0], np.cumsum(0.5 * (c[1:] + c[:-1]) * np.diff(grid))])
        return h - np.interp(0.0, grid, h)

    def tables(self) -> "PropertyTables":
        """Uniform tables the kernels read: T(H) on a uniform H grid and k(T) on a uniform T grid."""
        return self._tables

    @cached_property
    def _tables(self) -> "PropertyTables":
        t_grid = self._t_grid()
        # cp > 0 makes H(T) strictly increasing, so T(H) is one interpolation (a melting range
        # of zero width is a jump over one grid step)
        h_of_t = self._sensible(t_grid) + self.rho_mm3 * self.latent_heat * self.liquid_fraction(t_grid)
        h_grid = np.linspace(h_of_t[0], h_of_t[-1], TABLE_POINTS)
        t_of_h = np.interp(h_grid, h_of_t, t_grid)
        return PropertyTables(h0=float(h_grid[0]), dh=float(h_grid[1] - h_grid[0]), t_of_h=t_of_h,
                              k_of_h=self.conductivity(t_of_h), t0=float(t_grid[0]), dt=float(t_grid[1] - t_grid[0]),
                              k_of_t=self.conductivity(t_grid), h_of_t=h_of_t)

    @property
    def min_heat_capacity(self) -> float:
        """Smallest rho cp (J/(mm^3 K)): the latent heat only adds capacity, so this bounds the
        explicit time step from below."""
        return float(self.cp.min() * self.rho_mm3)

    @property
    def max_conductivity(self) -> float:
        """W/(mm K)."""
        return float(self.k.max() * 1e-3)

    def to_json(self) -> dict:
        return {"name": self.name, "source": self.source, "density_kg_m3": self.density,
                "solidus_C": self.solidus, "liquidus_C": self.liquidus, "latent_heat_J_kg": self.latent_heat,
                "boiling_C": self.boiling}


@dataclass(frozen=True, eq=False)
class PropertyTables:
    """What the kernels interpolate: ``t_of_h[i]`` and ``k_of_h[i]`` (W/(mm K)) at H = h0 + i dh,
    ``k_of_t[i]`` and ``h_of_t[i]`` at T = t0 + i dt."""

    h0: float
    dh: float
    t_of_h: np.ndarray
    k_of_h: np.ndarray
    t0: float
    dt: float
    k_of_t: np.ndarray
    h_of_t: np.ndarray

    def enthalpy(self, t_c) -> np.ndarray:
        return np.interp(np.asarray(t_c, np.float64), self.t0 + self.dt * np.arange(self.h_of_t.size), self.h_of_t)

    def temperature(self, h) -> np.ndarray:
        return np.interp(np.asarray(h, np.float64), self.h0 + self.dh * np.arange(self.t_of_h.size), self.t_of_h)


def material_from_mapping(data: dict, where: str) -> Material:
    """A material from a TOML table (or a built-in's dict); ``where`` names it in messages."""
    known = {"name", "source", "density", "solidus", "liquidus", "latent_heat", "boiling", "t", "k", "cp"}
    unknown = sorted(set(data) - known)
    if unknown:
        raise DmdvoxError(f"{where}: unknown field '{unknown[0]}'; the fields are {', '.join(sorted(known))}")
    for name in ("density", "solidus", "liquidus", "t", "k", "cp"):
        if name not in data:
            raise DmdvoxError(f"{where}: field '{name}' is missing (t in C, k in W/(m K), cp in J/(kg K), density "
                              "in kg/m^3, solidus and liquidus in C, latent_heat in J/kg)")

    def table(name):
        value = data[name]
        values = value if isinstance(value, (list, tuple)) else [value]
        try:
            return np.array([float(v) for v in values], np.float64)
        except (TypeError, ValueError):
            raise DmdvoxError(f"{where}: field '{name}' must be a number or a list of numbers") from None

    def number(name, default=None):
        value = data.get(name, default)
        try:
            return float(value)
        except (TypeError, ValueError):
            raise DmdvoxError(f"{where}: field '{name}' must be a number, not {value!r}") from None

    material = Material(name=str(data.get("name", where)), t=table("t"), k=table("k"), cp=table("cp"),
                        density=number("density"), solidus=number("solidus"), liquidus=number("liquidus"),
                        latent_heat=number("latent_heat", 0.0), source=str(data.get("source", where)),
                        boiling=None if data.get("boiling") is None else number("boiling"))
    material.validate(where)
    return material


def load_material(spec: str) -> Material:
    """``316L``, ``IN718``, ``Ti64`` (any case) or the path of a TOML file with the fields of
    :class:`Material` at its top level or in a ``[material]`` table."""
    for name, data in BUILT_IN.items():
        if spec.lower() == name.lower():
            return material_from_mapping(data, f"--material {name}")
    path = Path(spec)
    if path.suffix.lower() != ".toml":
        raise DmdvoxError(f"--material: unknown material {spec!r}; choose one of {', '.join(NAMES)} or give a "
                          "TOML file (docs/THERMAL.md)")
    if not path.is_file():
        raise InputFileError(f"--material: {spec}: no such file")
    try:
        data = tomllib.loads(path.read_text())
    except (tomllib.TOMLDecodeError, UnicodeDecodeError) as exc:
        raise InputFileError(f"--material: {spec}: not a TOML file ({exc})") from None
    data = data.get("material", data)
    return material_from_mapping(data, f"--material {spec}")


def constant_material(k: float, rho: float, cp: float, name: str = "constant") -> Material:
    """A material of constant k (W/(m K)), density (kg/m^3) and cp (J/(kg K)) that never melts:
    what the closed forms assume."""
    return Material(name=name, t=np.array([0.0]), k=np.array([float(k)]), cp=np.array([float(cp)]), density=float(rho),
                    solidus=TABLE_T_MAX_C - 1.0, liquidus=TABLE_T_MAX_C - 1.0, latent_heat=0.0, source="constant")


__all__ = ["Material", "PropertyTables", "load_material", "material_from_mapping", "constant_material", "NAMES",
           "BUILT_IN", "STEFAN_BOLTZMANN", "KELVIN"]
