#pragma once
#include "scene/scene.hpp"

namespace tp::render {

// Whether anything the frame draws has a glossy lobe (specular > 0): a sphere,
// or the pool's walls where there is a pool. Without one, the frame has no
// glossy prefilter pass.
bool hasGlossySurface(const scene::Scene& scene);

}  // namespace tp::render
