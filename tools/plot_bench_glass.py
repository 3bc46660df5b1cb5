#!/usr/bin/env python3
"""Plots `tidepool bench glass` CSV: error against the reference and GPU ms of the glass passes, per binary-search step count."""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main(csv_path, png_path):
    rows = list(csv.DictReader(open(csv_path)))
    device = rows[0]["device"] if rows else ""
    size = f'{rows[0]["width"]}x{rows[0]["height"]}' if rows else ""
    steps = [int(r["steps"]) for r in rows]
    fig, (left, right) = plt.subplots(1, 2, figsize=(11, 4.5))
    left.plot(steps, [float(r["rmse"]) for r in rows], marker="o", label="RMSE over the glass pixels")
    left.plot(steps, [float(r["max_error"]) for r in rows], marker="s", alpha=0.6, label="largest error")
    left.set_xscale("log", base=2)
    left.set_yscale("log")
    left.set_xlabel("binary-search steps")
    left.set_ylabel("tonemapped error against the reference (0..1)")
    left.grid(True, which="both", alpha=0.3)
    left.legend(fontsize=8)
    ms = [float(r["glass_ms"]) for r in rows]
    right.plot(ms, [float(r["rmse"]) for r in rows], marker="o")
    for s, x, r in zip(steps, ms, rows):
        right.annotate(str(s), (x, float(r["rmse"])), textcoords="offset points", xytext=(4, 4), fontsize=8)
    right.set_yscale("log")
    right.set_xlabel("GPU ms of the glass passes (back faces + front)")
    right.set_ylabel("RMSE over the glass pixels")
    right.grid(True, which="both", alpha=0.3)
    fig.suptitle(f"tidepool bench glass, {size}, on {device} (numbers: search steps)")
    fig.tight_layout()
    fig.savefig(png_path, dpi=110, format="png")


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
