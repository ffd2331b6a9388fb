"""``--thermal-feedback``: the melt pool, and so the bead, widens on a hot part.

Law (Rosenthal, REFERENCE.md section 8): the melt width of a fast moving source goes as
``w ~ sqrt(eta P / (rho c U dT))`` with ``dT = T_melt - T0``, so a bead laid on material at the
preheat ``T0`` instead of the reference ``T_ref`` (the ambient: the programmed bead is the cold
one) is wider by

    f = ((T_liquidus - T_ref) / (T_liquidus - T0)) ** p,    p = 1/2 (3-D source), 1 (thin 2-D wall)

and, the material delivered being the same, lower by 1/f: the cross-section area stays.
``T0`` of a row is the interlayer temperature of the layer below when its layer starts (the
plate's temperature for the first layer). The flow model then lands the wider, lower beads, so
the standoff drift that heat causes shows in its growth table.
"""

from __future__ import annotations

import dataclasses

import numpy as np

from ..errors import DmdvoxError
from ..process.beads import RowSections
from ..process.plan import ProcessPlan

LAWS = {"3d": 0.5, "wall": 1.0}


def width_factor(preheat, liquidus: float, reference: float, law: str = "3d") -> np.ndarray:
    """f of the module docstring (clipped: a preheat at or above 95 % of the way to the
    liquidus is taken at 95 %, where the law has long stopped holding)."""
    if law not in LAWS:
        raise DmdvoxError(f"--thermal-feedback: unknown law {law!r}; choose one of {', '.join(LAWS)}")
    t0 = np.minimum(np.asarray(preheat, np.float64), reference + 0.95 * (liquidus - reference))
    t0 = np.maximum(t0, reference)  # a layer cooler than the reference keeps the programmed bead
    return ((liquidus - reference) / (liquidus - t0)) ** LAWS[law]


def row_preheat(plan: ProcessPlan, layers: list[dict], plate_temperature: float) -> np.ndarray:
    """T0 of every row: the interlayer temperature of the layer laid before the row's layer."""
    tp = plan.toolpath
    starts = np.array([row["start_s"] for row in layers], np.float64)
    below = np.array([plate_temperature] + [row["interlayer_C"] if row["interlayer_C"] is not None
                                            else plate_temperature for row in layers[:-1]], np.float64)
    if starts.size == 0:
        return np.full(len(tp), plate_temperature)
    k = np.clip(np.searchsorted(starts, tp.t_start, side="right") - 1, 0, starts.size - 1)
    return below[k]


def fed_back(plan: ProcessPlan, factor: np.ndarray) -> ProcessPlan:
    """The plan with every row's bead ``factor`` times wider and, where the height is fixed,
    1/``factor`` lower (where the material gives the height, the area does it)."""
    s = plan.sections
    factor = np.asarray(factor, np.float64)
    height = np.where(np.isfinite(s.fixed_height), s.fixed_height / factor, s.fixed_height)
    sections = RowSections(s.width * factor, height, s.bottom_shift)
    return dataclasses.replace(plan, sections=sections)


__all__ = ["width_factor", "row_preheat", "fed_back", "LAWS"]
