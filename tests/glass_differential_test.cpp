// The footprints of the rays glass sends on (glassPathDifferentials,
// lib/ray_differential.glsl, run on the GPU by test_glass_differentials.comp)
// against central differences of the exact paths (shared/glass.h) on the
// CPU: each ray moved along its differential by +-eps, cast again at the
// sphere or box, and followed through it. The analytic differentials hold a
// sphere's curvature and a box's reflections inside (unfolded); the finite
// differences hold neither, only the paths.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <optional>
#include <random>
#include <vector>

#include "gpu_test.hpp"
#include "pool_shader_points.hpp"
#include "shared/glass.h"

namespace tp::test {
namespace {

// test_glass_differentials.comp's case.
struct GlassCase {
  glm::vec4 origin, direction;    // origin.w: the index of the ray's medium; direction.w: the water's level
  glm::vec4 originX, directionX;  // originX.w: the water's index; directionX.w: half its square (0: none)
  glm::vec4 center;               // w: a sphere's radius, a box's yaw
  glm::vec4 box;                  // xyz: a box's half size (0: a sphere); w: the index
};

// Where the ray meets the glass, and the paths from there.
struct Paths {
  glm::vec3 entry;
  shader::GlassExit exit;
};

std::optional<Paths> pathsOf(const GlassCase& c, glm::vec3 o, glm::vec3 d) {
  const bool box = c.box.x > 0.0f;
  const float ior = c.box.w, outside = c.origin.w;
  const shader::GlassSurround surround{c.direction.w, c.directionX.w, c.originX.w};
  if (box) {
    const glm::vec4 hit = shader::rayBox(o, d, c.center, glm::vec4(glm::vec3(c.box), 0.0f));
    if (hit.x <= 0.0f) return std::nullopt;
    const glm::vec3 p = o + hit.x * d;
    return Paths{p, shader::glassBoxPaths(p, d, glm::vec3(hit.y, hit.z, hit.w), c.center,
                                          glm::vec4(glm::vec3(c.box), 0.0f), ior, outside, surround)};
  }
  const float s = shader::raySphere(o, d, c.center);
  if (s <= 0.0f) return std::nullopt;
  const glm::vec3 p = o + s * d, n = (p - glm::vec3(c.center)) / c.center.w;
  return Paths{p, shader::glassSphereExactExit(p, d, n, c.center.w, ior, outside, surround)};
}

// The four derivatives the shader gives, by central differences; none where
// a moved ray meets the glass otherwise (another face, another number of
// reflections: the one-sided differences then disagree).
std::optional<std::array<glm::vec3, 4>> finiteDifferences(const GlassCase& c, float eps) {
  const glm::vec3 o(c.origin), d(c.direction), ox(c.originX), dx(c.directionX);
  const auto at = [&](float e) { return pathsOf(c, o + e * ox, glm::normalize(d + e * dx)); };
  const auto minus = at(-eps), centre = at(0.0f), plus = at(eps);
  if (!minus || !centre || !plus) return std::nullopt;
  const auto values = [](const Paths& p) {
    return std::array<glm::vec3, 4>{p.exit.exitPoint, p.exit.leaving, p.entry, p.exit.reflected};
  };
  const auto m = values(*minus), c0 = values(*centre), pl = values(*plus);
  std::array<glm::vec3, 4> out;
  for (size_t k = 0; k < 4; ++k) {
    const glm::vec3 forward = (pl[k] - c0[k]) / eps, backward = (c0[k] - m[k]) / eps;
    if (glm::length(forward - backward) > 0.05f * std::max(1.0f, glm::length(forward))) return std::nullopt;
    out[k] = (pl[k] - m[k]) / (2.0f * eps);
  }
  return out;
}

// A random unit vector perpendicular to d.
glm::vec3 perpendicular(glm::vec3 d, std::mt19937& rng) {
  std::normal_distribution<float> gauss;
  const glm::vec3 v(gauss(rng), gauss(rng), gauss(rng));
  return glm::normalize(v - d * glm::dot(v, d));
}

// Rays from 1.5-2.5 m away at a random point well inside the glass, with a
// differential of the size of a pixel's footprint (its origin's and its
// direction's), each in a random direction. In the air, or with water up to
// a random height through the glass, the ray in whichever its origin is.
std::vector<GlassCase> randomCases(bool boxes, uint32_t count, std::mt19937& rng, bool water = false) {
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  std::normal_distribution<float> gauss;
  std::vector<GlassCase> cases;
  for (uint32_t i = 0; i < count; ++i) {
    GlassCase c{};
    const glm::vec3 centre(unit(rng) - 0.5f, unit(rng) - 0.5f, unit(rng) - 0.5f);
    const float ior = 1.1f + 1.6f * unit(rng);
    glm::vec3 target;
    if (boxes) {
      // Long and thin as often as not: light pipes reflect inside.
      const glm::vec3 half(0.1f + 0.5f * unit(rng), 0.1f + 0.9f * unit(rng), 0.1f + 0.5f * unit(rng));
      c.center = glm::vec4(centre, 6.28f * unit(rng));
      c.box = glm::vec4(half, ior);
      target = centre + shader::fromBoxFrame(0.9f * half * (2.0f * glm::vec3(unit(rng), unit(rng), unit(rng)) - 1.0f),
                                             c.center.w);
    } else {
      const float radius = 0.2f + 0.6f * unit(rng);
      c.center = glm::vec4(centre, radius);
      c.box = glm::vec4(0.0f, 0.0f, 0.0f, ior);
      target = centre + 0.8f * radius * (2.0f * glm::vec3(unit(rng), unit(rng), unit(rng)) - 1.0f) / std::sqrt(3.0f);
    }
    const glm::vec3 away = glm::normalize(glm::vec3(gauss(rng), gauss(rng), gauss(rng)));
    const glm::vec3 origin = target + (1.5f + unit(rng)) * away, d = glm::normalize(target - origin);
    const float level = water ? centre.y + 1.4f * (unit(rng) - 0.5f) : 0.0f, waterIor = 1.333f;
    c.origin = glm::vec4(origin, water && origin.y < level ? waterIor : 1.0f);
    c.direction = glm::vec4(d, water ? level : 0.0f);
    c.originX = glm::vec4(0.01f * glm::normalize(glm::vec3(gauss(rng), gauss(rng), gauss(rng))), waterIor);
    c.directionX = glm::vec4(0.003f * perpendicular(d, rng), water ? 50.0f : 0.0f);
    cases.push_back(c);
  }
  return cases;
}

class GlassDifferentialTest : public GpuTest {
 protected:
  // Holds the GPU's derivatives against the finite differences: each within
  // 2% of its size (or of the differential's, where it is smaller). The
  // finite differences' own round-off reaches 1% for the spheres (in the
  // float casts: 3.6% with rays from 3-5 m and steps of 0.1).
  void expectDifferentialsMatch(const char* name, const std::vector<GlassCase>& cases, uint32_t* reflecting,
                                uint32_t* acrossTheLevel = nullptr, float step = 0.3f) {
    const auto gpu = shaderAtPoints(ctx(), "test_glass_differentials.comp", cases, 4);
    const char* what[4] = {"leaving origin", "leaving direction", "reflected origin", "reflected direction"};
    uint32_t compared = 0, failures = 0;
    float worst = 0.0f;
    for (size_t i = 0; i < cases.size(); ++i) {
      // Steps of 0.3 of the differential (3 mm, 1 mrad): far above
      // float round-off, and their second-order error far below 1% (at 0.1
      // the round-off reaches 1.7% for the spheres in the air).
      const auto fd = finiteDifferences(cases[i], step);
      const auto paths = pathsOf(cases[i], glm::vec3(cases[i].origin), glm::vec3(cases[i].direction));
      // Glass of an index under the water's may reflect the ray whole: no path goes in.
      if (!fd || paths->exit.reflectance >= 1.0f) continue;
      ++compared;
      if (reflecting && glm::dot(paths->exit.inside, paths->exit.lastInside) < 0.999f) ++*reflecting;
      if (acrossTheLevel && paths->exit.entryIor != paths->exit.exitIor) ++*acrossTheLevel;
      for (size_t k = 0; k < 4; ++k) {
        const glm::vec3 g(gpu[4 * i + k]);
        const float scale = std::max(glm::length((*fd)[k]), k % 2 ? 0.003f : 0.01f);
        const float error = glm::length(g - (*fd)[k]) / scale;
        worst = std::max(worst, error);
        if (error > 0.02f && ++failures <= 5) {
          ADD_FAILURE() << name << " case " << i << ", " << what[k] << ": GPU (" << g.x << ", " << g.y << ", " << g.z
                        << ") against (" << (*fd)[k].x << ", " << (*fd)[k].y << ", " << (*fd)[k].z << ")";
        }
      }
    }
    std::printf("glass differentials, %s: %u of %zu cases compared, largest error %.2e of the derivative's size\n",
                name, compared, cases.size(), worst);
    EXPECT_GT(compared, uint32_t(cases.size() * 3 / 4)) << name;
    EXPECT_EQ(failures, 0u) << name;
  }
};

}  // namespace

TEST_F(GlassDifferentialTest, SpheresMatchFiniteDifferencesOfTheirPaths) {
  std::mt19937 rng(7);
  expectDifferentialsMatch("spheres", randomCases(false, 512, rng), nullptr);
}

TEST_F(GlassDifferentialTest, BoxesMatchFiniteDifferencesOfTheirPathsReflectionsInsideIncluded) {
  std::mt19937 rng(11);
  uint32_t reflecting = 0;
  expectDifferentialsMatch("boxes", randomCases(true, 512, rng), &reflecting);
  std::printf("  of which %u reflect inside\n", reflecting);
  EXPECT_GT(reflecting, 40u);
}

// The same with water round the glass up to a random height through it: the
// ray comes in the water or the air, and leaves into either.
TEST_F(GlassDifferentialTest, GlassInTheWaterMatchesFiniteDifferencesOfItsPaths) {
  for (const bool boxes : {false, true}) {
    std::mt19937 rng(boxes ? 17 : 13);
    uint32_t across = 0;
    // Steps of 0.1: from the water into glass of a lower index the ray
    // bends fast near the critical angle, where steps of 0.3 leave a
    // second-order error of 4.5% (0.5% at 0.1).
    expectDifferentialsMatch(boxes ? "boxes in water" : "spheres in water", randomCases(boxes, 512, rng, true), nullptr,
                             &across, 0.1f);
    std::printf("  of which %u leave into another medium than they came in\n", across);
    EXPECT_GT(across, 50u);
  }
}

}  // namespace tp::test
