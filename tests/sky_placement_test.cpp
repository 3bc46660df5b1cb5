// sky.rotation and sky.intensity (render/sky_image.cpp placeSkyImage): an
// image sky turned about the vertical and scaled, against closed forms.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/constants.hpp>

#include "env_skies.hpp"
#include "io/image_io.hpp"
#include "process.hpp"
#include "render/sky_image.hpp"
#include "scene/scene.hpp"
#include "shading/frame_uniforms.hpp"

namespace tp::test {
namespace {

// d turned by `degrees` about +y, from +x towards +z.
glm::vec3 turned(glm::vec3 d, float degrees) {
  const float a = glm::radians(degrees), c = std::cos(a), s = std::sin(a);
  return {c * d.x - s * d.z, d.y, s * d.x + c * d.z};
}

// A sky with a different value at every texel, no symmetry to hide a turn.
render::SkyImage patternedSky(uint32_t w, uint32_t h) {
  render::SkyImage image{w, h, std::vector<glm::vec4>(size_t(w) * h)};
  for (uint32_t j = 0; j < h; ++j) {
    for (uint32_t i = 0; i < w; ++i) {
      image.texels[size_t(j) * w + i] =
          glm::vec4(float(i) + 0.5f * std::sin(float(j)), float(j), float(i * j % 7), 1.0f);
    }
  }
  return image;
}

}  // namespace

// A turn by whole texels: what the original shows along d, the turned sky
// shows along d turned, and the disc sky's sun moves by the same azimuth.
TEST(SkyPlacement, WholeTexelTurnMovesEveryDirectionByTheAngle) {
  const render::SkyImage sky = patternedSky(64, 32);
  for (const float degrees : {90.0f, -45.0f, 5.625f, 360.0f}) {  // 16, -8, 1 and 64 texels
    const render::SkyImage placed = render::placeSkyImage(sky, degrees, 1.0f);
    for (const glm::vec3 d : {glm::vec3(1, 0.2f, 0.3f), glm::vec3(-0.4f, 0.7f, 0.1f), glm::vec3(0.2f, -0.5f, -0.9f)}) {
      const glm::vec3 n = glm::normalize(d);
      const glm::vec3 expected = render::skyImageRadiance(sky, n);
      const glm::vec3 got = render::skyImageRadiance(placed, turned(n, degrees));
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], expected[c], 1e-3f * (1.0f + std::abs(expected[c]))) << degrees;
    }
  }
  // The sun of discSky stands at azimuth 0; turned by 90 degrees it stands towards +z.
  const render::SkyImage sun = render::placeSkyImage(discSky(256, 128, 1.0f, 100.0f), 90.0f, 1.0f);
  const float up = glm::radians(40.0f);
  EXPECT_FLOAT_EQ(render::skyImageRadiance(sun, {0.0f, std::sin(up), std::cos(up)}).x, 100.0f);
  EXPECT_FLOAT_EQ(render::skyImageRadiance(sun, {std::cos(up), std::sin(up), 0.0f}).x, 1.0f);
}

// A fractional turn of a sky that is linear along u: linear interpolation
// of a linear function is exact, so each texel holds its column less the shift.
TEST(SkyPlacement, FractionalTurnOfALinearSkyIsExact) {
  const uint32_t w = 360, h = 4;
  render::SkyImage ramp{w, h, std::vector<glm::vec4>(size_t(w) * h)};
  for (uint32_t j = 0; j < h; ++j) {
    for (uint32_t i = 0; i < w; ++i) ramp.texels[size_t(j) * w + i] = glm::vec4(float(i), 0.0f, 0.0f, 1.0f);
  }
  const float degrees = 10.25f;  // 10.25 texels of one degree
  const render::SkyImage placed = render::placeSkyImage(ramp, degrees, 3.0f);
  for (uint32_t i = 20; i < w; ++i) {  // away from the wrap, where the ramp jumps
    EXPECT_NEAR(placed.texels[i].x, 3.0f * (float(i) - degrees), 1e-3f) << i;
  }
}

// Intensity scales the radiance and the irradiance it makes, nothing else.
TEST(SkyPlacement, IntensityScalesRadianceAndIrradiance) {
  const render::SkyImage sky = discSky(64, 32, 0.5f, 40.0f);
  const render::SkyImage twice = render::placeSkyImage(sky, 0.0f, 2.0f);
  for (size_t k = 0; k < sky.texels.size(); ++k)
    EXPECT_EQ(twice.texels[k], glm::vec4(glm::vec3(sky.texels[k]) * 2.0f, 1.0f));
  scene::Scene s = scene::defaultScene();
  s.sky.image = "sky.exr";  // an image sky: no sun, the ground lit by the image alone
  const render::SkyLight once = render::sceneLight(s, [&](glm::vec3 d) { return render::skyImageRadiance(sky, d); });
  const render::SkyLight doubled =
      render::sceneLight(s, [&](glm::vec3 d) { return render::skyImageRadiance(twice, d); });
  for (int k = 0; k < shader::kSkyIrradianceTerms; ++k) {
    for (int c = 0; c < 3; ++c) {
      const float one = once.irradiance.c[k][c];
      EXPECT_NEAR(doubled.irradiance.c[k][c], 2.0f * one, 1e-4f * (1.0f + std::abs(one)));
    }
  }
}

TEST(SkyPlacement, KeysBelongToAnImageSky) {
  scene::Scene s = scene::defaultScene();
  s.sky.rotationDegrees = 30.0f;
  EXPECT_THROW(scene::validateScene(s), std::runtime_error);
  s.sky.rotationDegrees = 0.0f;
  s.sky.intensity = 2.0f;
  EXPECT_THROW(scene::validateScene(s), std::runtime_error);
  s.sky.image = "sky.exr";
  EXPECT_NO_THROW(scene::validateScene(s));
  s.sky.intensity = -1.0f;
  EXPECT_THROW(scene::validateScene(s), std::runtime_error);
}

// End to end: the frame's sky pixels under an image sky scaled by 2 are
// twice those under the image itself, in the raster and in the reference.
TEST(SkyPlacement, RenderedSkyFollowsTheIntensity) {
  ScratchDir dir;
  const render::SkyImage sky = discSky(64, 32, 0.5f, 40.0f);
  io::FloatImage file{sky.width, sky.height, {"R", "G", "B"}, {}};
  for (const glm::vec4& t : sky.texels) file.pixels.insert(file.pixels.end(), {t.x, t.y, t.z});
  io::writeExr(dir.file("sky.exr"), file, std::vector<io::PixelType>(3, io::PixelType::Float));
  // Looking up at the sky only: every pixel is sky.
  const std::string view = "render --size 32x16 --float --set sky.image=" + dir.file("sky.exr") +
                           " --set camera.target=[4.2,4.4,4.6] --set water.enabled=false --validate";
  for (const char* mode : {"", " --reference --samples 1"}) {
    ASSERT_EQ(runTidepool(view + mode + " --out " + dir.file("once.exr"), dir).exitCode, 0) << mode;
    const ProcessResult r = runTidepool(view + mode + " --set sky.intensity=2 --out " + dir.file("twice.exr"), dir);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const io::FloatImage once = io::readImage(dir.file("once.exr")), twice = io::readImage(dir.file("twice.exr"));
    double sum = 0.0;
    for (size_t k = 0; k < once.pixels.size(); ++k) {
      if (k % 4 == 3) continue;  // alpha
      EXPECT_NEAR(twice.pixels[k], 2.0f * once.pixels[k], 1e-4f * (1.0f + once.pixels[k])) << mode << " " << k;
      sum += once.pixels[k];
    }
    EXPECT_GT(sum, 0.0) << mode;
  }
}

}  // namespace tp::test
