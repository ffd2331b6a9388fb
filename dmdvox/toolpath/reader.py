"""Read a G-code file into a :class:`~dmdvox.toolpath.model.Toolpath`."""

from __future__ import annotations

import gzip
import mmap
import os
import re
import zlib
from collections import Counter
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from ..errors import DmdvoxError, GcodeError, InputFileError
from .kinematics import NO_MACHINE, Machine, load_machine
from . import gcode_kernel as K
from .dialects import (DEFAULT_FEED_MM_MIN, DIALECTS, FLAG_DWELL_P_MS, FLAG_Z_TOP, PARAM_KEY_BASE,
                       RAPID_FEED_MM_MIN, CustomDialect, get_dialect, with_dwell_unit)
from .fiveaxis import DEFAULT_AXIS_STEP_DEG, DEFAULT_TIP_CHORD_MM, tip_rows
from .model import NO_FEATURE, RAPID, ArcTable, Toolpath
from .motion_codes import scan_motion_codes

# LinuxCNC's arc end-point tolerances (mm): radii may differ by 0.005 mm and 0.1 %.
ARC_ABS_TOL_MM = 0.005
ARC_REL_TOL = 0.001
LAYER_Z_RESOLUTION_MM = 1e-3
MAX_EVENTS = 1 << 18
MAX_WARNINGS_LISTED = 200
MAX_GUNZIP_BYTES = 1 << 30  # a .gcode.gz is decompressed in memory
_GZIP_MAGIC = b"\x1f\x8b"

_LETTERS = [chr(65 + i) for i in range(26)]
_TCP_REMAPS = (428.0, 429.0)  # LinuxCNC's switchkins remaps (configs/sim/.../remap_subs)
_NOT_SUPPORTED = "parameters and expressions are not supported (LinuxCNC #<name>, #1, [...], o-words)"
# events said once for the file, not per line: (codes, what the one line says)
_SAID_ONCE = (((K.EV_REPEATED_F,), None),
              ((K.EV_PARAMETER, K.EV_EXPRESSION), f"{_NOT_SUPPORTED}: assignments skipped, words whose value is one "
                                                  "left out (an F: the previous feed kept)"))


def _describe(code: int, value: float) -> str:
    if code == K.EV_BAD_CHAR:
        return f"unexpected character {chr(int(value))!r}" if 32 <= value < 127 else f"unexpected byte 0x{int(value):02x} (binary data?)"
    if code == K.EV_NO_NUMBER:
        return f"word {_LETTERS[int(value)]} has no number"
    if code == K.EV_DUPLICATE_WORD:
        return f"word {_LETTERS[int(value)]} appears twice"
    if code == K.EV_BARE_NUMBER:
        return "number without a letter after the first word"
    if code == K.EV_NONFINITE:
        return f"word {_LETTERS[int(value)]} is not a finite number"
    if code == K.EV_ABSURD:
        return f"word {_LETTERS[int(value)]} is beyond {K.ABSURD_MM:g} (corrupt number?)"
    if code == K.EV_ARC_NO_CENTRE:
        return "arc without a centre (give I/J/K offsets in the arc plane, or R)"
    if code == K.EV_ARC_FULL_CIRCLE_R:
        return "R-form arc whose end equals its start: a full circle needs I/J/K"
    if code == K.EV_INVERSE_TIME_NO_F:
        return f"G93 inverse-time move without a positive F word (at least {K.MIN_FEED:g})"
    if code == K.EV_BAD_P:
        return f"arc P (turns) must be a positive integer, got {value:g}"
    if code == K.EV_NEGATIVE_DWELL:
        return f"dwell of {value:g} s is negative; line skipped"
    if code == K.EV_CHECKSUM:
        return f"checksum *{int(value)} does not match the line; line skipped"
    if code == K.EV_ARC_RADIUS_MISMATCH:
        return f"arc start and end radii differ by {value:.4g} mm (LinuxCNC tolerance 0.005 mm and 0.1 %)"
    if code == K.EV_ARC_R_TOO_SMALL:
        return f"arc radius R {value:g} is smaller than half the chord; drawn as a half circle"
    if code == K.EV_UNTERMINATED_COMMENT:
        return "comment '(' without ')'"
    if code == K.EV_POSITION_UNKNOWN:
        return "deposit move from an unknown position (no earlier absolute X, Y and Z, G28 or G92); not recorded"
    if code == K.EV_PARAMETER:
        return f"{_NOT_SUPPORTED}: a parameter assignment, skipped"
    if code == K.EV_EXPRESSION:
        return f"{_NOT_SUPPORTED}: the {_LETTERS[int(value)]} word's value is one, left out (an F: the previous feed kept)"
    if code == K.EV_EXPRESSION_PATH:
        return (f"{_NOT_SUPPORTED}: the {_LETTERS[int(value)]} word's value is one, and it decides the path or the "
                "material; dmdvox cannot evaluate it: give the program with its values written out (a post-processor "
                "without variables)")
    if code == K.EV_OWORD:
        return (f"{_NOT_SUPPORTED}: o-word control flow (subroutines, loops, conditions) decides which moves run; "
                "dmdvox cannot follow it: give the program with its moves written out (a post-processor without "
                "subroutines)")
    if code == K.EV_REPEATED_F:
        return "two F words on one line: the last one is the feed"
    if code == K.EV_NEGATIVE_FEED:
        if value > 0:
            return f"feed F{value:g} is below {K.MIN_FEED:g} (corrupt number?); previous feed kept"
        return f"feed F{value:g} is not positive; previous feed kept"
    return f"event {code}"


def _unknown_name(code: int, value: float) -> str:
    if code == K.EV_UNKNOWN_G:
        tenth = int(value)
        whole, decimal = divmod(abs(tenth), 10)
        return f"G{'-' if tenth < 0 else ''}{whole}" + (f".{decimal}" if decimal else "")
    if code == K.EV_UNKNOWN_M:
        return f"M{int(value)}"
    if code == K.EV_UNKNOWN_T:
        return "T"
    return _LETTERS[int(value)]


def _load(path: Path) -> np.ndarray:
    try:
        size = path.stat().st_size
        if size == 0:
            raise InputFileError(f"{path}: empty file; give a G-code program")
        with path.open("rb") as fh:
            if fh.read(2) == _GZIP_MAGIC:
                buf = _gunzip(path, fh)
                size = buf.shape[0]
            else:
                buf = np.frombuffer(mmap.mmap(fh.fileno(), 0, access=mmap.ACCESS_READ), dtype=np.uint8)
    except FileNotFoundError as exc:
        raise InputFileError(f"{path}: no such file") from exc
    except IsADirectoryError as exc:
        raise InputFileError(f"{path}: is a folder, not a G-code file") from exc
    except PermissionError as exc:
        raise InputFileError(f"{path}: not readable (permission denied)") from exc
    if size == 0:
        raise InputFileError(f"{path}: empty file (nothing inside the gzip data); give a G-code program")
    head = buf[: 1 << 16]
    controls = np.count_nonzero((head < 9) | ((head > 13) & (head < 32)))
    if np.count_nonzero(head == 0) or (controls > 16 and controls > len(head) // 20):
        raise InputFileError(f"{path}: binary data, not a G-code text file")
    if not np.any((head > 32) & (head < 127)) and size <= len(head):
        raise InputFileError(f"{path}: empty file (only white space); give a G-code program")
    return buf


def _gunzip(path: Path, fh) -> np.ndarray:
    """A gzip-compressed program (``.gcode.gz``) as its text's bytes, refused above
    ``MAX_GUNZIP_BYTES`` once decompressed (a gzip bomb, or a program better given plain: a plain
    file is mapped, not held in memory)."""
    fh.seek(0)
    data = bytearray()
    try:
        with gzip.GzipFile(fileobj=fh, mode="rb") as stream:
            while chunk := stream.read(1 << 22):
                data += chunk
                if len(data) > MAX_GUNZIP_BYTES:
                    raise InputFileError(
                        f"{path}: decompresses to more than {MAX_GUNZIP_BYTES:,} bytes, the limit for a gzip "
                        "program (held in memory); decompress it (gunzip -k) and give the plain file, which is read "
                        "without loading it whole")
    except (OSError, EOFError, zlib.error) as exc:
        raise InputFileError(f"{path}: not a readable gzip file ({exc}); give the program plain or as a whole "
                             ".gcode.gz") from None
    buf = np.frombuffer(data, dtype=np.uint8)
    buf.flags.writeable = False  # as a mapped file's: the kernels are compiled for read-only bytes
    return buf


def resolve_machine(machine, option: str = "--machine") -> Machine:
    """A :class:`Machine` from ``None`` / ``"none"`` (3-axis), a machine file path, or a Machine."""
    if machine is None or isinstance(machine, Machine):
        return NO_MACHINE if machine is None else machine
    if str(machine) == "none":
        return NO_MACHINE
    try:
        return load_machine(machine)
    except InputFileError as exc:
        raise InputFileError(f"{option} {machine}: {exc}; give a machine file such as "
                             "data/machines/trunnion-ac.toml, or none for a 3-axis machine") from None


def read_gcode(
    path: str | os.PathLike,
    dialect: str = "auto",
    strict: bool = False,
    laser_on: str | None = None,
    laser_off: str | None = None,
    default_feed_mm_min: float = DEFAULT_FEED_MM_MIN,
    rapid_feed_mm_min: float = RAPID_FEED_MM_MIN,
    machine=None,
    tip_chord_mm: float = DEFAULT_TIP_CHORD_MM,
    axis_step_deg: float = DEFAULT_AXIS_STEP_DEG,
    start=None,
    plate_z: float | None = None,
) -> Toolpath:
    """Interpret a G-code file.

    Lenient by default: a malformed line is skipped with a warning naming it. With
    ``strict`` the first malformed line (and any arc outside LinuxCNC's tolerances, a deposit
    move from an unknown position, a feed that is not positive, a laser M-code the dialect does
    not explain) raises :class:`GcodeError` ``FILE:LINE: what is wrong``. Warnings, unknown
    codes and the detected dialect are in ``toolpath.meta``.

    ``machine`` (a machine file, a :class:`Machine`, or None / "none" for a 3-axis machine):
    with a five-axis machine the rows are the tool tip's path in the workpiece frame, with the
    tool axis per row (:mod:`dmdvox.toolpath.fiveaxis`: the tip path sampled within
    ``tip_chord_mm``, axis steps of at most ``axis_step_deg``).

    ``start`` (x, y, z) mm: where the tool stands before the first line (``--start``), for a
    program that never says it (all G91, or no G28/G92/absolute word before its moves). A program
    that never gives Z runs at ``plate_z`` (else 0), warned.
    """
    path = Path(path)
    start_option, start_at = start, _start_position(start)
    if plate_z is not None and not np.isfinite(plate_z):
        raise DmdvoxError(f"--plate must be a finite height in mm, got {plate_z!r}")
    rules = get_dialect(dialect, laser_on, laser_off)
    machine = resolve_machine(machine)
    five = machine.is_five_axis
    for value, name in ((tip_chord_mm, "tip_chord_mm"), (axis_step_deg, "axis_step_deg")):
        if not (np.isfinite(value) and value > 0):
            raise DmdvoxError(f"{name} must be a positive number, not {value!r}")
    buf = _load(path)
    cap = K.count_newlines(buf) + 1  # rows <= lines
    start = np.empty((cap, 3), np.float64)
    end = np.empty((cap, 3), np.float64)
    deposit = np.empty(cap, np.bool_)
    kind = np.empty(cap, np.uint8)
    feed = np.empty(cap, np.float32)
    power = np.empty(cap, np.float32)
    t0 = np.empty(cap, np.float64)
    t1 = np.empty(cap, np.float64)
    line = np.empty(cap, np.int32)
    rotary = np.empty((cap, 3), np.float32)
    material = np.empty(cap, np.float32)
    dwell = np.empty(cap, np.float32)
    five_cap = cap if five else 0
    rot0 = np.empty((five_cap, 3), np.float64)
    rot1 = np.empty((five_cap, 3), np.float64)
    mode = np.empty(five_cap, np.uint8)
    arc_seg = np.empty(cap, np.int64)
    arc_centre = np.empty((cap, 3), np.float64)
    arc_axis = np.empty(cap, np.uint8)
    arc_sweep = np.empty(cap, np.float64)
    arc_r0 = np.empty(cap, np.float64)
    arc_r1 = np.empty(cap, np.float64)
    arc_len = np.empty(cap, np.float64)
    n_ev_cap = min(cap, MAX_EVENTS)
    ev_line = np.empty(n_ev_cap, np.int64)
    ev_code = np.empty(n_ev_cap, np.int32)
    ev_value = np.empty(n_ev_cap, np.float64)

    info = np.zeros(K.INFO_SIZE, np.int64)
    requested = rules.name

    def run(dialect, flags: int, at: np.ndarray, strict_run: bool = strict):
        params = _line_params(buf, dialect.params) if isinstance(dialect, CustomDialect) else _NO_PARAMS
        result = K.interpret(
            buf, dialect.rule_array(), params, dialect.flags | flags, strict_run, float(default_feed_mm_min),
            float(rapid_feed_mm_min), ARC_ABS_TOL_MM, ARC_REL_TOL,
            start, end, deposit, kind, feed, power, t0, t1, line, rotary, material, dwell, rot0, rot1, mode,
            arc_seg, arc_centre, arc_axis, arc_sweep, arc_r0, arc_r1, arc_len,
            ev_line, ev_code, ev_value, at, 0.0 if plate_z is None else float(plate_z), info,
        )
        status = result[5]
        if status:
            i = status - 1
            what = _describe(int(ev_code[i]), float(ev_value[i]))
            if int(ev_code[i]) == K.EV_POSITION_UNKNOWN:
                what += "; give the start with --start X,Y,Z (or a G28, G92 or absolute X Y Z before it)"
            raise GcodeError(str(path), int(ev_line[i]), what)
        return result

    flags = K.FLAG_FIVE_AXIS if five else 0
    evidence_found: list[str] = []
    if requested in ("auto", "custom"):
        # Auto finds the file's family in a first read, then reads it as that dialect, so that it
        # behaves exactly as the dialect it reports; custom takes that family's G4 P unit.
        first = run(DIALECTS["auto"], flags, start_at, False)
        n_ev, evidence = first[2], first[6]
        is_evidence = ev_code[:n_ev] == K.EV_EVIDENCE
        evidence_found = [_evidence_text(float(v), int(n)) for v, n in zip(ev_value[:n_ev][is_evidence],
                                                                        ev_line[:n_ev][is_evidence])]
        family = _detected_dialect(evidence)
        if requested == "custom":
            rules = with_dwell_unit(rules, bool(DIALECTS[family].flags & FLAG_DWELL_P_MS))
        elif family != "auto":
            rules = DIALECTS[family]
    detected = rules.name
    result = run(rules, flags, start_at)
    how_read = []  # how the reader took what the file leaves open, said once each
    if (info[K.INFO_UNKNOWN_MOVES] and not info[K.INFO_AXES_KNOWN] & 4 and not info[K.INFO_UNKNOWN_RELATIVE]
            and np.isnan(start_at[2])):
        # A flat program (laser, plasma) works in the frame of its work origin: it starts there,
        # on the plate. A G91 one is not placed by a guess: its start decides where the part is.
        start_at[2] = 0.0 if plate_z is None else float(plate_z)
        start_at[:2] = np.where(np.isnan(start_at[:2]), 0.0, start_at[:2])
        where = "the plate's (--plate)" if plate_z is not None else "0, no --plate given"
        how_read.append(f"{path}: the program never gives Z: its moves are taken at Z = {start_at[2]:g} ({where}), "
                        "from X0 Y0; give --start X,Y,Z if the tool stands elsewhere")
        result = run(rules, flags, start_at)
    relative_e = _relative_e_doubt(path, info, strict)
    if relative_e:
        how_read.append(relative_e)
        if not info[K.INFO_E_MODE_SAID]:
            result = run(rules, flags | K.FLAG_E_RELATIVE_START, start_at)
    rows, arcs, n_ev, dropped, lines, status, evidence, end_time = result
    if info[K.INFO_UNKNOWN_RELATIVE]:
        how_read.append(
            f"{path}: {info[K.INFO_UNKNOWN_RELATIVE]} relative (G91) moves start from a position the program never "
            "gives (no absolute X, Y and Z, G28 or G92 before them) and are not recorded; give the start with "
            "--start X,Y,Z")

    codes = ev_code[:n_ev]
    is_unknown = (codes >= K.EV_UNKNOWN_BASE) & (codes < K.EV_EVIDENCE)
    if strict:
        label = detected if requested == detected else f"{requested} (read as {detected})"
        _refuse_unexplained_laser_codes(path, label, codes, ev_value[:n_ev], ev_line[:n_ev])
    unknown = Counter(_unknown_name(int(c), float(v)) for c, v in zip(codes[is_unknown], ev_value[:n_ev][is_unknown]))
    # a file-wide habit (a generator's) is said once, with the number of lines
    once = np.isin(codes, [c for group, _ in _SAID_ONCE for c in group])
    warn_idx = np.flatnonzero((codes < K.EV_UNKNOWN_BASE) & ~once)
    if requested not in ("auto", "custom"):
        is_evidence = codes == K.EV_EVIDENCE
        evidence_found = [_evidence_text(float(v), int(n)) for v, n in zip(ev_value[:n_ev][is_evidence],
                                                                        ev_line[:n_ev][is_evidence])]
    long_dwells = np.flatnonzero(codes == K.EV_LONG_DWELL)
    warnings = [f"{path}:{int(ev_line[i])}: {_describe(int(ev_code[i]), float(ev_value[i]))}"
                for i in warn_idx[:MAX_WARNINGS_LISTED]]
    for group, text in _SAID_ONCE:
        hits = np.flatnonzero(np.isin(codes, group))
        if hits.size:
            i = int(hits[0])
            what = text if text and hits.size > 1 else _describe(int(codes[i]), float(ev_value[i]))
            more = f" ({hits.size} lines; the first is line {int(ev_line[i])})" if hits.size > 1 else ""
            warnings.append(f"{path}:{int(ev_line[i])}: {what}{more}")
    if len(warn_idx) > MAX_WARNINGS_LISTED or dropped:
        warnings.append(f"{path}: {len(warn_idx) - MAX_WARNINGS_LISTED + dropped} more warnings not listed")
    warnings += how_read
    remap = np.flatnonzero((codes == K.EV_UNKNOWN_M) & np.isin(ev_value[:n_ev], _TCP_REMAPS))
    if remap.size:
        i = int(remap[0])
        warnings.append(
            f"{path}:{int(ev_line[i])}: M{int(ev_value[i])}: M428 / M429 are LinuxCNC remaps (switchkins: M428 "
            "switches to tool-centre-point kinematics, M429 back), which dmdvox does not run: the X Y Z after M428 "
            "are read as written; for the tip path give --machine FILE.toml and write G43.4 / G49 for that switch "
            "(docs/MACHINES.md)")
    warnings += _remap_hints(path, unknown, codes, ev_value[:n_ev], ev_line[:n_ev])

    def trim(a: np.ndarray, n: int) -> np.ndarray:
        # Keep a view when it is nearly full; otherwise release the over-allocation.
        return a[:n] if n >= 0.9 * a.shape[0] else a[:n].copy()

    start, end, deposit, kind, feed, power = (trim(a, rows) for a in (start, end, deposit, kind, feed, power))
    t0, t1, line, rotary, material, dwell = (trim(a, rows) for a in (t0, t1, line, rotary, material, dwell))
    arc_table = ArcTable(
        segment=arc_seg[:arcs].copy(), centre=arc_centre[:arcs].copy(), normal_axis=arc_axis[:arcs].copy(),
        sweep=arc_sweep[:arcs].copy(), r_start=arc_r0[:arcs].copy(), r_end=arc_r1[:arcs].copy(), length=arc_len[:arcs].copy(),
    )
    axis = None
    five_meta = {}
    # rotary words on axes the machine does not have are kept as columns and not followed
    unused = [c for c in range(3) if c + 3 not in {ax.column for ax in machine.axes}]
    rotary_used = bool(rows) and bool(np.any(rotary[:, unused] != 0.0))
    if five:
        tip = tip_rows(machine, start, end, kind, feed, t0, t1, rot0[:rows], rot1[:rows], mode[:rows], arc_table,
                       end_time=float(end_time), chord_tolerance=tip_chord_mm, axis_step_deg=axis_step_deg)
        src = tip.src
        share = (tip.frac1 - tip.frac0).astype(np.float32)
        first_piece = tip.frac0 == 0.0
        deposit, power, line = deposit[src], power[src], line[src]
        material = material[src] * share
        dwell = np.where(first_piece, dwell[src], np.float32(0.0)).astype(np.float32)
        start, end, kind, feed, t0, t1 = tip.start, tip.end, tip.kind, tip.feed, tip.t_start, tip.t_end
        rotary, axis, arc_table, end_time = tip.rotary, tip.axis, tip.arcs, tip.end_time
        _check_rotary_limits(path, machine, rotary, line, strict, warnings)
        five_meta = {"machine": machine.to_json(), "tcp_used": bool(np.any(mode[:rows] & K.MODE_TCP)),
                     "tip_chord_mm": float(tip_chord_mm), "axis_step_deg": float(axis_step_deg),
                     "tilted": bool(np.any(axis[:, 2] < np.float32(1.0)))}
        rows = len(src)
    layer_z, layer = _layers(start, end, deposit)
    comments = slicer_comments(buf, line)
    tp = Toolpath(
        start=start, end=end, deposit=deposit, kind=kind, feed=feed, power=power, t_start=t0, t_end=t1,
        line=line, layer=layer, rotary=rotary, arcs=arc_table, layer_z=layer_z,
        e_material=material, dwell_on=dwell, width=comments.width, height=comments.height,
        feature=comments.feature, axis=axis,
        z_is_layer_top=bool(rules.flags & FLAG_Z_TOP) or detected == "reprap",
        source=str(path), dialect=detected,
        meta={
            "lines": int(lines),
            "warnings": warnings,
            "unknown_codes": dict(sorted(unknown.items())),
            "duration_s": float(end_time),
            "rotary_used": rotary_used,
            "features": comments.feature_names,
            "filament_diameter_mm": header_filament_diameter(buf),
            "program_motion": scan_motion_codes(buf, detected, line, t0, t1, deposit, feed),
            "moves_from_unknown_position": int(info[K.INFO_UNKNOWN_MOVES]),
            "dialect_evidence": evidence_found,
            "dwell_p_unit": "ms" if rules.flags & FLAG_DWELL_P_MS else "s",
            **five_meta,
        },
    )
    if long_dwells.size:
        i = int(long_dwells[0])
        warnings.append(f"{path}:{int(ev_line[i])}: a dwell of {ev_value[i]:g} s (over {K.LONG_DWELL_S / 60:g} min; "
                        f"{long_dwells.size} such dwell{'s' if long_dwells.size > 1 else ''}); G4 P is "
                        f"{tp.meta['dwell_p_unit']} under dialect {detected}: check --dialect")
    warnings += _doubtful_moves(tp)
    if requested == "auto" and detected != "reprap":  # E words on every bead are evidence enough
        weak = _weak_evidence(tp)
        if weak:
            warnings.append(weak)
    short = _short_deposit(tp, int(info[K.INFO_E_WORDS]))
    if short:
        warnings.append(short)
    if requested not in ("auto", "custom"):
        doubt = _dialect_doubt(tp, evidence, default_feed_mm_min=default_feed_mm_min,
                               rapid_feed_mm_min=rapid_feed_mm_min, start=start_option, plate_z=plate_z)
        if doubt:
            warnings.append(doubt)
    return tp


# The laser codes each dialect's rules explain; evidence of another family's means the file was
# written for that one.
_OWN_EVIDENCE = {"seed": K.EVID_SEED, "linuxcnc": K.EVID_LINUXCNC | K.EVID_SPINDLE | K.EVID_MELTIO,
                 "grbl": K.EVID_SPINDLE, "meltio": K.EVID_MELTIO, "reprap": K.EVID_E}
_LASER_M_NUMBERS = (3, 4, 5, 62, 63, 64, 65, 101, 102, 103, 108)
_LASER_M_CODES = {f"M{m}" for m in _LASER_M_NUMBERS}
DIALECT_DOUBT_RATIO = 2.0  # a deposit this many times longer (or shorter) under the detected dialect


def _dialect_doubt(tp: Toolpath, evidence: int, **options) -> str | None:
    """A warning when an explicit ``--dialect`` reads the file's laser codes very differently
    from the dialect the file's codes point to (``auto``): e.g. ``--dialect linuxcnc`` on the
    seed's M64/M65 without P deposits 2 % of the part, silently otherwise. The file is read a
    second time only when codes of another family are there or laser codes went unexplained."""
    foreign = evidence & ~_OWN_EVIDENCE.get(tp.dialect, 0)
    unexplained = _LASER_M_CODES & set(tp.meta["unknown_codes"])
    if not foreign and not unexplained:
        return None
    auto = read_gcode(tp.source, dialect="auto", **options)
    if auto.dialect in ("auto", tp.dialect):
        return None
    mine, theirs = float(tp.length[tp.deposit].sum()), float(auto.length[auto.deposit].sum())
    if theirs <= DIALECT_DOUBT_RATIO * mine and mine <= DIALECT_DOUBT_RATIO * theirs:
        return None
    codes = f"; unexplained: {', '.join(sorted(unexplained))}" if unexplained else ""
    share = f" ({100 * mine / theirs:.0f} %)" if theirs > 0 else ""
    return (f"{tp.source}: --dialect {tp.dialect} deposits {mine:.0f} mm of path{share}, but the file's laser codes "
            f"read as the {auto.dialect} dialect's (what --dialect auto picks{codes}), which deposits {theirs:.0f} mm; "
            "check --dialect")


@dataclass(frozen=True, eq=False)
class SlicerComments:
    """Per-row values of the slicers' modal line comments (NaN / ``NO_FEATURE`` where none
    applies yet): ``;WIDTH:`` and ``;HEIGHT:`` (PrusaSlicer, Slic3r, Orca) and ``;TYPE:`` (also
    Cura), each holding from its line until the next one of its kind."""

    width: np.ndarray  # (n,) float32 mm
    height: np.ndarray  # (n,) float32 mm
    feature: np.ndarray  # (n,) uint8 index into feature_names
    feature_names: list[str]


_BEAD_COMMENT = re.compile(rb";(WIDTH|HEIGHT|TYPE):[ \t]*([^\r\n;]*)")
_HEADER_BYTES = 1 << 18  # slicers write their settings in the first or last few kB
# Each slicer's filament-diameter comment (the first extruder's where it lists several):
# PrusaSlicer, Slic3r, Orca, Bambu "; filament_diameter = 1.75"; Cura's Griffin header
# ";EXTRUDER_TRAIN.0.MATERIAL.DIAMETER:2.85"; Simplify3D ";   filamentDiameter,1.75000" (or
# "filamentDiameters,1.75|1.75"); ideaMaker ";Filament Diameter #1: 1.750"; KISSlicer
# "; fiber_dia_mm = 1.75"; Skeinforge "(<setting> dimension Filament_Diameter_(mm): 1.82 </setting>)".
_FILAMENT_DIAMETER = re.compile(
    rb"^(?:;[ \t]*(?:filament_diameter[ \t]*=|Filament Diameter(?:[ \t]*#1)?[ \t]*[:=]"
    rb"|(?:EXTRUDER_TRAIN\.0\.)?MATERIAL\.DIAMETER[ \t]*:|material_diameter[ \t]*=|filamentDiameters?[ \t]*,"
    rb"|fiber_dia_mm[ \t]*=)|\(<setting>[ \t]*dimension[ \t]+Filament_Diameter_\(mm\):)[ \t]*([0-9]*\.?[0-9]+)",
    re.MULTILINE | re.IGNORECASE)
# Cura keeps its settings as JSON in ";SETTING_3 " lines cut every 80 characters, a key may
# straddle two of them: "material_diameter = 2.85" is found in the lines joined.
_CURA_SETTINGS = re.compile(rb"^;SETTING_3 ([^\r\n]*)", re.MULTILINE)
_CURA_DIAMETER = re.compile(rb"(?:^|\\n)material_diameter = ([0-9]*\.?[0-9]+)")


def slicer_comments(buf: np.ndarray, row_line: np.ndarray) -> SlicerComments:
    """The slicers' bead comments, carried to every row from the last such line at or before it."""
    n = row_line.shape[0]
    width = np.full(n, np.nan, np.float32)
    height = np.full(n, np.nan, np.float32)
    feature = np.full(n, NO_FEATURE, np.uint8)
    found = {b"WIDTH": ([], []), b"HEIGHT": ([], []), b"TYPE": ([], [])}
    for match in _BEAD_COMMENT.finditer(memoryview(buf)):
        offsets, values = found[match.group(1)]
        offsets.append(match.start())
        values.append(match.group(2).strip())
    if not any(offsets for offsets, _ in found.values()):
        return SlicerComments(width, height, feature, [])
    newlines = np.flatnonzero(buf == 10)

    def carried(offsets: list[int]) -> np.ndarray:
        """For each row, the index of the last comment on its line or before (-1: none)."""
        comment_line = np.searchsorted(newlines, np.asarray(offsets, np.int64)) + 1
        return np.searchsorted(comment_line, row_line, side="right") - 1

    for key, target in ((b"WIDTH", width), (b"HEIGHT", height)):
        offsets, values = found[key]
        if offsets:
            numbers = np.array([_number_or_nan(v) for v in values], np.float32)
            which = carried(offsets)
            target[which >= 0] = numbers[which[which >= 0]]
    names: list[str] = []
    offsets, values = found[b"TYPE"]
    if offsets:
        labels = [v.decode("ascii", "replace") for v in values]
        names = sorted(set(labels))[:NO_FEATURE]
        code = {name: k for k, name in enumerate(names)}
        codes = np.array([code.get(label, NO_FEATURE) for label in labels], np.uint8)
        which = carried(offsets)
        feature[which >= 0] = codes[which[which >= 0]]
    return SlicerComments(width, height, feature, names)


def _number_or_nan(text: bytes) -> float:
    try:
        value = float(text)
    except ValueError:
        return float("nan")
    return value if np.isfinite(value) and value > 0 else float("nan")


def header_filament_diameter(buf: np.ndarray) -> float | None:
    """The filament diameter a slicer wrote into its header or settings block, if any."""
    for part in (buf[:_HEADER_BYTES], buf[max(_HEADER_BYTES, buf.shape[0] - _HEADER_BYTES):]):
        match = _FILAMENT_DIAMETER.search(memoryview(part))
        if match:
            return _number_or_none(match.group(1))
        cura = b"".join(_CURA_SETTINGS.findall(memoryview(part)))
        match = _CURA_DIAMETER.search(cura)
        if match:
            return _number_or_none(match.group(1))
    return None


def _number_or_none(text: bytes) -> float | None:
    value = _number_or_nan(text)
    return None if np.isnan(value) else value


def _start_position(start) -> np.ndarray:
    """``start`` as the kernel's (3,) float64 position, NaN (unknown) when None."""
    if start is None:
        return np.full(3, np.nan)
    try:
        at = np.array([float(v) for v in start], np.float64)
    except (TypeError, ValueError):
        at = np.zeros(0)
    if at.shape != (3,) or not np.all(np.isfinite(at)):
        raise DmdvoxError(f"--start: expected X,Y,Z in mm (three finite numbers), got {start!r}")
    return at


E_FALLS_SHARE = 0.1  # absolute E below the previous value on this share of its words: not absolute
E_RISES_SHARE = 0.5  # ... and rising on less than this share
MIN_E_WORDS = 20  # fewer E words say nothing of a habit
MIN_SHORT_E_WORDS = 5  # a stripped reset shows at the second layer: the WAAM Transpiler's file has 10 E words
SHORT_DEPOSIT_SHARE = 0.2  # an E-fed file depositing less of its path than this is doubtful


def _relative_e_doubt(path: Path, info: np.ndarray, strict: bool) -> str | None:
    """A warning when absolute E words behave like increments: an absolute E only falls at a
    retract, so one that falls on many words and rises on few is relative E (Kiri:Moto writes it
    for printers set to relative in their firmware, with no M83). Without M82/M83 in the file the
    E words are then read as relative (its material is otherwise lost, silently); with an M82 the
    file's word stands, said loudly; --strict refuses to guess."""
    n = int(info[K.INFO_E_ABSOLUTE])
    falls, rises = int(info[K.INFO_E_FALLS]), int(info[K.INFO_E_RISES])
    if n < MIN_E_WORDS or falls < E_FALLS_SHARE * n or rises >= E_RISES_SHARE * n:
        return None
    habit = (f"read as absolute, E falls on {100 * falls / n:.0f} % of its {n} E words and rises on only "
             f"{100 * rises / n:.0f} %: they are increments (relative E)")
    if info[K.INFO_E_MODE_SAID]:
        return (f"{path}: {habit}, yet the file says M82 (absolute); read as absolute, its deposit is wrong: if the "
                "printer runs relative E, write M83 instead")
    if strict:
        raise DmdvoxError(f"{path}: the file sets no E mode (no M82 or M83) and, {habit}; --strict refuses to "
                          "guess: add M83 (relative) or M82 (absolute) at its start")
    return (f"{path}: the file sets no E mode (no M82 or M83) and, {habit}: E is read as relative; add M83 at its "
            "start to say so (or M82 if it really is absolute)")


def _short_deposit(tp: Toolpath, e_words: int) -> str | None:
    """A warning when a file whose E words meter the material deposits on less than
    SHORT_DEPOSIT_SHARE of its path: a post-processor that stripped the E resets (G92 E0) leaves
    an absolute E that stops rising after the first layer, and most of the part is read as travel."""
    if e_words < MIN_SHORT_E_WORDS or not len(tp):
        return None
    total = float(tp.length.sum())
    laid = float(tp.length[tp.deposit].sum())
    if total <= 0.0 or laid >= SHORT_DEPOSIT_SHARE * total:
        return None
    return (f"{tp.source}: its E words feed material on only {100 * laid / total:.0f} % of the path ({laid:.1f} of "
            f"{total:.1f} mm); the rest is read as travel. If a post-processor stripped the E resets (G92 E0), or "
            "E is relative without an M83, the deposit is wrong: check the file's E words")


def _check_rotary_limits(path: Path, machine: Machine, rotary: np.ndarray, line: np.ndarray, strict: bool,
                         warnings: list[str]) -> None:
    """A program that drives a rotary axis past the machine file's limits: an error under
    ``strict``, else a warning naming the first line (the path is followed as programmed)."""
    for ax in machine.axes:
        if ax.limits is None or rotary.shape[0] == 0:
            continue
        lo, hi = ax.limits
        v = rotary[:, ax.column - 3].astype(np.float64)
        bad = np.flatnonzero((v < lo - 1e-4) | (v > hi + 1e-4))
        if bad.size:
            i = int(bad[0])
            what = (f"{ax.letter} = {v[i]:g} is outside the machine's {ax.letter.lower()}.limits = [{lo:g}, {hi:g}] "
                    f"({machine.source or machine.name})")
            if strict:
                raise GcodeError(str(path), int(line[i]), what)
            warnings.append(f"{path}:{int(line[i])}: {what}; followed as programmed")


def _refuse_unexplained_laser_codes(path: Path, dialect: str, codes, values, lines) -> None:
    """--strict: a laser M-code the chosen dialect does not explain would leave the beam's state
    wrong (its deposits dropped or invented): stop at its first line."""
    laser = np.array(sorted(_LASER_M_NUMBERS), np.float64)
    hit = np.flatnonzero((codes == K.EV_UNKNOWN_M) & np.isin(values, laser))
    if hit.size:
        i = int(hit[0])
        raise GcodeError(str(path), int(lines[i]),
                         f"M{int(values[i])} is a laser code that --dialect {dialect} does not explain; --strict "
                         "refuses to guess the beam's state (choose the dialect that writes it, e.g. --dialect auto, "
                         "or --dialect custom with --laser-on/--laser-off)")


# Tool-centre-point forms dmdvox does not read (M428/M429 are said beside _TCP_REMAPS): what they
# are and what to do.
_REMAP_HINTS = {
    "G43.5": ("tool-centre-point control with the tool axis given as a vector (I J K; Fanuc's type 2), which "
              "dmdvox does not read: post the program with rotary axis angles and G43.4, and give --machine "
              "FILE.toml"),
}


def _remap_hints(path: Path, unknown: Counter, codes, values, lines) -> list[str]:
    """One hint per kind of unsupported tool-centre-point code the file uses, at the first line of one."""
    by_hint: dict[str, list[tuple[int, str]]] = {}
    for name in sorted(set(unknown) & set(_REMAP_HINTS)):
        is_g = name.startswith("G")
        target = round(float(name[1:]) * 10) if is_g else int(name[1:])
        hit = (codes == (K.EV_UNKNOWN_G if is_g else K.EV_UNKNOWN_M)) & (np.rint(values) == target)
        by_hint.setdefault(_REMAP_HINTS[name], []).append((int(lines[np.flatnonzero(hit)[0]]), name))
    out = []
    for hint, found in by_hint.items():
        names = ", ".join(f"{name} (x{unknown[name]})" for _, name in sorted(found))
        out.append(f"{path}:{min(found)[0]}: {names}: {hint}")
    return out


_NO_PARAMS = np.zeros((0, 3), np.float64)
_NUMBER = rb"[-+]?(?:\d+\.?\d*|\.\d+)"


def _line_params(buf: np.ndarray, names: tuple[str, ...]) -> np.ndarray:
    """The parenthesised parameters ``(NAME value)`` that custom rules read, as kernel rows (line,
    key, value) in line order; one after a ';' is in a comment and is not read."""
    if not names:
        return _NO_PARAMS
    alternatives = b"|".join(re.escape(name.encode()) for name in names)
    pattern = re.compile(rb"\(\s*(" + alternatives + rb")\s*[=:]?\s*(" + _NUMBER + rb")\s*\)", re.IGNORECASE)
    found = [(m.start(), PARAM_KEY_BASE + names.index(m.group(1).decode().upper()), float(m.group(2)))
             for m in pattern.finditer(memoryview(buf))]
    if not found:
        return _NO_PARAMS
    offsets = np.array([f[0] for f in found], np.int64)
    newlines = np.flatnonzero(buf == 10)
    line_index = np.searchsorted(newlines, offsets)  # 0-based line of each match
    line_start = np.concatenate(([0], newlines + 1))[line_index]
    rows = [(line_index[k] + 1, key, value) for k, (offset, key, value) in enumerate(found)
            if not np.any(buf[line_start[k]:offset] == 59)]
    return np.array(rows, np.float64).reshape(-1, 3)


LONG_MOVE_MM = 10_000.0  # 10 m: beyond any DED cell's axis
FEED_RANGE_MM_MIN = (0.1, 100_000.0)
LIFT_MM = 1.0  # a pure Z move longer than this is a lift, not a bead


def _first_and_count(tp: Toolpath, rows: np.ndarray) -> tuple[int, int]:
    index = np.flatnonzero(rows)
    return int(tp.line[index[0]]), int(index.size)


def _doubtful_moves(tp: Toolpath) -> list[str]:
    """A move over 10 m and a feed outside 0.1-100,000 mm/min, each said once: the first line and
    how many (units read wrong, a corrupt number, or a dialect that reads the words otherwise)."""
    if not len(tp):
        return []
    out = []
    long = tp.length > LONG_MOVE_MM
    if np.any(long):
        first, count = _first_and_count(tp, long)
        out.append(f"{tp.source}:{first}: a move of {float(tp.length[np.argmax(long)]) / 1000:.1f} m (over "
                   f"{LONG_MOVE_MM / 1000:g} m; {count} such move{'s' if count > 1 else ''}): check the units "
                   "(G20 inch, G21 mm) and the program's words")
    low, high = FEED_RANGE_MM_MIN
    per_min = tp.feed.astype(np.float64) * 60.0
    odd = (tp.kind != RAPID) & ((per_min < low) | (per_min > high)) & (tp.length > 0)
    if np.any(odd):
        first, count = _first_and_count(tp, odd)
        out.append(f"{tp.source}:{first}: a feed of {per_min[np.argmax(odd)]:.4g} mm/min (outside {low:g}-{high:,.0f} "
                   f"mm/min; {count} move{'s' if count > 1 else ''}): check the F words and their units")
    return out


def _weak_evidence(tp: Toolpath) -> str | None:
    """Auto-detection's doubt: the codes it went by say little when every move deposits, the
    deposit state never changes once on, or vertical lifts deposit (a DED program switches the
    beam off to lift; GLOW's M64 P2/P3 are the fume extractor and the argon, not the laser)."""
    dep = tp.deposit
    if not np.any(dep):
        return None
    reasons = []
    if np.all(dep):
        reasons.append("every move deposits")
    elif np.all(dep[int(np.argmax(dep)):]):
        reasons.append("the deposit state never changes once on")
    d = tp.end - tp.start
    lift = dep & (np.abs(d[:, 2]) > LIFT_MM) & (np.hypot(d[:, 0], d[:, 1]) <= 1e-6)
    if np.any(lift):
        first, count = _first_and_count(tp, lift)
        reasons.append(f"{count} vertical lift{'s' if count > 1 else ''} (pure Z moves over {LIFT_MM:g} mm) "
                       f"deposit, the first at line {first}")
    if not reasons:
        return None
    found = "; ".join(tp.meta.get("dialect_evidence", [])) or "no laser codes"
    return (f"{tp.source}: weak evidence for dialect {tp.dialect} (what --dialect auto went by: {found}): "
            f"{', '.join(reasons)}; if other codes switch the beam, say so with --dialect custom --laser-on/"
            "--laser-off (rules like 'M201 SDC>0', 'M42 P1 S1')")


_FAMILY_OF = {3: "spindle/laser (M3/M4/M5: linuxcnc, grbl)", 4: "spindle/laser (M3/M4/M5: linuxcnc, grbl)",
              5: "spindle/laser (M3/M4/M5: linuxcnc, grbl)", 62: "linuxcnc digital output",
              63: "linuxcnc digital output", 101: "seed (Fadal)", 102: "seed (Fadal)", 103: "seed (Fadal)",
              108: "seed (Fadal)"}


def _evidence_text(value: float, line: int) -> str:
    """One auto-detection clue as the kernel reported it (EV_EVIDENCE: M * 1000 + P + 1, or -1)."""
    if value < 0:
        return f"line {line}: E words on moves (reprap)"
    m, p = divmod(int(value), 1000)
    p -= 1
    code = f"M{m}" + (f" P{p}" if p >= 0 else "")
    if m in (64, 65):
        family = "meltio" if p in (8, 9) else ("linuxcnc digital output" if p >= 0 else "seed (Fadal)")
    else:
        family = _FAMILY_OF.get(m, "")
    return f"line {line}: {code} ({family})"


def _detected_dialect(evidence: int) -> str:
    if evidence & K.EVID_E:
        return "reprap"
    for bit, name in ((K.EVID_MELTIO, "meltio"), (K.EVID_SEED, "seed"), (K.EVID_LINUXCNC, "linuxcnc"),
                      (K.EVID_SPINDLE, "linuxcnc")):
        if evidence & bit:
            return name
    return "auto"


def _layers(start: np.ndarray, end: np.ndarray, deposit: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Distinct Z levels of the deposit rows that stay at one Z, and each row's layer (other rows:
    the next such row's). A plunge or a ramp with the beam on (a plasma pierce, a Z hop) is no
    layer of its own; where no deposit row stays level (a spiral vase), every deposit row counts."""
    run_of_row = np.empty(start.shape[0], np.int32)
    level = deposit & (np.abs(end[:, 2] - start[:, 2]) <= 0.5 * LAYER_Z_RESOLUTION_MM)
    run_key = K.layer_runs(start, level if level.any() else deposit, LAYER_Z_RESOLUTION_MM, run_of_row)
    if run_key.size == 0:
        return np.zeros(0, np.float64), np.full(start.shape[0], -1, np.int32)
    unique_keys, run_layer = np.unique(run_key, return_inverse=True)
    return unique_keys * LAYER_Z_RESOLUTION_MM, run_layer.astype(np.int32)[run_of_row]
