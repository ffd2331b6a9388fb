#!/usr/bin/env bash
# Slice data/slicer_block.stl with Debian's prusa-slicer into the real-slicer samples.
# (apt-get install prusa-slicer; scripts/setup.sh --with-tools does it.)
# The STL is made by scripts/make_demo_part.py (a 20 x 20 x 3 mm box).
set -euo pipefail
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$repo"
.venv/bin/python scripts/make_demo_part.py --size 20,20 --layers 10 --layer-step 0.3 --name slicer_block >/dev/null
rm -f data/slicer_block.gcode  # only the STL is wanted from that run
for density in 100 20; do
    # data/prusa_block_20.gcode links to the package's sample (dmdvox/samples/): give the slicer
    # the link's target, since writing a temporary file and renaming it would replace the link.
    prusa-slicer --export-gcode --layer-height 0.3 --first-layer-height 0.3 --extrusion-width 0.6 \
        --perimeters 2 --top-solid-layers 3 --bottom-solid-layers 3 --skirts 0 --brim-width 0 \
        --fill-density "${density}%" --fill-pattern rectilinear --use-relative-e-distances \
        --center 10,10 --output "$(readlink -f "data/prusa_block_${density}.gcode")" data/slicer_block.stl
done
