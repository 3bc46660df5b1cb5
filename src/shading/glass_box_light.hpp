#pragma once
// The sun under and behind a glass box: its shadow and the light it lets
// through, bends and reflects inside, as a grid of the irradiance on
// horizontal planes relative to the open sun's (shared/shadow_casters.h's
// layout). The surfaces' shaders read it in their sun term
// (shared/sun_shadow.h's glassBoxesSunShare), and so does the raster's model
// traced (--reference-model); the truth traces the glass itself.
//
// Light rays from a lattice over the sun's beam, each from a point of the
// sun's disc, are followed through the water's flat surface and the box:
// Fresnel's share at every face (the reflections inside and off the outside
// followed), total internal reflection, the water beyond a face
// under the level. Each layer counts the light crossing it, in coordinates
// sheared along the sun's ray (sunSheared), against the same rays traced
// with no box: the water's own Fresnel loss and the lattice cancel. The
// pool's walls and the water's absorption are left to the sun term's own.
#include <vector>

#include "scene/scene.hpp"
#include "shared/shadow_casters.h"

namespace tp::render {

struct GlassBoxGrid {
  glm::vec4 square{0.0f};     // the sheared coordinates' square: a0, b0, a1, b1
  glm::vec4 heights{0.0f};    // the lowest and highest layers' heights, the height the shear is taken to
  std::vector<float> values;  // TP_GLASS_BOX_SIZE, layer by layer (empty: only placed)
};

// The glass boxes that cast the sun's light: with render.shadows on and the
// sun over the horizon, the first TP_MAX_BOXES glass boxes, in the order
// their grids go.
std::vector<const scene::Box*> glassBoxCasters(const scene::Scene& scene);

// Where `box`'s grid lies (cheap): what the frame's uniforms carry.
GlassBoxGrid glassBoxGridPlacement(const scene::Scene& scene, const scene::Box& box);

// The grid traced.
GlassBoxGrid glassBoxLightGrid(const scene::Scene& scene, const scene::Box& box);

}  // namespace tp::render
