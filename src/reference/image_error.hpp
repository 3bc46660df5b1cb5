#pragma once
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "render/renderer.hpp"
#include "scene/scene.hpp"

namespace tp::render {

// The tonemap pass on the CPU (shared/tonemap.h): linear RGBA to RGBA8 sRGB,
// alpha 255, rounded as a UNORM store rounds.
std::vector<uint8_t> tonemapToSrgb8(std::span<const float> rgba, float exposure);

struct ImageError {
  double rmse = 0.0;      // over the RGB channels of the compared pixels
  double maxError = 0.0;  // largest channel difference
  size_t pixels = 0;      // pixels compared
};

// The difference a viewer sees: both linear RGBA images tonemapped (without
// the 8-bit rounding), in display units 0..1. With a mask (one byte per
// pixel), only pixels whose byte is non-zero count.
ImageError tonemappedError(std::span<const float> a, std::span<const float> b, float exposure,
                           std::span<const uint8_t> mask = {});

// The linear RGB of a over that of b, channel by channel, each summed over
// the pixels whose mask byte is non-zero: a bias that RMSE does not sign.
std::array<double, 3> meanRatio(std::span<const float> a, std::span<const float> b, std::span<const uint8_t> mask);

// The same difference between two RGBA8 sRGB images (the tonemap pass's
// output, a filtered one: the morphological anti-aliasing), in display units.
ImageError displayError(std::span<const uint8_t> a, std::span<const uint8_t> b, std::span<const uint8_t> mask = {});

// A linear RGBA image averaged over factor x factor blocks (width and height
// multiples of factor): a raster rendered at factor times the resolution, so
// filtered, meets the reference's many samples per pixel at its silhouettes.
std::vector<float> boxDownsample(std::span<const float> rgba, uint32_t width, uint32_t height, uint32_t factor);

// One byte per pixel, 1 where the frame's first surface (its position AOV) is
// the water: inside the water's square, within 0.1 m of its rest level.
std::vector<uint8_t> waterPixelMask(const RenderedFrame& aovs, const scene::Water& water);

}  // namespace tp::render
