#pragma once
#include <vector>

#include "scene/scene.hpp"
#include "shared/pool.h"

namespace tp::render {

// Vertices per side of the floor's grid mesh: drawn, intersected by the
// water's refracted rays (shared/pool_trace.h) and by the reference tracer.
inline constexpr uint32_t kPoolFloorGrid = 129;
// Texels per side of the raster's caustics texture over the pool.
inline constexpr uint32_t kCausticsSize = 512;

// The pool exists when the scene has water: it holds it.
inline bool hasPool(const scene::Scene& scene) { return scene.water.enabled; }

// Whether the pool's walls are brick, and whether a plane of the scene (the
// ground, the pool's floor or walls) is tiled or paved: otherwise the
// shaders are specialized without that pattern's code
// (shared/specialization.h).
bool hasBrickWalls(const scene::Scene& scene);
bool hasTiledSurface(const scene::Scene& scene);

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

// How far from the pool's centre, in x and in z, a caustics map of `texels`
// a side holds light lines read whole: the water's light reaches the walls
// (the caustics' mesh does: waterSurfaceToTheWalls), so to the outermost
// texels' centres, where a bilinear read stops. The lines beyond are read
// as the nearest within.
float causticsReach(const scene::Scene& scene, uint32_t texels);

// Where floor vertex (i, j) lies in xz.
glm::vec2 poolFloorVertexXz(const shader::PoolParams& pool, uint32_t i, uint32_t j);

}  // namespace tp::render
