#include "reference/image_error.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "shared/tonemap.h"

namespace tp::render {

std::vector<uint8_t> tonemapToSrgb8(std::span<const float> rgba, float exposure) {
  std::vector<uint8_t> out(rgba.size());
  for (size_t p = 0; p < rgba.size() / 4; ++p) {
    const glm::vec3 display = shader::tonemap(glm::vec3(rgba[p * 4], rgba[p * 4 + 1], rgba[p * 4 + 2]), exposure);
    for (int c = 0; c < 3; ++c) out[p * 4 + c] = uint8_t(std::lround(std::clamp(display[c], 0.0f, 1.0f) * 255.0f));
    out[p * 4 + 3] = 255;
  }
  return out;
}

std::vector<float> boxDownsample(std::span<const float> rgba, uint32_t width, uint32_t height, uint32_t factor) {
  if (factor == 0 || width % factor || height % factor || rgba.size() != size_t(width) * height * 4) {
    throw std::invalid_argument("boxDownsample: the size is not a multiple of the factor");
  }
  const uint32_t w = width / factor, h = height / factor;
  std::vector<float> out(size_t(w) * h * 4, 0.0f);
  const float weight = 1.0f / float(factor * factor);
  for (uint32_t y = 0; y < height; ++y) {
    for (uint32_t x = 0; x < width; ++x) {
      const size_t from = (size_t(y) * width + x) * 4, to = (size_t(y / factor) * w + x / factor) * 4;
      for (int c = 0; c < 4; ++c) out[to + c] += weight * rgba[from + c];
    }
  }
  return out;
}

namespace {

// RMSE and largest difference over the RGB of the pixels the mask keeps
// (all, without one); `display(p)` gives pixel p of both images in display units.
template <typename Display>
ImageError displayDifference(size_t pixels, std::span<const uint8_t> mask, Display display) {
  if (!mask.empty() && mask.size() != pixels) throw std::invalid_argument("image error: the mask differs in size");
  ImageError e;
  double sum = 0.0;
  for (size_t p = 0; p < pixels; ++p) {
    if (!mask.empty() && !mask[p]) continue;
    const auto [da, db] = display(p);
    for (int c = 0; c < 3; ++c) {
      const double d = double(da[c]) - double(db[c]);
      sum += d * d;
      e.maxError = std::max(e.maxError, std::abs(d));
    }
    ++e.pixels;
  }
  e.rmse = e.pixels ? std::sqrt(sum / double(3 * e.pixels)) : 0.0;
  return e;
}

}  // namespace

ImageError tonemappedError(std::span<const float> a, std::span<const float> b, float exposure,
                           std::span<const uint8_t> mask) {
  if (a.size() != b.size() || a.size() % 4 != 0) throw std::invalid_argument("tonemappedError: images differ in size");
  return displayDifference(a.size() / 4, mask, [&](size_t p) {
    return std::pair{shader::tonemap(glm::vec3(a[p * 4], a[p * 4 + 1], a[p * 4 + 2]), exposure),
                     shader::tonemap(glm::vec3(b[p * 4], b[p * 4 + 1], b[p * 4 + 2]), exposure)};
  });
}

std::array<double, 3> meanRatio(std::span<const float> a, std::span<const float> b, std::span<const uint8_t> mask) {
  if (a.size() != b.size() || a.size() != mask.size() * 4) throw std::invalid_argument("meanRatio: sizes differ");
  std::array<double, 3> sumA{}, sumB{};
  for (size_t p = 0; p < mask.size(); ++p)
    for (size_t c = 0; c < 3 && mask[p]; ++c) {
      sumA[c] += a[p * 4 + c];
      sumB[c] += b[p * 4 + c];
    }
  return {sumA[0] / sumB[0], sumA[1] / sumB[1], sumA[2] / sumB[2]};
}

ImageError displayError(std::span<const uint8_t> a, std::span<const uint8_t> b, std::span<const uint8_t> mask) {
  if (a.size() != b.size() || a.size() % 4 != 0) throw std::invalid_argument("displayError: images differ in size");
  return displayDifference(a.size() / 4, mask, [&](size_t p) {
    return std::pair{glm::vec3(a[p * 4], a[p * 4 + 1], a[p * 4 + 2]) / 255.0f,
                     glm::vec3(b[p * 4], b[p * 4 + 1], b[p * 4 + 2]) / 255.0f};
  });
}

std::vector<uint8_t> waterPixelMask(const RenderedFrame& aovs, const scene::Water& water) {
  std::vector<uint8_t> mask(size_t(aovs.width) * aovs.height);
  if (aovs.position.size() != mask.size() * 4)
    throw std::invalid_argument("waterPixelMask: the frame has no position AOV");
  for (size_t k = 0; k < mask.size(); ++k) {
    const float* p = &aovs.position[k * 4];
    mask[k] = std::abs(p[0]) < 0.5f * water.extent && std::abs(p[2]) < 0.5f * water.extent &&
              std::abs(p[1] - water.level) < 0.1f;
  }
  return mask;
}

}  // namespace tp::render
