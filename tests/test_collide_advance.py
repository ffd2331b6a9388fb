"""Conservative advancement, shared descents, the previous-pose hint and the axis-aligned voxel
path against a brute per-pose reference: ``query_one`` (a fresh descent per pose, no hint, no margin) must give
the very values of ``query_poses`` with and without advancement, on analytic scenes where the
first contact is known, on a growing part, and with a rotated probe."""

from __future__ import annotations

import numpy as np
import pytest

from dmdvox.collision.bodies import body_from_grid, mesh_body
from dmdvox.collision.kernels import (ADVANCE_TOL_MM, SHARE_MM, _boxes_apart, _collect, _descend, _replay, _workspace,
                                   abs_eps, query, query_one, query_poses, sat_disjoint)
from dmdvox.collision.path import sample_poses
from dmdvox.collision.run import BAND_VOXELS, nozzle_for
from dmdvox.collision.scene import rotation_matrix
from dmdvox.deposit.engine import deposit
from dmdvox.process.profiles import BeadProfile
from dmdvox.io.mesh import box_mesh
from dmdvox.toolpath import read_gcode

VOXEL = 0.25
REACH = 1.0 + VOXEL
SLOPE = 0.32  # cone tip 4, top 20 over 25 mm: the radius grows 0.32 mm per mm


def brute(G, P, R, tips, times, reach=REACH) -> np.ndarray:
    return np.array([query_one(G, P, R, np.ascontiguousarray(tip), float(t), reach) for tip, t in zip(tips, times)],
                    np.float32)


def both_ways(G, P, R, tips, times, reach=REACH):
    raw, n_raw = query_poses(G, P, R, tips, times, reach, False)
    adv, n_adv = query_poses(G, P, R, tips, times, reach, True)
    assert n_raw == len(tips)
    return raw, adv, int(n_adv)


def first_collision_line(d, lines):
    hit = np.flatnonzero(d < 0)
    return int(lines[hit[0]]) if hit.size else None


@pytest.fixture(scope="module")
def cone():
    return nozzle_for("cone:tip=4,top=20,length=25", VOXEL, REACH)


@pytest.fixture(scope="module")
def box():
    """The fixture: a box with its face x = 20, top z = 10."""
    return mesh_body("box", *box_mesh((20.0, -5.0, 0.0), (30.0, 5.0, 10.0)), VOXEL, BAND_VOXELS * VOXEL)


def test_grazing_passes_along_a_fixture(gcode_file, cone, box):
    # Passes along y beside the face x = 20 at tip height 2 (cone radius 2 + 0.32 * 8 = 4.56 mm
    # at the box top, whose edge is the closest point): gaps from 1.5 mm down to -0.8 mm, with
    # long approaches in free space. Pass n is line 4 + 3 n.
    contact = 20.0 - (2.0 + SLOPE * 8.0)
    gaps = [1.5, 0.9, 0.6, 0.3, 0.1, -0.4, -0.8]
    text = "G90 G21\nG0 X0 Y-20 Z2\n"
    for n, gap in enumerate(gaps):
        x = contact - gap / np.cos(np.arctan(SLOPE))
        text += f"G1 X{x:.4f} Y{-20 if n % 2 == 0 else 20} F600\nG1 Y{20 if n % 2 == 0 else -20}\nG0 X0\n"
    tp = read_gcode(gcode_file(text), dialect="seed")
    poses = sample_poses(tp, 0.5 * VOXEL)
    tips = np.ascontiguousarray(poses.point)
    G, P = box.kernel_args(), cone.kernel_args()
    raw, adv, queried = both_ways(G, P, np.eye(3), tips, poses.time)
    ref = brute(G, P, np.eye(3), tips, poses.time)
    assert np.array_equal(raw, ref) and np.array_equal(adv, ref)
    assert queried < 0.5 * len(tips)  # the approaches were skipped, not queried
    # the overlapping passes collide, those clear by more than two voxels do not
    lines = set(np.unique(poses.line[adv < 0]).tolist())
    assert {4 + 3 * 5, 4 + 3 * 6} <= lines and not {4, 7, 10} & lines
    assert first_collision_line(adv, poses.line) in (4 + 3 * 4, 4 + 3 * 5)
    assert first_collision_line(adv, poses.line) == first_collision_line(ref, poses.line)
    # each pass's closest pose sits at its gap, to within a voxel
    for n, gap in enumerate(gaps[1:], 1):
        on = poses.line == 4 + 3 * n
        assert ref[on].min() == pytest.approx(gap, abs=VOXEL), (n, gap)


def test_fast_travel_across_a_thin_wall(gcode_file):
    # A one-bead wall 1 mm thick (x 9.5..10.5) laid along y, then G0 travels through it at
    # 0.2 mm (lines 4-6 before the wall, 13-15 after; the wall is line 10): the crossings
    # collide once the wall stands, and only then, first where the 0.3 mm radius meets it.
    wall = "G0 X10 Y-6 Z0\nM65\nG1 X10 Y6 F600\nM64\n"
    cross = "G0 X0 Y0 Z0.2\nG0 X20 Y0 Z0.2\nG0 X0 Y1 Z0.2\n"
    tp = read_gcode(gcode_file("G90 G21\nM64\nG0 X0 Y0 Z10\n" + cross + "G0 Z10\n" + wall + "G0 Z10\n" + cross
                               + "G0 Z30\n"), dialect="seed")
    grid, _ = deposit(tp, BeadProfile("rect", 1.0, 1.0), VOXEL)
    part = body_from_grid("part", grid)
    nozzle = nozzle_for("cone:tip=0.6,top=0.6,length=4", VOXEL, REACH)
    poses = sample_poses(tp, 0.5 * VOXEL)
    G, P = part.kernel_args(), nozzle.kernel_args()
    tips = np.ascontiguousarray(poses.point)
    raw, adv, queried = both_ways(G, P, np.eye(3), tips, poses.time)
    ref = brute(G, P, np.eye(3), tips, poses.time)
    assert np.array_equal(raw, ref) and np.array_equal(adv, ref)
    assert queried < len(tips)
    hit_lines = set(np.unique(poses.line[(adv < 0) & ~tp.deposit[poses.row]]).tolist())
    assert not hit_lines & {4, 5, 6}
    assert {14, 15} <= hit_lines
    first = np.flatnonzero((adv < 0) & (poses.line == 14))[0]
    assert tips[first, 0] == pytest.approx(9.5 - 0.3, abs=VOXEL)


def test_rotated_probe_random_walk(box):
    # a general rotation takes the 15-axis margins and the general voxel path
    rng = np.random.default_rng(3)
    probe = mesh_body("probe", *box_mesh((-1.0, -2.0, -1.5), (1.0, 2.0, 1.5)), VOXEL, REACH + 5 * VOXEL)
    R = rotation_matrix((1.0, 2.0, 3.0), 27.0)
    steps = rng.normal(size=(3000, 3))
    steps *= 0.5 * VOXEL / np.linalg.norm(steps, axis=1, keepdims=True)
    steps[:, 0] += 0.03  # drift towards the box face and through it
    tips = np.ascontiguousarray(np.array([12.0, 0.0, 5.0]) + np.cumsum(steps, axis=0))
    times = np.zeros(len(tips))
    G, P = box.kernel_args(), probe.kernel_args()
    raw, adv, queried = both_ways(G, P, R, tips, times)
    ref = brute(G, P, R, tips, times)
    assert np.array_equal(raw, ref) and np.array_equal(adv, ref)
    assert queried < 0.8 * len(tips)
    assert (ref < 0).any() and np.isinf(ref).any() and ((ref >= 0) & np.isfinite(ref)).any()


def test_margin_certifies_every_pose_within_it(cone, box):
    # the certificate itself: a pose out of reach with margin m gives +inf at T + v, |v| < m,
    # checked at the sphere |v| = m - tol (the worst case) in random directions
    rng = np.random.default_rng(11)
    G, P = box.kernel_args(), cone.kernel_args()
    R = np.eye(3)
    ws = _workspace(G, P, abs_eps(R), REACH)
    checked = 0
    for n in range(200):
        T = np.array([rng.uniform(5.0, 20.0), rng.uniform(-10.0, 10.0), rng.uniform(-2.0, 14.0)])
        d, margin = query(G, P, R, abs_eps(R), T, 0.0, REACH, np.inf, ws, n + 1, 0.0)
        if not np.isinf(d) or margin <= ADVANCE_TOL_MM:
            continue
        v = rng.normal(size=(8, 3))
        v *= (margin - ADVANCE_TOL_MM) / np.linalg.norm(v, axis=1, keepdims=True)
        assert all(np.isinf(query_one(G, P, R, T + u, 0.0, REACH)) for u in v), (T, margin)
        checked += 1
    assert checked > 20


def test_margin_respects_arrival_within_the_window(gcode_file):
    # the nozzle waits beside a bead that is laid later: a certificate for a window reaching
    # past the bead's arrival must not skip the poses after it
    tp = read_gcode(gcode_file("G90 G21\nM64\nG0 X0 Y0 Z0\nM65\nG1 X10 F600\nM64\nG0 Z30\n"), dialect="seed")
    grid, _ = deposit(tp, BeadProfile("rect", 2.0, 1.0), VOXEL)
    part = body_from_grid("part", grid)
    nozzle = nozzle_for("cone:tip=1,top=1,length=3", VOXEL, REACH)
    G, P = part.kernel_args(), nozzle.kernel_args()
    row = int(np.flatnonzero(tp.deposit)[0])
    t0, t1 = float(tp.t_start[row]), float(tp.t_end[row])
    # the tip parked over the bead's middle, 0.3 mm above its top, before and after it is laid
    tips = np.ascontiguousarray(np.tile([5.0, 0.0, 0.8], (200, 1)))
    times = np.linspace(t0 - 1.0, t1 + 1.0, 200)
    raw, adv, _ = both_ways(G, P, np.eye(3), tips, times)
    ref = brute(G, P, np.eye(3), tips, times)
    assert np.array_equal(adv, ref) and np.array_equal(raw, ref)
    assert np.isinf(ref[times < t0]).all() and np.isfinite(ref[times > t1]).all()


def test_shared_descent_evaluates_the_same_blocks(cone, box):
    # the pairs listed at T (reach grown by SHARE_MM) replayed at T + v, |v| <= SHARE_MM: the
    # same blocks evaluated and the same value as a descent at T + v
    rng = np.random.default_rng(17)
    G, P = box.kernel_args(), cone.kernel_args()
    R = np.eye(3)
    AbsR = abs_eps(R)
    ws = _workspace(G, P, AbsR, REACH)
    done = ws[1]
    stamp = 0
    compared = 0
    for _ in range(60):
        T = np.array([rng.uniform(14.0, 17.0), rng.uniform(-8.0, 8.0), rng.uniform(0.0, 10.0)])
        n_pairs = _collect(G, P, R, T, 0.0, ws)
        assert n_pairs >= 0
        for _ in range(4):
            v = rng.normal(size=3)
            v *= (SHARE_MM - ADVANCE_TOL_MM) * rng.uniform(0.5, 1.0) / np.linalg.norm(v)
            stamp += 2
            d_ref, margin = _descend(G, P, R, AbsR, T + v, 0.0, REACH, REACH, ws, stamp, -np.inf)
            blocks_ref = np.flatnonzero(done == stamp)
            d, evaluated = _replay(G, P, R, T + v, 0.0, REACH, ws, n_pairs, stamp + 1)
            blocks = np.flatnonzero(done == stamp + 1)
            assert d == d_ref or (np.isinf(d) and np.isinf(d_ref))
            assert np.array_equal(blocks, blocks_ref) and evaluated == (blocks.size > 0)
            compared += blocks.size > 0
    assert compared > 50


def test_hint_does_not_change_the_value(cone, box):
    G, P = box.kernel_args(), cone.kernel_args()
    R = np.eye(3)
    ws = _workspace(G, P, abs_eps(R), REACH)
    xs = np.linspace(14.0, 16.5, 41)
    stamp = 1
    for x in xs:
        T = np.array([x, 0.3, 2.0])
        ref = query_one(G, P, R, T, 0.0, REACH)
        for hint in (np.inf, ref + 1e-3 if np.isfinite(ref) else 0.5, 0.0, -5.0, 0.2):
            stamp += 1
            d, _ = query(G, P, R, abs_eps(R), T, 0.0, REACH, hint, ws, stamp, -np.inf)
            assert d == ref or (np.isinf(d) and np.isinf(ref)), (x, hint, d, ref)


def test_axis_aligned_path_matches_the_general_path(cone, box):
    # R = I takes the per-axis tables; a rotation by 1e-300 degrees takes the general path with
    # the same coordinates: the values must agree bit for bit
    rng = np.random.default_rng(5)
    tips = np.ascontiguousarray(np.array([15.5, 0.0, 2.0]) + rng.uniform(-1.5, 1.5, size=(400, 3)))
    times = np.zeros(len(tips))
    G, P = box.kernel_args(), cone.kernel_args()
    tiny = rotation_matrix("z", 1e-300)
    assert not np.array_equal(tiny, np.eye(3))
    aligned, _ = query_poses(G, P, np.eye(3), tips, times, REACH, False)
    general, _ = query_poses(G, P, tiny, tips, times, REACH, False)
    assert np.array_equal(aligned, general)
    assert (aligned < 0).any() and np.isfinite(aligned).sum() > 100


def test_per_pose_rotations_match_the_single_pose_query(cone, box):
    # a pass along the face with the nozzle's tilt changing every few poses (rotation groups of
    # 1 to 7 poses, the identity among them): coherence only within a group, values per pose
    from dmdvox.collision.kernels import query_poses_rotated
    from dmdvox.collision.path import axis_rotations

    rng = np.random.default_rng(16)
    n = 600
    ys = np.linspace(-8.0, 8.0, n)
    tips = np.ascontiguousarray(np.column_stack([np.full(n, 15.2), ys, np.full(n, 2.0)]))
    group = np.cumsum(rng.integers(1, 8, size=n))
    group = np.searchsorted(group, np.arange(n), side="right")
    tilt = np.radians(rng.choice([0.0, 5.0, 15.0, -10.0], size=group.max() + 1))
    axis = np.column_stack([np.sin(tilt), np.zeros_like(tilt), np.cos(tilt)])[group]
    Rs, index = axis_rotations(axis)
    assert np.array_equal(Rs[index[tilt[group] == 0.0][0]], np.eye(3))  # vertical: the fast path
    G, P = box.kernel_args(), cone.kernel_args()
    times = np.zeros(n)
    raw, n_raw = query_poses_rotated(G, P, Rs, index, tips, times, REACH, False)
    adv, _ = query_poses_rotated(G, P, Rs, index, tips, times, REACH, True)
    ref = np.array([query_one(G, P, Rs[index[k]], tips[k], 0.0, REACH) for k in range(n)], np.float32)
    assert n_raw == n
    np.testing.assert_array_equal(raw, ref)
    np.testing.assert_array_equal(adv, ref)
    assert (ref < 0).any() and np.isinf(ref).any()  # tilts towards the face collide, others miss


def _finals(body, level, i, j, k, target):
    """The nodes a descent stops at below node (level, i, j, k) that hold material: level-0
    nodes, and for a probe FULL nodes too (rows level, i, j, k)."""
    occ, marr, loff, shape = body.occupancy, body.min_arrival, body.level_offset, body.level_shape
    out, stack = [], [(level, i, j, k)]
    while stack:
        lv, a, b, c = stack.pop()
        if a >= shape[lv, 0] or b >= shape[lv, 1] or c >= shape[lv, 2]:
            continue
        n = loff[lv] + (a * shape[lv, 1] + b) * shape[lv, 2] + c
        if occ[n] == 0 or not marr[n] < np.inf:
            continue
        if lv == 0 or (occ[n] == 2 and not target):
            out.append((lv, a, b, c))
            continue
        stack += [(lv - 1, 2 * a + da, 2 * b + db, 2 * c + dc) for da in (0, 1) for db in (0, 1) for dc in (0, 1)]
    return np.array(out, np.int64).reshape(-1, 4)


def _cube_centres(body, nodes):
    h = body.voxel
    size = 8.0 * h * (1 << nodes[:, 0])
    return body.grid.origin - 0.5 * h + (nodes[:, 1:] + 0.5) * size[:, None], 0.5 * size


@pytest.mark.parametrize("degrees", [0.0, 20.0, 63.0])
def test_material_boxes_only_prune_pairs_whose_final_pairs_are_apart(cone, box, degrees):
    # The descent's material-box test (node_box, _boxes_apart) must never reject a node pair
    # below which a final pair (target block, probe leaf or FULL node) passes the final SAT test
    # the descent applies (general_thresholds, or the aligned ones at R = I): otherwise a block
    # would go unevaluated. Poses place the posed probe box near the target box, so that many
    # pairs are close calls, on random nodes of every level above the final one.
    rng = np.random.default_rng(int(degrees) + 5)
    R = rotation_matrix((1.0, -2.0, 0.5), degrees)
    AbsR = abs_eps(R)
    aligned = degrees == 0.0
    ws = _workspace(box.kernel_args(), cone.kernel_args(), AbsR, REACH)
    thr = ws[4] if aligned else ws[8]
    G_box, P_box = box.node_box, cone.node_box

    def material_nodes(body):
        rows = []
        for lv in range(body.level_shape.shape[0]):
            shape = body.level_shape[lv]
            idx = np.argwhere(np.ones(shape, bool))
            n = body.level_offset[lv] + (idx[:, 0] * shape[1] + idx[:, 1]) * shape[2] + idx[:, 2]
            keep = (body.occupancy[n] > 0) & np.isfinite(body.min_arrival[n])
            rows.append(np.column_stack([np.full(keep.sum(), lv), idx[keep]]))
        return np.concatenate(rows)

    g_nodes, p_nodes = material_nodes(box), material_nodes(cone)
    apart = more = 0
    for _ in range(1000):
        g = g_nodes[rng.integers(len(g_nodes))]
        p = p_nodes[rng.integers(len(p_nodes))]
        p_final = p[0] == 0 or cone.occupancy[cone.level_offset[p[0]] + (p[1] * cone.level_shape[p[0], 1] + p[2])
                                                * cone.level_shape[p[0], 2] + p[3]] == 2
        if g[0] == 0 and p_final:
            continue
        (ga,), (ea,) = _cube_centres(box, g[None])
        (pb,), (eb,) = _cube_centres(cone, p[None])
        if g[0] > 0:
            row = G_box[box.level_offset[g[0]] + (g[1] * box.level_shape[g[0], 1] + g[2]) * box.level_shape[g[0], 2]
                        + g[3] - box.level_offset[1]]
            ga, ha = row[:3], row[3:] + REACH
        else:
            ha = np.full(3, ea + REACH)
        if p[0] > 0:
            row = P_box[cone.level_offset[p[0]] + (p[1] * cone.level_shape[p[0], 1] + p[2]) * cone.level_shape[p[0], 2]
                        + p[3] - cone.level_offset[1]]
            pb, hb = row[:3], row[3:]
        else:
            hb = np.full(3, eb)
        direction = rng.normal(size=3)
        direction /= np.linalg.norm(direction)
        T = ga - R @ pb + direction * rng.uniform(0.5, 1.2) * (np.linalg.norm(ha) + np.linalg.norm(hb))
        t = R @ pb + T - ga
        if not _boxes_apart(t[0], t[1], t[2], ha[0], ha[1], ha[2], hb[0], hb[1], hb[2], R, AbsR, aligned):
            continue
        apart += 1
        gf, pf = _finals(box, *g, target=True), _finals(cone, *p, target=False)
        gc, _ = _cube_centres(box, gf)
        pc, _ = _cube_centres(cone, pf)
        tv = (pc @ R.T)[None, :, :] + T - gc[:, None, :]  # (target finals, probe finals, 3)
        th = thr[0, pf[:, 0]]  # (probe finals, 3 or 6)
        sep = (np.abs(tv) > th[None, :, :3]).any(axis=2)
        if not aligned:
            sep |= (np.abs(tv @ R) > th[None, :, 3:]).any(axis=2)
        assert sep.all(), (g, p, T)
        # the plain cube test of the pair itself would have kept it: the boxes pruned more
        ta = R @ _cube_centres(cone, p[None])[0][0] + T - _cube_centres(box, g[None])[0][0]
        if not sat_disjoint(ta[0], ta[1], ta[2], ea + REACH, ea + REACH, ea + REACH, eb, eb, eb, R, AbsR):
            more += 1
    assert apart > 100 and more > 10, (apart, more)
