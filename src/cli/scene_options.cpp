#include "cli/scene_options.hpp"

#include <stdexcept>

#include "scene/scene_file.hpp"

namespace tp::app {

void addSceneOptions(CLI::App* cmd, SceneChoice& choice) {
  cmd->add_option("--scene", choice.path, "Scene file (JSON, see docs/scene-files.md); default: the built-in scene")
      ->type_name("PATH")
      ->check(CLI::ExistingFile);
  auto* noAo = cmd->add_flag("--no-ao", choice.noAo, "Switch the scene's ambient occlusion off for this run");
  cmd->add_option("--preset", choice.preset,
                  "AO preset for this run, replacing the scene's ao settings: fast, balanced, quality, or "
                  "baseline (the LearnOpenGL-style SSAO they are measured against)")
      ->type_name("NAME")
      ->check(CLI::IsMember({"fast", "balanced", "quality", "baseline"}))
      ->excludes(noAo);
}

scene::Scene loadScene(const SceneChoice& choice) {
  scene::Scene scene = choice.path.empty() ? scene::defaultScene() : scene::loadSceneFile(choice.path);
  if (!choice.preset.empty()) scene.ao = scene::aoPreset(choice.preset);
  if (choice.noAo) scene.ao.enabled = false;
  return scene;
}

void checkFramePixels(uint32_t width, uint32_t height) {
  if (uint64_t(width) * height > kMaxFramePixels) {
    throw std::runtime_error(std::to_string(width) + "x" + std::to_string(height) + " is over the limit of " +
                             std::to_string(kMaxFramePixels) + " pixels");
  }
}

}  // namespace tp::app
