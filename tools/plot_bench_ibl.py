#!/usr/bin/env python3
"""Plots `tidepool bench ibl` CSV: SH9 irradiance error against samples and against GPU ms, importance and uniform sampling."""
import csv
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main(csv_path, png_path):
    rows = list(csv.DictReader(open(csv_path)))
    device = rows[0]["device"] if rows else ""
    size = f'{rows[0]["width"]}x{rows[0]["height"]}' if rows else ""
    cdf = float(rows[0]["cdf_ms"]) if rows else 0.0
    series = defaultdict(list)
    for r in rows:
        series[r["sampling"]].append(r)
    fig, (left, right) = plt.subplots(1, 2, figsize=(12, 5))
    for sampling, rs in sorted(series.items()):
        rs.sort(key=lambda r: int(r["samples"]))
        err = [float(r["rms_error"]) for r in rs]
        left.plot([int(r["samples"]) for r in rs], err, marker="o", label=sampling)
        right.plot([float(r["sh_ms"]) for r in rs], err, marker="o", label=sampling)
        for r in rs:
            right.annotate(r["samples"], (float(r["sh_ms"]), float(r["rms_error"])), textcoords="offset points",
                           xytext=(3, 3), fontsize=6)
    for ax in (left, right):
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_ylabel("irradiance error (worst normal, / brightest; RMS over rotations)")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend()
    left.set_xlabel("samples")
    right.set_xlabel(f"GPU ms of the SH9 estimate (CDF build once: {cdf:.2f} ms)")
    fig.suptitle(f"tidepool bench ibl, procedural sky with sun {size}, on {device}")
    fig.tight_layout()
    fig.savefig(png_path, dpi=110, format="png")


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
