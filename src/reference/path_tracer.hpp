#pragma once
#include <cstdint>
#include <functional>

#include "render/renderer.hpp"
#include "scene/scene.hpp"
#include "sim/water_state.hpp"

namespace tp::render {

struct PathTracerOptions {
  uint32_t samples = 256;    // paths per pixel, each from a uniform point of it (a box filter of one pixel)
  uint32_t seed = 0;         // another seed, independent noise; the same seed, the same bits
  uint32_t maxBounces = 64;  // surfaces and scattering events along a path at most
  // Stop after the pass of samples that passes this many seconds (0: none);
  // at least one pass is rendered.
  double timeBudgetSeconds = 0.0;
  // Called after each pass with the samples each pixel has and the most asked.
  std::function<void(uint32_t done, uint32_t total)> progress = nullptr;
};

struct PathTracedFrame {
  RenderedFrame frame;
  uint32_t samples = 0;  // per pixel, fewer than asked when the time budget ran out
};

// The ground truth: the frame ray-traced on the CPU by a path tracer of the
// rendering equation for the scene's materials (docs/rendering.md#the-reference).
// It shares with the raster only what is exact by construction: the
// geometry (the water's surface reaching the walls, with its vertex
// normals), the patterns' albedos and the sky's radiance function. Opaque
// surfaces are Lambertian with a GGX lobe (reference/path_bsdf.hpp); water
// and glass are dielectrics with exact Fresnel, total internal reflection
// and internal bounces; the water absorbs and scatters along every path in
// it (Henyey-Greenstein), and radiance crossing an interface scales by the
// squared ratio of the indices. Paths end by Russian roulette after three
// bounces, or at `maxBounces`. Lights: the sky drawn by importance and the
// sun's disc drawn over its cone, each combined with the BSDF's direction
// by the power heuristic; under the water the sun is reached by a shadow
// ray refracted through the flat surface at its rest level, with Fresnel,
// the disc's solid angle compressed, absorption on the way down, and the
// focusing of the waves from light tracing (reference_caustics); paths that
// reach the sun by one refraction out of the water are that estimator's and
// are not counted twice. In the air the sun's image in the water is a light
// too: mirrored at the rest level, times Fresnel's reflectance, under flat
// water weighed against the paths that reach the sun by one reflection off
// it, under waves times their focusing of it (light-traced too) with those
// paths not counted. Samples come from a scrambled Sobol sequence
// (reference/path_sampler.hpp). The AOVs are those of the surface at each
// pixel's centre.
PathTracedFrame renderPathTraced(const scene::Scene& scene, const sim::WaterState* water, uint32_t frame,
                                 uint32_t width, uint32_t height, const PathTracerOptions& options);

}  // namespace tp::render
