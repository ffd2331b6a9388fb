"""The heat solver against closed forms (REFERENCE.md section 8) and its invariants.

Every expected value here comes from a formula or from the inputs, never from the solver."""

import math

import numpy as np
import pytest
from scipy.special import erfc

from dmdvox.thermal.lattice import BOTTOM, OPEN, lattice_from_birth
from dmdvox.thermal.materials import constant_material, load_material
from dmdvox.thermal.run import solve_history
from dmdvox.thermal.solver import HeatSettings, SourcePath, run, stable_time_step, start

# constant properties of the closed forms: k = 20 W/(m K), rho c = 4e-3 J/(mm^3 K), alpha = 5 mm^2/s
K, RHO, CP = 20.0, 8000.0, 500.0
ALPHA = K * 1e-3 / (RHO * 1e-9 * CP)
NO_LOSS = dict(ambient=0.0, convection=0.0, emissivity=0.0, bottom="adiabatic")


def _block(shape, voxel, top_z=0.0, x0=0.0, y0=0.0, birth=-np.inf):
    """A solid box of cells whose top face is at ``top_z`` and whose -x, -y faces at x0, y0."""
    origin = np.array([x0 + voxel / 2, y0 + voxel / 2, top_z - shape[2] * voxel + voxel / 2])
    return lattice_from_birth(np.full(shape, birth), origin, voxel)


def _rosenthal_error(voxel):
    """Largest relative error, at cells 3 or more voxels from the source, of the quasi-steady
    field of a point-like source moving along the symmetry plane y = 0 of a half block."""
    m = constant_material(K, RHO, CP)
    U, P = 10.0, 100.0
    length, half_width, depth = 28.0, 6.0, 6.0
    shape = tuple(int(round(v / voxel)) for v in (length, half_width, depth))
    lat = _block(shape, voxel)
    state = start(lat, m, HeatSettings(absorptivity=1.0, beam_radius=voxel, **NO_LOSS))
    x0, t = 3.0, 2.0  # 2 s: the start-up transient has decayed like exp(-U^2 t / (4 alpha)) = exp(-10)
    run(state, SourcePath.line([x0, 0, 0], [25.0, 0, 0], U, P / 2), t)  # half the power: half the solid
    xs = x0 + U * state.time  # the solver ends on a whole step, within dt after t
    c = lat.centres
    dx = c[:, 0] - xs
    r = np.sqrt(dx**2 + c[:, 1] ** 2 + c[:, 2] ** 2)
    exact = P / (2 * math.pi * K * 1e-3 * r) * np.exp(-U * (r + dx) / (2 * ALPHA))
    # cells 3 voxels or more from the source, within 3 mm, where the rise is at least 20 K
    # (1.5 % of the rise at 3 voxels: further ahead T - T0 vanishes and a ratio means nothing)
    near = (r >= 3 * voxel) & (r <= 3.0) & (exact >= 20.0)
    T = state.temperature()
    assert near.sum() > 100
    assert state.absorbed == pytest.approx(P / 2 * state.time, rel=1e-9)
    return float(np.max(np.abs(T[near] - exact[near]) / exact[near]))


def test_rosenthal_moving_point_source_within_5_percent_and_converging():
    coarse = _rosenthal_error(0.3)
    fine = _rosenthal_error(0.2)
    assert fine < 0.05
    assert fine < coarse


def test_semi_infinite_solid_under_constant_flux():
    """T(0, t) - T0 = 2 q sqrt(t / (pi k rho c)); below the surface, the exact depth profile."""
    m = constant_material(K, RHO, CP)
    voxel, depth, t, P = 0.25, 20.0, 2.0, 1.0
    lat = _block((2, 2, int(depth / voxel)), voxel)
    area = (2 * voxel) ** 2
    q = P / area  # W/mm^2 over the whole top: a beam far wider than the column
    state = start(lat, m, HeatSettings(absorptivity=1.0, beam_radius=1e4, **NO_LOSS))
    run(state, SourcePath.still([voxel, voxel, 0.0], 0.0, 10.0, P), t)
    k, rc = K * 1e-3, RHO * 1e-9 * CP
    column = np.flatnonzero((lat.ijk[:, 0] == 0) & (lat.ijk[:, 1] == 0))
    column = column[np.argsort(-lat.ijk[column, 2])]  # top first
    T = state.temperature()[column]
    surface = 2 * q * math.sqrt(t / (math.pi * k * rc))
    assert T[0] + (T[0] - T[1]) / 2 == pytest.approx(surface, rel=0.02)
    z = voxel / 2 + voxel * np.arange(8)
    s = math.sqrt(ALPHA * t)
    exact = 2 * q / k * (s / math.sqrt(math.pi) * np.exp(-z**2 / (4 * s * s)) - z / 2 * erfc(z / (2 * s)))
    assert np.allclose(T[:8], exact, rtol=0.02)


def test_lumped_convective_cooling():
    """A 2 mm copper-like cube (Biot 5e-3) on an adiabatic bottom: exp(-h A t / (rho c V))."""
    m = constant_material(400.0, 8900.0, 385.0)
    voxel, n = 0.5, 4
    lat = _block((n, n, n), voxel)
    h = 1000.0
    settings = HeatSettings(ambient=20.0, preheat=500.0, convection=h, emissivity=0.0, bottom="adiabatic")
    state = start(lat, m, settings)
    side = n * voxel
    tau = (8900e-9 * 385.0 * side**3) / (h * 1e-6 * 5 * side * side)  # five faces lose heat
    for t in (0.5, 1.0, 2.0, 3.0):
        run(state, SourcePath.still([0, 0, 0], 0.0, 0.0, 0.0), t)
        mean = float(np.mean(state.temperature()))
        assert mean - 20.0 == pytest.approx(480.0 * math.exp(-state.time / tau), rel=0.02)


def _wall_lattice(voxel, layers, layer_time, period, length=8.0, plate=(10.0, 10.0, 3.0)):
    """A plate with a one-cell-wide wall on it, layer n laid from t = n * period at the speed
    length / layer_time (cells born as the beam passes their centre)."""
    nx, ny, nz = (int(round(v / voxel)) for v in plate)
    shape = (nx, ny, nz + layers)
    birth = np.full(shape, np.inf)
    birth[:, :, :nz] = -np.inf
    x_lo = (plate[0] - length) / 2
    i = np.arange(int(round(length / voxel))) + int(round(x_lo / voxel))
    jw = ny // 2
    speed = length / layer_time
    for n in range(layers):
        birth[i, jw, nz + n] = n * period + ((i + 0.5) * voxel - x_lo) / speed
    origin = np.array([voxel / 2, voxel / 2, -nz * voxel + voxel / 2])
    lat = lattice_from_birth(birth, origin, voxel)
    y = (jw + 0.5) * voxel
    pieces = [SourcePath.line([x_lo, y, (n + 1) * voxel], [x_lo + length, y, (n + 1) * voxel], speed, 1.0,
                              t0=n * period) for n in range(layers)]
    path = SourcePath(*(np.concatenate([getattr(p, f) for p in pieces]) for f in ("t0", "t1", "p0", "p1", "power")))
    return lat, path, (x_lo, jw, nz)


def test_energy_balance_on_a_growing_wall():
    """absorbed = stored + lost within 0.5 % at every sample, with births, convection, radiation
    and a clamped bottom (a real alloy: latent heat and T-dependent properties)."""
    m = load_material("316L")
    lat, path, _ = _wall_lattice(0.5, 4, 1.0, 3.0)
    path = SourcePath(path.t0, path.t1, path.p0, path.p1, np.full(len(path), 300.0))
    settings = HeatSettings(absorptivity=0.5, beam_radius=0.5, convection=20.0, emissivity=0.5, bottom="clamped")
    result = solve_history(lat, m, settings, path, None, 14.0, sample_s=0.5)
    assert len(result.energy) >= 20
    for e in result.energy:
        assert e["absorbed_J"] > 0
        assert abs(e["absorbed_J"] - e["stored_J"] - e["lost_J"]) <= 0.005 * e["absorbed_J"]
    st = result.state
    assert st.n_born == len(lat)  # every wall cell born
    assert st.lost > 0 and np.nanmax(st.peak) > m.liquidus  # the beam melts the wall


def _exposed_area(lat, born):
    """Area (mm^2) of the faces of the cells ``born`` that face no born cell (the bottom excluded)."""
    nb = lat.neighbour[born]
    faced = np.zeros(nb.shape, bool)
    inner = nb >= 0
    faced[inner] = born[nb[inner]]
    return float(np.count_nonzero(~faced & (nb != BOTTOM))) * lat.voxel**2


def test_thin_wall_interlayer_temperature_levels_at_the_lumped_steady_state():
    """Interlayer temperature (mean of the top cells when the next layer starts) of a wall on a
    plate, short and long dwell, against the lumped model derived here: capacity C_n = rho c V_n
    and loss time tau_n = C_n / (h A_n) from the cells and exposed faces after layer n, energy E
    per layer delivered evenly over the pass t_p (it decays from then on: E_eff = E tau
    (e^(t_p / tau) - 1) / t_p), new cells born at the ambient, so
    T_n - T_inf = (C_{n-1} (T_{n-1} - T_inf) + E_eff) / C_n e^(-t / tau_n), and steady
    (E_eff / C) e^(-t / tau) / (1 - e^(-t / tau)). The body is made lumped on purpose (a
    conductivity that makes the wall's fin parameter m L = 0.33 and the plate even out in 0.03 s),
    so the comparison tests the solver's heat flow, not the model's assumption."""
    voxel, layers, t_pass, h_conv, power, t_inf = 2.0, 10, 0.2, 1000.0, 200.0, 20.0
    plate = (40.0, 40.0, 2.0)  # wide: the wall's sides add little to its loss area (tau_n falls slowly)
    rho, cp = 2400.0, 500.0  # tau ~ 2 s
    m = constant_material(7200.0, rho, cp)
    rc = rho * 1e-9 * cp
    found = {}
    for period in (1.0, 3.0):
        lat, path, (_, _, nz) = _wall_lattice(voxel, layers, t_pass, period, length=4.0, plate=plate)
        path = SourcePath(path.t0, path.t1, path.p0, path.p1, np.full(len(path), power))
        settings = HeatSettings(absorptivity=1.0, beam_radius=voxel, ambient=t_inf, convection=h_conv,
                                emissivity=0.0, bottom="adiabatic", birth_temperature=t_inf)
        state = start(lat, m, settings)
        measured, predicted = [], []
        # at each layer's start, before its beam: the mean of the previous layer's cells
        run(state, path, layers * period, stops=[n * period for n in range(1, layers + 1)],
            on_stop=lambda st, stop: measured.append(float(np.mean(st.temperature()[
                lat.ijk[:, 2] == nz + round(stop / period) - 1]))))
        T, C_prev = t_inf, rc * voxel**3 * np.count_nonzero(~np.isfinite(lat.birth))
        for n in range(1, layers + 1):
            born = lat.birth <= (n - 1) * period + t_pass
            C = rc * voxel**3 * np.count_nonzero(born)
            tau = C / (h_conv * 1e-6 * _exposed_area(lat, born))
            e_eff = power * t_pass * tau * (math.exp(t_pass / tau) - 1) / t_pass
            T = t_inf + (C_prev * (T - t_inf) + e_eff) / C * math.exp(-period / tau)
            C_prev = C
            predicted.append(T)
        rise = np.array(measured) - t_inf
        assert np.allclose(rise, np.array(predicted) - t_inf, rtol=0.10)
        r = math.exp(-period / tau)
        assert rise[-1] == pytest.approx((e_eff / C) * r / (1 - r), rel=0.10)
        found[period] = rise
    short, long = found[1.0], found[3.0]
    assert short[-1] > 1.3 * short[0]  # it rises with the layer number
    assert abs(short[-1] - short[-2]) < 0.1 * (short[1] - short[0])  # and levels off
    assert np.all(long < short)


def test_cells_are_born_in_order_and_faces_exposed_until_then():
    birth = np.full((3, 1, 3), np.inf)
    birth[:, :, 0] = -np.inf
    birth[:, 0, 1] = [3.0, 1.0, 2.0]
    lat = lattice_from_birth(birth, [0, 0, 0], 1.0)
    assert np.all(lat.birth[1:] >= lat.birth[:-1]) and len(lat) == 6
    assert lat.ijk[3].tolist() == [1, 0, 1] and lat.ijk[5].tolist() == [0, 0, 1]
    bottom = lat.neighbour[lat.ijk[:, 2] == 0, 4]
    assert np.all(bottom == BOTTOM)
    assert np.all(lat.neighbour[lat.ijk[:, 2] == 1, 5] == OPEN)
    m = constant_material(K, RHO, CP)
    state = start(lat, m, HeatSettings(**NO_LOSS))
    assert state.n_born == 3
    run(state, SourcePath.still([0, 0, 0], 0, 0, 0), 2.5)
    assert state.n_born == 5 and state.top[1, 0] == 3 and state.top[0, 0] == 0


def test_stable_time_step_criterion_and_determinism():
    m = load_material("IN718")
    s = HeatSettings()
    voxel = 0.5
    dt = stable_time_step(m, voxel, s)
    c = m.cp.min() * m.density * 1e-9 * voxel**3
    assert dt == pytest.approx(0.9 * c / (7 * m.k.max() * 1e-3 * voxel), rel=1e-12)
    lat, path, _ = _wall_lattice(voxel, 2, 1.0, 2.0)
    path = SourcePath(path.t0, path.t1, path.p0, path.p1, np.full(len(path), 500.0))
    a = start(lat, m, s)
    b = start(lat, m, s)
    run(a, path, 3.0)
    run(b, path, 3.0)
    assert np.array_equal(a.H, b.H) and np.array_equal(a.peak, b.peak)


def test_a_cell_arriving_in_the_last_step_exists_when_the_run_ends():
    """A cell born after the last step's start but before the run's end (the program's last
    bead end) is born by the end, its heat counted: absorbed = stored + lost."""
    m = constant_material(K, RHO, CP)
    birth = np.full((1, 1, 2), np.inf)
    birth[0, 0, 0] = -np.inf
    s = HeatSettings(**NO_LOSS)
    dt = stable_time_step(m, 1.0, s)
    birth[0, 0, 1] = 10.5 * dt  # within the 11th and last step of a run to 10.6 dt
    lat = lattice_from_birth(birth, [0, 0, 0], 1.0)
    state = start(lat, m, s)
    run(state, SourcePath.still([0, 0, 0], 0, 0, 0), 10.6 * dt)
    assert state.time == pytest.approx(11 * dt)
    assert state.n_born == 2 and state.top[0, 0] == 1
    assert state.absorbed == pytest.approx(state.stored - state.initial_stored + state.lost, rel=1e-12)


def test_the_beam_heats_no_cell_beyond_the_boiling_point_and_the_excess_is_a_loss():
    """A 1 kW beam held still on a 316L block: without a limit the spot passes 3,000 C; with the
    boiling point (3090 K) no cell exceeds it, what the beam would put beyond leaves as
    evaporation, counted as lost: absorbed = stored + lost within 0.5 % at every sample."""
    from dataclasses import replace

    m = load_material("316L")
    assert m.boiling == pytest.approx(3090.0 - 273.15, abs=0.5)
    lat = _block((8, 8, 6), 0.5, x0=-2.0, y0=-2.0)
    settings = HeatSettings(absorptivity=1.0, beam_radius=0.5, convection=10.0, emissivity=0.4, bottom="clamped")
    path = SourcePath.still([0.0, 0.0, 0.0], 0.0, 0.5, 1000.0)
    free = solve_history(lat, replace(m, boiling=None), settings, path, None, 0.5, sample_s=0.05)
    assert np.nanmax(free.state.peak) > m.boiling + 200.0
    capped = solve_history(lat, m, settings, path, None, 0.5, sample_s=0.05)
    st = capped.state
    assert np.nanmax(st.peak) <= m.boiling + 1e-6
    assert st.boiled > 0.05 * st.absorbed
    assert st.absorbed == pytest.approx(1000.0 * 0.5, abs=1000.0 * st.dt)  # the beam within a step
    for e in capped.energy:
        assert abs(e["absorbed_J"] - e["stored_J"] - e["lost_J"]) <= 0.005 * e["absorbed_J"]


def test_goldak_double_ellipsoid_integrates_to_the_power_and_the_kernel_places_it():
    """Goldak's source: its integral over the solid below the surface is Q (to 1e-6, Gauss-Legendre
    on each side); its value at the source and one semi-axis away in closed form; the solver puts
    eta P dt into the cells in proportion to it at their centres (one step from a uniform block:
    no conduction yet)."""
    from dmdvox.thermal.solver import goldak_density

    Q, a_f, a_r, b, c = 800.0, 1.5, 3.0, 2.0, 1.2
    x, w = np.polynomial.legendre.leggauss(80)

    def side(lo, hi):
        return 0.5 * (hi - lo) * x + 0.5 * (hi + lo), 0.5 * (hi - lo) * w

    total = 0.0
    for xs_, wx in (side(0.0, 6 * a_f), side(-6 * a_r, 0.0)):
        ys_, wy = side(-6 * b, 6 * b)
        zs_, wz = side(0.0, 6 * c)
        X, Y, Z = np.meshgrid(xs_, ys_, zs_, indexing="ij")
        q = goldak_density(np.stack([X, Y, Z], -1).reshape(-1, 3), Q, a_f, a_r, b, c).reshape(X.shape)
        total += np.einsum("ijk,i,j,k->", q, wx, wy, wz)
    assert total == pytest.approx(Q, rel=1e-6)
    centre = 6 * math.sqrt(3) * (2 * a_f / (a_f + a_r)) * Q / (a_f * b * c * math.pi**1.5)
    at = goldak_density([[0, 0, 0], [a_f, 0, 0], [-a_r, 0, 0], [0, b, 0], [0, 0, c]], Q, a_f, a_r, b, c)
    assert at[0] == pytest.approx(centre, rel=1e-12)
    assert np.allclose(at[1:], centre * math.exp(-3), rtol=1e-12)  # continuous at the source: f_f / a_f = f_r / a_r

    m = constant_material(K, RHO, CP)
    voxel = 0.25
    lat = _block((40, 24, 16), voxel, x0=-5.0, y0=-3.0)
    settings = HeatSettings(absorptivity=0.5, source="goldak", goldak=(a_f, a_r, b, c), **NO_LOSS)
    state = start(lat, m, settings)
    h0 = state.H.copy()
    run(state, SourcePath.line([-1.0, 0, 0], [4.0, 0, 0], 10.0, Q), state.dt)
    given = (state.H - h0) * voxel**3
    assert given.sum() == pytest.approx(0.5 * Q * state.dt, rel=1e-9)
    assert state.absorbed == pytest.approx(0.5 * Q * state.dt, rel=1e-9)
    source = np.array([-1.0 + 10.0 * 0.5 * state.dt, 0.0, 0.0])  # where the beam is mid-step
    rel = lat.centres - source
    rel[:, 2] = -rel[:, 2]  # depth below the top face, z = 0
    expect = goldak_density(rel, Q, a_f, a_r, b, c)
    reach = (np.abs(rel[:, 0]) <= 2 * max(a_f, a_r, b) + voxel) & (np.abs(rel[:, 1]) <= 2 * max(a_f, a_r, b) + voxel)
    inside = reach & (rel[:, 2] <= 2 * c)
    expect = np.where(inside, expect, 0.0)
    assert np.allclose(given / given.sum(), expect / expect.sum(), rtol=1e-9, atol=1e-15)
    assert given[rel[:, 2] > voxel].sum() > 0.3 * given.sum()  # a volumetric source: heat below the top cells


def test_a_graded_plate_carries_a_steady_flux_with_the_exact_linear_profile():
    """The plate's coarse layers: a 10 mm column of cells 1, 1, 2, 4, 4, 4 voxels tall under a
    uniform flux q, clamped at T_b below, no losses: at steady state T = T_b + q (z - z_b) / k at
    every cell centre (finite volumes are exact for a linear profile when the faces join the
    half heights in series), the flux through the bottom equals q."""
    from dmdvox.thermal.build import plate_layers

    m = constant_material(K, RHO, CP)
    voxel, n = 0.625, 16
    layers = plate_layers(n)
    assert sorted(layers[layers > 0].tolist()) == [1, 1, 2, 4, 4, 4]
    birth = np.full((2, 2, n), -np.inf)
    lat = lattice_from_birth(birth, [voxel / 2, voxel / 2, voxel / 2 - n * voxel], voxel, layers=layers)
    assert len(lat) == 4 * 6
    P = 2.0
    q = P / (2 * voxel) ** 2
    settings = HeatSettings(absorptivity=1.0, beam_radius=1e4, ambient=0.0, preheat=0.0, convection=0.0,
                            emissivity=0.0, bottom="clamped")
    state = start(lat, m, settings)
    run(state, SourcePath.still([voxel, voxel, 0.0], 0.0, 200.0, P), 100.0)  # 12 time constants
    z = lat.centres[:, 2] + n * voxel  # above the bottom face
    exact = q * z / (K * 1e-3)
    assert np.allclose(state.temperature(), exact, rtol=1e-4)


def test_energy_closes_to_1e9_on_a_wall_over_the_graded_plate():
    """The deposit's lattice (plate graded downwards): absorbed = stored + lost to 1e-9 of the
    absorbed energy at every sample."""
    lat, path, _ = _wall_lattice(0.5, 4, 1.0, 3.0)
    from dmdvox.thermal.build import plate_layers

    nz = lat.shape[2]
    plate = int(np.count_nonzero(~np.isfinite(lat.birth)) // (lat.shape[0] * lat.shape[1]))
    assert plate >= 4
    birth = np.full(lat.shape, np.inf)
    birth[tuple(lat.ijk.T)] = lat.birth
    layers = np.ones(nz, np.int64)
    layers[:plate] = plate_layers(plate)
    graded = lattice_from_birth(birth, lat.origin, lat.voxel, layers=layers)
    assert len(graded) < len(lat)
    m = load_material("316L")
    path = SourcePath(path.t0, path.t1, path.p0, path.p1, np.full(len(path), 300.0))
    settings = HeatSettings(absorptivity=0.5, beam_radius=0.5, convection=20.0, emissivity=0.5, bottom="clamped")
    result = solve_history(graded, m, settings, path, None, 14.0, sample_s=0.5)
    for e in result.energy:
        assert abs(e["absorbed_J"] - e["stored_J"] - e["lost_J"]) <= 1e-9 * e["absorbed_J"]
    assert result.state.n_born == len(graded)
