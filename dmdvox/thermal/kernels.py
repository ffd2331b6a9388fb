"""numba kernels of the explicit finite-volume heat solver (see :mod:`.solver` for the model).

One call advances ``n_steps`` steps of ``dt``; every step: cells whose birth time has come are
born, T and k are read from each cell's enthalpy, the events of the step are recorded (peak,
remelt, time above, the liquidus crossing's cooling rate and gradient), then every existing cell's
enthalpy gains the conduction through its faces, the losses of its exposed faces and its share of
the beam. The conduction between two cells is computed once and given to one, taken from the
other, so it cancels exactly and the energy balance closes to round-off.
"""

from __future__ import annotations

import numpy as np
from numba import njit

# energy accumulators (J)
E_SOURCE, E_BIRTH, E_CONVECTION, E_RADIATION, E_BOTTOM, E_MISSED, E_DEBT, E_BOILING = range(8)
N_ENERGY = 8


@njit(cache=True, inline="always")
def _tables(x, x0, inv_dx, a, b):
    """Two tables on one uniform grid, interpolated at ``x`` (constant beyond the ends)."""
    u = (x - x0) * inv_dx
    n = a.shape[0]
    if u <= 0.0:
        return a[0], b[0]
    if u >= n - 1:
        return a[n - 1], b[n - 1]
    i = np.int64(u)
    f = u - i
    return a[i] + f * (a[i + 1] - a[i]), b[i] + f * (b[i + 1] - b[i])


@njit(cache=True)
def advance(n_steps, t_begin, dt, voxel, origin, ijk, birth, neighbour, n_born, top,
            H, T, k, peak, t_above, cool_rate, gradient, t_solid, remelts, solid,
            seg_t0, seg_t1, seg_p0, seg_p1, seg_power, seg_ptr, beam_radius,
            h0, dh, t_of_h, k_of_h,
            h_birth, h_ambient, t_birth, t_liquidus, t_solidus, t_threshold,
            conv, emis_sigma, t_amb_k4, t_ambient, clamped, t_bottom, energy, h_boil, goldak, dz):
    """Advance the state ``n_steps`` steps from ``t_begin``; returns (n_born, seg_ptr).

    Units: mm, s, J, W; ``conv`` W/(mm^2 K), ``emis_sigma`` emissivity x Stefan-Boltzmann in
    W/(mm^2 K^4), ``t_amb_k4`` the ambient's (T + 273.15)^4. ``top[i, j]`` is the highest cell of
    column (i, j) that exists (-1: none): where the beam lands. ``h_boil``: the enthalpy at the
    boiling point (inf: no limit); what the beam would put into a cell beyond it leaves as
    evaporation, counted in ``energy[E_BOILING]``. ``goldak`` (a_f, a_r, b, c) mm, all > 0: the
    beam is Goldak's double ellipsoid in the cells under each column top instead of the
    Gaussian on the tops (zeros: the Gaussian). ``dz``: each cell's height in voxels (a plate
    layer of coarse cells spans several; its x and y neighbours span the same, its z neighbours
    are joined through both half heights in series).
    """
    n = birth.shape[0]
    area = voxel * voxel
    vol = area * voxel
    nx, ny = top.shape[0], top.shape[1]
    marked = np.empty(n, np.int64)
    dH = np.empty(n)
    n_seg = seg_t0.shape[0]
    rb2 = beam_radius * beam_radius
    inv_dh = 1.0 / dh
    reach = 3.0 * beam_radius
    volumetric = goldak[0] > 0.0
    if volumetric:
        # the double ellipsoid falls to exp(-12) = 6e-6 of its centre at twice each semi-axis
        reach = 2.0 * max(max(goldak[0], goldak[1]), goldak[2])
    for s in range(n_steps):
        t_now = t_begin + s * dt
        n_born = _births(t_now, n_born, birth, ijk, top, H, T, k, peak, solid, h0, inv_dh, t_of_h, k_of_h,
                         h_birth, h_ambient, t_birth, vol, energy)
        # temperatures and the step's events
        n_marked = 0
        for c in range(n_born):
            t_old = T[c]
            t_new, k_new = _tables(H[c], h0, inv_dh, t_of_h, k_of_h)
            if t_old >= t_liquidus and t_new < t_liquidus:
                cool_rate[c] = (t_old - t_new) / dt
                t_solid[c] = t_now
                marked[n_marked] = c
                n_marked += 1
            if t_new < t_solidus:
                solid[c] = 1
            elif t_new >= t_liquidus and solid[c] == 1:
                remelts[c] += 1
                solid[c] = 0
            if t_new > peak[c]:
                peak[c] = t_new
            if t_new >= t_threshold:
                t_above[c] += dt
            T[c] = t_new
            k[c] = k_new
        for q in range(n_marked):
            c = marked[q]
            g2 = 0.0
            for axis in range(3):
                a = neighbour[c, 2 * axis]
                b = neighbour[c, 2 * axis + 1]
                has_a = 0 <= a < n_born
                has_b = 0 <= b < n_born
                if has_a and has_b:
                    d = (T[b] - T[a]) / (2.0 * voxel)
                elif has_b:
                    d = (T[b] - T[c]) / voxel
                elif has_a:
                    d = (T[c] - T[a]) / voxel
                else:
                    d = 0.0
                g2 += d * d
            gradient[c] = np.sqrt(g2)
        # conduction (each pair once, through the cell's +x, +y, +z faces) and losses
        e_conv = 0.0
        e_rad = 0.0
        e_bot = 0.0
        for c in range(n_born):
            dH[c] = 0.0
        for c in range(n_born):
            tc = T[c]
            kc = k[c]
            q = 0.0
            for f in range(6):
                o = neighbour[c, f]
                if 0 <= o < n_born:
                    if f & 1:
                        ko = k[o]
                        if f == 5:
                            g = (2.0 * kc * ko / (dz[c] * ko + dz[o] * kc)) * voxel * (T[o] - tc)
                        else:
                            g = (2.0 * kc * ko / (kc + ko)) * voxel * dz[c] * (T[o] - tc)
                        q += g
                        dH[o] -= g
                    continue
                if o == -2:
                    if clamped:
                        qb = 2.0 * kc * voxel * (t_bottom - tc) / dz[c]
                        q += qb
                        e_bot -= qb
                    continue
                tk = tc + 273.15
                face = area * dz[c] if f < 4 else area
                qc = conv * face * (t_ambient - tc)
                qr = emis_sigma * face * (t_amb_k4 - tk * tk * tk * tk)
                q += qc + qr
                e_conv -= qc
                e_rad -= qr
            dH[c] += q
        energy[E_CONVECTION] += e_conv * dt
        energy[E_RADIATION] += e_rad * dt
        energy[E_BOTTOM] += e_bot * dt
        for c in range(n_born):
            H[c] += dH[c] * dt / (vol * dz[c])
        # the beam: a Gaussian (1/e^2 radius beam_radius) on the tops of the columns under it
        t_mid = t_now + 0.5 * dt
        while seg_ptr < n_seg and seg_t1[seg_ptr] <= t_mid:
            seg_ptr += 1
        if seg_ptr < n_seg and seg_t0[seg_ptr] <= t_mid:
            g = seg_ptr
            span = seg_t1[g] - seg_t0[g]
            f = (t_mid - seg_t0[g]) / span if span > 0.0 else 0.0
            xs = seg_p0[g, 0] + f * (seg_p1[g, 0] - seg_p0[g, 0])
            ys = seg_p0[g, 1] + f * (seg_p1[g, 1] - seg_p0[g, 1])
            e_step = seg_power[g] * dt
            pay = min(energy[E_DEBT], e_step)
            energy[E_DEBT] -= pay
            e_flux = e_step - pay
            i0 = max(np.int64(np.floor((xs - reach - origin[0]) / voxel)), 0)
            i1 = min(np.int64(np.ceil((xs + reach - origin[0]) / voxel)), nx - 1)
            j0 = max(np.int64(np.floor((ys - reach - origin[1]) / voxel)), 0)
            j1 = min(np.int64(np.ceil((ys + reach - origin[1]) / voxel)), ny - 1)
            if volumetric:
                ux = seg_p1[g, 0] - seg_p0[g, 0]
                uy = seg_p1[g, 1] - seg_p0[g, 1]
                _goldak(xs, ys, ux, uy, e_flux, goldak, i0, i1, j0, j1, origin, voxel, vol, top, ijk, neighbour,
                        n_born, H, h_boil, energy, dz)
                continue
            total = 0.0
            for i in range(i0, i1 + 1):
                dx = origin[0] + voxel * i - xs
                for j in range(j0, j1 + 1):
                    if top[i, j] >= 0:
                        dy = origin[1] + voxel * j - ys
                        total += np.exp(-2.0 * (dx * dx + dy * dy) / rb2)
            if total > 0.0:
                scale = e_flux / (total * vol)
                for i in range(i0, i1 + 1):
                    dx = origin[0] + voxel * i - xs
                    for j in range(j0, j1 + 1):
                        c = top[i, j]
                        if c >= 0:
                            dy = origin[1] + voxel * j - ys
                            H[c] += scale * np.exp(-2.0 * (dx * dx + dy * dy) / rb2)
                            if H[c] > h_boil:
                                energy[E_BOILING] += (H[c] - h_boil) * vol
                                H[c] = h_boil
                energy[E_SOURCE] += e_flux
            else:
                energy[E_MISSED] += e_flux
    # the cells that arrived during the last step exist when it ends: a bead's end that arrives
    # after the last step's start (the program's last bead) is part of the state handed back
    n_born = _births(t_begin + n_steps * dt, n_born, birth, ijk, top, H, T, k, peak, solid, h0, inv_dh, t_of_h,
                     k_of_h, h_birth, h_ambient, t_birth, vol, energy)
    return n_born, seg_ptr


@njit(cache=True)
def _goldak_weight(along, across, depth, a_f, a_r, b, c):
    """Goldak's double ellipsoid without its constant: exp(-3 (x/a)^2 - 3 (y/b)^2 - 3 (z/c)^2), a
    the front semi-axis ahead of the source, the rear one behind. With f_f = 2 a_f / (a_f + a_r)
    and f_r = 2 a_r / (a_f + a_r) the constant 6 sqrt(3) f Q / (a b c pi^1.5) is the same on both
    sides (the density continuous at the source) and f_f + f_r = 2."""
    a = a_f if along >= 0.0 else a_r
    return np.exp(-3.0 * ((along / a) ** 2 + (across / b) ** 2 + (depth / c) ** 2))


@njit(cache=True)
def _goldak(xs, ys, ux, uy, e_flux, goldak, i0, i1, j0, j1, origin, voxel, vol, top, ijk, neighbour, n_born, H,
            h_boil, energy, dz):
    """``e_flux`` into the cells of the columns under the source, each by the double ellipsoid at
    its centre (depth from its column's top face), normalised so they get exactly ``e_flux``."""
    a_f, a_r, b, c = goldak[0], goldak[1], goldak[2], goldak[3]
    norm = np.sqrt(ux * ux + uy * uy)
    if norm > 0.0:
        ux /= norm
        uy /= norm
    else:  # a still piece: no direction, the mean semi-axis on every side
        ux, uy = 1.0, 0.0
        a_f = a_r = 0.5 * (a_f + a_r)
    total = 0.0
    for sweep in range(2):
        for i in range(i0, i1 + 1):
            dx = origin[0] + voxel * i - xs
            for j in range(j0, j1 + 1):
                c0 = top[i, j]
                if c0 < 0:
                    continue
                dy = origin[1] + voxel * j - ys
                along = dx * ux + dy * uy
                across = -dx * uy + dy * ux
                surface = ijk[c0, 2] + 0.5
                cell = c0
                while cell >= 0:
                    depth = (surface - ijk[cell, 2] - 0.5 * (dz[cell] - 1.0)) * voxel
                    if depth > 2.0 * c:
                        break
                    w = _goldak_weight(along, across, depth, a_f, a_r, b, c) * dz[cell]  # density x volume
                    if sweep == 0:
                        total += w
                    else:
                        H[cell] += e_flux * w / (total * vol * dz[cell])
                        if H[cell] > h_boil:
                            energy[E_BOILING] += (H[cell] - h_boil) * vol * dz[cell]
                            H[cell] = h_boil
                    below = neighbour[cell, 4]
                    cell = below if 0 <= below < n_born else -1
        if total <= 0.0:
            energy[E_MISSED] += e_flux
            return
    energy[E_SOURCE] += e_flux


@njit(cache=True, inline="always")
def _births(t_now, n_born, birth, ijk, top, H, T, k, peak, solid, h0, inv_dh, t_of_h, k_of_h,
            h_birth, h_ambient, t_birth, vol, energy):
    """Cells whose birth time is at or before ``t_now``, born at ``t_birth`` (the liquidus or the
    given birth temperature), their enthalpy drawn from the beam; returns the new n_born."""
    n = birth.shape[0]
    while n_born < n and birth[n_born] <= t_now:
        c = n_born
        H[c] = h_birth
        T[c] = t_birth
        k[c] = _tables(h_birth, h0, inv_dh, t_of_h, k_of_h)[1]
        if t_birth > peak[c]:
            peak[c] = t_birth
        solid[c] = 0
        energy[E_BIRTH] += vol * (h_birth - h_ambient)
        energy[E_DEBT] += vol * (h_birth - h_ambient)
        i, j = ijk[c, 0], ijk[c, 1]
        if top[i, j] < 0 or ijk[top[i, j], 2] < ijk[c, 2]:
            top[i, j] = c
        n_born += 1
    return n_born


@njit(cache=True)
def stored_energy(H, n, vol, h_ambient, dz):
    total = 0.0
    for c in range(n):
        total += (H[c] - h_ambient) * dz[c]
    return total * vol
