#include "cli/frame_output.hpp"

#include <algorithm>
#include <cstdio>
#include <stdexcept>

#include "cli/usage_error.hpp"
#include "io/image_io.hpp"
#include "reference/gbuffer_world.hpp"
#include "reference/reference_ao.hpp"

namespace tp::app {
namespace {

// One float per pixel of a `width` x `height` image, nearest-sampled to the
// frame's size (the raw AO at half resolution).
std::vector<float> toFrameSize(const std::vector<float>& values, uint32_t width, uint32_t height, uint32_t frameWidth,
                               uint32_t frameHeight) {
  std::vector<float> out(size_t(frameWidth) * frameHeight);
  for (uint32_t y = 0; y < frameHeight; ++y) {
    for (uint32_t x = 0; x < frameWidth; ++x) {
      out[size_t(y) * frameWidth + x] = values[size_t(y * height / frameHeight) * width + x * width / frameWidth];
    }
  }
  return out;
}

// RGBA, then each requested AOV's channels (layer.channel names), interleaved.
// `ao`, `aoRaw`, `aoRef`: one value per pixel, where requested.
io::FloatImage withAovs(const render::RenderedFrame& frame, const std::vector<std::string>& aovs,
                        const std::vector<float>& aoRaw, const std::vector<float>& aoRef) {
  struct Channel {
    std::string name;
    const std::vector<float>* source;
    int component;
    int stride;
  };
  std::vector<Channel> channels{
      {"R", &frame.rgba, 0, 4}, {"G", &frame.rgba, 1, 4}, {"B", &frame.rgba, 2, 4}, {"A", &frame.rgba, 3, 4}};
  if (wants(aovs, "Z")) channels.push_back({"Z", &frame.position, 3, 4});
  if (wants(aovs, "N")) {
    for (int c = 0; c < 3; ++c) channels.push_back({std::string("N.") + "xyz"[c], &frame.normal, c, 4});
  }
  if (wants(aovs, "P")) {
    for (int c = 0; c < 3; ++c) channels.push_back({std::string("P.") + "xyz"[c], &frame.position, c, 4});
  }
  if (wants(aovs, "ao")) channels.push_back({"ao", &frame.ao, 0, 1});
  if (wants(aovs, "ao_raw")) channels.push_back({"ao_raw", &aoRaw, 0, 1});
  if (wants(aovs, "ao_ref")) channels.push_back({"ao_ref", &aoRef, 0, 1});
  io::FloatImage image{frame.width, frame.height, {}, {}};
  for (const auto& c : channels) image.channels.push_back(c.name);
  const size_t pixels = size_t(frame.width) * frame.height;
  image.pixels.resize(pixels * channels.size());
  for (size_t p = 0; p < pixels; ++p) {
    for (size_t c = 0; c < channels.size(); ++c) {
      image.pixels[p * channels.size() + c] = (*channels[c].source)[p * channels[c].stride + channels[c].component];
    }
  }
  return image;
}

// Ambient occlusion ray traced from the frame's own G-buffer, the ground truth
// of the SSAO error figures.
std::vector<float> referenceAo(const scene::Scene& scene, const render::RenderedFrame& frame, uint32_t frameNumber) {
  const render::WorldGbuffer g = render::worldGbuffer(frame);
  render::ReferenceAoOptions options{
      .radius = scene.ao.radius, .exactSpheres = false, .originOffset = g.uncertainty, .progress = [](double done) {
        std::fprintf(stderr, "reference AO: %3.0f%%\n", 100.0 * done);
      }};
  return render::referenceAmbientOcclusion(scene, nullptr, float(frameNumber) * scene.water.frameTime, g.position,
                                           g.normal, frame.width, frame.height, options);
}

}  // namespace

bool wants(const std::vector<std::string>& aovs, const char* name) {
  return std::find(aovs.begin(), aovs.end(), name) != aovs.end();
}

RasterPlan rasterPlan(const RenderOptions& o, const scene::Scene& scene) {
  const bool ao = wants(o.aovs, "ao") || wants(o.aovs, "ao_raw") || wants(o.aovs, "ao_ref");
  if (ao && (o.reference || !scene.ao.enabled)) {
    throw UsageError(
        "--aov ao, ao_raw and ao_ref come from the SSAO passes: not with --reference or --no-ao, "
        "nor with a scene whose ao.enabled is false");
  }
  const bool geometry = wants(o.aovs, "Z") || wants(o.aovs, "N") || wants(o.aovs, "P");
  return {{.aovs = geometry, .skipping = !o.noSkip}, {.hdr = true, .ldr = !o.png.empty(), .aovs = geometry, .ao = ao}};
}

void writeFrame(const RenderOptions& o, const scene::Scene& scene, const render::RenderedFrame& frame,
                uint32_t frameNumber, const std::string& exr, const std::string& png) {
  std::vector<float> aoRaw, aoRef;
  if (wants(o.aovs, "ao_raw"))
    aoRaw = toFrameSize(frame.aoRaw, frame.aoWidth, frame.aoHeight, frame.width, frame.height);
  if (wants(o.aovs, "ao_ref")) aoRef = referenceAo(scene, frame, frameNumber);
  io::FloatImage image = withAovs(frame, o.aovs, aoRaw, aoRef);
  std::vector<io::PixelType> types(image.channels.size(), io::PixelType::Float);
  if (!o.floatOutput) std::fill(types.begin(), types.begin() + 4, io::PixelType::Half);
  io::ExrAttributes attributes{.hasCamera = true, .worldToCamera = frame.worldToCamera, .worldToNDC = frame.worldToNDC};
  if (!exr.empty()) io::writeExr(exr, image, types, attributes);
  if (!png.empty()) io::writePng(png, frame.width, frame.height, frame.srgb);
}

}  // namespace tp::app
