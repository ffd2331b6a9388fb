"""--thermal-feedback: a bead laid hot is wider and lower by the documented law, mass kept."""

import numpy as np
import pytest

from dmdvox.errors import DmdvoxError
from dmdvox.process.flow import FlowSettings
from dmdvox.process.plan import ProcessSettings, plan_process
from dmdvox.thermal.feedback import fed_back, row_preheat, width_factor
from dmdvox.toolpath.reader import read_gcode

TRACK = """(one 12 mm powder track)
M64
G90 G21 G17
F600
G0 X0 Y0 Z5
G1 Z0
M65
G1 X12 Y0 Z0
M64
"""


def test_width_law():
    # Rosenthal 3-D: w ~ dT^-1/2; thin wall: w ~ dT^-1
    assert width_factor(700.0, 1450.0, 20.0) == pytest.approx((1430.0 / 750.0) ** 0.5)
    assert width_factor(700.0, 1450.0, 20.0, "wall") == pytest.approx(1430.0 / 750.0)
    assert width_factor(10.0, 1450.0, 20.0) == 1.0
    with pytest.raises(DmdvoxError, match="--thermal-feedback"):
        width_factor(700.0, 1450.0, 20.0, "2d")


def test_a_hot_bead_is_wider_and_lower_with_its_mass(tmp_path):
    """The beads the flow model lands (what the deposit engine sweeps): every element f wider,
    1/f lower, the material the same."""
    path = tmp_path / "track.gcode"
    path.write_text(TRACK)
    settings = ProcessSettings(model="flow", flow=FlowSettings(powder_rate_g_min=10.0, density_g_cm3=7.95))
    cold = plan_process(read_gcode(str(path), dialect="seed"), settings)
    f = float(width_factor(700.0, 1450.0, 20.0))
    hot = fed_back(cold, np.full(len(cold.toolpath), f))
    a, b = (p.beads(0.125) for p in (cold, hot))
    assert len(a) == len(b) and len(a) > 0
    assert np.allclose(b.width / a.width, f, rtol=0.05)
    assert np.allclose(b.height / a.height, 1 / f, rtol=0.05)
    assert b.volume.sum() == pytest.approx(a.volume.sum(), rel=0.01)


def test_row_preheat_is_the_layer_below(tmp_path):
    path = tmp_path / "track.gcode"
    path.write_text(TRACK)
    plan = plan_process(read_gcode(str(path), dialect="seed"), ProcessSettings())
    tp = plan.toolpath
    layers = [{"start_s": float(tp.t_start[np.flatnonzero(tp.deposit)[0]]), "interlayer_C": 400.0}]
    t0 = row_preheat(plan, layers, 25.0)
    assert np.all(t0 == 25.0)  # the first layer lies on the plate
    two = layers + [{"start_s": 1e9, "interlayer_C": None}]
    assert np.all(row_preheat(plan, two, 25.0) == 25.0)
