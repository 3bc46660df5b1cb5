#!/usr/bin/env python3
"""Plots `tidepool bench tiles` CSV: ms per step against the active fraction, and active/full."""
import csv
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main(csv_path, png_path):
    rows = list(csv.DictReader(open(csv_path)))
    by_grid = defaultdict(list)
    for r in rows:
        by_grid[int(r["grid"])].append(r)
    device = rows[0]["device"] if rows else ""
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(13, 5))
    for (grid, rs), colour in zip(sorted(by_grid.items()), plt.rcParams["axes.prop_cycle"].by_key()["color"]):
        rs.sort(key=lambda r: float(r["active_fraction"]))
        f = [float(r["active_fraction"]) for r in rs]
        ax1.plot(f, [float(r["ms_active"]) for r in rs], marker="o", color=colour, label=f"{grid}² active list")
        ax1.plot(f, [float(r["ms_full"]) for r in rs], linestyle="--", color=colour, label=f"{grid}² all tiles")
        ax1.plot(f, [float(r["ms_one_per_dispatch"]) for r in rs], linestyle=":", color=colour,
                 label=f"{grid}² one step per dispatch")
        ax2.plot(f, [float(r["active_over_full"]) for r in rs], marker="o", color=colour, label=f"{grid}²")
    ax1.set_yscale("log")
    ax1.set_xlabel("fraction of tiles active")
    ax1.set_ylabel("ms per step")
    ax1.set_title("time per step")
    ax1.grid(True, which="both", alpha=0.3)
    ax1.legend(fontsize=7)
    ax2.axhline(1.0, color="black", linewidth=0.8)
    ax2.set_xlabel("fraction of tiles active")
    ax2.set_ylabel("active list / all tiles (time)")
    ax2.set_title("when the active list pays (below 1)")
    ax2.grid(True, alpha=0.3)
    ax2.legend(fontsize=8)
    fig.suptitle(f"tidepool bench tiles on {device}")
    fig.tight_layout()
    fig.savefig(png_path, dpi=110, format="png")


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
