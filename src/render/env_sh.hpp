#pragma once
#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

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

// Monte Carlo estimates over the whole sphere from the n-point Hammersley set
// rotated by `rotation` (shader::envHammersley), each direction drawn by the
// sampler or uniformly (density 1 / 4pi), of the image's (nearest-texel) radiance: its SH9 coefficients and
// its irradiance on a surface with normal `normal`.
shader::Sh9 estimateSh9(const SkyImage& image, const EnvSampler& sampler, EnvSampling kind, uint32_t n,
                        glm::vec2 rotation);
glm::vec3 estimateIrradiance(const SkyImage& image, const EnvSampler& sampler, EnvSampling kind, uint32_t n,
                             glm::vec2 rotation, glm::vec3 normal);

// n unit vectors spread evenly over the sphere (a Fibonacci spiral): the
// normals at which estimates of the irradiance are compared.
std::vector<glm::vec3> spiralNormals(int n);

}  // namespace tp::render
