"""Plots a `voxgi study` CSV: error against time on log axes, one marker per technique, the
Pareto front of all points as a solid staircase, each technique's own front dashed with its points
labelled by their swept values, each point's own direct light without its indirect term as a
hollow twin, the trivial answers (black, a constant at the reference's mean) as dashed horizontal
lines, and the reference's noise floor as a dotted line. Called by voxgi (embedded); usable by hand:
/usr/bin/python3 tools/plot_study.py study.csv study.png rel_mse "relative MSE" "title" [floor]
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main(csv_path, png_path, metric, metric_label, title, noise_floor=None):
    with open(csv_path, newline="") as f:
        every = list(csv.DictReader(f))
    rows = [r for r in every if not r["technique"].startswith("baseline_")]
    baselines = [r for r in every if r["technique"].startswith("baseline_")]
    fig, ax = plt.subplots(figsize=(8, 5.5), dpi=110)
    markers = {"vct": "o", "path": "s"}
    for technique in sorted({r["technique"] for r in rows}):
        points = [r for r in rows if r["technique"] == technique]
        x = [float(r["seconds"]) for r in points]
        y = [float(r[metric]) for r in points]
        dots = ax.scatter(x, y, marker=markers.get(technique, "^"), s=28, alpha=0.8,
                          label=technique)
        direct = [r for r in points if r.get("direct_only_" + metric, "") != ""]
        if direct:
            ax.scatter([float(r["seconds"]) for r in direct],
                       [float(r["direct_only_" + metric]) for r in direct],
                       marker=markers.get(technique, "^"), s=28, facecolors="none",
                       edgecolors=dots.get_facecolor()[0], linewidths=0.8,
                       label=technique + ", direct light only")
        # The technique's own front, dashed; only its points are labelled, to stay readable
        # (every point is in the CSV).
        own = sorted((r for r in points if r["pareto_technique"] == "1"),
                     key=lambda r: float(r["seconds"]))
        ax.step([float(r["seconds"]) for r in own], [float(r[metric]) for r in own],
                where="post", color=dots.get_facecolor()[0], linestyle="--", linewidth=0.8)
        for r in own:
            ax.annotate(r["label"], (float(r["seconds"]), float(r[metric])), fontsize=6,
                        xytext=(3, 3), textcoords="offset points")
    front = sorted((r for r in rows if r["pareto"] == "1"), key=lambda r: float(r["seconds"]))
    if front:
        ax.step([float(r["seconds"]) for r in front], [float(r[metric]) for r in front],
                where="post", color="black", linewidth=1, label="Pareto front (all)")
    for r, style in zip(baselines, ("-.", "--", ":")):
        if r.get(metric, "") != "":
            ax.axhline(float(r[metric]), color="dimgrey", linestyle=style, linewidth=0.9,
                       label="baseline: " + r["label"])
    if noise_floor is not None:
        ax.axhline(float(noise_floor), color="grey", linestyle=":",
                   label="reference noise floor")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("time per frame, seconds (median)")
    ax.set_ylabel(metric_label + " against the reference")
    ax.set_title(title, fontsize=9)
    ax.grid(True, which="both", linewidth=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(png_path)


if __name__ == "__main__":
    if len(sys.argv) not in (6, 7):
        sys.exit("usage: plot_study.py CSV PNG METRIC LABEL TITLE [NOISE_FLOOR]")
    main(*sys.argv[1:])
