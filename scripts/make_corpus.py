#!/usr/bin/env python3
"""Write the real-slicer corpus' CAD parts: closed STLs in data/corpus/.

Every part stands on z = 0 at its final machine coordinates, so the slicers are told to keep it
where it is (see scripts/make_corpus.sh) and the G-code compares with the STL without any
--cad-offset. The four small parts are 3 mm tall (ten 0.3 mm layers):

    cylinder   d 16 mm, centre (50, 50), 128 facets (chord sag 2.4 um: far below a voxel)
    lbracket   L of two 6 mm legs, 22 x 16 mm overall, corner at (40, 40)
    holeplate  20 x 20 mm plate with an 8 mm round through-hole, centre (50, 50)
    frustum    d 16 mm at the bottom, d 10 mm at the top (45 degree taper: no overhang)

and one taller part, sliced by PrusaSlicer at 100 % only, for the comparison at scale:

    tallcylinder  d 20 mm, 20 mm tall, centre (50, 50)

    python scripts/make_corpus.py [--out data/corpus]
"""

from __future__ import annotations

import argparse
import math
from pathlib import Path

import numpy as np

HEIGHT = 3.0
CENTRE = (50.0, 50.0)
FACETS = 128  # a multiple of 8, so the hole plate's rays hit the square's corners


def extrude(bottom_xy, top_xy, cap_triangles, loops, z0=0.0, z1=HEIGHT):
    """A closed prism (or a taper, when top_xy differs from bottom_xy) between z0 and z1.

    cap_triangles index the 2D vertices and run counter-clockwise seen from +z; each loop runs
    with the material on its left (outer boundary counter-clockwise, holes clockwise), which
    makes every side quad face outwards.
    """
    bottom = np.asarray(bottom_xy, float)
    top = np.asarray(top_xy, float)
    n = bottom.shape[0]
    vertices = np.vstack([np.column_stack([bottom, np.full(n, z0)]), np.column_stack([top, np.full(n, z1)])])
    caps = np.asarray(cap_triangles, np.int64)
    triangles = [caps[:, ::-1], caps + n]
    for loop in loops:
        i = np.asarray(loop, np.int64)
        j = np.roll(i, -1)
        triangles += [np.column_stack([i, j, j + n]), np.column_stack([i, j + n, i + n])]
    return vertices, np.vstack(triangles)


def circle(radius, centre=CENTRE, count=FACETS):
    angle = 2 * math.pi * np.arange(count) / count
    return np.column_stack([centre[0] + radius * np.cos(angle), centre[1] + radius * np.sin(angle)])


def fan(count):
    """Triangles of a polygon star-shaped from its vertex 0 (convex ones and the L)."""
    return [(0, k, k + 1) for k in range(1, count - 1)]


def cylinder(diameter=16.0):
    ring = circle(diameter / 2)
    return extrude(ring, ring, fan(FACETS), [range(FACETS)])


def tallcylinder(diameter=20.0, height=20.0):
    ring = circle(diameter / 2)
    return extrude(ring, ring, fan(FACETS), [range(FACETS)], z1=height)


def frustum(bottom_diameter=16.0, top_diameter=10.0):
    return extrude(circle(bottom_diameter / 2), circle(top_diameter / 2), fan(FACETS), [range(FACETS)])


def lbracket(corner=(40.0, 40.0), size_x=22.0, size_y=16.0, leg=6.0):
    x, y = corner
    outline = [(x, y), (x + size_x, y), (x + size_x, y + leg), (x + leg, y + leg), (x + leg, y + size_y),
               (x, y + size_y)]
    return extrude(outline, outline, fan(len(outline)), [range(len(outline))])


def holeplate(size=20.0, hole_diameter=8.0):
    """The square is sampled on the circle's rays (corners included), so the ring between the two
    is quads inside one wedge each: convex, and the cap needs no general triangulator."""
    angle = 2 * math.pi * np.arange(FACETS) / FACETS
    direction = np.column_stack([np.cos(angle), np.sin(angle)])
    # Distance along each ray to the square's boundary: the half size over the ray's larger component.
    reach = (size / 2) / np.abs(direction).max(axis=1)
    outer = np.asarray(CENTRE) + direction * reach[:, None]
    inner = np.asarray(CENTRE) + direction * (hole_diameter / 2)
    xy = np.vstack([outer, inner])
    k = np.arange(FACETS)
    k1 = (k + 1) % FACETS
    caps = np.vstack([np.column_stack([k, k1, FACETS + k1]), np.column_stack([k, FACETS + k1, FACETS + k])])
    return extrude(xy, xy, caps, [range(FACETS), FACETS + np.arange(FACETS)[::-1]])


SHAPES = {"cylinder": cylinder, "lbracket": lbracket, "holeplate": holeplate, "frustum": frustum,
          "tallcylinder": tallcylinder}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--out", default=str(Path(__file__).resolve().parents[1] / "data" / "corpus"))
    args = parser.parse_args()
    from dmdvox.io.mesh import write_stl

    for name, make in SHAPES.items():
        path = write_stl(Path(args.out) / f"{name}.stl", *make())
        print(f"wrote {path}")


if __name__ == "__main__":
    main()
