#include "scene/scene.hpp"

#include "shared/objects.h"
#include "shared/ssao.h"

#include <cmath>
#include <initializer_list>
#include <stdexcept>
#include <string>

#include "base/number_text.hpp"

namespace tp::scene {
namespace {

void requireFinite(const glm::vec3& v, const char* field) {
  if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z)) {
    throw std::runtime_error(std::string(field) + " must be finite");
  }
}

void requireNonNegative(const glm::vec3& v, const char* field) {
  requireFinite(v, field);
  if (v.x < 0.0f || v.y < 0.0f || v.z < 0.0f) throw std::runtime_error(std::string(field) + " must not be negative");
}

void requireRange(float value, float lo, float hi, const char* field) {
  if (!(value >= lo && value <= hi)) {
    throw std::runtime_error(std::string(field) + " = " + base::numberText(value) + " is outside [" +
                             base::numberText(lo) + ", " + base::numberText(hi) + "]");
  }
}

void requireOneOf(const std::string& value, const std::vector<std::string>& allowed, const char* field) {
  std::string names;
  for (const std::string& a : allowed) {
    if (value == a) return;
    names += (names.empty() ? "" : ", ") + a;
  }
  throw std::runtime_error(std::string(field) + " must be one of " + names + ", got '" + value + "'");
}

}  // namespace

Ao aoPreset(const std::string& name) {
  Ao ao;  // balanced
  if (name == "balanced") return ao;
  if (name == "fast") {
    ao.resolution = "half";
    return ao;
  }
  if (name == "quality") {
    ao.kernelSize = 32;
    ao.blurTaps = 6;
    return ao;
  }
  if (name == "baseline") {  // LearnOpenGL: 64 random samples, 4x4 random noise, 4x4 box blur
    ao.pattern = "random";
    ao.depthLookup = "nearest";
    ao.kernelSize = 64;
    ao.noiseSize = 4;
    ao.blur = "box";
    ao.blurTaps = 4;
    return ao;
  }
  throw std::invalid_argument("unknown AO preset '" + name + "' (fast, balanced, quality, baseline)");
}

Scene defaultScene() { return Scene{}; }

Scene sceneAt(const Scene& scene, float t) {
  Scene placed = scene;
  for (Sphere& sphere : placed.spheres) sphere.center = sphereCenterAt(sphere, t);
  placed.camera = cameraAt(scene.camera, t);
  return placed;
}

Camera cameraAtFrame(const Scene& scene, uint32_t frame) {
  return cameraAt(scene.camera, float(frame) * scene.water.frameTime);
}

glm::vec3 sphereCenterAt(const Sphere& sphere, float t) {
  const auto& path = sphere.path;
  if (path.empty()) return sphere.center;
  if (t <= path.front().time) return path.front().center;
  for (size_t i = 1; i < path.size(); ++i) {
    if (t <= path[i].time) {
      const float f = (t - path[i - 1].time) / (path[i].time - path[i - 1].time);
      return glm::mix(path[i - 1].center, path[i].center, f);
    }
  }
  return path.back().center;
}

namespace {

// validateScene's parts, one object of the file each, in the order it checks them.
void validateSky(const Scene& s) {
  requireRange(s.sky.sunElevationDegrees, -90.0f, 90.0f, "sky.sun_elevation");
  requireRange(s.sky.sunAzimuthDegrees, -360.0f, 360.0f, "sky.sun_azimuth");
  requireRange(s.sky.sunAngularRadiusDegrees, 0.01f, 45.0f, "sky.sun_angular_radius");
  requireNonNegative(s.sky.sunRadiance, "sky.sun_radiance");
  requireNonNegative(s.sky.zenith, "sky.zenith");
  requireNonNegative(s.sky.horizon, "sky.horizon");
  requireNonNegative(s.sky.ground, "sky.ground");
  requireNonNegative(s.sky.glow, "sky.glow");
  requireRange(s.sky.zenithExponent, 0.01f, 100.0f, "sky.zenith_exponent");
  requireRange(s.sky.glowExponent, 1.0f, 1e5f, "sky.glow_exponent");
  requireRange(s.sky.horizonBlend, 1e-4f, 1.0f, "sky.horizon_blend");
  requireRange(float(s.sky.textureWidth), 16.0f, 16384.0f, "sky.texture_width");
  requireRange(s.sky.rotationDegrees, -360.0f, 360.0f, "sky.rotation");
  requireRange(s.sky.intensity, 0.0f, 1e6f, "sky.intensity");
  requireRange(s.sky.hazeDistance, 0.0f, 1e6f, "sky.haze_distance");
  if (s.sky.image.empty() && (s.sky.rotationDegrees != 0.0f || s.sky.intensity != 1.0f)) {
    throw std::runtime_error(
        "sky.rotation and sky.intensity turn and scale an image sky (sky.image); the procedural sky turns with "
        "sky.sun_azimuth and scales with its radiances");
  }
  const Clouds& c = s.sky.clouds;
  requireRange(c.coverage, 0.0f, 1.0f, "sky.clouds.coverage");
  requireRange(c.scale, 1e-3f, 1e3f, "sky.clouds.scale");
  requireRange(float(c.octaves), 1.0f, 12.0f, "sky.clouds.octaves");
  requireRange(c.persistence, 0.0f, 1.0f, "sky.clouds.persistence");
  requireOneOf(c.noise, choices::kNoise, "sky.clouds.noise");
  requireNonNegative(c.color, "sky.clouds.color");
}

void validateGround(const Scene& s) {
  requireRange(s.ground.halfExtent, 1e-3f, 1e5f, "ground.half_extent");
  requireRange(s.ground.height, -1e4f, 1e4f, "ground.height");
  requireRange(s.ground.checkerSize, 1e-4f, 1e4f, "ground.checker_size");
  requireNonNegative(s.ground.albedoA, "ground.albedo_a");
  requireNonNegative(s.ground.albedoB, "ground.albedo_b");
  requireOneOf(s.ground.pattern, choices::kGroundPattern, "ground.pattern");
  requireRange(s.ground.paverWidth, 1e-3f, 1e3f, "ground.paver_width");
  requireRange(s.ground.paverDepth, 1e-3f, 1e3f, "ground.paver_depth");
  requireRange(s.ground.jointWidth, 0.0f, 1e3f, "ground.joint_width");
  if (!(s.ground.jointWidth < std::min(s.ground.paverWidth, s.ground.paverDepth))) {
    throw std::runtime_error("ground.joint_width must be less than ground.paver_width and ground.paver_depth");
  }
  requireNonNegative(s.ground.jointAlbedo, "ground.joint_albedo");
  requireRange(s.ground.copingWidth, 0.0f, 1e3f, "ground.coping_width");
  requireNonNegative(s.ground.copingAlbedo, "ground.coping_albedo");
  requireRange(s.ground.terraceHalfExtent, 0.0f, 1e5f, "ground.terrace_half_extent");
  requireNonNegative(s.ground.lawnAlbedo, "ground.lawn_albedo");
}

void validateRender(const Scene& s) {
  requireRange(s.render.exposure, 1e-6f, 1e6f, "render.exposure");
  requireOneOf(s.render.refraction, choices::kRefraction, "render.refraction");
  requireOneOf(s.render.antialiasing, choices::kAntialiasing, "render.antialiasing");
  requireRange(float(s.render.glassSearchSteps), 1.0f, 64.0f, "render.glass_search_steps");
}

void validateWater(const Scene& s) {
  const Water& w = s.water;
  requireRange(float(w.grid), 2.0f, 8192.0f, "water.grid");
  requireRange(w.extent, 1e-3f, 1e4f, "water.extent");
  requireRange(w.level, -1e4f, 1e4f, "water.level");
  requireRange(w.waveSpeed, 1e-6f, 1e4f, "water.wave_speed");
  requireRange(w.damping, 0.0f, 1e4f, "water.damping");
  requireRange(w.gridDamping, 0.0f, 1e4f, "water.grid_damping");
  requireOneOf(w.boundary, choices::kBoundary, "water.boundary");
  requireOneOf(w.sphereForcing, choices::kSphereForcing, "water.sphere_forcing");
  requireRange(w.maxSlope, 0.0f, 1e4f, "water.max_slope");
  requireRange(w.frameTime, 1e-6f, 10.0f, "water.frame_time");
  requireRange(w.ior, 1.0f, 3.0f, "water.ior");
  requireNonNegative(w.absorption, "water.absorption");
  requireNonNegative(w.scattering, "water.scattering");
  // |g| = 1 is a delta: the phase function's peak is infinite.
  requireRange(w.scatteringAnisotropy, -0.99f, 0.99f, "water.scattering_anisotropy");
  requireRange(float(w.scatteringShadowPieces), 0.0f, 64.0f, "water.scattering_shadow_pieces");
}

// The pool, its terrain floor, and the water below its rim.
void validatePool(const Scene& s) {
  const Water& w = s.water;
  requireRange(s.pool.depth, 1e-3f, 1e3f, "pool.depth");
  requireNonNegative(s.pool.wallAlbedo, "pool.wall_albedo");
  requireOneOf(s.pool.wallPattern, choices::kWallPattern, "pool.wall_pattern");
  requireRange(s.pool.brickWidth, 1e-3f, 1e2f, "pool.brick_width");
  requireRange(s.pool.brickHeight, 1e-3f, 1e2f, "pool.brick_height");
  requireRange(s.pool.mortarFraction, 0.0f, 0.5f, "pool.mortar_fraction");
  if (!(s.pool.mortarFraction * s.pool.brickHeight < s.pool.brickWidth)) {
    throw std::runtime_error(
        "pool.mortar_fraction times pool.brick_height (the joints' width) must be less than pool.brick_width");
  }
  requireNonNegative(s.pool.brickAlbedo, "pool.brick_albedo");
  requireNonNegative(s.pool.mortarAlbedo, "pool.mortar_albedo");
  requireRange(s.pool.dirt, 0.0f, 1.0f, "pool.dirt");
  requireRange(s.pool.tileSize, 1e-4f, 1e3f, "pool.tile_size");
  requireNonNegative(s.pool.tileAlbedoA, "pool.tile_albedo_a");
  requireNonNegative(s.pool.tileAlbedoB, "pool.tile_albedo_b");
  requireOneOf(s.pool.floorPattern, choices::kFloorPattern, "pool.floor_pattern");
  requireRange(s.pool.groutWidth, 0.0f, 1e3f, "pool.grout_width");
  if (!(s.pool.groutWidth < s.pool.tileSize)) {
    throw std::runtime_error("pool.grout_width must be less than pool.tile_size");
  }
  requireNonNegative(s.pool.groutAlbedo, "pool.grout_albedo");
  requireRange(s.pool.wallSpecular, 0.0f, 1.0f, "pool.wall_specular");
  requireRange(s.pool.wallRoughness, 0.0f, 1.0f, "pool.wall_roughness");
  requireRange(s.terrain.amplitude, 0.0f, 2.0f * s.pool.depth, "terrain.amplitude");
  requireRange(s.terrain.frequency, 0.0f, 1e3f, "terrain.frequency");
  requireRange(float(s.terrain.octaves), 1.0f, 16.0f, "terrain.octaves");
  requireRange(s.terrain.persistence, 0.0f, 1.0f, "terrain.persistence");
  if (w.enabled && w.level >= s.ground.height) {
    throw std::runtime_error("water.level " + base::numberText(w.level) +
                             " must be below the pool's rim, the ground at " + base::numberText(s.ground.height));
  }
}

// Glass's index of refraction: over the air's, and no more than 3.
void requireGlassIndex(float ior, const char* field) {
  if (!(ior > 1.0f && ior <= 3.0f)) {
    throw std::runtime_error(std::string(field) + " = " + base::numberText(ior) + " is outside (1, 3]");
  }
}

void validateSpheres(const Scene& s) {
  if (s.spheres.size() > TP_MAX_SPHERES) {
    throw std::runtime_error("spheres: at most " + std::to_string(TP_MAX_SPHERES) + ", got " +
                             std::to_string(s.spheres.size()));
  }
  for (const Sphere& sphere : s.spheres) {
    requireFinite(sphere.center, "spheres[].center");
    requireRange(sphere.radius, 1e-4f, 1e3f, "spheres[].radius");
    requireNonNegative(sphere.albedo, "spheres[].albedo");
    requireOneOf(sphere.material, choices::kMaterial, "spheres[].material");
    requireGlassIndex(sphere.ior, "spheres[].ior");
    requireRange(sphere.specular, 0.0f, 1.0f, "spheres[].specular");
    requireRange(sphere.roughness, 0.0f, 1.0f, "spheres[].roughness");
    for (size_t k = 0; k < sphere.path.size(); ++k) {
      requireFinite(sphere.path[k].center, "spheres[].path[].center");
      requireRange(sphere.path[k].time, 0.0f, 1e6f, "spheres[].path[].time");
      if (k > 0 && !(sphere.path[k].time > sphere.path[k - 1].time)) {
        throw std::runtime_error("spheres[].path: keyframe times must increase");
      }
    }
  }
}

void validateBoxes(const Scene& s) {
  if (s.boxes.size() > TP_MAX_BOXES) {
    throw std::runtime_error("boxes: at most " + std::to_string(TP_MAX_BOXES) + ", got " +
                             std::to_string(s.boxes.size()));
  }
  for (const Box& box : s.boxes) {
    requireFinite(box.center, "boxes[].center");
    requireRange(box.size.x, 1e-4f, 1e3f, "boxes[].size.x");
    requireRange(box.size.y, 1e-4f, 1e3f, "boxes[].size.y");
    requireRange(box.size.z, 1e-4f, 1e3f, "boxes[].size.z");
    requireRange(box.yawDegrees, -360.0f, 360.0f, "boxes[].yaw");
    requireNonNegative(box.albedo, "boxes[].albedo");
    requireOneOf(box.material, choices::kMaterial, "boxes[].material");
    requireGlassIndex(box.ior, "boxes[].ior");
  }
}

void validateAo(const Scene& s) {
  const Ao& ao = s.ao;
  requireOneOf(ao.pattern, choices::kAoPattern, "ao.pattern");
  requireRange(float(ao.kernelSize), 1.0f, float(TP_MAX_SSAO_KERNEL), "ao.kernel_size");
  requireRange(ao.radius, 1e-3f, 1e3f, "ao.radius");
  requireRange(ao.bias, 0.0f, 1e3f, "ao.bias");
  requireRange(float(ao.noiseSize), 1.0f, 8.0f, "ao.noise_size");
  requireOneOf(ao.depthLookup, choices::kAoDepthLookup, "ao.depth_lookup");
  requireOneOf(ao.blur, choices::kAoBlur, "ao.blur");
  requireRange(float(ao.blurTaps), 1.0f, 32.0f, "ao.blur_taps");
  requireRange(ao.blurDepthTolerance, 1e-6f, 10.0f, "ao.blur_depth_tolerance");
  requireOneOf(ao.resolution, choices::kAoResolution, "ao.resolution");
}

}  // namespace

void validateScene(const Scene& s) {
  requireFinite(s.camera.position, "camera.position");
  requireFinite(s.camera.target, "camera.target");
  requireFinite(s.camera.up, "camera.up");
  validateCamera(s.camera);
  validateSky(s);
  validateGround(s);
  validateRender(s);
  validateWater(s);
  validatePool(s);
  validateSpheres(s);
  validateBoxes(s);
  validateAo(s);
  for (const Drop& d : s.water.drops) validateDrop(d);
}

void validateDrop(const Drop& d) {
  requireRange(d.x, -1e4f, 1e4f, "water.drops[].x");
  requireRange(d.z, -1e4f, 1e4f, "water.drops[].z");
  requireRange(d.radius, 1e-6f, 1e4f, "water.drops[].radius");
  requireRange(d.amplitude, -1e4f, 1e4f, "water.drops[].amplitude");
  // Any frame is a time: one the run never reaches simply never comes.
}

}  // namespace tp::scene
