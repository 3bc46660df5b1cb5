#pragma once
#include <CLI/CLI.hpp>
#include <cstdint>
#include <string>

#include "scene/scene.hpp"

namespace tp::app {

// The scene a command shows, as `render` and `view` take it.
struct SceneChoice {
  std::string path;    // empty: the built-in default scene
  bool noAo = false;   // switch the scene's ambient occlusion off
  std::string preset;  // AO preset replacing the scene's ao settings; empty: the scene's own
};

// Adds --scene, --no-ao and --preset.
void addSceneOptions(CLI::App* command, SceneChoice& choice);

// The chosen scene, its AO settings replaced as asked. Throws on a broken scene file.
scene::Scene loadScene(const SceneChoice& choice);

// The largest frame `render` and `view` make: each side, and in all.
constexpr uint32_t kMaxFrameSide = 16384;
constexpr uint64_t kMaxFramePixels = uint64_t(8192) * 8192;

// Throws, naming the size and the limit, when width x height is over kMaxFramePixels.
void checkFramePixels(uint32_t width, uint32_t height);

}  // namespace tp::app
