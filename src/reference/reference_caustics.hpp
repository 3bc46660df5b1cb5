#pragma once
// The reference's caustics: the sun's irradiance under the water through the
// simulated surface, relative to flat water, by light tracing. Photons
// leave the sun on a regular lattice, meet the water's triangle mesh (the
// surface reaching the walls, shading/water_model's waterSurfaceToTheWalls,
// with its interpolated vertex normals), are refracted by
// Snell's law and go on to what they meet first under the water: the
// floor's mesh, a wall, a box or a sphere. They are counted there per texel
// of a grid over the pool, indexed as the raster's caustics texture is, by
// the light line of where they land (shared/shading.h's causticsLine: where
// the flat water's refracted sun line through the point crosses the rest
// level). Independent of the raster's map (the areas of the water grid's
// triangles, landed on the pool's box), whose error it measures.
//
// The same quantity as the raster's, so that the two compare: the focusing
// alone. The photons are not stopped above the water (the shadows there are
// the sun shadows', which multiply it) and are not absorbed (the sun light
// under the water is not, in either renderer). Under flat water every
// photon lands on its own light line: each texel receives exactly its share.
#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

#include "scene/mesh.hpp"
#include "scene/scene.hpp"

namespace tp::render {

struct CausticsMap {
  uint32_t size = 0;         // texels per side
  float halfExtent = 0.0f;   // the grid covers [-halfExtent, halfExtent]^2 in xz
  float reach = 0.0f;        // the lines read whole (shading/pool_model's causticsReach)
  std::vector<float> ratio;  // size * size, row z, column x

  // The ratio at light line xz (causticsLine), bilinear between texel
  // centres, as the raster's sampler reads its map; the lines past `reach`
  // read as the nearest within, as the raster's causticsUv reads them.
  float at(glm::vec2 xz) const;
};

// Photons per texel side by default: 8 x 8 photons a texel.
constexpr uint32_t kCausticPhotonsPerTexelSide = 8;

// What the photons land on under the water: the pool's floor and walls, the
// boxes (meshes of sceneMeshes), the opaque spheres.
struct CausticReceivers {
  std::vector<scene::Mesh> meshes;
  std::vector<scene::Sphere> spheres;
};

// The caustics of the scene's pool under `water` (its mesh reaching the
// walls and one normal per vertex: waterSurfaceToTheWalls), on a grid of
// `size` texels a side over the light lines, each sent
// photonsPerTexelSide^2 photons.
CausticsMap traceCaustics(const scene::Scene& scene, const scene::Mesh& water,
                          const std::vector<glm::vec3>& waterNormals, const CausticReceivers& receivers, uint32_t size,
                          uint32_t photonsPerTexelSide = kCausticPhotonsPerTexelSide);

// The sun's reflection by the water's surface in the air, relative to flat
// water, by light tracing: the same photons, reflected by the mesh's
// interpolated normals, go on to what they meet first above it (`receivers`:
// the walls above the water, the boxes, the opaque spheres). Each counts at
// its landing point's mirror point (mirrorPoint: where the line from it
// towards the sun's image in the flat water meets the rest level), weighted
// by its Fresnel reflectance over the flat water's at the sun's angle. A
// point in the air lit by the sun's image through mirror point q takes the
// flat water's light times the ratio at q. Under flat water every photon
// counts at its own lattice point at weight 1. `reach` is the pool's half.
CausticsMap traceReflectedCaustics(const scene::Scene& scene, const scene::Mesh& water,
                                   const std::vector<glm::vec3>& waterNormals, const CausticReceivers& receivers,
                                   uint32_t size, uint32_t photonsPerTexelSide = kCausticPhotonsPerTexelSide);

// Where the line from p towards the sun's image in flat water at `level`
// (direction toSun mirrored, going down) meets that level, in xz.
glm::vec2 mirrorPoint(glm::vec3 p, glm::vec3 toSun, float level);

}  // namespace tp::render
