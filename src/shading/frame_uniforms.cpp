#include "shading/frame_uniforms.hpp"

#include <algorithm>

#include "shading/objects_model.hpp"
#include "shading/pool_model.hpp"
#include "shading/sky_model.hpp"

namespace tp::render {

bool spheresCastShadows(const scene::Scene& scene) {
  return scene.render.shadows && std::any_of(scene.spheres.begin(), scene.spheres.end(),
                                             [](const scene::Sphere& s) { return !scene::isGlass(s); });
}

bool boxesCastShadows(const scene::Scene& scene) {
  return scene.render.shadows &&
         std::any_of(scene.boxes.begin(), scene.boxes.end(), [](const scene::Box& b) { return !scene::isGlass(b); });
}

bool castsShadows(const scene::Scene& scene) {
  return spheresCastShadows(scene) || boxesCastShadows(scene) || (scene.render.shadows && hasPool(scene));
}

shader::ShadowCasters shadowCasters(const scene::Scene& scene, float time) {
  shader::ShadowCasters c{};
  c.sun.x = glm::radians(scene.sky.sunAngularRadiusDegrees);
  if (!castsShadows(scene)) return c;  // nothing casts: sunVisibility is 1
  uint32_t spheres = 0;
  for (const scene::Sphere& s : scene.spheres) {
    // Glass lets the light through (its caustic is not drawn).
    if (scene::isGlass(s) || spheres == TP_MAX_SPHERES) continue;
    c.spheres[spheres++] = glm::vec4(scene::sphereCenterAt(s, time), s.radius);
  }
  uint32_t boxes = 0;
  for (const scene::Box& b : scene.boxes) {
    if (scene::isGlass(b) || boxes == TP_MAX_BOXES) continue;
    const shader::BoxParams box = boxParams(b);
    c.boxCenter[boxes] = box.center;
    c.boxHalfSize[boxes++] = box.halfSize;
  }
  const bool pool = hasPool(scene);
  c.sun = glm::vec4(c.sun.x, float(spheres), float(boxes), pool ? 1.0f : 0.0f);
  if (pool) c.pool = glm::vec4(0.5f * scene.water.extent, scene.ground.height, scene.water.level, scene.water.ior);
  return c;
}

shader::FrameUniforms frameUniforms(const scene::Scene& scene, uint32_t width, uint32_t height) {
  return frameUniforms(scene, proceduralSkyLight(scene.sky), width, height);
}

shader::FrameUniforms frameUniforms(const scene::Scene& scene, const SkyLight& light, uint32_t width, uint32_t height,
                                    glm::vec2 pixelOffset, float filterWidth) {
  shader::FrameUniforms u{};
  u.view = scene.camera.view();
  // A pixel that samples `pixelOffset` from its centre sees what lies there:
  // the image moves by minus the offset, in clip space by its NDC times w.
  glm::mat4 shift(1.0f);
  shift[3][0] = -2.0f * pixelOffset.x / float(width);
  shift[3][1] = -2.0f * pixelOffset.y / float(height);
  u.projection = shift * scene.camera.projection(float(width) / float(height));
  u.viewProjection = u.projection * u.view;
  u.inverseViewProjection = glm::inverse(u.viewProjection);
  u.cameraPosition = glm::vec4(scene.camera.position, 1.0f);
  u.sunDirection = glm::vec4(light.sunDirection, 0.0f);
  u.sunIrradiance = glm::vec4(light.sunIrradiance, 0.0f);
  u.viewport = glm::vec4(float(width), float(height), 1.0f / float(width), 1.0f / float(height));
  u.inverseProjection = glm::inverse(u.projection);
  u.skySh = light.skySh;
  // y: the uniform index base, 0 (shared/sun_shadow.h).
  u.sampling = glm::vec4(filterWidth, 0.0f, 0.0f, 0.0f);
  return u;
}

}  // namespace tp::render
