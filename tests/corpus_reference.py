"""An independent reference reader for the real-program corpus (data/corpus/real).

It shares no code with dmdvox: plain Python, one pass over the lines, with the deposition rule of
each file given explicitly by its MANIFEST.toml entry (what the program's own comments, its
generator's source and its repository's docs say switches deposition), never guessed from the
file. It is deliberately small and literal so that it is obviously right for what it covers:

* motion: G0/G1/G2/G3 (and G00..G03), modal motion on lines that give only axis words; arcs in
  the XY plane (G17) with I/J centres (relative, G91.1) or R (negative R: the long way), full
  circles when the end is the start, helices (a Z move along the arc: sqrt((r*sweep)^2 + dz^2));
* G90/G91, G20/G21 (inch: lengths, centres, radii and feeds x 25.4), G92 (X Y Z and the
  extrusion axis), M82/M83; G4 dwell with P in the unit the manifest names; G93 inverse time;
* every other code's words are its parameters (M201 X10000 moves nothing; M73 R32 is no radius;
  M68 E2 Q100 is no extrusion). The manifest's ``flavour`` says who owns the axis words of a line
  with an M-code and no motion code: ``"reprap"`` (Marlin, Klipper, PrusaSlicer: the M-code, one
  command per line) or ``"rs274"`` (LinuxCNC, Grbl, Mach3: they move in the modal motion mode);
* LinuxCNC #<param> and [expression] words are skipped: where they would decide the geometry the
  manifest says what is left unchecked.

Deposition rules (``deposit`` in the manifest):

* ``"e"``: a move deposits when the extrusion axis (E, or the manifest's ``extrusion_axis``)
  feeds material along it: its increase beyond what refills an earlier retract (a retract of 1 mm
  then E+0.01 leaves the filament 0.99 mm short: nothing leaves the nozzle);
  ``e_origin_resets_at`` names a comment at which the generator's own tool restarts its E
  bookkeeping (the WAAM transpiler's per-layer reset, see the manifest); ``e_relative`` says E is
  relative from the first line, set by the printer and not the file (Kiri:Moto writes no M83;
  M82/M83 in the file still switch it);
* ``"codes"``: a state switched by ``deposit_on`` / ``deposit_off`` rules of the form
  ``M<n> [KEY OP VALUE ...]`` (KEY a word letter, ``$``, or a parenthesised ``(KEY value)`` comment
  on the line; S falls back to the modal S). Words on a motion line act before its motion (Grbl
  and LinuxCNC do so). Codes listed in ``ramp_codes`` (LinuxCNC M67) change the output along the
  move: the move deposits if the state before or after it is on. G0 never deposits.

Layers are the distinct Z (mm, to 0.001) of deposit moves that stay at one Z; ``min_duration_s``
is the time the program itself fixes from below: feed moves at their programmed F (inverse time
under G93), dwells; rapids and acceleration only add to it.
"""

from __future__ import annotations

import gzip
import math
import re
from dataclasses import dataclass, field
from pathlib import Path

INCH = 25.4
_WORD = re.compile(r"([A-Z$])\s*([-+]?(?:\d+\.?\d*|\.\d+))")
_PAREN = re.compile(r"\(([^()]*)\)")
_RULE_COND = re.compile(r"^([A-Z$]+)\s*(>=|<=|>|<|=)\s*([-+]?\d*\.?\d+)$")
_PARAM = re.compile(r"#<[^>]*>|#\d+")
_BRACKET = re.compile(r"\[[^\[\]]*\]")
MOTION = {0.0, 1.0, 2.0, 3.0}
PROBE = {31.0, 38.2, 38.3, 38.4, 38.5}  # a move that stops at contact: travel, and no time bound
# codes whose axis words are parameters (offsets, firmware retraction, local frames)
CONSUMING = {10.0, 11.0, 10.1, 30.0, 52.0, 92.1, 92.2, 92.3}


def _strip_expressions(code: str) -> str:
    """LinuxCNC parameters and [expressions] out, so that their digits are not read as words."""
    code = _PARAM.sub(" ", code)
    while _BRACKET.search(code):
        code = _BRACKET.sub(" ", code)
    return code


def read_text(path: Path) -> str:
    data = path.read_bytes()
    if path.suffix == ".gz":
        data = gzip.decompress(data)
    return data.decode("ascii")


@dataclass
class Rule:
    code: int
    conditions: list[tuple[str, str, float]]

    @staticmethod
    def parse(text: str) -> "Rule":
        head, *rest = text.split()
        conditions = []
        for item in rest:
            m = _RULE_COND.match(item)
            if not m:
                raise ValueError(f"rule {text!r}: {item!r} is not KEY OP VALUE")
            conditions.append((m.group(1), m.group(2), float(m.group(3))))
        return Rule(int(head[1:]), conditions)

    def matches(self, mcodes: list[int], value) -> bool:
        if self.code not in mcodes:
            return False
        for key, op, want in self.conditions:
            got = value(key)
            if got is None:
                return False
            if not {">": got > want, "<": got < want, "=": math.isclose(got, want, abs_tol=1e-9),
                    ">=": got >= want, "<=": got <= want}[op]:
                return False
        return True


@dataclass
class Result:
    deposit_length_mm: float = 0.0
    travel_length_mm: float = 0.0
    moves: int = 0
    deposit_moves: int = 0
    layers: int = 0
    min_duration_s: float = 0.0
    dwell_s: float = 0.0
    inverse_time_moves: int = 0
    malformed_arcs: int = 0
    rapids_while_on: int = 0
    rotary_words: int = 0
    deposit_z: set = field(default_factory=set)


def _arc_length(x0, y0, z0, x1, y1, z1, words, clockwise, scale) -> tuple[float, bool]:
    """Exact length of an XY arc (helix if Z moves) and whether its radii disagree."""
    if "R" in words:
        r = words["R"] * scale
        chord = math.hypot(x1 - x0, y1 - y0)
        half = min(1.0, chord / (2 * abs(r))) if r else 1.0
        sweep = 2 * math.asin(half)
        if r < 0:
            sweep = 2 * math.pi - sweep
        return math.hypot(abs(r) * sweep, z1 - z0), chord > 2 * abs(r) + 1e-6
    cx = x0 + words.get("I", 0.0) * scale
    cy = y0 + words.get("J", 0.0) * scale
    r0 = math.hypot(x0 - cx, y0 - cy)
    r1 = math.hypot(x1 - cx, y1 - cy)
    a0 = math.atan2(y0 - cy, x0 - cx)
    a1 = math.atan2(y1 - cy, x1 - cx)
    sweep = (a0 - a1) if clockwise else (a1 - a0)
    sweep %= 2 * math.pi
    if sweep < 1e-12:  # end == start: a full turn
        sweep = 2 * math.pi
    malformed = abs(r1 - r0) > max(0.005, 0.001 * r0)
    return math.hypot(r0 * sweep, z1 - z0), malformed


def read(path: Path, spec: dict) -> Result:
    mode = spec["deposit"]
    axis = spec.get("extrusion_axis", "E")
    dwell_unit = {"s": 1.0, "ms": 0.001}[spec.get("dwell_p", "s")]
    on_rules = [Rule.parse(t) for t in spec.get("deposit_on", [])]
    off_rules = [Rule.parse(t) for t in spec.get("deposit_off", [])]
    ramp_codes = set(spec.get("ramp_codes", []))
    e_reset = spec.get("e_origin_resets_at")
    rotary = set("ABC") - {axis}
    reprap = {"reprap": True, "rs274": False}[spec["flavour"]]

    res = Result()
    pos = [0.0, 0.0, 0.0]
    e = 0.0
    retracted = 0.0  # filament mm drawn back by retracts and not yet fed again
    scale = 1.0
    absolute = True
    e_absolute = not spec.get("e_relative", False)
    inverse_time = False
    motion = None
    feed = 0.0  # mm/min (1/min under G93)
    s_modal = 0.0
    on = False
    for raw in read_text(path).splitlines():
        text = raw.strip()
        if e_reset and text.startswith(e_reset):
            e = 0.0
        code = text.split(";", 1)[0]
        parens = _PAREN.findall(code)
        code = _strip_expressions(_PAREN.sub(" ", code).upper())
        code = re.sub(r"\*\d+\s*$", "", re.sub(r"^N\d+\s*", "", code.strip()))
        words_list = _WORD.findall(code)
        if not words_list:
            continue
        gcodes = [float(v) for letter, v in words_list if letter == "G"]
        mcodes = [int(float(v)) for letter, v in words_list if letter == "M"]
        words = {letter: float(v) for letter, v in words_list if letter not in "GMN"}
        if "S" in words:
            s_modal = words["S"]

        def value(key, _words=words, _parens=parens):
            if key in _words:
                return _words[key]
            for p in _parens:
                parts = p.split()
                if len(parts) == 2 and parts[0].upper() == key:
                    try:
                        return float(parts[1])
                    except ValueError:
                        return None
            return s_modal if key == "S" else None

        was_on = on
        for rule in off_rules:
            if rule.matches(mcodes, value):
                on = False
        for rule in on_rules:
            if rule.matches(mcodes, value):
                on = True
        e_absolute = {82: True, 83: False}.get(mcodes[-1], e_absolute) if mcodes else e_absolute

        line_motion = None
        consumed = False
        for n in gcodes:
            if n in MOTION:
                line_motion = motion = int(n)
            elif n in PROBE:
                line_motion = "probe"
            elif n == 20:
                scale = INCH
            elif n == 21:
                scale = 1.0
            elif n == 90:
                absolute = True
            elif n == 91:
                absolute = False
            elif n == 93:
                inverse_time = True
            elif n == 94:
                inverse_time = False
            elif n == 4:
                dwell = words["P"] * dwell_unit if "P" in words else words.get("S", 0.0)
                res.dwell_s += dwell
                res.min_duration_s += dwell
                consumed = True
            elif n == 92:
                for i, letter in enumerate("XYZ"):
                    if letter in words:
                        pos[i] = words[letter] * scale
                if axis in words:
                    e = words[axis]
                consumed = True
            elif n == 28:  # homing: the named axes (all when none is named) go to 0
                named = [i for i, letter in enumerate("XYZ") if letter in words] or [0, 1, 2]
                for i in named:
                    pos[i] = 0.0
                consumed = True
            elif n in CONSUMING:
                consumed = True
        if mcodes and line_motion is None and reprap:
            continue  # RepRap firmware: "M201 X10000 Y10000", "M593 X T2 F0": the M-code's words
        if "F" in words:
            feed = words["F"] if inverse_time else words["F"] * scale
        if consumed:
            continue
        # RS-274 (LinuxCNC, Grbl, Mach3): axis words beside an M-code move in the modal mode,
        # but "M68 E2 Q100"'s E is that code's parameter
        e_axis = mode == "e" and not (mcodes and line_motion is None)
        axes = ("X", "Y", "Z", axis) if e_axis else ("X", "Y", "Z")
        if not any(letter in words for letter in axes):
            continue
        kind = line_motion if line_motion == "probe" else motion
        if kind is None:
            continue
        target = list(pos)
        for i, letter in enumerate("XYZ"):
            if letter in words:
                v = words[letter] * scale
                target[i] = v if absolute else pos[i] + v
        if any(letter in words for letter in rotary):
            res.rotary_words += 1
        material = 0.0
        if e_axis and axis in words:
            v = words[axis]
            if e_absolute and absolute:
                de, e = v - e, v
            else:
                de, e = v, e + v
            # a retract leaves the filament short: the next feed refills the nozzle first
            refill = min(max(de, 0.0), retracted)
            retracted += max(-de, 0.0) - refill
            material = max(de, 0.0) - refill
        if kind in (2, 3):
            length, bad = _arc_length(*pos, *target, words, kind == 2, scale)
            res.malformed_arcs += bad
        else:
            length = math.dist(pos, target)
        start, pos = pos, target
        if length == 0:
            continue
        res.moves += 1
        feeding = kind in (1, 2, 3)
        if mode == "e":
            deposit = feeding and material > 0
        else:
            ramp = was_on and bool(ramp_codes & {f"M{m}" for m in mcodes})
            deposit = feeding and (on or ramp)
            res.rapids_while_on += kind == 0 and on
        if deposit:
            res.deposit_length_mm += length
            res.deposit_moves += 1
            if abs(target[2] - start[2]) < 1e-9:
                res.deposit_z.add(round(target[2], 3))
        else:
            res.travel_length_mm += length
        if feeding:
            if inverse_time:
                res.inverse_time_moves += 1
                res.min_duration_s += 60.0 / feed if feed > 0 else 0.0
            elif feed > 0:
                res.min_duration_s += 60.0 * length / feed
    res.layers = len(res.deposit_z)
    return res
