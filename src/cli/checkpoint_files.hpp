#pragma once
#include <cstdint>
#include <optional>
#include <string>

#include "render/renderer.hpp"
#include "scene/scene.hpp"

namespace tp::app {

// The checkpoints of a shot in a folder (render --checkpoint-dir): for frame
// N, water.NNNNNN.exr (the water's state in `tidepool sim`'s EXR format:
// channels u and v) and water.NNNNNN.json (the frame, the sleep rule's
// count, and the fingerprint of what the water depends on), the JSON written
// last, each through a temporary file: a checkpoint is there when its JSON
// is, and then whole.

// What the water depends on: the scene's water and spheres (a camera, sky or
// AO change keeps the checkpoints good), as a 64-bit FNV-1a of their scene-file text.
uint64_t waterFingerprint(const scene::Scene& scene);

void saveCheckpoint(const std::string& dir, const sim::WaterCheckpoint& checkpoint, uint64_t fingerprint);

// The checkpoint of the latest frame <= `atMost` in `dir`, if any. Throws one
// line when it was made for another scene (another fingerprint), or is
// unreadable.
std::optional<sim::WaterCheckpoint> latestCheckpoint(const std::string& dir, uint32_t atMost, uint64_t fingerprint);

}  // namespace tp::app
