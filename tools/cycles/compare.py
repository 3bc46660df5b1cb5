#!/usr/bin/env python3
"""tidepool's reference and raster against Blender Cycles on one scene.

    python3 tools/cycles/compare.py SCENE.json OUTDIR [--samples-cycles N] [--samples-ref N]
        [--size WxH] [--tidepool PATH] [--blender PATH] [--ladder | --no-ladder] [--json FILE]

Writes into OUTDIR the comparison sky (make_sky.py), the scene beside it, the
frame's glTF (`tidepool export`), the reference's and the raster's EXRs
(`tidepool render`), Cycles' frames of two seeds (render_cycles.py), and prints
the tonemapped RMSE of each pair, Cycles' noise and the run times; with
--ladder, Cycles at 1, 2, 4, ... samples against its converged frame beside the
raster's error and time. Conventions: docs/testing.md, "Against Blender Cycles".

Needs numpy and OpenImageIO's Python module (Debian: python3-numpy,
python3-openimageio) and Blender (Debian: blender).
"""
import argparse
import hashlib
import json
import math
import os
import re
import shutil
import subprocess
import sys
import time

import numpy as np
import OpenImageIO as oiio

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import make_sky  # noqa: E402
import scene_json  # noqa: E402

LVP_ICD = "/usr/share/vulkan/icd.d/lvp_icd.x86_64.json"
CYCLES_SEEDS = (1, 2)
LADDER_SEED = 3
REFERENCE_SEEDS = (1, 2)


# --- the metric: tidepool's tonemappedError (src/reference/image_error.cpp) -------------------------

def aces_filmic(x):
    """Narkowicz's ACES fit, shaders_glsl/shared/tonemap.h."""
    a, b, c, d, e = 2.51, 0.03, 2.43, 0.59, 0.14
    return np.clip((x * (a * x + b)) / (x * (c * x + d) + e), 0.0, 1.0)


def srgb_encode(x):
    return np.where(x <= 0.0031308, x * 12.92, 1.055 * np.power(np.maximum(x, 0.0), 1.0 / 2.4) - 0.055)


def tonemap(rgb, exposure):
    return srgb_encode(aces_filmic(rgb.astype(np.float32) * np.float32(exposure)))


def tonemapped_rmse(a, b, exposure):
    """RMSE over R, G, B of every pixel of the two images tonemapped as the preview is."""
    d = tonemap(a[..., :3], exposure).astype(np.float64) - tonemap(b[..., :3], exposure).astype(np.float64)
    return float(np.sqrt(np.mean(d * d)))


def read_exr(path):
    buf = oiio.ImageBuf(path)
    if buf.has_error:
        raise SystemExit(f"compare: cannot read {path}: {buf.geterror()}")
    pixels = buf.get_pixels(oiio.FLOAT)
    if pixels is None or pixels.ndim != 3 or pixels.shape[2] < 3:
        raise SystemExit(f"compare: {path} holds no RGB image")
    if not np.all(np.isfinite(pixels[..., :3])):
        raise SystemExit(f"compare: {path} holds a NaN or an infinity")
    return pixels[..., :3]


# --- running things ----------------------------------------------------------------------------------

def run(cmd, env=None, log=None):
    """Runs cmd, returns (wall seconds, stdout). Fails with its output on a non-zero exit."""
    start = time.perf_counter()
    p = subprocess.run(cmd, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    wall = time.perf_counter() - start
    if log:
        with open(log, "w") as f:
            f.write(" ".join(cmd) + "\n" + p.stdout)
    if p.returncode != 0:
        raise SystemExit(f"compare: {' '.join(cmd)} failed ({p.returncode}):\n{p.stdout[-4000:]}")
    return wall, p.stdout


def tidepool_env():
    env = dict(os.environ)
    env.setdefault("VK_ICD_FILENAMES", LVP_ICD)
    env.setdefault("VK_DRIVER_FILES", env["VK_ICD_FILENAMES"])
    return env


def render_takes_seed(tidepool):
    _, text = run([tidepool, "help", "render"], env=tidepool_env())
    return re.search(r"--seed\b", text) is not None


class Comparison:
    def __init__(self, args):
        self.args = args
        self.out = os.path.abspath(args.outdir)
        os.makedirs(self.out, exist_ok=True)
        self.size = args.size
        self.width, self.height = (int(x) for x in args.size.lower().split("x"))
        self.times = {}
        self.env = tidepool_env()
        self.cycles_sources = []  # (key, "kept" | "cached" | "rendered") of each Cycles frame, in order

    def path(self, name):
        return os.path.join(self.out, name)

    def prepare(self):
        """The sky and the scene beside it (its sky.image names the sky there)."""
        texels = make_sky.sky_texels(self.args.sky_width)
        make_sky.write(self.path("sky.exr"), texels)
        with open(self.args.scene) as f:
            scene = json.load(f)
        scene.setdefault("sky", {})["image"] = "sky.exr"
        with open(self.path("scene.json"), "w") as f:
            json.dump(scene, f, indent=2)
        self.scene = scene_json.resolve(self.path("scene.json"))
        self.exposure = float(self.scene["render"]["exposure"])

    def tidepool(self, *words, log):
        cmd = [self.args.tidepool, *words, "--scene", self.path("scene.json"), "--frame", str(self.args.frame)]
        return run(cmd, env=self.env, log=self.path(log))[0]

    def export(self):
        self.times["export"] = self.tidepool("export", "--out", self.path("scene.glb"), log="export.log")

    def reference(self):
        seeds = REFERENCE_SEEDS if render_takes_seed(self.args.tidepool) else (None,)
        frames = []
        for seed in seeds:
            name = "reference.exr" if seed is None else f"reference_s{seed}.exr"
            extra = [] if seed is None else ["--seed", str(seed)]
            wall = self.tidepool("render", "--reference", "--samples", str(self.args.samples_ref), "--size", self.size,
                                 "--float", *extra, "--out", self.path(name), log=name + ".log")
            self.times.setdefault("reference", []).append(wall)
            frames.append(read_exr(self.path(name)))
        self.reference_frames = frames
        self.reference_mean = sum(frames) / len(frames)

    def model(self):
        """`render --reference-model`: the raster's lighting model traced on the CPU (the old reference)."""
        self.times["model"] = self.tidepool("render", "--reference-model", "--samples", str(self.args.samples_ref),
                                            "--size", self.size, "--float", "--out", self.path("model.exr"),
                                            log="model.log")
        self.model_frame = read_exr(self.path("model.exr"))

    def raster(self):
        extra = ["--samples", str(self.args.samples_raster)] if self.args.samples_raster > 1 else []
        self.times["raster"] = self.tidepool("render", "--size", self.size, "--float", *extra,
                                             "--out", self.path("raster.exr"), log="raster.log")
        self.raster_frame = read_exr(self.path("raster.exr"))

    def cycles_key(self, samples, seed):
        """What a Cycles frame depends on: the inputs, the scripts, the settings and Blender's version."""
        h = hashlib.sha256()
        h.update(read_exr(self.path("sky.exr")).tobytes())  # its pixels: the file holds the time of writing
        for path in (self.path("scene.glb"), self.path("scene.json"), os.path.join(HERE, "render_cycles.py"), os.path.join(HERE, "scene_json.py"),
                     os.path.join(scene_json.REPO, "scenes", "default.json")):
            with open(path, "rb") as f:
                h.update(hashlib.sha256(f.read()).digest())
        if not hasattr(self, "blender_version"):
            self.blender_version = run([self.args.blender, "-b", "--factory-startup", "--version"])[1].split("\n")[0]
        camera = oiio.ImageInput.open(self.path("raster.exr"))
        for attr in ("worldToCamera", "worldToNDC"):
            h.update(repr(camera.spec().getattribute(attr)).encode())
        camera.close()
        h.update(repr((samples, seed, self.size, self.blender_version,
                       os.environ.get("TIDEPOOL_CYCLES_ALBEDO_SCALE", "1"))).encode())
        return h.hexdigest()[:24]

    def cycles(self, samples, seed, name):
        key = self.cycles_key(samples, seed)
        cached = None
        # Kept frames first (read only: the repository's), then the cache this run may write.
        for folder, source in ((self.args.cycles_frames, "kept"), (self.args.cycles_cache, "cached")):
            if folder and os.path.exists(os.path.join(folder, key + ".exr")):
                shutil.copyfile(os.path.join(folder, key + ".exr"), self.path(name))
                self.cycles_sources.append((key, source))
                return read_exr(self.path(name)), 0.0, 0.0
        if self.args.cycles_cache:
            os.makedirs(self.args.cycles_cache, exist_ok=True)
            cached = os.path.join(self.args.cycles_cache, key + ".exr")
        self.cycles_sources.append((key, "rendered"))
        cmd = [self.args.blender, "-b", "--factory-startup", "--python-exit-code", "1",
               "--python", os.path.join(HERE, "render_cycles.py"), "--",
               "--glb", self.path("scene.glb"), "--scene", self.path("scene.json"),
               "--camera-exr", self.path("raster.exr"), "--sky", self.path("sky.exr"),
               "--out", self.path(name), "--samples", str(samples), "--seed", str(seed), "--size", self.size]
        if self.args.threads:
            cmd += ["--threads", str(self.args.threads)]
        wall, text = run(cmd, log=self.path(name + ".log"))
        m = re.search(r"render_cycles: rendered in ([0-9.]+) s", text)
        if cached:
            shutil.copyfile(self.path(name), cached + ".part")
            os.replace(cached + ".part", cached)
        return read_exr(self.path(name)), wall, float(m.group(1)) if m else float("nan")

    def run_all(self):
        self.prepare()
        self.export()
        self.raster()  # first: its EXR carries the camera Cycles takes
        self.reference()
        self.model_frame = None
        if self.args.model:
            self.model()
        frames = []
        for seed in CYCLES_SEEDS:
            frame, wall, render = self.cycles(self.args.samples_cycles, seed, f"cycles_s{seed}.exr")
            frames.append(frame)
            self.times.setdefault("cycles", []).append((wall, render))
        self.cycles_frames = frames
        self.cycles_mean = (frames[0] + frames[1]) / 2
        self.ladder = []
        if self.args.ladder:
            k = 1
            while k < self.args.samples_cycles:
                frame, wall, render = self.cycles(k, LADDER_SEED, f"cycles_ladder_{k}.exr")
                self.ladder.append((k, wall, render, self.err(frame, self.cycles_mean)))
                k *= 2
        return self.figures()

    def err(self, a, b):
        return tonemapped_rmse(a, b, self.exposure)

    def figures(self):
        c1, c2 = self.cycles_frames
        between = self.err(c1, c2)
        f = {
            "scene": os.path.splitext(os.path.basename(self.args.scene))[0],
            "size": self.size,
            "exposure": self.exposure,
            "samples_cycles": self.args.samples_cycles,
            "samples_ref": self.args.samples_ref,
            "reference_vs_cycles": self.err(self.reference_mean, self.cycles_mean),
            "raster_vs_cycles": self.err(self.raster_frame, self.cycles_mean),
            "reference_vs_raster": self.err(self.reference_mean, self.raster_frame),
            # Two seeds differ by sqrt(2) times one seed's noise; their mean has half of their difference.
            "cycles_noise_one_seed": between / math.sqrt(2.0),
            "cycles_noise_mean": between / 2.0,
            "reference_noise_mean": None,
            "model_vs_cycles": None if self.model_frame is None else self.err(self.model_frame, self.cycles_mean),
            "times": self.times,
            "cycles_sources": self.cycles_sources,
            "ladder": self.ladder,
        }
        if len(self.reference_frames) == 2:
            f["reference_noise_mean"] = self.err(*self.reference_frames) / 2.0
        return f


def combined_noise(f):
    return math.hypot(f["cycles_noise_mean"], f["reference_noise_mean"] or 0.0)


def print_figures(f, out=sys.stdout):
    w = lambda s: print(s, file=out)  # noqa: E731
    ref_noise = f["reference_noise_mean"]
    w(f"{f['scene']}: {f['size']}, exposure {f['exposure']}, Cycles 2 x {f['samples_cycles']} samples, "
      f"reference {f['samples_ref']} samples")
    w(f"  {'tonemapped RMSE':34s}")
    w(f"  {'reference vs Cycles':34s} {f['reference_vs_cycles']:.4f}")
    w(f"  {'raster vs Cycles':34s} {f['raster_vs_cycles']:.4f}")
    w(f"  {'reference vs raster':34s} {f['reference_vs_raster']:.4f}")
    if f.get("model_vs_cycles") is not None:
        w(f"  {'reference-model vs Cycles':34s} {f['model_vs_cycles']:.4f}")
    w(f"  {'Cycles noise, one seed':34s} {f['cycles_noise_one_seed']:.4f}")
    w(f"  {'Cycles noise, mean of two seeds':34s} {f['cycles_noise_mean']:.4f}")
    w(f"  {'reference noise, mean of two seeds':34s} "
      + (f"{ref_noise:.4f}" if ref_noise is not None else "n/a (render takes no --seed)"))
    t = f["times"]
    cyc = t["cycles"]
    w(f"  time: export {t['export']:.1f} s, raster {t['raster']:.1f} s, reference "
      + " + ".join(f"{x:.1f}" for x in t["reference"]) + " s, "
      + (f"reference-model {t['model']:.1f} s, " if "model" in t else "") + "Cycles "
      + " + ".join(f"{a:.1f} ({b:.1f} rendering)" if source == "rendered" else f"{source} {key}"
                   for (a, b), (key, source) in zip(cyc, f["cycles_sources"])) + " s")
    if f["ladder"]:
        w(f"  {'run time against error':34s} {'wall s':>8s} {'render s':>9s} {'RMSE vs Cycles mean':>20s}")
        for k, wall, render, e in f["ladder"]:
            w(f"  {'Cycles ' + str(k) + ' samples':34s} {wall:8.1f} {render:9.2f} {e:20.4f}")
        for k, (wall, render) in zip(CYCLES_SEEDS, cyc):
            w(f"  {'Cycles ' + str(f['samples_cycles']) + ' samples, seed ' + str(k):34s} {wall:8.1f} {render:9.2f} "
              f"{f['cycles_noise_one_seed']:20.4f}  (its noise)")
        w(f"  {'raster':34s} {t['raster']:8.1f} {'':9s} {f['raster_vs_cycles']:20.4f}")
        w(f"  {'reference ' + str(f['samples_ref']) + ' samples':34s} {t['reference'][0]:8.1f} {'':9s} "
          f"{f['reference_vs_cycles']:20.4f}")


def parse_args(argv=None):
    p = argparse.ArgumentParser(description="tidepool's reference and raster against Blender Cycles")
    p.add_argument("scene")
    p.add_argument("outdir")
    p.add_argument("--samples-cycles", type=int, default=1024, help="per seed (two seeds)")
    p.add_argument("--samples-ref", type=int, default=256)
    p.add_argument("--samples-raster", type=int, default=1)
    p.add_argument("--size", default="160x90")
    p.add_argument("--frame", type=int, default=0)
    p.add_argument("--sky-width", type=int, default=1024)
    p.add_argument("--threads", type=int, default=0, help="Cycles' threads (0: all)")
    p.add_argument("--tidepool", default=os.environ.get("TIDEPOOL", "build/tidepool"))
    p.add_argument("--blender", default=shutil.which("blender") or "blender")
    p.add_argument("--ladder", action=argparse.BooleanOptionalAction, default=True,
                   help="Cycles at 1, 2, 4, ... samples against its converged frame (default on)")
    p.add_argument("--cycles-cache", help="keep Cycles' frames here, keyed by everything they depend on, and "
                   "take them from here when nothing changed (the reference's figures are always fresh)")
    p.add_argument("--cycles-frames", help="Cycles' frames kept with the tests (tests/cycles/frames), keyed as "
                   "the cache is: read only, looked at before the cache")
    p.add_argument("--model", action="store_true",
                   help="also `render --reference-model` (the raster's lighting model traced) against Cycles")
    p.add_argument("--json", help="also write the figures here")
    return p.parse_args(argv)


def main():
    args = parse_args()
    figures = Comparison(args).run_all()
    print_figures(figures)
    if args.json:
        with open(args.json, "w") as f:
            json.dump(figures, f, indent=2)


if __name__ == "__main__":
    main()
