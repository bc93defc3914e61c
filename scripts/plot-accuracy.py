#!/usr/bin/python3
"""Draws the plots of `lucent bench accuracy` from its CSV.

  plot-accuracy.py CSV OUTDIR

accuracy-pareto.png: relative RMSE against time, every setting a point, one
colour per scene, and each scene's Pareto front (the settings no other setting
beats on both error and time) as a line; left against the frame time, right
against preprocessing time plus one frame.
accuracy-knobs.png: one panel per knob, error against the knob's value, one
line per scene; the published scheme is drawn dashed in the samples panel.
"""
import csv
import sys
from collections import defaultdict
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def pareto(points):
    front, best = [], float("inf")
    for t, e in sorted(points):
        if e < best:
            front.append((t, e))
            best = e
    return front


def main(csv_file, out_dir):
    rows = list(csv.DictReader(open(csv_file)))
    if not rows:
        sys.exit(f"plot-accuracy: {csv_file}: no rows")
    out = Path(out_dir)
    scenes = sorted({r["scene"] for r in rows})
    colours = {s: plt.cm.tab10(i % 10) for i, s in enumerate(scenes)}

    fig, axes = plt.subplots(1, 2, figsize=(12, 5))
    for ax, label, cost in (
        (axes[0], "median frame time (ms)", lambda r: float(r["frame_ms"])),
        (axes[1], "preprocessing + one frame (s)", lambda r: float(r["preprocess_s"]) + float(r["frame_ms"]) / 1e3),
    ):
        for scene in scenes:
            mine = [r for r in rows if r["scene"] == scene]
            pts = [(cost(r), 100 * float(r["rel_rmse"])) for r in mine]
            ax.scatter(*zip(*pts), s=12, color=colours[scene], alpha=0.5)
            ax.plot(*zip(*pareto(pts)), color=colours[scene], label=scene)
            published = [(cost(r), 100 * float(r["rel_rmse"])) for r in mine if r["knob"] == "published"]
            if published:
                ax.scatter(*zip(*published), s=30, marker="x", color=colours[scene])
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel(label)
        ax.set_ylabel("relative RMSE against the reference (%)")
        ax.grid(True, which="both", alpha=0.3)
    axes[0].legend(title="scene (x: published scheme)")
    fig.suptitle("lucent bench accuracy: error against time, Pareto fronts")
    fig.tight_layout()
    fig.savefig(out / "accuracy-pareto.png", dpi=110)

    knobs = [k for k in dict.fromkeys(r["knob"] for r in rows) if k != "published"]
    cols = min(4, max(len(knobs), 1))
    nrows = (len(knobs) + cols - 1) // cols
    fig, axes = plt.subplots(nrows, cols, figsize=(4 * cols, 3.5 * nrows), squeeze=False)
    for ax, knob in zip(axes.flat, knobs):
        for scene in scenes:
            series = defaultdict(list)
            for r in rows:
                if r["scene"] == scene and (r["knob"] == knob or (knob == "samples" and r["knob"] == "published")):
                    series[r["knob"]].append((float(r["value"]), 100 * float(r["rel_rmse"])))
            for name, pts in series.items():
                pts.sort()
                ax.plot(*zip(*pts), marker="o", ms=3, color=colours[scene],
                        linestyle="--" if name == "published" else "-",
                        label=scene if name == knob else None)
        ax.set_title(knob + (" (dashed: published)" if knob == "samples" else ""))
        if knob in ("samples", "cutoff", "projection-directions", "heuristic-directions"):
            ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_ylabel("relative RMSE (%)")
        ax.grid(True, which="both", alpha=0.3)
    for ax in list(axes.flat)[len(knobs):]:
        ax.axis("off")
    axes.flat[0].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(out / "accuracy-knobs.png", dpi=110)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])
