"""What a program tells its firmware about motion: machine limits, retract-only moves, stops.

The interpreter kernel times every move at its programmed feed and treats limit codes as
unknown; :func:`scan_motion_codes` reads, from the program's text, what the motion planner
(:mod:`dmdvox.process.planner`) needs to run the program as the firmware would:

* **limits**, in force from their line on (the firmware applies them in program order):
  ``M201`` (max acceleration per axis, mm/s^2), ``M203`` (max feed per axis: mm/s in Marlin and
  Prusa firmware, mm/min under ``; gcode_flavor = reprapfirmware``), ``M204`` (``P`` print,
  ``R`` retract, ``T`` travel acceleration; ``S`` print and travel, Marlin's legacy form),
  ``M205`` (``X Y Z E`` classic jerk, ``J`` junction deviation), Klipper's
  ``SET_VELOCITY_LIMIT VELOCITY= ACCEL= ACCEL_TO_DECEL= SQUARE_CORNER_VELOCITY=
  MINIMUM_CRUISE_RATIO=``; and, before the first code, the slicer's own record of the machine:
  PrusaSlicer's ``; machine_max_*`` settings (the first, "normal mode" value of each) and
  Cura's ``;SETTING_3`` block (``machine_max_*``, ``machine_acceleration``). Marlin codes are
  read only in E-driven (reprap) programs: elsewhere M201-M205 mean other things (a DED cell's
  ``M201 (SDC 40)`` is a laser power);
* **retract-only moves** (a ``G1`` with only E and F words): their filament travel and feed, so
  that the planner runs them with the retract acceleration instead of at constant feed;
* **stop codes**: the lines of codes after which the dialect's controller drains its motion
  queue (see :data:`STOP_CODES`).

Everything is keyed by the program's physical line, so that it follows the rows through any
selection (``toolpath.line``).
"""

from __future__ import annotations

import re
from dataclasses import dataclass

import numpy as np

# Columns of ProgramMotion.values (NaN: the program does not set it from that line on).
ACCEL_PRINT, ACCEL_RETRACT, ACCEL_TRAVEL = 0, 1, 2
AMAX_X = 3  # .. AMAX_E = 6, per-axis max acceleration X Y Z E (mm/s^2)
VMAX_X = 7  # .. VMAX_E = 10, per-axis max feed X Y Z E (mm/s)
JERK_X = 11  # .. JERK_E = 14, classic jerk X Y Z E (mm/s)
JD, SCV, ACCEL_TO_DECEL, VELOCITY, CRUISE_RATIO = 15, 16, 17, 18, 19
N_VALUES = 20
VALUE_NAMES = ("accel_print", "accel_retract", "accel_travel", "max_accel_x", "max_accel_y", "max_accel_z",
               "max_accel_e", "max_feed_x", "max_feed_y", "max_feed_z", "max_feed_e", "jerk_x", "jerk_y", "jerk_z",
               "jerk_e", "junction_deviation", "square_corner_velocity", "accel_to_decel", "velocity",
               "minimum_cruise_ratio")

# Codes after which the controller stops the tool (drains its queue) before going on, per
# dialect. LinuxCNC: M3/M4/M5 and the immediate outputs M64/M65 break blending (its manual:
# "they are not synchronized with movement, and they will break blending"); M62/M63 switch
# with the next motion and do not. The seed's Fadal and Meltio's cell run M-functions
# between blocks, after the motion stops. Marlin/RepRap: M400 waits for the moves to finish;
# switching the extrusion on or off is the E axis's motion, no stop. Grbl in laser mode runs
# through M3/M4/M5 (its laser-mode documentation), and a dwell stops every dialect (the gap).
STOP_CODES = {
    "linuxcnc": ("M3", "M4", "M5", "M64", "M65"),
    "seed": ("M64", "M65", "M101", "M102", "M103", "M108"),
    "meltio": ("M64", "M65"),
    "reprap": ("M400",),
    "grbl": (),
}

_HEAD_TAIL = 1 << 18  # slicers write their settings in the first or last few hundred kB
_NUMBER = rb"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?"
_LIMIT_CODE = re.compile(rb"^[ \t]*(?:N\d+[ \t]*)?(M20[1345]|SET_VELOCITY_LIMIT)(?![0-9])([^;\n\r(]*)",
                         re.MULTILINE | re.IGNORECASE)
_WORD = re.compile(rb"([A-Z])[ \t]*(" + _NUMBER + rb")", re.IGNORECASE)
_KLIPPER_PARAM = re.compile(rb"([A-Z_]+)[ \t]*=[ \t]*(" + _NUMBER + rb")", re.IGNORECASE)
_PRUSA_SETTING = re.compile(rb"^;[ \t]*(machine_max_(?:acceleration|feedrate|jerk)_[a-z]+|gcode_flavor)[ \t]*="
                            rb"[ \t]*([^\r\n]*)", re.MULTILINE)
_CURA_SETTINGS = re.compile(rb"^;SETTING_3 ([^\r\n]*)", re.MULTILINE)
_CURA_SETTING = re.compile(rb"(machine_max_(?:acceleration|feedrate)_[xyze]|machine_max_jerk_(?:xy|z|e)"
                           rb"|machine_acceleration)[ \t]*=[ \t]*(" + _NUMBER + rb")")
_E_ONLY = re.compile(rb"^[ \t]*(?:N\d+[ \t]*)?G0*[01](?![0-9.])((?:[ \t]*[EF][ \t]*" + _NUMBER + rb")+)[ \t]*"
                     rb"(?:[;(*][^\r\n]*)?\r?$", re.MULTILINE | re.IGNORECASE)
_LINE_WORDS = re.compile(rb"^[ \t]*(?:N\d+[ \t]*)?([GM])0*(\d+)(?![0-9.])([^;\r\n(]*)", re.IGNORECASE)
_KLIPPER_FLAVOR = re.compile(rb"^;[ \t]*gcode_flavor[ \t]*=[ \t]*klipper", re.MULTILINE | re.IGNORECASE)

_PRUSA_KEYS = {b"machine_max_acceleration_extruding": ACCEL_PRINT, b"machine_max_acceleration_retracting": ACCEL_RETRACT,
               b"machine_max_acceleration_travel": ACCEL_TRAVEL}
for _k, _axis in enumerate(b"xyze"):
    _a = bytes([_axis])
    _PRUSA_KEYS[b"machine_max_acceleration_" + _a] = AMAX_X + _k
    _PRUSA_KEYS[b"machine_max_feedrate_" + _a] = VMAX_X + _k
    _PRUSA_KEYS[b"machine_max_jerk_" + _a] = JERK_X + _k
_CURA_KEYS = {b"machine_acceleration": (ACCEL_PRINT, ACCEL_TRAVEL, ACCEL_RETRACT), b"machine_max_jerk_xy": (JERK_X, JERK_X + 1),
              b"machine_max_jerk_z": (JERK_X + 2,), b"machine_max_jerk_e": (JERK_X + 3,)}
for _k, _axis in enumerate(b"xyze"):
    _a = bytes([_axis])
    _CURA_KEYS[b"machine_max_acceleration_" + _a] = (AMAX_X + _k,)
    _CURA_KEYS[b"machine_max_feedrate_" + _a] = (VMAX_X + _k,)
_AXES = b"XYZE"


@dataclass(frozen=True, eq=False)
class ProgramMotion:
    """The program's own motion settings, each in force from its line on, and its retract-only
    moves and stop codes (see the module docstring)."""

    line: np.ndarray  # (m,) int64 first line each row of ``values`` is in force (0: the whole program)
    values: np.ndarray  # (m, N_VALUES) float64 the settings in force from that line (NaN: not set)
    sources: dict  # value name -> where the program set it first ("M201 line 12", "; machine_max_...")
    klipper: bool  # the program talks to Klipper (SET_VELOCITY_LIMIT, or the slicer says so)
    e_line: np.ndarray  # (k,) int64 lines of the retract-only moves the planner runs
    e_delta: np.ndarray  # (k,) float64 their filament travel (mm, signed)
    e_feed: np.ndarray  # (k,) float64 their feed (mm/s)
    stop_line: np.ndarray  # (s,) int64 lines of codes that stop the motion

    @staticmethod
    def empty() -> "ProgramMotion":
        i, f = np.zeros(0, np.int64), np.zeros(0, np.float64)
        return ProgramMotion(np.zeros(1, np.int64), np.full((1, N_VALUES), np.nan), {}, False, i, f, f.copy(), i.copy())

    def values_at(self, lines: np.ndarray) -> np.ndarray:
        """Index into ``values`` of the settings in force at each of ``lines``."""
        return np.maximum(np.searchsorted(self.line, lines, side="right") - 1, 0)


def _number(text: bytes) -> float:
    try:
        return float(text)
    except ValueError:
        return float("nan")


def _line_of(newlines: np.ndarray, offsets) -> np.ndarray:
    return np.searchsorted(newlines, np.asarray(offsets, np.int64)) + 1


def _settings_block(buf: np.ndarray) -> tuple[dict[int, float], dict[int, str], bool]:
    """The slicers' record of the machine limits (PrusaSlicer's settings, Cura's SETTING_3)."""
    values: dict[int, float] = {}
    sources: dict[int, str] = {}
    mm_min = False
    n = buf.shape[0]
    parts = [memoryview(buf[:_HEAD_TAIL])]
    if n > _HEAD_TAIL:
        parts.append(memoryview(buf[max(_HEAD_TAIL, n - _HEAD_TAIL):]))
    for part in parts:
        for match in _PRUSA_SETTING.finditer(part):
            key, text = match.group(1), match.group(2)
            if key == b"gcode_flavor":
                mm_min = mm_min or text.strip().lower().startswith(b"reprapfirmware")
                continue
            column = _PRUSA_KEYS.get(key)
            value = _number(text.split(b",")[0])  # "normal mode, stealth mode": the first
            if column is not None and np.isfinite(value) and column not in values:
                values[column] = value
                sources[column] = f"; {key.decode()}"
        # Cura cuts its settings into ;SETTING_3 lines of a fixed width, words split across them
        joined = b"".join(block.group(1) for block in _CURA_SETTINGS.finditer(part))
        if joined:
            for match in _CURA_SETTING.finditer(joined):
                value = _number(match.group(2))
                for column in _CURA_KEYS[match.group(1)]:
                    if np.isfinite(value) and column not in values:
                        values[column] = value
                        sources[column] = f";SETTING_3 {match.group(1).decode()}"
    return values, sources, mm_min


def _limit_codes(buf: np.ndarray, newlines: np.ndarray, marlin: bool, mm_min: bool):
    """(line, {column: value}) of every limit code, in program order."""
    out = []
    for match in _LIMIT_CODE.finditer(memoryview(buf)):
        code = match.group(1).upper()
        body = match.group(2)
        changes: dict[int, float] = {}
        if code == b"SET_VELOCITY_LIMIT":
            names = {b"VELOCITY": VELOCITY, b"ACCEL": ACCEL_PRINT, b"ACCEL_TO_DECEL": ACCEL_TO_DECEL,
                     b"SQUARE_CORNER_VELOCITY": SCV, b"MINIMUM_CRUISE_RATIO": CRUISE_RATIO}
            for key, text in _KLIPPER_PARAM.findall(body):
                column = names.get(key.upper())
                if column is not None:
                    changes[column] = _number(text)
            if ACCEL_PRINT in changes:
                changes[ACCEL_TRAVEL] = changes[ACCEL_PRINT]
        elif marlin:
            words = {letter.upper(): _number(text) for letter, text in _WORD.findall(body)}
            if code == b"M201":
                for k, axis in enumerate(_AXES):
                    if bytes([axis]) in words:
                        changes[AMAX_X + k] = words[bytes([axis])]
            elif code == b"M203":
                scale = 1.0 / 60.0 if mm_min else 1.0
                for k, axis in enumerate(_AXES):
                    if bytes([axis]) in words:
                        changes[VMAX_X + k] = words[bytes([axis])] * scale
            elif code == b"M204":
                if b"S" in words:
                    changes[ACCEL_PRINT] = changes[ACCEL_TRAVEL] = words[b"S"]
                for letter, column in ((b"P", ACCEL_PRINT), (b"R", ACCEL_RETRACT), (b"T", ACCEL_TRAVEL)):
                    if letter in words:
                        changes[column] = words[letter]
            else:  # M205
                for k, axis in enumerate(_AXES):
                    if bytes([axis]) in words:
                        changes[JERK_X + k] = words[bytes([axis])]
                if b"J" in words:
                    changes[JD] = words[b"J"]
        # zero or negative limits mean nothing a planner can run (J0 and a cruise ratio of 0 do)
        changes = {c: v for c, v in changes.items() if np.isfinite(v) and (v > 0.0 or (v == 0.0 and c in (JD, CRUISE_RATIO)))}
        if changes:
            line = int(_line_of(newlines, [match.start()])[0])
            out.append((line, changes, code.decode()))
    return out


def _gap_e_moves(buf: np.ndarray, line_start: np.ndarray, lines: range, e_relative: bool, e_pos: float | None,
                 feed: float):
    """The retract-only moves on ``lines`` (a gap between two rows): [line, delta, feed] each,
    delta None where absolute E has no known position yet; and whether a dwell or a move the
    planner cannot run is among them. E modes and G92 E are followed as the interpreter does."""
    moves = []
    other = False
    for ln in lines:
        match = _LINE_WORDS.match(bytes(buf[line_start[ln - 1]:line_start[ln]]))
        if match is None:
            continue
        letter, number = match.group(1).upper(), int(match.group(2))
        words = {w.upper(): _number(v) for w, v in _WORD.findall(match.group(3))}
        if letter == b"G" and number in (0, 1):
            if set(words) - {b"E", b"F"}:
                other = True  # a zero-length move with other words: leave the gap as the reader timed it
                continue
            if words.get(b"F", 0.0) > 0.0:
                feed = words[b"F"] / 60.0
            if b"E" in words:
                e = words[b"E"]
                delta = e if e_relative else (None if e_pos is None else e - e_pos)
                if e_relative:
                    e_pos = None if e_pos is None else e_pos + e
                else:
                    e_pos = e
                if delta != 0.0:
                    moves.append([ln, delta, feed])
        elif letter == b"G" and number == 92:
            e_pos = words.get(b"E", 0.0 if not words else e_pos)
        elif (letter, number) in ((b"G", 90), (b"M", 82)):
            e_relative = False
        elif (letter, number) in ((b"G", 91), (b"M", 83)):
            e_relative = True
        elif letter == b"G" and number == 4:
            other = True
    if sum(m[1] is None for m in moves) > 1:
        other = True
    return moves, other


def _row_e_word(buf: np.ndarray, line_start: np.ndarray, line: int) -> float | None:
    """The E word on a row's own line (its end position under absolute E), if any."""
    match = _LINE_WORDS.match(bytes(buf[line_start[line - 1]:line_start[line]]))
    if match is None:
        return None
    e_words = [_number(v) for w, v in _WORD.findall(match.group(3)) if w.upper() == b"E"]
    return e_words[-1] if e_words else None


def _e_moves(buf: np.ndarray, newlines: np.ndarray, row_line: np.ndarray, t_start: np.ndarray, t_end: np.ndarray,
             deposit: np.ndarray, feed: np.ndarray):
    """The retract-only moves of an E-driven program in the gaps between rows that hold nothing
    else (no dwell): each gap's E-only moves' travel over their feeds is the gap, as the reader
    timed it, or the gap is left alone."""
    found = [m.start() for m in _E_ONLY.finditer(memoryview(buf))]
    n = row_line.shape[0]
    if not found or n < 2:
        return np.zeros(0, np.int64), np.zeros(0), np.zeros(0)
    e_lines = np.unique(_line_of(newlines, found))
    line_start = np.concatenate([[0], newlines + 1, [buf.shape[0]]]).astype(np.int64)
    mode_line, mode_rel = [], []
    for match in re.finditer(rb"^[ \t]*(?:N\d+[ \t]*)?(M8[23]|G9[01])(?![0-9.])", memoryview(buf),
                             re.MULTILINE | re.IGNORECASE):
        mode_line.append(int(_line_of(newlines, [match.start()])[0]))
        mode_rel.append(match.group(1).upper() in (b"M83", b"G91"))
    mode_line = np.array(mode_line, np.int64)
    gap_of = np.searchsorted(row_line, e_lines, side="right")  # the row each move comes before
    out_line, out_delta, out_feed = [], [], []
    for k in np.unique(gap_of):
        if k == 0 or k >= n:
            continue  # before the first row or after the last: the planner keeps that time as it is
        prev = k - 1
        first, last = int(row_line[prev]) + 1, int(row_line[k]) - 1
        if last < first:
            continue
        m = int(np.searchsorted(mode_line, first, side="right")) - 1
        e_relative = bool(mode_rel[m]) if m >= 0 else False
        e_pos = None if e_relative else _row_e_word(buf, line_start, first - 1)
        moves, other = _gap_e_moves(buf, line_start, range(first, last + 1), e_relative, e_pos, float(feed[prev]))
        if other or not moves:
            continue
        gap = float(t_start[k] - t_end[prev])
        known = sum(abs(d) / f for _, d, f in moves if d is not None)
        for move in moves:
            if move[1] is None:
                # the one move whose start is unknown: its travel is the rest of the gap, a
                # retract after a deposit move, a prime after a travel
                move[1] = (gap - known) * move[2] * (-1.0 if deposit[prev] else 1.0)
        total = sum(abs(d) / f for _, d, f in moves)
        if abs(total - gap) > 1e-6 * max(1.0, gap):
            continue  # the gap holds more than these moves: keep it as the reader timed it
        for ln, d, f in moves:
            out_line.append(ln)
            out_delta.append(d)
            out_feed.append(f)
    return np.array(out_line, np.int64), np.array(out_delta, np.float64), np.array(out_feed, np.float64)


def scan_motion_codes(buf: np.ndarray, dialect: str, row_line: np.ndarray, t_start: np.ndarray,
                      t_end: np.ndarray, deposit: np.ndarray, feed: np.ndarray) -> ProgramMotion:
    """The program's limits, retract-only moves and stop codes (see the module docstring);
    ``dialect`` is the detected one, the rows' arrays the reader's."""
    newlines = np.flatnonzero(buf == 10)
    marlin = dialect == "reprap"
    base, base_sources, mm_min = _settings_block(buf) if marlin else ({}, {}, False)
    codes = _limit_codes(buf, newlines, marlin, mm_min)
    klipper = bool(_KLIPPER_FLAVOR.search(memoryview(buf[:_HEAD_TAIL]))) or any(c[2] == "SET_VELOCITY_LIMIT"
                                                                               for c in codes)
    lines = [0]
    row = np.full(N_VALUES, np.nan)
    for column, value in base.items():
        row[column] = value
    table = [row.copy()]
    sources = {VALUE_NAMES[c]: s for c, s in base_sources.items()}
    for line, changes, code in codes:
        for column, value in changes.items():
            row[column] = value
            sources.setdefault(VALUE_NAMES[column], f"{code} line {line}")
        if line == lines[-1]:
            table[-1] = row.copy()
        else:
            lines.append(line)
            table.append(row.copy())
    if marlin:
        e_line, e_delta, e_feed = _e_moves(buf, newlines, row_line, t_start, t_end, deposit, feed)
    else:
        e_line, e_delta, e_feed = np.zeros(0, np.int64), np.zeros(0), np.zeros(0)
    stops = STOP_CODES.get(dialect, ())
    stop_line = np.zeros(0, np.int64)
    if stops:
        numbers = b"|".join(code[1:].encode() for code in stops)
        # the code in a block's words, not in its comment
        pattern = re.compile(rb"^[^;(\r\n]*?(?<![A-Z0-9.])M0*(?:" + numbers + rb")(?![0-9.])", re.MULTILINE | re.IGNORECASE)
        offsets = [m.start() for m in pattern.finditer(memoryview(buf))]
        if offsets:
            stop_line = np.unique(_line_of(newlines, offsets)).astype(np.int64)
    return ProgramMotion(np.array(lines, np.int64), np.array(table, np.float64), sources, klipper, e_line, e_delta,
                         e_feed, stop_line)
