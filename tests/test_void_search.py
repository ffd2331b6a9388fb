"""The void search's shortcuts (grid/enclosure.py) change no answer: the reach searched only where
a flag can still change against the search over every voxel, on a part with a pore, a cavity
behind a channel narrower than the channel width, one behind a wider channel, crevices and an
open fin, and on a deposited thin-walled box (issue 26)."""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest

from dmdvox.deposit.engine import deposit_beads
from dmdvox.deposit.simulate import fixed_plan
from dmdvox.grid import enclosure as E
from dmdvox.grid.build import grid_from_dense
from dmdvox.grid.enclosure import CHANNEL_FRACTION, enclosed_voids
from dmdvox.grid.sparse import BLOCK_VOXELS
from dmdvox.process.profiles import BeadProfile
from dmdvox.toolpath import read_gcode

VOXEL = 0.1
BEAD = 2.5  # channel width s = 0.625 mm: ball centres 3.125 voxels clear, beyond the 3-voxel band


def box(X, Y, Z, lo, hi):
    c = [(lo[a] + hi[a]) / 2 for a in range(3)]
    q = np.stack([np.abs(X - c[0]), np.abs(Y - c[1]), np.abs(Z - c[2])], -1) - (np.asarray(hi) - lo) / 2
    return np.linalg.norm(np.maximum(q, 0), axis=-1) + np.minimum(q.max(-1), 0)


def ball(X, Y, Z, c, r):
    return np.sqrt((X - c[0]) ** 2 + (Y - c[1]) ** 2 + (Z - c[2]) ** 2) - r


def rod_y(X, Y, Z, x, z, r, y0, y1):
    """A cylinder along y from y0 to y1."""
    radial = np.sqrt((X - x) ** 2 + (Z - z) ** 2) - r
    return np.maximum(radial, np.maximum(y0 - Y, Y - y1))


def part(X, Y, Z):
    solid = box(X, Y, Z, (0.5, 0.5, 0.0), (6.0, 4.0, 2.4))
    solid = np.minimum(solid, box(X, Y, Z, (1.0, 0.5, 2.4), (5.5, 0.62, 3.6)))  # an open fin on top
    cavity = ball(X, Y, Z, (1.5, 2.2, 1.2), 0.5)  # a pore
    cavity = np.minimum(cavity, ball(X, Y, Z, (3.2, 2.2, 1.2), 0.5))  # behind a narrow channel
    cavity = np.minimum(cavity, rod_y(X, Y, Z, 3.2, 1.2, 0.15, 1.8, 9.0))
    cavity = np.minimum(cavity, ball(X, Y, Z, (4.8, 2.2, 1.2), 0.5))  # behind a wide one
    cavity = np.minimum(cavity, rod_y(X, Y, Z, 4.8, 1.2, 0.45, 1.8, 9.0))
    for x in (2.0, 2.6, 3.3):  # crevices in the top: concave corners the direct reach leaves out
        cavity = np.minimum(cavity, box(X, Y, Z, (x, 1.0, 2.0), (x + 0.18, 3.6, 2.6)))
    return np.maximum(solid, -cavity)


@pytest.fixture(scope="module")
def walled():
    n = (64, 48, 40)
    lo = (-0.15, -0.15, -0.35)
    X, Y, Z = np.meshgrid(*[lo[a] + VOXEL * np.arange(n[a]) for a in range(3)], indexing="ij")
    sdf = np.clip(part(X, Y, Z), -3 * VOXEL, 3 * VOXEL).astype(np.float32)
    arrival = np.where(sdf < 0, 10.0 + Z, np.inf).astype(np.float32)
    return grid_from_dense(sdf, arrival, VOXEL, np.asarray(lo, float), 3 * VOXEL)


def assert_same_voids(a, b):
    for field in dataclasses.fields(a):
        x, y = getattr(a, field.name), getattr(b, field.name)
        if isinstance(x, np.ndarray):
            assert x.dtype == y.dtype and x.shape == y.shape, field.name
            assert np.array_equal(x, y, equal_nan=x.dtype.kind == "f"), field.name
        else:
            assert x == y, field.name


def left_out_and_searched(grid, bead_width):
    """Voxels the direct reach leaves out, and the work blocks the pruned search may enter."""
    v = grid.voxel
    zp = (E.lowest_deposit_z(grid) - grid.origin[2]) / v
    channel = CHANNEL_FRACTION * bead_width
    r_vox, band_vox = 0.5 * channel / v, float(np.float32(grid.band)) / v
    reach_vox = max(channel / v, r_vox + E.REACH_SLACK_VOXELS)
    wid, wcoord, tile_open = E._work_blocks(grid, zp, r_vox, band_vox)
    n = len(wcoord)
    state = np.empty((n, BLOCK_VOXELS), np.uint8)
    dep = np.empty((n, BLOCK_VOXELS), np.float32)
    E._classify(wcoord, grid.view(), 1.0 / v, band_vox, zp, r_vox, state, dep)
    E._extend_clearance(wid, wcoord, state, dep, band_vox, r_vox, grid.n_leaf)
    labels, counts = E._label_blocks(state == E.CENTRE)
    comp_off = np.concatenate([[0], np.cumsum(counts)])
    root = E._connect(wid, tile_open, wcoord, labels, comp_off)
    E._mark_exterior_centres(state, labels, comp_off, root, root[wid.size], wid.size)
    tile_ext = tile_open & (root[: wid.size] == root[wid.size])
    dist = np.full(n * BLOCK_VOXELS, np.inf, np.float32)
    nbr = E._block_neighbours(wid, wcoord)
    E._reach_direct(nbr, wid, wcoord, state, dep, tile_ext, zp, r_vox, reach_vox, band_vox, dist)
    cls = state & E.CLASS_MASK
    left = ((cls == E.RESIDUAL) | (cls == E.PARTIAL)) & ~(dist.reshape(n, BLOCK_VOXELS) <= reach_vox)
    lo, hi = E._unreached_boxes(wid, wcoord, state, dist, reach_vox, False)
    return int(left.sum()), int(np.count_nonzero(lo[:, 0] <= hi[:, 0])), n


def test_pruned_reach_finds_the_exhaustive_voids(walled):
    grid = walled
    fast = enclosed_voids(grid, bead_width=BEAD)
    assert_same_voids(fast, enclosed_voids(grid, bead_width=BEAD, exhaustive=True))
    # the pore and the cavity behind the channel narrower than s (0.3 < 0.625 mm) are enclosed,
    # the cavity behind the 0.9 mm channel is open, and so are the crevices and the fin
    assert fast.n_pores == 2
    pore = 4 / 3 * math.pi * 0.5**3
    centres = fast.centroid_mm[~fast.speck]
    by_x = np.argsort(centres[:, 0])
    np.testing.assert_allclose(centres[by_x][:, [0, 2]], [[1.5, 1.2], [3.2, 1.2]], atol=0.15)
    volumes = fast.volume_mm3[~fast.speck][by_x]
    assert volumes[0] == pytest.approx(pore, rel=0.03)
    channel = math.pi * 0.15**2 * (4.0 - 2.2 - 0.5)  # the channel inside the part beyond its ball
    assert pore < volumes[1] < pore + channel
    # the search had something to prove, and proved it in part of the blocks only
    left, searched, n = left_out_and_searched(grid, BEAD)
    assert left > 100
    assert 0 < searched < n


def test_without_the_channel_rule_or_the_plate_the_same_voids(walled):
    for kwargs in ({"bead_width": None}, {"bead_width": BEAD, "plate_z": -np.inf}, {"bead_width": 1.0}):
        fast = enclosed_voids(walled, **kwargs)
        assert_same_voids(fast, enclosed_voids(walled, exhaustive=True, **kwargs))
    # no rule: every channel opens its cavity, only the sealed pore is left
    assert enclosed_voids(walled, bead_width=None).n_pores == 1


def test_deposited_thin_walled_box_has_no_void_either_way(tmp_path):
    # two overlapping square tracks per layer, as in scripts/bench_thin_wall_box.py
    lines = ["M64", "G90 G21 G17", "F750"]
    for layer in range(4):
        z = 0.8 * layer
        for a in (1.25, 2.5):
            b = 12.0 - a
            lines += [f"G0 X{a} Y{a} Z{z:.1f}", "M65", f"G1 X{b} Y{a}", f"G1 X{b} Y{b}", f"G1 X{a} Y{b}",
                      f"G1 X{a} Y{a}", "M64"]
    path = tmp_path / "box.gcode"
    path.write_text("\n".join(lines) + "\n")
    plan = fixed_plan(read_gcode(path, dialect="seed"), BeadProfile("rect", 2.5, 0.8))
    grid, _ = deposit_beads(plan.beads(VOXEL), VOXEL)
    fast = enclosed_voids(grid, bead_width=2.5)
    assert_same_voids(fast, enclosed_voids(grid, bead_width=2.5, exhaustive=True))
    assert fast.n_pores == 0
    left, searched, n = left_out_and_searched(grid, 2.5)
    assert left > 0 and searched < n
