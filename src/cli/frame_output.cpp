#include "cli/frame_output.hpp"

#include <algorithm>
#include <cstdio>
#include <stdexcept>

#include "base/rational.hpp"
#include "cli/build_version.hpp"
#include "cli/frame_channels.hpp"
#include "cli/usage_error.hpp"
#include "io/image_io.hpp"
#include "reference/gbuffer_world.hpp"
#include "reference/reference_ao.hpp"

namespace tp::app {
namespace {

// Video rates are n/1 or n*1000/1001 (NTSC's 30000/1001).
constexpr int32_t kFpsMaxDenominator = 1001;

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

// The frame's EXR: RGBA, the AOVs asked for, the attributes (writeFrame).
void writeFrameExr(const RenderOptions& o, const scene::Scene& scene, const render::RenderedFrame& frame,
                   uint32_t frameNumber, const std::string& exr) {
  std::vector<float> aoRaw, aoRef;
  if (wants(o.aovs, "ao_raw"))
    aoRaw = toFrameSize(frame.aoRaw, frame.aoWidth, frame.aoHeight, frame.width, frame.height);
  if (wants(o.aovs, "ao_ref")) aoRef = referenceAo(scene, frame, frameNumber);
  const FrameChannelOptions channels{
      .aovs = o.aovs, .farPlane = scene.camera.farPlane, .transparentSky = o.transparentSky};
  io::FloatImage image = frameChannels(frame, channels, aoRaw, aoRef);
  std::vector<io::PixelType> types(image.channels.size(), io::PixelType::Float);
  if (!o.floatOutput) std::fill(types.begin(), types.begin() + 4, io::PixelType::Half);
  io::ExrAttributes attributes = frameExrAttributes(scene, frame, frameNumber);
  attributes.compression = o.compression;
  io::writeExr(exr, image, types, attributes);
}

}  // namespace

bool wants(const std::vector<std::string>& aovs, const char* name) {
  return std::find(aovs.begin(), aovs.end(), name) != aovs.end();
}

RasterPlan rasterPlan(const RenderOptions& o, const scene::Scene& scene) {
  const bool ao = wants(o.aovs, "ao") || wants(o.aovs, "ao_raw") || wants(o.aovs, "ao_ref");
  if (ao && (o.reference || o.modelReference || !scene.ao.enabled)) {
    throw UsageError(
        "--aov ao, ao_raw and ao_ref come from the SSAO passes: not with --reference or --no-ao, "
        "nor with a scene whose ao.enabled is false");
  }
  // A transparent sky needs to know where nothing is hit: the positions' pass.
  const bool geometry = wants(o.aovs, "Z") || wants(o.aovs, "N") || wants(o.aovs, "P") || o.transparentSky;
  // The HDR frame is read back for the EXR only; a PNG is the tonemapped frame.
  return {{.aovs = geometry, .skipping = !o.noSkip},
          {.hdr = !o.exr.empty(), .ldr = !o.png.empty(), .aovs = geometry, .ao = ao}};
}

base::Rational sceneFrameRate(const scene::Scene& scene) {
  return base::nearestRational(1.0 / double(scene.water.frameTime), kFpsMaxDenominator);
}

io::ExrAttributes frameExrAttributes(const scene::Scene& scene, const render::RenderedFrame& frame,
                                     uint32_t frameNumber) {
  return {.hasCamera = true,
          .worldToCamera = frame.worldToCamera,
          .worldToNDC = frame.worldToNDC,
          .linearRec709 = true,
          .software = versionText(),
          .frame = frameNumber,
          .framesPerSecond = sceneFrameRate(scene)};
}

void writeFrame(const RenderOptions& o, const scene::Scene& scene, const render::RenderedFrame& frame,
                uint32_t frameNumber, const std::string& exr, const std::string& png) {
  if (!exr.empty()) writeFrameExr(o, scene, frame, frameNumber, exr);
  if (!png.empty()) io::writePng(png, frame.width, frame.height, frame.srgb);
}

}  // namespace tp::app
