#!/usr/bin/env python3
"""Generate the five-axis sample: a tube built on a rotating table, and its CAD STL.

The machine is ``data/machines/trunnion-ac.toml`` (a C table on an A cradle, the nozzle
vertical, the workpiece origin on the C axis at the table top). With tool-centre-point control
off, X Y Z A C are machine joints: the nozzle stands at X = R, Y = 0 and each layer is one move
that turns the table through 360 degrees (``G1 C360``, ``G1 C720``, ...: the C axis is not
wrapped, so each turns once more), laying a ring of radius R in the workpiece frame; the laser
is off (M64) while Z steps up between rings. Seed dialect (M65 on, M64 off), rect bead
2.5 x 0.8 mm, tip feed 600 mm/min.

The CAD part is the tube the rings should fill: radii R -+ half the bead width, height
layers x layer step (a 256-sided prism; its area is within 0.01 % of the circle's).

    python scripts/make_tube_sample.py [--radius 15] [--layers 12] [--out data]
"""

from __future__ import annotations

import argparse
from pathlib import Path

import numpy as np

WIDTH = 2.5
LAYER_STEP = 0.8
FEED_MM_MIN = 600.0
SIDES = 256


def tube_program(radius: float, layers: int) -> list[str]:
    lines = [f"(dmdvox five-axis sample: a tube of radius {radius:g} mm on the C table of "
             "data/machines/trunnion-ac.toml, TCP off)",
             "M64", "G90 G21 G17",
             "G49 (tool-centre-point control off: X Y Z A C are machine joints)",
             f"G0 X{radius:.4f} Y0 Z5 A0 C0",
             f"G1 Z0 F{FEED_MM_MIN:.1f}"]
    for layer in range(layers):
        if layer:
            lines.append(f"G1 Z{layer * LAYER_STEP:.4f}")
        lines += ["M65", f"G1 C{360 * (layer + 1)}", "M64"]
    lines += ["G0 Z50", "M30"]
    return lines


def tube_mesh(r_in: float, r_out: float, height: float, sides: int = SIDES) -> tuple[np.ndarray, np.ndarray]:
    """A closed, outward-facing tube (annular prism)."""
    angle = 2 * np.pi * np.arange(sides) / sides
    ring = np.column_stack([np.cos(angle), np.sin(angle)])
    vertices = np.concatenate([np.column_stack([r * ring, np.full(sides, z)])
                               for r, z in ((r_out, 0.0), (r_out, height), (r_in, 0.0), (r_in, height))])
    ob, ot, ib, it = (k * sides for k in range(4))
    i = np.arange(sides)
    j = (i + 1) % sides
    triangles = np.concatenate([
        np.column_stack([ob + i, ob + j, ot + j]), np.column_stack([ob + i, ot + j, ot + i]),  # outer wall
        np.column_stack([ib + i, it + j, ib + j]), np.column_stack([ib + i, it + i, it + j]),  # inner wall
        np.column_stack([ot + i, ot + j, it + j]), np.column_stack([ot + i, it + j, it + i]),  # top
        np.column_stack([ob + i, ib + j, ob + j]), np.column_stack([ob + i, ib + i, ib + j]),  # bottom
    ])
    return vertices, triangles.astype(np.int64)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--radius", type=float, default=15.0)
    parser.add_argument("--layers", type=int, default=12)
    parser.add_argument("--out", default=str(Path(__file__).resolve().parents[1] / "data"))
    parser.add_argument("--name", default="tube_trunnion")
    args = parser.parse_args()
    from dmdvox.io.atomic import write_text
    from dmdvox.io.mesh import write_stl

    out = Path(args.out)
    write_text(out / f"{args.name}.gcode", "\n".join(tube_program(args.radius, args.layers)) + "\n")
    write_stl(out / f"{args.name}.stl", *tube_mesh(args.radius - WIDTH / 2, args.radius + WIDTH / 2,
                                                   args.layers * LAYER_STEP))
    print(f"wrote {out / args.name}.gcode and .stl")


if __name__ == "__main__":
    main()
