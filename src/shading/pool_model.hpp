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

// The pool as the shaders and the reference take it: its parameters, and its
// floor mesh's vertices row by row (kPoolFloorGrid per side, from the pool's
// -x, -z corner), xyz the terrain's normal there (poolFloorNormal), w its
// height; drawn, cast against and ray traced alike. Made together: the
// parameters hold the vertices' range of heights.
struct PoolModel {
  shader::PoolParams params;
  std::vector<glm::vec4> floorVertices;
};

// The one place where the scene's pool and terrain become shader parameters.
PoolModel poolModel(const scene::Scene& scene);
// Its parameters alone.
shader::PoolParams poolParams(const scene::Scene& scene);

// Where floor vertex (i, j) lies in xz.
glm::vec2 poolFloorVertexXz(const shader::PoolParams& pool, uint32_t i, uint32_t j);

}  // namespace tp::render
