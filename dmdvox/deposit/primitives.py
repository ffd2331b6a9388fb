"""Bead solids as signed distance functions (numba scalars).

Each returns ``(d, frac)``: the signed distance in mm (negative inside) and, for points inside
the solid (elsewhere 0 for segments), the path parameter in [0, 1] of the path point that lays
the material there (arrival time is
``t0 + frac * (t1 - t0)``). Sign is exact for all of them; distance is exact except where noted.
"""

from __future__ import annotations

import math

from numba import njit

from .profiles import RECT, profile_sdf

_VERTICAL = 0.999


@njit(cache=True)
def _extrusion(qx, s_out, code, w, h, n, y):
    """Profile extruded with flat ends: ``s_out`` = distance beyond the nearer end (< 0 inside)."""
    q0 = profile_sdf(code, w, h, n, qx, y)
    inner = min(max(q0, s_out), 0.0)
    return inner + math.sqrt(max(q0, 0.0) ** 2 + max(s_out, 0.0) ** 2)


@njit(cache=True)
def cap_sdf(px, py, pz, cx, cy, cz, code, w, h, n):
    """The profile revolved about the vertical axis through c: a round joint or end."""
    r = math.sqrt((px - cx) ** 2 + (py - cy) ** 2)
    return profile_sdf(code, w, h, n, r, pz - cz), 0.0


@njit(cache=True)
def segment_frame(ax, ay, az, bx, by, bz):
    """Travel direction t, up axis u (+Z made perpendicular to t), v = t x u, and length."""
    dx = bx - ax
    dy = by - ay
    dz = bz - az
    length = math.sqrt(dx * dx + dy * dy + dz * dz)
    if length <= 1e-12:
        return 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0
    tx = dx / length
    ty = dy / length
    tz = dz / length
    if abs(tz) > _VERTICAL:
        return tx, ty, tz, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, length
    ux = -tz * tx
    uy = -tz * ty
    uz = 1.0 - tz * tz
    un = math.sqrt(ux * ux + uy * uy + uz * uz)
    ux /= un
    uy /= un
    uz /= un
    return tx, ty, tz, ux, uy, uz, ty * uz - tz * uy, tz * ux - tx * uz, tx * uy - ty * ux, length


@njit(cache=True)
def segment_sdf_framed(px, py, pz, ax, ay, az, tx, ty, tz, ux, uy, uz, vx, vy, vz, length, code, w, h, n):
    """:func:`segment_sdf` with the frame from :func:`segment_frame` computed once per segment."""
    if length <= 1e-12:
        return cap_sdf(px, py, pz, ax, ay, az, code, w, h, n)
    wx = px - ax
    wy = py - ay
    wz = pz - az
    along = wx * tx + wy * ty + wz * tz
    if abs(tz) > _VERTICAL:
        # A vertical move has no travel-perpendicular up axis: the bead is the cap swept up,
        # i.e. the union of the revolved profile at the top end and a column below it down to
        # the bottom end. Sign exact; inside, the union's min is a lower bound on depth.
        dz = tz * length
        lo_z = az + min(0.0, dz)
        rise = abs(dz)
        r = math.sqrt(wx * wx + wy * wy)
        d_top = profile_sdf(code, w, h, n, r, pz - lo_z - rise)
        qy = r - 0.5 * w
        qz = abs(pz - lo_z - 0.5 * rise) - 0.5 * rise
        d_col = math.sqrt(max(qy, 0.0) ** 2 + max(qz, 0.0) ** 2) + min(max(qy, qz), 0.0)
        frac = min(1.0, max(0.0, (pz - az) / dz))
        return min(d_top, d_col), frac
    lateral = wx * vx + wy * vy + wz * vz
    up = wx * ux + wy * uy + wz * uz
    s_out = abs(along - 0.5 * length) - 0.5 * length
    if code == RECT:
        # The extruded rectangle is a box: one square root instead of two.
        q0 = abs(lateral) - 0.5 * w
        q1 = abs(up - 0.5 * h) - 0.5 * h
        d = math.sqrt(max(q0, 0.0) ** 2 + max(q1, 0.0) ** 2 + max(s_out, 0.0) ** 2) + min(max(q0, q1, s_out), 0.0)
    else:
        d = _extrusion(lateral, s_out, code, w, h, n, up)
    # Arrival only matters inside; skip the division elsewhere.
    frac = min(1.0, max(0.0, along / length)) if d <= 0.0 else 0.0
    return d, frac


@njit(cache=True)
def segment_sdf(px, py, pz, ax, ay, az, bx, by, bz, code, w, h, n):
    """The profile extruded along a -> b, its up axis +Z made perpendicular to the travel."""
    tx, ty, tz, ux, uy, uz, vx, vy, vz, length = segment_frame(ax, ay, az, bx, by, bz)
    return segment_sdf_framed(px, py, pz, ax, ay, az, tx, ty, tz, ux, uy, uz, vx, vy, vz, length, code, w, h, n)


@njit(cache=True)
def arc_sdf(px, py, pz, cx, cy, cz, radius, theta0, sweep, code, w, h, n):
    """A horizontal arc bead: the profile revolved about the vertical axis through (cx, cy)
    at offset ``radius``, from angle ``theta0`` over the signed ``sweep`` (radians)."""
    rx = px - cx
    ry = py - cy
    rho = math.sqrt(rx * rx + ry * ry)
    z = pz - cz
    span = abs(sweep)
    two_pi = 2.0 * math.pi
    if span >= two_pi - 1e-12:
        phi = math.atan2(ry, rx)
        rel = (phi - theta0) % two_pi if sweep > 0 else (theta0 - phi) % two_pi
        return profile_sdf(code, w, h, n, rho - radius, z), rel / span
    phi = math.atan2(ry, rx)
    rel = (phi - theta0) % two_pi if sweep > 0 else (theta0 - phi) % two_pi
    if rel <= span:
        return profile_sdf(code, w, h, n, rho - radius, z), rel / span
    # Beyond one end: the end face's profile plane, as for a straight segment's flat end.
    sign = 1.0 if sweep > 0 else -1.0
    best = math.inf
    frac = 0.0
    for end in range(2):
        theta = theta0 + (sweep if end == 1 else 0.0)
        ex = math.cos(theta)
        ey = math.sin(theta)
        # Outward normal of the end face: along the travel at the end, against it at the start.
        out = sign if end == 1 else -sign
        nx = -ey * out
        ny = ex * out
        beyond = rx * nx + ry * ny
        if beyond < 0.0:
            # Out of range, the point is beyond at least one end plane (the in-range wedge is
            # the intersection or union of the two half planes); only those give the distance.
            continue
        radial = rx * ex + ry * ey - radius
        d = _extrusion(radial, beyond, code, w, h, n, z)
        if d < best:
            best = d
            frac = float(end)
    return best, frac
