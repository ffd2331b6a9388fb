"""The `info` summary of a toolpath (JSON keys are part of the CLI contract)."""

from __future__ import annotations

import numpy as np
from numba import njit

from .model import RAPID, Toolpath


@njit(cache=True)
def _chord_lengths(start, end, deposit):
    """Deposit and travel straight-line lengths in one pass (no per-row array: `info` runs
    this over millions of rows)."""
    dep_len = 0.0
    travel_len = 0.0
    for i in range(start.shape[0]):
        d = 0.0
        for a in range(3):
            d += (end[i, a] - start[i, a]) ** 2
        d = np.sqrt(d)
        if deposit[i]:
            dep_len += d
        else:
            travel_len += d
    return dep_len, travel_len


def summarize(tp: Toolpath) -> dict:
    deposit = tp.deposit
    dep_len, travel_len = _chord_lengths(tp.start, tp.end, deposit)
    # Arcs: swap their chord for the exact length.
    arc_rows = tp.arcs.segment
    chords = np.linalg.norm(tp.end[arc_rows] - tp.start[arc_rows], axis=1)
    arc_dep = deposit[arc_rows]
    dep_len += float((tp.arcs.length - chords)[arc_dep].sum())
    travel_len += float((tp.arcs.length - chords)[~arc_dep].sum())
    return {
        "lines": int(tp.meta.get("lines", 0)),
        "dialect": tp.dialect,
        "dialect_evidence": list(tp.meta.get("dialect_evidence", [])),
        "moves": len(tp),
        "deposit_segments": int(np.count_nonzero(deposit)),
        "deposit_length_mm": float(dep_len),
        "travel_length_mm": float(travel_len),
        "layers": int(tp.layer_z.shape[0]),
        "bbox_mm": tp.deposit_bbox().tolist(),
        "duration_s": tp.duration,
        "unknown_codes": sorted(tp.meta.get("unknown_codes", {})),
        "warnings": list(tp.meta.get("warnings", [])),
        **_five_axis(tp),
    }


def _five_axis(tp: Toolpath) -> dict:
    """The machine and how far the tool axis tilts (``machine`` only with a machine file)."""
    if "machine" not in tp.meta:
        return {}
    tilt = 0.0
    if len(tp) and not tp.vertical:
        tilt = float(np.degrees(np.arccos(np.clip(tp.axis[:, 2].astype(np.float64), -1.0, 1.0).min())))
    return {"machine": tp.meta["machine"], "tcp_used": bool(tp.meta.get("tcp_used", False)),
            "max_tilt_deg": tilt}


def format_summary(tp: Toolpath, info: dict) -> str:
    (x0, y0, z0), (x1, y1, z1) = info["bbox_mm"]
    hours, rest = divmod(info["duration_s"], 3600.0)
    minutes, seconds = divmod(rest, 60.0)
    rapid = int(np.count_nonzero(tp.kind == RAPID))
    lines = [
        f"{tp.source}  (dialect: {tp.dialect})",
        f"  lines               {info['lines']:>12,d}",
        f"  moves               {info['moves']:>12,d}   ({rapid:,d} rapid, {len(tp.arcs):,d} arcs)",
        f"  deposit segments    {info['deposit_segments']:>12,d}",
        f"  deposit length      {info['deposit_length_mm']:>12,.1f} mm",
        f"  travel length       {info['travel_length_mm']:>12,.1f} mm",
        f"  layers              {info['layers']:>12,d}" + (f"   (step {tp.layer_step:.3f} mm)" if info["layers"] > 1 else ""),
        f"  deposit bbox        x {x0:.3f}..{x1:.3f}  y {y0:.3f}..{y1:.3f}  z {z0:.3f}..{z1:.3f} mm",
        f"  duration            {int(hours):d}:{int(minutes):02d}:{seconds:05.2f}",
    ]
    unknown = tp.meta.get("unknown_codes", {})
    if unknown:
        lines.append("  ignored codes       " + ", ".join(f"{c} x{n}" for c, n in unknown.items()))
    if "machine" in info:
        machine = info["machine"]
        lines.append(f"  machine             {machine['kind']} ({machine['name']}); tool axis tilts up to "
                     f"{info['max_tilt_deg']:.1f} deg; tool-centre-point control "
                     f"{'used' if info['tcp_used'] else 'not used'}")
    if tp.meta.get("rotary_used"):
        lines.append("  rotary axes         A/B/C words the machine does not have (kept as columns, not followed)")
    return "\n".join(lines)
