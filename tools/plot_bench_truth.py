#!/usr/bin/env python3
"""Plots `tidepool bench truth` CSV: the raster's error against the path-traced truth, per scene and region."""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

REGIONS = ["pool", "objects", "ground", "sky"]


def main(csv_path, png_path):
    rows = list(csv.DictReader(open(csv_path)))
    device = rows[0]["device"] if rows else ""
    size = f'{rows[0]["width"]}x{rows[0]["height"]}' if rows else ""
    fig, ax = plt.subplots(figsize=(max(6, 1.6 * len(rows) + 2), 4.5))
    width = 0.8 / (len(REGIONS) + 1)
    for k, name in enumerate(["frame"] + REGIONS):
        column = "rmse" if name == "frame" else f"rmse_{name}"
        xs = [i + (k - len(REGIONS) / 2) * width for i in range(len(rows))]
        ax.bar(xs, [float(r[column]) for r in rows], width, label=name)
    ax.set_xticks(range(len(rows)))
    ax.set_xticklabels([r["scene"] for r in rows], rotation=20, ha="right", fontsize=8)
    ax.set_ylabel("tonemapped RMSE against the truth (0..1)")
    ax.grid(True, axis="y", alpha=0.3)
    ax.legend(fontsize=8)
    fig.suptitle(f"tidepool bench truth, {size}, raster on {device}")
    fig.tight_layout()
    fig.savefig(png_path, dpi=110, format="png")


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
