#include "cli/export_command.hpp"

#include <cstdio>
#include <optional>

#include "cli/gpu_session.hpp"
#include "io/mesh_io.hpp"
#include "scene/scene_file.hpp"
#include "shading/water_model.hpp"

namespace tp::app {

CLI::App* addExportCommand(CLI::App& app, ExportOptions& o) {
  CLI::App* cmd = app.add_subcommand("export", "Write the scene's triangles (water included) at a frame as OBJ or PLY");
  cmd->add_option("--scene", o.scenePath, "Scene file (JSON, see docs/scene-files.md); default: the built-in scene")
      ->type_name("PATH")
      ->check(CLI::ExistingFile);
  cmd->add_option("--frame", o.frame, "Frame number: the water after that many frames")->capture_default_str();
  cmd->add_option("--out", o.out, "Output .obj or .ply")->type_name("PATH")->required();
  addGpuOptions(cmd, o.validate, o.device);
  return cmd;
}

int runExport(const ExportOptions& o) {
  io::checkMeshOutput(o.out);
  const scene::Scene scene = o.scenePath.empty() ? scene::defaultScene() : scene::loadSceneFile(o.scenePath);
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
