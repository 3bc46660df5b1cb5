#pragma once
#include <string>

#include "scene/scene.hpp"

namespace tp::scene {

// Reads a JSON scene file (format in docs/scene-files.md, examples in scenes/). Every
// field has the default scene's value when absent; unknown keys, wrong types
// and impossible values throw std::runtime_error naming the file and the key.
Scene loadSceneFile(const std::string& path);

// The same, from text; `origin` names the source in messages.
Scene parseScene(const std::string& text, const std::string& origin);

// The scene as a scene file that reads back to the same scene, every field
// spelled out (no AO preset: its settings). A sky image path is written as
// the scene holds it (loaded scenes hold it resolved).
std::string sceneToJson(const Scene& scene);
// The scene with one setting changed, named by its scene-file key with dots
// (`water.wave_speed`, `spheres.0.radius`, `ao.preset`); `value` is JSON (a
// bare word is read as a string). Throws std::runtime_error naming the key
// when the scene has no such key, or the scene it makes is impossible.
Scene withSetting(const Scene& scene, const std::string& key, const std::string& value);

// Writes sceneToJson to a .json path, whole or not at all (base::AtomicFile).
void saveSceneFile(const std::string& path, const Scene& scene);

}  // namespace tp::scene
