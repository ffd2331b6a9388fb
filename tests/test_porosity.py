"""Enclosed voids (grid/enclosure.py, docs/POROSITY.md) against closed forms: the substrate and
the channel rule close a slicer-like tube's infill cavity, void volumes converge with the voxel,
specks are counted apart, voids own their voxels; every surface point has an arrival time."""

from __future__ import annotations

import math

import numpy as np
import pytest

from dmdvox.deposit.engine import deposit, deposit_beads
from dmdvox.grid.analysis import porosity
from dmdvox.grid.build import grid_from_dense
from dmdvox.grid.enclosure import CHANNEL_FRACTION, REACH_SLACK_VOXELS, lowest_deposit_z, speck_floor
from dmdvox.process.plan import chord_tolerance, default_voxel, fixed_beads
from dmdvox.process.profiles import BeadProfile
from dmdvox.study.overlap import OverlapCase, patch_toolpath
from dmdvox.toolpath import read_gcode


def seed_program(runs) -> str:
    """Seed-dialect G-code: each run a list of (x, y, z) points laid with the laser on."""
    lines = ["G90 G1 X0 Y0 Z0 F600"]
    for run in runs:
        x, y, z = run[0]
        lines += [f"G1 X{x:.4f} Y{y:.4f} Z{z:.4f}", "M65"]
        lines += [f"G1 X{x:.4f} Y{y:.4f} Z{z:.4f}" for x, y, z in run[1:]]
        lines.append("M64")
    return "\n".join(lines) + "\n"


# ---- the tube: a cavity that leaked through slivers --------------------------------------------

W, H, GAP, LINES = 1.0, 0.5, 0.07, 7  # rect bead; slivers of 0.07 w between the skin lines
INNER = LINES * W + (LINES + 1) * GAP  # inside the walls: 7 lines and 8 slivers
A = INNER / 2 + W / 2  # wall centre lines


def tube_program() -> str:
    """Five layers of rect beads stacked at the bead height: a square wall loop in every layer;
    layer 0 (bottom) and 4 (top) skins of 7 lines along x with a 0.07 mm sliver on either side
    of each (the slivers run wall to wall); layer 2 three sparse infill lines along y."""
    runs = []
    skin = [-INNER / 2 + GAP + W / 2 + k * (W + GAP) for k in range(LINES)]
    for layer in range(5):
        z = layer * H
        runs.append([(-A, -A, z), (A, -A, z), (A, A, z), (-A, A, z), (-A, -A, z)])
        if layer in (0, 4):
            runs += [[(-A, y, z), (A, y, z)] for y in skin]
        if layer == 2:
            runs += [[(x, -A, z), (x, A, z)] for x in (-2.0, 0.0, 2.0)]
    return seed_program(runs)


@pytest.fixture(scope="module")
def tube(tmp_path_factory):
    path = tmp_path_factory.mktemp("tube") / "tube.gcode"
    path.write_text(tube_program())
    bead = BeadProfile("rect", W, H)
    voxel = default_voxel(bead)
    grid, _ = deposit(read_gcode(path, dialect="seed"), bead, voxel)
    return grid


def test_tube_cavity_is_enclosed_by_the_plate_and_the_channel_rule(tube):
    grid = tube
    v = grid.voxel
    s = CHANNEL_FRACTION * W
    assert GAP < s and GAP > v  # slivers narrower than the channel width, wide enough to be voxels
    cavity = INNER**2 * 3 * H - 3 * W * H * INNER  # layers 1-3 inside the walls, less the infill
    sliver = GAP * H * INNER
    # The plate closes the bottom slivers whole. The top ones open to the outside: the exterior
    # reaches R = s from the ball centres above the top (the centre boundary sits
    # sqrt(r^2 - (gap/2)^2) above the sliver's mouth), the rest belongs to the cavity.
    reach = max(s, s / 2 + REACH_SLACK_VOXELS * v)
    absorbed = reach - math.sqrt((s / 2) ** 2 - (GAP / 2) ** 2)
    expected = cavity + (LINES + 1) * sliver * (1 + (H - absorbed) / H)

    assert lowest_deposit_z(grid) == pytest.approx(0.0, abs=1e-6)
    result = porosity(grid, plate_z=0.0, bead_width=W)
    assert len(result.pores) == 1
    pore = result.pores[0]
    assert pore.wide
    # the top slivers' reach is placed to a voxel: (8 slivers) x gap x length x voxel
    assert pore.volume_mm3 == pytest.approx(expected, abs=(LINES + 1) * GAP * INNER * v)
    np.testing.assert_allclose(pore.centroid_mm[:2], 0.0, atol=1e-6)
    assert result.porosity_percent == pytest.approx(
        100 * result.pore_volume_mm3 / (result.deposit_volume_mm3 + result.pore_volume_mm3))
    # default plate: the lowest deposit, the same to its sub-voxel reading
    assert porosity(grid, bead_width=W).pore_volume_mm3 == pytest.approx(result.pore_volume_mm3, rel=1e-9)

    # without the plate the channel rule alone closes it: the bottom slivers lose their mouths too
    alone = porosity(grid, plate_z=-np.inf, bead_width=W)
    assert len(alone.pores) == 1
    assert result.pores[0].volume_mm3 - alone.pores[0].volume_mm3 == pytest.approx(
        (LINES + 1) * sliver * absorbed / H, abs=(LINES + 1) * GAP * INNER * v)
    # what the old analysis saw: the slivers open the cavity (no plate, no channel rule)
    assert porosity(grid, plate_z=-np.inf).pores == ()
    # the plate alone closes the bottom but not the top slivers
    assert porosity(grid, plate_z=0.0).pores == ()


# ---- convergence: void volumes are sub-voxel ----------------------------------------------------

def rect_channels():
    """Five rect beads 1 mm wide, 0.45 high, 1.37 mm apart along x, closed by a bead across each
    end; a top layer of touching beads along y: four channels 0.37 x 0.45 mm, 5 mm long, on the
    plate. Faces fall between voxel centres at both voxels."""
    w, h, pitch = 1.0, 0.45, 1.37
    ys = [k * pitch for k in range(5)]
    runs = [[(0.0, y, 0.0), (6.0, y, 0.0)] for y in ys]
    runs += [[(x, ys[0], 0.0), (x, ys[-1], 0.0)] for x in (0.0, 6.0)]
    runs += [[(float(x), ys[0], h), (float(x), ys[-1], h)] for x in range(7)]
    return seed_program(runs), BeadProfile("rect", w, h), 4 * (pitch - w) * h * (6.0 - w)


@pytest.mark.parametrize("voxels_per_width", [10, 20])
def test_rect_channels_converge_to_their_volume(gcode_file, voxels_per_width):
    text, bead, exact = rect_channels()
    grid, _ = deposit(read_gcode(gcode_file(text), dialect="seed"), bead, bead.width / voxels_per_width)
    result = porosity(grid, plate_z=0.0, bead_width=bead.width)
    assert len(result.pores) == 4
    # planar faces: the cell fractions are exact; what is left are the channels' corners and
    # ends, O(voxel^2) per metre of edge
    assert sum(p.volume_mm3 for p in result.pores) == pytest.approx(exact, rel=0.015)
    # the notches between the round ends of the touching top beads are specks, not pores
    assert result.speck_volume_mm3 < 0.01 * exact


def lens_patch(voxel: float, layers: int = 3):
    """The overlap study's patch at spacing w/2 (parabolas w = 2, h = 1, layer step h): under each
    layer above the first, each period holds the lens between the bead tops z = h (1 - (2y/w)^2)
    and the next layer's flat bottom, of area h d^3 / (3 w^2) (d = 1: 1/12 mm^2)."""
    case = OverlapCase("parabola", 2.0, 1.0, 4.0, 1.0, 1.0, layers, voxel)
    beads = fixed_beads(patch_toolpath(case), case.bead, chord_tolerance(voxel))
    grid, _ = deposit_beads(beads, voxel)
    return grid, porosity(grid, plate_z=0.0, bead_width=2.0)


def window_void(grid, result) -> tuple[float, float]:
    """Void in the central window (|x| <= 0.5, five periods |y| <= 2.5, the first interface) and
    its closed form over the window's voxel columns."""
    def inside(ijk):
        p = grid.index_to_world(ijk)
        return ((np.abs(p[:, 0]) <= 0.5 + 1e-9) & (np.abs(p[:, 1]) <= 2.5) & (p[:, 2] > 0.5)
                & (p[:, 2] < 1.5)).astype(float)

    columns = np.count_nonzero(np.abs(grid.index_to_world(np.stack(
        [np.arange(8 * grid.block_shape[0]), np.zeros(8 * grid.block_shape[0]),
         np.zeros(8 * grid.block_shape[0])], -1))[:, 0]) <= 0.5 + 1e-9)
    return float(result.voids.volume_where(inside).sum()), 5 * 1.0 / 12.0 * columns * grid.voxel


def test_lens_voids_converge_to_their_closed_form():
    errors = []
    for voxel in (0.05, 0.025):  # w/40 and w/80: the lens is 5 and 10 voxels deep
        grid, result = lens_patch(voxel, layers=2)
        got, exact = window_void(grid, result)
        errors.append(got / exact - 1)
    # the thin tips are sub-voxel: their fractions overestimate by a few percent at w/40
    assert abs(errors[0]) < 0.04 and abs(errors[1]) < 0.02
    assert abs(errors[1]) < abs(errors[0])


def test_default_voxel_porosity_is_within_half_a_point_of_the_converged_one():
    fine = lens_patch(0.025)[1].porosity_percent
    default = lens_patch(default_voxel(BeadProfile("parabola", 2.0, 1.0)))[1].porosity_percent
    assert fine > 4.0  # two layers of lenses in a 3 mm high patch (closed form ~5.7 % in its core)
    assert default == pytest.approx(fine, abs=0.5)


# ---- the plate, specks, components --------------------------------------------------------------

def dense_grid(sdf_of_xyz, n: int, voxel: float, lo):
    ax = [lo[a] + voxel * np.arange(n) for a in range(3)]
    X, Y, Z = np.meshgrid(*ax, indexing="ij")
    sdf = sdf_of_xyz(X, Y, Z).astype(np.float32)
    arrival = np.where(sdf < 0, 10.0 + Z, np.inf).astype(np.float32)
    return grid_from_dense(sdf, arrival, voxel, np.asarray(lo, float), 3 * voxel), sdf, arrival


def box(X, Y, Z, lo, hi):
    c = [(lo[a] + hi[a]) / 2 for a in range(3)]
    q = np.stack([np.abs(X - c[0]), np.abs(Y - c[1]), np.abs(Z - c[2])], -1) - (np.asarray(hi) - lo) / 2
    return np.linalg.norm(np.maximum(q, 0), axis=-1) + np.minimum(q.max(-1), 0)


def test_the_plate_closes_an_upturned_cup():
    # A 4 x 4 x 2 block on z = 0 with a 2 x 2 x 1.5 cavity open at its bottom face.
    def cup(X, Y, Z):
        return np.maximum(box(X, Y, Z, (-2, -2, 0), (2, 2, 2)), -box(X, Y, Z, (-1, -1, -1), (1, 1, 1.5)))

    grid, _, _ = dense_grid(cup, 64, 0.1, (-3.15, -3.15, -0.95))
    assert lowest_deposit_z(grid) == pytest.approx(0.0, abs=1e-6)
    assert porosity(grid, plate_z=-np.inf).pores == ()
    (pore,) = porosity(grid).pores
    assert pore.volume_mm3 == pytest.approx(2 * 2 * 1.5, rel=2e-3)
    # a plate between voxel centres cuts the cavity sub-voxel
    (pore,) = porosity(grid, plate_z=0.237).pores
    assert pore.volume_mm3 == pytest.approx(2 * 2 * (1.5 - 0.237), rel=2e-3)
    assert pore.centroid_mm[2] == pytest.approx((1.5 + 0.237) / 2, abs=0.01)


def test_specks_are_counted_apart():
    centres = [(x, y, 0.0) for x in (-1.5, -0.5, 0.5, 1.5) for y in (-1.5, 1.5)]

    def holes(X, Y, Z):
        d = box(X, Y, Z, (-2.5, -2.5, -1), (2.5, 2.5, 1))
        d = np.maximum(d, -(np.sqrt(X**2 + Y**2 + Z**2) - 0.6))  # one pore
        for c in centres:  # eight specks
            d = np.maximum(d, -(np.sqrt((X - c[0]) ** 2 + (Y - c[1]) ** 2 + (Z - c[2]) ** 2) - 0.1))
        return d

    grid, _, _ = dense_grid(holes, 120, 0.05, (-2.975, -2.975, -1.475))
    result = porosity(grid, bead_width=1.0)
    floor = speck_floor(0.05, CHANNEL_FRACTION * 1.0)
    small, big = 4 / 3 * math.pi * 0.1**3, 4 / 3 * math.pi * 0.6**3
    assert small < floor < big
    assert len(result.pores) == 1 and result.speck_count == len(centres)
    assert result.pores[0].volume_mm3 == pytest.approx(big, rel=0.01)
    assert result.speck_volume_mm3 == pytest.approx(len(centres) * small, rel=0.1)
    # porosity and pore volume count what pore_count counts: the pore, the specks apart
    assert result.pore_volume_mm3 == pytest.approx(result.pores[0].volume_mm3, rel=1e-12)
    solid_and_pore = 5 * 5 * 2 - len(centres) * small  # the box without its specks
    assert result.deposit_volume_mm3 + result.pore_volume_mm3 == pytest.approx(solid_and_pore, rel=2e-3)
    assert result.porosity_percent == pytest.approx(100 * big / solid_and_pore, rel=0.01)
    assert result.speck_floor_mm3 == floor


def test_voids_own_their_voxels():
    def two(X, Y, Z):
        d = box(X, Y, Z, (-4, -2, -2), (4, 2, 2))
        d = np.maximum(d, -(np.sqrt((X + 2) ** 2 + Y**2 + Z**2) - 1.2))
        return np.maximum(d, -box(X, Y, Z, (0.5, -1, -1), (3.5, 1, 1)))

    grid, _, _ = dense_grid(two, 112, 0.1, (-5.55, -5.55, -5.55))
    voids = porosity(grid).voids
    assert voids.n_pores == 2
    big, ball = np.argsort(-voids.volume_mm3)
    assert voids.volume_mm3[big] == pytest.approx(3 * 2 * 2, rel=2e-3)
    assert voids.volume_mm3[ball] == pytest.approx(4 / 3 * math.pi * 1.2**3, rel=5e-3)
    # the fractions the voxels credit add up to each void's volume
    own = voids.block_label >= 0
    per = np.bincount(voids.block_label[own], weights=voids.block_fraction[own], minlength=2)
    per += np.bincount(voids.tile_label, minlength=2) * 512
    np.testing.assert_allclose(per * 0.1**3, voids.volume_mm3, rtol=1e-5)
    np.testing.assert_allclose(voids.volume_where(lambda ijk: np.ones(len(ijk))), voids.volume_mm3, rtol=1e-5)
    # split by a plane through both (the CAD's occupancy, as compare will pass it): halves
    below = voids.volume_where(lambda ijk: np.clip(0.5 - grid.index_to_world(ijk)[:, 1] / 0.1, 0, 1))
    np.testing.assert_allclose(below, voids.volume_mm3 / 2, rtol=5e-3)
    for p in range(2):
        assert np.all(voids.bbox_mm[p, 0] <= voids.centroid_mm[p]) and np.all(voids.centroid_mm[p] <= voids.bbox_mm[p, 1])


# ---- arrival on every surface point -------------------------------------------------------------

def test_every_surface_point_has_an_arrival_time():
    """A slab whose top is a hair above a voxel row (a layer step of 0.1 + 0.2 mm meeting a
    0.3 mm one): the mesher puts vertices on that row, whose 8 voxels around are all outside."""
    from dmdvox.grid.surface import surface_arrival, surface_mesh

    top = 0.1 + 0.2  # 0.30000000000000004

    def slab(X, Y, Z):
        return box(X, Y, Z, (-1.0, -1.0, -0.5), (1.0, 1.0, top))

    grid, sdf, arrival = dense_grid(slab, 48, 0.05, (-1.2, -1.2, -0.9))
    row = np.isclose(-0.9 + 0.05 * np.arange(48), 0.3, atol=1e-9)
    assert np.any((sdf[:, :, row] > 0) & (sdf[:, :, row] < 1e-12))  # the hair: outside, by rounding
    vertices, _ = surface_mesh(grid)
    idx = grid.world_to_index(vertices)
    corners = np.floor(idx).astype(np.int64)[:, None, :] + np.array(list(np.ndindex(2, 2, 2)))
    inside_corner = (grid.value_at_index(corners.reshape(-1, 3)) < 0).reshape(-1, 8).any(axis=1)
    assert not inside_corner.all()  # the geometry has such points (they were arrival -1)

    got = surface_arrival(grid, vertices)
    assert np.all(np.isfinite(got))
    # each takes the nearest inside voxel's time: 10 + its z; the nearest is at most a voxel and
    # a half away (through the hair row), and the slab's times grow with z only
    inside = np.argwhere(sdf < 0)
    for n in np.flatnonzero(~inside_corner)[:50]:
        d2 = np.sum((inside - idx[n]) ** 2, axis=1)
        nearest = inside[d2 == d2.min()]
        assert got[n] in arrival[tuple(nearest.T)]


def test_clearance_beyond_the_band_is_the_chamfer_dijkstra():
    # The clearance field that the channel rule reads beyond the band, handed out by the band's
    # voxels and settled in frontier rounds, against a plain heap Dijkstra over the same voxels (26 neighbours, steps 1,
    # sqrt 2, sqrt 3): every voxel's class and distance alike.
    import heapq

    from dmdvox.grid import enclosure as E
    from dmdvox.grid.sparse import BLOCK_VOXELS

    voxel, band = 0.1, 0.3
    ijk = np.indices((48, 40, 32)).reshape(3, -1).T * voxel
    # two slabs with a slot between them and a ball: faces at many angles beyond the band
    slab = np.maximum(np.abs(ijk[:, 2] - 1.0) - 0.6, np.abs(ijk[:, 1] - 1.6) - 1.2)
    ball = np.linalg.norm(ijk - (3.2, 2.0, 1.6), axis=1) - 0.9
    sdf = np.clip(np.minimum(np.maximum(slab, -(np.abs(ijk[:, 0] - 2.4) - 0.25)), ball), -band, band)
    sdf = sdf.reshape(48, 40, 32).astype(np.float32)
    grid = grid_from_dense(sdf, np.where(sdf < 0, 0.0, np.inf).astype(np.float32), voxel, np.zeros(3), band)
    r_vox, band_vox, zp = 6.0, float(np.float32(band)) / voxel, -np.inf
    wid, wcoord, _ = E._work_blocks(grid, zp, r_vox, band_vox)
    state = np.empty((len(wcoord), BLOCK_VOXELS), np.uint8)
    dep = np.empty((len(wcoord), BLOCK_VOXELS), np.float32)
    E._classify(wcoord, grid.view(), 1.0 / voxel, band_vox, zp, r_vox, state, dep)
    unknown = state == E.UNKNOWN
    assert unknown.sum() > 10_000

    limit = r_vox + 2.0
    dist = np.full(unknown.size, np.inf)
    steps = [(dx, dy, dz) for dx in (-1, 0, 1) for dy in (-1, 0, 1) for dz in (-1, 0, 1) if dx or dy or dz]

    def neighbour(w, v, dx, dy, dz):
        """(work block, local voxel) at an offset; work block -1 when none holds it."""
        i = 8 * int(wcoord[w, 0]) + (v >> 6) + dx
        j = 8 * int(wcoord[w, 1]) + ((v >> 3) & 7) + dy
        k = 8 * int(wcoord[w, 2]) + (v & 7) + dz
        if min(i, j, k) < 0 or i >> 3 >= wid.shape[0] or j >> 3 >= wid.shape[1] or k >> 3 >= wid.shape[2]:
            return -1, 0
        return int(wid[i >> 3, j >> 3, k >> 3]), (i & 7) * 64 + (j & 7) * 8 + (k & 7)
    for w, v in zip(*np.nonzero(unknown)):
        best = min((dep[w2, v2] + math.sqrt(dx * dx + dy * dy + dz * dz)
                    for dx, dy, dz in steps
                    for w2, v2 in [neighbour(w, v, dx, dy, dz)]
                    if w2 >= 0 and not unknown[w2, v2] and 0 < dep[w2, v2] < band_vox - 1e-6), default=np.inf)
        if best < limit:
            dist[w * BLOCK_VOXELS + v] = best
    heap = [(d, g) for g, d in enumerate(dist) if d < limit]
    heapq.heapify(heap)
    while heap:
        d, g = heapq.heappop(heap)
        if d > dist[g]:
            continue
        for dx, dy, dz in steps:
            w2, v2 = neighbour(g // BLOCK_VOXELS, g % BLOCK_VOXELS, dx, dy, dz)
            if w2 >= 0 and unknown[w2, v2]:
                nd, g2 = d + math.sqrt(dx * dx + dy * dy + dz * dz), w2 * BLOCK_VOXELS + v2
                if nd < dist[g2] and nd < limit:
                    dist[g2] = nd
                    heapq.heappush(heap, (nd, g2))
    dist = dist.reshape(unknown.shape)
    expect_state = np.where(unknown, np.where(dist < r_vox, E.RESIDUAL, E.CENTRE), state)
    expect_dep = np.where(unknown, np.minimum(dist, limit), dep).astype(np.float32)

    # the reach reads the distance below r_vox + 1 and, up to the limit, at the axis neighbours of
    # the RESIDUAL and PARTIAL voxels; elsewhere it needs only to know it is r_vox + 1 or more
    read = expect_dep < r_vox + 1
    for w, v in zip(*np.nonzero((expect_state == E.RESIDUAL) | (expect_state == E.PARTIAL))):
        for dx, dy, dz in [(1, 0, 0), (-1, 0, 0), (0, 1, 0), (0, -1, 0), (0, 0, 1), (0, 0, -1)]:
            w2, v2 = neighbour(w, v, dx, dy, dz)
            if w2 >= 0:
                read[w2, v2] = True
    assert (~read & unknown & (expect_dep >= r_vox + 1) & (expect_dep < limit)).sum() > 1000  # left unsettled

    for exhaustive in (False, True):
        got_state, got_dep = state.copy(), dep.copy()
        E._extend_clearance(wid, wcoord, got_state, got_dep, band_vox, r_vox, grid.n_leaf, exhaustive)
        assert np.array_equal(got_state, expect_state)
        if exhaustive:
            assert np.array_equal(got_dep, expect_dep)
        else:
            assert np.array_equal(got_dep[read], expect_dep[read]) and np.all(got_dep[~read] >= r_vox + 1)
    assert ((expect_state == E.RESIDUAL) & unknown).sum() > 1000 and ((expect_state == E.CENTRE) & unknown).sum() > 1000
