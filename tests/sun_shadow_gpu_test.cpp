// The raster's sun shadows as a camera sees them: a sphere's shadow on the
// ground, seen from straight above, measured from the frames alone (the
// share of the sun's light each pixel lost) against its closed form.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <glm/gtc/constants.hpp>

#include "gpu_test.hpp"
#include "render/renderer.hpp"
#include "shading/sky_model.hpp"

namespace tp::test {
namespace {

constexpr uint32_t kSide = 256;

// Open ground, no water, no AO, a camera straight above the origin.
scene::Scene groundFromAbove() {
  scene::Scene s = scene::defaultScene();
  s.water.enabled = false;
  s.ao.enabled = false;
  s.boxes.clear();
  s.spheres.clear();
  s.sky.sunElevationDegrees = 50.0f;
  s.sky.sunAzimuthDegrees = 60.0f;
  s.camera.position = {0.0f, 8.0f, 0.0f};
  s.camera.target = {0.0f, 0.0f, 0.0f};
  s.camera.up = {0.0f, 0.0f, -1.0f};
  s.camera.fovYDegrees = 30.0f;
  return s;
}

std::vector<float> luminance(const gpu::Context& ctx, const scene::Scene& s) {
  render::Renderer renderer(ctx, s, kSide, kSide);
  const auto rgba = renderer.render({.frame = 0}).rgba;
  std::vector<float> y(kSide * kSide);
  for (size_t p = 0; p < y.size(); ++p)
    y[p] = 0.2126f * rgba[p * 4] + 0.7152f * rgba[p * 4 + 1] + 0.0722f * rgba[p * 4 + 2];
  return y;
}

}  // namespace

class SunShadowGpuTest : public GpuTest {};

// Each pixel's lost share of the sun, (open - shadowed) / (open - no sun),
// summed over the ground: the ellipse's area pi r^2 / sin(elevation), centred
// where the sun's ray through the sphere's centre meets the ground. The
// pixels where the sphere itself is seen are left out (it stands clear of
// its shadow here).
TEST_F(SunShadowGpuTest, ASpheresShadowOnTheGroundHasTheEllipsesAreaAndCentre) {
  const scene::Scene open = groundFromAbove();
  scene::Scene shadowed = open, sunless = open, sunlessShadowed = open;
  const scene::Sphere sphere{.center = {0.0f, 1.2f, 0.0f}, .radius = 0.4f};
  shadowed.spheres = sunlessShadowed.spheres = {sphere};
  sunless.sky.sunRadiance = sunlessShadowed.sky.sunRadiance = glm::vec3(0.0f);
  const auto a = luminance(ctx(), open), b = luminance(ctx(), shadowed), noSun = luminance(ctx(), sunless),
             noSunSphere = luminance(ctx(), sunlessShadowed);
  // The ground each pixel covers, in metres, and where its centre is.
  const double side = 2.0 * 8.0 * std::tan(glm::radians(15.0)), cell = side / kSide;
  double area = 0.0, x = 0.0, z = 0.0;
  for (uint32_t i = 0; i < kSide; ++i) {
    for (uint32_t j = 0; j < kSide; ++j) {
      const size_t p = size_t(i) * kSide + j;
      if (std::abs(noSunSphere[p] - noSun[p]) > 1e-4f * noSun[p]) continue;  // the sphere, not the ground
      const double lost = (a[p] - b[p]) / (a[p] - noSun[p]);
      // Image x is world +x; image rows run down the image, world +z (up is -z).
      const double wx = (j + 0.5) * cell - side / 2, wz = (i + 0.5) * cell - side / 2;
      area += lost * cell * cell;
      x += lost * wx * cell * cell;
      z += lost * wz * cell * cell;
    }
  }
  const glm::vec3 toSun = render::sunDirection(open.sky);
  const double expected = glm::pi<double>() * 0.4 * 0.4 / std::sin(glm::radians(50.0));
  const double cx = -1.2 * toSun.x / toSun.y, cz = -1.2 * toSun.z / toSun.y;
  std::printf("shadow area %.4f m^2 (closed form %.4f), centre (%.3f, %.3f) (closed form (%.3f, %.3f))\n", area,
              expected, x / area, z / area, cx, cz);
  EXPECT_NEAR(area / expected, 1.0, 0.02);
  EXPECT_LT(std::hypot(x / area - cx, z / area - cz), 0.02);
}

}  // namespace tp::test

namespace tp::test {

// The surfaces' variants without the shadows' code (render.shadows off, or
// nothing to cast one) draw what the shadows' variants draw where no shadow
// falls, to the bit: here the one sphere stands behind the camera and its
// shadow falls out of view. Where a shadow is seen, the two differ.
TEST_F(SunShadowGpuTest, TheVariantWithoutShadowsDrawsTheSameBitsWhereNoShadowFalls) {
  scene::Scene s = scene::defaultScene();
  s.water.enabled = false;  // no pool: the sphere is the only caster
  s.ao.enabled = false;
  s.spheres = {{.center = {8.0f, 0.5f, 12.0f}, .radius = 0.5f}};  // behind the camera
  scene::Scene off = s;
  off.render.shadows = false;
  render::Renderer a(ctx(), s, 160, 90), b(ctx(), off, 160, 90);
  const auto on = a.render({.frame = 0}).rgba, without = b.render({.frame = 0}).rgba;
  EXPECT_EQ(std::memcmp(on.data(), without.data(), on.size() * sizeof(float)), 0);

  s.spheres = {{.center = {0.0f, 1.0f, 0.0f}, .radius = 0.5f}};  // in view, its shadow too
  off.spheres = s.spheres;
  render::Renderer c(ctx(), s, 160, 90), d(ctx(), off, 160, 90);
  const auto shadowed = c.render({.frame = 0}).rgba, unshadowed = d.render({.frame = 0}).rgba;
  size_t darker = 0;
  for (size_t p = 0; p < shadowed.size() / 4; ++p) darker += shadowed[p * 4 + 1] < 0.9f * unshadowed[p * 4 + 1];
  EXPECT_GT(darker, 20u);  // measured 54: the shadow falls partly behind the sphere
}

}  // namespace tp::test
