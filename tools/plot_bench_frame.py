#!/usr/bin/env python3
"""Plots `tidepool bench frame` CSV: GPU ms per frame of each scene variant with skipping off and on."""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main(csv_path, png_path):
    rows = list(csv.DictReader(open(csv_path)))
    device = rows[0]["device"] if rows else ""
    size = f'{rows[0]["width"]}x{rows[0]["height"]}' if rows else ""
    variants = list(dict.fromkeys(r["variant"] for r in rows))
    ms = {(r["variant"], r["skipping"]): float(r["gpu_ms"]) for r in rows}
    fig, ax = plt.subplots(figsize=(9, 5))
    width = 0.4
    for k, (skipping, label) in enumerate([("0", "nothing skipped"), ("1", "skipping")]):
        xs = [i + (k - 0.5) * width for i in range(len(variants))]
        ax.bar(xs, [ms.get((v, skipping), 0.0) for v in variants], width, label=label)
    ax.set_xticks(range(len(variants)))
    ax.set_xticklabels(variants, rotation=20, ha="right")
    ax.set_ylabel("GPU ms per frame (median)")
    ax.set_title(f"tidepool bench frame, {size}, on {device}")
    ax.grid(True, axis="y", alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(png_path, dpi=110, format="png")


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
