#include "cli/frame_channels.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace tp::app {
namespace {

bool sky(const render::RenderedFrame& frame, size_t pixel) { return !std::isfinite(frame.position[pixel * 4 + 3]); }

// frame.position with the pixels where nothing is hit moved onto the far
// plane: xyz the pixel centre's ray at view depth farPlane, w farPlane.
std::vector<float> finitePositions(const render::RenderedFrame& frame, float farPlane) {
  std::vector<float> out = frame.position;
  // Double precision: the far plane is thousands of near planes away.
  const glm::dmat4 ndcToWorld = glm::inverse(glm::dmat4(frame.worldToNDC));
  for (uint32_t y = 0; y < frame.height; ++y) {
    for (uint32_t x = 0; x < frame.width; ++x) {
      const size_t p = size_t(y) * frame.width + x;
      if (!sky(frame, p)) continue;
      // Vulkan's NDC: y down the image, depth 1 on the far plane.
      const glm::dvec4 ndc(2.0 * (x + 0.5) / frame.width - 1.0, 2.0 * (y + 0.5) / frame.height - 1.0, 1.0, 1.0);
      const glm::dvec4 world = ndcToWorld * ndc;
      for (int c = 0; c < 3; ++c) out[p * 4 + c] = float(world[c] / world.w);
      out[p * 4 + 3] = farPlane;
    }
  }
  return out;
}

// frame.rgba with RGBA 0 (premultiplied: nothing) where nothing is hit.
std::vector<float> transparentSky(const render::RenderedFrame& frame) {
  std::vector<float> out = frame.rgba;
  for (size_t p = 0; p < size_t(frame.width) * frame.height; ++p) {
    if (sky(frame, p)) std::fill_n(out.begin() + p * 4, 4, 0.0f);
  }
  return out;
}

}  // namespace

std::vector<std::string> aovChannelNames(const std::string& aov) {
  if (aov == "Z") return {"Z"};
  if (aov == "N") return {"N.X", "N.Y", "N.Z"};
  if (aov == "P") return {"P.X", "P.Y", "P.Z"};
  if (aov == "ao") return {"AO.Y"};
  if (aov == "ao_raw") return {"AO_raw.Y"};
  if (aov == "ao_ref") return {"AO_ref.Y"};
  throw std::logic_error("no EXR channels for --aov " + aov);
}

io::FloatImage frameChannels(const render::RenderedFrame& frame, const FrameChannelOptions& options,
                             const std::vector<float>& aoRaw, const std::vector<float>& aoRef) {
  struct Source {
    const std::vector<float>* values;
    int stride;  // floats per pixel
  };
  const size_t pixels = size_t(frame.width) * frame.height;
  const bool positions = frame.position.size() == pixels * 4;
  if (options.transparentSky && !positions) throw std::logic_error("a transparent sky needs the frame's positions");
  // Several samples give the pixels the sky shows through their share of it.
  const std::vector<float> rgba = !options.transparentSky     ? std::vector<float>{}
                                  : !frame.foreground.empty() ? frame.foreground
                                                              : transparentSky(frame);
  const std::vector<float> position = positions ? finitePositions(frame, options.farPlane) : std::vector<float>{};
  auto sourceOf = [&](const std::string& aov) -> Source {
    if (aov == "Z" || aov == "P") return {&position, 4};
    if (aov == "N") return {&frame.normal, 4};
    if (aov == "ao") return {&frame.ao, 1};
    if (aov == "ao_raw") return {&aoRaw, 1};
    return {&aoRef, 1};
  };

  struct Channel {
    std::string name;
    Source source;
    int component;
  };
  std::vector<Channel> channels;
  const Source beauty{options.transparentSky ? &rgba : &frame.rgba, 4};
  for (int c = 0; c < 4; ++c) channels.push_back({std::string(1, "RGBA"[c]), beauty, c});
  // Z is position's w; the other AOVs' channels are their first components.
  for (const char* aov : {"Z", "N", "P", "ao", "ao_raw", "ao_ref"}) {
    if (std::find(options.aovs.begin(), options.aovs.end(), aov) == options.aovs.end()) continue;
    const std::vector<std::string> names = aovChannelNames(aov);
    const int first = std::string(aov) == "Z" ? 3 : 0;
    for (size_t c = 0; c < names.size(); ++c) channels.push_back({names[c], sourceOf(aov), first + int(c)});
  }

  io::FloatImage image{frame.width, frame.height, {}, {}};
  for (const auto& c : channels) image.channels.push_back(c.name);
  image.pixels.resize(pixels * channels.size());
  for (size_t p = 0; p < pixels; ++p) {
    for (size_t c = 0; c < channels.size(); ++c) {
      const Source& s = channels[c].source;
      image.pixels[p * channels.size() + c] = (*s.values)[p * s.stride + channels[c].component];
    }
  }
  return image;
}

}  // namespace tp::app
