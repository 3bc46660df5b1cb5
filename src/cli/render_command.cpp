#include "cli/render_command.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <stdexcept>

#include "base/atomic_file.hpp"
#include "cli/frame_output.hpp"
#include "cli/gpu_session.hpp"
#include "cli/profile_table.hpp"
#include "cli/render_sequence.hpp"
#include "io/image_io.hpp"
#include "reference/gbuffer_world.hpp"
#include "reference/image_error.hpp"
#include "reference/reference_ao.hpp"
#include "reference/reference_tracer.hpp"
#include "render/renderer.hpp"
#include "shading/water_model.hpp"

namespace tp::app {
namespace {

// The CPU reference of the frame; the water is still simulated on the GPU,
// exactly as the renderer simulates it.
render::RenderedFrame renderReferenceFrame(GpuSession& session, const scene::Scene& scene, const RenderOptions& o) {
  std::optional<sim::WaterState> water;
  if (scene.water.enabled) water = sim::simulateWater(session.context(), scene, o.frame);
  render::ReferenceOptions options{.samples = o.samples, .progress = [](double done) {
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
  cmd->add_option("--width", o.width, "Image width in pixels")
      ->capture_default_str()
      ->check(CLI::Range(1u, kMaxFrameSide));
  cmd->add_option("--height", o.height, "Image height in pixels")
      ->capture_default_str()
      ->check(CLI::Range(1u, kMaxFrameSide));
  auto* frame = cmd->add_option("--frame", o.frame,
                                "Frame number: the water after N frames of water.frame_time from the scene's start")
                    ->capture_default_str();
  auto* frames =
      cmd->add_option("--frames", o.frames,
                      "Render the frames A to B (A-B, both included), each to --out with its #### replaced by the "
                      "frame number (e.g. frames/shot.####.exr; --png likewise), with progress (a bar on a "
                      "terminal, a line per frame otherwise); SIGINT or SIGTERM stop it after the frame being "
                      "written (exit 130 or 143)")
          ->type_name("A-B")
          ->excludes(frame);
  cmd->add_option("--checkpoint-every", o.checkpointEvery,
                  "With --frames: save the water's state after every frame that is a multiple of K, in "
                  "--checkpoint-dir")
      ->type_name("K")
      ->check(CLI::Range(1u, 1000000u))
      ->needs(frames);
  cmd->add_option("--checkpoint-dir", o.checkpointDir,
                  "With --frames: where checkpoints are saved (water.NNNNNN.exr in `sim`'s format, and .json); a "
                  "range starts from the latest one at or before its first frame to render, so any range can run "
                  "on its own machine")
      ->type_name("DIR")
      ->needs(frames);
  cmd->add_flag("--resume", o.resume,
                "With --frames: leave out the frames whose files are already there and whole (a run stopped or "
                "split goes on where it ended)")
      ->needs(frames);
  cmd->add_option("--out", o.out, "Output EXR path (written via a temporary file); with --frames, a pattern with ####")
      ->type_name("PATH")
      ->capture_default_str();
  cmd->add_option("--png", o.png, "Also write a tonemapped sRGB PNG preview here; with --frames, a pattern with ####")
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
                "Record every pass the scene has, even those this frame does not need (the frame to compare "
                "against; docs/frame-skipping.md)");
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
  cmd->add_flag("--reference", o.reference,
                "Ray-trace the frame on the CPU instead (Embree; exact reflection, refraction and Fresnel, no "
                "caustics): the ground truth for error figures; slow")
      ->excludes(profile)
      ->excludes(frames);
  profile->excludes(frames);
  cmd->add_option("--samples", o.samples, "Samples per pixel of --reference")
      ->capture_default_str()
      ->check(CLI::Range(1u, 65536u));
  return cmd;
}

int runRender(const RenderOptions& o) {
  checkFramePixels(o.width, o.height);
  if (!o.frames.empty()) return runRenderSequence(o);
  // Check every output before any work, so a bad path costs nothing and leaves nothing.
  base::requireExtension(o.out, ".exr");
  base::checkWritable(o.out);
  if (!o.png.empty()) {
    base::requireExtension(o.png, ".png");
    base::checkWritable(o.png);
  }
  const scene::Scene scene = loadScene(o.scene);
  RasterPlan plan = rasterPlan(o, scene);
  GpuSession session(o.validate, o.device);
  render::RenderedFrame frame;
  if (o.reference) {
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
    frame = renderer.render(plan.request);
  }
  writeFrame(o, scene, frame, o.frame, o.out, o.png);
  std::printf("wrote %s (%ux%u, %s) on %s\n", o.out.c_str(), frame.width, frame.height,
              o.floatOutput ? "float" : "half",
              o.reference ? "the CPU (reference)" : session.context().deviceName().c_str());
  if (!o.png.empty()) std::printf("wrote %s\n", o.png.c_str());
  if (o.profile) printProfile(frame);
  return session.finish();
}

}  // namespace tp::app
