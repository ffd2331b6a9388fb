"""The G-code interpreter kernel: the file's bytes straight into segment arrays.

Everything here is numba; the caller (:mod:`dmdvox.toolpath.reader`) turns the event codes
into messages. Lines are tokenised in place (no strings, no per-line allocation), numbers are
parsed with exact decimal scaling, and the modal state machine follows RS274/NGC (LinuxCNC)
with RepRap's E semantics where the dialect asks for them.

Tokenising is most of the work and each line's words depend on that line alone, so it runs
in parallel: the file is cut into pieces of ``_PIECE_BYTES`` (a piece owns the lines that
start in it), whose lines become compact word lists. The modal state machine then walks those
lists in file order on one thread. ``_CHUNK_PIECES`` pieces go at a time, which bounds the
word lists' memory whatever the file size; the result does not depend on the thread count.
"""

from __future__ import annotations

import numpy as np
from numba import njit, prange
from numba.cpython.unsafe.numbers import trailing_zeros

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
EV_NEGATIVE_DWELL = 11
EV_WARN_BASE = 100
EV_CHECKSUM = 101
EV_ARC_RADIUS_MISMATCH = 102  # fatal with --strict
EV_ARC_R_TOO_SMALL = 103  # fatal with --strict
EV_UNTERMINATED_COMMENT = 104
EV_POSITION_UNKNOWN = 105
EV_NEGATIVE_FEED = 106
EV_REPEATED_F = 107  # two F words on one motion line: the last one counts
EV_PARAMETER = 108  # a LinuxCNC parameter assignment (#<name> = 4, #1=5): skipped
EV_EXPRESSION = 109  # a word whose value is a parameter or [expression] (F#<rate>): left out
EV_EXPRESSION_PATH = 110  # the same on a word that decides the path or material: refused
EV_OWORD = 111  # o-word control flow (o100 sub, o<loop> while): refused
EV_UNKNOWN_BASE = 200
EV_UNKNOWN_G = 201  # value = code * 10
EV_UNKNOWN_M = 202
EV_UNKNOWN_WORD = 203  # value = letter index
EV_UNKNOWN_T = 204
# Evidence for the auto dialect: the first line of each family's codes (value: M * 1000 + P + 1,
# P + 1 = 0 without a P word; -1: an E word on a move). Not warnings: the reader reports them.
EV_EVIDENCE = 300
# Numbers worth a doubt, counted by kind (the reader says the first line and the count)
EV_LONG_DWELL = 301  # value: the dwell, s
LONG_DWELL_S = 600.0

# Reader flags (beside the dialect's FLAG_* of dialects.py, bits 1-16).
FLAG_FIVE_AXIS = 32  # a machine file is given: rotary-only moves make rows, rotary values recorded
FLAG_E_RELATIVE_START = 64  # E words are relative from the first line (the printer's mode, no M83)

# out_info entries: what the reader needs to say why moves are missing or E reads wrong
INFO_UNKNOWN_MOVES = 0  # moves from a position not yet known: not recorded
INFO_UNKNOWN_RELATIVE = 1  # of those, moves under G91
INFO_UNKNOWN_DEPOSIT = 2  # of those, moves that would deposit
INFO_AXES_KNOWN = 3  # bit ax: axis ax (X, Y, Z) was known by the end
INFO_E_ABSOLUTE = 4  # motion lines with an E word read as absolute
INFO_E_FALLS = 5  # of those, E below the previous E
INFO_E_RISES = 6  # of those, E above it
INFO_E_MODE_SAID = 7  # M82 / M83 lines
INFO_E_WORDS = 8  # motion lines with an E word that meters material (E-driven reading)
INFO_SIZE = 9

# out_mode bits of five-axis rows
MODE_TCP = 1  # tool-centre-point control on: X Y Z are the tip in the workpiece frame
MODE_INVERSE_TIME = 2  # G93: the row's duration is the program's
MODE_RAPID = 4  # G0 at the rapid rate

# Evidence bits for the auto dialect's report.
EVID_E = 1
EVID_SEED = 2
EVID_LINUXCNC = 4
EVID_SPINDLE = 8
EVID_MELTIO = 16

ABSURD_MM = 1.0e7  # 10 km: no machine has such an axis; larger values are corrupt input
# Smaller F words (per minute; G93: moves per minute) are corrupt too: a move's time over such a
# feed can overflow to infinity (F with 300 zeros after the point did).
MIN_FEED = 1.0e-6

_POW10 = np.array([10.0**k for k in range(23)], dtype=np.float64)
_GAUSS_X, _GAUSS_W = np.polynomial.legendre.leggauss(32)

# Letter indices
_A, _B, _C, _E, _F, _G, _I, _J, _K, _M, _N, _P, _R, _S, _T, _X, _Y, _Z = (
    ord(c) - 65 for c in "ABCEFGIJKMNPRSTXYZ"
)
_MAX_CODES = 16
# Letter masks (bit i: letter i)
_XYZ = 1 << _X | 1 << _Y | 1 << _Z
_ABC = 1 << _A | 1 << _B | 1 << _C
_IJKR = 1 << _I | 1 << _J | 1 << _K | 1 << _R

# A stored word is a letter and at least one digit, so a piece's complete lines hold at most
# one word per two bytes; the line running past its end adds at most _MAX_WORDS (every
# letter but G and M once, and _MAX_CODES of each of those). A line has at least one byte, so
# a piece holds at most _PIECE_BYTES lines.
_PIECE_BYTES = 1 << 16
_CHUNK_PIECES = 16
_MAX_WORDS = 24 + 2 * _MAX_CODES
_PIECE_WORDS = _PIECE_BYTES // 2 + _MAX_WORDS


@njit(cache=True)
def count_newlines(buf):
    """The number of newline bytes (numba: no temporary array, unlike numpy)."""
    n = 0
    for b in buf:
        n += b == 10
    return n


# Eight bytes at a time (SWAR): which lead bytes are digits, and their value.
_NIBBLE_HI = np.uint64(0xF0F0F0F0F0F0F0F0)
_NIBBLE_LO = np.uint64(0x0F0F0F0F0F0F0F0F)
_ASCII_0 = np.uint64(0x3030303030303030)
_PLUS_6 = np.uint64(0x0606060606060606)
_POW10_INT = np.array([10**k for k in range(8)], dtype=np.int64)


@njit(cache=True)
def _load8(buf, pos):
    """``buf[pos:pos + 8]`` as a little-endian uint64 (one load: the index is unsigned, so
    numba adds no negative-index wraparound)."""
    x = np.uint64(0)
    at = np.uint64(pos)
    for i in range(8):
        x |= np.uint64(buf[at + np.uint64(i)]) << np.uint64(8 * i)
    return x


@njit(cache=True)
def _digit_run(x):
    """How many of the eight bytes in ``x`` (from the first) are ASCII digits before another byte."""
    not_digit = ((x & _NIBBLE_HI) ^ _ASCII_0) | (((x & _NIBBLE_LO) + _PLUS_6) & _NIBBLE_HI)
    return np.int64(trailing_zeros(not_digit)) >> 3


@njit(cache=True)
def _digits_value(x, k):
    """The number written by the first ``k`` (1 to 8) bytes of ``x``, all digits."""
    x = x << np.uint64(64 - 8 * k)  # the others out; zeros (leading '0's) come in
    x = ((x & _NIBBLE_LO) * np.uint64(10 * 2**8 + 1)) >> np.uint64(8)
    x = ((x & np.uint64(0x00FF00FF00FF00FF)) * np.uint64(100 * 2**16 + 1)) >> np.uint64(16)
    x = ((x & np.uint64(0x0000FFFF0000FFFF)) * np.uint64(10000 * 2**32 + 1)) >> np.uint64(32)
    return np.int64(x)


@njit(inline="always")  # once per word: numba's call overhead would be a large share
def _parse_number(buf, pos, n):
    """Parse a decimal number starting at ``pos``; return (value, next_pos, ok).

    Spaces between the sign and the digits are allowed (``X - 1.5``), no exponent: like
    LinuxCNC and Marlin, ``1e5`` is the number 1 followed by an E word. The digits go into an
    int64 mantissa until it reaches 1e17 (further integer digits only scale it, further
    fraction digits are dropped), which is then scaled by an exact power of ten.
    """
    while pos < n and (buf[pos] == 32 or buf[pos] == 9):
        pos += 1
    neg = False
    if pos < n and (buf[pos] == 45 or buf[pos] == 43):
        neg = buf[pos] == 45
        pos += 1
        while pos < n and (buf[pos] == 32 or buf[pos] == 9):
            pos += 1
    if pos + 16 <= n:  # room for both eight-byte loads
        # Fast path for up to 7 integer and 7 fraction digits, eight bytes at a time: that
        # many digits all fit the mantissa, so the value is the one the loop below computes.
        x = _load8(buf, pos)
        k = _digit_run(x)
        if k < 8:
            mant = _digits_value(x, k) if k else np.int64(0)
            nxt = pos + k
            k_frac = 0
            if buf[nxt] == 46:
                x = _load8(buf, nxt + 1)
                k_frac = _digit_run(x)
                nxt += 1 + k_frac
                if 0 < k_frac < 8:
                    mant = mant * _POW10_INT[k_frac] + _digits_value(x, k_frac)
            if k_frac < 8:
                if k + k_frac == 0:
                    return 0.0, nxt, False
                value = float(mant)
                if k_frac:
                    value = value / _POW10[k_frac]
                return (-value if neg else value), nxt, True
    mant = np.int64(0)
    digits = 0
    extra_int = 0  # integer digits beyond int64 precision
    frac = 0
    seen_point = False
    while pos < n:
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


# Numbers that are not a word's value, marked in place of the word's letter index.
_CHECKSUM = -1
_BARE_NUMBER = -2
_KEYWORD = -3  # a '#' that may begin #TRAFO ON/OFF

# Tool-centre-point control keywords, upper case (matched in either case), and the G code each
# stands for: Siemens TRAORI / TRAFOOF, Beckhoff #TRAFO ON / #TRAFO OFF.
G_TCP_ON = 43.4
G_TCP_OFF = 49.0
_KW_TRAORI = np.frombuffer(b"TRAORI", np.uint8)
_KW_TRAFOOF = np.frombuffer(b"TRAFOOF", np.uint8)
_KW_HASH_TRAFO = np.frombuffer(b"#TRAFO", np.uint8)
_KW_ON = np.frombuffer(b"ON", np.uint8)
_KW_OFF = np.frombuffer(b"OFF", np.uint8)


@njit(cache=True)
def _match_word(buf, pos, n, word):
    """The end of ``word`` (upper-case ASCII) when ``buf`` holds it at ``pos`` in either case,
    not followed by a letter, digit or '_' (a longer name); else -1."""
    m = word.shape[0]
    if pos + m > n:
        return -1
    for i in range(m):
        b = buf[pos + i]
        if 97 <= b <= 122:
            b -= 32
        if b != word[i]:
            return -1
    end = pos + m
    if end < n:
        b = buf[end] | 0x20
        if (48 <= buf[end] <= 57) or (97 <= b <= 122) or buf[end] == 95:
            return -1
    return end


@njit(cache=True)
def _keyword(buf, pos, n):
    """(G value, end) of a tool-centre-point keyword at ``pos``; (0, pos) when there is none."""
    end = _match_word(buf, pos, n, _KW_TRAORI)
    if end >= 0:
        return G_TCP_ON, end
    end = _match_word(buf, pos, n, _KW_TRAFOOF)
    if end >= 0:
        return G_TCP_OFF, end
    end = _match_word(buf, pos, n, _KW_HASH_TRAFO)
    if end >= 0:
        while end < n and (buf[end] == 32 or buf[end] == 9):
            end += 1
        on = _match_word(buf, end, n, _KW_ON)
        if on >= 0:
            return G_TCP_ON, on
        off = _match_word(buf, end, n, _KW_OFF)
        if off >= 0:
            return G_TCP_OFF, off
    return 0.0, pos


# M-codes whose rest of line is free text (Marlin/RepRap: file names, messages).
_TEXT_M = (23, 28, 32, 33, 117, 118, 928)


@njit(cache=True)
def _is_text_m(value):
    for m in _TEXT_M:
        if value == m:
            return True
    return False


@njit(cache=True)
def _ends_token(b):
    """Whether byte ``b`` ends a firmware parameter token: white space, line end, comment."""
    return b == 32 or b == 9 or b == 10 or b == 13 or b == 59 or b == 40


@njit(cache=True)
def _skip_expression(buf, q, n):
    """The end of the LinuxCNC parameter or expression at ``q``: ``#<name>``, ``#123``, ``#[..]``,
    ``[..]`` (nested); ``q`` itself when none starts there."""
    if q < n and buf[q] == 35:
        q += 1
        while q < n and buf[q] == 35:  # #[#1]: indirection
            q += 1
        if q < n and buf[q] == 60:  # '<'
            while q < n and buf[q] != 62 and buf[q] != 10:
                q += 1
            return q + 1 if q < n and buf[q] == 62 else q
        if q < n and buf[q] != 91:
            while q < n and 48 <= buf[q] <= 57:
                q += 1
            return q
    if q < n and buf[q] == 91:  # '[' ... ']', nested
        depth = 0
        while q < n and buf[q] != 10:
            if buf[q] == 91:
                depth += 1
            elif buf[q] == 93:
                depth -= 1
                if depth == 0:
                    return q + 1
            q += 1
    return q


# Letters whose value decides the path or the material (axes, arc centre and radius, E, S):
# an expression there cannot be left out.
_PATH_LETTERS = (1 << 23 | 1 << 24 | 1 << 25 | 1 << 0 | 1 << 1 | 1 << 2 | 1 << 20 | 1 << 21 | 1 << 22
                 | 1 << 8 | 1 << 9 | 1 << 10 | 1 << 17 | 1 << 4 | 1 << 18)


@njit(cache=True)
def _is_name_byte(b):
    """A letter of either case or '_' (names of extended commands: PRINT_START, GET_POSITION)."""
    return (65 <= (b & 0xDF) <= 90) or b == 95


@njit(inline="always")  # once per line: numba's call overhead would be a large share
def _tokenise_line(buf, pos, w_letter, w_value, w):
    """Split the line starting at ``pos`` into words, stored from index ``w`` on.

    Returns (event, event_value, letter_mask, n_words, line_end): bit ``i`` of
    ``letter_mask`` flags letter ``i`` (G and M excepted, they may repeat; the first
    _MAX_CODES of each are kept); ``line_end`` is the index of the newline (or the buffer's end).

    After an M-code or a G-code other than G0-G3 the words are that code's parameters, in the
    firmware's own syntax, which is not checked: flags without a number (``M84 E``, ``G28 X``,
    stored as 0), quoted strings (``M862.3 P "MINI"``), text (``M486 AShape-Box``, ``M3 $0``,
    ``M115 U6.1.3+7898``); a repeated letter keeps its last value. After M117/M118 (and the file
    name codes) the rest of the line is text. A line whose first word is a name (Klipper's
    ``PRINT_START EXTRUDER=215``) is an extended command: no words. Two F words on a motion line:
    the last one counts, with the warning event EV_REPEATED_F (the line is still run).
    """
    n = buf.shape[0]
    ls = pos
    mask = 0
    nw = 0
    n_g = 0
    n_m = 0
    first_word = True
    lenient = False  # an M-code or a G-code that owns its words came first: its parameters follow
    moved = False  # a G0-G3 word was seen
    ev = 0
    ev_val = 0.0
    note = 0  # a warning that leaves the line runnable
    while pos < n:
        c = buf[pos]
        if c == 32:
            pos += 1
            continue
        # Every number goes through the one _parse_number below: it is inlined, and one copy
        # keeps the loop small.
        idx = (c & 0xDF) - 65  # a letter of either case: 0 to 25
        start = pos + 1
        if 0 <= idx < 26:
            if first_word and pos + 1 < n and _is_name_byte(buf[pos + 1]) and _keyword(buf, pos, n)[0] == 0.0:
                break  # an extended command (a macro name and its NAME=value arguments)
            if first_word and idx == 14 and pos + 1 < n and (buf[pos + 1] == 60 or 48 <= buf[pos + 1] <= 57):
                # o100 sub, o<loop> while [...]: control flow; O1000 alone is a program number
                q = pos + 1
                if buf[q] == 60:
                    while q < n and buf[q] != 62 and buf[q] != 10:
                        q += 1
                    q += 1
                while q < n and 48 <= buf[q] <= 57:
                    q += 1
                while q < n and (buf[q] == 32 or buf[q] == 9):
                    q += 1
                if q + 1 < n and _is_name_byte(buf[q]) and _is_name_byte(buf[q + 1]):
                    ev = EV_OWORD
                    break
        elif c == 10:
            break
        elif c == 9 or c == 13 or c == 37:  # tab, CR, '%'
            pos += 1
            continue
        elif c == 59:  # ';' comment to end of line
            break
        elif c == 40:  # '(' comment
            pos += 1
            while pos < n and buf[pos] != 41 and buf[pos] != 10:
                pos += 1
            if pos == n or buf[pos] == 10:
                ev = EV_UNTERMINATED_COMMENT
                break
            pos += 1
            continue
        elif c == 42:  # '*' checksum (RepRap)
            idx = _CHECKSUM
        elif c == 47 and first_word:  # '/' block delete marker: run the block
            pos += 1
            continue
        elif c == 95 and first_word:  # '_MACRO': an extended command
            break
        elif first_word and (48 <= c <= 57 or c == 45 or c == 43 or c == 46):
            # Bare leading numbers (the seed's two numeric columns) before the first word.
            idx = _BARE_NUMBER
            start = pos
        elif c == 35:  # '#': Beckhoff's #TRAFO ON/OFF (a keyword), else not G-code we read
            idx = _KEYWORD
        elif lenient:
            if c == 34:  # a quoted string parameter
                pos += 1
                while pos < n and buf[pos] != 34 and buf[pos] != 10:
                    pos += 1
                if pos < n and buf[pos] == 34:
                    pos += 1
                continue
            while pos < n and not _ends_token(buf[pos]):  # text of the code's own syntax
                pos += 1
            continue
        else:
            if 48 <= c <= 57 or c == 45 or c == 43 or c == 46:
                ev = EV_BARE_NUMBER
            else:
                ev = EV_BAD_CHAR
                ev_val = float(c)
            break
        value, nxt, ok = _parse_number(buf, start, n)
        if idx == _KEYWORD or (not ok and idx >= 0):
            # A letter without a number, or a '#', may begin a tool-centre-point keyword
            # (TRAORI, TRAFOOF, #TRAFO ON/OFF): it is stored as the G word of the same meaning
            # (G43.4, G49). Any other '#' (LinuxCNC parameters, ...) is not read.
            kw_value, kw_end = _keyword(buf, pos, n)
            if kw_value > 0.0:
                idx = _G
                value = kw_value
                nxt = kw_end
                ok = True
            elif idx == _KEYWORD:
                ev = EV_PARAMETER  # #<name> = value, #1=5: an assignment
                break
            if not ok:
                q = start
                while q < n and (buf[q] == 32 or buf[q] == 9):
                    q += 1
                if q < n and (buf[q] == 45 or buf[q] == 43):
                    q += 1
                    while q < n and (buf[q] == 32 or buf[q] == 9):
                        q += 1
                if q < n and (buf[q] == 35 or buf[q] == 91):
                    if (_PATH_LETTERS >> idx) & 1:
                        ev = EV_EXPRESSION_PATH
                        ev_val = float(idx)
                        break
                    note = EV_EXPRESSION
                    ev_val = float(idx)
                    pos = _skip_expression(buf, q, n)
                    first_word = False
                    continue
            if not ok and lenient:
                # A flag (M84 E, G28 X) or a text parameter (M486 AShape): to the token's end.
                q = pos + 1
                if q >= n or _ends_token(buf[q]) or buf[q] == 34:
                    if not (mask >> idx) & 1:
                        mask |= 1 << idx
                        w_letter[w + nw] = idx
                        w_value[w + nw] = 0.0
                        nw += 1
                while q < n and not _ends_token(buf[q]) and buf[q] != 34:
                    q += 1
                pos = q
                first_word = False
                continue
        if idx == _CHECKSUM:
            checksum = 0  # XOR of every byte before the '*'
            for q in range(ls, pos):
                checksum ^= buf[q]
            if ok and int(value) != checksum:
                ev = EV_CHECKSUM
                ev_val = value
            break
        if idx == _BARE_NUMBER:
            if not ok:
                ev = EV_BAD_CHAR
                ev_val = float(c)
                break
            pos = nxt
            continue
        if not ok:
            ev = EV_NO_NUMBER
        elif not np.isfinite(value):
            ev = EV_NONFINITE
        elif abs(value) > ABSURD_MM:
            ev = EV_ABSURD
        elif idx == _G:
            if n_g < _MAX_CODES:
                w_letter[w + nw] = idx
                w_value[w + nw] = value
                nw += 1
                n_g += 1
            g = int(round(value * 10.0))
            if g == 0 or g == 10 or g == 20 or g == 30:
                lenient = False
                moved = True
            elif n_g + n_m == 1 and not _checked_g(g):
                lenient = True
        elif idx == _M:
            if n_m < _MAX_CODES:
                w_letter[w + nw] = idx
                w_value[w + nw] = value
                nw += 1
                n_m += 1
            if not moved:
                lenient = True
            if _is_text_m(value):
                break
        elif (mask >> idx) & 1:
            if lenient or idx == _F:
                # the last value counts (firmware parameters; a generator's second F word)
                for q in range(w, w + nw):
                    if w_letter[q] == idx:
                        w_value[q] = value
                if not lenient:
                    note = EV_REPEATED_F
            else:
                ev = EV_DUPLICATE_WORD
        else:
            mask |= 1 << idx
            w_letter[w + nw] = idx
            w_value[w + nw] = value
            nw += 1
        if ev != 0:
            ev_val = float(idx)
            break
        pos = nxt
        first_word = False
    while pos < n and buf[pos] != 10:
        pos += 1
    if ev == 0 and note != 0:
        ev = note
    return ev, ev_val, mask, nw, pos


@njit(cache=True)
def _mode_only_g(g):
    """Whether G-code ``g`` (times ten) only sets a mode, leaving the line's axis words to the
    modal motion: cutter and tool-length compensation, machine and work coordinates (G53 G0 X0,
    G54 X1), path control, canned-cycle cancel and return modes."""
    return (400 <= g <= 431 or g == 530 or 540 <= g <= 593 or g == 610 or g == 611 or g == 640
            or g == 800 or g == 980 or g == 990)


@njit(cache=True)
def _checked_g(g):
    """Whether the words after G-code ``g`` (times ten) are G-code words, checked as such: the
    motion codes, the modes the interpreter follows and those beside modal motion, dwell, G92."""
    return (g <= 40 or 170 <= g <= 210 or 900 <= g <= 940 or g == 434 or g == 490
            or _mode_only_g(g))


@njit(cache=True)
def _rs274_m(m):
    """Whether M-code ``m`` is one of RS-274's (LinuxCNC, Grbl, Mach3), which may stand beside
    axis words that move in the modal motion: program stops, spindle and coolant, overrides,
    digital and analog outputs."""
    return 0 <= m <= 9 or m == 19 or m == 30 or 48 <= m <= 53 or 60 <= m <= 68


@njit(cache=True)
def _in_rules(rules, m):
    """Whether the dialect's rule table names M-code ``m`` (its laser codes are its own)."""
    for ri in range(rules.shape[0]):
        if rules[ri, 0] == m:
            return True
    return False


@njit(cache=True)
def _has(mask, letter):
    """Whether a line's letter mask has ``letter``."""
    return ((mask >> letter) & 1) != 0


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
def _word_or_param(key, mask, values, s_modal, line_params, lp0, lp1):
    """A rule condition's value on this line: a word (a missing S: the S in force), or a
    parenthesised parameter (key >= 26, from ``line_params`` rows lp0:lp1); NaN when absent."""
    if key < 26:
        if _has(mask, key):
            return values[key]
        return s_modal if key == _S else np.nan
    for i in range(lp0, lp1):
        if line_params[i, 1] == key:
            return line_params[i, 2]
    return np.nan


@njit(cache=True)
def _conditions_hold(rules, ri, mask, values, s_modal, line_params, lp0, lp1):
    """Whether rule ``ri``'s conditions (columns 4 on: key, operator, value) hold on this line."""
    for c in range(4, rules.shape[1], 3):
        key = int(rules[ri, c])
        if key < 0:
            break
        got = _word_or_param(key, mask, values, s_modal, line_params, lp0, lp1)
        if np.isnan(got):
            return False
        op = int(rules[ri, c + 1])
        want = rules[ri, c + 2]
        equal = abs(got - want) <= 1e-9
        if not ((op == 0 and equal) or (op == 1 and not equal) or (op == 2 and got > want)
                or (op == 3 and got >= want) or (op == 4 and got < want) or (op == 5 and got <= want)):
            return False
    return True


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


# The parallel tokenising loop sits in interpret itself: a cached function that calls a
# parallel one crashes when loaded from the cache (numba issue #8578).
@njit(cache=True, parallel=True)
def interpret(buf, rules, line_params, flags, strict, default_feed, rapid_feed, arc_abs_tol, arc_rel_tol,
              out_start, out_end, out_deposit, out_kind, out_feed, out_power, out_t0, out_t1,
              out_line, out_rotary, out_material, out_dwell, out_rot0, out_rot1, out_mode,
              arc_seg, arc_centre, arc_axis, arc_sweep, arc_r0, arc_r1, arc_len,
              ev_line, ev_code, ev_value, start_pos, plate_z, out_info):
    """Interpret the whole buffer. Returns (rows, arcs, events, events_dropped, lines, status,
    evidence, end_time).

    ``status`` is 0, or the event index that stopped a --strict run (or a program whose path
    hangs on what the reader cannot evaluate: EV_EXPRESSION_PATH, EV_OWORD).

    ``start_pos`` (3,): the position before the first line, NaN where unknown (then an axis is
    known from its first absolute word, G28 or G92 on). A probe (G31, G38.x) down in Z stops at
    ``plate_z`` (it touches the plate there), not at its far target: a G92 Z0 after it then zeroes
    Z on the plate, as on the machine. ``out_info`` (INFO_SIZE,) gets the counts named by the
    INFO_* constants.

    ``rules`` is a dialect's rule table (:meth:`dmdvox.toolpath.dialects.Dialect.rule_array`);
    ``line_params`` (k, 3) float64 rows (line, key, value), in line order, the parenthesised
    parameters that custom rules read (``M201 (SDC 37.8)``). ``out_power`` gets the S word in
    force, or the value of the power key of the last rule that matched (NaN before any).

    ``out_material`` gets each row's E advance that is material (filament mm): a retract opens
    a debt that the following positive advances repay first, so an unretract (a re-prime of
    the same length) delivers nothing. ``out_dwell`` gets the time the beam stood still while on
    just before the row (a dwell with the laser on, e.g. to start a melt pool): material
    collects there whatever the row itself does.

    Five-axis mode (``flags & FLAG_FIVE_AXIS``, a machine file given): a move of the rotary axes
    alone makes a row (of no length here), and every row records the rotary values at its start
    and end (``out_rot0``, ``out_rot1``, float64) and ``out_mode`` (MODE_* bits: tool-centre-point
    control, inverse time, rapid) for :mod:`dmdvox.toolpath.fiveaxis`, which turns the rows into
    the tip path and times them. Otherwise those three arrays may be empty and are not touched.
    Tool-centre-point control (G43.4/G49, M128/M129, TRAORI/TRAFOOF, #TRAFO ON/OFF) is state in
    every dialect.
    """
    use_e = (flags & 1) != 0
    s0_off = (flags & 2) != 0
    dwell_ms = (flags & 4) != 0
    auto_e = (flags & 8) != 0
    five_axis = (flags & FLAG_FIVE_AXIS) != 0
    # RepRap firmware (Marlin, RRF, Klipper) moves G0 at the modal F like G1; CNC controls rapid
    g0_at_feed = use_e
    n_rules = rules.shape[0]

    # One chunk's tokens (see the module docstring), reused from chunk to chunk.
    n = buf.shape[0]
    n_pieces = (n + _PIECE_BYTES - 1) // _PIECE_BYTES
    chunk_pieces = min(n_pieces, _CHUNK_PIECES)
    rec_event = np.empty(min(n, _CHUNK_PIECES * _PIECE_BYTES), np.uint8)
    rec_value = np.empty(rec_event.shape[0], np.float64)
    rec_mask = np.empty(rec_event.shape[0], np.uint32)
    rec_words = np.empty(rec_event.shape[0], np.uint8)
    w_letter = np.empty(chunk_pieces * _PIECE_WORDS, np.uint8)
    w_value = np.empty(w_letter.shape[0], np.float64)
    n_lines = np.empty(chunk_pieces, np.int64)

    values = np.zeros(26, np.float64)  # read only where the line's letter mask has the letter
    mcodes = np.zeros(_MAX_CODES, np.int64)

    pos = np.zeros(3, np.float64)  # machine position, mm
    known = np.zeros(3, np.bool_)
    for ax in range(3):
        if np.isfinite(start_pos[ax]):
            pos[ax] = start_pos[ax]
            known[ax] = True
    out_info[:] = 0
    offset = np.zeros(3, np.float64)  # G92: machine = program + offset
    rot = np.zeros(3, np.float64)
    rot_offset = np.zeros(3, np.float64)
    rot_start = np.zeros(3, np.float64)
    tcp = False  # tool-centre-point control: X Y Z are the tip in the workpiece frame
    target = np.zeros(3, np.float64)
    unit = 1.0
    relative = False
    arc_relative_centre = True
    plane = 2  # normal axis: G17 -> Z
    inverse_time = False
    motion = 1  # G1 until told otherwise (the seed files never say G0)
    feed = default_feed / 60.0
    power = np.nan
    s_modal = np.nan  # the S word in force
    lp = 0  # line_params rows of the line: lp to lp_end
    lp_end = 0
    laser = False
    spindle = False
    pending = 0  # M62/M63 waiting for the next motion: 1 on, 2 off
    e_pos = 0.0
    retract_debt = 0.0  # filament mm retracted and not yet primed back
    dwell_on = 0.0  # beam-on standstill since the last row, s
    # E mode as Marlin and Klipper keep it: M83 (or the printer's setting) makes E relative until
    # M82, whatever G90 says; G91 makes every axis relative, E too, until G90.
    e_said_relative = (flags & FLAG_E_RELATIVE_START) != 0
    e_relative = e_said_relative
    e_mode = use_e
    evidence = 0
    t = 0.0
    warned_unknown = False

    rows = 0
    arcs = 0
    n_ev = 0
    dropped = 0
    line_no = 0
    status = 0
    for first_piece in range(0, n_pieces, _CHUNK_PIECES):
        n_chunk = min(_CHUNK_PIECES, n_pieces - first_piece)
        # ---- tokenise the chunk's pieces in parallel ---------------------------------------------
        # Piece k's line records start at k * _PIECE_BYTES, its words at k * _PIECE_WORDS.
        for k in prange(n_chunk):
            lo = (first_piece + k) * _PIECE_BYTES
            hi = min(lo + _PIECE_BYTES, n)
            at = lo
            if at > 0 and buf[at - 1] != 10:  # the line under way belongs to the previous piece
                while at < hi and buf[at] != 10:
                    at += 1
                at += 1
            rec = k * _PIECE_BYTES
            word = k * _PIECE_WORDS
            while at < hi:
                line_ev, line_ev_val, line_mask, line_words, line_end = _tokenise_line(
                    buf, at, w_letter, w_value, word)
                rec_event[rec] = line_ev
                rec_value[rec] = line_ev_val
                rec_mask[rec] = line_mask
                rec_words[rec] = line_words
                rec += 1
                word += line_words
                at = line_end + 1
            n_lines[k] = rec - k * _PIECE_BYTES

        # ---- run the chunk's lines in order ----------------------------------------------------
        for k in range(n_chunk):
            w = k * _PIECE_WORDS
            for r in range(k * _PIECE_BYTES, k * _PIECE_BYTES + n_lines[k]):
                line_no += 1
                w0 = w
                w += rec_words[r]
                ev = rec_event[r]
                if ev == EV_REPEATED_F or ev == EV_EXPRESSION:
                    # the line is run (the last F; without the word whose value is an expression)
                    n_ev, dropped = _push(ev_line, ev_code, ev_value, n_ev, dropped, line_no, ev, rec_value[r])
                    if strict and ev == EV_EXPRESSION:
                        status = n_ev
                        break
                elif ev != 0:
                    # Every other tokeniser event leaves the line unrunnable (a checksum mismatch
                    # means a corrupted transmission): skip it, or stop a --strict run.
                    n_ev, dropped = _push(ev_line, ev_code, ev_value, n_ev, dropped, line_no, ev, rec_value[r])
                    if strict or ev == EV_EXPRESSION_PATH or ev == EV_OWORD:  # the path itself is unknown
                        status = n_ev
                        break
                    continue
                mask = np.int64(rec_mask[r])

                # ---- modal and non-motion G codes; the other words' values -----------------------
                move_code = -1
                probe = False
                consume = False  # a G-code whose axis words are its parameters (G10 L20, G29, G52)
                dwell = False
                set_g92 = False
                homing = False
                bad = 0
                bad_val = 0.0
                n_m = 0
                for q in range(w0, w):
                    letter = w_letter[q]
                    if letter == _M:
                        mcodes[n_m] = int(round(w_value[q]))
                        n_m += 1
                        continue
                    if letter != _G:
                        values[letter] = w_value[q]
                        continue
                    g = int(round(w_value[q] * 10.0))
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
                        e_relative = e_said_relative
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
                    elif g == 434:  # G43.4 (and TRAORI, #TRAFO ON): tool-centre-point control on
                        tcp = True
                    elif g == 490:  # G49 (and TRAFOOF, #TRAFO OFF): off
                        tcp = False
                    else:
                        bad = EV_UNKNOWN_G
                        bad_val = float(g)
                        if g == 310 or 382 <= g <= 385:
                            probe = True  # G31, G38.2-G38.5: a feed move that stops at contact
                        elif not _mode_only_g(g):
                            consume = True
                if bad != 0:
                    n_ev, dropped = _push(ev_line, ev_code, ev_value, n_ev, dropped, line_no, bad, bad_val)

                # Only G0-G3 (and probes) move the tool; the other codes own their words: a RepRap
                # M-code all of them (M201 X10000 is an acceleration limit), an RS-274 one
                # (M3, M8, M64 P1, the dialect's codes) leaves the axis words to the modal motion
                # (X5 M3 S100 moves) but not E (M68 E2 Q100: E names an output).
                word_mask = mask  # the line's own words, for the rules' conditions (M68 E=2 Q>0)
                m_line = n_m > 0 and move_code < 0 and not probe
                owned = consume and move_code < 0 and not probe
                if m_line and not owned:
                    for mi in range(n_m):
                        if e_mode or not (_rs274_m(mcodes[mi]) or _in_rules(rules, mcodes[mi])):
                            owned = True
                if owned:
                    mask &= ~(_XYZ | _ABC | _IJKR | 1 << _E | 1 << _F | 1 << _S | 1 << _T)
                elif m_line:
                    mask &= ~(_IJKR | 1 << _E)
                if n_m and not owned:
                    for mi in range(n_m):
                        if 66 <= mcodes[mi] <= 68:  # M66-M68 E: an analog channel, on motion lines too
                            mask &= ~(1 << _E)

                if _has(mask, _F) and not inverse_time:
                    if values[_F] < MIN_FEED:
                        n_ev, dropped = _push(ev_line, ev_code, ev_value, n_ev, dropped, line_no,
                                              EV_NEGATIVE_FEED, values[_F])
                        if strict:  # the feed would be changed: refuse
                            status = n_ev
                            break
                    else:
                        feed = values[_F] * unit / 60.0
                if _has(mask, _S):
                    power = values[_S]
                    s_modal = values[_S]
                if _has(mask, _T):
                    n_ev, dropped = _push(ev_line, ev_code, ev_value, n_ev, dropped, line_no, EV_UNKNOWN_T, values[_T])

                # ---- M codes through the dialect's rule table ------------------------------------
                if n_m:
                    while lp < line_params.shape[0] and line_params[lp, 0] < line_no:
                        lp += 1
                    lp_end = lp
                    while lp_end < line_params.shape[0] and line_params[lp_end, 0] == line_no:
                        lp_end += 1
                e_names_output = False  # LinuxCNC's M62-M68 name their output with E or P
                for mi in range(n_m):
                    m = mcodes[mi]
                    e_names_output |= 62 <= m <= 68
                    if m == 128 or m == 129:  # Heidenhain tool-centre-point control, any dialect
                        tcp = m == 128
                        continue
                    has_p = _has(mask, _P)
                    p_val = int(round(values[_P])) if has_p else -1
                    action = 0
                    for ri in range(n_rules):
                        if int(rules[ri, 0]) != m:
                            continue
                        rp = int(rules[ri, 1])
                        if ((rp == -2 or (rp == -1 and not has_p) or (rp >= 0 and has_p and rp == p_val))
                                and _conditions_hold(rules, ri, word_mask, values, s_modal, line_params,
                                                     lp, lp_end)):
                            action = int(rules[ri, 2])
                            power_key = int(rules[ri, 3])
                            if power_key >= 0:
                                power = _word_or_param(power_key, word_mask, values, s_modal, line_params, lp,
                                                       lp_end)
                            break
                    if action == 0:
                        n_ev, dropped = _push(ev_line, ev_code, ev_value, n_ev, dropped, line_no,
                                              EV_UNKNOWN_M, float(m))
                        continue
                    family = 0
                    if m == 64 or m == 65:
                        if has_p and (p_val == 8 or p_val == 9):
                            family = EVID_MELTIO
                        elif has_p:
                            family = EVID_LINUXCNC
                        else:
                            family = EVID_SEED
                    elif m == 62 or m == 63:
                        family = EVID_LINUXCNC
                    elif m == 101 or m == 102 or m == 103 or m == 108:
                        family = EVID_SEED
                    elif m == 3 or m == 4 or m == 5:
                        family = EVID_SPINDLE
                    if family and not (evidence & family):
                        evidence |= family
                        n_ev, dropped = _push(ev_line, ev_code, ev_value, n_ev, dropped, line_no, EV_EVIDENCE,
                                              m * 1000.0 + min(max(p_val, -1), 998) + 1)
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
                        e_said_relative = False
                        out_info[INFO_E_MODE_SAID] += 1
                    elif action == 8:
                        e_relative = True
                        e_said_relative = True
                        out_info[INFO_E_MODE_SAID] += 1

                if dwell:
                    wait = 0.0
                    if _has(mask, _P):
                        wait = values[_P] / 1000.0 if dwell_ms else values[_P]
                    elif _has(mask, _S):
                        wait = values[_S]
                    elif _has(mask, _X):
                        wait = values[_X]
                    if wait > LONG_DWELL_S:
                        n_ev, dropped = _push(ev_line, ev_code, ev_value, n_ev, dropped, line_no,
                                              EV_LONG_DWELL, wait)
                    if wait < 0.0:  # time cannot run backwards (LinuxCNC: an error)
                        n_ev, dropped = _push(ev_line, ev_code, ev_value, n_ev, dropped, line_no,
                                              EV_NEGATIVE_DWELL, wait)
                        if strict:
                            status = n_ev
                            break
                        continue
                    t += wait
                    if not e_mode and laser and (not s0_off or not spindle or s_modal > 0.0):
                        dwell_on += wait
                    continue

                if homing:
                    # G28: the axes named (all when none) go home, taken as machine zero. From a
                    # known place the tool travels there, and the trip takes time: PrusaSlicer's
                    # and Bambu's estimators time it as a move at the modal feed (a slicer's end
                    # `G28 X0` is seconds of a short program). From an unknown place it just arrives.
                    any_axis = (mask & _XYZ) != 0
                    home_known = known[0] and known[1] and known[2]
                    for ax in range(3):
                        target[ax] = pos[ax]
                        if not any_axis or _has(mask, _X + ax):
                            target[ax] = 0.0
                            known[ax] = True
                            offset[ax] = 0.0
                    if not home_known:
                        for ax in range(3):
                            pos[ax] = target[ax]
                        continue

                if set_g92:
                    for ax in range(3):
                        li = _X if ax == 0 else (_Y if ax == 1 else _Z)
                        if _has(mask, li):
                            offset[ax] = pos[ax] - values[li] * unit
                            known[ax] = True
                    for ax in range(3):
                        if _has(mask, _A + ax):
                            rot_offset[ax] = rot[ax] - values[_A + ax]
                    if _has(mask, _E):
                        e_pos = values[_E]
                    if (mask & (_XYZ | _ABC | 1 << _E)) == 0:
                        for ax in range(3):
                            offset[ax] = pos[ax]
                            known[ax] = True
                        e_pos = 0.0
                    continue

                if move_code >= 0:
                    motion = move_code
                line_motion = 1 if probe else motion
                if homing:
                    line_motion = 0

                has_xyz = (mask & _XYZ) != 0
                has_rot = (mask & _ABC) != 0
                has_e = _has(mask, _E) and not homing
                has_centre = (mask & _IJKR) != 0 and not homing
                if not (has_xyz or has_rot or has_e or homing) and not (line_motion >= 2 and has_centre):
                    continue

                # ---- target position -------------------------------------------------------------
                start_known = known[0] and known[1] and known[2]
                for ax in range(3):
                    li = _X if ax == 0 else (_Y if ax == 1 else _Z)
                    if homing:
                        continue  # set above
                    if _has(mask, li):
                        if relative:
                            target[ax] = pos[ax] + values[li] * unit
                        else:
                            target[ax] = values[li] * unit + offset[ax]
                            known[ax] = True
                    else:
                        target[ax] = pos[ax]
                if probe and target[2] < plate_z <= pos[2]:
                    target[2] = plate_z
                for ax in range(3):
                    rot_start[ax] = rot[ax]
                    if _has(mask, _A + ax):
                        if relative:
                            rot[ax] = rot[ax] + values[_A + ax]
                        else:
                            rot[ax] = values[_A + ax] + rot_offset[ax]

                extrudes = False
                e_delta = 0.0
                e_material = 0.0
                # G1 X5 M67 E2 Q25: the E is the analog output's number, not an extrusion
                if has_e and not e_names_output:
                    if auto_e:
                        e_mode = True
                        g0_at_feed = True
                        if not (evidence & EVID_E):
                            evidence |= EVID_E
                            n_ev, dropped = _push(ev_line, ev_code, ev_value, n_ev, dropped, line_no,
                                                  EV_EVIDENCE, -1.0)
                    if e_mode:
                        out_info[INFO_E_WORDS] += 1
                        e_delta = values[_E] if e_relative else values[_E] - e_pos
                        if not e_relative:
                            out_info[INFO_E_ABSOLUTE] += 1
                            if e_delta < 0.0:
                                out_info[INFO_E_FALLS] += 1
                            elif e_delta > 0.0:
                                out_info[INFO_E_RISES] += 1
                        e_pos = e_pos + values[_E] if e_relative else values[_E]
                        if e_delta < 0.0:
                            retract_debt -= e_delta
                            e_material = 0.0
                        else:
                            repaid = min(retract_debt, e_delta)
                            retract_debt -= repaid
                            e_material = e_delta - repaid
                        extrudes = e_material > 0.0

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

                is_arc = line_motion >= 2 and (has_xyz or has_centre)
                if e_mode:
                    deposit = extrudes and motion != 0 and not probe
                else:
                    beam = laser and (not s0_off or not spindle or s_modal > 0.0)
                    deposit = beam and line_motion != 0 and not probe
                if not start_known:
                    out_info[INFO_UNKNOWN_MOVES] += 1
                    if relative:
                        out_info[INFO_UNKNOWN_RELATIVE] += 1
                    if deposit:
                        out_info[INFO_UNKNOWN_DEPOSIT] += 1
                    # Positioning from an unknown place is normal; depositing from one loses material.
                    if deposit and not warned_unknown:
                        warned_unknown = True
                        n_ev, dropped = _push(ev_line, ev_code, ev_value, n_ev, dropped, line_no,
                                              EV_POSITION_UNKNOWN, 0.0)
                        if strict:  # material would be dropped: refuse
                            status = n_ev
                            break
                    for ax in range(3):
                        pos[ax] = target[ax]
                    continue

                # ---- geometry --------------------------------------------------------------------
                length = lin_len
                kind = 0 if line_motion == 0 else 1
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
                    if _has(mask, _R):
                        radius = values[_R] * unit
                        if chord <= 1e-12:
                            ok = False
                            r_err = -1.0
                        else:
                            half = 0.5 * chord
                            h2 = radius * radius - half * half
                            if h2 < 0.0:
                                if abs(radius) < half - max(arc_abs_tol, 1e-9):
                                    n_ev, dropped = _push(ev_line, ev_code, ev_value, n_ev, dropped, line_no,
                                                          EV_ARC_R_TOO_SMALL, radius)
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
                    elif _has(mask, i0) or _has(mask, i1):
                        v0 = values[i0] * unit if _has(mask, i0) else 0.0
                        v1 = values[i1] * unit if _has(mask, i1) else 0.0
                        if arc_relative_centre:
                            c0 = s0 + v0
                            c1 = s1 + v1
                        else:
                            c0 = (v0 + offset[a0]) if _has(mask, i0) else s0
                            c1 = (v1 + offset[a1]) if _has(mask, i1) else s1
                    else:
                        ok = False
                    if not ok:
                        n_ev, dropped = _push(ev_line, ev_code, ev_value, n_ev, dropped, line_no,
                                              EV_ARC_FULL_CIRCLE_R if r_err < 0.0 else EV_ARC_NO_CENTRE, 0.0)
                        if strict:
                            status = n_ev
                            break
                        continue
                    r0 = np.sqrt((s0 - c0) ** 2 + (s1 - c1) ** 2)
                    r1 = np.sqrt((e0 - c0) ** 2 + (e1 - c1) ** 2)
                    diff = abs(r1 - r0)
                    if diff > 0.5 or (diff > arc_abs_tol and diff > arc_rel_tol * r0):
                        n_ev, dropped = _push(ev_line, ev_code, ev_value, n_ev, dropped, line_no,
                                              EV_ARC_RADIUS_MISMATCH, diff)
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
                    if _has(mask, _P):
                        turns = int(round(values[_P]))
                        if turns < 1:
                            n_ev, dropped = _push(ev_line, ev_code, ev_value, n_ev, dropped, line_no,
                                                  EV_BAD_P, values[_P])
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

                turned = five_axis and (rot[0] != rot_start[0] or rot[1] != rot_start[1]
                                        or rot[2] != rot_start[2])
                if length <= 1e-12 and not is_arc and not turned:
                    if has_e and e_mode and e_delta != 0.0:
                        t += abs(e_delta) / feed  # retract / unretract: time without motion
                    for ax in range(3):
                        pos[ax] = target[ax]
                    continue

                mode = MODE_TCP if tcp else 0
                if line_motion == 0 and not g0_at_feed:
                    mode |= MODE_RAPID
                    speed = rapid_feed / 60.0
                    duration = length / speed
                elif inverse_time:
                    if not _has(mask, _F) or values[_F] < MIN_FEED:
                        n_ev, dropped = _push(ev_line, ev_code, ev_value, n_ev, dropped, line_no,
                                              EV_INVERSE_TIME_NO_F, 0.0)
                        if strict:
                            status = n_ev
                            break
                        for ax in range(3):
                            pos[ax] = target[ax]
                        continue
                    duration = 60.0 / values[_F]
                    speed = length / duration if duration > 0.0 else 0.0
                    mode |= MODE_INVERSE_TIME
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
                if five_axis:
                    for ax in range(3):
                        out_rot0[rows, ax] = rot_start[ax]
                        out_rot1[rows, ax] = rot[ax]
                    out_mode[rows] = mode
                out_deposit[rows] = deposit
                out_kind[rows] = kind
                out_feed[rows] = speed
                out_power[rows] = power
                out_t0[rows] = t
                t += duration
                out_t1[rows] = t
                out_line[rows] = line_no
                out_material[rows] = e_material if deposit else 0.0
                out_dwell[rows] = dwell_on
                dwell_on = 0.0
                rows += 1
            if status:
                break
        if status:
            break
    for ax in range(3):
        if known[ax]:
            out_info[INFO_AXES_KNOWN] |= 1 << ax
    return rows, arcs, n_ev, dropped, line_no, status, evidence, t


@njit(cache=True)
def layer_runs(start, deposit, resolution, run_of_row):
    """Group deposit rows into runs of consecutive rows with one layer key (start Z in
    ``resolution`` steps, rounded half to even like numpy) and return the runs' keys.
    ``run_of_row`` gets each deposit row's run and each travel row the next deposit row's (past
    the last one, the last one's).

    Layers come in long runs, so sorting the runs' keys instead of every row's is cheap.
    """
    n = start.shape[0]
    run_key = np.empty(n, np.int64)
    runs = 0
    for i in range(n):
        if deposit[i]:
            key = np.int64(np.rint(start[i, 2] / resolution))
            if runs == 0 or key != run_key[runs - 1]:
                run_key[runs] = key
                runs += 1
            run_of_row[i] = runs - 1
    following = runs - 1
    for i in range(n - 1, -1, -1):
        if deposit[i]:
            following = run_of_row[i]
        else:
            run_of_row[i] = following
    return run_key[:runs]
