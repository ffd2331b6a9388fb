"""Ranges of values as the studies take them: ``A`` or ``A:B:STEP``."""

from __future__ import annotations

import math

from ..errors import DmdvoxError

RANGE_TOLERANCE = 1e-9  # of a step: B is included when (B - A) / STEP is this close to a whole number
RANGE_DECIMALS = 12  # A + k * STEP rounded, so that 0.1 + 3 * 0.1 prints and compares as 0.4
MAX_RANGE_POINTS = 10_000


def parse_range(text: str, option: str) -> list[float]:
    """``A`` or ``A:B:STEP`` (B included when the steps land on it) as a list of floats."""
    parts = str(text).split(":")
    try:
        values = [float(p) for p in parts]
    except ValueError:
        values = []
    if len(values) == 1 and math.isfinite(values[0]):
        return values
    if len(values) != 3 or not all(math.isfinite(v) for v in values):
        raise DmdvoxError(f"{option}: expected A or A:B:STEP (numbers), got {text!r}")
    a, b, step = values
    if step <= 0 or b < a:
        raise DmdvoxError(f"{option} {text}: needs A <= B and STEP > 0")
    n = int(math.floor((b - a) / step + RANGE_TOLERANCE)) + 1
    if n > MAX_RANGE_POINTS:
        raise DmdvoxError(f"{option} {text}: {n} points; at most {MAX_RANGE_POINTS}")
    return [round(a + k * step, RANGE_DECIMALS) for k in range(n)]
