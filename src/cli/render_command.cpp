#include "cli/render_command.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <stdexcept>

#include "base/atomic_file.hpp"
#include "cli/frame_output.hpp"
#include "cli/frame_samples.hpp"
#include "cli/frame_size.hpp"
#include "cli/gpu_session.hpp"
#include "cli/number_checks.hpp"
#include "cli/profile_table.hpp"
#include "cli/render_sequence.hpp"
#include "cli/sequence_run.hpp"
#include "cli/usage_error.hpp"
#include "io/image_io.hpp"
#include "reference/gbuffer_world.hpp"
#include "reference/image_error.hpp"
#include "reference/path_tracer.hpp"
#include "reference/reference_ao.hpp"
#include "reference/reference_tracer.hpp"
#include "render/renderer.hpp"
#include "shading/water_model.hpp"

namespace tp::app {
namespace {

// --samples with --reference, or its default: 64 rays a pixel.
uint32_t referenceSamples(const RenderOptions& o) { return o.samples > 0 ? o.samples : 64; }

// The CPU reference of the frame: the path tracer (the truth) or the
// raster's lighting model traced; the water is still simulated on the GPU,
// exactly as the renderer simulates it.
render::RenderedFrame renderReferenceFrame(GpuSession& session, const scene::Scene& scene, const RenderOptions& o) {
  std::optional<sim::WaterState> water;
  if (scene.water.enabled) water = sim::simulateWater(session.context(), scene, o.frame);
  render::RenderedFrame frame;
  if (o.modelReference) {
    render::ReferenceOptions options{.samples = referenceSamples(o), .progress = [](double done) {
                                       std::fprintf(stderr, "reference: %3.0f%%\n", 100.0 * done);
                                     }};
    frame = render::renderReference(scene, water ? &*water : nullptr, o.frame, o.width, o.height, options);
  } else {
    render::PathTracerOptions options{.samples = referenceSamples(o),
                                      .seed = o.seed,
                                      .timeBudgetSeconds = o.timeBudget,
                                      .progress = [](uint32_t done, uint32_t total) {
                                        std::fprintf(stderr, "reference: %3.0f%% (%u of %u samples)\n",
                                                     100.0 * done / total, done, total);
                                      }};
    render::PathTracedFrame traced =
        render::renderPathTraced(scene, water ? &*water : nullptr, o.frame, o.width, o.height, options);
    if (traced.samples < options.samples)
      std::fprintf(stderr, "reference: the time budget of %g s ran out at %u samples of %u\n", o.timeBudget,
                   traced.samples, options.samples);
    frame = std::move(traced.frame);
  }
  if (!o.png.empty()) frame.srgb = render::tonemapToSrgb8(frame.rgba, scene.render.exposure);
  return frame;
}

}  // namespace

CLI::App* addRenderCommand(CLI::App& app, RenderOptions& o) {
  CLI::App* cmd = app.add_subcommand(
      "render",
      "Render a frame, or a sequence, offscreen to EXR (linear RGBA and AOVs), PNG (tonemapped sRGB) or both");
  addSceneOptions(cmd, o.scene);
  cmd->add_option("--size", o.size, "Image size, e.g. 1920x1080 (default 1280x720)")
      ->type_name("WxH")
      ->check(frameSizeCheck(1, kMaxFrameSide));
  // The old spelling of --size, out of --help (docs/command-line.md).
  for (auto [name, side] : {std::pair{"--width", &o.oldWidth}, std::pair{"--height", &o.oldHeight}}) {
    cmd->add_option(name, *side, "the old spelling of --size, one side")->group("")->check(inRange(1u, kMaxFrameSide));
  }
  auto* frame = cmd->add_option("--frame", o.frame,
                                "Frame number: the water after N frames of water.frame_time from the scene's start")
                    ->capture_default_str()
                    ->check(frameNumber());
  auto* frames =
      cmd->add_option(
             "--frames", o.frames,
             "Render the frames A to B (A-B, both included), each to --out with its #### (or %04d or $F4) "
             "replaced by the frame number (e.g. frames/shot.####.exr; --png likewise), with progress (a bar on a "
             "terminal, a line per frame otherwise); SIGINT or SIGTERM stop it after the frame being "
             "written (exit 130 or 143)")
          ->type_name("A-B")
          ->excludes(frame);
  cmd->add_option("--checkpoint-every", o.checkpointEvery,
                  "With --frames: save the water's state after every frame that is a multiple of K, in "
                  "--checkpoint-dir")
      ->type_name("K")
      ->check(inRange(1u, 1000000u))
      ->needs(frames);
  cmd->add_option("--checkpoint-dir", o.checkpointDir,
                  "With --frames: where checkpoints are saved (water.NNNNNN.exr in `sim`'s format, and .json); a "
                  "range starts from the latest one at or before its first frame to render, so any range can run "
                  "on its own machine; made if it is not there")
      ->type_name("DIR")
      ->needs(frames);
  addResumeOption(cmd, o.resume, frames);
  cmd->add_option(
         "--out", o.outs,
         "Output file, its format from its extension: .exr (linear RGBA and the AOVs) or .png (the "
         "tonemapped 8-bit sRGB frame); give one of each for both; default render.exr; with --frames, a "
         "pattern with #### (or %04d or $F4); each written via a temporary file, its folder made if it is not there")
      ->type_name("PATH");
  cmd->add_option("--png", o.pngAlso,
                  "Also write a PNG here, beside the EXR (render.exr unless --out names one): the old spelling of "
                  "--out PATH.png")
      ->type_name("PATH");
  auto* half = cmd->add_flag("--half", o.halfOutput, "Write 16-bit half EXR channels (default)");
  auto* full = cmd->add_flag("--float", o.floatOutput, "Write 32-bit float EXR channels");
  half->excludes(full);
  addGpuOptions(cmd, o.validate, o.device);
  auto* profile =
      cmd->add_flag("--profile", o.profile,
                    "Submit each pass on its own and print it with its wall and GPU milliseconds, dispatches, "
                    "draws and workgroups");
  cmd->add_flag("--no-skip", o.noSkip,
                "Record every pass the scene has, even those this frame does not need, and draw with the "
                "general shaders, not those specialized by the scene (the frame to compare against; "
                "docs/frame-skipping.md)");
  cmd->add_option("--aov", o.aovs,
                  "Extra float32 EXR channels in layers, comma-separated: Z (view depth), N (N.X N.Y N.Z world "
                  "normal), P (P.X P.Y P.Z world position); where nothing is hit Z is the camera's far plane and P "
                  "on it. With AO on: ao (AO.Y, after blur and upsample), ao_raw (AO_raw.Y, unblurred, at the AO "
                  "resolution), ao_ref (AO_ref.Y, ray traced from the same G-buffer with Embree, 1024 rays per "
                  "pixel; slow)")
      ->delimiter(',')
      ->type_name("LIST")
      ->check(CLI::IsMember({"Z", "N", "P", "ao", "ao_raw", "ao_ref"}));
  cmd->add_flag("--transparent-sky", o.transparentSky,
                "Write RGBA 0 in the EXR where only the sky is seen, for compositing over a plate (the sky still "
                "lights and is reflected; the PNG keeps it)");
  cmd->add_option("--compression", o.compression,
                  "EXR compression: zip, piz, dwaa (lossy on R G B and the AO layers) or none")
      ->type_name("NAME")
      ->capture_default_str()
      ->check(CLI::IsMember(io::exrCompressions()));
  CLI::Option* reference =
      cmd->add_flag("--reference", o.reference,
                    "Path-trace the frame on the CPU instead (Embree; the rendering equation for the scene's "
                    "materials: every bounce, glass and water with Fresnel, absorption and scattering, the sun "
                    "through the waves): the ground truth for error figures; slow")
          ->excludes(profile)
          ->excludes(frames);
  cmd->add_flag("--reference-model", o.modelReference,
                "Trace the raster's own lighting model on the CPU instead (its sky irradiance and sun, "
                "exact paths through water and glass): checks the raster's paths, not its light")
      ->excludes(profile)
      ->excludes(frames)
      ->excludes(reference);
  cmd->add_option("--seed", o.seed, "With --reference: the paths' seed; another seed, independent noise (default 0)")
      ->type_name("N")
      ->needs(reference);
  cmd->add_option("--time-budget", o.timeBudget,
                  "With --reference: stop after the pass of samples that passes this many seconds (at least one "
                  "pass; default: none)")
      ->type_name("SECONDS")
      ->check(CLI::PositiveNumber)
      ->needs(reference);
  profile->excludes(frames);
  cmd->add_option("--samples", o.samples,
                  "Samples per pixel: N jittered frames of the same moment, averaged (anti-aliasing; the water "
                  "steps once; AOVs at the pixel centres; default 1), or with --reference or --reference-model N paths "
                  "(default 64)")
      ->type_name("N")
      ->check(inRange(1u, 65536u));
  return cmd;
}

uint32_t rasterSamples(const RenderOptions& o) { return o.samples > 0 ? o.samples : 1; }

RenderOptions resolveOutputs(const RenderOptions& options) {
  RenderOptions o = options;
  if (!o.size.empty()) {
    if (o.oldWidth > 0 || o.oldHeight > 0) throw UsageError("--size " + o.size + ": not with --width or --height");
    const FrameSize size = *parseFrameSize(o.size, 1, kMaxFrameSide);  // checked by the parser
    o.width = size.width;
    o.height = size.height;
  }
  if (o.oldWidth > 0) o.width = o.oldWidth;
  if (o.oldHeight > 0) o.height = o.oldHeight;
  std::vector<std::string> outs = o.outs;
  if (outs.empty()) outs.push_back("render.exr");
  if (!o.pngAlso.empty()) {
    if (!base::hasExtension(o.pngAlso, ".png")) throw UsageError("--png " + o.pngAlso + ": the path must end in .png");
    outs.push_back(o.pngAlso);
  }
  o.exr.clear();
  o.png.clear();
  for (const std::string& out : outs) {
    std::string* slot = base::hasExtension(out, ".exr") ? &o.exr : base::hasExtension(out, ".png") ? &o.png : nullptr;
    if (!slot) {
      throw UsageError("--out " + out + ": the format comes from the extension, which must be .exr or .png");
    }
    if (!slot->empty()) throw UsageError("--out " + out + ": a second output of its format (one of each: .exr, .png)");
    *slot = out;
  }
  if (!o.aovs.empty() && o.exr.empty()) throw UsageError("--aov: the AOVs are EXR channels; add --out PATH.exr");
  if (o.profile && o.samples > 1) {
    throw UsageError("--profile times the passes of one frame: not with --samples " + std::to_string(o.samples));
  }
  return o;
}

int runRender(const RenderOptions& options) {
  const RenderOptions o = resolveOutputs(options);
  checkFramePixels(o.width, o.height);
  if (!o.frames.empty()) return runRenderSequence(o);
  // Check every output before any work, so a bad path costs nothing and leaves nothing.
  for (const std::string& path : {o.exr, o.png}) {
    if (!path.empty()) base::checkWritable(path);
  }
  // The camera where its path or turntable puts it at this frame's time.
  scene::Scene scene = loadScene(o.scene);
  scene.camera = scene::cameraAtFrame(scene, o.frame);
  RasterPlan plan = rasterPlan(o, scene);
  GpuSession session(o.validate, o.device);
  render::RenderedFrame frame;
  if (o.reference || o.modelReference) {
    frame = renderReferenceFrame(session, scene, o);
  } else {
    render::Renderer renderer(session.context(), scene, o.width, o.height, plan.renderer);
    if (o.profile) {
      // lavapipe compiles a pipeline's shaders for the state of its first draw,
      // at that draw: the profile is of a second frame, as a sequence renders it.
      plan.request.frame = o.frame > 0 ? o.frame - 1 : 0;
      renderer.render(plan.request);
      plan.request.passWallTimes = true;
    }
    plan.request.frame = o.frame;
    frame = renderSamples(renderer, plan.request, rasterSamples(o), o.transparentSky);
  }
  writeFrame(o, scene, frame, o.frame, o.exr, o.png);
  const std::string device = o.reference || o.modelReference ? "the CPU (reference)" : session.context().deviceName();
  if (!o.exr.empty()) {
    std::printf("wrote %s (%ux%u, %s) on %s\n", o.exr.c_str(), frame.width, frame.height,
                o.floatOutput ? "float" : "half", device.c_str());
  }
  if (!o.png.empty()) {
    std::printf("wrote %s (%ux%u) on %s\n", o.png.c_str(), frame.width, frame.height, device.c_str());
  }
  if (o.profile) printProfile(frame);
  return session.finish();
}

}  // namespace tp::app
