"""`dmdvox demo`: the whole pipeline on the shipped samples, in one folder.

The seed-parameter block (data/demo_block.gcode) is deposited, compared with its CAD box,
pictured, and checked against a cone nozzle, a clamp beside the part and the plate, all in one
report page (`dmdvox report`); a picture of the half-built part is added. The clamp is
deliberately too tall: the check finds where the nozzle would hit it. The heat runs on the
deposit too (the page's Heat section, ``HEAT``: 316L, a 1 kW beam at the default absorptivity
0.4 on the default thermal voxel, about 20 s of CPU: docs/PERFORMANCE.md).
"""

from __future__ import annotations

import argparse
import json
from pathlib import Path

# The samples ship inside the package (a wheel has no data/ folder); the repository's data/
# holds links to them.
DATA = Path(__file__).resolve().parent / "samples"
NOZZLE = "cone:tip=4,top=20,length=25"
CLAMP = "demo_clamp.stl"
# the heat stage's options (dmdvox.thermal.run.OPTION_KEYS), at the default thermal voxel (a
# quarter of the bead, 0.625 mm)
HEAT = {"material": "316L", "laser_power": 1000.0}
HEAT_KEYS = ("thermal_voxel_mm", "cells", "part_cells", "plate_cells", "steps", "beam_energy_J", "absorbed_J",
             "birth_heat_unpaid_J", "boiled_J", "lost_J",
             "energy_balance_max_percent", "max_peak_temperature_C", "max_interlayer_temperature_C",
             "max_melt_pool_width_mm", "remelted_cells")


def _args(command: str, *options: str) -> argparse.Namespace:
    """The demo's steps as the command lines a user would type."""
    from .cli import build_parser

    return build_parser().parse_args([command, str(DATA / "demo_block.gcode"), "--json", *options])


def run_demo(args) -> dict:
    from . import progress
    from .cli import _nozzle, _plan
    from .io.atomic import write_text
    from .reporting.build import ReportRequest, report
    from .view.render import render_moment

    out = Path(args.out)
    progress.stage("demo", f"1/2 report on {DATA / 'demo_block.gcode'}: deposit, compare with its CAD box, "
                           f"check the nozzle against the clamp and the plate, the heat, pictures, page in {out}")
    options = _args("report", "--cad", str(DATA / "demo_block.stl"), "--nozzle", NOZZLE, "--standoff", "12.7",
                    "--fixture", str(DATA / CLAMP), "--plate", "0", "--out", str(out))
    plan = _plan(options)
    page = report(ReportRequest(plan, out, cad=options.cad, nozzle=_nozzle(options), thermal=dict(HEAT))).summary
    progress.stage("demo", "2/2 picture of the half-built part")
    tp, bead = plan.toolpath, plan.profile
    half = render_moment(plan, out / "demo_block_half.png", at=0.5, cad_path=DATA / "demo_block.stl")["png"]
    cmp, collide = page["compare"], page["collide"]
    summary = {
        "report_html": page["report_html"],
        "deposit_volume_mm3": cmp["deposit_volume_mm3"],
        "pore_count": cmp["pore_count"],
        "void_percent": cmp["void_percent"],
        "overbuild_percent": cmp["overbuild_percent"],
        "deviation_mm": cmp["deviation_mm"],
        "collisions": collide["collisions"],
        "first_collision_line": collide["first_collision_line"],
        "thermal": {"material": HEAT["material"], "laser_power_W": HEAT["laser_power"],
                    **{k: page["thermal"][k] for k in HEAT_KEYS}},
        "outputs": page["outputs"] + [half],
    }
    summary["outputs"].append(str(write_text(out / "demo_summary.json", json.dumps(summary, indent=2))))
    if not args.json:
        print(f"demo: {tp.source}, {bead.name} bead {bead.width:g} x {bead.height:g} mm")
        print(f"  deposit    {cmp['deposit_volume_mm3']:,.1f} mm^3, {cmp['pore_count']} pores")
        print(f"  vs CAD     void {cmp['void_percent']:.2f} %, overbuild {cmp['overbuild_percent']:.2f} %, "
              f"deviation rms {cmp['deviation_mm']['rms']:.3f} mm")
        hits = sorted({c["line"] for c in collide["collisions"]})
        print(f"  nozzle     {len(collide['collisions'])} collision(s) with the clamp on lines "
              f"{', '.join(map(str, hits[:12]))}{' ...' if len(hits) > 12 else ''}" if hits else "  nozzle     no collision")
        heat = summary["thermal"]
        print(f"  heat       peak {heat['max_peak_temperature_C']:,.0f} C, interlayer up to "
              f"{heat['max_interlayer_temperature_C']:,.0f} C, melt pool up to {heat['max_melt_pool_width_mm']:.2f} mm")
        print(f"  report     {page['report_html']}")
        print(f"  wrote {len(summary['outputs'])} files under {out}/")
    return summary
