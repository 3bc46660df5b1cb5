#!/usr/bin/env python3
"""Plots `tidepool bench ibl`'s glossy CSV: each level's error against samples per texel, and the worst level's
error against GPU ms, for environment, lobe and MIS sampling."""
import csv
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main(csv_path, png_path):
    rows = list(csv.DictReader(open(csv_path)))
    device = rows[0]["device"] if rows else ""
    size = f'{rows[0]["map_width"]} wide, {rows[0]["levels"]} levels, sky {rows[0]["sky_width"]}' if rows else ""
    per_level = defaultdict(list)  # (sampling, level) -> rows
    for r in rows:
        per_level[(r["sampling"], int(r["level"]))].append(r)
    styles = {"mis": "-", "environment": "--", "lobe": ":"}
    fig, (left, right) = plt.subplots(1, 2, figsize=(13, 5))
    for (sampling, level), rs in sorted(per_level.items()):
        rs.sort(key=lambda r: int(r["samples"]))
        e = float(rs[0]["exponent"])
        left.plot([int(r["samples"]) for r in rs], [float(r["rms_error"]) for r in rs], styles.get(sampling, "-"),
                  marker="o", markersize=3, color=f"C{level}", label=f"{sampling}, level {level} (e {e:.0f})")
    worst = defaultdict(dict)  # sampling -> samples -> (ms, worst rms over levels)
    for r in rows:
        ms, err = float(r["prefilter_ms"]), float(r["rms_error"])
        prev = worst[r["sampling"]].get(int(r["samples"]), (ms, 0.0))
        worst[r["sampling"]][int(r["samples"])] = (ms, max(prev[1], err))
    for sampling, by_samples in sorted(worst.items()):
        pts = sorted(by_samples.items())
        right.plot([p[1][0] for p in pts], [p[1][1] for p in pts], styles.get(sampling, "-"), marker="o", label=sampling)
        for n, (ms, err) in pts:
            right.annotate(str(n), (ms, err), textcoords="offset points", xytext=(3, 3), fontsize=6)
    for ax in (left, right):
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.grid(True, which="both", alpha=0.3)
    left.set_xlabel("samples per texel")
    left.set_ylabel("RMS error / level mean")
    left.legend(fontsize=6, ncol=3)
    right.set_xlabel("GPU ms of the whole map (CDFs and every level)")
    right.set_ylabel("worst level's RMS error / its mean")
    right.legend()
    fig.suptitle(f"tidepool bench ibl, glossy prefilter ({size}), on {device}")
    fig.tight_layout()
    fig.savefig(png_path, dpi=110, format="png")


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
