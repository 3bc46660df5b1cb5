// Glass boxes: the exact path through a box (shared/glass.h) against the
// closed forms of a slab and of a light pipe. The raster's glass boxes
// against the reference: tests/glass_test.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "shared/glass.h"
#include "shared/objects.h"

namespace tp::test {
namespace {

constexpr float kIor = 1.5f;
// No water anywhere round the glass.
constexpr shader::GlassSurround kInAir{0.0f, 0.0f, 1.0f};

// A ray at `degrees` from the vertical in the xy plane, going down.
glm::vec3 downAt(float degrees) {
  const float a = glm::radians(degrees);
  return {std::sin(a), -std::cos(a), 0.0f};
}

}  // namespace

// A ray into the top of a wide, thin slab leaves through its bottom parallel
// to itself, moved sideways by t sin(i - r) / cos(r) (t the slab's
// thickness, i and r the angles of incidence and refraction): the textbook
// slab.
TEST(GlassBoxOptics, ASlabMovesTheRayAndKeepsItsDirection) {
  const glm::vec4 center(0.0f, 0.0f, 0.0f, 0.0f), half(10.0f, 0.1f, 10.0f, 0.0f);
  for (float degrees : {0.0f, 20.0f, 45.0f, 80.0f}) {
    const glm::vec3 dir = downAt(degrees), entry(0.0f, 0.1f, 0.0f);
    const shader::GlassExit g = shader::glassBoxPaths(entry, dir, {0.0f, 1.0f, 0.0f}, center, half, kIor, 1.0f, kInAir);
    const float i = glm::radians(degrees), r = std::asin(std::sin(i) / kIor);
    EXPECT_NEAR(glm::distance(g.leaving, dir), 0.0f, 1e-5f) << degrees;
    EXPECT_NEAR(g.exitPoint.y, -0.1f, 1e-6f) << degrees;
    // Along x the ray inside runs t tan(r); sideways from the line it came along, t sin(i - r) / cos(r).
    EXPECT_NEAR(g.exitPoint.x, 0.2f * std::tan(r), 1e-5f) << degrees;
    const glm::vec3 straight = entry + (0.2f / std::cos(i)) * dir;
    const float moved = glm::length(glm::cross(g.exitPoint - straight, dir));
    EXPECT_NEAR(moved, 0.2f * std::sin(i - r) / std::cos(r), 1e-5f) << degrees;
    EXPECT_NEAR(g.reflectance, shader::fresnelDielectric(std::cos(i), 1.0f, kIor), 1e-6f);
    EXPECT_NEAR(glm::distance(g.reflected, glm::vec3(dir.x, -dir.y, dir.z)), 0.0f, 1e-6f);
  }
}

// Under the water each surface bends the ray by the glass's index over the
// water's: in a slab wholly under the level the ray runs at sin r = n_w sin(i)
// / n_g and leaves as it came, moved sideways by t sin(i - r) / cos(r). Across
// the level, the top face in the air and the bottom in the water, parallel
// faces leave it as if it had gone from the air straight into the water:
// sin(out) = sin(i) / n_w, whatever the glass.
TEST(GlassBoxOptics, ASlabInTheWaterBendsByTheRatioOfTheIndices) {
  const float water = 1.333f;
  const glm::vec4 center(0.0f, 0.0f, 0.0f, 0.0f), half(10.0f, 0.1f, 10.0f, 0.0f);
  const shader::GlassSurround under{1.0f, 50.0f, water}, across{0.05f, 50.0f, water};
  for (float degrees : {0.0f, 20.0f, 45.0f, 80.0f}) {
    const glm::vec3 dir = downAt(degrees), entry(0.0f, 0.1f, 0.0f);
    const float i = glm::radians(degrees), r = std::asin(water * std::sin(i) / kIor);
    const shader::GlassExit g = shader::glassBoxPaths(entry, dir, {0.0f, 1.0f, 0.0f}, center, half, kIor, water, under);
    EXPECT_NEAR(glm::distance(g.leaving, dir), 0.0f, 1e-5f) << degrees;
    EXPECT_NEAR(g.exitPoint.x, 0.2f * std::tan(r), 1e-5f) << degrees;
    const glm::vec3 straight = entry + (0.2f / std::cos(i)) * dir;
    EXPECT_NEAR(glm::length(glm::cross(g.exitPoint - straight, dir)), 0.2f * std::sin(i - r) / std::cos(r), 1e-5f)
        << degrees;
    EXPECT_NEAR(g.reflectance, shader::fresnelDielectric(std::cos(i), water, kIor), 1e-6f) << degrees;

    const shader::GlassExit a = shader::glassBoxPaths(entry, dir, {0.0f, 1.0f, 0.0f}, center, half, kIor, 1.0f, across);
    EXPECT_NEAR(a.leaving.x, std::sin(i) / water, 1e-5f) << degrees;
    EXPECT_LT(a.leaving.y, 0.0f);
    EXPECT_NEAR(a.reflectance, shader::fresnelDielectric(std::cos(i), 1.0f, kIor), 1e-6f) << degrees;
  }
}

// A light pipe: a ray into the top of a tall, narrow glass box meets its
// sides past the critical angle (it enters within asin(1 / 1.5) = 41.8
// degrees of the vertical, so meets a side at least 48.2 degrees from its
// normal) and reflects between them down to the bottom. Unfolded, the path
// is a straight line: the exit lies where that line, folded back into the
// box, meets the bottom, and the ray leaves as it came, mirrored once for
// each reflection.
TEST(GlassBoxOptics, ALightPipeReflectsOffItsSidesAndLeavesThroughTheBottom) {
  const float w = 0.1f, height = 1.0f;  // half width and height
  const glm::vec4 center(0.0f, 0.0f, 0.0f, 0.0f), half(w, 0.5f * height, w, 0.0f);
  for (float degrees : {10.0f, 30.0f, 60.0f, 85.0f}) {
    const glm::vec3 dir = downAt(degrees), entry(-0.05f, 0.5f * height, 0.0f);
    const shader::GlassExit g = shader::glassBoxPaths(entry, dir, {0.0f, 1.0f, 0.0f}, center, half, kIor, 1.0f, kInAir);
    const float r = std::asin(std::sin(glm::radians(degrees)) / kIor);
    const float unfolded = entry.x + height * std::tan(r);  // where the straight line meets the bottom
    // Folded into [-w, w]: each crossing of a side is one reflection.
    const int reflections = int(std::floor((unfolded + w) / (2.0f * w)));
    const float offset = unfolded + w - 2.0f * w * float(reflections);
    const float folded = reflections % 2 == 0 ? offset - w : w - offset;
    ASSERT_LE(reflections, TP_GLASS_BOX_REFLECTIONS) << degrees;
    EXPECT_NEAR(g.exitPoint.y, -0.5f * height, 1e-5f) << degrees;
    EXPECT_NEAR(g.exitPoint.x, folded, 1e-4f) << degrees << ": " << reflections << " reflections";
    const glm::vec3 expected(reflections % 2 == 0 ? dir.x : -dir.x, dir.y, dir.z);
    EXPECT_NEAR(glm::distance(g.leaving, expected), 0.0f, 1e-5f) << degrees;
  }
}

// Turned about the vertical, the box turns its paths with it.
TEST(GlassBoxOptics, ATurnedBoxTurnsItsPaths) {
  const float yaw = glm::radians(30.0f);
  const glm::vec3 ax = shader::boxAxisX(yaw), az = shader::boxAxisZ(yaw);
  auto turned = [&](glm::vec3 v) { return v.x * ax + glm::vec3(0.0f, v.y, 0.0f) + v.z * az; };
  const glm::vec4 half(0.3f, 0.4f, 0.2f, 0.0f), at(1.0f, 2.0f, -1.0f, 0.0f);
  const glm::vec3 entry(0.3f, 0.1f, -0.05f), dir = glm::normalize(glm::vec3(-0.7f, -0.3f, 0.4f));
  const shader::GlassExit plain =
      shader::glassBoxPaths(entry, dir, {1.0f, 0.0f, 0.0f}, glm::vec4(0.0f), half, kIor, 1.0f, kInAir);
  const shader::GlassExit g = shader::glassBoxPaths(glm::vec3(at) + turned(entry), turned(dir), turned({1, 0, 0}),
                                                    glm::vec4(glm::vec3(at), yaw), half, kIor, 1.0f, kInAir);
  EXPECT_NEAR(glm::distance(g.exitPoint, glm::vec3(at) + turned(plain.exitPoint)), 0.0f, 1e-5f);
  EXPECT_NEAR(glm::distance(g.leaving, turned(plain.leaving)), 0.0f, 1e-5f);
  EXPECT_NEAR(g.reflectance, plain.reflectance, 1e-6f);
}

// Every ray into a box leaves from a point on its surface going outwards,
// along a unit direction, for entries over every face, directions over the
// hemisphere and indices from 1.01 to 3.
TEST(GlassBoxOptics, EveryRayLeavesFromTheSurfaceOutwards) {
  const glm::vec4 half(0.5f, 0.2f, 0.3f, 0.0f);
  size_t rays = 0;
  for (float ior : {1.01f, 1.5f, 3.0f}) {
    for (int axis = 0; axis < 3; ++axis) {
      for (int i = 1; i <= 400; ++i) {  // from 1: point 0 is a corner
        // Points and directions spread by the golden ratio's sequence.
        const float u = std::fmod(0.618034f * float(i), 1.0f), v = std::fmod(0.754878f * float(i), 1.0f);
        const float w = std::fmod(0.569840f * float(i) + 0.3f, 1.0f);
        glm::vec3 n(0.0f), entry;
        n[axis] = 1.0f;
        entry = glm::vec3(half) * glm::vec3(2.0f * u - 1.0f, 2.0f * v - 1.0f, 2.0f * w - 1.0f);
        entry[axis] = half[axis];
        const float cosI = 0.02f + 0.98f * v, phi = 6.2831853f * u;
        glm::vec3 dir(0.0f);
        dir[axis] = -cosI;
        dir[(axis + 1) % 3] = std::sqrt(1.0f - cosI * cosI) * std::cos(phi);
        dir[(axis + 2) % 3] = std::sqrt(1.0f - cosI * cosI) * std::sin(phi);
        const shader::GlassExit g = shader::glassBoxPaths(entry, dir, n, glm::vec4(0.0f), half, ior, 1.0f, kInAir);
        const glm::vec3 out = glm::abs(g.exitPoint) / glm::vec3(half);
        EXPECT_NEAR(std::max({out.x, out.y, out.z}), 1.0f, 1e-5f);
        EXPECT_NEAR(glm::length(g.leaving), 1.0f, 1e-5f);
        // Outwards through the face it leaves by.
        int face = 0;
        for (int k = 1; k < 3; ++k)
          if (out[k] > out[face]) face = k;
        EXPECT_GT(g.leaving[face] * g.exitPoint[face], 0.0f) << ior << " " << axis << " " << i;
        ++rays;
      }
    }
  }
  EXPECT_EQ(rays, 3600u);
}

}  // namespace tp::test
