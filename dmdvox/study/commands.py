"""`dmdvox study overlap` and `dmdvox study sweep`: parameter grids run as independent tasks."""

from __future__ import annotations

import csv
import io
import math
import sys

import numpy as np

from ..errors import DmdvoxError
from ..tasks import run_tasks
from .overlap import FLOW_ROW_KEYS, ROW_KEYS, OverlapCase, default_study_voxel, overlap_case

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


def add_overlap_options(p) -> None:
    """The options of ``dmdvox study overlap`` on an argparse (sub)parser."""
    from ..process.profiles import PROFILE_NAMES

    p.add_argument("--profile", default="parabola", choices=PROFILE_NAMES, help="bead cross-section (default parabola)")
    p.add_argument("--width", type=float, required=True, metavar="MM", help="bead width")
    p.add_argument("--height", type=float, default=None, metavar="MM",
                   help="bead height (with --area: from the area, the width and the profile)")
    p.add_argument("--area", type=float, default=None, metavar="MM2",
                   help="the beads' cross-section: the flow model lands them, mass conserved")
    p.add_argument("--model", default=None, choices=("union", "flow"),
                   help="union: beads where programmed, overlap lost; flow: beads land on the patch, mass "
                        "conserved (default: flow with --area, else union)")
    p.add_argument("--exponent", type=float, default=4.0, help="Lame profile exponent (default 4)")
    p.add_argument("--spacing", required=True, metavar="A:B:STEP", help="hatch spacings in mm (or one value)")
    p.add_argument("--layer-step", default=None, metavar="A:B:STEP",
                   help="layer steps in mm (or one value; default: the bead height)")
    p.add_argument("--layers", type=int, default=3, help="layers in each patch (default 3)")
    p.add_argument("--voxel", type=float, default=None, metavar="MM",
                   help="voxel size (default: width/40, at most height/8)")
    p.add_argument("--scheduler", default=None, metavar="ADDR",
                   help="dask scheduler address (tcp://host:port); default: local processes")
    p.add_argument("--json", action="store_true", help="print one JSON object on stdout")
    p.add_argument("--csv", default=None, metavar="FILE", help="write the table as CSV")
    p.add_argument("--plot", default=None, metavar="FILE.png", help="plot porosity and waviness against overlap ratio")


def overlap_cases(args) -> list[OverlapCase]:
    """The study's cases, spacing-major then layer step, from the parsed options."""
    from ..process.beads import section_height
    from ..process.profiles import BeadProfile, profile_code

    model = args.model or ("flow" if args.area is not None else "union")
    if args.area is not None:
        if model == "union":
            raise DmdvoxError("--area sets the material the flow model lands; the union model takes --height")
        if args.height is not None:
            raise DmdvoxError("--area and --height both set the bead's height: give one")
        height = float(section_height(profile_code(args.profile), np.array([float(args.width)]),
                                      np.array([float(args.area)]), args.exponent)[0])
    elif args.height is None:
        raise DmdvoxError("give --height (or --area for a flow study)")
    else:
        height = args.height
    bead = BeadProfile(args.profile, args.width, height, args.exponent)
    spacings = parse_range(args.spacing, "--spacing")
    steps = [bead.height] if args.layer_step is None else parse_range(args.layer_step, "--layer-step")
    voxel = default_study_voxel(bead) if args.voxel is None else float(args.voxel)
    return [OverlapCase(bead.name, bead.width, bead.height, bead.exponent, float(d), float(s), int(args.layers), voxel,
                        model=model, area=args.area)
            for d in spacings for s in steps]


def rows_to_csv(rows: list[dict], keys: tuple[str, ...] | list[str]) -> str:
    buffer = io.StringIO()
    writer = csv.DictWriter(buffer, fieldnames=list(keys), lineterminator="\n")
    writer.writeheader()
    for row in rows:
        writer.writerow({k: repr(v) if isinstance(v, float) else v for k, v in row.items()})
    return buffer.getvalue()


def plot_overlap(rows: list[dict], width: float, path: str, union_rows: list[dict] | None = None) -> None:
    """Porosity and waviness against overlap ratio, one line per layer step; the flat-top
    spacing (as an overlap ratio) marked on both panels; a flow study also draws the layer
    height against A / d, and the geometric union of the same cases dashed beside it. Written
    atomically."""
    import matplotlib

    matplotlib.use("Agg")  # headless: no display on build machines and workers
    import matplotlib.pyplot as plt

    from ..io.atomic import atomic_path

    flow = "layer_height_mm" in rows[0]
    fig, axes = plt.subplots(3 if flow else 2, 1, sharex=True, figsize=(7.0, 9.0 if flow else 6.5))
    ax_p, ax_w = axes[0], axes[1]
    steps = sorted({r["layer_step_mm"] for r in rows})
    for step in steps:
        sel = sorted((r for r in rows if r["layer_step_mm"] == step), key=lambda r: r["overlap_ratio"])
        ratio = np.array([r["overlap_ratio"] for r in sel], np.float64)
        label = f"{'flow, ' if flow else ''}layer step {step:g} mm"
        line = ax_p.plot(ratio, [r["porosity_percent"] for r in sel], "o-", ms=3, label=label)[0]
        ax_w.plot(ratio, [r["waviness_mm"] for r in sel], "o-", ms=3, label=label, color=line.get_color())
        if flow:
            axes[2].plot(ratio, [r["layer_height_mm"] for r in sel], "o-", ms=3, label=label, color=line.get_color())
        if union_rows:
            usel = sorted((r for r in union_rows if r["layer_step_mm"] == step), key=lambda r: r["overlap_ratio"])
            uratio = [r["overlap_ratio"] for r in usel]
            ulabel = f"union, layer step {step:g} mm"
            ax_p.plot(uratio, [r["porosity_percent"] for r in usel], "s--", ms=3, label=ulabel,
                      color=line.get_color(), alpha=0.6)
            ax_w.plot(uratio, [r["waviness_mm"] for r in usel], "s--", ms=3, label=ulabel, color=line.get_color(),
                      alpha=0.6)
    if flow:
        ratio = np.linspace(min(r["overlap_ratio"] for r in rows), max(r["overlap_ratio"] for r in rows), 200)
        axes[2].plot(ratio, rows[0]["area_mm2"] / (width * (1.0 - ratio)), color="0.3", lw=1, label="A / d")
        axes[2].set_ylabel("layer height (mm)")
        axes[2].legend(fontsize=8)
        axes[2].grid(True, alpha=0.3)
    flat_top = 1.0 - rows[0]["flat_top_spacing_mm"] / width
    for ax in (ax_p, ax_w):
        ax.axvline(flat_top, color="0.3", ls="--", lw=1,
                   label=f"flat-top spacing {rows[0]['flat_top_spacing_mm']:.3g} mm")
        ax.grid(True, alpha=0.3)
    ax_p.set_ylabel("lack of fusion below top surface (%)" if flow else "porosity below top surface (%)")
    ax_w.set_ylabel("waviness, peak-to-valley (mm)")
    axes[-1].set_xlabel("overlap ratio 1 - spacing / width")
    ax_p.legend(fontsize=8)
    fig.tight_layout()
    with atomic_path(path) as tmp:
        fig.savefig(tmp, dpi=120, format="png")
    plt.close(fig)


def run_study_overlap(args) -> dict:
    """``dmdvox study overlap``: one row per (spacing, layer step); ``{"rows": [...]}``."""
    from ..io.atomic import write_text

    import dataclasses

    cases = overlap_cases(args)
    flow = cases[0].model == "flow"
    keys = FLOW_ROW_KEYS if flow else ROW_KEYS
    # a flow study also runs the geometric union of the same beads, for the plot and the JSON
    union_cases = [dataclasses.replace(c, model="union", area=None) for c in cases] if flow else []
    results = run_tasks(overlap_case, cases + union_cases, args.scheduler, desc="overlap study")
    rows, union_rows = results[:len(cases)], results[len(cases):]
    if args.csv:
        write_text(args.csv, rows_to_csv(rows, keys))
    if args.plot:
        plot_overlap(rows, cases[0].width, args.plot, union_rows)
    if not args.json:
        print("  ".join(f"{k:>22}" for k in keys))
        for row in rows:
            print("  ".join(f"{row[k]:22.4f}" for k in keys))
        for path in (args.csv, args.plot):
            if path:
                print(f"wrote {path}", file=sys.stderr)
    out = {"model": cases[0].model, "rows": rows}
    if flow:
        out["union_rows"] = union_rows
    return out
