"""The flow model on slicer files nobody here wrote (issue 23): data/corpus at default settings.

The references are computed here, not by dmdvox: the delivered volume by a filament counter
written below (E pushed past its high-water mark, so a retract and its prime deliver nothing,
times the filament's section), the parts' volumes from their closed forms (tests/test_corpus.py).
"""

from __future__ import annotations

import math
import re

import pytest

from dmdvox.deposit.simulate import SimulateRequest, simulate
from dmdvox.process.plan import ProcessSettings, plan_process
from dmdvox.toolpath import read_gcode

from .test_corpus import CORPUS, cad_volume

FILAMENT_MM = {"prusa": 1.75, "slic3r": 3.0, "cura": 1.75}  # the files' headers (test_corpus.test_info)
SPARSE = [f"{shape}_{slicer}_25" for shape in ("cylinder", "lbracket") for slicer in ("prusa", "slic3r", "cura")]
_WORD = re.compile(r"([A-Z])([-+]?[0-9]*\.?[0-9]+)")


def e_delivered_mm3(path, diameter_mm: float) -> float:
    """Filament volume the program pushes out: the E axis in one continuous coordinate (G92 E
    resets shift it, M82/M83 switch absolute/relative E), counted where it passes its highest
    value so far."""
    relative = False
    raw = 0.0  # the E position the program sees
    base = 0.0  # continuous coordinate = base + raw
    high = 0.0
    delivered = 0.0
    for line in path.read_text().splitlines():
        code = line.split(";", 1)[0].strip().upper()
        if not code:
            continue
        words = dict(_WORD.findall(code))
        head = code.split()[0]
        if head == "M82":
            relative = False
        elif head == "M83":
            relative = True
        elif head == "G92" and "E" in words:
            e = float(words["E"])
            base += raw - e
            raw = e
        elif head in ("G0", "G1", "G00", "G01") and "E" in words:
            e = float(words["E"])
            raw = raw + e if relative else e
            now = base + raw
            if now > high:
                delivered += now - high
                high = now
    return delivered * math.pi * diameter_mm**2 / 4


_runs: dict[str, dict] = {}


def run(name: str) -> dict:
    if name not in _runs:
        path = CORPUS / f"{name}.gcode"
        plan = plan_process(read_gcode(path, dialect="auto"), ProcessSettings())
        result = simulate(SimulateRequest(plan))
        _runs[name] = {**result.summary, "counter_mm3": e_delivered_mm3(path, FILAMENT_MM[name.split("_")[1]])}
    return _runs[name]


@pytest.mark.parametrize("name", SPARSE)
def test_sparse_infill_is_held_by_its_crossings(name):
    # Each infill line rests on the lines of the layer below where they cross and spans the gaps
    # between (a filament bridge): nothing is lost, the grid holds what the program delivers, and
    # the cavities the sparse layers leave are the part's internal void, 1 - delivered / CAD.
    out = run(name)
    delivered = out["counter_mm3"]
    assert out["model"] == "flow"
    assert out["deposited_volume_mm3"] == pytest.approx(delivered, rel=1e-3)
    assert out["lost_volume_mm3"] < 0.005 * delivered
    assert out["deposit_volume_mm3"] == pytest.approx(delivered, rel=0.01)
    void = 100 * (1 - delivered / cad_volume(name.split("_")[0]))
    assert out["porosity_percent"] == pytest.approx(void, abs=3.0)

