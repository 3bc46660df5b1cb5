#include "cli/scene_options.hpp"

#include "cli/usage_error.hpp"
#include "scene/scene_file.hpp"

namespace tp::app {

void addSceneSourceOptions(CLI::App* cmd, SceneSource& source, const std::string& sceneHelp) {
  cmd->add_option("--scene", source.path, sceneHelp)->type_name("PATH")->check(CLI::ExistingFile);
  cmd->add_option("--set", source.settings,
                  "Change one scene key for this run, as the scene file spells it with dots (camera.fov=40, "
                  "water.wave_speed=0.9, spheres.0.radius=0.3, sky.sun_radiance=[900,880,860]); repeatable, "
                  "applied in order after the scene file")
      ->type_name("KEY=VALUE");
}

scene::Scene withSettings(scene::Scene scene, const std::vector<std::string>& settings) {
  for (const std::string& setting : settings) {
    const size_t equals = setting.find('=');
    if (equals == std::string::npos || equals == 0) {
      throw UsageError("--set " + setting + ": expected KEY=VALUE, e.g. --set camera.fov=40");
    }
    try {
      scene = scene::withSetting(scene, setting.substr(0, equals), setting.substr(equals + 1));
    } catch (const std::runtime_error& e) {
      // The scene's own message names the key already ("setting KEY: ...").
      std::string why = e.what();
      const std::string origin = "setting " + setting.substr(0, equals) + ": ";
      if (why.rfind(origin, 0) == 0) why.erase(0, origin.size());
      throw UsageError("--set " + setting + ": " + why);
    }
  }
  return scene;
}

scene::Scene loadScene(const SceneSource& source, const scene::Scene& builtIn) {
  return withSettings(source.path.empty() ? builtIn : scene::loadSceneFile(source.path), source.settings);
}

void addSceneOptions(CLI::App* cmd, SceneChoice& choice) {
  addSceneSourceOptions(cmd, choice.source, "Scene file (JSON, see docs/scene-files.md); default: the built-in scene");
  auto* noAo = cmd->add_flag("--no-ao", choice.noAo, "Switch the scene's ambient occlusion off for this run");
  cmd->add_option("--preset", choice.preset,
                  "AO preset for this run, replacing the scene's ao settings: fast, balanced, quality, or "
                  "baseline (the LearnOpenGL-style SSAO they are measured against)")
      ->type_name("NAME")
      ->check(CLI::IsMember({"fast", "balanced", "quality", "baseline"}))
      ->excludes(noAo);
}

scene::Scene loadScene(const SceneChoice& choice) {
  scene::Scene scene = loadScene(SceneSource{choice.source.path, {}}, scene::defaultScene());
  if (!choice.preset.empty()) scene.ao = scene::aoPreset(choice.preset);
  if (choice.noAo) scene.ao.enabled = false;
  return withSettings(std::move(scene), choice.source.settings);
}

void checkFramePixels(uint32_t width, uint32_t height) {
  if (uint64_t(width) * height > kMaxFramePixels) {
    throw UsageError(std::to_string(width) + "x" + std::to_string(height) + " is over the limit of " +
                     std::to_string(kMaxFramePixels) + " pixels");
  }
}

}  // namespace tp::app
