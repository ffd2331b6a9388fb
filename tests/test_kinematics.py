"""Machine kinematics (dmdvox.toolpath.kinematics): closed forms, LinuxCNC's equations, round trips.

Every expected value here comes from a hand computation or an independent formula written in the
test (LinuxCNC manual, 5-Axis Kinematics chapter; ISO 841 sign convention), never from the
program's own output.
"""

from __future__ import annotations

import json
import math
import zlib
from pathlib import Path

import numpy as np
import pytest

from dmdvox.errors import DmdvoxError
from dmdvox.toolpath.kinematics import (
    MACHINE_KINDS,
    NO_MACHINE,
    Machine,
    RotaryAxis,
    check_limits,
    forward,
    inverse,
    load_machine,
    short_way,
    workpiece_to_machine,
)

MACHINES = Path(__file__).resolve().parents[1] / "data" / "machines"
S3 = math.sqrt(3.0)


def joints(x=0.0, y=0.0, z=0.0, a=0.0, b=0.0, c=0.0):
    return np.array([[x, y, z, a, b, c]], dtype=np.float64)


def trt_ac(*, a_point=(0.0, 0.0, 0.0), c_point=(0.0, 0.0, 0.0), sense="iso", tool_length=0.0,
           a_dir=(1.0, 0.0, 0.0), c_dir=(0.0, 0.0, 1.0), a_limits=None):
    return Machine(kind="trt-ac", name="test trt-ac", tool_length=tool_length, axes=(
        RotaryAxis("A", a_dir, a_point, sense=sense, limits=a_limits),
        RotaryAxis("C", c_dir, c_point, sense=sense, wrapped=True)))


def trt_bc(*, b_point=(0.0, 0.0, 0.0), c_point=(0.0, 0.0, 0.0), sense="iso", tool_length=0.0):
    return Machine(kind="trt-bc", name="test trt-bc", tool_length=tool_length, axes=(
        RotaryAxis("B", (0.0, 1.0, 0.0), b_point, sense=sense),
        RotaryAxis("C", (0.0, 0.0, 1.0), c_point, sense=sense, wrapped=True)))


# ------------------------------------------------------------------------------------------
# Shipped machine files
# ------------------------------------------------------------------------------------------

@pytest.mark.parametrize("fname, kind, letters", [
    ("none.toml", "none", ()),
    ("trunnion-ac.toml", "trt-ac", ("A", "C")),
    ("trunnion-bc.toml", "trt-bc", ("B", "C")),
    ("head-bc.toml", "head-bc", ("C", "B")),
])
def test_shipped_machine_files_load(fname, kind, letters):
    m = load_machine(MACHINES / fname)
    assert m.kind == kind and m.kind in MACHINE_KINDS
    assert tuple(a.letter for a in m.axes) == letters
    assert m.name and m.source.endswith(fname)
    json.dumps(m.to_json())  # serialisable for reports
    assert m.to_json()["kind"] == kind


def test_shipped_geometry_is_as_documented():
    ac = load_machine(MACHINES / "trunnion-ac.toml")
    assert ac.axis("C").point == (0.0, 0.0, 0.0) and ac.axis("C").direction == (0.0, 0.0, 1.0)
    assert ac.axis("A").direction == (1.0, 0.0, 0.0) and not ac.axis("C").wrapped
    assert ac.axis("C").limits is None  # an endless table, programmed unwrapped
    assert load_machine(MACHINES / "trunnion-bc.toml").axis("C").wrapped
    head = load_machine(MACHINES / "head-bc.toml")
    assert head.pivot_length == 150.0
    assert load_machine(MACHINES / "none.toml").kind == NO_MACHINE.kind == "none"


# ------------------------------------------------------------------------------------------
# Closed forms (ISO 841: positive = tool turns right-handed relative to the workpiece)
# ------------------------------------------------------------------------------------------

def test_trunnion_ac_c90_turns_workpiece_point_clockwise():
    """C = +90 on an ISO trunnion: the table turns the workpiece clockwise seen from above."""
    m = load_machine(MACHINES / "trunnion-ac.toml")
    R_ = 40.0
    Rm, t = workpiece_to_machine(m, joints(c=90.0))
    # the workpiece point (R, 0, 0) is carried to the machine position (0, -R, 0)
    np.testing.assert_allclose(Rm[0] @ [R_, 0.0, 0.0] + t[0], [0.0, -R_, 0.0], atol=1e-12)
    # conversely the nozzle at machine (R, 0, 0) deposits at workpiece (0, R, 0)
    tip, axis = forward(m, joints(x=R_, c=90.0))
    np.testing.assert_allclose(tip[0], [0.0, R_, 0.0], atol=1e-12)
    np.testing.assert_allclose(axis[0], [0.0, 0.0, 1.0], atol=1e-15)


def test_trunnion_ac_turning_c_at_fixed_x_lays_a_ring():
    """A tube: X = R fixed, C turning -> the tip runs on the circle of radius R, z = layer."""
    m = load_machine(MACHINES / "trunnion-ac.toml")
    R_, z = 25.0, 3.5
    c = np.linspace(0.0, 360.0, 73)
    j = np.zeros((c.size, 6))
    j[:, 0], j[:, 2], j[:, 5] = R_, z, c
    tip, axis = forward(m, j)
    # workpiece angle of the tip = +C (tool goes counterclockwise around the part)
    expected = np.column_stack([R_ * np.cos(np.radians(c)), R_ * np.sin(np.radians(c)),
                                np.full(c.size, z)])
    np.testing.assert_allclose(tip, expected, atol=1e-12)
    np.testing.assert_allclose(axis, np.tile([0.0, 0.0, 1.0], (c.size, 1)), atol=1e-15)


def test_trunnion_ac_a90_tilts_tool_axis():
    m = load_machine(MACHINES / "trunnion-ac.toml")
    # A = +90: the tool turns right-handed about +X relative to the part: Rx(90) z = (0, -1, 0)
    _, axis = forward(m, joints(a=90.0))
    np.testing.assert_allclose(axis[0], [0.0, -1.0, 0.0], atol=1e-15)
    # then C = +90 turns that direction right-handed about +Z: Rz(90) (0, -1, 0) = (1, 0, 0)
    _, axis = forward(m, joints(a=90.0, c=90.0))
    np.testing.assert_allclose(axis[0], [1.0, 0.0, 0.0], atol=1e-15)
    # general closed form (sin C sin A, -cos C sin A, cos A)
    A, C = 35.0, -120.0
    _, axis = forward(m, joints(a=A, c=C))
    sa, ca, sc, cc = (math.sin(math.radians(A)), math.cos(math.radians(A)),
                      math.sin(math.radians(C)), math.cos(math.radians(C)))
    np.testing.assert_allclose(axis[0], [sc * sa, -cc * sa, ca], atol=1e-15)


def test_trunnion_ac_a90_tip_about_offset_pivot():
    """Shipped trunnion-ac: A axis through (0, 0, -60). Nozzle at machine (10, 0, 0), A = 90:
    the part turned by Rx(-90) about the pivot, so the tip in the part is
    Rx(90) ((10, 0, 0) - (0, 0, -60)) + (0, 0, -60) = (10, -60, 0) + (0, 0, -60)."""
    m = load_machine(MACHINES / "trunnion-ac.toml")
    tip, _ = forward(m, joints(x=10.0, a=90.0))
    np.testing.assert_allclose(tip[0], [10.0, -60.0, -60.0], atol=1e-12)


def test_trunnion_bc_b90_tilts_tool_axis_to_x():
    """trt-bc, B = +90: Ry(90) z = (1, 0, 0); shipped B axis through (5, 0, -100):
    tip = Ry(90) ((0, 0, 0) - (5, 0, -100)) + (5, 0, -100) = (100, 0, 5) + (5, 0, -100)."""
    m = load_machine(MACHINES / "trunnion-bc.toml")
    tip, axis = forward(m, joints(b=90.0))
    np.testing.assert_allclose(axis[0], [1.0, 0.0, 0.0], atol=1e-15)
    np.testing.assert_allclose(tip[0], [105.0, 0.0, -95.0], atol=1e-12)


def test_head_bc_b90_axis_along_x_tip_pivot_minus_length():
    m = load_machine(MACHINES / "head-bc.toml")
    L = 150.0
    X, Y, Z = 12.0, -7.0, 40.0
    tip, axis = forward(m, joints(X, Y, Z, b=90.0))
    pivot = np.array([X, Y, Z + L])  # X Y Z is the tip at B = C = 0
    np.testing.assert_allclose(axis[0], [1.0, 0.0, 0.0], atol=1e-15)
    np.testing.assert_allclose(tip[0], pivot - L * np.array([1.0, 0.0, 0.0]), atol=1e-12)
    # B = C = 0: the tip is X Y Z, the axis +Z
    tip, axis = forward(m, joints(X, Y, Z))
    np.testing.assert_allclose(tip[0], [X, Y, Z], atol=1e-12)
    np.testing.assert_allclose(axis[0], [0.0, 0.0, 1.0], atol=1e-15)
    # C = +90 turns the tilted head counterclockwise: axis (0, 1, 0)
    tip, axis = forward(m, joints(X, Y, Z, b=90.0, c=90.0))
    np.testing.assert_allclose(axis[0], [0.0, 1.0, 0.0], atol=1e-15)
    np.testing.assert_allclose(tip[0], pivot - L * np.array([0.0, 1.0, 0.0]), atol=1e-12)


def test_none_machine_is_identity_and_refuses_tilts():
    j = np.array([[1.0, 2.0, 3.0, 40.0, 50.0, 60.0]])
    tip, axis = forward(NO_MACHINE, j)
    np.testing.assert_array_equal(tip, [[1.0, 2.0, 3.0]])
    np.testing.assert_array_equal(axis, [[0.0, 0.0, 1.0]])
    out = inverse(NO_MACHINE, [[4.0, 5.0, 6.0]], [[0.0, 0.0, 2.0]], near=j)
    np.testing.assert_array_equal(out, [[4.0, 5.0, 6.0, 40.0, 50.0, 60.0]])
    with pytest.raises(DmdvoxError, match=r"pose 1.*not \+Z"):
        inverse(NO_MACHINE, np.zeros((2, 3)), [[0.0, 0.0, 1.0], [0.0, 0.1, 1.0]])
    R, t = workpiece_to_machine(NO_MACHINE, j)
    np.testing.assert_array_equal(R[0], np.eye(3))
    np.testing.assert_array_equal(t[0], [0.0, 0.0, 0.0])


# ------------------------------------------------------------------------------------------
# LinuxCNC's documented equations
# ------------------------------------------------------------------------------------------

def test_xyzac_trt_matches_linuxcnc_manual_hand_computation():
    """LinuxCNC manual, "5-Axis Kinematics", section "Transformations for a xyzac-trt machine
    with rotary axis offsets" (docs/src/motion/5-axis-kinematics.adoc): forward transformation
    Q = Q_A_P . P (equation image equation__25, printed as (26)) and K (equation__21):

        Qx =  cC Px + sC cA Py + sC sA Pz - sC cA Dy - sC sA Dz + sC Dy
        Qy = -sC Px + cC cA Py + cC sA Pz - cC cA Dy - cC sA Dz + cC Dy
        Qz =        -    sA Py +    cA Pz +    sA Dy -    cA Dz +    Dz
        K  = (sC sA, cC sA, cA)

    LinuxCNC turns its trt tables the opposite way to ISO ("the rotational axes move in the
    opposite direction of what the convention is"): dmdvox models it with sense = "reversed",
    C axis through the origin, A axis through (0, Dy, Dz).

    Pose: A = 30, C = 60 (cA = sqrt3/2, sA = 1/2, cC = 1/2, sC = sqrt3/2), Dy = 20, Dz = -50,
    P = (10, 40, 100):
      Qx = 1/2*10 + (3/4)*40 + (sqrt3/4)*100 - (3/4)*20 - (sqrt3/4)*(-50) + (sqrt3/2)*20
         = 5 + 30 + 25 sqrt3 - 15 + 12.5 sqrt3 + 10 sqrt3              = 20 + 47.5 sqrt3
      Qy = -(sqrt3/2)*10 + (sqrt3/4)*40 + (1/4)*100 - (sqrt3/4)*20 - (1/4)*(-50) + (1/2)*20
         = -5 sqrt3 + 10 sqrt3 + 25 - 5 sqrt3 + 12.5 + 10              = 47.5
      Qz = -(1/2)*40 + (sqrt3/2)*100 + (1/2)*20 - (sqrt3/2)*(-50) - 50
         = -20 + 50 sqrt3 + 10 + 25 sqrt3 - 50                          = -60 + 75 sqrt3
      K  = (sqrt3/4, 1/4, sqrt3/2)
    """
    m = trt_ac(a_point=(0.0, 20.0, -50.0), sense="reversed")
    P = joints(10.0, 40.0, 100.0, a=30.0, c=60.0)
    tip, axis = forward(m, P)
    np.testing.assert_allclose(tip[0], [20.0 + 47.5 * S3, 47.5, -60.0 + 75.0 * S3], atol=1e-12)
    np.testing.assert_allclose(axis[0], [S3 / 4.0, 0.25, S3 / 2.0], atol=1e-15)
    # the manual's inverse transformation (equation__27, printed as (28)) gives P back from Q:
    #   Px = cC Qx - sC Qy
    #   Py = sC cA Qx + cC cA Qy - sA Qz - cA Dy + sA Dz + Dy
    #   Pz = sC sA Qx + cC sA Qy + cA Qz - sA Dy - cA Dz + Dz
    # and A = acos(Kz) = 30, C = atan2(Kx, Ky) = 60 (equations __22, __23)
    back = inverse(m, tip, axis, near=joints(a=25.0, c=50.0))
    np.testing.assert_allclose(back[0], P[0], atol=1e-12)


def _linuxcnc_trt_ac_world(P, a, c, rot, dy, dz, dt):
    """Reference: LinuxCNC xyzac-trt forward with a rotation point and a tool offset, written
    from the manual's equation (26) shifted by the rotation point r, with LinuxCNC's tool-offset
    pin dt added to the z offset (Dz -> Dz + dt), as src/emc/kinematics/trtfuncs.c does."""
    sa, ca, sc, cc = np.sin(a), np.cos(a), np.sin(c), np.cos(c)
    Dz = dz + dt
    px, py, pz = P[:, 0] - rot[0], P[:, 1] - rot[1], P[:, 2] - rot[2]
    qx = cc * px + sc * ca * py + sc * sa * pz - sc * ca * dy - sc * sa * Dz + sc * dy
    qy = -sc * px + cc * ca * py + cc * sa * pz - cc * ca * dy - cc * sa * Dz + cc * dy
    qz = -sa * py + ca * pz + sa * dy - ca * Dz + Dz
    return np.column_stack([qx, qy, qz]) + rot


def test_xyzac_trt_with_rotation_point_and_tool_offset_matches_linuxcnc():
    """LinuxCNC's world position is the controlled point: its Z includes the tool length (G43);
    dmdvox's tip with tool_length = tool-offset is that point minus tool-offset along workpiece Z."""
    rot = np.array([15.0, -8.0, 3.0])
    dy, dz, dt = 12.0, -70.0, 45.0
    m = trt_ac(c_point=tuple(rot), a_point=tuple(rot + [0.0, dy, dz]), sense="reversed",
               tool_length=dt)
    rng = np.random.default_rng(7)
    n = 1000
    j = np.zeros((n, 6))
    j[:, :3] = rng.uniform(-150, 150, (n, 3))
    j[:, 3] = rng.uniform(-120, 120, n)
    j[:, 5] = rng.uniform(-400, 400, n)
    tip, axis = forward(m, j)
    world = _linuxcnc_trt_ac_world(j, np.radians(j[:, 3]), np.radians(j[:, 5]), rot, dy, dz, dt)
    np.testing.assert_allclose(tip + [0.0, 0.0, dt], world, atol=1e-9)
    a, c = np.radians(j[:, 3]), np.radians(j[:, 5])
    np.testing.assert_allclose(axis, np.column_stack([np.sin(c) * np.sin(a),
                                                      np.cos(c) * np.sin(a), np.cos(a)]), atol=1e-12)


def test_xyzbc_trt_matches_linuxcnc_manual_hand_computation():
    """LinuxCNC manual, section "Transformations for a xyzbc-trt machine with rotary axis
    offsets", forward transformation (equation__35, printed as (37)):

        Qx =  cC cB Px + sC Py - cC sB Pz - cC cB Dx + cC sB Dz + cC Dx
        Qy = -sC cB Px + cC Py + sC sB Pz + sC cB Dx - sC sB Dz - sC Dx
        Qz =     sB Px         +    cB Pz -    sB Dx -    cB Dz +    Dz

    dmdvox: trt-bc with sense = "reversed", C through the origin, B through (Dx, 0, Dz).
    Pose: B = 30, C = 90 (cB = sqrt3/2, sB = 1/2, cC = 0, sC = 1), Dx = 6, Dz = -80,
    P = (20, 30, 50):
      Qx = 0 + 30 - 0 - 0 + 0 + 0                                          = 30
      Qy = -(sqrt3/2)*20 + 0 + (1/2)*50 + (sqrt3/2)*6 - (1/2)*(-80) - 6
         = -10 sqrt3 + 25 + 3 sqrt3 + 40 - 6                               = 59 - 7 sqrt3
      Qz = (1/2)*20 + (sqrt3/2)*50 - (1/2)*6 - (sqrt3/2)*(-80) - 80
         = 10 + 25 sqrt3 - 3 + 40 sqrt3 - 80                               = -73 + 65 sqrt3
    Tool axis: the third column of the rotation part, (-cC sB, sC sB, cB) = (0, 1/2, sqrt3/2).
    """
    m = trt_bc(b_point=(6.0, 0.0, -80.0), sense="reversed")
    P = joints(20.0, 30.0, 50.0, b=30.0, c=90.0)
    tip, axis = forward(m, P)
    np.testing.assert_allclose(tip[0], [30.0, 59.0 - 7.0 * S3, -73.0 + 65.0 * S3], atol=1e-12)
    np.testing.assert_allclose(axis[0], [0.0, 0.5, S3 / 2.0], atol=1e-15)
    back = inverse(m, tip, axis, near=joints(b=20.0, c=80.0))
    np.testing.assert_allclose(back[0], P[0], atol=1e-12)


def test_head_bc_matches_linuxcnc_5axiskins_hand_computation():
    """LinuxCNC 5axiskins (XYZBC head, its note: the tilt turns opposite to the convention):
    tip = J + (0, 0, L) + L (sin(180 - B) cos C, sin(180 - B) sin C, cos(180 - B)).
    B = 30, C = 90, L = 150, J = (10, 20, 30):
      tip = (10 + 150*(1/2)*0, 20 + 150*(1/2)*1, 30 + 150 + 150*(-sqrt3/2)) = (10, 95, 180 - 75 sqrt3)
    and the tool axis (tip to pivot) = (pivot - tip)/L = (0, -1/2, sqrt3/2).
    dmdvox: head-bc with b.sense = "reversed", c.sense = "iso"."""
    m = Machine(kind="head-bc", name="5axiskins", pivot_length=150.0, axes=(
        RotaryAxis("C", (0.0, 0.0, 1.0)), RotaryAxis("B", (0.0, 1.0, 0.0), sense="reversed")))
    tip, axis = forward(m, joints(10.0, 20.0, 30.0, b=30.0, c=90.0))
    np.testing.assert_allclose(tip[0], [10.0, 95.0, 180.0 - 75.0 * S3], atol=1e-12)
    np.testing.assert_allclose(axis[0], [0.0, -0.5, S3 / 2.0], atol=1e-15)


# ------------------------------------------------------------------------------------------
# Round trips on 10^6 random poses
# ------------------------------------------------------------------------------------------

def _skewed_head():
    return Machine(kind="head-bc", name="calibrated head", pivot_length=180.0, axes=(
        RotaryAxis("C", (0.004, -0.003, 1.0), limits=(-400.0, 400.0)),
        RotaryAxis("B", (0.01, 1.0, 0.02), sense="reversed", limits=(-120.0, 120.0))))


def _skewed_trunnion():
    return trt_ac(a_point=(3.0, -20.0, -90.0), c_point=(1.5, 2.0, 0.0), a_dir=(1.0, 0.015, -0.01),
                  c_dir=(0.005, 0.01, 1.0), sense="reversed", tool_length=30.0,
                  a_limits=(-100.0, 130.0))


ROUND_TRIP_MACHINES = {
    "trunnion-ac": lambda: load_machine(MACHINES / "trunnion-ac.toml"),
    "trunnion-bc": lambda: load_machine(MACHINES / "trunnion-bc.toml"),
    "head-bc": lambda: load_machine(MACHINES / "head-bc.toml"),
    "trunnion-ac-linuxcnc-skewed": _skewed_trunnion,
    "head-bc-skewed": _skewed_head,
}


def _random_poses(m, n, rng, min_tilt=2.0):
    """Random joints within the limits, the tilt at least min_tilt degrees from the singular 0."""
    j = np.zeros((n, 6))
    j[:, :3] = rng.uniform(-300.0, 300.0, (n, 3))
    tilt = m.axes[0] if m.kind.startswith("trt") else m.axes[1]
    for ax in m.axes:
        lo, hi = ax.limits if ax.limits is not None else (-720.0, 720.0)
        if ax is tilt:
            v = rng.uniform(lo, hi, n)
            small = np.abs(v) < min_tilt
            while small.any():
                v[small] = rng.uniform(lo, hi, small.sum())
                small = np.abs(v) < min_tilt
        else:
            v = rng.uniform(lo, hi, n)
        j[:, ax.column] = v
    return j


@pytest.mark.parametrize("which", list(ROUND_TRIP_MACHINES))
def test_forward_inverse_round_trip_million_poses(which):
    m = ROUND_TRIP_MACHINES[which]()
    rng = np.random.default_rng(zlib.crc32(which.encode()))
    n = 1_000_000
    j = _random_poses(m, n, rng)
    tip, axis = forward(m, j)
    np.testing.assert_allclose(np.linalg.norm(axis, axis=1), 1.0, atol=1e-12)
    # near: the original rotary values perturbed by up to 20 degrees (and any unused column)
    near = j.copy()
    near[:, 3:] += rng.uniform(-20.0, 20.0, (n, 3))
    back = inverse(m, tip, axis, near=near)
    used = [ax.column for ax in m.axes]
    np.testing.assert_allclose(back[:, :3], j[:, :3], rtol=0, atol=1e-9)   # mm
    np.testing.assert_allclose(back[:, used], j[:, used], rtol=0, atol=1e-9)  # degrees
    unused = [c for c in (3, 4, 5) if c not in used]
    np.testing.assert_array_equal(back[:, unused], near[:, unused])
    # and back to the same tip and axis
    tip2, axis2 = forward(m, back)
    np.testing.assert_allclose(tip2, tip, rtol=0, atol=1e-9)
    np.testing.assert_allclose(axis2, axis, rtol=0, atol=1e-12)


def test_inverse_picks_branch_and_turn_nearest_near():
    m = load_machine(MACHINES / "trunnion-ac.toml")
    tip, axis = forward(m, joints(5.0, 6.0, 7.0, a=40.0, c=30.0))
    # the other branch of the same pose: A -> -A, C -> C + 180
    out = inverse(m, tip, axis, near=joints(a=-35.0, c=200.0))
    np.testing.assert_allclose(out[0, [3, 5]], [-40.0, 210.0], atol=1e-9)
    # C on the turn of near: 30 + 2*360
    out = inverse(m, tip, axis, near=joints(a=40.0, c=700.0))
    np.testing.assert_allclose(out[0, [3, 5]], [40.0, 750.0], atol=1e-9)
    np.testing.assert_allclose(forward(m, out)[0], tip, atol=1e-9)


def test_inverse_respects_limits():
    m = load_machine(MACHINES / "trunnion-bc.toml")  # B limits [-10, 110]
    # tool axis -X: B = +90 with C = 180, or B = -90 with C = 0 (outside the limits)
    out = inverse(m, [[0.0, 0.0, 0.0]], [[-1.0, 0.0, 0.0]], near=joints(b=-80.0, c=10.0))
    np.testing.assert_allclose(out[0, [4, 5]], [90.0, 180.0], atol=1e-9)
    # cos B = -0.7: |B| = 134.4 degrees, beyond both limits
    with pytest.raises(DmdvoxError, match=r"pose 1:.*b\.limits"):
        inverse(m, np.zeros((2, 3)), [[0.0, 0.0, 1.0], [0.714, 0.0, -0.7]])


def test_singular_pose_any_c_works_nearest_near_chosen():
    m = load_machine(MACHINES / "trunnion-ac.toml")
    # at A = 0 the tool axis lies along C: every C gives the same tool axis (0, 0, 1); a tip on
    # the C axis (0, 0, h) stays put for every C
    c = np.linspace(-400.0, 400.0, 17)
    j = np.zeros((c.size, 6))
    j[:, 2], j[:, 5] = 12.0, c
    tip, axis = forward(m, j)
    np.testing.assert_allclose(tip, np.tile([0.0, 0.0, 12.0], (c.size, 1)), atol=1e-12)
    np.testing.assert_allclose(axis, np.tile([0.0, 0.0, 1.0], (c.size, 1)), atol=1e-15)
    # inverse keeps near's C (any turn) and puts the off-axis tip where that C needs it
    p = np.array([[30.0, 0.0, 5.0]] * 3)
    near = np.zeros((3, 6))
    near[:, 5] = [37.5, 400.0, -1000.0]
    out = inverse(m, p, np.tile([0.0, 0.0, 1.0], (3, 1)), near=near)
    np.testing.assert_allclose(out[:, 5], near[:, 5], atol=0)
    np.testing.assert_allclose(out[:, 3], 0.0, atol=1e-12)
    # machine position: the table turns the part by -C: (30 cos C, -30 sin C, 5)
    cr = np.radians(near[:, 5])
    np.testing.assert_allclose(out[:, :3], np.column_stack([30 * np.cos(cr), -30 * np.sin(cr),
                                                            np.full(3, 5.0)]), atol=1e-12)
    np.testing.assert_allclose(forward(m, out)[0], p, atol=1e-12)


def test_singular_head_vertical_keeps_near_c_clamped():
    m = load_machine(MACHINES / "head-bc.toml")  # C limits [-360, 360]
    near = np.zeros((2, 6))
    near[:, 5] = [-123.0, 500.0]
    out = inverse(m, [[1.0, 2.0, 3.0]] * 2, [[0.0, 0.0, 1.0]] * 2, near=near)
    np.testing.assert_allclose(out[:, 5], [-123.0, 360.0], atol=0)
    np.testing.assert_allclose(out[:, 4], 0.0, atol=1e-12)
    np.testing.assert_allclose(out[:, :3], [[1.0, 2.0, 3.0]] * 2, atol=1e-12)


def test_inverse_rejects_zero_axis():
    m = load_machine(MACHINES / "head-bc.toml")
    with pytest.raises(DmdvoxError, match="pose 0.*tool axis"):
        inverse(m, [[0.0, 0.0, 0.0]], [[0.0, 0.0, 0.0]])


# ------------------------------------------------------------------------------------------
# workpiece_to_machine
# ------------------------------------------------------------------------------------------

@pytest.mark.parametrize("which", list(ROUND_TRIP_MACHINES))
def test_workpiece_to_machine_consistent_with_forward(which):
    m = ROUND_TRIP_MACHINES[which]()
    rng = np.random.default_rng(3)
    j = _random_poses(m, 2000, rng, min_tilt=0.0)
    tip, axis = forward(m, j)
    R, t = workpiece_to_machine(m, j)
    # a workpiece point at the tip is where the machine holds the tip
    machine_tip = np.einsum("nij,nj->ni", R, tip) + t
    if m.kind.startswith("trt"):
        expected_tip = j[:, :3] - [0.0, 0.0, m.tool_length]
        expected_axis = np.tile([0.0, 0.0, 1.0], (len(j), 1))  # the nozzle stays vertical
    else:
        expected_tip = tip  # head-head: the workpiece does not move
        expected_axis = axis
        np.testing.assert_array_equal(R, np.broadcast_to(np.eye(3), R.shape))
    np.testing.assert_allclose(machine_tip, expected_tip, atol=1e-9)
    np.testing.assert_allclose(np.einsum("nij,nj->ni", R, axis), expected_axis, atol=1e-12)
    # R is a rotation
    np.testing.assert_allclose(np.einsum("nki,nkj->nij", R, R),
                               np.broadcast_to(np.eye(3), R.shape), atol=1e-12)
    np.testing.assert_allclose(np.linalg.det(R), 1.0, atol=1e-12)


def test_fixture_on_table_moves_with_it():
    """A fixture corner at workpiece (50, 0, 0) on the shipped trunnion-ac (A axis through
    (0, 0, -60)): A = 90 turns the part by Rx(-90) about the pivot:
    Rx(-90) ((50, 0, 0) - (0, 0, -60)) + (0, 0, -60) = (50, 60, 0) + (0, 0, -60)."""
    m = load_machine(MACHINES / "trunnion-ac.toml")
    R, t = workpiece_to_machine(m, joints(a=90.0))
    np.testing.assert_allclose(R[0] @ [50.0, 0.0, 0.0] + t[0], [50.0, 60.0, -60.0], atol=1e-12)


# ------------------------------------------------------------------------------------------
# Wrapped axes and limits
# ------------------------------------------------------------------------------------------

def test_short_way_for_wrapped_axes_only():
    m = load_machine(MACHINES / "trunnion-bc.toml")  # C wrapped, B not
    prog = np.zeros((4, 6))
    prog[:, 5] = [350.0, 10.0, 190.0, -170.0]  # 350 -> 10 is +20; 10 -> 190 is 180; -170 = 190
    prog[:, 4] = [0.0, 100.0, -100.0, 0.0]
    path = short_way(m, prog)
    np.testing.assert_allclose(path[:, 5], [350.0, 370.0, 550.0, 550.0])
    np.testing.assert_array_equal(path[:, 4], prog[:, 4])
    unwrapped = load_machine(MACHINES / "trunnion-ac.toml")  # C not wrapped: as programmed
    np.testing.assert_array_equal(short_way(unwrapped, prog), prog)


def test_check_limits_names_pose_and_field():
    m = load_machine(MACHINES / "head-bc.toml")
    check_limits(m, joints(b=110.0))
    with pytest.raises(DmdvoxError, match=r"pose 1: B = 115 .*b\.limits"):
        check_limits(m, np.vstack([joints(b=10.0), joints(b=115.0)]))


# ------------------------------------------------------------------------------------------
# Bad machine files
# ------------------------------------------------------------------------------------------

GOOD_AC = """
kind = "trt-ac"
name = "t"
[a]
point = [0, 0, -60]
direction = [1, 0, 0]
limits = [-110, 110]
[c]
point = [0, 0, 0]
direction = [0, 0, 1]
wrapped = true
"""

GOOD_HEAD = """
kind = "head-bc"
name = "h"
pivot_length = 150
[c]
direction = [0, 0, 1]
[b]
direction = [0, 1, 0]
"""


@pytest.mark.parametrize("text, field", [
    ('kind = "robot"\nname = "x"\n', "kind"),
    ('name = "x"\n', "kind"),
    ('kind = "none"\n', "name"),
    ('kind = "none"\nname = ""\n', "name"),
    ('kind = "none"\nname = "x"\nfoo = 1\n', "foo"),
    (GOOD_AC.replace("point = [0, 0, -60]\n", ""), "a.point"),
    (GOOD_AC.replace('direction = [0, 0, 1]\n', ""), "c.direction"),
    (GOOD_AC.replace("[c]\npoint = [0, 0, 0]\ndirection = [0, 0, 1]\nwrapped = true\n", ""), "c"),
    (GOOD_AC.replace("[0, 0, -60]", '[0, "zero", -60]'), "a.point[1]"),
    (GOOD_AC.replace("[0, 0, -60]", "[0, 0]"), "a.point"),
    (GOOD_AC.replace("direction = [1, 0, 0]", "direction = [0, 0, 0]"), "a.direction"),
    (GOOD_AC.replace("direction = [1, 0, 0]", "direction = [0, 0, 2]"), "c.direction"),  # parallel
    (GOOD_AC.replace("[-110, 110]", "[110, -110]"), "a.limits"),
    (GOOD_AC.replace("[-110, 110]", '["-110", 110]'), "a.limits[0]"),
    (GOOD_AC.replace("wrapped = true", "wrapped = true\nlimits = [0, 10]"), "c.limits"),
    (GOOD_AC.replace("wrapped = true", 'wrapped = "yes"'), "c.wrapped"),
    (GOOD_AC.replace("wrapped = true", 'sense = "linuxcnc"'), "c.sense"),
    (GOOD_AC.replace("wrapped = true", "pivot = 3"), "c.pivot"),
    (GOOD_AC.replace('name = "t"', 'name = "t"\ntool_length = -5'), "tool_length"),
    (GOOD_AC.replace('name = "t"', 'name = "t"\npivot_length = 100'), "pivot_length"),
    (GOOD_HEAD.replace("pivot_length = 150\n", ""), "pivot_length"),
    (GOOD_HEAD.replace("150", '"150"'), "pivot_length"),
    (GOOD_HEAD.replace("150", "nan"), "pivot_length"),
    (GOOD_HEAD.replace("direction = [0, 1, 0]", "direction = [0, 0, 0]"), "b.direction"),
    (GOOD_HEAD.replace("direction = [0, 1, 0]", "direction = [0, 1, 0]\npoint = [0, 0, 0]"),
     "b.point"),
    (GOOD_HEAD.replace("[b]", "[a]"), "a"),
])
def test_bad_machine_file_names_file_and_field(tmp_path, text, field):
    path = tmp_path / "bad-machine.toml"
    path.write_text(text)
    with pytest.raises(DmdvoxError) as err:
        load_machine(path)
    msg = str(err.value)
    assert str(path) in msg
    assert f"field '{field}'" in msg


def test_good_fixtures_load(tmp_path):
    for text in (GOOD_AC, GOOD_HEAD):
        path = tmp_path / "m.toml"
        path.write_text(text)
        load_machine(path)


def test_unreadable_machine_files(tmp_path):
    with pytest.raises(DmdvoxError, match="not found"):
        load_machine(tmp_path / "missing.toml")
    path = tmp_path / "broken.toml"
    path.write_text('kind = "trt-ac\n')
    with pytest.raises(DmdvoxError, match=r"broken\.toml.*not valid TOML"):
        load_machine(path)
