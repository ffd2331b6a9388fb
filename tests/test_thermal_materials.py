"""The heat model's alloys: built-in tables, TOML files, enthalpy, and refusals naming the field."""

import numpy as np
import pytest

from dmdvox.errors import DmdvoxError
from dmdvox.thermal.materials import KELVIN, NAMES, load_material


@pytest.mark.parametrize("name", NAMES)
def test_built_in_materials_load_and_cite(name):
    m = load_material(name.lower())
    assert m.name == name and m.source
    assert m.liquidus > m.solidus > 1000.0
    assert np.all(np.diff(m.t) > 0) and np.all(m.k > 0) and np.all(m.cp > 0)


def test_316l_follows_kim_correlations():
    """Kim (1975): k = 9.248 + 0.01571 T, cp = 462 + 0.134 T (solid, T in K)."""
    m = load_material("316L")
    t = np.array([300.0, 700.0, 1100.0])
    assert np.allclose(m.conductivity(t) * 1e3, 9.248 + 0.01571 * (t + KELVIN), rtol=2e-3)
    assert np.allclose(m.heat_capacity(t) / m.rho_mm3, 462.0 + 0.134 * (t + KELVIN), rtol=2e-3)


def test_enthalpy_carries_sensible_and_latent_heat():
    m = load_material("IN718")
    # over the melting range: the latent heat plus the sensible heat of a linear cp (trapezoid)
    cp_s, cp_l = np.interp([m.solidus, m.liquidus], m.t, m.cp)
    expect = m.rho_mm3 * (m.latent_heat + 0.5 * (cp_s + cp_l) * (m.liquidus - m.solidus))
    h = m.enthalpy([m.solidus, m.liquidus])
    assert h[1] - h[0] == pytest.approx(expect, rel=2e-3)
    # in the solid the slope is rho cp
    slope = (m.enthalpy(501.0) - m.enthalpy(499.0)) / 2.0
    assert slope == pytest.approx(m.heat_capacity(500.0), rel=1e-3)
    # the kernels' tables invert H(T)
    tables = m.tables()
    t = np.array([20.0, 800.0, 1280.0, 1300.0, 1500.0])
    assert np.allclose(tables.temperature(m.enthalpy(t)), t, atol=0.5)


def test_toml_material(tmp_path):
    path = tmp_path / "alloy.toml"
    path.write_text('[material]\nname = "mine"\nt = [20.0, 1000.0]\nk = [10.0, 20.0]\ncp = [500.0, 600.0]\n'
                    'density = 8000.0\nsolidus = 1300.0\nliquidus = 1400.0\nlatent_heat = 2.5e5\n')
    m = load_material(str(path))
    assert m.name == "mine" and m.conductivity(510.0) == pytest.approx(0.015)


@pytest.mark.parametrize("body, field", [
    ("t = [20.0, 10.0]\nk = [10.0, 20.0]\ncp = [500.0, 600.0]\n", "'t'"),
    ("t = [20.0, 30.0]\nk = [10.0, -1.0]\ncp = [500.0, 600.0]\n", "'k'"),
    ("t = [20.0, 30.0]\nk = [10.0, 1.0]\ncp = [-500.0, 600.0]\n", "'cp'"),
    ("t = [20.0, 30.0]\nk = [10.0, 1.0]\ncp = [500.0, 600.0]\nlatent_heat = -1.0\n", "'latent_heat'"),
])
def test_bad_tables_name_the_field(tmp_path, body, field):
    path = tmp_path / "bad.toml"
    path.write_text(body + "density = 8000.0\nsolidus = 1300.0\nliquidus = 1400.0\n")
    with pytest.raises(DmdvoxError, match=field):
        load_material(str(path))


def test_negative_density_and_unknown_material(tmp_path):
    path = tmp_path / "bad.toml"
    path.write_text("t = 20.0\nk = 10.0\ncp = 500.0\ndensity = -8000.0\nsolidus = 1300.0\nliquidus = 1400.0\n")
    with pytest.raises(DmdvoxError, match="'density'"):
        load_material(str(path))
    with pytest.raises(DmdvoxError, match="--material: unknown material 'steel'"):
        load_material("steel")
