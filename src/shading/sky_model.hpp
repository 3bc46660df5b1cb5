#pragma once
#include <cstdint>
#include <glm/glm.hpp>
#include <string>

#include "scene/scene.hpp"
#include "shared/sh9.h"
#include "shared/sky.h"

namespace tp::render {

// The one place where the scene's sky description becomes shader parameters
// and the light the rest of the frame is lit by.
glm::vec3 sunDirection(const scene::Sky& sky);
// A scene file's noise name (scene::choices::kNoise) as shared/noise.h's TP_NOISE_*.
uint32_t noiseKind(const std::string& name);
shader::SkyParams skyParams(const scene::Sky& sky);
// Irradiance of the sun disk on a surface facing it: radiance times solid angle.
glm::vec3 sunIrradiance(const scene::Sky& sky);
// The SH9 coefficients of the sky without the sun disk above the horizon
// (the ground hides the rest), integrated numerically from the same
// skyRadiance the GPU evaluates: the sky's irradiance for any normal
// (shader::sh9Irradiance).
shader::Sh9 skySh9(const scene::Sky& sky);

// The light the frame's surfaces are lit by: a sun (direction and irradiance
// on a surface facing it) and the sky's radiance above the horizon in SH9.
struct SkyLight {
  glm::vec3 sunDirection{0.0f, 1.0f, 0.0f};
  glm::vec3 sunIrradiance{0.0f};
  shader::Sh9 skySh{};
};
SkyLight proceduralSkyLight(const scene::Sky& sky);

}  // namespace tp::render
