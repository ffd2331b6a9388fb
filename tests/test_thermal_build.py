"""From a program and its deposit to the heat model: the lattice (births, plate) and the beam."""

import numpy as np
import pytest

from dmdvox.deposit.simulate import SimulateRequest, simulate
from dmdvox.errors import DmdvoxError
from dmdvox.process.plan import ProcessSettings, plan_process
from dmdvox.process.planner import MotionSettings
from dmdvox.thermal.build import PLATE_MARGIN_MM, PlateSpec, beam_path, deposit_lattice, thermal_voxel
from dmdvox.toolpath.reader import read_gcode

FEED = 10.0  # mm/s
WALL = """(two 10 mm tracks, one on the other; a 0.5 s dwell with the beam on before the second)
M64
G90 G21 G17
F600
G0 X0 Y0 Z5
G1 Z0
M65
G1 X10 Y0 Z0
M64
G0 X0 Y0 Z5.75
G1 Z0.75
M65
G4 P500
G1 X10
M64
"""


@pytest.fixture(scope="module")
def wall(tmp_path_factory):
    path = tmp_path_factory.mktemp("wall") / "wall.gcode"
    path.write_text(WALL)
    plan = plan_process(read_gcode(str(path), dialect="seed"),
                        ProcessSettings(motion=MotionSettings(accel_mm_s2=0.0)))
    grid = simulate(SimulateRequest(plan, voxel=0.125, cache=False)).grid
    return plan, grid


def test_cells_are_born_when_the_bead_covers_their_centre(wall):
    plan, grid = wall
    m, h = thermal_voxel(grid, None, plan.profile.width)
    assert m == 5 and h == pytest.approx(0.625)  # a quarter of the 2.5 mm bead on the 0.125 mm lattice
    lat = deposit_lattice(grid, m, 0.0)
    part = np.isfinite(lat.birth)
    c = lat.centres[part]
    tp = plan.toolpath
    rows = np.flatnonzero(tp.deposit)
    # the centreline cells of the first track, away from its caps: born as the tool passes x
    on_line = (np.abs(c[:, 1]) < h / 2) & (c[:, 2] < 0.75) & (c[:, 0] > 1.5) & (c[:, 0] < 8.5)
    assert on_line.sum() >= 10
    expect = tp.t_start[rows[0]] + c[on_line, 0] / FEED
    assert np.allclose(lat.birth[part][on_line], expect, atol=h / FEED)
    assert np.all(c[:, 2] > 0.0)  # above the plate's top
    # the part's cells hold the beads' volume (two rect tracks 2.5 x 0.75 x 10 mm with round
    # ends) where the cells fit the 1.5 mm height: 0.375 mm, four cells
    fine = deposit_lattice(grid, 3, 0.0)
    volume = 2 * (2.5 * 0.75 * 10.0 + np.pi * 1.25**2 * 0.75)
    assert np.count_nonzero(np.isfinite(fine.birth)) * fine.voxel**3 == pytest.approx(volume, rel=0.05)


def test_plate_is_the_footprint_plus_the_margin_and_10_mm_thick(wall):
    plan, grid = wall
    lat = deposit_lattice(grid, 5, 0.0)
    plate = ~np.isfinite(lat.birth)
    c = lat.centres[plate]
    h = lat.voxel
    # the plate's top on a cell boundary within half a deposit voxel of z = 0
    assert c[:, 2].max() == pytest.approx(-h / 2, abs=grid.voxel / 2)
    # 10 mm from the top face to the bottom face (the plate's cells grow taller downwards)
    half = 0.5 * h * lat.dz[plate]
    assert (c[:, 2] + half).max() - (c[:, 2] - half).min() == pytest.approx(10.0)
    # its volume: every column of the footprint 10 mm deep
    columns = len({(i, j) for i, j in lat.ijk[plate, :2].tolist()})
    assert np.sum(lat.dz[plate]) * h**3 == pytest.approx(columns * h * h * 10.0)
    # footprint: x -1.25 .. 11.25, y -1.25 .. 1.25 (the bead's half width round the track)
    for axis, (lo, hi) in enumerate(((-1.25, 11.25), (-1.25, 1.25))):
        assert c[:, axis].min() == pytest.approx(lo - PLATE_MARGIN_MM, abs=1.5 * h)
        assert c[:, axis].max() == pytest.approx(hi + PLATE_MARGIN_MM, abs=1.5 * h)
    sized = deposit_lattice(grid, 5, 0.0, PlateSpec(30.0, 20.0, 5.0))
    on = ~np.isfinite(sized.birth)
    c = sized.centres[on]
    assert c[:, 0].max() - c[:, 0].min() == pytest.approx(30.0 - h, abs=h)
    half = 0.5 * h * sized.dz[on]
    assert (c[:, 2] + half).max() - (c[:, 2] - half).min() == pytest.approx(5.0)


def test_beam_follows_the_planned_path_with_its_dwell(wall):
    plan, _ = wall
    tp = plan.toolpath
    path = beam_path(plan, 800.0)
    rows = np.flatnonzero(tp.deposit & (tp.length > 0))
    # energy: the power over both tracks' times and the 0.5 s dwell
    assert path.energy == pytest.approx(800.0 * (2 * 10.0 / FEED + 0.5), rel=1e-9)
    t = tp.t_start[rows[1]] + 0.37
    assert path.position(t)[0] == pytest.approx([0.37 * FEED, 0.0, 0.75])
    still = path.position(tp.t_start[rows[1]] - 0.25)[0]
    assert still == pytest.approx([0.0, 0.0, 0.75])
    assert np.all(np.isnan(path.position(tp.t_end[rows[0]] + 0.1)))  # the travel between: off


def test_bad_beam_and_lattice_inputs_name_the_option(wall):
    plan, grid = wall
    with pytest.raises(DmdvoxError, match="--laser-power"):
        beam_path(plan, -5.0)
    with pytest.raises(DmdvoxError, match="--laser-power"):
        beam_path(plan, None)  # the program has no S words
    with pytest.raises(DmdvoxError, match="--thermal-voxel"):
        thermal_voxel(grid, 3.0, plan.profile.width)


def test_lattice_memory_bound_holds_the_lattice_and_refusal_names_a_voxel_that_fits(wall):
    import re

    from dmdvox.errors import ResourceError
    from dmdvox.thermal.build import lattice_bytes
    from dmdvox.thermal.lattice import bytes_per_cell
    from dmdvox.thermal.run import check_lattice_memory

    plan, grid = wall
    m, _ = thermal_voxel(grid, None, plan.profile.width)
    need = lattice_bytes(grid, m, 0.0)
    lat = deposit_lattice(grid, m, 0.0)
    # the bound, known before allocating, covers every cell the lattice then holds and its box
    assert need >= len(lat) * bytes_per_cell() + lat.nbytes
    assert need >= int(np.prod(lat.shape)) * (bytes_per_cell() + 8)
    check_lattice_memory(grid, m, 0.0, PlateSpec(), plan.profile.width, need)  # exactly enough: runs
    with pytest.raises(ResourceError) as err:
        check_lattice_memory(grid, m, 0.0, PlateSpec(), plan.profile.width, need // 4)
    text = str(err.value)
    assert text.startswith("--thermal-voxel 0.625:")
    fits = float(re.search(r"give --thermal-voxel ([0-9.]+) or coarser", text).group(1))
    m_fit = int(round(fits / grid.voxel))
    assert m_fit > m and m_fit * grid.voxel == pytest.approx(fits)
    assert lattice_bytes(grid, m_fit, 0.0) <= need // 4
    # a budget no voxel up to the bead width meets: said so
    with pytest.raises(ResourceError, match="would not fit"):
        check_lattice_memory(grid, m, 0.0, PlateSpec(), plan.profile.width, 1000)


def test_every_part_cell_of_a_wall_ending_on_its_last_bead_is_born(wall):
    """WALL ends on its last bead: the cells of that bead's end arrive at the program's end (as
    float32, rounded up past it). Every part cell is born by the end of the run, none after
    the program's end."""
    from dmdvox.thermal.outputs import heat_deposit

    plan, _ = wall
    grid = simulate(SimulateRequest(plan, voxel=0.3125, cache=False)).grid
    result, _ = heat_deposit(plan, grid, 0.0, {"material": "316L", "laser_power": 1000.0, "thermal_voxel": 0.625})
    lat = result.lattice
    part = np.isfinite(lat.birth)
    end = plan.toolpath.duration
    assert np.max(lat.birth[part]) <= end
    # the last track's end cap: cells born within the run's last step
    assert np.count_nonzero(lat.birth[part] > result.state.time - result.state.dt) > 0
    assert result.state.n_born == len(lat)
    assert np.all(np.isfinite(result.state.peak))


@pytest.mark.parametrize("m", [2, 3])
def test_births_read_the_arrival_at_the_cell_centre_for_odd_and_even_m(wall, m):
    """Along the first track (constant speed, no acceleration) the bead passes a cell's centre
    at t_start + x / FEED: an even m reads the centre too (the mean of the 2 x 2 x 2 voxels
    around it), not the voxel m // 2, half a deposit voxel ahead (6.25 ms late at 0.125 mm and
    10 mm/s). The lowest cells: their voxels lie in the deposit's narrow band, where it keeps
    each voxel's arrival (deeper inside, an octant's earliest)."""
    plan, grid = wall
    lat = deposit_lattice(grid, m, 0.0)
    h = m * grid.voxel
    part = np.isfinite(lat.birth)
    c = lat.centres[part]
    tp = plan.toolpath
    rows = np.flatnonzero(tp.deposit)
    on_line = (np.abs(c[:, 1]) < 0.5) & (c[:, 2] < h) & (c[:, 0] > 2.0) & (c[:, 0] < 8.0)
    assert on_line.sum() >= 10
    expect = tp.t_start[rows[0]] + c[on_line, 0] / FEED
    # the arrival's own resolution along the track: a tenth of a deposit voxel's passage
    assert np.allclose(lat.birth[part][on_line], expect, rtol=0, atol=0.1 * grid.voxel / FEED)
