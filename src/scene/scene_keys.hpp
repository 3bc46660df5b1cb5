#pragma once
#include "scene/scene.hpp"

namespace tp::scene {

// Every key of a scene file, once, for every visitor: the file's reader and
// writer (scene_file.cpp) and the viewer's panel (viewer/view_panel.cpp). V has
//   number(key, float&), count(key, unsigned&), vec3(key, glm::vec3&),
//   color(key, glm::vec3&) (an RGB radiance or albedo: a vec3 in the file),
//   flag(key, bool&), text(key, std::string&),
//   choice(key, std::string&, allowed values), preset(key, Ao&),
//   object(key, fields(V&)), objects(key, std::vector<T>&, fields(V&, T&)).
// One function per object of the file, so that each stays short.
template <typename R>
void visitCameraKeys(R& r, Camera& x) {
  r.vec3("position", x.position);
  r.vec3("target", x.target);
  r.vec3("up", x.up);
  r.number("fov", x.fovYDegrees);
  r.number("near", x.nearPlane);
  r.number("far", x.farPlane);
  r.objects("path", x.path, [](auto& k, CameraKeyframe& key) {
    k.number("time", key.time);
    k.vec3("position", key.position);
    k.vec3("target", key.target);
    k.number("fov", key.fovYDegrees);
  });
  r.choice("interpolation", x.interpolation, kCameraInterpolation);
  r.number("turntable", x.turntableSeconds);
}

template <typename R>
void visitSkyKeys(R& r, Sky& x) {
  r.number("sun_elevation", x.sunElevationDegrees);
  r.number("sun_azimuth", x.sunAzimuthDegrees);
  r.number("sun_angular_radius", x.sunAngularRadiusDegrees);
  r.color("sun_radiance", x.sunRadiance);
  r.color("zenith", x.zenith);
  r.color("horizon", x.horizon);
  r.color("ground", x.ground);
  r.color("glow", x.glow);
  r.number("zenith_exponent", x.zenithExponent);
  r.number("glow_exponent", x.glowExponent);
  r.number("horizon_blend", x.horizonBlend);
  r.count("texture_width", x.textureWidth);
  r.text("image", x.image);
  r.number("rotation", x.rotationDegrees);
  r.number("intensity", x.intensity);
  r.number("haze_distance", x.hazeDistance);
  r.object("clouds", [&](auto& c) {
    c.number("coverage", x.clouds.coverage);
    c.number("scale", x.clouds.scale);
    c.count("octaves", x.clouds.octaves);
    c.number("persistence", x.clouds.persistence);
    c.count("seed", x.clouds.seed);
    c.choice("noise", x.clouds.noise, choices::kNoise);
    c.color("color", x.clouds.color);
  });
}

template <typename R>
void visitGroundKeys(R& r, Ground& x) {
  r.number("half_extent", x.halfExtent);
  r.number("height", x.height);
  r.choice("pattern", x.pattern, choices::kGroundPattern);
  r.number("checker_size", x.checkerSize);
  r.color("albedo_a", x.albedoA);
  r.color("albedo_b", x.albedoB);
  r.number("paver_width", x.paverWidth);
  r.number("paver_depth", x.paverDepth);
  r.number("joint_width", x.jointWidth);
  r.color("joint_albedo", x.jointAlbedo);
  r.number("coping_width", x.copingWidth);
  r.color("coping_albedo", x.copingAlbedo);
  r.number("terrace_half_extent", x.terraceHalfExtent);
  r.color("lawn_albedo", x.lawnAlbedo);
}

template <typename R>
void visitWaterKeys(R& r, Water& x) {
  r.flag("enabled", x.enabled);
  r.count("grid", x.grid);
  r.number("extent", x.extent);
  r.number("level", x.level);
  r.number("wave_speed", x.waveSpeed);
  r.number("damping", x.damping);
  r.number("grid_damping", x.gridDamping);
  r.choice("boundary", x.boundary, choices::kBoundary);
  r.choice("sphere_forcing", x.sphereForcing, choices::kSphereForcing);
  r.number("max_slope", x.maxSlope);
  r.number("frame_time", x.frameTime);
  r.number("ior", x.ior);
  r.vec3("absorption", x.absorption);
  r.vec3("scattering", x.scattering);
  r.number("scattering_anisotropy", x.scatteringAnisotropy);
  r.count("scattering_shadow_pieces", x.scatteringShadowPieces);
  r.objects("drops", x.drops, [](auto& d, scene::Drop& drop) {
    d.number("x", drop.x);
    d.number("z", drop.z);
    d.number("radius", drop.radius);
    d.number("amplitude", drop.amplitude);
    d.count("frame", drop.frame);
  });
}

template <typename R>
void visitPoolKeys(R& r, Pool& x) {
  r.number("depth", x.depth);
  r.color("wall_albedo", x.wallAlbedo);
  r.choice("wall_pattern", x.wallPattern, choices::kWallPattern);
  r.number("brick_width", x.brickWidth);
  r.number("brick_height", x.brickHeight);
  r.number("mortar_fraction", x.mortarFraction);
  r.color("brick_albedo", x.brickAlbedo);
  r.color("mortar_albedo", x.mortarAlbedo);
  r.number("dirt", x.dirt);
  r.choice("floor_pattern", x.floorPattern, choices::kFloorPattern);
  r.number("tile_size", x.tileSize);
  r.color("tile_albedo_a", x.tileAlbedoA);
  r.color("tile_albedo_b", x.tileAlbedoB);
  r.number("grout_width", x.groutWidth);
  r.color("grout_albedo", x.groutAlbedo);
  r.number("wall_specular", x.wallSpecular);
  r.number("wall_roughness", x.wallRoughness);
}

template <typename R>
void visitTerrainKeys(R& r, Terrain& x) {
  r.number("amplitude", x.amplitude);
  r.number("frequency", x.frequency);
  r.count("octaves", x.octaves);
  r.number("persistence", x.persistence);
  r.count("seed", x.seed);
}

template <typename R>
void visitAoKeys(R& r, Ao& x) {
  r.preset("preset", x);  // first: the keys beside it override their own values alone
  r.flag("enabled", x.enabled);
  r.choice("pattern", x.pattern, choices::kAoPattern);
  r.count("kernel_size", x.kernelSize);
  r.number("radius", x.radius);
  r.number("bias", x.bias);
  r.count("noise_size", x.noiseSize);
  r.choice("depth_lookup", x.depthLookup, choices::kAoDepthLookup);
  r.choice("blur", x.blur, choices::kAoBlur);
  r.count("blur_taps", x.blurTaps);
  r.number("blur_depth_tolerance", x.blurDepthTolerance);
  r.choice("resolution", x.resolution, choices::kAoResolution);
}

template <typename R>
void visitRenderKeys(R& r, Render& x) {
  r.number("exposure", x.exposure);
  r.choice("refraction", x.refraction, choices::kRefraction);
  r.flag("caustics", x.caustics);
  r.count("glass_search_steps", x.glassSearchSteps);
  r.choice("antialiasing", x.antialiasing, choices::kAntialiasing);
  r.flag("shadows", x.shadows);
}

template <typename R>
void visitSphereKeys(R& r, Sphere& sphere) {
  r.vec3("center", sphere.center);
  r.number("radius", sphere.radius);
  r.color("albedo", sphere.albedo);
  r.number("specular", sphere.specular);
  r.number("roughness", sphere.roughness);
  r.objects("path", sphere.path, [](auto& k, scene::Keyframe& key) {
    k.number("time", key.time);
    k.vec3("center", key.center);
  });
  r.choice("material", sphere.material, choices::kMaterial);
  r.number("ior", sphere.ior);
}

template <typename R>
void visitBoxKeys(R& r, Box& box) {
  r.vec3("center", box.center);
  r.vec3("size", box.size);
  r.number("yaw", box.yawDegrees);
  r.color("albedo", box.albedo);
  r.choice("material", box.material, choices::kMaterial);
  r.number("ior", box.ior);
}

template <typename V>
void visitScene(V& v, Scene& s) {
  v.object("camera", [&](auto& r) { visitCameraKeys(r, s.camera); });
  v.object("sky", [&](auto& r) { visitSkyKeys(r, s.sky); });
  v.object("ground", [&](auto& r) { visitGroundKeys(r, s.ground); });
  v.object("water", [&](auto& r) { visitWaterKeys(r, s.water); });
  v.object("pool", [&](auto& r) { visitPoolKeys(r, s.pool); });
  v.object("terrain", [&](auto& r) { visitTerrainKeys(r, s.terrain); });
  v.objects("spheres", s.spheres, [](auto& r, Sphere& sphere) { visitSphereKeys(r, sphere); });
  v.objects("boxes", s.boxes, [](auto& r, Box& box) { visitBoxKeys(r, box); });
  v.object("ao", [&](auto& r) { visitAoKeys(r, s.ao); });
  v.object("render", [&](auto& r) { visitRenderKeys(r, s.render); });
}

}  // namespace tp::scene
