"""Plots a `voxgi study --frames` CSV: three panels over the frame number, one colour per
technique. Top: each frame's error against its reference, a black frame's dashed. Middle: the
flicker of each frame's change from the one before against the reference's, a sequence that holds
still dashed and the reference's own noise dotted. Bottom: each frame's cost, updated from the
frame before (solid) and rebuilt from scratch (dashed), on a log axis. Called by voxgi
(embedded); usable by hand:
/usr/bin/python3 tools/plot_study_frames.py study.csv study.png "relative MSE" "title"
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.ticker import MaxNLocator  # noqa: E402


def column(rows, name):
    """(frames, values) of the rows where the column is filled."""
    kept = [r for r in rows if r[name] != ""]
    return [int(r["frame"]) for r in kept], [float(r[name]) for r in kept]


def main(csv_path, png_path, metric_label, title):
    with open(csv_path, newline="") as f:
        rows = list(csv.DictReader(f))
    techniques = []
    for r in rows:
        if r["technique"] not in techniques:
            techniques.append(r["technique"])
    fig, (error, flicker, cost) = plt.subplots(3, 1, figsize=(8, 9), dpi=110, sharex=True)
    for technique in techniques:
        mine = [r for r in rows if r["technique"] == technique]
        line, = error.plot(*column(mine, "error"), marker="o", markersize=3, label=technique)
        colour = line.get_color()
        flicker.plot(*column(mine, "flicker"), marker="o", markersize=3, color=colour,
                     label=technique)
        frames, seconds = column(mine, "seconds")
        cost.plot(frames, [1e3 * s for s in seconds], marker="o", markersize=3, color=colour,
                  label=technique + ", updated")
        frames, seconds = column(mine, "rebuild_seconds")
        cost.plot(frames, [1e3 * s for s in seconds], linestyle="--", color=colour,
                  label=technique + ", rebuilt")
    # The baselines are the reference's, the same for every technique: the first's rows.
    first = [r for r in rows if r["technique"] == techniques[0]]
    error.plot(*column(first, "black_error"), linestyle="--", color="grey", label="black")
    flicker.plot(*column(first, "held"), linestyle="--", color="grey",
                 label="held (no change)")
    if any(r["noise"] != "" for r in first):
        flicker.plot(*column(first, "noise"), linestyle=":", color="grey",
                     label="reference noise")
    error.set_ylabel(metric_label + " per frame")
    error.set_yscale("log")
    flicker.set_ylabel("flicker (change against the reference's)")
    cost.set_ylabel("ms per frame")
    cost.set_yscale("log")
    cost.set_xlabel("frame")
    cost.xaxis.set_major_locator(MaxNLocator(integer=True))
    for ax in (error, flicker, cost):
        ax.grid(True, which="both", linewidth=0.3)
        ax.legend(fontsize=7, ncol=2)
    error.set_title(title, fontsize=9)
    fig.tight_layout()
    fig.savefig(png_path)


if __name__ == "__main__":
    main(*sys.argv[1:])
