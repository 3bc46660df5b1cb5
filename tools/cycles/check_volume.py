"""Checks the water's absorption as render_cycles.py hands it to Cycles: sigma_a per channel.

    blender -b --factory-startup --python-exit-code 1 --python tools/cycles/check_volume.py

A slab D metres thick, its faces transparent (no refraction, no Fresnel), filled with
the medium render_cycles.glass_material builds for an absorption sigma_a (1/m), seen
by an orthographic camera straight through it against a white world of radiance 1:
each pixel must be exp(-sigma_a D). Exits non-zero when a channel is off by more
than 1e-4 (relative).
"""
import math
import os
import sys
import tempfile

import bpy
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import render_cycles  # noqa: E402

THICKNESS = 0.7
CASES = [(0.45, 0.09, 0.06), (2.0, 0.5, 0.0), (0.6, 0.12, 0.08)]


def render_slab(absorption):
    bpy.ops.wm.read_factory_settings(use_empty=True)
    scene = bpy.context.scene
    bpy.ops.mesh.primitive_cube_add(size=1.0)
    slab = bpy.context.active_object
    slab.scale = (10.0, 10.0, THICKNESS)
    render_cycles.assign(slab, render_cycles.glass_material("medium", 1.0, absorption, None, surface="transparent"))
    world = bpy.data.worlds.new("white")
    world.use_nodes = True
    world.node_tree.nodes["Background"].inputs["Color"].default_value = (1.0, 1.0, 1.0, 1.0)
    world.node_tree.nodes["Background"].inputs["Strength"].default_value = 1.0
    scene.world = world
    cam_data = bpy.data.cameras.new("camera")
    cam_data.type = "ORTHO"
    cam_data.ortho_scale = 1.0
    cam = bpy.data.objects.new("camera", cam_data)
    cam.location = (0.0, 0.0, 5.0)  # looking down -z, through the slab
    scene.collection.objects.link(cam)
    scene.camera = cam

    class Args:
        samples, seed, threads = 4, 0, 0
    render_cycles.settings(scene, Args, 8, 8)
    out = os.path.join(tempfile.mkdtemp(), "slab.exr")
    scene.render.filepath = out
    bpy.ops.render.render(write_still=True)
    image = bpy.data.images.load(out)
    pixels = np.array(image.pixels[:], dtype=np.float64).reshape(-1, 4)[:, :3]
    return pixels.mean(axis=0), pixels.std(axis=0)


def main():
    worst = 0.0
    for absorption in CASES:
        got, spread = render_slab(absorption)
        want = np.exp(-np.array(absorption) * THICKNESS)
        rel = np.abs(got - want) / want
        worst = max(worst, float(rel.max()))
        print(f"check_volume: sigma_a {absorption} through {THICKNESS} m: Cycles {np.round(got, 6).tolist()}, "
              f"exp(-sigma d) {np.round(want, 6).tolist()}, relative error {rel.max():.2e}")
    print(f"check_volume: worst relative error {worst:.2e}")
    if worst > 1e-4:
        sys.exit(1)


main()
