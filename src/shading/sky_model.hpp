#pragma once
#include <cstdint>
#include <glm/glm.hpp>
#include <string>

#include "scene/scene.hpp"
#include "shared/sky.h"
#include "shared/sky_irradiance.h"

namespace tp::render {

// The one place where the scene's sky description becomes shader parameters
// and the light the rest of the frame is lit by.
glm::vec3 sunDirection(const scene::Sky& sky);
// A scene file's noise name (scene::choices::kNoise) as shared/noise.h's TP_NOISE_*.
uint32_t noiseKind(const std::string& name);
shader::SkyParams skyParams(const scene::Sky& sky);
// Irradiance of the sun disk on a surface facing it: radiance times solid angle.
glm::vec3 sunIrradiance(const scene::Sky& sky);

// The light the frame's surfaces are lit by: a sun (direction and irradiance
// on a surface facing it) and the irradiance of the light round a point in
// the open, the sky's above the horizon and the ground's below it
// (shading/frame_uniforms.hpp's sceneLight makes it).
struct SkyLight {
  glm::vec3 sunDirection{0.0f, 1.0f, 0.0f};
  glm::vec3 sunIrradiance{0.0f};
  shader::SkyIrradiance irradiance{};
};

}  // namespace tp::render
