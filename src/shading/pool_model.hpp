#pragma once
#include <vector>

#include "scene/scene.hpp"
#include "shared/pool.h"

namespace tp::render {

// Vertices per side of the floor's grid mesh: drawn, intersected by the
// water's refracted rays (shared/pool_trace.h) and by the reference tracer.
inline constexpr uint32_t kPoolFloorGrid = 129;

// The pool exists when the scene has water: it holds it.
inline bool hasPool(const scene::Scene& scene) { return scene.water.enabled; }

// The one place where the scene's pool and terrain become shader parameters.
shader::PoolParams poolParams(const scene::Scene& scene);

// The floor mesh's vertices, row by row (kPoolFloorGrid per side, from the
// pool's -x, -z corner): xyz the terrain's normal there (poolFloorNormal),
// w its height. Drawn, cast against and ray traced alike.
std::vector<glm::vec4> poolFloorVertices(const shader::PoolParams& pool);

}  // namespace tp::render
