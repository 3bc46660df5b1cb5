#pragma once
#include <CLI/CLI.hpp>
#include <cstdint>
#include <string>
#include <vector>

#include "scene/scene.hpp"

namespace tp::app {

// A scene file and the keys the command line changes in it, as every
// command that takes --scene takes them.
struct SceneSource {
  std::string path;                   // empty: the command's built-in scene
  std::vector<std::string> settings;  // KEY=VALUE, applied in order after everything else
};

// Adds --scene (described by `sceneHelp`) and --set.
void addSceneSourceOptions(CLI::App* command, SceneSource& source, const std::string& sceneHelp);

// The scene of `source`: its file or `builtIn`, with its settings applied.
// Throws on a broken scene file, and UsageError on a bad --set.
scene::Scene loadScene(const SceneSource& source, const scene::Scene& builtIn);

// `scene` with each KEY=VALUE of --set applied in order (scene::withSetting).
// Throws UsageError naming the setting.
scene::Scene withSettings(scene::Scene scene, const std::vector<std::string>& settings);

// The scene a command shows, as `render` and `view` take it.
struct SceneChoice {
  SceneSource source;  // --scene and --set
  bool noAo = false;   // switch the scene's ambient occlusion off
  std::string preset;  // AO preset replacing the scene's ao settings; empty: the scene's own
};

// Adds --scene, --set, --no-ao and --preset.
void addSceneOptions(CLI::App* command, SceneChoice& choice);

// The chosen scene, its AO settings replaced as asked, then --set applied
// (so a --set of an ao key wins over --preset). Throws on a broken scene
// file, and UsageError on a bad --set.
scene::Scene loadScene(const SceneChoice& choice);

// The largest frame `render` and `view` make: each side, and in all.
constexpr uint32_t kMaxFrameSide = 16384;
constexpr uint64_t kMaxFramePixels = uint64_t(8192) * 8192;

// Throws UsageError, naming the size and the limit, when width x height is
// over kMaxFramePixels.
void checkFramePixels(uint32_t width, uint32_t height);

}  // namespace tp::app
