#include "shading/frame_uniforms.hpp"

#include <algorithm>
#include <cmath>
#include <glm/gtc/constants.hpp>

#include "shading/glass_caustic.hpp"
#include "shading/objects_model.hpp"
#include "shading/pool_model.hpp"
#include "shading/sky_irradiance.hpp"
#include "shading/sky_model.hpp"
#include "shading/water_model.hpp"
#include "shared/surface_pattern.h"

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
  return spheresCastShadows(scene) || boxesCastShadows(scene) || glassCastsShadows(scene) ||
         (scene.render.shadows && hasPool(scene));
}

shader::ShadowCasters shadowCasters(const scene::Scene& scene, float time) {
  shader::ShadowCasters c{};
  c.sun.x = glm::radians(scene.sky.sunAngularRadiusDegrees);
  if (!castsShadows(scene)) return c;  // nothing casts: sunVisibility is 1
  uint32_t spheres = 0;
  for (const scene::Sphere& s : scene.spheres) {
    // Glass casts by its table (glassCasters).
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
  uint32_t glass = 0;
  for (const scene::Sphere* s : glassCasters(scene, time))
    c.glassSpheres[glass++] = glm::vec4(scene::sphereCenterAt(*s, time), s->radius);
  c.glass.x = float(glass);
  uint32_t grids = 0;
  for (const scene::Box* b : glassBoxCasters(scene)) {
    const GlassBoxGrid g = glassBoxGridPlacement(scene, *b);
    c.glassBoxGrids[2 * grids] = g.square;
    c.glassBoxGrids[2 * grids++ + 1] = g.heights;
  }
  c.glass.y = float(grids);
  const bool pool = hasPool(scene);
  c.sun = glm::vec4(c.sun.x, float(spheres), float(boxes), pool ? 1.0f : 0.0f);
  if (pool) c.pool = glm::vec4(0.5f * scene.water.extent, scene.ground.height, scene.water.level, scene.water.ior);
  return c;
}

namespace {

// The ground's mean albedo near the pool (its hole left out).
glm::vec3 groundMeanAlbedo(const scene::Scene& scene) {
  // Over a square about the pool, each point's pattern averaged over a
  // metre (the tiles' and pavers' mean tone).
  const shader::GroundParams ground = groundParams(scene);
  const float hole = hasPool(scene) ? 0.5f * scene.water.extent : 0.0f;
  constexpr int kSteps = 32;
  constexpr float kReach = 8.0f;  // metres from the pool's centre
  glm::vec3 sum(0.0f);
  int n = 0;
  for (int j = 0; j < kSteps; ++j) {
    for (int i = 0; i < kSteps; ++i) {
      const glm::vec2 xz = (glm::vec2(float(i), float(j)) + 0.5f) / float(kSteps) * (2.0f * kReach) - kReach;
      if (std::max(std::abs(xz.x), std::abs(xz.y)) < hole) continue;
      sum += shader::groundAlbedo(ground, xz, glm::vec2(1.0f));
      ++n;
    }
  }
  return sum / float(std::max(n, 1));
}

}  // namespace

SkyLight sceneLight(const scene::Scene& scene, const SkyRadiance& sky) {
  // Bins fine enough that the fit's error is the polynomial's, not theirs
  // (a 2-degree blob's light is placed by its bin's centroid).
  constexpr uint32_t kBands = 32, kAzimuths = 128, kSubsamples = 2;
  SkyLight light;
  if (scene.sky.image.empty()) {
    light.sunDirection = sunDirection(scene.sky);
    light.sunIrradiance = sunIrradiance(scene.sky);
  }
  const SkyBins bins(sky, kBands, kAzimuths, kSubsamples);
  const glm::vec3 groundIrradiance = light.sunIrradiance * std::max(light.sunDirection.y, 0.0f) + bins.irradianceUp();
  light.irradiance = fitSkyIrradiance(bins, groundMeanAlbedo(scene) * groundIrradiance / glm::pi<float>());
  return light;
}

shader::FrameUniforms frameUniforms(const scene::Scene& scene, uint32_t width, uint32_t height) {
  const shader::SkyParams sky = skyParams(scene.sky);
  return frameUniforms(scene, sceneLight(scene, [&](glm::vec3 d) { return shader::skyRadiance(sky, d, 0.0f); }), width,
                       height);
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
  u.skyIrradiance = light.irradiance;
  // y: the uniform index base, 0 (shared/sun_shadow.h).
  u.sampling = glm::vec4(filterWidth, 0.0f, 0.0f, 0.0f);
  return u;
}

}  // namespace tp::render
