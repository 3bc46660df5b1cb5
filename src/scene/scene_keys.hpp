#pragma once
#include "scene/scene.hpp"

namespace tp::scene {

// Every key of a scene file, once, for every visitor: the file's reader and
// writer (scene_file.cpp) and the viewer's panel (app/view_panel.cpp). V has
//   number(key, float&), count(key, unsigned&), vec3(key, glm::vec3&),
//   color(key, glm::vec3&) (an RGB radiance or albedo: a vec3 in the file),
//   flag(key, bool&), text(key, std::string&),
//   choice(key, std::string&, allowed values), preset(key, Ao&),
//   object(key, fields(V&)), objects(key, std::vector<T>&, fields(V&, T&)).
template <typename V>
void visitScene(V& v, Scene& s) {
  v.object("camera", [&](auto& r) {
    r.vec3("position", s.camera.position);
    r.vec3("target", s.camera.target);
    r.vec3("up", s.camera.up);
    r.number("fov", s.camera.fovYDegrees);
    r.number("near", s.camera.nearPlane);
    r.number("far", s.camera.farPlane);
  });
  v.object("sky", [&](auto& r) {
    r.number("sun_elevation", s.sky.sunElevationDegrees);
    r.number("sun_azimuth", s.sky.sunAzimuthDegrees);
    r.number("sun_angular_radius", s.sky.sunAngularRadiusDegrees);
    r.color("sun_radiance", s.sky.sunRadiance);
    r.color("zenith", s.sky.zenith);
    r.color("horizon", s.sky.horizon);
    r.color("ground", s.sky.ground);
    r.color("glow", s.sky.glow);
    r.number("zenith_exponent", s.sky.zenithExponent);
    r.number("glow_exponent", s.sky.glowExponent);
    r.number("horizon_blend", s.sky.horizonBlend);
    r.count("texture_width", s.sky.textureWidth);
    r.text("image", s.sky.image);
    r.object("clouds", [&](auto& c) {
      c.number("coverage", s.sky.clouds.coverage);
      c.number("scale", s.sky.clouds.scale);
      c.count("octaves", s.sky.clouds.octaves);
      c.number("persistence", s.sky.clouds.persistence);
      c.count("seed", s.sky.clouds.seed);
      c.choice("noise", s.sky.clouds.noise, choices::kNoise);
      c.color("color", s.sky.clouds.color);
    });
  });
  v.object("ground", [&](auto& r) {
    r.number("half_extent", s.ground.halfExtent);
    r.number("height", s.ground.height);
    r.number("checker_size", s.ground.checkerSize);
    r.color("albedo_a", s.ground.albedoA);
    r.color("albedo_b", s.ground.albedoB);
  });
  v.object("water", [&](auto& r) {
    r.flag("enabled", s.water.enabled);
    r.count("grid", s.water.grid);
    r.number("extent", s.water.extent);
    r.number("level", s.water.level);
    r.number("wave_speed", s.water.waveSpeed);
    r.number("damping", s.water.damping);
    r.choice("boundary", s.water.boundary, choices::kBoundary);
    r.number("max_slope", s.water.maxSlope);
    r.number("frame_time", s.water.frameTime);
    r.number("ior", s.water.ior);
    r.vec3("absorption", s.water.absorption);
    r.objects("drops", s.water.drops, [](auto& d, scene::Drop& drop) {
      d.number("x", drop.x);
      d.number("z", drop.z);
      d.number("radius", drop.radius);
      d.number("amplitude", drop.amplitude);
      d.count("frame", drop.frame);
    });
  });
  v.object("pool", [&](auto& r) {
    r.number("depth", s.pool.depth);
    r.color("wall_albedo", s.pool.wallAlbedo);
    r.choice("wall_pattern", s.pool.wallPattern, choices::kWallPattern);
    r.number("brick_width", s.pool.brickWidth);
    r.number("brick_height", s.pool.brickHeight);
    r.number("mortar_fraction", s.pool.mortarFraction);
    r.color("brick_albedo", s.pool.brickAlbedo);
    r.color("mortar_albedo", s.pool.mortarAlbedo);
    r.number("dirt", s.pool.dirt);
    r.number("tile_size", s.pool.tileSize);
    r.color("tile_albedo_a", s.pool.tileAlbedoA);
    r.color("tile_albedo_b", s.pool.tileAlbedoB);
    r.number("wall_specular", s.pool.wallSpecular);
    r.number("wall_roughness", s.pool.wallRoughness);
  });
  v.object("terrain", [&](auto& r) {
    r.number("amplitude", s.terrain.amplitude);
    r.number("frequency", s.terrain.frequency);
    r.count("octaves", s.terrain.octaves);
    r.number("persistence", s.terrain.persistence);
    r.count("seed", s.terrain.seed);
  });
  v.objects("spheres", s.spheres, [](auto& r, scene::Sphere& sphere) {
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
  });
  v.objects("boxes", s.boxes, [](auto& r, scene::Box& box) {
    r.vec3("center", box.center);
    r.vec3("size", box.size);
    r.number("yaw", box.yawDegrees);
    r.color("albedo", box.albedo);
  });
  v.object("ao", [&](auto& r) {
    r.preset("preset", s.ao);  // first: the keys beside it override their own values alone
    r.flag("enabled", s.ao.enabled);
    r.choice("pattern", s.ao.pattern, choices::kAoPattern);
    r.count("kernel_size", s.ao.kernelSize);
    r.number("radius", s.ao.radius);
    r.number("bias", s.ao.bias);
    r.count("noise_size", s.ao.noiseSize);
    r.choice("depth_lookup", s.ao.depthLookup, choices::kAoDepthLookup);
    r.choice("blur", s.ao.blur, choices::kAoBlur);
    r.count("blur_taps", s.ao.blurTaps);
    r.number("blur_depth_tolerance", s.ao.blurDepthTolerance);
    r.choice("resolution", s.ao.resolution, choices::kAoResolution);
  });
  v.object("render", [&](auto& r) {
    r.number("exposure", s.render.exposure);
    r.choice("refraction", s.render.refraction, choices::kRefraction);
    r.flag("caustics", s.render.caustics);
    r.count("glass_search_steps", s.render.glassSearchSteps);
  });
}

}  // namespace tp::scene
