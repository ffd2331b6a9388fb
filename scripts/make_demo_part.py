#!/usr/bin/env python3
"""Generate the demo part: a block built with the seed thesis' parameters, and its CAD STL.

Seed parameters: 2.5 mm track width, 1.25 mm centre-line spacing (50 % overlap), zigzag
hatch alternating between X and Y each layer, laser on M65 / off M64 (Fadal dialect, Z = bead
bottom). The CAD box is the volume the beads' straight parts should fill.

    python scripts/make_demo_part.py [--size 20,20] [--layers 8] [--layer-step 0.75] [--out data]
"""

from __future__ import annotations

import argparse
from pathlib import Path

import numpy as np

TRACK_WIDTH = 2.5
SPACING = 1.25
FEED_MM_MIN = 750.0  # the seed's F750


def hatch_layer(size_x: float, size_y: float, along_x: bool, z: float) -> list[str]:
    """Zigzag centre lines inside a size_x * size_y rectangle whose corner is the origin."""
    half = TRACK_WIDTH / 2
    long_len, short_len = (size_x, size_y) if along_x else (size_y, size_x)
    n_tracks = int(round((short_len - TRACK_WIDTH) / SPACING)) + 1
    offsets = half + SPACING * np.arange(n_tracks)
    lines = []
    for k, off in enumerate(offsets):
        a, b = (half, long_len - half) if k % 2 == 0 else (long_len - half, half)
        for along in (a, b):
            x, y = (along, off) if along_x else (off, along)
            if k == 0 and along == a:
                lines += [f"G0 X{x:.4f} Y{y:.4f} Z{z + 5:.4f}", f"G1 Z{z:.4f} F{FEED_MM_MIN:.1f}", "M65"]
            else:
                lines.append(f"G1 X{x:.4f} Y{y:.4f} Z{z:.4f}")
    lines.append("M64")
    return lines


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--size", default="20,20", help="block footprint X,Y in mm")
    parser.add_argument("--layers", type=int, default=8)
    parser.add_argument("--layer-step", type=float, default=0.75, help="mm between layers (= bead height)")
    parser.add_argument("--out", default=str(Path(__file__).resolve().parents[1] / "data"))
    parser.add_argument("--name", default="demo_block")
    args = parser.parse_args()
    size_x, size_y = (float(v) for v in args.size.split(","))
    out = Path(args.out)

    program = ["(dmdvox demo block: seed parameters, 2.5 mm track, 1.25 mm spacing, M65 on / M64 off)",
               "M64", "G90 G21 G17", f"F{FEED_MM_MIN:.1f}"]
    for layer in range(args.layers):
        program += hatch_layer(size_x, size_y, along_x=layer % 2 == 0, z=layer * args.layer_step)
    program.append("G0 Z50")
    program.append("M30")

    from dmdvox.io.atomic import write_text
    from dmdvox.io.mesh import box_mesh, write_stl

    write_text(out / f"{args.name}.gcode", "\n".join(program) + "\n")
    vertices, triangles = box_mesh((0.0, 0.0, 0.0), (size_x, size_y, args.layers * args.layer_step))
    write_stl(out / f"{args.name}.stl", vertices, triangles)
    print(f"wrote {out / (args.name + '.gcode')} and {out / (args.name + '.stl')}")
    if args.name == "demo_block":
        # A clamp beside the first tracks' ends, deliberately too tall for the nozzle (the demo's
        # collision check finds it).
        write_stl(out / "demo_clamp.stl", *box_mesh((-6.0, 4.0, 0.0), (-1.0, 16.0, 14.0)))
        print(f"wrote {out / 'demo_clamp.stl'}")


if __name__ == "__main__":
    main()
