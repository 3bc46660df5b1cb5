#include "cli/export_command.hpp"

#include <cstdio>
#include <limits>
#include <optional>

#include "base/atomic_file.hpp"
#include "cli/frame_sequence.hpp"
#include "cli/gpu_session.hpp"
#include "cli/heightfield_output.hpp"
#include "cli/number_checks.hpp"
#include "cli/sequence_progress.hpp"
#include "cli/usage_error.hpp"
#include "io/mesh_io.hpp"
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

int exportSequence(const ExportOptions& o, const scene::Scene& scene, FrameRange range) {
  SequenceProgress progress(range.count(), range.count());
  const auto write = [&](uint32_t frame, const sim::WaterState* water) {
    const std::string path = framePath(o.out, frame);
    writeFrame(scene, water, frame, path);
    progress.rendered(frame, path);
  };
  int exitCode = 0;
  if (scene.water.enabled) {
    // One run of the water through the range, each frame written as it is reached.
    GpuSession session(o.validate, o.device);
    sim::simulateWaterFrames(session.context(), scene, range.first, range.last,
                             [&](uint32_t frame, const sim::WaterState& water) { write(frame, &water); });
    exitCode = session.finish();
  } else {
    for (uint32_t frame = range.first;; ++frame) {
      write(frame, nullptr);
      if (frame == range.last) break;
    }
  }
  progress.finish();
  std::printf("wrote frames %u-%u to %s\n", range.first, range.last, o.out.c_str());
  return exitCode;
}

}  // namespace

CLI::App* addExportCommand(CLI::App& app, ExportOptions& o) {
  CLI::App* cmd = app.add_subcommand(
      "export", "Write the scene's triangles (water included) at a frame, or a range of frames, as OBJ, PLY or glTF");
  addSceneSourceOptions(cmd, o.scene, "Scene file (JSON, see docs/scene-files.md); default: the built-in scene");
  CLI::Option* frame = cmd->add_option("--frame", o.frame, "Frame number: the water after that many frames")
                           ->capture_default_str()
                           ->check(inRange(0u, std::numeric_limits<uint32_t>::max()));
  cmd->add_option("--frames", o.frames, "A-B: a mesh sequence, frame N written to --out with its #### replaced by N")
      ->type_name("A-B")
      ->excludes(frame);
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
    if (!hasFrameField(o.out)) {
      throw UsageError("--out " + o.out +
                       ": with --frames the path needs #### where the frame number goes, e.g. meshes/pool.####.obj");
    }
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
