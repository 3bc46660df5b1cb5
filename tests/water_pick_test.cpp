// Picking in the viewer (app/water_pick) against closed forms: the ray
// through a pixel, its hit on flat, tilted and bumped water, rays that miss,
// and ray-sphere intersections.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "scene/scene.hpp"
#include "sim/water_state.hpp"
#include "viewer/water_pick.hpp"

namespace tp::test {
namespace {

using app::Ray;

scene::Water defaultWater() { return scene::defaultScene().water; }

// The heights of a plane u = a x + c z + b (world x, z) at the cell centres.
sim::WaterState planeState(const scene::Water& water, double a, double c, double b) {
  sim::WaterState s = sim::flatState(water.grid);
  const double h = double(water.extent) / water.grid, corner = -0.5 * double(water.extent);
  for (uint32_t j = 0; j < water.grid; ++j) {
    for (uint32_t i = 0; i < water.grid; ++i) {
      s.u[size_t(j) * water.grid + i] = float(a * (corner + (i + 0.5) * h) + c * (corner + (j + 0.5) * h) + b);
    }
  }
  return s;
}

Ray towards(glm::dvec3 from, glm::dvec3 to) { return Ray{from, glm::normalize(to - from)}; }

}  // namespace

TEST(WaterPick, AStraightDownRayHitsFlatWaterExactlyBelowIt) {
  const scene::Water water = defaultWater();
  const sim::WaterState flat = sim::flatState(water.grid);
  for (const glm::dvec2 xz : {glm::dvec2(0.37, -1.21), glm::dvec2(-1.99, 1.99), glm::dvec2(0.0, 0.0)}) {
    const Ray down{{xz.x, 2.5, xz.y}, {0.0, -1.0, 0.0}};
    for (const sim::WaterState* state : {&flat, static_cast<const sim::WaterState*>(nullptr)}) {
      const auto hit = app::pickWater(down, water, state);
      ASSERT_TRUE(hit) << xz.x << "," << xz.y;
      EXPECT_EQ(*hit, glm::dvec3(xz.x, double(water.level), xz.y));
    }
  }
}

// The frame's pixel grid against the camera's own basis: the ray through
// pixel point (px, py) of a W x H frame has the direction
// forward + right * tan(fov/2) * aspect * ndcX - up * tan(fov/2) * ndcY,
// ndc = 2 p / size - 1 (Vulkan: y down the image), and meets the rest plane
// at t = (level - y0) / dy.
TEST(WaterPick, TheRayThroughAPixelMeetsFlatWaterWhereTheClosedFormSays) {
  const scene::Water water = defaultWater();
  scene::Camera camera;
  camera.position = {0.4f, 3.0f, 4.0f};
  camera.target = {-0.2f, water.level, 0.3f};
  camera.fovYDegrees = 50.0f;
  constexpr uint32_t kW = 161, kH = 91;
  const glm::dvec3 eye(camera.position);
  const glm::dvec3 forward = glm::normalize(glm::dvec3(camera.target) - eye);
  const glm::dvec3 right = glm::normalize(glm::cross(forward, glm::dvec3(camera.up)));
  const glm::dvec3 up = glm::cross(right, forward);
  const double tanHalf = std::tan(double(camera.fovYDegrees) * std::numbers::pi / 360.0), aspect = double(kW) / kH;
  const sim::WaterState flat = sim::flatState(water.grid);
  // A grid of points over the frame, pixel centres and corners: those whose
  // closed-form crossing lies inside the square hit there; the rest (the
  // square is 4 m wide, this view sees beyond it) meet nothing.
  int hits = 0, misses = 0;
  for (double py = 0.5; py < kH; py += 6.25) {
    for (double px = 0.0; px < kW; px += 7.5) {
      const glm::dvec2 pixel(px, py);
      const glm::dvec2 ndc = 2.0 * pixel / glm::dvec2(kW, kH) - 1.0;
      const glm::dvec3 direction =
          glm::normalize(forward + right * (tanHalf * aspect * ndc.x) - up * (tanHalf * ndc.y));
      const Ray ray = app::pixelRay(camera, kW, kH, pixel);
      EXPECT_EQ(ray.origin, eye);
      EXPECT_NEAR(glm::length(ray.direction - direction), 0.0, 1e-6) << px << "," << py;
      const glm::dvec3 expected = eye + direction * ((double(water.level) - eye.y) / direction.y);
      const auto hit = app::pickWater(ray, water, &flat);
      const double half = 0.5 * water.extent;
      if (std::abs(std::abs(expected.x) - half) < 1e-3 || std::abs(std::abs(expected.z) - half) < 1e-3) continue;
      if (std::abs(expected.x) > half || std::abs(expected.z) > half) {
        EXPECT_FALSE(hit) << px << "," << py;
        ++misses;
        continue;
      }
      ASSERT_TRUE(hit) << px << "," << py;
      ++hits;
      EXPECT_NEAR(glm::length(*hit - expected), 0.0, 1e-5) << px << "," << py;
      // And back: the hit projects to the point it came from.
      EXPECT_NEAR(glm::length(app::worldToPixel(camera, kW, kH, *hit) - pixel), 0.0, 1e-3);
    }
  }
  EXPECT_GT(hits, 50);
  EXPECT_GT(misses, 50);
  // The centre of an odd-sized frame looks at the target.
  const auto centre = app::pickWater(app::pixelRay(camera, kW, kH, {kW / 2.0, kH / 2.0}), water, &flat);
  ASSERT_TRUE(centre);
  EXPECT_NEAR(glm::length(*centre - glm::dvec3(camera.target)), 0.0, 1e-5);
}

// Linear interpolation reproduces a plane: the hit on u = a x + c z + b is
// the ray's crossing of y = level + a x + c z + b,
// t = (level + b + a x0 + c z0 - y0) / (dy - a dx - c dz), to the float
// rounding of the stored heights (measured: 3.8e-9 m at most).
TEST(WaterPick, ATiltedPlaneIsHitWhereTheClosedFormSays) {
  const scene::Water water = defaultWater();
  for (const glm::dvec3 plane :
       {glm::dvec3(0.08, 0.0, 0.02), glm::dvec3(0.0, -0.11, 0.03), glm::dvec3(0.05, 0.07, -0.01)}) {
    const double a = plane.x, c = plane.y, b = plane.z;
    const sim::WaterState state = planeState(water, a, c, b);
    for (const Ray ray : {towards({3.2, 2.4, 4.6}, {-0.3, -0.15, 0.4}), towards({-2.5, 0.5, 0.1}, {1.0, -0.2, -0.6}),
                          towards({0.3, 1.0, -0.2}, {0.31, -1.0, -0.22})}) {
      const double t = (double(water.level) + b + a * ray.origin.x + c * ray.origin.z - ray.origin.y) /
                       (ray.direction.y - a * ray.direction.x - c * ray.direction.z);
      const auto hit = app::pickWater(ray, water, &state);
      ASSERT_TRUE(hit);
      EXPECT_NEAR(glm::length(*hit - ray.at(t)), 0.0, 1e-6) << a << " " << c << " " << b;
    }
  }
}

// A raised-cosine drop A (1 + cos(pi r / R)) / 2 stands in the way of a
// horizontal ray at 0.4 A above the rest level, which meets it where the
// bump is 0.4 A high: r = R acos(-0.2) / pi, in front of the centre.
// Interpolating linearly between cell centres costs up to about h^2/8 times
// the curvature (measured error: 2.8e-4 m; h = 3.1 cm).
TEST(WaterPick, AGrazingRayStopsAtTheFirstCrest) {
  const scene::Water water = defaultWater();
  constexpr double kA = 0.2, kR = 0.5;
  sim::WaterState state = sim::flatState(water.grid);
  sim::addDrop(state, water.extent, 0.5 * water.extent, 0.5 * water.extent, kR, kA);  // centred on the origin
  const double height = double(water.level) + 0.4 * kA;
  const Ray ray{{-1.9, height, 0.0}, {1.0, 0.0, 0.0}};
  const auto hit = app::pickWater(ray, water, &state);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->x, -kR * std::acos(-0.2) / std::numbers::pi, 2e-3);
  EXPECT_NEAR(hit->y, height, 1e-9);
  EXPECT_EQ(hit->z, 0.0);
  // Just over the crest, the ray passes.
  EXPECT_FALSE(app::pickWater(Ray{{-1.9, double(water.level) + 1.01 * kA, 0.0}, {1.0, 0.0, 0.0}}, water, &state));
}

TEST(WaterPick, RaysThatMissTheSquareOrPointUpMeetNothing) {
  const scene::Water water = defaultWater();  // the square |x|, |z| < 2
  const sim::WaterState flat = sim::flatState(water.grid);
  for (const sim::WaterState* state : {&flat, static_cast<const sim::WaterState*>(nullptr)}) {
    EXPECT_FALSE(app::pickWater(towards({0.0, 2.0, 0.0}, {0.0, 3.0, 0.5}), water, state));    // up
    EXPECT_FALSE(app::pickWater(towards({0.0, 2.0, 0.0}, {2.5, -0.15, 0.0}), water, state));  // beyond the edge
    EXPECT_FALSE(app::pickWater(Ray{{3.0, 2.0, 0.0}, {0.0, -1.0, 0.0}}, water, state));       // beside the square
    EXPECT_FALSE(app::pickWater(Ray{{0.0, 1.0, 0.0}, {1.0, 0.0, 0.0}}, water, state));        // level, above
    EXPECT_FALSE(app::pickWater(towards({5.0, 1.0, 5.0}, {9.0, -0.15, 9.0}), water, state));  // away from it
  }
}

TEST(WaterPick, ARayFromUnderTheWaterMeetsTheSurfaceFromBelow) {
  const scene::Water water = defaultWater();
  const sim::WaterState flat = sim::flatState(water.grid);
  const auto hit = app::pickWater(Ray{{0.5, -0.6, -0.25}, {0.0, 1.0, 0.0}}, water, &flat);
  ASSERT_TRUE(hit);
  EXPECT_EQ(*hit, glm::dvec3(0.5, double(water.level), -0.25));
}

// |o + t d - c| = r: t = -b -+ sqrt(b^2 - |o - c|^2 + r^2), b = d.(o - c).
TEST(WaterPick, RaySphereMatchesTheClosedForm) {
  const Ray ray{{0.0, 0.0, -5.0}, {0.0, 0.0, 1.0}};
  // The axis passes 0.5 from the centre: the chord's near end at 5 - sqrt(1 - 0.25).
  EXPECT_NEAR(*app::raySphere(ray, {0.3, 0.4, 0.0}, 1.0), 5.0 - std::sqrt(0.75), 1e-12);
  EXPECT_FALSE(app::raySphere(ray, {2.0, 0.0, 0.0}, 1.0));               // passes beside it
  EXPECT_FALSE(app::raySphere(ray, {0.0, 0.0, -9.0}, 1.0));              // behind the origin
  EXPECT_NEAR(*app::raySphere(ray, {0.0, 0.0, -5.0}, 0.7), 0.7, 1e-12);  // from inside: the far side
  // A slanted ray, against the closed form in full.
  const Ray slanted = towards({1.0, 2.0, 3.0}, {-0.5, 0.1, 0.2});
  const glm::dvec3 centre(-0.2, 0.3, 0.5);
  const double b = glm::dot(slanted.direction, slanted.origin - centre);
  const double t = -b - std::sqrt(b * b - glm::dot(slanted.origin - centre, slanted.origin - centre) + 0.36);
  EXPECT_NEAR(*app::raySphere(slanted, centre, 0.6), t, 1e-12);
  EXPECT_NEAR(glm::length(slanted.at(t) - centre), 0.6, 1e-12);

  // pickSphere takes the nearest of those hit.
  std::vector<scene::Sphere> spheres(3);
  spheres[0].center = {0.0f, 0.0f, 3.0f};
  spheres[0].radius = 0.5f;
  spheres[1].center = {0.1f, 0.0f, 0.0f};
  spheres[1].radius = 0.5f;
  spheres[2].center = {4.0f, 0.0f, -2.0f};
  spheres[2].radius = 1.0f;
  const auto picked = app::pickSphere(ray, spheres);
  ASSERT_TRUE(picked);
  EXPECT_EQ(picked->index, 1u);
  EXPECT_NEAR(picked->t, 5.0 - std::sqrt(0.25 - 0.01), 1e-7);
  EXPECT_FALSE(app::pickSphere(Ray{{0.0, 5.0, 0.0}, {0.0, 1.0, 0.0}}, spheres));
}

TEST(WaterPick, RayPlaneMeetsTheHorizontalPlaneAtItsHeight) {
  const Ray ray = towards({1.0, 2.0, 3.0}, {0.0, 0.0, 0.0});
  const auto hit = app::rayPlaneY(ray, -0.25, 100.0);
  ASSERT_TRUE(hit);
  EXPECT_EQ(hit->y, -0.25);
  // 2.25 / 2 of the way from (1, 2, 3) to the origin.
  EXPECT_NEAR(hit->x, 1.0 * (1.0 - 2.25 / 2.0), 1e-12);
  EXPECT_NEAR(hit->z, 3.0 * (1.0 - 2.25 / 2.0), 1e-12);
  EXPECT_FALSE(app::rayPlaneY(ray, 2.5, 100.0));                                    // behind
  EXPECT_FALSE(app::rayPlaneY(ray, -0.25, 1.0));                                    // beyond the distance
  EXPECT_FALSE(app::rayPlaneY(Ray{{0.0, 1.0, 0.0}, {1.0, 0.0, 0.0}}, 0.0, 100.0));  // parallel
}

}  // namespace tp::test
