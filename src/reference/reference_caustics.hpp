#pragma once
// The reference's caustics: the sun's irradiance on the pool's floor through
// the simulated surface, relative to flat water, by light tracing. Photons
// leave the sun on a regular lattice, meet the water's triangle mesh (the
// reference's own, with its interpolated vertex normals), are refracted by
// Snell's law and land on the floor's mesh, where they are counted per texel
// of a grid over the pool. Independent of the raster's caustics map (the
// areas of the water grid's triangles projected to the mean floor's plane),
// whose error it measures.
//
// The same quantity as the raster's, so that the two compare: the focusing
// alone. The photons pass the walls and the objects (their shadows are the
// sun shadows', which multiply it), and are not absorbed (the floor's sun
// light is not, in either renderer). Under flat water each texel of the lit
// floor receives exactly its share: the lattice, shifted by the flat
// refraction, puts the same count in every texel.
#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

#include "scene/mesh.hpp"
#include "scene/scene.hpp"

namespace tp::render {

struct CausticsMap {
  uint32_t size = 0;         // texels per side
  float halfExtent = 0.0f;   // the grid covers [-halfExtent, halfExtent]^2 in xz
  std::vector<float> ratio;  // size * size, row z, column x

  // The ratio at world xz, bilinear between texel centres (clamped at the edges),
  // as the raster's sampler reads its map.
  float at(glm::vec2 xz) const;
};

// Photons per texel side by default: 4 x 4 photons a texel.
constexpr uint32_t kCausticPhotonsPerTexelSide = 8;

// The caustics of the scene's pool under `water` (the water and floor meshes
// of sceneMeshes), on a grid of `size` texels a side, each sent
// photonsPerTexelSide^2 photons.
CausticsMap traceCaustics(const scene::Scene& scene, const scene::Mesh& water,
                          const std::vector<glm::vec3>& waterNormals, const scene::Mesh& floor, uint32_t size,
                          uint32_t photonsPerTexelSide = kCausticPhotonsPerTexelSide);

}  // namespace tp::render
