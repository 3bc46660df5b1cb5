#pragma once
#include <cstdint>
#include <glm/glm.hpp>

#include "render/env_sampler.hpp"
#include "render/sky_image.hpp"
#include "shared/sh9.h"

namespace tp::render {

// The SH9 coefficients of an equirectangular image taken as piecewise
// constant, integrated exactly texel by texel (closed forms in theta and
// phi), over the directions with theta <= maxTheta (pi: the whole sphere;
// pi / 2: the sky above the horizon, which the ground does not hide).
shader::Sh9 projectSh9(const SkyImage& image, float maxTheta);

// How the Monte Carlo estimators draw their directions.
enum class EnvSampling { Importance, Uniform };

// The n points of the Hammersley set shifted by `rotation` modulo 1
// (Cranley-Patterson): fixed rotations give independent deterministic sets.
glm::vec2 rotatedHammersley(uint32_t k, uint32_t n, glm::vec2 rotation);

// One direction and its solid-angle density: from the sampler, or uniform
// over the sphere (density 1 / 4pi).
EnvSample drawDirection(const EnvSampler& sampler, EnvSampling kind, glm::vec2 xi);

// Monte Carlo estimates over the whole sphere from n rotated Hammersley
// points, of the image's (nearest-texel) radiance: its SH9 coefficients and
// its irradiance on a surface with normal `normal`.
shader::Sh9 estimateSh9(const SkyImage& image, const EnvSampler& sampler, EnvSampling kind, uint32_t n,
                        glm::vec2 rotation);
glm::vec3 estimateIrradiance(const SkyImage& image, const EnvSampler& sampler, EnvSampling kind, uint32_t n,
                             glm::vec2 rotation, glm::vec3 normal);

// The nearest texel's radiance along d.
glm::vec3 texelRadiance(const SkyImage& image, glm::vec3 d);

}  // namespace tp::render
