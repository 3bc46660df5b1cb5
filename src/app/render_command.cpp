#include "app/render_command.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <stdexcept>

#include "app/gpu_session.hpp"
#include "app/profile_table.hpp"
#include "io/atomic_file.hpp"
#include "io/image_io.hpp"
#include "render/gbuffer_world.hpp"
#include "render/image_error.hpp"
#include "render/reference_ao.hpp"
#include "render/reference_tracer.hpp"
#include "render/renderer.hpp"
#include "render/water_model.hpp"

namespace tp::app {
namespace {

bool wants(const std::vector<std::string>& aovs, const char* name) {
  return std::find(aovs.begin(), aovs.end(), name) != aovs.end();
}

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
  render::ReferenceAoOptions options{.radius = scene.ao.radius,
                                     .exactSpheres = false,
                                     .originOffset = g.uncertainty,
                                     .progress = [](double done) {
                                       std::fprintf(stderr, "reference AO: %3.0f%%\n", 100.0 * done);
                                     }};
  return render::referenceAmbientOcclusion(scene, nullptr, float(frameNumber) * scene.water.frameTime, g.position,
                                           g.normal, frame.width, frame.height, options);
}

// The CPU reference of the frame; the water is still simulated on the GPU,
// exactly as the renderer simulates it.
render::RenderedFrame renderReferenceFrame(GpuSession& session, const scene::Scene& scene, const RenderOptions& o) {
  std::optional<sim::WaterState> water;
  if (scene.water.enabled) water = render::simulateWater(session.context(), scene, o.frame);
  render::ReferenceOptions options{.samples = o.samples,
                                   .progress = [](double done) {
                                     std::fprintf(stderr, "reference: %3.0f%%\n", 100.0 * done);
                                   }};
  render::RenderedFrame frame =
      render::renderReference(scene, water ? &*water : nullptr, o.frame, o.width, o.height, options);
  if (!o.png.empty()) frame.srgb = render::tonemapToSrgb8(frame.rgba, scene.render.exposure);
  return frame;
}

}  // namespace

CLI::App* addRenderCommand(CLI::App& app, RenderOptions& o) {
  CLI::App* cmd = app.add_subcommand("render", "Render a frame offscreen to EXR (linear RGBA) and optionally PNG");
  addSceneOptions(cmd, o.scene);
  cmd->add_option("--width", o.width, "Image width in pixels")->capture_default_str()->check(CLI::Range(1u, kMaxFrameSide));
  cmd->add_option("--height", o.height, "Image height in pixels")->capture_default_str()->check(CLI::Range(1u, kMaxFrameSide));
  cmd->add_option("--frame", o.frame, "Frame number: the water after N frames of water.frame_time from the scene's start")
      ->capture_default_str();
  cmd->add_option("--out", o.out, "Output EXR path (written via a temporary file)")->type_name("PATH")->capture_default_str();
  cmd->add_option("--png", o.png, "Also write a tonemapped sRGB PNG preview here")->type_name("PATH");
  auto* half = cmd->add_flag("--half", o.halfOutput, "Write 16-bit half EXR channels (default)");
  auto* full = cmd->add_flag("--float", o.floatOutput, "Write 32-bit float EXR channels");
  half->excludes(full);
  addGpuOptions(cmd, o.validate, o.device);
  auto* profile = cmd->add_flag("--profile", o.profile,
                                "Print each pass recorded with its GPU milliseconds, dispatches, draws and workgroups");
  cmd->add_flag("--no-skip", o.noSkip,
                "Record every pass the scene has, even those this frame does not need (the frame to compare "
                "against; README, \"What a frame skips\")");
  cmd->add_option("--aov", o.aovs,
                  "Extra float32 EXR channels, comma-separated: Z (view depth), N (N.x N.y N.z world normal), "
                  "P (P.x P.y P.z world position); infinite Z and P where nothing is hit. With AO on: ao (after "
                  "blur and upsample), ao_raw (unblurred, at the AO resolution), ao_ref (ray traced from the same "
                  "G-buffer with Embree, 1024 rays per pixel; slow)")
      ->delimiter(',')
      ->type_name("LIST")
      ->check(CLI::IsMember({"Z", "N", "P", "ao", "ao_raw", "ao_ref"}));
  cmd->add_flag("--reference", o.reference,
                "Ray-trace the frame on the CPU instead (Embree; exact reflection, refraction and Fresnel, no "
                "caustics): the ground truth for error figures; slow")
      ->excludes(profile);
  cmd->add_option("--samples", o.samples, "Samples per pixel of --reference")
      ->capture_default_str()
      ->check(CLI::Range(1u, 65536u));
  return cmd;
}

int runRender(const RenderOptions& o) {
  checkFramePixels(o.width, o.height);
  // Check every output before any work, so a bad path costs nothing and leaves nothing.
  io::requireExtension(o.out, ".exr");
  io::checkWritable(o.out);
  if (!o.png.empty()) {
    io::requireExtension(o.png, ".png");
    io::checkWritable(o.png);
  }
  const scene::Scene scene = loadScene(o.scene);
  const bool aoAovs = wants(o.aovs, "ao") || wants(o.aovs, "ao_raw") || wants(o.aovs, "ao_ref");
  if (aoAovs && (o.reference || !scene.ao.enabled)) {
    throw std::runtime_error("--aov ao, ao_raw and ao_ref come from the SSAO passes: not with --reference or --no-ao, "
                             "nor with a scene whose ao.enabled is false");
  }

  const bool aovs = wants(o.aovs, "Z") || wants(o.aovs, "N") || wants(o.aovs, "P");
  GpuSession session(o.validate, o.device);
  render::RenderedFrame frame;
  if (o.reference) {
    frame = renderReferenceFrame(session, scene, o);
  } else {
    render::Renderer renderer(session.context(), scene, o.width, o.height, {.aovs = aovs, .skipping = !o.noSkip});
    frame = renderer.render({.frame = o.frame, .hdr = true, .ldr = !o.png.empty(), .aovs = aovs, .ao = aoAovs});
  }
  std::vector<float> aoRaw, aoRef;
  if (wants(o.aovs, "ao_raw")) aoRaw = toFrameSize(frame.aoRaw, frame.aoWidth, frame.aoHeight, frame.width, frame.height);
  if (wants(o.aovs, "ao_ref")) aoRef = referenceAo(scene, frame, o.frame);

  io::FloatImage image = withAovs(frame, o.aovs, aoRaw, aoRef);
  std::vector<io::PixelType> types(image.channels.size(), io::PixelType::Float);
  if (!o.floatOutput) std::fill(types.begin(), types.begin() + 4, io::PixelType::Half);
  io::ExrAttributes attributes{.hasCamera = true, .worldToCamera = frame.worldToCamera, .worldToNDC = frame.worldToNDC};
  io::writeExr(o.out, image, types, attributes);
  std::printf("wrote %s (%ux%u, %s) on %s\n", o.out.c_str(), frame.width, frame.height, o.floatOutput ? "float" : "half",
              o.reference ? "the CPU (reference)" : session.context().deviceName().c_str());
  if (!o.png.empty()) {
    io::writePng(o.png, frame.width, frame.height, frame.srgb);
    std::printf("wrote %s\n", o.png.c_str());
  }
  if (o.profile) printProfile(frame);
  return session.finish();
}

}  // namespace tp::app
