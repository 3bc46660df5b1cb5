#!/usr/bin/env python3
"""Plots `tidepool bench passes` CSV: each pass's median wall ms, stacked, per resolution, with the frame's fps."""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main(csv_path, png_path):
    rows = list(csv.DictReader(open(csv_path)))
    device = rows[0]["device"] if rows else ""
    sizes = list(dict.fromkeys(f'{r["width"]}x{r["height"]}' for r in rows))
    passes = list(dict.fromkeys(r["pass"] for r in rows))
    wall = {(f'{r["width"]}x{r["height"]}', r["pass"]): float(r["wall_ms"]) for r in rows}
    fps = {f'{r["width"]}x{r["height"]}': float(r["fps"]) for r in rows}
    fig, ax = plt.subplots(figsize=(9, 5))
    left = [0.0] * len(sizes)
    colours = plt.get_cmap("tab20")
    for k, name in enumerate(passes):
        widths = [wall.get((size, name), 0.0) for size in sizes]
        ax.barh(range(len(sizes)), widths, left=left, label=name, color=colours(k % 20))
        left = [a + b for a, b in zip(left, widths)]
    ax.set_yticks(range(len(sizes)))
    ax.set_yticklabels([f"{size}\n{fps[size]:.1f} fps" for size in sizes])
    ax.set_xlabel("wall ms per pass (median, each pass submitted on its own)")
    ax.set_title(f"tidepool bench passes, on {device}")
    ax.grid(True, axis="x", alpha=0.3)
    ax.legend(fontsize=7, ncol=2, loc="lower right")
    fig.tight_layout()
    fig.savefig(png_path, dpi=110, format="png")


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
