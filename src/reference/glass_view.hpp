#pragma once
// What the glass test and `tidepool bench glass` measure: one view of a glass
// sphere, and the pixels that show it.
#include <cstdint>
#include <vector>

#include "render/renderer.hpp"
#include "scene/scene.hpp"

namespace tp::render {

// A glass sphere (ior 1.5) floating over the ground under the default sky,
// no water and no AO, seen from slightly above: the sky and its lower half
// refracted through it, and the sun reflected on it.
scene::Scene glassSphereView();

// The same view with a glass box (ior 1.5, 1 x 0.6 x 0.8 m, turned 30
// degrees) in the sphere's place: the ground's checker through it, moved
// along and down by its slab, and its sides' reflections inside.
scene::Scene glassBoxView();

// One byte per pixel, 1 where the frame's first surface (its position AOV,
// such as the reference's) lies on one of `placed`'s glass spheres or boxes
// (the scene with its spheres where the frame shows them).
std::vector<uint8_t> glassPixelMask(const RenderedFrame& aovs, const scene::Scene& placed);

}  // namespace tp::render
