#!/usr/bin/python3
"""One scanline of several renders against their reference, as [Martin 2012, Fig. 5.4] plots it.

    tools/plot_scanline.py OUT.png LABEL=COMPARE.json [LABEL=COMPARE.json ...]

Each COMPARE.json is written by `voxgi compare TEST REF --json COMPARE.json --scanline ROW`
against the same reference; the first one's reference is drawn as "reference".
"""
import json
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main(argv):
    if len(argv) < 3 or any("=" not in a for a in argv[2:]):
        sys.exit(__doc__)
    out, runs = argv[1], [a.split("=", 1) for a in argv[2:]]
    fig, ax = plt.subplots(figsize=(6.4, 3.6))
    reference = None
    for label, path in runs:
        with open(path) as f:
            scan = json.load(f)["scanline"]
        if reference is None:
            reference = scan
            ax.plot(scan["reference"], color="black", linewidth=2, label="reference (path tracer)")
        elif scan["row"] != reference["row"]:
            sys.exit(f"{path}: row {scan['row']}, the first file's is {reference['row']}")
        ax.plot(scan["test"], linewidth=1.2, label=label)
    ax.set_xlabel("pixel")
    ax.set_ylabel("luminance (linear)")
    ax.set_title(f"row {reference['row']}")
    ax.legend()
    fig.tight_layout()
    fig.savefig(out, dpi=110)


if __name__ == "__main__":
    main(sys.argv)
