"""Bead solids as signed distance functions (numba scalar functions).

Each returns ``(d, frac)``: the signed distance in mm (negative inside) and the path parameter
in [0, 1] of the path point that lays the material there (arrival time is
``t0 + frac * (t1 - t0)``). Points are bead-bottom centres; the cross-section is a profile
from :mod:`dmdvox.process.profiles` (``code, w, h, n``) standing on the point along the bead's
up axis ``u``, continued straight down by ``foot`` below its bottom (a bead that landed on an
uneven surface fills down to it; ``foot = 0`` is the bare profile).

Sign is exact everywhere. Distance is exact everywhere except inside an arc bead whose radius
is below w/2 (the profile crosses the arc's axis): there ``|d|`` is a lower bound on the depth.
"""

from __future__ import annotations

import math

from numba import njit

from ..process.profiles import profile_sdf, profile_top, top_curve_dist2

# |t_z| above this: the travel is too close to vertical to define a bead up axis from it
_VERTICAL = 0.999
_TWO_PI = 2.0 * math.pi


@njit(cache=True)
def section_sdf(code, w, h, n, foot, y, z):
    """The cross-section: the profile with a straight foot of depth ``foot`` below it."""
    if foot <= 0.0:
        return profile_sdf(code, w, h, n, y, z)
    return _column_sdf(code, w, h, n, abs(y), z + foot, foot)


@njit(cache=True)
def cap_sdf(px, py, pz, cx, cy, cz, ux, uy, uz, code, w, h, n, foot):
    """The cross-section revolved about the axis u through c (a round joint or end).

    Exact: the section is symmetric, so the nearest point lies in the meridian plane through
    the query point. ``frac`` is 0: the cap belongs to its centre point.
    """
    dx = px - cx
    dy = py - cy
    dz = pz - cz
    along = dx * ux + dy * uy + dz * uz
    r = math.sqrt(max(dx * dx + dy * dy + dz * dz - along * along, 0.0))
    return section_sdf(code, w, h, n, foot, r, along), 0.0


@njit(cache=True)
def clipped_cap_sdf(px, py, pz, cx, cy, cz, ux, uy, uz, ax, ay, az, bx, by, bz, code, w, h, n, foot):
    """The cap cut to the points beyond both planes through c with normals a and b (a zero
    normal cuts nothing): the part of a joint or end that its pieces do not already cover, so
    that its volume is the wedge between them (half the cap at a run's end).

    Intersection by ``max``: the sign is exact; outside, near the cut edges, the distance is a
    lower bound (those edges lie on the pieces' end faces, inside the deposit's union).
    """
    d, frac = cap_sdf(px, py, pz, cx, cy, cz, ux, uy, uz, code, w, h, n, foot)
    dx = px - cx
    dy = py - cy
    dz = pz - cz
    if ax != 0.0 or ay != 0.0 or az != 0.0:
        d = max(d, -(dx * ax + dy * ay + dz * az))
    if bx != 0.0 or by != 0.0 or bz != 0.0:
        d = max(d, -(dx * bx + dy * by + dz * bz))
    return d, frac


@njit(cache=True)
def _column_sdf(code, w, h, n, r, zz, rise):
    """The cap swept straight up by ``rise``, at horizontal distance r, height zz above its base.

    Its meridian section is Q = {|y| <= w/2, 0 <= z <= rise + top(y)}: P on top of a
    rectangle. Outside, Q is P swept along a vertical segment, so the distance is the least
    distance to a shifted copy of P, and that is the copy nearest in height (the distance to
    P grows with height above its base). Inside, the boundary is the base, the straight sides
    up to ``rise`` and the shifted top curve.
    """
    a = 0.5 * w
    if r <= a and zz >= 0.0:
        top_r = profile_top(code, w, h, n, r)
        if zz <= rise + top_r:
            best2 = zz * zz
            if zz <= rise:
                best2 = min(best2, (a - r) ** 2)
            return -math.sqrt(top_curve_dist2(code, a, h, n, r, zz - rise, top_r, best2))
    return profile_sdf(code, w, h, n, r, zz - min(max(zz, 0.0), rise))


@njit(cache=True)
def segment_sdf(px, py, pz, ax, ay, az, bx, by, bz, ux, uy, uz, code, w, h, n, foot):
    """The cross-section extruded along the straight segment a -> b, with flat ends.

    The section's plane is perpendicular to the travel t; its up axis is the bead's up axis u
    made perpendicular to t. Exact: q = (section distance, distance beyond the nearer end
    plane) combined as for a box. A segment nearly along u (|t.u| > 0.999) has no such up axis
    and is the cap at its lower end swept along u over the segment's rise
    (:func:`_column_sdf`, also exact); a zero-length one is the cap at a. ``frac`` is the
    projection on the segment, clamped to [0, 1].
    """
    ex = bx - ax
    ey = by - ay
    ez = bz - az
    length = math.sqrt(ex * ex + ey * ey + ez * ez)
    if length == 0.0:
        return cap_sdf(px, py, pz, ax, ay, az, ux, uy, uz, code, w, h, n, foot)
    tx = ex / length
    ty = ey / length
    tz = ez / length
    wx = px - ax
    wy = py - ay
    wz = pz - az
    along = wx * tx + wy * ty + wz * tz
    frac = min(max(along / length, 0.0), 1.0)
    tu = tx * ux + ty * uy + tz * uz
    if abs(tu) > _VERTICAL:
        up = wx * ux + wy * uy + wz * uz
        r = math.sqrt(max(wx * wx + wy * wy + wz * wz - up * up, 0.0))
        rise = abs(length * tu)
        base = min(0.0, length * tu)  # the lower end, along u
        return _column_sdf(code, w, h, n, r, up - base + foot, rise + foot), frac
    un = math.sqrt(1.0 - tu * tu)
    vx = (ux - tu * tx) / un
    vy = (uy - tu * ty) / un
    vz = (uz - tu * tz) / un
    # lateral axis: t x u (for u = +Z the same as before)
    lx = ty * vz - tz * vy
    ly = tz * vx - tx * vz
    lz = tx * vy - ty * vx
    q0 = section_sdf(code, w, h, n, foot, wx * lx + wy * ly + wz * lz, wx * vx + wy * vy + wz * vz)
    q1 = abs(along - 0.5 * length) - 0.5 * length
    d = min(max(q0, q1), 0.0) + math.sqrt(max(q0, 0.0) ** 2 + max(q1, 0.0) ** 2)
    return d, frac


@njit(cache=True)
def _face_dist(code, w, h, n, foot, dx, dy, dz, radius, theta):
    """Distance to the arc's section standing in the vertical plane through the axis at theta.

    The plane is taken whole (signed in-plane coordinate), so a section that crosses the
    axis is measured on both sides of it.
    """
    c = math.cos(theta)
    s = math.sin(theta)
    q0 = section_sdf(code, w, h, n, foot, dx * c + dy * s - radius, dz)
    off = -dx * s + dy * c
    return math.sqrt(max(q0, 0.0) ** 2 + off * off)


@njit(cache=True)
def arc_sdf(px, py, pz, cx, cy, cz, radius, theta0, sweep, code, w, h, n, foot):
    """A horizontal (G17) arc bead: the section revolved about the vertical axis through c.

    The bead centre line has ``radius`` about (cx, cy) at bead-bottom height cz, starts at
    angle ``theta0`` and turns by the signed ``sweep`` (positive counter-clockwise); with
    ``|sweep| >= 2 pi`` it is the full ring. ``frac`` is the fraction of the sweep travelled
    when the head first passes the query point's meridian; beyond an end, that end's 0 or 1.

    For radius >= w/2 the distance is exact: within the angular range the nearest point is
    in the query point's meridian; beyond it, it is on the angularly nearer end face (each
    meridian section point is nearest at the angle closest to the query point); inside, the
    end faces compete with the side. For radius < w/2 the profile also reaches the opposite
    meridian; outside, the distance is still exact (the least distance over the swept angles
    is reached at the query meridian, the opposite one, an end, or on the axis), inside it
    is the distance to a superset of the boundary, a lower bound on the depth.
    """
    a = 0.5 * w
    dx = px - cx
    dy = py - cy
    dz = pz - cz
    rho = math.sqrt(dx * dx + dy * dy)
    span = abs(sweep)
    direction = 1.0 if sweep >= 0.0 else -1.0
    # angle travelled from the start to the query meridian, in the direction of motion
    alpha = ((math.atan2(dy, dx) - theta0) * direction) % _TWO_PI
    d_near = section_sdf(code, w, h, n, foot, rho - radius, dz)
    theta1 = theta0 + sweep
    if radius >= a:
        if span >= _TWO_PI:
            return d_near, alpha / span
        if alpha <= span:
            frac = alpha / span
            if d_near >= 0.0:
                return d_near, frac
            depth = -d_near
            for theta in (theta0, theta1):
                # the distance to the face's plane bounds the distance to the face below
                if abs(dy * math.cos(theta) - dx * math.sin(theta)) < depth:
                    depth = min(depth, _face_dist(code, w, h, n, foot, dx, dy, dz, radius, theta))
            return -depth, frac
        if alpha - span <= _TWO_PI - alpha:
            return _face_dist(code, w, h, n, foot, dx, dy, dz, radius, theta1), 1.0
        return _face_dist(code, w, h, n, foot, dx, dy, dz, radius, theta0), 0.0
    d_far = section_sdf(code, w, h, n, foot, rho + radius, dz)
    if span >= _TWO_PI:
        # the meridian section is the union of the profile and its mirror across the axis
        return min(d_near, d_far), alpha / span
    alpha_opp = (alpha + math.pi) % _TWO_PI
    in_near = alpha <= span
    in_far = alpha_opp <= span
    if in_near:
        frac = alpha / span
    elif in_far:
        frac = alpha_opp / span
    else:
        frac = 1.0 if alpha - span <= _TWO_PI - alpha else 0.0
    f_start = _face_dist(code, w, h, n, foot, dx, dy, dz, radius, theta0)
    f_end = _face_dist(code, w, h, n, foot, dx, dy, dz, radius, theta1)
    if (in_near and d_near <= 0.0) or (in_far and d_far <= 0.0):
        return -min(abs(d_near), abs(d_far), f_start, f_end), frac
    d = min(f_start, f_end)
    if in_near:
        d = min(d, d_near)
    if in_far:
        d = min(d, d_far)
    # the stretch of the axis inside the section lies in every swept meridian
    top_axis = profile_top(code, w, h, n, radius)
    d = min(d, math.sqrt(rho * rho + (dz - min(max(dz, -foot), top_axis)) ** 2))
    return d, frac
