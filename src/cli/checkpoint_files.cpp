#include "cli/checkpoint_files.hpp"
#include "io/water_state_file.hpp"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "base/atomic_file.hpp"
#include "base/text_file.hpp"
#include "scene/scene_file.hpp"

namespace tp::app {
namespace {

using nlohmann::json;

constexpr uint64_t kFnvOffset = 14695981039346656037ull;
constexpr uint64_t kFnvPrime = 1099511628211ull;

std::string stem(const std::string& dir, uint32_t frame) {
  char name[32];
  std::snprintf(name, sizeof name, "water.%06u", frame);
  return (std::filesystem::path(dir) / name).string();
}

}  // namespace

uint64_t waterFingerprint(const scene::Scene& scene) {
  scene::Scene water;
  water.water = scene.water;
  water.spheres = scene.spheres;
  uint64_t hash = kFnvOffset;
  for (const unsigned char c : scene::sceneToJson(water)) hash = (hash ^ c) * kFnvPrime;
  return hash;
}

void saveCheckpoint(const std::string& dir, const sim::WaterCheckpoint& checkpoint, uint64_t fingerprint) {
  const std::string base = stem(dir, checkpoint.frame);
  io::writeStateExr(base + ".exr", checkpoint.state);
  const json meta{{"frame", checkpoint.frame},
                  {"quiet_frames", checkpoint.quietFrames},
                  {"asleep", checkpoint.asleep},
                  {"water_fingerprint", fingerprint}};
  base::AtomicFile file(base + ".json");
  {
    std::ofstream out(file.tempPath(), std::ios::binary);
    out << meta.dump(2) << "\n";
    out.close();
    if (!out) throw std::runtime_error("cannot write checkpoint " + base + ".json");
  }
  file.commit();
}

std::optional<sim::WaterCheckpoint> latestCheckpoint(const std::string& dir, uint32_t atMost, uint64_t fingerprint) {
  if (!std::filesystem::exists(dir)) return std::nullopt;  // made with the first checkpoint
  std::optional<uint32_t> best;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(dir, ec)) {
    const std::string name = entry.path().filename().string();
    unsigned frame = 0;
    char tail[8] = {};
    // water.NNNNNN.json exactly (a temporary file's name has more after it).
    if (std::sscanf(name.c_str(), "water.%6u.%5s", &frame, tail) != 2 || std::string(tail) != "json" ||
        name.size() != std::string("water.000000.json").size()) {
      continue;
    }
    if (frame <= atMost && (!best || frame > *best)) best = frame;
  }
  if (ec) throw std::runtime_error("cannot read checkpoint folder " + dir + ": " + ec.message());
  if (!best) return std::nullopt;
  const std::string base = stem(dir, *best);
  const auto text = base::readTextFile(base + ".json");
  if (!text) throw std::runtime_error("cannot read checkpoint " + base + ".json");
  json meta;
  try {
    meta = json::parse(*text);
    sim::WaterCheckpoint checkpoint;
    checkpoint.frame = meta.at("frame").get<uint32_t>();
    checkpoint.quietFrames = meta.at("quiet_frames").get<uint32_t>();
    checkpoint.asleep = meta.at("asleep").get<bool>();
    if (meta.at("water_fingerprint").get<uint64_t>() != fingerprint) {
      throw std::runtime_error("checkpoint " + base +
                               ".json was made for another scene's water (its water or spheres "
                               "differ): use another --checkpoint-dir");
    }
    if (checkpoint.frame != *best) throw std::runtime_error("checkpoint " + base + ".json names another frame");
    checkpoint.state = io::readStateExr(base + ".exr");
    return checkpoint;
  } catch (const json::exception& e) {
    throw std::runtime_error("checkpoint " + base + ".json is not a checkpoint (" + e.what() + ")");
  }
}

}  // namespace tp::app
