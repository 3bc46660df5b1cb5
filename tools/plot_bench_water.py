#!/usr/bin/env python3
"""Plots `tidepool bench water` CSV: image error against GPU time per refraction mode, and floor position error."""
import csv
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main(csv_path, png_path):
    rows = list(csv.DictReader(open(csv_path)))
    device = rows[0]["device"] if rows else ""
    series = defaultdict(list)
    for r in rows:
        series[(r["view"], r["mode"])].append(r)
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(13, 5))
    markers = {"accurate": "o", "apparent": "s"}
    for (view, mode), rs in sorted(series.items()):
        rs.sort(key=lambda r: int(r["width"]) * int(r["height"]))
        ms = [float(r["refraction_ms"]) for r in rs]
        err = [float(r["rmse_water"]) for r in rs]
        ax1.plot(ms, err, marker=markers.get(mode, "x"), label=f"{mode}, {view}")
        for x, y, r in zip(ms, err, rs):
            ax1.annotate(f'{r["width"]}x{r["height"]}', (x, y), textcoords="offset points", xytext=(4, 4), fontsize=6)
        pixels = [int(r["width"]) * int(r["height"]) for r in rs]
        ax2.plot(pixels, [float(r["floor_error_px"]) for r in rs], marker=markers.get(mode, "x"), label=f"{mode}, {view}")
    ax1.set_xscale("log")
    ax1.set_xlabel("GPU ms of the water passes (water + underwater copy)")
    ax1.set_ylabel("RMSE on the water vs reference (tonemapped, 0..1)")
    ax1.set_title("error against time")
    ax1.grid(True, which="both", alpha=0.3)
    ax1.legend(fontsize=7)
    ax2.set_xscale("log")
    ax2.set_yscale("log")
    ax2.set_xlabel("pixels")
    ax2.set_ylabel("mean floor position error (pixels)")
    ax2.set_title("where the floor is read through the water")
    ax2.grid(True, which="both", alpha=0.3)
    ax2.legend(fontsize=7)
    fig.suptitle(f"tidepool bench water on {device}")
    fig.tight_layout()
    fig.savefig(png_path, dpi=110, format="png")


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
