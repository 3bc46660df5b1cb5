#!/usr/bin/env python3
"""Writes the comparison sky: an equirectangular half-float EXR, deterministic.

A smooth sky (zenith blue, a bright horizon, a darker ground below it, all
blended smoothly) and a "sun": a disc of radiance SUN_RADIANCE, SUN_RADIUS
degrees across its flat core, falling smoothly to nothing over SUN_EDGE more
degrees, so that both path tracers find it by their own importance sampling
and converge. The texels are half floats, the precision tidepool's texture
holds them at, so that both renderers read the same numbers.

Layout as tidepool reads a sky image (shaders_glsl/shared/equirect.h): row 0
is the zenith, u = atan2(z, x) / 2 pi + 1/2, v = acos(y) / pi, y up.

    python3 tools/cycles/make_sky.py OUT.exr [--width 1024]
"""
import argparse
import math

import numpy as np
import OpenImageIO as oiio

SUN_ELEVATION = 40.0  # degrees
SUN_AZIMUTH = 60.0  # degrees, from +x towards +z (tidepool's sky.sun_azimuth)
SUN_RADIUS = 8.0  # degrees: the flat core
SUN_EDGE = 4.0  # degrees: the smooth fall to zero past the core
SUN_RADIANCE = np.array([16.0, 15.0, 13.5])
ZENITH = np.array([0.18, 0.34, 0.80])
HORIZON = np.array([0.80, 0.86, 0.95])
GROUND = np.array([0.30, 0.27, 0.22])


def smoothstep(e0, e1, x):
    t = np.clip((x - e0) / (e1 - e0), 0.0, 1.0)
    return t * t * (3.0 - 2.0 * t)


def sky_texels(width):
    height = width // 2
    u = (np.arange(width) + 0.5) / width
    v = (np.arange(height) + 0.5) / height
    phi = (u - 0.5) * 2.0 * math.pi
    theta = v * math.pi
    st, ct = np.sin(theta)[:, None], np.cos(theta)[:, None]
    d = np.stack([st * np.cos(phi)[None, :], np.broadcast_to(ct, (height, width)), st * np.sin(phi)[None, :]], axis=-1)
    y = d[..., 1]
    # Above the horizon: horizon to zenith in sqrt(sin elevation); below: to the ground over 10 degrees.
    up = np.sqrt(np.clip(y, 0.0, 1.0))[..., None]
    sky = HORIZON * (1.0 - up) + ZENITH * up
    below = smoothstep(0.0, -math.sin(math.radians(10.0)), y)[..., None]
    radiance = sky * (1.0 - below) + GROUND * below
    el, az = math.radians(SUN_ELEVATION), math.radians(SUN_AZIMUTH)
    sun = np.array([math.cos(el) * math.cos(az), math.sin(el), math.cos(el) * math.sin(az)])
    angle = np.degrees(np.arccos(np.clip(d @ sun, -1.0, 1.0)))
    disc = 1.0 - smoothstep(SUN_RADIUS, SUN_RADIUS + SUN_EDGE, angle)
    radiance = radiance + disc[..., None] * SUN_RADIANCE
    return radiance.astype(np.float16).astype(np.float32)


def write(path, texels):
    height, width = texels.shape[:2]
    spec = oiio.ImageSpec(width, height, 3, oiio.HALF)
    spec.attribute("compression", "zip")
    out = oiio.ImageOutput.create(path)
    if out is None or not out.open(path, spec):
        raise SystemExit(f"make_sky: cannot write {path}: {oiio.geterror()}")
    out.write_image(texels)
    out.close()


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("out")
    parser.add_argument("--width", type=int, default=1024)
    args = parser.parse_args()
    write(args.out, sky_texels(args.width))


if __name__ == "__main__":
    main()
