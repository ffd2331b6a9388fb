"""`dmdvox study overlap` and `dmdvox study sweep`: parameter grids run as independent tasks."""

from __future__ import annotations

import csv
import io
import math
import sys

import numpy as np

from ..errors import DmdvoxError
from .execute import run_tasks
from .overlap import ROW_KEYS, OverlapCase, default_study_voxel, overlap_case

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
    p.add_argument("--height", type=float, required=True, metavar="MM", help="bead height")
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
    from ..process.profiles import BeadProfile

    bead = BeadProfile(args.profile, args.width, args.height, args.exponent)
    spacings = parse_range(args.spacing, "--spacing")
    steps = [bead.height] if args.layer_step is None else parse_range(args.layer_step, "--layer-step")
    voxel = default_study_voxel(bead) if args.voxel is None else float(args.voxel)
    return [OverlapCase(bead.name, bead.width, bead.height, bead.exponent, float(d), float(s), int(args.layers), voxel)
            for d in spacings for s in steps]


def rows_to_csv(rows: list[dict], keys: tuple[str, ...] | list[str]) -> str:
    buffer = io.StringIO()
    writer = csv.DictWriter(buffer, fieldnames=list(keys), lineterminator="\n")
    writer.writeheader()
    for row in rows:
        writer.writerow({k: repr(v) if isinstance(v, float) else v for k, v in row.items()})
    return buffer.getvalue()


def plot_overlap(rows: list[dict], width: float, path: str) -> None:
    """Porosity and waviness against overlap ratio, one line per layer step; the flat-top
    spacing (as an overlap ratio) marked on both panels. Written atomically."""
    import matplotlib

    matplotlib.use("Agg")  # headless: no display on build machines and workers
    import matplotlib.pyplot as plt

    from ..io.atomic import atomic_path

    fig, (ax_p, ax_w) = plt.subplots(2, 1, sharex=True, figsize=(7.0, 6.5))
    steps = sorted({r["layer_step_mm"] for r in rows})
    for step in steps:
        sel = sorted((r for r in rows if r["layer_step_mm"] == step), key=lambda r: r["overlap_ratio"])
        ratio = np.array([r["overlap_ratio"] for r in sel], np.float64)
        label = f"layer step {step:g} mm"
        ax_p.plot(ratio, [r["porosity_percent"] for r in sel], "o-", ms=3, label=label)
        ax_w.plot(ratio, [r["waviness_mm"] for r in sel], "o-", ms=3, label=label)
    flat_top = 1.0 - rows[0]["flat_top_spacing_mm"] / width
    for ax in (ax_p, ax_w):
        ax.axvline(flat_top, color="0.3", ls="--", lw=1,
                   label=f"flat-top spacing {rows[0]['flat_top_spacing_mm']:.3g} mm")
        ax.grid(True, alpha=0.3)
    ax_p.set_ylabel("porosity below top surface (%)")
    ax_w.set_ylabel("waviness, peak-to-valley (mm)")
    ax_w.set_xlabel("overlap ratio 1 - spacing / width")
    ax_p.legend(fontsize=8)
    fig.tight_layout()
    with atomic_path(path) as tmp:
        fig.savefig(tmp, dpi=120, format="png")
    plt.close(fig)


def run_study_overlap(args) -> dict:
    """``dmdvox study overlap``: one row per (spacing, layer step); ``{"rows": [...]}``."""
    from ..io.atomic import write_text

    cases = overlap_cases(args)
    rows = run_tasks(overlap_case, cases, args.scheduler, desc="overlap study")
    if args.csv:
        write_text(args.csv, rows_to_csv(rows, ROW_KEYS))
    if args.plot:
        plot_overlap(rows, cases[0].width, args.plot)
    if not args.json:
        print("  ".join(f"{k:>19}" for k in ROW_KEYS))
        for row in rows:
            print("  ".join(f"{row[k]:19.4f}" for k in ROW_KEYS))
        for path in (args.csv, args.plot):
            if path:
                print(f"wrote {path}", file=sys.stderr)
    return {"rows": rows}
