#include "cli/render_sequence.hpp"

#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <stdexcept>
#include <vector>

#include "base/atomic_file.hpp"
#include "base/background_work.hpp"
#include "cli/checkpoint_files.hpp"
#include "cli/frame_output.hpp"
#include "cli/frame_samples.hpp"
#include "cli/frame_sequence.hpp"
#include "cli/gpu_session.hpp"
#include "cli/interrupt_guard.hpp"
#include "cli/sequence_progress.hpp"
#include "cli/sequence_run.hpp"
#include "cli/usage_error.hpp"
#include "io/image_io.hpp"
#include "render/renderer.hpp"

namespace tp::app {
namespace {

// Whether a frame's files are there and whole, as a finished render leaves them.
bool alreadyWritten(const std::string& exr, const std::string& png, uint32_t width, uint32_t height) {
  for (const std::string& path : {exr, png}) {
    if (!path.empty() && !imageIsWhole(path, width, height)) return false;
  }
  return true;
}

}  // namespace

int runRenderSequence(const RenderOptions& o) {
  const FrameRange range = parseFrameRange(o.frames);
  for (const std::string& pattern : {o.exr, o.png}) {
    if (pattern.empty()) continue;
    checkFramePattern(pattern, o.frames);
    base::checkWritable(framePath(pattern, range.first));
  }
  if (o.checkpointEvery > 0 && o.checkpointDir.empty()) throw UsageError("--checkpoint-every needs --checkpoint-dir");
  if (!o.checkpointDir.empty()) {
    // A folder not there yet is made with the first checkpoint.
    if (std::filesystem::exists(o.checkpointDir) && !std::filesystem::is_directory(o.checkpointDir)) {
      throw UsageError("--checkpoint-dir " + o.checkpointDir + ": not a folder");
    }
    base::checkWritable((std::filesystem::path(o.checkpointDir) / "water.000000.json").string());
  }
  const scene::Scene scene = loadScene(o.scene);
  RasterPlan plan = rasterPlan(o, scene);
  if (!o.checkpointDir.empty() && !scene.water.enabled) {
    throw UsageError("--checkpoint-dir: the scene has no water to checkpoint");
  }

  const std::vector<uint32_t> todo = framesToWrite(
      range, o.resume,
      [&](uint32_t f) { return alreadyWritten(framePath(o.exr, f), framePath(o.png, f), o.width, o.height); },
      "render");
  if (todo.empty()) return 0;

  GpuSession session(o.validate, o.device);
  render::Renderer renderer(session.context(), scene, o.width, o.height, plan.renderer);
  const uint64_t fingerprint = scene.water.enabled ? waterFingerprint(scene) : 0;
  if (!o.checkpointDir.empty()) {
    if (const auto checkpoint = latestCheckpoint(o.checkpointDir, todo.front(), fingerprint)) {
      renderer.resume(*checkpoint);
      std::printf("resumed the water from checkpoint frame %u\n", checkpoint->frame);
    }
  }
  InterruptGuard interrupts;
  SequenceProgress progress(uint32_t(todo.size()), range.count());
  uint32_t written = 0;  // by the writer; read once it is idle
  {
    // Frame f's files (and its checkpoint) are written while frame f+1
    // renders, in the order a single thread would write them.
    base::BackgroundWork writer;
    for (const uint32_t f : todo) {
      if (InterruptGuard::received()) break;
      plan.request.frame = f;
      if (scene::isAnimated(scene.camera)) renderer.setCamera(scene::cameraAtFrame(scene, f));
      auto frame = std::make_shared<const render::RenderedFrame>(
          renderSamples(renderer, plan.request, rasterSamples(o), o.transparentSky));
      std::optional<sim::WaterCheckpoint> checkpoint;
      if (o.checkpointEvery > 0 && f % o.checkpointEvery == 0) checkpoint = renderer.checkpoint();
      writer.start([&, frame, f, checkpoint = std::move(checkpoint)] {
        const std::string exr = framePath(o.exr, f), png = framePath(o.png, f);
        writeFrame(o, scene, *frame, f, exr, png);
        if (checkpoint) saveCheckpoint(o.checkpointDir, *checkpoint, fingerprint);
        ++written;
        progress.rendered(f, exr.empty() ? png : exr);
      });
    }
    writer.finish();
  }
  progress.finish();
  if (InterruptGuard::received()) {
    session.finish();
    return reportStop("render", written, todo.size(), "render");
  }
  std::printf("wrote frames %u-%u (%u rendered) at %ux%u on %s\n", range.first, range.last, written, o.width, o.height,
              session.context().deviceName().c_str());
  return session.finish();
}

}  // namespace tp::app
