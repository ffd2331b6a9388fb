"""Plots of study tables (matplotlib, headless), written atomically."""

from __future__ import annotations

import numpy as np


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
