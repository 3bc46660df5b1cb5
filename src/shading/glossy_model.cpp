#include "shading/glossy_model.hpp"

#include "shading/pool_model.hpp"

namespace tp::render {

bool hasGlossySurface(const scene::Scene& scene) {
  for (const scene::Sphere& sphere : scene.spheres) {
    if (sphere.specular > 0.0f) return true;
  }
  return hasPool(scene) && scene.pool.wallSpecular > 0.0f;
}

}  // namespace tp::render
