#!/usr/bin/env python3
"""Plots `tidepool bench sim` CSV: error against time per step, and throughput."""
import csv
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main(csv_path, png_path):
    rows = list(csv.DictReader(open(csv_path)))
    by_method = defaultdict(list)
    for r in rows:
        by_method[r["method"]].append(r)
    device = rows[0]["device"] if rows else ""
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(13, 5))
    for method, rs in by_method.items():
        rs.sort(key=lambda r: int(r["grid"]))
        ms = [float(r["ms_per_step"]) for r in rs]
        err = [float(r["error_continuous"]) for r in rs]
        grids = [int(r["grid"]) for r in rs]
        ax1.plot(ms, err, marker="o", label=method)
        for x, y, g in zip(ms, err, grids):
            ax1.annotate(f"{g}²", (x, y), textcoords="offset points", xytext=(4, 4), fontsize=7)
        ax2.plot(grids, [float(r["mcells_per_s"]) for r in rs], marker="o", label=method)
    ax1.set_xscale("log")
    ax1.set_yscale("log")
    ax1.set_xlabel("time per step (ms)")
    ax1.set_ylabel("max error vs continuous mode")
    ax1.set_title("error against time")
    ax1.grid(True, which="both", alpha=0.3)
    ax1.legend(fontsize=8)
    ax2.set_xscale("log", base=2)
    ax2.set_xlabel("grid side")
    ax2.set_ylabel("Mcells/s")
    ax2.set_title("throughput")
    ax2.grid(True, which="both", alpha=0.3)
    fig.suptitle(f"tidepool bench sim on {device}")
    fig.tight_layout()
    fig.savefig(png_path, dpi=110, format="png")


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
