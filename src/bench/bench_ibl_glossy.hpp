#pragma once
#include "bench/bench_ibl.hpp"
#include "gpu/context.hpp"
#include "render/sky_image.hpp"

namespace tp::app {

// bench ibl's second table: the glossy prefilter of `sky` (see BenchIblOptions).
void benchGlossyPrefilter(const gpu::Context& ctx, const render::SkyImage& sky, const BenchIblOptions& options);

}  // namespace tp::app
