#!/usr/bin/env python3
"""Plots `tidepool bench wake` CSV: the wake's high-wavenumber share, steepest slope and crest against ms per step."""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main(csv_path, png_path):
    rows = list(csv.DictReader(open(csv_path)))
    device = rows[0]["device"] if rows else ""
    measures = [("high_share", "variance share above half Nyquist"), ("max_slope", "steepest slope"),
                ("crest_m", "highest crest (m)")]
    fig, axes = plt.subplots(1, 3, figsize=(14, 4.5))
    # One colour per forcing, widening, widening near the wave speed, grid
    # damping and slope limit (older CSVs have no forcing column: the column
    # forcing; none has a widening for it; older ones have no slope limit: the
    # limiter off, and no near-speed widening: off).
    def series_of(r):
        return (r.get("forcing", "column"), r.get("spread_depth_factor", ""), r.get("near_speed_widening", ""),
                float(r["grid_damping"]), float(r.get("slope_limit") or 0))

    series = sorted({series_of(r) for r in rows})
    markers = {"half": "o", "submerged": "s"}
    colours = plt.get_cmap("viridis")
    # A log axis over less than a decade labels its minor ticks on top of each other.
    ms = [float(r["ms_per_step"]) for r in rows]
    time_axis = "log" if ms and max(ms) > 10 * min(ms) else "linear"
    for ax, (key, label) in zip(axes, measures):
        for k, (forcing, widening, near, kappa, limit) in enumerate(series):
            name = f"{forcing}, widening {widening}" if widening else forcing
            if near:
                name += f", near c {near}"
            if limit:
                name += f", slope limit {limit:g}"
            for immersion, marker in markers.items():
                picked = [r for r in rows
                          if series_of(r) == (forcing, widening, near, kappa, limit) and r["immersion"] == immersion]
                if not picked:
                    continue
                ax.scatter([float(r["ms_per_step"]) for r in picked], [float(r[key]) for r in picked],
                           marker=marker, color=colours(k / max(1, len(series) - 1)),
                           label=f"{name}, kappa {kappa:g}/s, {immersion}")
                for r in picked:
                    ax.annotate(f'{r["grid"]} {float(r["speed_fraction"]):g}c',
                                (float(r["ms_per_step"]), float(r[key])), fontsize=6)
        ax.set_xscale(time_axis)
        ax.set_yscale("log")
        ax.set_xlabel("wall ms per step (forcing and step)")
        ax.set_ylabel(label)
        ax.grid(True, which="both", alpha=0.3)
    axes[0].axhline(0.02, color="red", lw=0.8)
    axes[1].axhline(1.0, color="red", lw=0.8)
    axes[2].axhline(0.1, color="red", lw=0.8)
    axes[0].legend(fontsize=7)
    fig.suptitle(f"tidepool bench wake: the default scene's sphere crossing its pool, on {device}")
    fig.tight_layout()
    fig.savefig(png_path, dpi=110, format="png")


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
