#include "shading/frame_uniforms.hpp"

#include "shading/sky_model.hpp"

namespace tp::render {

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
  u.sampling = glm::vec4(filterWidth, 0.0f, 0.0f, 0.0f);
  return u;
}

}  // namespace tp::render
