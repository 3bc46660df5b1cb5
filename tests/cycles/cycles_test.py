#!/usr/bin/env python3
"""The ctest `cycles_reference`: every scene in tests/cycles/ against Blender Cycles.

    python3 tests/cycles/cycles_test.py --tidepool build/tidepool --outdir build/tests/cycles

For each scene: the reference's difference from Cycles within BOUND (the
noise included; what is left with both estimates' noise taken out in
quadrature is printed), and within their noise (NOISE_FACTOR times the
combined noise, plus FLOOR); the
raster's distance to Cycles printed, and held to RASTER_BOUND for the scenes
listed in raster_passing.txt. The figures are printed; any bound not met fails.
Conventions and the reasons for the numbers: docs/testing.md, "Against Blender Cycles".
"""
import argparse
import glob
import math
import os
import shutil
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "tools", "cycles"))
import compare  # noqa: E402

BOUND = 0.01  # reference vs Cycles, tonemapped RMSE
NOISE_FACTOR = 3.0
FLOOR = 0.002  # what two converged renderers of the same scene still differ by (docs/testing.md)
RASTER_BOUND = 0.02
SAMPLES_CYCLES = 512  # per seed, two seeds, for a scene SAMPLES_CYCLES_OF leaves out
# Cycles' samples per scene: each scene's noise (mean of two seeds) 0.002-0.007; the whole test's
# first run (nothing cached) took 12 minutes on two cores, a run with Cycles cached about 2
# (docs/testing.md).
SAMPLES_CYCLES_OF = {"lambert_sphere": 256, "glossy_sphere": 256, "glass_sphere": 512,
                     "flat_pool": 768, "half_submerged": 768, "deep_pool": 1024}
SAMPLES_REF = 256
SAMPLES_RASTER = 16  # the measure: the raster's frame of 16 jittered samples
# Cycles' frames of the scenes as they are, kept with the tests, each under a key of everything it
# depends on (Blender's version among them): a fresh clone takes them instead of rendering them
# again (12 minutes on two cores). A frame whose key changed is rendered again, and the run says so.
FRAMES = os.path.join(HERE, "frames")


def raster_passing():
    names = set()
    with open(os.path.join(HERE, "raster_passing.txt")) as f:
        for line in f:
            line = line.split("#", 1)[0].strip()
            if line:
                names.add(line)
    return names


def report_frames(args, used):
    """Says where Cycles' frames came from; with --keep-frames, keeps exactly these."""
    counts = {source: sum(1 for _, _, s in used if s == source) for source in ("kept", "cached", "rendered")}
    print(f"Cycles frames: {counts['kept']} kept in {args.cycles_frames}, {counts['cached']} from the cache, "
          f"{counts['rendered']} rendered now")
    if not args.keep_frames:
        if counts["kept"] < len(used):
            print("  to keep them with the tests: the same command with --keep-frames, then commit the folder")
        return
    if args.scenes:
        sys.exit("cycles_test: --keep-frames needs every scene (no scene names)")
    os.makedirs(args.cycles_frames, exist_ok=True)
    keys = set()
    for path, key, _ in used:
        keys.add(key)
        shutil.copyfile(path, os.path.join(args.cycles_frames, key + ".exr"))
    for old in glob.glob(os.path.join(args.cycles_frames, "*.exr")):
        if os.path.splitext(os.path.basename(old))[0] not in keys:
            os.remove(old)
    print(f"  {args.cycles_frames} now holds these {len(keys)} frames and no other")


def main():
    sys.stdout.reconfigure(line_buffering=True)  # ctest's log shows each scene as it ends
    p = argparse.ArgumentParser()
    p.add_argument("--tidepool", required=True)
    p.add_argument("--blender", default="blender")
    p.add_argument("--outdir", required=True)
    p.add_argument("--samples-cycles", type=int, help="per seed, for every scene (default: SAMPLES_CYCLES_OF)")
    p.add_argument("--samples-ref", type=int, default=SAMPLES_REF)
    p.add_argument("--threads", type=int, default=0)
    p.add_argument("--cycles-cache", help="Cycles' frames kept between runs (default: OUTDIR/cycles-cache)")
    p.add_argument("--cycles-frames", default=FRAMES,
                   help="Cycles' frames kept with the tests, taken before rendering (default: tests/cycles/frames)")
    p.add_argument("--keep-frames", action="store_true",
                   help="after a run of every scene, make --cycles-frames hold exactly the Cycles frames it used")
    p.add_argument("scenes", nargs="*", help="scene files (default: every tests/cycles/*.json)")
    args = p.parse_args()
    args.cycles_cache = args.cycles_cache or os.path.join(args.outdir, "cycles-cache")
    scenes = args.scenes or sorted(glob.glob(os.path.join(HERE, "*.json")))
    passing = raster_passing()
    unknown = passing - {os.path.splitext(os.path.basename(s))[0] for s in scenes}
    if unknown and not args.scenes:
        sys.exit(f"cycles_test: raster_passing.txt names scenes that do not exist: {sorted(unknown)}")
    failures, rows, used = [], [], []
    for scene in scenes:
        name = os.path.splitext(os.path.basename(scene))[0]
        cargs = compare.parse_args([scene, os.path.join(args.outdir, name), "--no-ladder",
                                    "--samples-cycles",
                                    str(args.samples_cycles or SAMPLES_CYCLES_OF.get(name, SAMPLES_CYCLES)),
                                    "--samples-ref",
                                    str(args.samples_ref), "--tidepool", args.tidepool, "--blender", args.blender,
                                    "--threads", str(args.threads), "--cycles-cache", args.cycles_cache,
                                    "--cycles-frames", args.cycles_frames, "--samples-raster", str(SAMPLES_RASTER)])
        f = compare.Comparison(cargs).run_all()
        used += [(os.path.join(args.outdir, name, f"cycles_s{seed}.exr"), key, source)
                 for seed, (key, source) in zip(compare.CYCLES_SEEDS, f["cycles_sources"])]
        compare.print_figures(f)
        noise = compare.combined_noise(f)
        within = NOISE_FACTOR * noise + FLOOR
        e = f["reference_vs_cycles"]
        # The noise adds in quadrature to the systematic difference: what is left of it.
        systematic = math.sqrt(max(0.0, e * e - noise * noise))
        ok_bound, ok_noise = e <= BOUND, e <= within
        raster_checked = name in passing
        ok_raster = f["raster_vs_cycles"] <= RASTER_BOUND or not raster_checked
        print(f"  reference vs Cycles {e:.4f} <= {BOUND} {'yes' if ok_bound else 'NO'} (noise taken out {systematic:.4f}); "
              f"<= {NOISE_FACTOR:g} x noise {noise:.4f} + {FLOOR} = {within:.4f} {'yes' if ok_noise else 'NO'}; "
              f"raster {f['raster_vs_cycles']:.4f} <= {RASTER_BOUND} "
              + (("yes" if ok_raster else "NO") if raster_checked else "(reported only)"), flush=True)
        if not (ok_bound and ok_noise and ok_raster):
            failures.append(name)
        rows.append((name, f, noise))
    print("\nscene              ref-Cycles  raster-Cycles  ref-raster  Cycles noise (one seed, mean)  ref noise")
    for name, f, noise in rows:
        rn = f["reference_noise_mean"]
        print(f"{name:18s} {f['reference_vs_cycles']:10.4f} {f['raster_vs_cycles']:14.4f} "
              f"{f['reference_vs_raster']:11.4f} {f['cycles_noise_one_seed']:14.4f} {f['cycles_noise_mean']:7.4f}"
              f"         {('%.4f' % rn) if rn is not None else 'n/a'}")
    report_frames(args, used)
    if failures:
        print(f"cycles_test: FAILED: {', '.join(failures)}")
        sys.exit(1)
    print("cycles_test: every scene within its bounds")


if __name__ == "__main__":
    main()
