// libFuzzer target: the scene parser (scene::parseScene) on arbitrary bytes.
// It must either return a scene that validateScene accepts, which writes
// and reads back to itself, or throw std::runtime_error; anything else (a
// crash, another exception, a sanitizer report, a scene that does not read
// back) is a finding.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include "scene/scene_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  tp::scene::Scene scene;
  try {
    scene = tp::scene::parseScene(text, "fuzz.json");
  } catch (const std::runtime_error&) {
    return 0;
  }
  tp::scene::validateScene(scene);
  if (!(tp::scene::parseScene(tp::scene::sceneToJson(scene), "written.json") == scene)) std::abort();
  return 0;
}
