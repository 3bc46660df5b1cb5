// Light scattered once in the water (shared/water_scattering.h), on the
// CPU: the phase function against its defining integrals, the closed form
// against a quadrature of the model's integrand written out here, and the
// semi-infinite slab against its textbook closed form.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <glm/gtc/constants.hpp>
#include <map>
#include <optional>

#include "shading/frame_uniforms.hpp"
#include "shared/water_scattering.h"

namespace tp::test {
namespace {

using shader::henyeyGreenstein;
using shader::waterInScatter;

constexpr float kLevel = -0.15f, kIor = 1.333f;
constexpr uint32_t kPieces = 4;  // water.scattering_shadow_pieces' default
const glm::vec3 kExtinction(0.55f, 0.19f, 0.16f);
const glm::vec4 kScattering(0.1f, 0.1f, 0.1f, 0.7f);

// The default scene's light with the sun at `elevationDegrees`; nothing
// casts a shadow unless `sphere` is given.
shader::FrameUniforms sunAt(float elevationDegrees, std::optional<scene::Sphere> sphere = std::nullopt) {
  scene::Scene s = scene::defaultScene();
  s.sky.sunElevationDegrees = elevationDegrees;
  s.render.shadows = sphere.has_value();
  s.spheres.clear();
  if (sphere) s.spheres.push_back(*sphere);
  shader::FrameUniforms frame = render::frameUniforms(s, 64, 64);
  frame.shadows = render::shadowCasters(s, 0.0f);
  return frame;
}

// A pool's light around (SH9 of the radiance arriving from each
// direction), as the bake gives it under a high sun: a bright floor below,
// Snell's window above, brighter towards +x. Positive everywhere.
shader::Sh9 lightAround() {
  shader::Sh9 sh{};
  sh.c[0] = glm::vec4(0.90f, 1.60f, 1.70f, 0.0f);     // the mean
  sh.c[1] = glm::vec4(-0.20f, -0.35f, -0.40f, 0.0f);  // y: brighter below
  sh.c[3] = glm::vec4(0.10f, 0.15f, 0.12f, 0.0f);     // x
  sh.c[5] = glm::vec4(0.04f, 0.05f, 0.06f, 0.0f);     // yz
  sh.c[6] = glm::vec4(0.12f, 0.22f, 0.25f, 0.0f);     // 3y^2 - 1: bright up and down
  sh.c[8] = glm::vec4(-0.05f, -0.06f, -0.04f, 0.0f);  // x^2 - z^2
  return sh;
}

// The light around scattered towards -dir, per unit of sigma_s: Henyey and
// Greenstein's phase function times the radiance the SH9 holds, integrated
// over the sphere of directions by the midpoint rule (not by the bands'
// factors the header uses), in polar angle about dir, where the phase
// peaks, finely enough for g = 0.9; the radiance is a trigonometric
// polynomial of degree 2 in the azimuth, which 16 points take exactly.
glm::dvec3 aroundScattered(const shader::Sh9& sh, glm::vec3 dir, float g) {
  constexpr int kPolar = 4000, kAzimuth = 16;
  const glm::dvec3 w(dir);
  const glm::dvec3 t =
      glm::normalize(glm::cross(std::abs(w.y) < 0.9 ? glm::dvec3(0.0, 1.0, 0.0) : glm::dvec3(1.0, 0.0, 0.0), w));
  const glm::dvec3 b = glm::cross(w, t);
  glm::dvec3 sum(0.0);
  for (int i = 0; i < kPolar; ++i) {
    const double theta = (i + 0.5) * glm::pi<double>() / kPolar;
    // Light from `from` travels along -from; scattered towards -dir: the
    // angle between the two travels is theta.
    const double phase = henyeyGreenstein(float(std::cos(theta)), g) * std::sin(theta);
    for (int j = 0; j < kAzimuth; ++j) {
      const double a = (j + 0.5) * 2.0 * glm::pi<double>() / kAzimuth;
      const glm::vec3 from(std::cos(theta) * w + std::sin(theta) * (std::cos(a) * t + std::sin(a) * b));
      glm::dvec3 radiance(0.0);
      for (uint32_t k = 0; k < 9; ++k) radiance += glm::dvec3(glm::vec3(sh.c[k])) * double(shader::sh9Basis(k, from));
      sum += radiance * phase;
    }
  }
  return sum * (glm::pi<double>() / kPolar) * (2.0 * glm::pi<double>() / kAzimuth);
}

// The model's integrand at distance s along the path, written from the
// model's words, not from the header's pieces: the sun's beam at the point
// and the light around (its scattered share `around`, from
// aroundScattered), scattered towards the start, attenuated on the way back.
glm::dvec3 integrand(const shader::FrameUniforms& frame, glm::dvec3 around, glm::vec3 start, glm::vec3 dir, double s) {
  const glm::vec3 at = start + float(s) * dir;
  const glm::dvec3 x = glm::dvec3(start) + s * glm::dvec3(dir);
  const double depth = kLevel - x.y;
  const glm::dvec3 ext(kExtinction), back = glm::exp(-ext * s);
  glm::dvec3 light = around;
  const glm::dvec3 toSun(frame.sunDirection);
  // Snell's law for the beam's angle from the vertical.
  const double sinWater = std::sqrt(1.0 - toSun.y * toSun.y) / kIor, mu = std::sqrt(1.0 - sinWater * sinWater);
  const glm::dvec3 horizontal = glm::normalize(glm::dvec3(toSun.x, 0.0, toSun.z));
  const glm::dvec3 travel = -sinWater * horizontal - glm::dvec3(0.0, mu, 0.0);
  const double g = kScattering.w, c = glm::dot(travel, -glm::dvec3(dir));
  const double phase = (1.0 - g * g) / (4.0 * glm::pi<double>() * std::pow(1.0 + g * g - 2.0 * g * c, 1.5));
  const double share = shader::sunVisibility(frame.shadows, at, glm::vec3(toSun));
  light += share * phase * glm::dvec3(frame.sunIrradiance) * (toSun.y / mu) * glm::exp(-ext * depth / mu);
  return glm::dvec3(glm::vec3(kScattering)) * light * back;
}

// Composite Simpson's rule over [0, length].
glm::dvec3 quadrature(const shader::FrameUniforms& frame, glm::vec3 start, glm::vec3 dir, double length) {
  constexpr int kIntervals = 4000;
  const double h = length / kIntervals;
  const glm::dvec3 around = aroundScattered(lightAround(), dir, kScattering.w);
  glm::dvec3 sum = integrand(frame, around, start, dir, 0.0) + integrand(frame, around, start, dir, length);
  for (int i = 1; i < kIntervals; ++i) sum += (i % 2 ? 4.0 : 2.0) * integrand(frame, around, start, dir, i * h);
  return sum * h / 3.0;
}

}  // namespace

// The phase function is a density over the sphere of directions whose mean
// cosine is g (its definition), for forward, even and backward scattering.
TEST(WaterScattering, PhaseFunctionIsNormalisedWithMeanCosineG) {
  for (const float g : {-0.5f, 0.0f, 0.3f, 0.7f, 0.9f}) {
    constexpr int kSteps = 200000;
    double total = 0.0, meanCosine = 0.0;
    for (int i = 0; i < kSteps; ++i) {  // midpoints in cos(theta): dOmega = 2 pi dcos
      const double c = -1.0 + (i + 0.5) * 2.0 / kSteps;
      const double p = henyeyGreenstein(float(c), g) * 2.0 * glm::pi<double>() * 2.0 / kSteps;
      total += p;
      meanCosine += c * p;
    }
    EXPECT_NEAR(total, 1.0, 1e-4) << "g " << g;
    EXPECT_NEAR(meanCosine, g, 1e-4) << "g " << g;
  }
}

// The light around scattered by the phase function: the header's bands
// scaled by g^l against the integral over the sphere, for forward, even and
// backward scattering, looking up, down, level and slanting. With g = 0 it
// is the light's mean over the sphere.
TEST(WaterScattering, LightAroundScatteredIsThePhaseOverTheSphere) {
  const shader::Sh9 sh = lightAround();
  double worst = 0.0;
  for (const float g : {-0.5f, 0.0f, 0.3f, 0.7f, 0.9f}) {
    for (const glm::vec3 dir : {glm::vec3(0.0f, 1.0f, 0.0f), glm::vec3(0.0f, -1.0f, 0.0f), glm::vec3(1.0f, 0.0f, 0.0f),
                                glm::normalize(glm::vec3(-0.6f, -0.3f, 0.8f))}) {
      const glm::dvec3 expected = aroundScattered(sh, dir, g);
      const glm::vec3 got = shader::poolLightScattered(sh, dir, g);
      for (int c = 0; c < 3; ++c) {
        const double relative = std::abs(got[c] - expected[c]) / expected[c];
        worst = std::max(worst, relative);
        EXPECT_LT(relative, 1e-4) << "g " << g << " channel " << c;
      }
      if (g == 0.0f) {
        for (int c = 0; c < 3; ++c)
          EXPECT_NEAR(got[c], sh.c[0][c] / (2.0f * std::sqrt(glm::pi<float>())), 1e-6f) << "channel " << c;
      }
    }
  }
  std::printf("light around scattered against the sphere's quadrature: largest relative difference %.2e\n", worst);
}

// The closed form against Simpson's rule over the model's integrand, on
// paths down, up, level and slanting, near and far from the surface, under
// a high and a low sun (including straight along the sun's beam, where the
// closed form takes its series).
TEST(WaterScattering, ClosedFormMatchesQuadrature) {
  struct Path {
    glm::vec3 start, dir;
    float length;
  };
  double worst = 0.0;
  for (const float elevation : {70.0f, 35.0f, 8.0f}) {
    const shader::FrameUniforms frame = sunAt(elevation);
    const glm::vec3 againstBeam =
        -glm::refract(-glm::vec3(frame.sunDirection), glm::vec3(0.0f, 1.0f, 0.0f), 1.0f / kIor);
    for (const Path& p :
         {Path{{0.0f, kLevel, 0.0f}, {0.0f, -1.0f, 0.0f}, 1.2f}, Path{{0.3f, -1.2f, 0.2f}, {0.0f, 1.0f, 0.0f}, 1.0f},
          Path{{-1.0f, -0.7f, 0.5f}, glm::normalize(glm::vec3(1.0f, 0.0f, -0.4f)), 3.5f},
          Path{{1.5f, -0.2f, -1.5f}, glm::normalize(glm::vec3(-0.6f, -0.3f, 0.8f)), 2.6f},
          Path{{0.0f, -1.1f, 0.0f}, againstBeam, 0.9f}}) {
      const glm::dvec3 expected = quadrature(frame, p.start, p.dir, p.length);
      // One closed form (0 pieces), and the default's pieces, all lit here:
      // the same integral summed in float in parts.
      for (const uint32_t pieces : {0u, kPieces}) {
        const glm::vec3 got = waterInScatter(frame, kExtinction, kScattering, kLevel, kIor, pieces, lightAround(),
                                             p.start, p.dir, p.length);
        for (int c = 0; c < 3; ++c) {
          const double relative = std::abs(got[c] - expected[c]) / expected[c];
          worst = std::max(worst, relative);
          EXPECT_LT(relative, 5e-5) << "sun " << elevation << " channel " << c << " pieces " << pieces;
        }
      }
    }
  }
  std::printf("closed form against Simpson's rule: largest relative difference %.2e\n", worst);
}

// A sphere under the water shadows the sun's beam across a path: the pieces
// the closed form is cut into, each shadowed at its middle, against the
// quadrature of the shadowed integrand (the shadow's edges taken by 4000
// points, each point's share of the sun's disc). The error falls as the
// pieces grow; the unshadowed closed form is far off: the shadow matters.
// A harsh case: the whole path crosses the shadow, 0.6 m wide in 2 m.
TEST(WaterScattering, ShadowedBeamConvergesToQuadratureOfTheShadowedIntegrand) {
  const scene::Sphere sphere{.center = {0.0f, -0.6f, 0.0f}, .radius = 0.3f};
  const shader::FrameUniforms shadowed = sunAt(60.0f, sphere), open = sunAt(60.0f);
  const glm::vec3 toSun(shadowed.sunDirection);
  // Level, under the sphere's shadow, across it.
  const glm::vec3 across = glm::normalize(glm::cross(glm::vec3(toSun.x, 0.0f, toSun.z), glm::vec3(0.0f, 1.0f, 0.0f)));
  const glm::vec3 below = sphere.center + 0.6f * glm::refract(-toSun, glm::vec3(0.0f, 1.0f, 0.0f), 1.0f / kIor);
  const glm::vec3 start = below - 1.0f * across;
  const glm::dvec3 expected = quadrature(shadowed, start, across, 2.0);
  const glm::vec3 unshadowed =
      waterInScatter(open, kExtinction, kScattering, kLevel, kIor, 0, lightAround(), start, across, 2.0f);
  // No pieces: the beam unshadowed in one closed form, the casters ignored.
  const glm::vec3 whole =
      waterInScatter(shadowed, kExtinction, kScattering, kLevel, kIor, 0, lightAround(), start, across, 2.0f);
  std::map<uint32_t, double> errors;
  for (const uint32_t pieces : {2u, 4u, 8u, 16u, 32u}) {
    const glm::vec3 got =
        waterInScatter(shadowed, kExtinction, kScattering, kLevel, kIor, pieces, lightAround(), start, across, 2.0f);
    for (int c = 0; c < 3; ++c) errors[pieces] = std::max(errors[pieces], std::abs(got[c] - expected[c]) / expected[c]);
    std::printf("%2u pieces: largest relative difference %.4f\n", pieces, errors[pieces]);
  }
  double without = 0.0;
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(whole[c], unshadowed[c], 1e-5f * unshadowed[c]) << "channel " << c;
    without = std::max(without, std::abs(unshadowed[c] - expected[c]) / expected[c]);
  }
  std::printf("unshadowed: %.4f\n", without);
  EXPECT_LT(errors[32], 0.02);
  EXPECT_LT(errors[32], 0.5 * errors[4]);
  EXPECT_LT(errors[8], errors[2]);
  EXPECT_GT(without, 5.0 * errors[32]);
}

// Looking straight down from the surface into water without a floor, the
// single-scattering radiance is sigma_s (p E / (sigma_t (1 + 1 / mu)) +
// S / sigma_t), S the light around's scattered share (the same at every
// depth); level, at depth d, with the path running for ever, it is sigma_s
// (p E exp(-sigma_t d / mu) + S) / sigma_t.
TEST(WaterScattering, SemiInfiniteSlabMatchesItsClosedForm) {
  const shader::FrameUniforms frame = sunAt(50.0f);
  const glm::vec3 toSun(frame.sunDirection);
  const double mu = std::sqrt(1.0 - (1.0 - toSun.y * toSun.y) / (kIor * kIor));
  const glm::dvec3 sun = glm::dvec3(frame.sunIrradiance) * double(toSun.y) / mu;
  const glm::dvec3 ext(kExtinction), sigma{glm::vec3(kScattering)};
  // Down: the beam travels at mu below the horizon's normal; the path points down.
  const double downPhase = henyeyGreenstein(-float(mu), kScattering.w);
  const glm::dvec3 aroundDown = aroundScattered(lightAround(), {0.0f, -1.0f, 0.0f}, kScattering.w);
  const glm::dvec3 down = sigma * (downPhase * sun / (ext * (1.0 + 1.0 / mu)) + aroundDown / ext);
  const glm::vec3 gotDown = waterInScatter(frame, kExtinction, kScattering, kLevel, kIor, kPieces, lightAround(),
                                           {0.0f, kLevel, 0.0f}, {0.0f, -1.0f, 0.0f}, 1e4f);
  // Level, looking towards the sun's side: the light scattered back travels
  // away from it, at sin(refracted angle) to the beam's cosine.
  const glm::vec3 towardsSun = glm::normalize(glm::vec3(toSun.x, 0.0f, toSun.z));
  const double depth = 0.8, levelPhase = henyeyGreenstein(float(std::sqrt(1.0 - mu * mu)), kScattering.w);
  const glm::dvec3 aroundLevel = aroundScattered(lightAround(), towardsSun, kScattering.w);
  const glm::dvec3 level = sigma * (levelPhase * sun * glm::exp(-ext * depth / mu) + aroundLevel) / ext;
  const glm::vec3 gotLevel = waterInScatter(frame, kExtinction, kScattering, kLevel, kIor, kPieces, lightAround(),
                                            {0.0f, kLevel - float(depth), 0.0f}, towardsSun, 1e4f);
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(gotDown[c], down[c], 1e-5 * down[c]) << "channel " << c;
    EXPECT_NEAR(gotLevel[c], level[c], 1e-5 * level[c]) << "channel " << c;
  }
  std::printf("slab looking down: %.5f %.5f %.5f (closed form %.5f %.5f %.5f)\n", gotDown.x, gotDown.y, gotDown.z,
              down.x, down.y, down.z);
}

// No scattering coefficient, no light: exactly 0, so that adding it changes
// no bit of a frame.
TEST(WaterScattering, NoScatteringAddsExactlyNothing) {
  const shader::FrameUniforms frame = sunAt(40.0f);
  const glm::vec3 light = waterInScatter(frame, kExtinction, glm::vec4(0.0f, 0.0f, 0.0f, 0.7f), kLevel, kIor, kPieces,
                                         lightAround(), {0.0f, -0.5f, 0.0f}, {0.0f, -1.0f, 0.0f}, 2.0f);
  EXPECT_EQ(light, glm::vec3(0.0f));
  EXPECT_FALSE(shader::waterScatters(glm::vec4(0.0f, 0.0f, 0.0f, 0.7f)));
  shader::CameraMedium medium{glm::vec4(kExtinction, 1.0f), glm::vec4(0.0f),
                              glm::vec4(kLevel, kIor, float(kPieces), 0.0f)};
  EXPECT_EQ(shader::viewInScatter(frame, medium, lightAround(), glm::vec3(1.0f, -1.0f, 0.0f)), glm::vec3(0.0f));
}

}  // namespace tp::test
