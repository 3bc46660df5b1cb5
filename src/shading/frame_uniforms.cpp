#include "shading/frame_uniforms.hpp"

#include "shading/sky_model.hpp"

namespace tp::render {

shader::FrameUniforms frameUniforms(const scene::Scene& scene, uint32_t width, uint32_t height) {
  return frameUniforms(scene, proceduralSkyLight(scene.sky), width, height);
}

shader::FrameUniforms frameUniforms(const scene::Scene& scene, const SkyLight& light, uint32_t width, uint32_t height) {
  shader::FrameUniforms u{};
  u.view = scene.camera.view();
  u.projection = scene.camera.projection(float(width) / float(height));
  u.viewProjection = u.projection * u.view;
  u.inverseViewProjection = glm::inverse(u.viewProjection);
  u.cameraPosition = glm::vec4(scene.camera.position, 1.0f);
  u.sunDirection = glm::vec4(light.sunDirection, 0.0f);
  u.sunIrradiance = glm::vec4(light.sunIrradiance, 0.0f);
  u.viewport = glm::vec4(float(width), float(height), 1.0f / float(width), 1.0f / float(height));
  u.inverseProjection = glm::inverse(u.projection);
  u.skySh = light.skySh;
  return u;
}

}  // namespace tp::render
