#pragma once
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "scene/scene.hpp"
#include "sim/water_state.hpp"

namespace tp::render {

struct ReferenceAoOptions {
  float radius = 0.5f;  // metres: occluders farther than this along a ray do not count
  // Cosine-weighted rays per pixel. 1024 keeps the reference's own noise well
  // under the SSAO errors it is meant to measure: against closed forms
  // (tests/reference_ao_test.cpp) the per-pixel error measured RMS 0.002, worst
  // 0.0055, where 1024 independent rays would have a standard error up to 0.016.
  uint32_t rays = 1024;
  // true: the spheres are cast exactly (points given on the true sphere);
  // false: as the raster draws them, tessellated, for points taken from a
  // rasterised G-buffer, which lie on the tessellation, inside the true sphere.
  bool exactSpheres = true;
  // Per pixel, how far the ray starts off the surface along its normal, where
  // the given positions are uncertain by more than the default 1e-4 m (those
  // reconstructed from a depth buffer: WorldGbuffer::uncertainty). Empty: the default.
  std::span<const float> originOffset;
  // Called with the fraction of rows done, at most every tenth (the tracer's habit).
  std::function<void(double)> progress = nullptr;
};

// Ambient occlusion of each pixel's surface, ray traced on the CPU with Embree
// against the frame's opaque geometry: every triangle mesh sceneMeshes returns
// except the water surface and glass spheres and boxes, and the spheres cast exactly, as ReferenceScene
// does (or tessellated, ReferenceAoOptions::exactSpheres). Per pixel, AO = 1 - (rays that hit something within
// `radius`) / rays, the rays cosine-weighted about the normal; 1 where the pixel has no surface. `position` and
// `normal` are RGBA float images (width * height * 4, rows top first) of world position and world normal, as the
// renderer's AOVs give them: position +inf (normal zero) where nothing is hit; the normal faces the side the pixel is
// seen from. Returns one value per pixel, in the images' order. Deterministic: the same inputs give the same bits on
// every run. Throws std::invalid_argument on image sizes that do not match, a radius that is not positive and finite,
// or no rays.
std::vector<float> referenceAmbientOcclusion(const scene::Scene& scene, const sim::WaterState* water, float time,
                                             std::span<const float> position, std::span<const float> normal,
                                             uint32_t width, uint32_t height, const ReferenceAoOptions& options);

}  // namespace tp::render
