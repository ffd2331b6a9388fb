"""The G-code interpreter kernel: one pass over the file's bytes, straight into segment arrays.

Everything here is numba; the caller (:mod:`dmdvox.toolpath.reader`) turns the event codes
into messages. Lines are tokenised in place (no strings, no per-line allocation), numbers are
parsed with exact decimal scaling, and the modal state machine follows RS274/NGC (LinuxCNC)
with RepRap's E semantics where the dialect asks for them.
"""

from __future__ import annotations

import numpy as np
from numba import njit

# Event codes. Those below EV_WARN_BASE make a line malformed (skipped; fatal with --strict).
EV_BAD_CHAR = 1
EV_NO_NUMBER = 2
EV_DUPLICATE_WORD = 3
EV_BARE_NUMBER = 4
EV_NONFINITE = 5
EV_ABSURD = 6
EV_ARC_NO_CENTRE = 7
EV_ARC_FULL_CIRCLE_R = 8
EV_INVERSE_TIME_NO_F = 9
EV_BAD_P = 10
EV_WARN_BASE = 100
EV_CHECKSUM = 101
EV_ARC_RADIUS_MISMATCH = 102  # fatal with --strict
EV_ARC_R_TOO_SMALL = 103  # fatal with --strict
EV_UNTERMINATED_COMMENT = 104
EV_POSITION_UNKNOWN = 105
EV_NEGATIVE_FEED = 106
EV_UNKNOWN_BASE = 200
EV_UNKNOWN_G = 201  # value = code * 10
EV_UNKNOWN_M = 202
EV_UNKNOWN_WORD = 203  # value = letter index
EV_UNKNOWN_T = 204

# Evidence bits for the auto dialect's report.
EVID_E = 1
EVID_SEED = 2
EVID_LINUXCNC = 4
EVID_SPINDLE = 8
EVID_MELTIO = 16

ABSURD_MM = 1.0e7  # 10 km: no machine has such an axis; larger values are corrupt input

_POW10 = np.array([10.0**k for k in range(23)], dtype=np.float64)
_GAUSS_X, _GAUSS_W = np.polynomial.legendre.leggauss(32)

# Letter indices
_A, _B, _C, _E, _F, _G, _I, _J, _K, _M, _N, _P, _R, _S, _T, _X, _Y, _Z = (
    ord(c) - 65 for c in "ABCEFGIJKMNPRSTXYZ"
)
_MAX_CODES = 16


@njit(cache=True)
def _count_lines(buf):
    n = 0
    for b in buf:
        if b == 10:
            n += 1
    if buf.shape[0] > 0 and buf[buf.shape[0] - 1] != 10:
        n += 1
    return n


@njit(cache=True)
def _parse_number(buf, pos, end):
    """Parse a decimal number starting at ``pos``; return (value, next_pos, ok).

    Spaces between the sign and the digits are allowed (``X - 1.5``), no exponent: like
    LinuxCNC and Marlin, ``1e5`` is the number 1 followed by an E word.
    """
    while pos < end and (buf[pos] == 32 or buf[pos] == 9):
        pos += 1
    neg = False
    if pos < end and (buf[pos] == 45 or buf[pos] == 43):
        neg = buf[pos] == 45
        pos += 1
        while pos < end and (buf[pos] == 32 or buf[pos] == 9):
            pos += 1
    mant = np.int64(0)
    digits = 0
    extra_int = 0  # integer digits beyond int64 precision
    frac = 0
    seen_point = False
    while pos < end:
        c = buf[pos]
        if 48 <= c <= 57:
            digits += 1
            if mant < 100000000000000000:
                mant = mant * 10 + (c - 48)
                if seen_point:
                    frac += 1
            elif not seen_point:
                extra_int += 1
            pos += 1
        elif c == 46 and not seen_point:
            seen_point = True
            pos += 1
        else:
            break
    if digits == 0:
        return 0.0, pos, False
    value = float(mant)
    scale = extra_int - frac
    if scale < 0:
        if -scale <= 22:
            value = value / _POW10[-scale]
        else:
            value = value * 10.0**scale
    elif scale > 0:
        value = value * 10.0**scale
    if neg:
        value = -value
    return value, pos, True


@njit(cache=True)
def _tokenise(buf, ls, le, letters, values, gcodes, mcodes):
    """Split one line into words. Returns (event, event_value, n_g, n_m).

    ``letters[i]`` flags which non-G/M letters appeared; ``values[i]`` their values.
    """
    for i in range(26):
        letters[i] = False
    n_g = 0
    n_m = 0
    pos = ls
    first_word = True
    checksum = 0
    while pos < le:
        c = buf[pos]
        if c == 32 or c == 9 or c == 13 or c == 37:  # space, tab, CR, '%'
            checksum ^= c
            pos += 1
            continue
        if c == 59:  # ';' comment to end of line
            break
        if c == 40:  # '(' comment
            close = pos + 1
            while close < le and buf[close] != 41:
                close += 1
            if close >= le:
                return EV_UNTERMINATED_COMMENT, 0.0, n_g, n_m
            for q in range(pos, close + 1):
                checksum ^= buf[q]
            pos = close + 1
            continue
        if c == 42:  # '*' checksum (RepRap): XOR of every byte before it
            value, nxt, ok = _parse_number(buf, pos + 1, le)
            if ok and int(value) != checksum:
                return EV_CHECKSUM, value, n_g, n_m
            break
        if c == 47 and first_word:  # '/' block delete marker: run the block
            checksum ^= c
            pos += 1
            continue
        if 97 <= c <= 122:
            c -= 32
        if 65 <= c <= 90:
            start = pos
            value, nxt, ok = _parse_number(buf, pos + 1, le)
            if not ok:
                return EV_NO_NUMBER, float(c - 65), n_g, n_m
            if not np.isfinite(value):
                return EV_NONFINITE, float(c - 65), n_g, n_m
            if abs(value) > ABSURD_MM:
                return EV_ABSURD, float(c - 65), n_g, n_m
            idx = c - 65
            if idx == _G:
                if n_g < _MAX_CODES:
                    gcodes[n_g] = int(round(value * 10.0))
                    n_g += 1
            elif idx == _M:
                if n_m < _MAX_CODES:
                    mcodes[n_m] = int(round(value))
                    n_m += 1
            else:
                if letters[idx]:
                    return EV_DUPLICATE_WORD, float(idx), n_g, n_m
                letters[idx] = True
                values[idx] = value
            for q in range(start, nxt):
                checksum ^= buf[q]
            pos = nxt
            first_word = False
            continue
        if first_word and (48 <= c <= 57 or c == 45 or c == 43 or c == 46):
            # Bare leading numbers (the seed's two numeric columns) before the first word.
            value, nxt, ok = _parse_number(buf, pos, le)
            if not ok:
                return EV_BAD_CHAR, float(c), n_g, n_m
            for q in range(pos, nxt):
                checksum ^= buf[q]
            pos = nxt
            continue
        if 48 <= c <= 57 or c == 45 or c == 43 or c == 46:
            return EV_BARE_NUMBER, 0.0, n_g, n_m
        return EV_BAD_CHAR, float(c), n_g, n_m
    return 0, 0.0, n_g, n_m


@njit(cache=True)
def _push(ev_line, ev_code, ev_value, n_ev, dropped, line_no, code, value):
    """Record one event; past the buffer's capacity only count it."""
    if n_ev < ev_line.shape[0]:
        ev_line[n_ev] = line_no
        ev_code[n_ev] = code
        ev_value[n_ev] = value
        return n_ev + 1, dropped
    return n_ev, dropped + 1


@njit(cache=True)
def _wrap_positive(angle):
    """Map to (0, 2 pi]."""
    two_pi = 2.0 * np.pi
    a = angle % two_pi
    if a <= 1e-12:
        a += two_pi
    return a


@njit(cache=True)
def _arc_length(r0, r1, sweep, rise):
    if abs(r1 - r0) <= 1e-12 * max(1.0, r0):
        return np.sqrt((r0 * sweep) ** 2 + rise * rise)
    # Spiral (radius varying linearly with angle, as LinuxCNC runs it): Gauss-Legendre is
    # exact to rounding for this smooth integrand.
    total = 0.0
    span = abs(sweep)
    dr = (r1 - r0) / span
    dz = rise / span
    for q in range(_GAUSS_X.shape[0]):
        phi = 0.5 * span * (_GAUSS_X[q] + 1.0)
        r = r0 + dr * phi
        total += _GAUSS_W[q] * np.sqrt(r * r + dr * dr + dz * dz)
    return 0.5 * span * total


@njit(cache=True)
def interpret(buf, rules, flags, strict, default_feed, rapid_feed, arc_abs_tol, arc_rel_tol,
              out_start, out_end, out_deposit, out_kind, out_feed, out_power, out_t0, out_t1,
              out_line, out_rotary,
              arc_seg, arc_centre, arc_axis, arc_sweep, arc_r0, arc_r1, arc_len,
              ev_line, ev_code, ev_value):
    """Interpret the whole buffer. Returns (rows, arcs, events, events_dropped, lines, status,
    evidence, end_time).

    ``status`` is 0, or the event index that stopped a --strict run.
    """
    use_e = (flags & 1) != 0
    s0_off = (flags & 2) != 0
    dwell_ms = (flags & 4) != 0
    auto_e = (flags & 8) != 0
    n_rules = rules.shape[0]

    letters = np.zeros(26, np.bool_)
    values = np.zeros(26, np.float64)
    gcodes = np.zeros(_MAX_CODES, np.int64)
    mcodes = np.zeros(_MAX_CODES, np.int64)

    pos = np.zeros(3, np.float64)  # machine position, mm
    known = np.zeros(3, np.bool_)
    offset = np.zeros(3, np.float64)  # G92: machine = program + offset
    rot = np.zeros(3, np.float64)
    rot_offset = np.zeros(3, np.float64)
    target = np.zeros(3, np.float64)
    unit = 1.0
    relative = False
    arc_relative_centre = True
    plane = 2  # normal axis: G17 -> Z
    inverse_time = False
    motion = 1  # G1 until told otherwise (the seed files never say G0)
    feed = default_feed / 60.0
    power = 0.0
    laser = False
    spindle = False
    pending = 0  # M62/M63 waiting for the next motion: 1 on, 2 off
    e_pos = 0.0
    e_relative = False
    e_mode = use_e
    evidence = 0
    t = 0.0
    warned_unknown = False

    rows = 0
    arcs = 0
    n_ev = 0
    dropped = 0
    line_no = 0
    n = buf.shape[0]
    ls = 0
    status = 0
    while ls < n:
        le = ls
        while le < n and buf[le] != 10:
            le += 1
        line_no += 1
        ev, ev_val, n_g, n_m = _tokenise(buf, ls, le, letters, values, gcodes, mcodes)
        ls = le + 1
        if ev != 0:
            n_ev, dropped = _push(ev_line, ev_code, ev_value, n_ev, dropped, line_no, ev, ev_val)
            if ev < EV_WARN_BASE or ev == EV_UNTERMINATED_COMMENT:
                if strict:
                    status = n_ev
                    break
                continue
            if ev != EV_CHECKSUM:
                continue
            # A checksum mismatch means a corrupted transmission line: never run it.
            if strict:
                status = n_ev
                break
            continue

        # ---- modal and non-motion G codes -------------------------------------------------
        move_code = -1
        dwell = False
        set_g92 = False
        homing = False
        bad = 0
        bad_val = 0.0
        for gi in range(n_g):
            g = gcodes[gi]
            if g == 0 or g == 10 or g == 20 or g == 30:
                move_code = g // 10
            elif g == 40:
                dwell = True
            elif g == 170:
                plane = 2
            elif g == 180:
                plane = 1
            elif g == 190:
                plane = 0
            elif g == 200:
                unit = 25.4
            elif g == 210:
                unit = 1.0
            elif g == 900:
                relative = False
                e_relative = False
            elif g == 910:
                relative = True
                e_relative = True
            elif g == 901:
                arc_relative_centre = False
            elif g == 911:
                arc_relative_centre = True
            elif g == 920:
                set_g92 = True
            elif g == 930:
                inverse_time = True
            elif g == 940:
                inverse_time = False
            elif g == 280:
                homing = True
            else:
                bad = EV_UNKNOWN_G
                bad_val = float(g)
        if bad != 0:
            n_ev, dropped = _push(ev_line, ev_code, ev_value, n_ev, dropped, line_no, bad, bad_val)

        if letters[_F] and not inverse_time:
            if values[_F] <= 0.0:
                n_ev, dropped = _push(ev_line, ev_code, ev_value, n_ev, dropped, line_no, EV_NEGATIVE_FEED, values[_F])
            else:
                feed = values[_F] * unit / 60.0
        if letters[_S]:
            power = values[_S]
        if letters[_T]:
            n_ev, dropped = _push(ev_line, ev_code, ev_value, n_ev, dropped, line_no, EV_UNKNOWN_T, values[_T])

        # ---- M codes through the dialect's rule table --------------------------------------
        for mi in range(n_m):
            m = mcodes[mi]
            has_p = letters[_P]
            p_val = int(round(values[_P])) if has_p else -1
            action = 0
            for r in range(n_rules):
                if rules[r, 0] != m:
                    continue
                rp = rules[r, 1]
                if rp == -2 or (rp == -1 and not has_p) or (rp >= 0 and has_p and rp == p_val):
                    action = rules[r, 2]
                    break
            if action == 0:
                n_ev, dropped = _push(ev_line, ev_code, ev_value, n_ev, dropped, line_no, EV_UNKNOWN_M, float(m))
                continue
            if m == 64 or m == 65:
                if has_p and (p_val == 8 or p_val == 9):
                    evidence |= EVID_MELTIO
                elif has_p:
                    evidence |= EVID_LINUXCNC
                else:
                    evidence |= EVID_SEED
            elif m == 62 or m == 63:
                evidence |= EVID_LINUXCNC
            elif m == 101 or m == 102 or m == 103 or m == 108:
                evidence |= EVID_SEED
            elif m == 3 or m == 4 or m == 5:
                evidence |= EVID_SPINDLE
            if action == 1:
                laser = True
            elif action == 2:
                laser = False
                spindle = False
            elif action == 3:
                pending = 1
            elif action == 4:
                pending = 2
            elif action == 5:
                spindle = True
                laser = True
            elif action == 6:
                spindle = False
                laser = False
            elif action == 7:
                e_relative = False
            elif action == 8:
                e_relative = True

        if dwell:
            if letters[_P]:
                t += values[_P] / 1000.0 if dwell_ms else values[_P]
            elif letters[_S]:
                t += values[_S]
            elif letters[_X]:
                t += values[_X]
            continue

        if homing:
            # G28: the axes named (all when none) go home, taken as machine zero.
            any_axis = letters[_X] or letters[_Y] or letters[_Z]
            for ax in range(3):
                if not any_axis or letters[_X + ax]:
                    pos[ax] = 0.0
                    known[ax] = True
                    offset[ax] = 0.0
            continue

        if set_g92:
            for ax in range(3):
                li = _X if ax == 0 else (_Y if ax == 1 else _Z)
                if letters[li]:
                    offset[ax] = pos[ax] - values[li] * unit
                    known[ax] = True
            for ax in range(3):
                if letters[_A + ax]:
                    rot_offset[ax] = rot[ax] - values[_A + ax]
            if letters[_E]:
                e_pos = values[_E]
            if not (letters[_X] or letters[_Y] or letters[_Z] or letters[_E]
                    or letters[_A] or letters[_B] or letters[_C]):
                for ax in range(3):
                    offset[ax] = pos[ax]
                    known[ax] = True
                e_pos = 0.0
            continue

        if move_code >= 0:
            motion = move_code

        has_xyz = letters[_X] or letters[_Y] or letters[_Z]
        has_rot = letters[_A] or letters[_B] or letters[_C]
        has_e = letters[_E]
        if not (has_xyz or has_rot or has_e) and not (motion >= 2 and (letters[_I] or letters[_J] or letters[_K] or letters[_R])):
            continue

        # ---- target position ----------------------------------------------------------------
        start_known = known[0] and known[1] and known[2]
        for ax in range(3):
            li = _X if ax == 0 else (_Y if ax == 1 else _Z)
            if letters[li]:
                if relative:
                    target[ax] = pos[ax] + values[li] * unit
                else:
                    target[ax] = values[li] * unit + offset[ax]
                    known[ax] = True
            else:
                target[ax] = pos[ax]
        for ax in range(3):
            if letters[_A + ax]:
                if relative:
                    rot[ax] = rot[ax] + values[_A + ax]
                else:
                    rot[ax] = values[_A + ax] + rot_offset[ax]

        extrudes = False
        e_delta = 0.0
        if has_e:
            if auto_e:
                e_mode = True
                evidence |= EVID_E
            if e_mode:
                e_delta = values[_E] if e_relative else values[_E] - e_pos
                e_pos = e_pos + values[_E] if e_relative else values[_E]
                extrudes = e_delta > 0.0

        if pending == 1:
            laser = True
            pending = 0
        elif pending == 2:
            laser = False
            pending = 0

        dx = target[0] - pos[0]
        dy = target[1] - pos[1]
        dz = target[2] - pos[2]
        lin_len = np.sqrt(dx * dx + dy * dy + dz * dz)

        is_arc = motion >= 2 and (has_xyz or letters[_I] or letters[_J] or letters[_K] or letters[_R])
        if e_mode:
            deposit = extrudes and motion != 0
        else:
            beam = laser and (not s0_off or not spindle or power > 0.0)
            deposit = beam and motion != 0
        if not start_known:
            # Positioning from an unknown place is normal; depositing from one loses material.
            if deposit and not warned_unknown:
                warned_unknown = True
                n_ev, dropped = _push(ev_line, ev_code, ev_value, n_ev, dropped, line_no, EV_POSITION_UNKNOWN, 0.0)
            for ax in range(3):
                pos[ax] = target[ax]
            continue

        # ---- geometry ---------------------------------------------------------------------
        length = lin_len
        kind = 0 if motion == 0 else 1
        if is_arc:
            a0 = 0 if plane == 2 else (2 if plane == 1 else 1)
            a1 = 1 if plane == 2 else (0 if plane == 1 else 2)
            i0 = _I + a0
            i1 = _I + a1
            s0 = pos[a0]
            s1 = pos[a1]
            e0 = target[a0]
            e1 = target[a1]
            c0 = 0.0
            c1 = 0.0
            ok = True
            r_err = 0.0
            chord = np.sqrt((e0 - s0) ** 2 + (e1 - s1) ** 2)
            if letters[_R]:
                radius = values[_R] * unit
                if chord <= 1e-12:
                    ok = False
                    r_err = -1.0
                else:
                    half = 0.5 * chord
                    h2 = radius * radius - half * half
                    if h2 < 0.0:
                        if abs(radius) < half - max(arc_abs_tol, 1e-9):
                            n_ev, dropped = _push(ev_line, ev_code, ev_value, n_ev, dropped, line_no, EV_ARC_R_TOO_SMALL, radius)
                            if strict:
                                status = n_ev
                                break
                        h2 = 0.0
                    h = np.sqrt(h2)
                    m0 = 0.5 * (s0 + e0)
                    m1 = 0.5 * (s1 + e1)
                    u0 = (e0 - s0) / chord
                    u1 = (e1 - s1) / chord
                    # left normal of the chord
                    l0 = -u1
                    l1 = u0
                    side = 1.0 if motion == 3 else -1.0
                    if radius < 0.0:
                        side = -side
                    c0 = m0 + side * h * l0
                    c1 = m1 + side * h * l1
            elif letters[i0] or letters[i1]:
                v0 = values[i0] * unit if letters[i0] else 0.0
                v1 = values[i1] * unit if letters[i1] else 0.0
                if arc_relative_centre:
                    c0 = s0 + v0
                    c1 = s1 + v1
                else:
                    c0 = (v0 + offset[a0]) if letters[i0] else s0
                    c1 = (v1 + offset[a1]) if letters[i1] else s1
            else:
                ok = False
            if not ok:
                n_ev, dropped = _push(ev_line, ev_code, ev_value, n_ev, dropped, line_no, EV_ARC_FULL_CIRCLE_R if r_err < 0.0 else EV_ARC_NO_CENTRE, 0.0)
                if strict:
                    status = n_ev
                    break
                continue
            r0 = np.sqrt((s0 - c0) ** 2 + (s1 - c1) ** 2)
            r1 = np.sqrt((e0 - c0) ** 2 + (e1 - c1) ** 2)
            diff = abs(r1 - r0)
            if diff > 0.5 or (diff > arc_abs_tol and diff > arc_rel_tol * r0):
                n_ev, dropped = _push(ev_line, ev_code, ev_value, n_ev, dropped, line_no, EV_ARC_RADIUS_MISMATCH, diff)
                if strict:
                    status = n_ev
                    break
            th0 = np.arctan2(s1 - c1, s0 - c0)
            th1 = np.arctan2(e1 - c1, e0 - c0)
            if chord <= 1e-9 and r0 > 0.0:
                span = 2.0 * np.pi
            elif motion == 3:
                span = _wrap_positive(th1 - th0)
            else:
                span = _wrap_positive(th0 - th1)
            if letters[_P]:
                turns = int(round(values[_P]))
                if turns < 1:
                    n_ev, dropped = _push(ev_line, ev_code, ev_value, n_ev, dropped, line_no, EV_BAD_P, values[_P])
                    if strict:
                        status = n_ev
                        break
                    continue
                span += 2.0 * np.pi * (turns - 1)
            sweep = span if motion == 3 else -span
            rise = target[plane] - pos[plane]
            length = _arc_length(r0, r1, sweep, rise)
            if r0 <= 1e-12 and r1 <= 1e-12:
                length = abs(rise)
            kind = motion
            arc_seg[arcs] = rows
            arc_centre[arcs, a0] = c0
            arc_centre[arcs, a1] = c1
            arc_centre[arcs, plane] = pos[plane]
            arc_axis[arcs] = plane
            arc_sweep[arcs] = sweep
            arc_r0[arcs] = r0
            arc_r1[arcs] = r1
            arc_len[arcs] = length

        if length <= 1e-12 and not is_arc:
            if has_e and e_mode and e_delta != 0.0:
                t += abs(e_delta) / feed  # retract / unretract: time without motion
            for ax in range(3):
                pos[ax] = target[ax]
            continue

        if motion == 0:
            speed = rapid_feed / 60.0
            duration = length / speed
        elif inverse_time:
            if not letters[_F] or values[_F] <= 0.0:
                n_ev, dropped = _push(ev_line, ev_code, ev_value, n_ev, dropped, line_no, EV_INVERSE_TIME_NO_F, 0.0)
                if strict:
                    status = n_ev
                    break
                for ax in range(3):
                    pos[ax] = target[ax]
                continue
            duration = 60.0 / values[_F]
            speed = length / duration if duration > 0.0 else 0.0
        else:
            speed = feed
            duration = length / speed
        if is_arc:
            arcs += 1

        for ax in range(3):
            out_start[rows, ax] = pos[ax]
            out_end[rows, ax] = target[ax]
            out_rotary[rows, ax] = rot[ax]
            pos[ax] = target[ax]
        out_deposit[rows] = deposit
        out_kind[rows] = kind
        out_feed[rows] = speed
        out_power[rows] = power
        out_t0[rows] = t
        t += duration
        out_t1[rows] = t
        out_line[rows] = line_no
        rows += 1
    return rows, arcs, n_ev, dropped, line_no, status, evidence, t
