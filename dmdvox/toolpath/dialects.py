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
| custom   | codes given with --laser-on            | codes given with --laser-off   | |
| auto     | E words: reprap; otherwise the M-code families above, told apart by their P word |

Rapids (G0) never deposit in any dialect. Without an F word the feed is
``DEFAULT_FEED_MM_MIN``; rapids run at ``RAPID_FEED_MM_MIN`` (override per run), except under
reprap (and auto from its first E word on), where G0 moves at the modal F as RepRap firmware
does.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

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


@dataclass(frozen=True)
class Dialect:
    name: str
    rules: tuple[tuple[int, int, int], ...]
    flags: int

    def rule_array(self) -> np.ndarray:
        table = np.array(self.rules, dtype=np.int64).reshape(-1, 3)
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

_CODE_RE = re.compile(r"^M(\d+)(?:\s*P(\d+))?$")


def _parse_codes(text: str, option: str) -> list[tuple[int, int]]:
    codes = []
    for item in filter(None, (part.strip().upper() for part in text.split(","))):
        match = _CODE_RE.match(item.replace(" ", ""))
        if not match:
            raise DmdvoxError(f"{option}: '{item}' is not an M-code; give a comma list like 'M65,M101' or 'M64 P8'")
        codes.append((int(match.group(1)), int(match.group(2)) if match.group(2) else ANY_P))
    if not codes:
        raise DmdvoxError(f"{option}: no codes given; give a comma list like 'M65,M101'")
    return codes


def get_dialect(name: str, laser_on: str | None = None, laser_off: str | None = None) -> Dialect:
    """The rule table for ``name``; ``custom`` builds one from the two code lists."""
    if name not in DIALECT_NAMES:
        raise DmdvoxError(f"--dialect: unknown dialect '{name}'; choose one of {', '.join(DIALECT_NAMES)}")
    if name == "custom":
        if laser_on is None or laser_off is None:
            raise DmdvoxError("--dialect custom needs both --laser-on and --laser-off code lists")
        rules = [(m, p, ON) for m, p in _parse_codes(laser_on, "--laser-on")]
        rules += [(m, p, OFF) for m, p in _parse_codes(laser_off, "--laser-off")]
        return Dialect("custom", tuple(rules), FLAG_DWELL_P_MS)
    if laser_on is not None or laser_off is not None:
        raise DmdvoxError("--laser-on/--laser-off only apply to --dialect custom")
    return DIALECTS[name]
