#pragma once
// How finely a grid mesh over the pool (the water's, the floor's) needs to
// be drawn in a frame: on lavapipe a triangle costs whether it covers a pixel
// or not, and in a small frame the water's cells are fractions of a pixel.
#include <cstdint>

#include <glm/glm.hpp>

namespace tp::render {

// The coarsest step the mesh may be drawn at (shading/water_model.hpp's
// waterGridStrips): 1, 2 or 4.
inline constexpr uint32_t kMaxGridStep = 4;
// A drawn quad spans at most this many pixels along the square's longest
// projected edge, where the square is seen largest.
inline constexpr float kMaxQuadPixels = 2.0f;

// The step for a grid of `vertices` a side over the level square of side
// `extent` centred at `centre`, seen through `viewProjection` in a frame of
// `pixels`: the largest power of two up to kMaxGridStep whose quads span at
// most kMaxQuadPixels along each projected edge of the square. 1 when a
// corner is behind the camera (the square may then fill the frame).
uint32_t gridStep(const glm::mat4& viewProjection, glm::vec2 pixels, glm::vec3 centre, float extent, uint32_t vertices);

}  // namespace tp::render
