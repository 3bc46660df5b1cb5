"""Renders a tidepool frame in Blender Cycles, as the independent check of the reference.

    blender -b --factory-startup --python-exit-code 1 --python tools/cycles/render_cycles.py -- \
        --glb scene.glb --scene scene.json --camera-exr frame.exr --sky sky.exr \
        --out cycles.exr --samples N --seed S --size WxH

--glb is what `tidepool export` writes for the frame, --scene the scene file it
was exported from (for what glTF does not carry: the glossy lobe's share, the
water's absorption and scattering), --camera-exr an EXR tidepool rendered of
the frame (its worldToCamera and worldToNDC attributes give the camera),
--sky the equirectangular image the scene's sky.image names. The conventions
(axes, camera, sky, filter, materials, the water's volume, bounces) are those
of docs/testing.md, "Against Blender Cycles".

TIDEPOOL_CYCLES_ALBEDO_SCALE=k multiplies every Lambertian albedo by k: a
deliberately wrong material, to show that the comparison can fail.
"""
import argparse
import json
import math
import os
import sys
import time

import numpy as np

# Debian's Blender 3.4 glTF importer still spells numpy's removed alias np.bool.
np.bool = bool

import bmesh  # noqa: E402
import bpy  # noqa: E402
from mathutils import Matrix  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import scene_json  # noqa: E402

# tidepool is y-up, Blender z-up: the glTF importer maps (x, y, z) to (x, -z, y).
TIDEPOOL_TO_BLENDER = Matrix(((1, 0, 0, 0), (0, 0, -1, 0), (0, 1, 0, 0), (0, 0, 0, 1)))

# How far (metres) the water's closed solid reaches past the pool's walls and under its floor,
# so that the walls and the floor stand inside the water and no face is coplanar with another.
WATER_SKIRT_OUT = 0.002
WATER_SKIRT_DOWN = 0.05

BOUNCES = dict(max_bounces=64, diffuse_bounces=16, glossy_bounces=16, transmission_bounces=64,
               volume_bounces=16, transparent_max_bounces=16)


def parse_args():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    p = argparse.ArgumentParser(prog="render_cycles.py")
    p.add_argument("--glb", required=True)
    p.add_argument("--scene", required=True, help="the tidepool scene file the glb was exported from")
    p.add_argument("--camera-exr", required=True)
    p.add_argument("--sky", required=True)
    p.add_argument("--out", required=True)
    p.add_argument("--samples", type=int, default=256)
    p.add_argument("--seed", type=int, default=0)
    p.add_argument("--size", default="160x90")
    p.add_argument("--threads", type=int, default=0, help="0: all")
    p.add_argument("--blend", help="also save the .blend here, to look at by hand")
    return p.parse_args(argv)


# --- the camera -------------------------------------------------------------------------------

def read_exr_camera(path):
    """worldToCamera and worldToNDC of a tidepool EXR, as column-vector numpy matrices."""
    import OpenImageIO as oiio
    spec = oiio.ImageInput.open(path)
    if spec is None:
        raise SystemExit(f"render_cycles: cannot read {path}: {oiio.geterror()}")
    s = spec.spec()
    mats = {}
    for name in ("worldToCamera", "worldToNDC"):
        v = s.getattribute(name)
        if v is None:
            raise SystemExit(f"render_cycles: {path} has no {name} attribute")
        # OpenEXR's m44f is row-vector: p' = p M. The column-vector matrix is M transposed.
        mats[name] = np.array(v, dtype=np.float64).reshape(4, 4).T
    spec.close()
    return mats["worldToCamera"], mats["worldToNDC"]


def set_camera(scene, exr, width, height):
    world_to_camera, world_to_ndc = read_exr_camera(exr)
    camera_to_world = np.linalg.inv(world_to_camera)
    projection = world_to_ndc @ camera_to_world  # camera space to NDC
    # Vulkan NDC (y down): |P[1][1]| = 1 / tan(fovy / 2), |P[0][0]| = that / aspect.
    fovy = 2.0 * math.atan(1.0 / abs(projection[1, 1]))
    aspect = abs(projection[1, 1] / projection[0, 0])
    if abs(aspect - width / height) > 1e-3 * aspect:
        raise SystemExit(f"render_cycles: the EXR's aspect {aspect:.5f} is not the frame's {width}x{height}")
    cam_data = bpy.data.cameras.new("camera")
    cam_data.sensor_fit = "VERTICAL"
    cam_data.angle_y = fovy
    cam_data.clip_start = 1e-3
    cam_data.clip_end = 1e5
    cam = bpy.data.objects.new("camera", cam_data)
    scene.collection.objects.link(cam)
    # Both cameras look down their -z with +y up; only the world's axes differ.
    cam.matrix_world = TIDEPOOL_TO_BLENDER @ Matrix(camera_to_world.tolist())
    scene.camera = cam
    return fovy


# --- the world ---------------------------------------------------------------------------------

def set_world(scene, sky_path, sky):
    if float(sky.get("rotation", 0.0)) != 0.0:
        raise SystemExit("render_cycles: sky.rotation is not carried to Cycles; use an unturned image")
    world = bpy.data.worlds.new("sky")
    world.use_nodes = True
    nodes, links = world.node_tree.nodes, world.node_tree.links
    nodes.clear()
    env = nodes.new("ShaderNodeTexEnvironment")
    env.image = bpy.data.images.load(os.path.abspath(sky_path))
    env.image.colorspace_settings.name = "Linear"
    env.interpolation = "Linear"
    env.projection = "EQUIRECTANGULAR"
    background = nodes.new("ShaderNodeBackground")
    background.inputs["Strength"].default_value = float(sky.get("intensity", 1.0))
    out = nodes.new("ShaderNodeOutputWorld")
    links.new(env.outputs["Color"], background.inputs["Color"])
    links.new(background.outputs["Background"], out.inputs["Surface"])
    world.cycles.sampling_method = "AUTOMATIC"
    scene.world = world


# --- materials -----------------------------------------------------------------------------------

def gltf_material(obj):
    """Base colour, roughness, IOR and transmission of the imported glTF material."""
    mat = obj.active_material
    base, rough, ior, transmission = (0.8, 0.8, 0.8), 1.0, 1.5, 0.0
    if mat and mat.use_nodes:
        for node in mat.node_tree.nodes:
            if node.type == "BSDF_PRINCIPLED":
                base = tuple(node.inputs["Base Color"].default_value)[:3]
                rough = node.inputs["Roughness"].default_value
                ior = node.inputs["IOR"].default_value
                transmission = node.inputs["Transmission"].default_value
    return dict(albedo=base, roughness=rough, ior=ior, transmission=transmission)


def new_material(name):
    mat = bpy.data.materials.new(name)
    mat.use_nodes = True
    mat.node_tree.nodes.clear()
    out = mat.node_tree.nodes.new("ShaderNodeOutputMaterial")
    out.target = "CYCLES"
    return mat, out


def albedo_scale():
    return float(os.environ.get("TIDEPOOL_CYCLES_ALBEDO_SCALE", "1"))


def opaque_material(name, albedo, specular, roughness):
    """Lambertian (specular 0), or a mix of the Lambertian (1 - s) and white GGX (s) lobes."""
    mat, out = new_material(name)
    nodes, links = mat.node_tree.nodes, mat.node_tree.links
    diffuse = nodes.new("ShaderNodeBsdfDiffuse")
    k = albedo_scale()
    diffuse.inputs["Color"].default_value = (*[k * c for c in albedo], 1.0)
    diffuse.inputs["Roughness"].default_value = 0.0
    if specular <= 0.0:
        links.new(diffuse.outputs["BSDF"], out.inputs["Surface"])
        return mat
    glossy = nodes.new("ShaderNodeBsdfGlossy")
    glossy.distribution = "GGX"
    glossy.inputs["Color"].default_value = (1.0, 1.0, 1.0, 1.0)
    glossy.inputs["Roughness"].default_value = roughness  # Cycles' alpha is its square
    mix = nodes.new("ShaderNodeMixShader")
    mix.inputs["Fac"].default_value = specular
    links.new(diffuse.outputs["BSDF"], mix.inputs[1])
    links.new(glossy.outputs["BSDF"], mix.inputs[2])
    links.new(mix.outputs["Shader"], out.inputs["Surface"])
    return mat


def glass_material(name, ior, absorption=None, scattering=None, anisotropy=0.0, surface="glass"):
    """Smooth white glass of index ior; with absorption/scattering (1/m per channel) a medium inside.
    surface="transparent": no refraction or reflection at all (tools/cycles/check_volume.py)."""
    mat, out = new_material(name)
    nodes, links = mat.node_tree.nodes, mat.node_tree.links
    if surface == "glass":
        glass = nodes.new("ShaderNodeBsdfGlass")
        glass.distribution = "SHARP"
        glass.inputs["Color"].default_value = (1.0, 1.0, 1.0, 1.0)
        glass.inputs["IOR"].default_value = ior
    else:
        glass = nodes.new("ShaderNodeBsdfTransparent")
        glass.inputs["Color"].default_value = (1.0, 1.0, 1.0, 1.0)
    links.new(glass.outputs["BSDF"], out.inputs["Surface"])
    volumes = []
    if absorption is not None and max(absorption) > 0.0:
        # Cycles: sigma_a = density (1 - colour), per channel.
        density = max(absorption)
        node = nodes.new("ShaderNodeVolumeAbsorption")
        node.inputs["Color"].default_value = (*[1.0 - a / density for a in absorption], 1.0)
        node.inputs["Density"].default_value = density
        volumes.append(node.outputs["Volume"])
    if scattering is not None and max(scattering) > 0.0:
        # Cycles: sigma_s = density colour, per channel; Henyey-Greenstein phase.
        density = max(scattering)
        node = nodes.new("ShaderNodeVolumeScatter")
        node.inputs["Color"].default_value = (*[s / density for s in scattering], 1.0)
        node.inputs["Density"].default_value = density
        node.inputs["Anisotropy"].default_value = anisotropy
        volumes.append(node.outputs["Volume"])
    if volumes:
        volume = volumes[0]
        if len(volumes) == 2:
            add = nodes.new("ShaderNodeAddShader")
            links.new(volumes[0], add.inputs[0])
            links.new(volumes[1], add.inputs[1])
            volume = add.outputs["Shader"]
        links.new(volume, out.inputs["Volume"])
        mat.cycles.homogeneous_volume = True
        mat.cycles.volume_sampling = "MULTIPLE_IMPORTANCE"
    return mat


def assign(obj, mat):
    obj.data.materials.clear()
    obj.data.materials.append(mat)
    for poly in obj.data.polygons:
        poly.material_index = 0


# --- the water as a closed solid ------------------------------------------------------------------

def close_water(obj, scene_data):
    """The exported water sheet closed into a solid: its border pushed WATER_SKIRT_OUT past the
    pool's walls and carried down past the floor, and a bottom cap. Returns the new object."""
    extent = float(scene_data["water"]["extent"])
    depth = float(scene_data["pool"]["depth"])
    amplitude = float(scene_data["terrain"]["amplitude"])
    bottom = float(scene_data["ground"]["height"]) - depth - amplitude - WATER_SKIRT_DOWN  # tidepool y

    mesh = obj.data
    to_world = obj.matrix_world
    bm = bmesh.new()
    bm.from_mesh(mesh)
    bm.transform(to_world)
    bmesh.ops.remove_doubles(bm, verts=bm.verts, dist=1e-6)
    # Custom normals of the sheet (the renderer's), per vertex, before any new face is added.
    mesh.calc_normals_split()
    normal_of = {}
    for loop in mesh.loops:
        normal_of.setdefault(tuple(round(c, 6) for c in (to_world @ mesh.vertices[loop.vertex_index].co)),
                             (to_world.to_3x3() @ loop.normal).normalized())
    half = 0.5 * extent
    border = [e for e in bm.edges if e.is_boundary]
    if not border:
        raise SystemExit("render_cycles: the water sheet has no border")
    border_verts = {v for e in border for v in e.verts}
    for v in border_verts:  # Blender x = tidepool x, Blender y = -tidepool z
        x, y = v.co.x, v.co.y
        if abs(abs(x) - half) > 1e-4 and abs(abs(y) - half) > 1e-4:
            raise SystemExit(f"render_cycles: a border vertex of the water is not on the walls: {tuple(v.co)}")
        if abs(abs(x) - half) <= 1e-4:
            v.co.x = math.copysign(half + WATER_SKIRT_OUT, x)
        if abs(abs(y) - half) <= 1e-4:
            v.co.y = math.copysign(half + WATER_SKIRT_OUT, y)
    top_faces = set(bm.faces)
    result = bmesh.ops.extrude_edge_only(bm, edges=border)
    new_verts = [g for g in result["geom"] if isinstance(g, bmesh.types.BMVert)]
    for v in new_verts:
        v.co.z = bottom
    new_edges = [g for g in result["geom"] if isinstance(g, bmesh.types.BMEdge)
                 and all(v in new_verts for v in g.verts)]
    bmesh.ops.contextual_create(bm, geom=new_edges)
    bmesh.ops.recalc_face_normals(bm, faces=bm.faces)
    # The sheet's faces must face up (out of the water): a ray from the air entering it.
    ups = [f.normal.z for f in top_faces]
    if min(ups) <= 0.0:
        raise SystemExit("render_cycles: the closed water's top does not face up")

    solid = bpy.data.meshes.new("water_solid")
    bm.to_mesh(solid)
    bm.free()
    # The sheet keeps the renderer's normals (smooth, custom); the skirt and the cap are flat.
    solid.use_auto_smooth = True
    solid.auto_smooth_angle = math.pi
    loop_normals = []
    for poly in solid.polygons:
        for li in poly.loop_indices:
            co = solid.vertices[solid.loops[li].vertex_index].co
            key = tuple(round(c, 6) for c in co)
            n = normal_of.get(key) if poly.normal.z > 0.5 and co.z > bottom + 1e-3 else None
            loop_normals.append(tuple(n) if n is not None else tuple(poly.normal))
        poly.use_smooth = True
    solid.normals_split_custom_set(loop_normals)
    new_obj = bpy.data.objects.new("water_solid", solid)
    bpy.context.scene.collection.objects.link(new_obj)
    bpy.data.objects.remove(obj, do_unlink=True)
    return new_obj


# --- spheres, exactly --------------------------------------------------------------------------

SPHERE_SEGMENTS = 512  # around; half as many rings: a sagitta of 1.9e-5 of the radius


def uv_sphere(name, radius, segments, rings):
    """A UV sphere about the origin, smooth, its normals exactly radial (numpy: bmesh's is slow)."""
    theta = np.arange(1, rings) * math.pi / rings  # from the north pole (+z)
    phi = np.arange(segments) * 2.0 * math.pi / segments
    st, ct = np.sin(theta)[:, None], np.cos(theta)[:, None]
    ring = np.stack([st * np.cos(phi), st * np.sin(phi), np.broadcast_to(ct, (rings - 1, segments))], -1)
    unit = np.concatenate([[[0.0, 0.0, 1.0]], ring.reshape(-1, 3), [[0.0, 0.0, -1.0]]])
    north, south = 0, len(unit) - 1
    idx = lambda j, i: 1 + j * segments + (i % segments)  # noqa: E731
    i = np.arange(segments)
    # Counter-clockwise seen from outside (phi grows to the right of a viewer outside, +z up).
    faces = [np.stack([np.full(segments, north), idx(0, i), idx(0, i + 1), np.full(segments, -1)], -1)]
    for j in range(rings - 2):
        faces.append(np.stack([idx(j, i), idx(j + 1, i), idx(j + 1, i + 1), idx(j, i + 1)], -1))
    faces.append(np.stack([idx(rings - 2, i), np.full(segments, south), idx(rings - 2, i + 1),
                           np.full(segments, -1)], -1))
    faces = np.concatenate(faces)
    sizes = np.where(faces[:, 3] < 0, 3, 4)
    loops = faces.reshape(-1)[faces.reshape(-1) >= 0]
    mesh = bpy.data.meshes.new(name)
    mesh.vertices.add(len(unit))
    mesh.vertices.foreach_set("co", (unit * radius).astype(np.float32).reshape(-1))
    mesh.loops.add(len(loops))
    mesh.loops.foreach_set("vertex_index", loops.astype(np.int32))
    mesh.polygons.add(len(faces))
    starts = np.concatenate([[0], np.cumsum(sizes)[:-1]])
    mesh.polygons.foreach_set("loop_start", starts.astype(np.int32))
    mesh.polygons.foreach_set("loop_total", sizes.astype(np.int32))
    mesh.polygons.foreach_set("use_smooth", np.ones(len(faces), dtype=bool))
    mesh.update(calc_edges=True)
    mesh.validate()
    mesh.use_auto_smooth = True
    mesh.auto_smooth_angle = math.pi
    mesh.normals_split_custom_set_from_vertices([tuple(n) for n in unit])
    return mesh


def refine_sphere(obj, item):
    """The exported sphere's tessellation replaced by a fine one on the same sphere, with radial
    normals: the reference casts spheres exactly. Centre and radius from the exported vertices
    (the sphere where it is at the frame), checked against the scene's radius."""
    world = [obj.matrix_world @ v.co for v in obj.data.vertices]
    lo = [min(p[i] for p in world) for i in range(3)]
    hi = [max(p[i] for p in world) for i in range(3)]
    centre = [(a + b) / 2 for a, b in zip(lo, hi)]
    radius = max(math.dist(p, centre) for p in world)
    want = float(item.get("radius", 0.5))
    if abs(radius - want) > 1e-4 * max(want, 1.0):
        raise SystemExit(f"render_cycles: {obj.name}'s vertices make a radius {radius}, the scene says {want}")
    mesh = uv_sphere(obj.name + "_exact", want, SPHERE_SEGMENTS, SPHERE_SEGMENTS // 2)
    exact = bpy.data.objects.new(obj.name, mesh)
    exact.location = centre
    name = obj.name
    bpy.data.objects.remove(obj, do_unlink=True)
    exact.name = name
    bpy.context.scene.collection.objects.link(exact)
    return exact


# --- the scene ---------------------------------------------------------------------------------------

def build(args, scene_data):
    bpy.ops.wm.read_factory_settings(use_empty=True)
    scene = bpy.context.scene
    bpy.ops.import_scene.gltf(filepath=os.path.abspath(args.glb), import_shading="NORMALS", merge_vertices=False)
    objects = [o for o in scene.objects if o.type == "MESH"]
    names = sorted(o.name for o in objects)
    spheres, boxes = scene_data.get("spheres", []), scene_data.get("boxes", [])
    pool = scene_data["pool"]
    water = scene_data["water"]
    report = []
    for obj in objects:
        g = gltf_material(obj)
        name = obj.name
        if name == "water":
            solid = close_water(obj, scene_data)
            assign(solid, glass_material("water", float(water["ior"]), water["absorption"], water["scattering"],
                                         float(water["scattering_anisotropy"])))
            report.append(f"water: glass ior {water['ior']}, absorption {water['absorption']}, "
                          f"scattering {water['scattering']} g {water['scattering_anisotropy']}")
            continue
        if name in ("ground", "pool_floor"):
            assign(obj, opaque_material(name, g["albedo"], 0.0, 1.0))
            report.append(f"{name}: lambert {fmt(g['albedo'])}")
            continue
        if name == "pool_walls":
            s, r = float(pool["wall_specular"]), float(pool["wall_roughness"])
            assign(obj, opaque_material(name, g["albedo"], s, r))
            report.append(f"{name}: albedo {fmt(g['albedo'])} specular {s} roughness {r}")
            continue
        for prefix, items in (("sphere", spheres), ("box", boxes)):
            if name.startswith(prefix) and name[len(prefix):].isdigit():
                index = int(name[len(prefix):])
                if index >= len(items):
                    raise SystemExit(f"render_cycles: {name} has no scene entry ({len(items)} {prefix}s)")
                item = items[index]
                if prefix == "sphere":
                    obj = refine_sphere(obj, item)
                if item.get("material", "lambert") == "glass":
                    if g["transmission"] < 1.0:
                        raise SystemExit(f"render_cycles: {name} is glass in the scene, not in the glTF")
                    ior = float(item.get("ior", 1.5))
                    assign(obj, glass_material(name, ior))
                    report.append(f"{name}: glass ior {ior}")
                else:
                    s = float(item.get("specular", 0.0))
                    r = float(item.get("roughness", 0.5))
                    assign(obj, opaque_material(name, g["albedo"], s, r))
                    report.append(f"{name}: albedo {fmt(g['albedo'])} specular {s} roughness {r}")
                break
        else:
            raise SystemExit(f"render_cycles: no material rule for the glTF object {name!r} (objects: {names})")
    return scene, report


def fmt(v):
    return "[" + ", ".join(f"{c:.4g}" for c in v) + "]"


def settings(scene, args, width, height):
    scene.render.engine = "CYCLES"
    c = scene.cycles
    c.device = "CPU"
    c.feature_set = "SUPPORTED"
    c.samples = args.samples
    c.seed = args.seed
    c.use_animated_seed = False
    c.use_adaptive_sampling = False
    c.use_denoising = False
    c.use_guiding = False
    c.pixel_filter_type = "BOX"
    c.filter_width = 1.0
    c.sample_clamp_direct = 0.0
    c.sample_clamp_indirect = 0.0
    c.light_sampling_threshold = 0.0
    c.caustics_reflective = True
    c.caustics_refractive = True
    c.blur_glossy = 0.0
    c.min_light_bounces = 0
    c.min_transparent_bounces = 0
    c.use_fast_gi = False
    c.film_exposure = 1.0
    for key, value in BOUNCES.items():
        setattr(c, key, value)
    scene.render.film_transparent = False
    scene.render.resolution_x, scene.render.resolution_y = width, height
    scene.render.resolution_percentage = 100
    scene.render.pixel_aspect_x = scene.render.pixel_aspect_y = 1.0
    scene.render.use_border = False
    scene.render.dither_intensity = 0.0
    scene.render.threads_mode = "FIXED" if args.threads > 0 else "AUTO"
    if args.threads > 0:
        scene.render.threads = args.threads
    vs = scene.view_settings
    vs.view_transform = "Standard"
    vs.look = "None"
    vs.exposure = 0.0
    vs.gamma = 1.0
    scene.display_settings.display_device = "sRGB"
    im = scene.render.image_settings
    im.file_format = "OPEN_EXR"
    im.color_mode = "RGBA"
    im.color_depth = "32"
    im.exr_codec = "ZIP"
    scene.render.use_compositing = False
    scene.render.use_sequencer = False


def main():
    args = parse_args()
    width, height = (int(x) for x in args.size.lower().split("x"))
    scene_data = scene_json.resolve(args.scene)
    scene, report = build(args, scene_data)
    set_world(scene, args.sky, scene_data["sky"])
    fovy = set_camera(scene, args.camera_exr, width, height)
    settings(scene, args, width, height)
    print(f"render_cycles: fov {math.degrees(fovy):.4f} deg, {args.samples} samples, seed {args.seed}, "
          f"albedo scale {albedo_scale()}")
    for line in report:
        print("render_cycles: " + line)
    if args.blend:
        bpy.ops.wm.save_as_mainfile(filepath=os.path.abspath(args.blend))
    scene.render.filepath = os.path.abspath(args.out)
    start = time.perf_counter()
    bpy.ops.render.render(write_still=True)
    print(f"render_cycles: rendered in {time.perf_counter() - start:.2f} s")


if __name__ == "__main__":
    main()
