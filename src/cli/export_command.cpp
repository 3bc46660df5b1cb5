#include "cli/export_command.hpp"

#include <cstdio>
#include <limits>
#include <optional>

#include "base/atomic_file.hpp"
#include "cli/gpu_session.hpp"
#include "cli/number_checks.hpp"
#include "cli/usage_error.hpp"
#include "io/mesh_io.hpp"
#include "scene/scene_file.hpp"
#include "shading/water_model.hpp"

namespace tp::app {

CLI::App* addExportCommand(CLI::App& app, ExportOptions& o) {
  CLI::App* cmd = app.add_subcommand("export", "Write the scene's triangles (water included) at a frame as OBJ or PLY");
  addSceneSourceOptions(cmd, o.scene, "Scene file (JSON, see docs/scene-files.md); default: the built-in scene");
  cmd->add_option("--frame", o.frame, "Frame number: the water after that many frames")
      ->capture_default_str()
      ->check(inRange(0u, std::numeric_limits<uint32_t>::max()));
  cmd->add_option("--out", o.out, "Output .obj or .ply")->type_name("PATH")->required();
  addGpuOptions(cmd, o.validate, o.device);
  return cmd;
}

int runExport(const ExportOptions& o) {
  if (!base::hasExtension(o.out, ".obj") && !base::hasExtension(o.out, ".ply")) {
    throw UsageError("--out " + o.out + ": the format comes from the extension, which must be .obj or .ply");
  }
  io::checkMeshOutput(o.out);
  const scene::Scene scene = loadScene(o.scene, scene::defaultScene());
  std::optional<sim::WaterState> water;
  int exitCode = 0;
  if (scene.water.enabled) {
    // The same simulation the renderer runs for this frame.
    GpuSession session(o.validate, o.device);
    water = sim::simulateWater(session.context(), scene, o.frame);
    exitCode = session.finish();
  }
  const auto meshes = render::sceneMeshes(scene, water ? &*water : nullptr, float(o.frame) * scene.water.frameTime);
  io::writeMeshes(o.out, meshes);
  size_t triangles = 0;
  for (const auto& m : meshes) triangles += m.indices.size() / 3;
  std::printf("wrote %s (%zu meshes, %zu triangles, frame %u)\n", o.out.c_str(), meshes.size(), triangles, o.frame);
  return exitCode;
}

}  // namespace tp::app
