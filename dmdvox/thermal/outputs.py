"""What `dmdvox thermal --out DIR` writes (every file atomically):

* ``STEM_thermal.vdb``: one FloatGrid per cell field (below) on the thermal lattice, inactive
  (background +inf) where no cell or no value;
* ``STEM_thermal.vti``: the same fields as VTK point arrays on the lattice's image (NaN where no
  cell), their units in the field data;
* ``STEM_layers.csv`` (per layer), ``STEM_melt_pool.csv`` (per deposit row), ``STEM_probes.csv``
  (time and one column per probe), ``STEM_energy.csv`` (the balance at every sample);
* ``STEM_path.txt`` (3DThesis path file) and ``STEM_path.crs`` (GAMMA): the beam, to run the
  same program in those codes (docs/THERMAL.md, "Exports").

Cell fields: ``peak_temperature_C``, ``remelts``, ``time_above_s`` (above the solidus, or the
given threshold), ``cooling_rate_C_s``, ``gradient_C_mm`` and ``solidification_rate_mm_s`` (G and
R = cooling rate / G at the last liquidus crossing), ``birth_s`` (-1: the plate).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from ..grid.vdbio import stable_uuid, voxel_transform
from ..io.atomic import atomic_path, write_text
from ..io.tables import rows_to_csv
from ..io.vtk_image import write_voxels
from .run import ThermalResult, thermal_history, thermal_request

UNITS = {"peak_temperature_C": "C", "cooling_rate_C_s": "C/s", "gradient_C_mm": "C/mm",
         "solidification_rate_mm_s": "mm/s", "time_above_s": "s", "birth_s": "s", "remelts": "count"}


def cell_fields(result: ThermalResult) -> dict[str, np.ndarray]:
    """Per-cell fields (lattice order, float64; NaN: no value)."""
    st = result.state
    born = np.arange(len(result.lattice)) < st.n_born
    peak = np.where(born, st.peak, np.nan)
    return {
        "peak_temperature_C": peak,
        "remelts": np.where(born, st.remelts, np.nan),
        "time_above_s": np.where(born, st.time_above, np.nan),
        "cooling_rate_C_s": st.cooling_rate.copy(),
        "gradient_C_mm": st.gradient.copy(),
        "solidification_rate_mm_s": st.solidification_rate,
        "birth_s": np.where(np.isfinite(result.lattice.birth), result.lattice.birth, -1.0),
    }


def at_points(result: ThermalResult, values: np.ndarray, points: np.ndarray) -> np.ndarray:
    """A cell field (lattice order) at world points (n, 3): the value of the part's cell (born
    by the end of the run, not the plate) nearest each point, NaN where that cell has none. A
    surface vertex lies between cells and empty space, up to a cell or more from the nearest
    centre (a cell is born where the deposit holds its centre), so a fixed window of cells
    around it can hold none of the part."""
    from scipy.spatial import cKDTree

    lat = result.lattice
    points = np.asarray(points, np.float64).reshape(-1, 3)
    part = np.flatnonzero((np.arange(len(lat)) < result.state.n_born) & np.isfinite(lat.birth))
    out = np.full(len(points), np.nan)
    if part.size == 0 or len(points) == 0:
        return out
    nearest = cKDTree(lat.centres[part]).query(points)[1]
    out[:] = np.asarray(values, np.float64)[part[nearest]]
    return out


def _dense(result: ThermalResult, values: np.ndarray, fill: float) -> np.ndarray:
    out = np.full(result.lattice.shape, fill, np.float32)
    out[tuple(result.lattice.ijk.T)] = np.where(np.isfinite(values), values, fill).astype(np.float32)
    return out


def write_fields_vdb(result: ThermalResult, path: Path, metadata: dict) -> Path:
    from ..vdb import openvdb

    lat = result.lattice
    grids = []
    for name, values in cell_fields(result).items():
        g = openvdb.FloatGrid(float("inf"))
        g.name = name
        g.transform = voxel_transform(lat.voxel, lat.origin)
        g["unit"] = UNITS[name]
        g.copyFromArray(_dense(result, values, np.inf), (0, 0, 0), 0.0)
        grids.append(g)
    md = {str(k): (v if isinstance(v, (str, int, float, bool)) else str(v)) for k, v in metadata.items()}
    with atomic_path(path) as tmp:
        openvdb.write(str(tmp), grids=grids, metadata=md)
        stable_uuid(tmp)
    return path


def thesis_path(result: ThermalResult) -> str:
    """The beam as a 3DThesis path file (REFERENCE.md 8): ``Mode X Y Z Pmod Param`` per line, mm;
    mode 1 a line to (X, Y, Z) at speed Param (mm/s), mode 0 a spot held for Param seconds;
    Pmod the power as a fraction of the largest. The travel between pieces is a line (or a
    wait) at Pmod 0."""
    p = result.path
    if not len(p):
        return "Mode X(mm) Y(mm) Z(mm) Pmod Param\n"
    peak = float(p.power.max()) or 1.0
    gap = np.r_[p.t0[0], p.t0[1:] - p.t1[:-1]]
    prev = np.vstack([p.p0[:1], p.p1[:-1]])
    jump = np.linalg.norm(p.p0 - prev, axis=1)
    length = np.linalg.norm(p.p1 - p.p0, axis=1)
    duration = p.t1 - p.t0
    rows = []

    def line(mode, xyz, pmod, param):
        return f"{mode} {xyz[0]:.9g} {xyz[1]:.9g} {xyz[2]:.9g} {pmod:.6g} {param:.9g}"

    rows.append(line(0, p.p0[0], 0.0, gap[0]))
    for i in range(len(p)):
        if i and (jump[i] > 1e-9 or gap[i] > 0):
            moving = jump[i] > 1e-9
            rows.append(line(1 if moving else 0, p.p0[i], 0.0,
                             (jump[i] / gap[i] if gap[i] > 0 else 1e9) if moving else gap[i]))
        still = length[i] <= 1e-9
        rows.append(line(0 if still else 1, p.p1[i], p.power[i] / peak,
                         duration[i] if still else length[i] / duration[i]))
    return "\n".join(["Mode X(mm) Y(mm) Z(mm) Pmod Param", *rows]) + "\n"


def gamma_crs(result: ThermalResult) -> str:
    """The beam as a GAMMA toolpath (``.crs``): ``time x y z on`` per line (s, mm, 1 on / 0 off),
    a point at each piece's start and end."""
    p = result.path
    rows = []
    for i in range(len(p)):
        a, b = p.p0[i], p.p1[i]
        on = 1 if p.power[i] > 0 else 0
        rows.append(f"{p.t0[i]:.9g} {a[0]:.9g} {a[1]:.9g} {a[2]:.9g} {on}")
        end_on = 1 if i + 1 < len(p) and p.t0[i + 1] <= p.t1[i] and p.power[i + 1] > 0 else 0
        rows.append(f"{p.t1[i]:.9g} {b[0]:.9g} {b[1]:.9g} {b[2]:.9g} {end_on}")
    return "\n".join(rows) + "\n"


def write_outputs(result: ThermalResult, out: Path, stem: str, metadata: dict) -> list[str]:
    out = Path(out)
    lat = result.lattice
    written = [str(write_fields_vdb(result, out / f"{stem}_thermal.vdb", metadata))]
    arrays = {name: _dense(result, values, np.nan) for name, values in cell_fields(result).items()}
    written += [str(p) for p in write_voxels(out / f"{stem}_thermal.vti", lat.origin, lat.voxel, arrays, units=UNITS)]
    layer_keys = ["layer", "first_line", "start_s", "end_s", "interlayer_C", "peak_C", "cool_below_interpass_s"]
    written.append(str(write_text(out / f"{stem}_layers.csv", rows_to_csv(result.layers, layer_keys))))
    pool_keys = ["row", "line", "time_s", "length_mm", "width_mm", "depth_mm"]
    written.append(str(write_text(out / f"{stem}_melt_pool.csv", rows_to_csv(result.pools, pool_keys))))
    if result.probes:
        keys = ["time_s"] + [f"T_C_at_{x:g}_{y:g}_{z:g}" for x, y, z in result.probes]
        rows = [dict(zip(keys, [float(t), *map(float, row)])) for t, row in zip(result.samples, result.probe_T)]
        written.append(str(write_text(out / f"{stem}_probes.csv", rows_to_csv(rows, keys))))
    energy_keys = ["time_s", "absorbed_J", "stored_J", "lost_J", "balance_percent"]
    written.append(str(write_text(out / f"{stem}_energy.csv", rows_to_csv(result.energy, energy_keys))))
    written.append(str(write_text(out / f"{stem}_path.txt", thesis_path(result))))
    written.append(str(write_text(out / f"{stem}_path.crs", gamma_crs(result))))
    return written


def heat_deposit(plan, grid, plate_top: float | None, options: dict, out_dir=None,
                 max_memory: int | None = None) -> tuple[ThermalResult, dict]:
    """The heat stage on a deposit already swept (``grid``, its plate top ``plate_top``): the
    history with the heat ``options`` (:data:`~dmdvox.thermal.run.OPTION_KEYS`), and the
    summary `dmdvox thermal --json` prints, with the files written under ``out_dir`` (None:
    none) in its ``outputs``."""
    result = thermal_history(thermal_request(plan, grid, options, plate_top, max_memory))
    summary = result.summary()
    summary["outputs"] = []
    if out_dir is not None:
        stem = Path(plan.toolpath.source).stem or "part"
        summary["outputs"] = write_outputs(result, Path(out_dir), stem,
                                           {"material": result.material.name, "source": str(plan.toolpath.source)})
    return result, summary


__all__ = ["at_points", "cell_fields", "heat_deposit", "write_outputs", "thesis_path", "gamma_crs", "UNITS"]
