#!/usr/bin/env bash
# The real-slicer corpus: four small parts (scripts/make_corpus.py) sliced by Debian's three
# slicers at 100 % and 25 % infill into data/corpus/. Needs
#     apt-get install prusa-slicer slic3r cura-engine
# (tested with prusa-slicer 2.5.0, slic3r 1.3.0, cura-engine 4.13.0). The tests only read the
# committed files: neither they nor CI need the slicers. docs/CORPUS.md explains the choices.
#
# Same process for all three: 0.3 mm layers (first layer too), 0.6 mm extrusion width on every
# feature (first layer included), 2 perimeters, 3 solid layers top and bottom, no skirt, brim or
# raft, straight-line infill alternating direction per layer.
#
# Placement: each STL already sits at its machine coordinates (bottom on z = 0), and each slicer
# is told to leave it there, so `dmdvox compare` needs no --cad-offset:
#   prusa-slicer --center / slic3r --print-center move the bounding box centre to the given XY:
#     we give the STL's own bounding box centre;
#   CuraEngine keeps the mesh coordinates with center_object=false and adds no bed offset with
#     machine_center_is_zero=true (data/corpus/cura_corpus.def.json).
#
# Arcs: none of the three writes G2/G3. PrusaSlicer 2.5 has no arc fitting (it came in 2.6);
# slic3r 1.3 accepts --gcode-arcs but dies with "Arc fitting is not available (incomplete
# feature)" (/usr/lib/slic3r/Slic3r/GCode/ArcFitting.pm); CuraEngine 4.13 has none.
#
# E words: prusa-slicer writes relative E (M83, --use-relative-e-distances), slic3r and Cura
# absolute E (M82; Cura resets it with G92 E0 after retracts), so both reader modes are covered.
#
# Small sparse regions stay sparse: solid_infill_below_area 0 keeps PrusaSlicer and slic3r from
# making regions under 70 mm^2 solid (their default; the frustum's last sparse layer has 76 mm^2
# inside its perimeters, close enough that a slightly different part would cross it).
#
# Determinism: PrusaSlicer places seams differently from run to run when its worker threads race
# (ties on these symmetric parts); pinned to one CPU (taskset, util-linux) it repeats exactly.
set -euo pipefail
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$repo"
out=data/corpus
.venv/bin/python scripts/make_corpus.py --out "$out" >/dev/null

# Bounding box centre of each part (scripts/make_corpus.py).
declare -A centre=([cylinder]=50,50 [lbracket]=51,48 [holeplate]=50,50 [frustum]=50,50)

common=(--layer-height 0.3 --first-layer-height 0.3 --extrusion-width 0.6 --first-layer-extrusion-width 0.6
        --perimeters 2 --top-solid-layers 3 --bottom-solid-layers 3 --skirts 0 --brim-width 0
        --fill-pattern rectilinear --solid-infill-below-area 0)

for shape in cylinder lbracket holeplate frustum; do
    stl="$out/$shape.stl"
    for density in 100 25; do
        taskset -c 0 prusa-slicer --export-gcode "${common[@]}" --fill-density "${density}%" --use-relative-e-distances \
            --center "${centre[$shape]}" --output "$out/${shape}_prusa_${density}.gcode" "$stl" >/dev/null
        taskset -c 0 slic3r "${common[@]}" --fill-density "${density}%" \
            --print-center "${centre[$shape]}" --output "$out/${shape}_slic3r_${density}.gcode" "$stl" >/dev/null
        # Cura's engine reads no density: the front end turns it into the line distance, which for
        # the "lines" pattern is line width / density (0.6 mm at 100 %, 2.4 mm at 25 %).
        distance=$(python3 -c "print(round(0.6 * 100 / $density, 4))")
        taskset -c 0 CuraEngine slice -j "$out/cura_corpus.def.json" -s "infill_line_distance=$distance" \
            -l "$stl" -o "$out/${shape}_cura_${density}.gcode" 2>/dev/null
    done
done
# PrusaSlicer and slic3r stamp the date and time into their first line: cut it so a rerun gives
# identical files (Cura's ;MESH: comment holds the relative path given above: stable).
sed -i -e '1s/ on [0-9]\{4\}-[0-9-]* at [0-9:]*\( UTC\)\?$//' "$out"/*.gcode
ls -l "$out"/*.gcode
