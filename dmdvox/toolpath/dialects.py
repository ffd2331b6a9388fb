"""Deposition rule tables, one per G-code dialect.

Each dialect maps M-codes (optionally qualified by their P word) to an action on the
deposition state, plus a few flags. The tables are data: the interpreter kernel only reads
them, so a new dialect is a new table, not new control flow.

| dialect  | deposition on                          | deposition off                 | notes |
|----------|----------------------------------------|--------------------------------|-------|
| seed     | M65, M101, M103, M108                  | M64, M102                      | the 2012 thesis' Fadal DMD files; G4 P in ms |
| linuxcnc | M3/M4 with S>0; M64 Pn; M62 Pn (sync)  | M5; M65 Pn; M63 Pn (sync); S0  | M62/M63 act at the next motion; G4 P in s |
| reprap   | a move whose E increases               | a move without E increase      | M82/M83, G92 E; E-only moves are retracts; Z is the layer top |
| grbl     | M3/M4 with S>0                         | M5, S0; G0 never deposits      | G4 P in s |
| meltio   | M64 P8                                 | M65 P8; M64 P9 (travel)        | P8 drives the laser/feeder output, P9 flags travel |
| custom   | rules given with --laser-on            | rules given with --laser-off   | G4 P in the unit of the family auto finds |
| auto     | E words: reprap; otherwise the M-code families above, told apart by their P word |

A custom rule is an M-code and conditions on its line's words, ``KEY OP VALUE`` with OP one of
``= != > >= < <=`` (``P1`` alone means ``P=1``): ``M42 P1 S1``, ``M3 S>0``, ``M68 E=2 Q>0``. A
KEY of more than one letter is a parenthesised parameter on the line: ``M201 SDC>0`` matches
``M201 (SDC 37.8)``. A missing S falls back to the S in force; any other missing key fails the
condition. The matched rule's last condition on a word other than P and E (which number the
output on LinuxCNC's M62-M68 and Marlin's M42) sets the power column: S, Q, SDC.

Auto reads the file once to find its family, then reads it as that dialect (the one it reports):
its dwell unit, rapid feed and E handling, not a mixture.

Rapids (G0) never deposit in any dialect. Without an F word the feed is
``DEFAULT_FEED_MM_MIN``; rapids run at ``RAPID_FEED_MM_MIN`` (override per run), except under
reprap (and auto from its first E word on), where G0 moves at the modal F as RepRap firmware
does.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, replace

import numpy as np

from ..errors import DmdvoxError

DEFAULT_FEED_MM_MIN = 600.0
RAPID_FEED_MM_MIN = 6000.0

# Actions the kernel understands (keep in sync with gcode_kernel.py).
ON = 1
OFF = 2
ON_AT_MOTION = 3  # LinuxCNC M62: switches with the next motion
OFF_AT_MOTION = 4  # LinuxCNC M63
SPINDLE_ON = 5  # M3/M4: on while S > 0
SPINDLE_OFF = 6  # M5
E_ABSOLUTE = 7  # M82
E_RELATIVE = 8  # M83

NO_P = -1  # rule applies when the line has no P word
ANY_P = -2  # rule applies whatever the P word

FLAG_USE_E = 1  # deposition follows E increases
FLAG_S0_OFF = 2  # S0 switches the beam off while the spindle/laser is on
FLAG_DWELL_P_MS = 4  # G4 P is milliseconds (else seconds)
FLAG_AUTO_E = 8  # auto: switch to E-driven deposition at the first E word on a motion line
FLAG_Z_TOP = 16  # Z is the top of the bead (slicers)

_SPINDLE = [(3, ANY_P, SPINDLE_ON), (4, ANY_P, SPINDLE_ON), (5, ANY_P, SPINDLE_OFF)]
_E_MODES = [(82, ANY_P, E_ABSOLUTE), (83, ANY_P, E_RELATIVE)]
_SEED = [(65, NO_P, ON), (101, ANY_P, ON), (103, ANY_P, ON), (108, ANY_P, ON), (64, NO_P, OFF), (102, ANY_P, OFF)]
_MELTIO = [(64, 8, ON), (65, 8, OFF), (64, 9, OFF)]
_LINUXCNC_IO = [(62, ANY_P, ON_AT_MOTION), (63, ANY_P, OFF_AT_MOTION), (64, ANY_P, ON), (65, ANY_P, OFF)]

# Condition operators of custom rules (the kernel's codes)
OPERATORS = {"=": 0, "==": 0, "!=": 1, ">": 2, ">=": 3, "<": 4, "<=": 5}
MAX_CONDITIONS = 4
PARAM_KEY_BASE = 26  # condition keys below: word letters (A = 0); from it on: Dialect.params[key - 26]
NO_KEY = -1
# Rule table columns: code, P, action, power key, then MAX_CONDITIONS (key, operator, value)
RULE_COLUMNS = 4 + 3 * MAX_CONDITIONS
_P_KEY, _E_KEY = ord("P") - 65, ord("E") - 65

_HEAD_RE = re.compile(r"^M(\d+)(?![\d.])")
_CONDITION_RE = re.compile(r"\s*([A-Z][A-Z_0-9]*)\s*(>=|<=|!=|==|=|>|<)?\s*([-+]?(?:\d+\.?\d*|\.\d+))")
_EXAMPLE = "give a comma list like 'M65,M101', 'M42 P1 S1' or 'M201 SDC>0'"


@dataclass(frozen=True)
class Dialect:
    name: str
    rules: tuple[tuple[int, int, int], ...]
    flags: int

    def rule_array(self) -> np.ndarray:
        """(rules, RULE_COLUMNS) float64: code, P, action, power key, conditions (none here)."""
        table = np.full((len(self.rules), RULE_COLUMNS), float(NO_KEY), np.float64)
        table[:, :3] = np.array(self.rules, dtype=np.float64).reshape(-1, 3)
        # The kernel takes the first match: a specific P beats "no P", which beats "any P".
        specificity = np.where(table[:, 1] >= 0, 0, np.where(table[:, 1] == NO_P, 1, 2))
        order = np.lexsort((specificity, table[:, 0]))
        return np.ascontiguousarray(table[order])


DIALECTS: dict[str, Dialect] = {
    "seed": Dialect("seed", tuple(_SEED), FLAG_DWELL_P_MS),
    "linuxcnc": Dialect("linuxcnc", tuple(_SPINDLE + _LINUXCNC_IO), FLAG_S0_OFF),
    "reprap": Dialect("reprap", tuple(_E_MODES), FLAG_USE_E | FLAG_DWELL_P_MS | FLAG_Z_TOP),
    "grbl": Dialect("grbl", tuple(_SPINDLE), FLAG_S0_OFF),
    "meltio": Dialect("meltio", tuple(_MELTIO), FLAG_DWELL_P_MS),
    # auto: P8/P9 select Meltio, other P words LinuxCNC I/O, no P the seed's Fadal codes.
    "auto": Dialect(
        "auto",
        tuple(_MELTIO + [(62, ANY_P, ON_AT_MOTION), (63, ANY_P, OFF_AT_MOTION), (64, ANY_P, ON), (65, ANY_P, OFF)]
              + _SEED + _SPINDLE + _E_MODES),
        FLAG_AUTO_E | FLAG_S0_OFF | FLAG_DWELL_P_MS,
    ),
}
DIALECT_NAMES = ("auto", "seed", "linuxcnc", "reprap", "grbl", "meltio", "custom")


@dataclass(frozen=True)
class Condition:
    key: str  # a word letter, or the name of a parenthesised parameter
    op: str
    value: float


def _parse_rules(text, option: str) -> list[tuple[int, tuple[Condition, ...]]]:
    """``M<n> [KEY OP VALUE ...]`` items of a comma list (a list of such strings from a cell file)."""
    if isinstance(text, (list, tuple)) and all(isinstance(item, str) for item in text):
        text = ",".join(text)
    if not isinstance(text, str):
        raise DmdvoxError(f"{option}: {text!r} is not a list of codes; {_EXAMPLE}")
    rules = []
    for item in filter(None, (part.strip().upper() for part in text.split(","))):
        head = _HEAD_RE.match(item)
        rest = item[head.end():] if head else ""
        conditions = []
        while head and rest.strip():
            match = _CONDITION_RE.match(rest)
            if not match:
                break
            conditions.append(Condition(match.group(1), "=" if match.group(2) in (None, "==") else match.group(2),
                                        float(match.group(3))))
            rest = rest[match.end():]
        if not head or rest.strip():
            raise DmdvoxError(f"{option}: '{item}' is not an M-code with conditions KEY OP VALUE (OP one of "
                              f"= != > >= < <=); {_EXAMPLE}")
        if len(conditions) > MAX_CONDITIONS:
            raise DmdvoxError(f"{option}: '{item}' has {len(conditions)} conditions; at most {MAX_CONDITIONS}")
        rules.append((int(head.group(1)), tuple(conditions)))
    if not rules:
        raise DmdvoxError(f"{option}: no codes given; {_EXAMPLE}")
    return rules


@dataclass(frozen=True)
class CustomDialect(Dialect):
    """A ``custom`` dialect: rules with conditions (module docstring) and the names of the
    parenthesised parameters they read (``params``, keys PARAM_KEY_BASE on)."""

    conditions: tuple[tuple[Condition, ...], ...] = ()
    params: tuple[str, ...] = ()

    def key(self, name: str) -> int:
        return ord(name) - 65 if len(name) == 1 else PARAM_KEY_BASE + self.params.index(name)

    def rule_array(self) -> np.ndarray:
        table = np.full((len(self.rules), RULE_COLUMNS), float(NO_KEY), np.float64)
        for i, ((m, p, action), conditions) in enumerate(zip(self.rules, self.conditions)):
            keys = [self.key(c.key) for c in conditions]
            table[i, :3] = (m, p, action)
            table[i, 3] = next((k for k in reversed(keys) if k not in (_P_KEY, _E_KEY)), NO_KEY)
            for j, (k, c) in enumerate(zip(keys, conditions)):
                table[i, 4 + 3 * j:7 + 3 * j] = (k, OPERATORS[c.op], c.value)
        # The kernel takes the first match: a rule with more conditions before one with fewer.
        order = np.lexsort((-np.array([len(c) for c in self.conditions]), table[:, 0]))
        return np.ascontiguousarray(table[order])


def with_dwell_unit(dialect: Dialect, milliseconds: bool) -> Dialect:
    """``dialect`` reading G4 P in milliseconds or seconds."""
    flags = (dialect.flags | FLAG_DWELL_P_MS) if milliseconds else (dialect.flags & ~FLAG_DWELL_P_MS)
    return replace(dialect, flags=flags)


def get_dialect(name: str, laser_on=None, laser_off=None) -> Dialect:
    """The rule table for ``name``; ``custom`` builds one from the two rule lists (a comma list,
    or a list of rules as a cell file gives them)."""
    if name not in DIALECT_NAMES:
        raise DmdvoxError(f"--dialect: unknown dialect '{name}'; choose one of {', '.join(DIALECT_NAMES)}")
    if name == "custom":
        if laser_on is None or laser_off is None:
            raise DmdvoxError("--dialect custom needs both --laser-on and --laser-off code lists")
        parsed = [(m, c, ON) for m, c in _parse_rules(laser_on, "--laser-on")]
        parsed += [(m, c, OFF) for m, c in _parse_rules(laser_off, "--laser-off")]
        params = tuple(sorted({c.key for _, conditions, _ in parsed for c in conditions if len(c.key) > 1}))
        return CustomDialect("custom", tuple((m, ANY_P, action) for m, _, action in parsed), FLAG_DWELL_P_MS,
                             conditions=tuple(c for _, c, _ in parsed), params=params)
    if laser_on is not None or laser_off is not None:
        raise DmdvoxError("--laser-on/--laser-off only apply to --dialect custom")
    return DIALECTS[name]
