#pragma once
#include <cstdint>
#include <functional>

#include "render/renderer.hpp"
#include "scene/scene.hpp"
#include "sim/water_state.hpp"

namespace tp::render {

struct ReferenceOptions {
  uint32_t samples = 64;     // per pixel, Hammersley points over the pixel (a box filter)
  uint32_t maxSpecular = 8;  // reflections and refractions along one path
  // Called with the fraction of rows done, from one thread at a time.
  std::function<void(double)> progress = nullptr;
};

// The frame the renderer would draw, ray-traced on the CPU: Embree against the
// scene's triangles (the water surface is the simulated grid, shaded with the
// vertex normals the raster uses), spheres cast exactly, exact Fresnel and
// Snell at the water on every path in both directions (total internal
// reflection included), absorption along every path under water. Diffuse
// surfaces are shaded with the renderer's own functions (shared/shading.h):
// the sun without shadows and the sky's irradiance; light reaching the floor
// through the waves (caustics) is left out. `water` is the frame's simulated
// state (null without water). The result has the renderer's layout: linear
// RGBA, and normal and position/Z of the surface at each pixel's centre.
RenderedFrame renderReference(const scene::Scene& scene, const sim::WaterState* water, uint32_t frame, uint32_t width,
                              uint32_t height, const ReferenceOptions& options);

}  // namespace tp::render
