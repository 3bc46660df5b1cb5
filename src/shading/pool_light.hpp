#pragma once
#include <glm/glm.hpp>
#include <vector>

#include "shading/sky_irradiance.hpp"
#include "shared/objects.h"
#include "shared/pool.h"

namespace tp::render {

// The sun as the bake takes it: where it is and its irradiance on a surface
// facing it (none for an image sky).
struct PoolLightSun {
  glm::vec3 direction{0.0f, 1.0f, 0.0f};
  glm::vec3 irradiance{0.0f};
};

// What the pool's bake gives the shaders.
struct PoolLight {
  // The floor's vertices followed by the baked light: the buffer the
  // shaders read both from (shared/pool_light.h). The light: for each of
  // TP_POOL_LIGHT_TEXELS texels, the irradiance from everything but the
  // sun straight through the surface, by paths through the pool as it
  // stands (flat water at its rest level, the walls, the floor's mesh, the
  // opaque boxes, no spheres): the first direction from a fixed
  // cosine-weighted set, the surface's Fresnel split followed both ways, the
  // sun drawn at every later bounce. A box under the water is a surface the
  // paths bounce off; one in the air takes the sun and the open sky on its
  // face, and hides the sky and the sun from what it stands over.
  // The walls above the water (the dry band's texels) take the sky over the
  // rim and the sky and the sun the flat water mirrors, summed over the
  // sky's bins, and by a fixed set of cosine-weighted directions the pool's
  // light through the surface and the other walls' (the sun's, and the dry
  // band's of a first pass); a box hides the sky and the sun from them and
  // brings its own light where their lines meet it. Then the light
  // around at each of TP_POOL_AROUND_POINTS points in the water, 9 SH9
  // coefficients each: the radiance reaching the point from every
  // direction, each direction's ray meeting the sky through the surface (or
  // a box above it), or the floor or a wall, whose light is the baked one
  // and the sun's through the flat surface where it reaches, absorbed on the
  // way; reflected off the surface's underside once on. Its rays pass
  // through the boxes under the water.
  // Deterministic: the raster and the model tracer bake the same numbers.
  std::vector<glm::vec4> floorAndLight;
};

// The texels and the light around, for the pool's parameters and floor
// mesh (PoolModel's floorVertices), among the scene's opaque boxes
// (opaqueBoxes).
PoolLight bakePoolLight(const shader::PoolParams& pool, std::vector<glm::vec4> floorVertices, const SkyRadiance& sky,
                        const PoolLightSun& sun, const std::vector<shader::BoxParams>& boxes);

}  // namespace tp::render
