// A glass ball's shadow and caustic on the ground in the raster (its table,
// shading/glass_caustic) against the path-traced truth, which refracts the
// sun's light through the ball itself. Sun only, the sky black: each pixel's
// light over that of the open ground is the share of the sun the ball left
// it, in the raster and in the truth alike.
//
// The truth reaches the focused sun only by paths that leave the ground,
// pass the ball and meet the sun's disc: a few per pixel in thousands. So
// the shares are compared as means over rings about the shadow's axis, each
// of 50 to 700 pixels, against the truth's noise there.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <glm/gtc/constants.hpp>
#include <optional>

#include "gpu_test.hpp"
#include "reference/path_tracer.hpp"
#include "render/renderer.hpp"
#include "shading/sky_model.hpp"
#include "shared/shadow_casters.h"

namespace tp::test {
namespace {

constexpr uint32_t kSide = 96;
constexpr uint32_t kPaths = 8192;     // the truth's per pixel, with the ball
constexpr uint32_t kOpenPaths = 64;   // and without: the open sun, one shadow ray a path
constexpr int kRings = 8;             // over TP_GLASS_TABLE_REACH radii from the axis
constexpr uint32_t kBoxPaths = 2048;  // the truth's per pixel, with a glass box

// A ball of index 1.5 whose centre stands 2.5 radii before the ground along
// the sun: past its paraxial focus (1.5 radii), in its caustic.
const scene::Sphere kBall{.center = {0.0f, 1.133f, 0.0f}, .radius = 0.5f, .material = "glass", .ior = 1.5f};

// The open ground lit by the sun alone, seen from the side away from the
// sun, where the ball does not hide its own shadow; the ball, if `ball`.
scene::Scene sunOnly(bool ball) {
  scene::Scene s = scene::defaultScene();
  s.water.enabled = false;
  s.ao.enabled = false;
  s.boxes.clear();
  s.spheres.clear();
  if (ball) s.spheres = {kBall};
  s.sky.sunElevationDegrees = 65.0f;
  s.sky.zenith = s.sky.horizon = s.sky.ground = s.sky.glow = glm::vec3(0.0f);
  s.sky.clouds.coverage = 0.0f;
  s.sky.hazeDistance = 0.0f;
  s.ground.albedoA = s.ground.albedoB = glm::vec3(0.5f);
  const glm::vec3 toSun = render::sunDirection(s.sky);
  const glm::vec3 centre = kBall.center - toSun * (kBall.center.y / toSun.y);
  const glm::vec3 away = -glm::normalize(glm::vec3(toSun.x, 0.0f, toSun.z));
  s.camera.position = centre + 3.0f * away + glm::vec3(0.0f, 5.0f, 0.0f);
  s.camera.target = centre;
  s.camera.fovYDegrees = 28.0f;
  return s;
}

std::vector<double> luminance(const render::RenderedFrame& f) {
  std::vector<double> y(size_t(f.width) * f.height);
  for (size_t p = 0; p < y.size(); ++p)
    y[p] = 0.2126 * f.rgba[p * 4] + 0.7152 * f.rgba[p * 4 + 1] + 0.0722 * f.rgba[p * 4 + 2];
  return y;
}

// Where pixel (i, j)'s central ray meets the ground, or nothing where it
// passes near the ball (the ball is seen there, not the ground).
std::optional<glm::vec3> groundSeen(const glm::mat4& worldToNDC, uint32_t i, uint32_t j) {
  const glm::mat4 toWorld = glm::inverse(worldToNDC);
  const glm::vec2 ndc((j + 0.5f) / kSide * 2.0f - 1.0f, (i + 0.5f) / kSide * 2.0f - 1.0f);
  const glm::vec4 nearH = toWorld * glm::vec4(ndc, 0.0f, 1.0f), farH = toWorld * glm::vec4(ndc, 1.0f, 1.0f);
  const glm::vec3 from = glm::vec3(nearH) / nearH.w, d = glm::normalize(glm::vec3(farH) / farH.w - from);
  if (d.y >= 0.0f) return std::nullopt;
  const glm::vec3 c = kBall.center - from;
  if (glm::length(c - glm::dot(c, d) * d) < 1.05f * kBall.radius) return std::nullopt;
  return from + d * (-from.y / d.y);
}

// The mean share of the sun over each ring, in the raster and the truth,
// and the standard error of the truth's mean: its pixels' spread over the
// root of their number (the spread of the shares across the ring counted
// as noise too, so it errs large).
struct Rings {
  std::array<double, kRings> raster{}, truth{}, truthSquares{}, noise{};
  std::array<size_t, kRings> pixels{};
};

}  // namespace

class GlassShadowTest : public GpuTest {};

// Ring by ring within two radii of the shadow's axis, the raster's mean
// share of the sun against the truth's.
TEST_F(GlassShadowTest, RasterMatchesTheTruthsShadowAndCaustic) {
  const scene::Scene open = sunOnly(false), ball = sunOnly(true);
  render::Renderer rasterOpen(ctx(), open, kSide, kSide), rasterBall(ctx(), ball, kSide, kSide);
  const render::RenderedFrame openFrame = rasterOpen.render({.frame = 0});
  const std::vector<double> lit = luminance(openFrame), raster = luminance(rasterBall.render({.frame = 0}));
  const std::vector<double> truthOpen =
      luminance(render::renderPathTraced(open, nullptr, 0, kSide, kSide, {.samples = kOpenPaths, .seed = 1}).frame);
  const std::vector<double> truth =
      luminance(render::renderPathTraced(ball, nullptr, 0, kSide, kSide, {.samples = kPaths, .seed = 1}).frame);
  const glm::vec3 toSun = render::sunDirection(open.sky);
  Rings rings;
  for (uint32_t i = 0; i < kSide; ++i) {
    for (uint32_t j = 0; j < kSide; ++j) {
      const std::optional<glm::vec3> p = groundSeen(openFrame.worldToNDC, i, j);
      if (!p) continue;
      const glm::vec3 v = *p - kBall.center;
      const float across = glm::length(v - glm::dot(v, toSun) * toSun) / kBall.radius;
      const size_t ring = size_t(across / float(TP_GLASS_TABLE_REACH) * kRings);
      if (ring >= size_t(kRings)) continue;
      const size_t k = size_t(i) * kSide + j;
      const double share = truth[k] / truthOpen[k];
      rings.raster[ring] += raster[k] / lit[k];
      rings.truth[ring] += share;
      rings.truthSquares[ring] += share * share;
      ++rings.pixels[ring];
    }
  }
  for (size_t r = 0; r < size_t(kRings); ++r) {
    const double n = double(rings.pixels[r]);
    ASSERT_GT(n, 40.0) << "ring " << r;
    rings.raster[r] /= n;
    rings.truth[r] /= n;
    const double spread = std::sqrt(std::max(0.0, rings.truthSquares[r] / n - rings.truth[r] * rings.truth[r]));
    rings.noise[r] = spread / std::sqrt(n);
    std::printf("ring %.2f-%.2f radii, %3zu pixels: truth %.3f +- %.3f, raster %.3f\n",
                double(r) * TP_GLASS_TABLE_REACH / kRings, double(r + 1) * TP_GLASS_TABLE_REACH / kRings,
                rings.pixels[r], rings.truth[r], rings.noise[r], rings.raster[r]);
  }
  // Each ring within three standard errors of the truth; letting the sun
  // through, the rings the ball shades and focuses lie tens of them off.
  double worst = 0.0, worstThrough = 0.0;
  for (size_t r = 0; r < size_t(kRings); ++r) {
    worst = std::max(worst, std::abs(rings.raster[r] - rings.truth[r]) / rings.noise[r]);
    worstThrough = std::max(worstThrough, std::abs(1.0 - rings.truth[r]) / rings.noise[r]);
  }
  std::printf("worst ring: %.1f standard errors off with the table, %.1f letting the sun through\n", worst,
              worstThrough);
  EXPECT_LT(worst, 3.0);
  EXPECT_GT(worstThrough, 10.0);
}

// A glass box's shadow and the light it lets through (its grid,
// shading/glass_box_light) against the truth, as the ball's above but over
// blocks of 8 x 8 pixels of the ground: a box of index 1.5 (0.7 x 0.5 x
// 0.45 m, turned 30 degrees, its bottom 0.25 m over the ground) under a sun
// at 50 degrees, seen from above its shadow. Each block's mean share of the
// sun, raster against truth, within three standard errors of the truth's
// (the spread of its pixels' shares over the root of their number) and
// 0.035: the grid leaves out what the box's sides reflect past its square
// (the truth's ground there 2.5-3% over the open sun, +- 0.2%), and blurs
// the shadow's edge over its step (a block across the edge: truth 0.050 +-
// 0.032, raster 0.159). Letting the sun through is 7 allowances off.
TEST_F(GlassShadowTest, ABoxsShadowMatchesTheTruth) {
  constexpr uint32_t kBlock = 8, kBlocks = kSide / kBlock;
  auto sunOnlyBox = [](bool box) {
    scene::Scene s = sunOnly(false);
    s.sky.sunElevationDegrees = 50.0f;
    if (box)
      s.boxes = {{.center = {0.0f, 0.5f, 0.0f},
                  .size = {0.7f, 0.5f, 0.45f},
                  .yawDegrees = 30.0f,
                  .material = "glass",
                  .ior = 1.5f}};
    const glm::vec3 toSun = render::sunDirection(s.sky);
    const glm::vec3 centre = glm::vec3(0.0f, 0.5f, 0.0f) - toSun * (0.5f / toSun.y);
    s.camera.position = centre - 0.3f * glm::vec3(toSun.x, 0.0f, toSun.z) + glm::vec3(0.0f, 2.5f, 0.01f);
    s.camera.target = centre;
    s.camera.fovYDegrees = 45.0f;
    return s;
  };
  const scene::Scene open = sunOnlyBox(false), box = sunOnlyBox(true);
  render::Renderer rasterOpen(ctx(), open, kSide, kSide), rasterBox(ctx(), box, kSide, kSide);
  const std::vector<double> lit = luminance(rasterOpen.render({.frame = 0}));
  const std::vector<double> raster = luminance(rasterBox.render({.frame = 0}));
  const std::vector<double> truthOpen =
      luminance(render::renderPathTraced(open, nullptr, 0, kSide, kSide, {.samples = kOpenPaths, .seed = 1}).frame);
  const render::RenderedFrame truthFrame =
      render::renderPathTraced(box, nullptr, 0, kSide, kSide, {.samples = kBoxPaths, .seed = 1}).frame;
  const std::vector<double> truth = luminance(truthFrame);
  double worst = 0.0, worstThrough = 0.0;
  size_t blocks = 0;
  for (uint32_t bi = 0; bi < kBlocks; ++bi) {
    for (uint32_t bj = 0; bj < kBlocks; ++bj) {
      double sumRaster = 0.0, sumTruth = 0.0, squares = 0.0;
      size_t n = 0;
      for (uint32_t i = bi * kBlock; i < (bi + 1) * kBlock; ++i) {
        for (uint32_t j = bj * kBlock; j < (bj + 1) * kBlock; ++j) {
          const size_t k = size_t(i) * kSide + j;
          // The ground's own pixels: the truth's first surface on it, not on the box.
          if (std::abs(truthFrame.position[k * 4 + 1]) > 1e-3f) continue;
          const double share = truth[k] / truthOpen[k];
          sumRaster += raster[k] / lit[k];
          sumTruth += share;
          squares += share * share;
          ++n;
        }
      }
      if (n < kBlock * kBlock / 2) continue;
      const double meanRaster = sumRaster / double(n), meanTruth = sumTruth / double(n);
      const double noise = std::sqrt(std::max(0.0, squares / double(n) - meanTruth * meanTruth) / double(n));
      const double allowed = 3.0 * noise + 0.035;
      worst = std::max(worst, std::abs(meanRaster - meanTruth) / allowed);
      worstThrough = std::max(worstThrough, std::abs(1.0 - meanTruth) / allowed);
      ++blocks;
      if (std::abs(1.0 - meanTruth) > 0.1 || std::abs(meanRaster - meanTruth) > allowed)
        std::printf("block (%u, %u), %zu pixels: truth %.3f +- %.3f, raster %.3f\n", bi, bj, n, meanTruth, noise,
                    meanRaster);
    }
  }
  std::printf("%zu blocks; the worst %.2f of its allowance off with the grid, %.2f letting the sun through\n", blocks,
              worst, worstThrough);
  ASSERT_GT(blocks, size_t(kBlocks * kBlocks / 2));
  EXPECT_LT(worst, 1.0);
  EXPECT_GT(worstThrough, 3.0);
}

}  // namespace tp::test
