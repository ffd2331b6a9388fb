"""The deposit cache (dmdvox/deposit/cache.py): a kept deposit gives the very numbers a sweep
gives, any change of input misses, and a bad entry or folder never breaks a command."""

import dataclasses
import os

import numpy as np
import pytest

from dmdvox.comparison.compare import CompareRequest, compare
from dmdvox.deposit import cache as cache_module
from dmdvox.deposit.cache import DepositCache
from dmdvox.deposit.engine import deposit_beads
from dmdvox.deposit.simulate import SimulateRequest, fixed_plan, simulate
from dmdvox.errors import ResourceError
from dmdvox.grid.analysis import porosity
from dmdvox.io.mesh import box_mesh, write_stl
from dmdvox.process.profiles import BeadProfile
from dmdvox.toolpath import read_gcode

VOXEL = 0.25
# wider than the deposit on every side, by more than a block (2 mm at this voxel) on some
CAD_LO, CAD_HI = (-3.0, -0.5, -2.6), (24.0, 20.2, 9.0)


@pytest.fixture(scope="module")
def demo_plan(tmp_path_factory):
    """Three parallel beads, two layers, 0.5 mm apart: two sliver pores between them."""
    lines = ["G90 G1 X0 Y0 Z0 F600"]
    for z in (0.0, 1.0):
        for y in (0.0, 3.0, 6.0):
            lines += [f"G1 X0 Y{y} Z{z}", "M65", f"G1 X10 Y{y} Z{z}", "M64"]
    gcode = tmp_path_factory.mktemp("part") / "slivers.gcode"
    gcode.write_text("\n".join(lines) + "\n")
    return fixed_plan(read_gcode(gcode, dialect="seed"), BeadProfile("rect", 2.5, 1.0))


@pytest.fixture
def kept(tmp_path, monkeypatch):
    """The commands' cache in a folder of the test's own, keeping deposits of any size."""
    folder = tmp_path / "cache"
    monkeypatch.setattr(DepositCache, "from_environment", classmethod(lambda cls: cls(folder, min_active_voxels=0)))
    return DepositCache(folder, min_active_voxels=0)


def _grids_equal(a, b):
    for f in dataclasses.fields(a):
        x, y = getattr(a, f.name), getattr(b, f.name)
        if isinstance(x, np.ndarray):
            assert x.dtype == y.dtype and np.array_equal(x, y), f.name
        else:
            assert x == y, f.name


def _without_timings(summary):
    return {k: v for k, v in summary.items() if k != "timings_s"}


def test_a_kept_deposit_gives_the_comparison_a_sweep_gives(demo_plan, kept, tmp_path):
    cad = tmp_path / "cad.stl"
    write_stl(cad, *box_mesh(CAD_LO, CAD_HI))
    stored = simulate(SimulateRequest(demo_plan, voxel=VOXEL))
    assert "cache_load_s" not in stored["timings_s"] and len(list(kept.folder.glob("*.npz"))) == 1
    from_cache = compare(CompareRequest(demo_plan, cad, voxel=VOXEL))
    assert "cache_load_s" in from_cache["timings_s"] and "sweep_s" not in from_cache["timings_s"]
    swept = compare(CompareRequest(demo_plan, cad, voxel=VOXEL, cache=False))
    assert "sweep_s" in swept["timings_s"] and "cache_load_s" not in swept["timings_s"]
    assert _without_timings(from_cache.summary) == _without_timings(swept.summary)
    assert swept["pore_count"] == 2  # the voids travel through the cache, not only the grid
    _grids_equal(from_cache.deposit, swept.deposit)
    _grids_equal(from_cache.simulation.porosity.voids, swept.simulation.porosity.voids)
    # and what both compared is the deposit swept on the CAD's table directly, voids and all
    direct, _ = deposit_beads(demo_plan.lay(VOXEL).beads, VOXEL, extra_bounds=(np.array(CAD_LO), np.array(CAD_HI)))
    used = from_cache.deposit
    assert np.array_equal(used.origin, direct.origin) and used.block_shape == direct.block_shape
    np.testing.assert_array_equal(used.dense_sdf(), direct.dense_sdf())
    voids = porosity(direct, demo_plan.settings.landing.plate_z, demo_plan.profile.width).voids
    ijk = np.argwhere(np.ones(8 * np.asarray(direct.block_shape), bool))
    np.testing.assert_array_equal(from_cache.simulation.porosity.voids.label_at(ijk), voids.label_at(ijk))


def test_a_grid_widened_by_whole_blocks_is_the_grid_swept_wide(demo_plan):
    # compare sweeps the deposit on its own table and widens it to the CAD's; the values at
    # every voxel and the voids must be those of a sweep on the wide table itself
    beads = demo_plan.lay(VOXEL).beads
    narrow, _ = deposit_beads(beads, VOXEL)
    wide, _ = deposit_beads(beads, VOXEL, extra_bounds=(np.array(CAD_LO), np.array(CAD_HI)))
    assert np.all(np.asarray(wide.block_shape) > np.asarray(narrow.block_shape))
    assert np.any(wide.origin < narrow.origin - 8 * VOXEL)  # grown below by more than a block
    widened = narrow.widened(wide.origin, wide.block_shape)
    np.testing.assert_array_equal(widened.dense_sdf(), wide.dense_sdf())
    np.testing.assert_array_equal(widened.dense_arrival(), wide.dense_arrival())
    plate = demo_plan.settings.landing.plate_z
    own, grown = porosity(narrow, plate, demo_plan.profile.width), porosity(wide, plate, demo_plan.profile.width)
    assert len(own.pores) == len(grown.pores) == 2
    np.testing.assert_array_equal(own.voids.volume_mm3, grown.voids.volume_mm3)
    ijk = np.argwhere(np.ones(8 * np.asarray(wide.block_shape), bool))
    np.testing.assert_array_equal(own.voids.widened(wide.origin).label_at(ijk), grown.voids.label_at(ijk))
    with pytest.raises(ValueError, match="whole blocks"):
        narrow.widened(wide.origin + VOXEL, wide.block_shape)


def test_every_input_of_the_deposit_is_in_the_key(demo_plan, kept):
    """The key is known before any bead is laid: the planned program, the bead, the settings,
    the voxel and ``until`` each change it; equal content gives the same key."""
    replace = dataclasses.replace
    tp, profile, settings = demo_plan.toolpath, demo_plan.profile, demo_plan.settings
    key = kept.plan_key(demo_plan, VOXEL, None)
    assert kept.plan_key(replace(demo_plan, toolpath=replace(tp, end=tp.end.copy())), VOXEL, None) == key
    nudged = tp.end.copy()
    row = int(np.flatnonzero(tp.deposit)[len(np.flatnonzero(tp.deposit)) // 2])
    nudged[row, 2] = np.nextafter(nudged[row, 2], np.inf)
    plate = -1.0 if settings.landing.plate_z is None else None
    others = [
        kept.plan_key(replace(demo_plan, toolpath=replace(tp, end=nudged)), VOXEL, None),
        kept.plan_key(replace(demo_plan, profile=replace(profile, exponent=profile.exponent + 1.0)), VOXEL, None),
        kept.plan_key(replace(demo_plan, profile=replace(profile, width=profile.width * 2)), VOXEL, None),
        kept.plan_key(replace(demo_plan, settings=replace(settings, landing=replace(settings.landing, plate_z=plate))),
                      VOXEL, None),
        kept.plan_key(demo_plan, 0.2, None),
        kept.plan_key(demo_plan, VOXEL, 5.0),
    ]
    assert len({key, *others}) == len(others) + 1


def test_the_code_is_in_the_key(demo_plan, kept, monkeypatch):
    before = kept.plan_key(demo_plan, VOXEL, None)
    monkeypatch.setattr(cache_module, "code_fingerprint", lambda: "another dmdvox")
    assert kept.plan_key(demo_plan, VOXEL, None) != before


def _stored(demo_plan, cache, width=None):
    beads = demo_plan.lay(VOXEL).beads
    grid, _ = deposit_beads(beads, VOXEL)
    result = porosity(grid, demo_plan.settings.landing.plate_z, demo_plan.profile.width)
    plan = demo_plan if width is None else \
        dataclasses.replace(demo_plan, profile=dataclasses.replace(demo_plan.profile, width=width))
    key = cache.plan_key(plan, VOXEL, None)
    return key, cache.store(key, grid, result), grid, result


def test_an_entry_loads_back_exactly_and_is_refused_beyond_the_memory_budget(demo_plan, kept):
    key, path, grid, result = _stored(demo_plan, kept)
    loaded_grid, loaded, _, _ = kept.load(key, VOXEL, None)
    _grids_equal(loaded_grid, grid)
    _grids_equal(loaded.voids, result.voids)
    assert [p.volume_mm3 for p in loaded.pores] == [p.volume_mm3 for p in result.pores]
    assert loaded.porosity_percent == result.porosity_percent
    with pytest.raises(ResourceError, match="needs about"):
        kept.load(key, VOXEL, path.stat().st_size // 2)


def test_an_unreadable_entry_is_said_removed_and_swept_again(demo_plan, kept, capsys):
    key, path, _, _ = _stored(demo_plan, kept)
    path.write_bytes(path.read_bytes()[: path.stat().st_size // 3])
    assert kept.load(key, VOXEL, None) is None
    assert "does not match its checksum" in capsys.readouterr().err and not path.exists()
    assert kept.load(key, VOXEL, None) is None  # gone: an ordinary miss, said no more
    assert capsys.readouterr().err == ""


def test_a_hand_edited_entry_is_said_removed_and_swept_again(demo_plan, kept, capsys):
    """An entry edited into another valid one (its volume set to 1.0 and a pore's voxels moved:
    it loads without error) is not trusted: its bytes no longer match the checksum kept beside
    it, and the command sweeps again."""
    import json

    key, path, _, result = _stored(demo_plan, kept)
    with np.load(path, allow_pickle=False) as entry:
        members = {name: entry[name] for name in entry.files}
    header = json.loads(str(members["header"]))
    header["deposit_volume_mm3"] = 1.0
    members["header"] = np.array(json.dumps(header))
    members["voids.block_coord"] = members["voids.block_coord"] + 1
    with open(path, "wb") as fh:
        np.savez(fh, **members)
    assert kept.load(key, VOXEL, None) is None
    assert "does not match its checksum" in capsys.readouterr().err
    assert not path.exists() and not kept.checksum_path(key).exists()
    swept = simulate(SimulateRequest(demo_plan, voxel=VOXEL))
    assert "sweep_s" in swept["timings_s"] and "cache_load_s" not in swept["timings_s"]
    assert swept["deposit_volume_mm3"] == result.deposit_volume_mm3 and swept["pore_count"] == 2
    # swept again and kept again, with its checksum: the next command loads it
    assert "cache_load_s" in simulate(SimulateRequest(demo_plan, voxel=VOXEL))["timings_s"]


def test_an_entry_without_its_checksum_is_swept_again(demo_plan, kept, capsys):
    key, path, _, _ = _stored(demo_plan, kept)
    kept.checksum_path(key).unlink()
    assert kept.load(key, VOXEL, None) is None and not path.exists()
    assert "does not match its checksum" in capsys.readouterr().err


def test_small_deposits_are_not_kept(demo_plan, tmp_path):
    small = DepositCache(tmp_path / "cache")  # the default floor, far above the demo's voxels
    _, path, grid, _ = _stored(demo_plan, small)
    assert grid.active_voxels < small.min_active_voxels and path is None
    assert not small.folder.exists() or not any(small.folder.iterdir())


def test_the_folder_keeps_the_most_recently_used_entries(demo_plan, tmp_path):
    unbounded = DepositCache(tmp_path / "cache", min_active_voxels=0)
    first, path, _, _ = _stored(demo_plan, unbounded, width=1.0)
    bounded = dataclasses.replace(unbounded, max_bytes=int(2.5 * path.stat().st_size))
    second, _, _, _ = _stored(demo_plan, bounded, width=2.0)
    an_hour_ago = path.stat().st_mtime - 3600
    os.utime(path, (an_hour_ago - 60, an_hour_ago - 60))  # the first kept is the oldest...
    os.utime(bounded.path(second), (an_hour_ago, an_hour_ago))
    assert bounded.load(first, VOXEL, None) is not None  # ...until it is used again
    third, _, _, _ = _stored(demo_plan, bounded, width=3.0)
    assert {p.stem for p in bounded.folder.glob("*.npz")} == {first, third}


def test_an_unwritable_folder_is_said_and_the_command_goes_on(demo_plan, tmp_path, monkeypatch, capsys):
    blocker = tmp_path / "a file"
    blocker.write_text("not a folder")
    monkeypatch.setattr(DepositCache, "from_environment",
                        classmethod(lambda cls: cls(blocker / "cache", min_active_voxels=0)))
    result = simulate(SimulateRequest(demo_plan, voxel=VOXEL))
    assert result["deposit_volume_mm3"] > 0
    assert "could not be kept" in capsys.readouterr().err


def test_the_environment_names_the_folder_or_turns_it_off(tmp_path, monkeypatch):
    monkeypatch.setenv("DMDVOX_CACHE", "OFF")
    assert DepositCache.from_environment() is None
    monkeypatch.setenv("DMDVOX_CACHE", str(tmp_path / "mine"))
    assert DepositCache.from_environment().folder == tmp_path / "mine"
    monkeypatch.delenv("DMDVOX_CACHE")
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "xdg"))
    assert DepositCache.from_environment().folder == tmp_path / "xdg" / "dmdvox" / "deposits"
    monkeypatch.delenv("XDG_CACHE_HOME")
    monkeypatch.setenv("HOME", str(tmp_path / "home"))
    assert DepositCache.from_environment().folder == tmp_path / "home" / ".cache" / "dmdvox" / "deposits"


def test_a_hit_skips_laying_and_landing_and_gives_the_same_result(kept, monkeypatch):
    """Keyed on the plan before landing, the entry holds the landed beads: a hit calls neither
    the bead builder nor the landing, and gives the sweep's numbers and beads."""
    import dmdvox.process.plan as plan_module
    from dmdvox.process.landing import LandingSettings
    from dmdvox.process.plan import ProcessSettings, plan_process

    from .conftest import DATA

    def planned(**landing):
        return plan_process(read_gcode(DATA / "prusa_block_20.gcode"), ProcessSettings(landing=LandingSettings(**landing)))

    plan = planned()
    assert plan.model == "flow"
    # the key is the plan's content: the same for the program planned again, another for another setting
    assert kept.plan_key(plan, 0.1, None) == kept.plan_key(planned(), 0.1, None)
    assert len({kept.plan_key(plan, 0.1, None), kept.plan_key(plan, 0.1, 5.0), kept.plan_key(plan, 0.12, None),
                kept.plan_key(planned(max_drop_mm=0.5), 0.1, None)}) == 4
    stored = simulate(SimulateRequest(plan, voxel=0.1))
    calls = []

    def counted(name, function):
        def wrapper(*args, **kwargs):
            calls.append(name)
            return function(*args, **kwargs)
        return wrapper

    monkeypatch.setattr(plan_module, "land", counted("land", plan_module.land))
    monkeypatch.setattr(plan_module, "build_beads", counted("beads", plan_module.build_beads))
    hit = simulate(SimulateRequest(plan, voxel=0.1))
    assert calls == [] and "cache_load_s" in hit["timings_s"] and "beads_s" not in hit["timings_s"]
    # a hit's memory estimate is the entry's size and what follows it (DepositCache.load), not the sweep's
    same = {k: v for k, v in _without_timings(hit.summary).items() if k != "memory_estimate_bytes"}
    assert same == {k: v for k, v in _without_timings(stored.summary).items() if k != "memory_estimate_bytes"}
    _grids_equal(hit.grid, stored.grid)
    _grids_equal(hit.laid.beads, stored.laid.beads)
    _grids_equal(hit.laid.programmed, stored.laid.programmed)
    assert {f.name for f in dataclasses.fields(hit.laid.landing)} >= {"dz", "reason"}
    for f in dataclasses.fields(stored.laid.landing):
        if f.name != "programmed":
            x, y = getattr(hit.laid.landing, f.name), getattr(stored.laid.landing, f.name)
            assert np.array_equal(x, y) if isinstance(x, np.ndarray) else x == y, f.name
