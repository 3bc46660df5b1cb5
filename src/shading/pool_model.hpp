#pragma once
#include "scene/scene.hpp"
#include "shared/pool.h"

namespace tp::render {

// Ray-march steps and bisections of the refracted rays against the floor.
inline constexpr uint32_t kPoolMarchSteps = 48;
inline constexpr uint32_t kPoolBisections = 10;
// Vertices per side of the floor's grid mesh.
inline constexpr uint32_t kPoolFloorGrid = 129;

// The pool exists when the scene has water: it holds it.
inline bool hasPool(const scene::Scene& scene) { return scene.water.enabled; }

// The one place where the scene's pool and terrain become shader parameters.
shader::PoolParams poolParams(const scene::Scene& scene);

}  // namespace tp::render
