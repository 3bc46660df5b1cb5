#include "cli/export_command.hpp"

#include <cstdio>
#include <optional>

#include "cli/gpu_session.hpp"
#include "io/mesh_io.hpp"
#include "scene/scene_file.hpp"
#include "shading/shaded_meshes.hpp"
#include "sim/water_scene.hpp"

namespace tp::app {
namespace {

// Writes one frame's meshes; returns its triangles.
size_t writeFrame(const scene::Scene& scene, const sim::WaterState* water, uint32_t frame, const std::string& path) {
  const auto meshes = render::shadedSceneMeshes(scene, water, float(frame) * scene.water.frameTime);
  io::writeMeshes(path, meshes);
  size_t triangles = 0;
  for (const auto& m : meshes) triangles += m.mesh.indices.size() / 3;
  return triangles;
}

}  // namespace

CLI::App* addExportCommand(CLI::App& app, ExportOptions& o) {
  CLI::App* cmd = app.add_subcommand("export", "Write the scene's triangles (water included) at a frame as OBJ or PLY");
  cmd->add_option("--scene", o.scenePath, "Scene file (JSON, see docs/scene-files.md); default: the built-in scene")
      ->type_name("PATH")
      ->check(CLI::ExistingFile);
  cmd->add_option("--frame", o.frame, "Frame number: the water after that many frames")->capture_default_str();
  cmd->add_option("--out", o.out, "Output .obj (with its .mtl beside it) or .ply")->type_name("PATH")->required();
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
  const size_t triangles = writeFrame(scene, water ? &*water : nullptr, o.frame, o.out);
  std::printf("wrote %s (%zu triangles, frame %u)\n", o.out.c_str(), triangles, o.frame);
  return exitCode;
}

}  // namespace tp::app
