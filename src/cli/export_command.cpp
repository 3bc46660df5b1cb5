#include "cli/export_command.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <optional>

#include "base/atomic_file.hpp"
#include "cli/frame_sequence.hpp"
#include "cli/gpu_session.hpp"
#include "cli/heightfield_output.hpp"
#include "cli/interrupt_guard.hpp"
#include "cli/number_checks.hpp"
#include "cli/sequence_progress.hpp"
#include "cli/sequence_run.hpp"
#include "cli/usage_error.hpp"
#include "io/mesh_io.hpp"
#include "io/obj_writer.hpp"
#include "scene/scene_file.hpp"
#include "shading/shaded_meshes.hpp"
#include "sim/water_scene.hpp"

namespace tp::app {
namespace {

// Writes one frame: its meshes, or its water as a heightfield (.exr);
// returns what was written, for the summary.
std::string writeFrame(const scene::Scene& scene, const sim::WaterState* water, uint32_t frame,
                       const std::string& path) {
  if (isHeightfieldOutput(path)) {
    writeHeightfield(path, scene, *water, frame);
    return std::to_string(water->n) + "x" + std::to_string(water->n) + " heightfield";
  }
  const auto meshes = render::shadedSceneMeshes(scene, water, float(frame) * scene.water.frameTime);
  io::writeMeshes(path, meshes);
  size_t triangles = 0;
  for (const auto& m : meshes) triangles += m.mesh.indices.size() / 3;
  return std::to_string(triangles) + " triangles";
}

// Whether a frame's file is there whole: a heightfield readable at the
// grid's size; a mesh file there (each is renamed into place once written),
// an OBJ with its .mtl.
bool alreadyWritten(const std::string& path, const scene::Scene& scene) {
  if (isHeightfieldOutput(path)) return imageIsWhole(path, scene.water.grid, scene.water.grid);
  const bool obj = base::hasExtension(path, ".obj");
  return std::filesystem::is_regular_file(path) && (!obj || std::filesystem::is_regular_file(io::mtlPathFor(path)));
}

int exportSequence(const ExportOptions& o, const scene::Scene& scene, FrameRange range) {
  const std::vector<uint32_t> todo = framesToWrite(
      range, o.resume, [&](uint32_t f) { return alreadyWritten(framePath(o.out, f), scene); }, "export");
  if (todo.empty()) return 0;
  InterruptGuard interrupts;
  SequenceProgress progress(uint32_t(todo.size()), range.count());
  uint32_t written = 0;
  // Writes frame `frame` if it is still to write; returns whether to go on:
  // a signal ends the run after the frame being written, never inside one.
  const auto write = [&](uint32_t frame, const sim::WaterState* water) {
    if (InterruptGuard::received()) return false;
    if (std::binary_search(todo.begin(), todo.end(), frame)) {
      const std::string path = framePath(o.out, frame);
      writeFrame(scene, water, frame, path);
      ++written;
      progress.rendered(frame, path);
    }
    return InterruptGuard::received() == 0;
  };
  int exitCode = 0;
  if (scene.water.enabled) {
    // One run of the water to the last frame to write, each frame written as it is reached.
    GpuSession session(o.validate, o.device);
    sim::simulateWaterFrames(session.context(), scene, todo.front(), todo.back(),
                             [&](uint32_t frame, const sim::WaterState& water) { return write(frame, &water); });
    exitCode = session.finish();
  } else {
    for (const uint32_t frame : todo) {
      if (!write(frame, nullptr)) break;
    }
  }
  progress.finish();
  if (InterruptGuard::received()) return reportStop("export", written, todo.size(), "export");
  std::printf("wrote frames %u-%u to %s\n", range.first, range.last, o.out.c_str());
  return exitCode;
}

}  // namespace

CLI::App* addExportCommand(CLI::App& app, ExportOptions& o) {
  CLI::App* cmd = app.add_subcommand(
      "export",
      "Write the scene's triangles (water included) at a frame, or a range of frames, as OBJ, PLY or glTF; or the "
      "water's heightfield as EXR (an EXR sequence with --frames), to displace a grid with in a DCC");
  addSceneSourceOptions(cmd, o.scene, "Scene file (JSON, see docs/scene-files.md); default: the built-in scene");
  CLI::Option* frame = cmd->add_option("--frame", o.frame, "Frame number: the water after that many frames")
                           ->capture_default_str()
                           ->check(frameNumber());
  CLI::Option* frames =
      cmd->add_option("--frames", o.frames,
                      "A-B: a mesh sequence, frame N written to --out with its #### (or %04d or $F4) replaced by N")
          ->type_name("A-B")
          ->excludes(frame);
  addResumeOption(cmd, o.resume, frames);
  cmd->add_option("--out", o.out,
                  "Output .obj (with its .mtl beside it), .ply or .glb; or .exr: the water alone as a heightfield "
                  "(world height Y and normal N per cell) to displace a grid with")
      ->type_name("PATH")
      ->required();
  addGpuOptions(cmd, o.validate, o.device);
  return cmd;
}

int runExport(const ExportOptions& o) {
  std::optional<FrameRange> range;
  if (!o.frames.empty()) {
    range = parseFrameRange(o.frames);
    checkFramePattern(o.out, o.frames);
  }
  const bool heightfield = isHeightfieldOutput(o.out);
  if (!io::isMeshOutput(o.out) && !heightfield) {
    throw UsageError("--out " + o.out +
                     ": the format comes from the extension, which must be .obj, .ply, .glb or .exr (a heightfield)");
  }
  const std::string first = range ? framePath(o.out, range->first) : o.out;
  heightfield ? base::checkWritable(first) : io::checkMeshOutput(first);
  const scene::Scene scene = loadScene(o.scene, scene::defaultScene());
  if (heightfield && !scene.water.enabled) {
    throw UsageError("--out " + o.out + ": a heightfield is the water's, and this scene has water.enabled false");
  }
  if (range) return exportSequence(o, scene, *range);
  std::optional<sim::WaterState> water;
  int exitCode = 0;
  if (scene.water.enabled) {
    // The same simulation the renderer runs for this frame.
    GpuSession session(o.validate, o.device);
    water = sim::simulateWater(session.context(), scene, o.frame);
    exitCode = session.finish();
  }
  const std::string written = writeFrame(scene, water ? &*water : nullptr, o.frame, o.out);
  std::printf("wrote %s (%s, frame %u)\n", o.out.c_str(), written.c_str(), o.frame);
  return exitCode;
}

}  // namespace tp::app
