#pragma once
// Where the objects' sun shadows can fall, from a frame's casters, so that a
// surface they cannot reach draws without their code (lavapipe runs code
// that no pixel needs: docs/frame-skipping.md).
#include <glm/glm.hpp>

#include "shared/shadow_casters.h"

namespace tp::render {

// Whether no sphere's and no box's shadow, penumbra included, nor a glass
// sphere's table (its shadow and caustic), can fall on
// the ground: the plane y = groundHeight outside the pool's square hole of
// half side `hole` (0: no pool, the whole plane). `toSun`: unit, towards the
// sun. Conservative: false when in doubt (a sun at the horizon).
bool groundOutOfObjectShadows(const shader::ShadowCasters& casters, glm::vec3 toSun, float groundHeight, float hole);

}  // namespace tp::render
