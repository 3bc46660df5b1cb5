#!/usr/bin/env python3
"""Plots `tidepool bench ssao` CSV: mean AO error against GPU time of the AO passes, Pareto front and presets marked."""
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
    fig, ax = plt.subplots(figsize=(9, 6))
    series = defaultdict(list)
    for r in rows:
        if r["preset"] == "0":
            series[(r["blur"], r["resolution"])].append(r)
    markers = {"full": "o", "half": "s"}
    for (blur, resolution), rs in sorted(series.items()):
        rs.sort(key=lambda r: int(r["kernel"]))
        ax.plot([float(r["ao_ms"]) for r in rs], [float(r["mae"]) for r in rs], marker=markers[resolution],
                label=f"blur {blur}, {resolution} resolution", alpha=0.8)
        for r in rs:
            ax.annotate(r["kernel"], (float(r["ao_ms"]), float(r["mae"])), textcoords="offset points", xytext=(3, 3),
                        fontsize=6)
    front = sorted((float(r["ao_ms"]), float(r["mae"])) for r in rows if r["pareto"] == "1")
    if front:
        ax.step([f[0] for f in front], [f[1] for f in front], where="post", color="black", lw=1, ls="--",
                label="Pareto front")
    for r in rows:
        if r["preset"] == "1":
            ax.scatter(float(r["ao_ms"]), float(r["mae"]), marker="*", s=160, color="crimson", zorder=5)
            ax.annotate(r["case"], (float(r["ao_ms"]), float(r["mae"])), textcoords="offset points", xytext=(6, -10),
                        fontsize=8, color="crimson")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("GPU ms of the AO passes (SSAO, blur, upsample, apply)")
    ax.set_ylabel("mean |AO - ray-traced AO| over surface pixels")
    ax.set_title(f"tidepool bench ssao, {size}, on {device}\n(numbers: kernel samples; stars: presets)")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(png_path, dpi=110, format="png")


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
