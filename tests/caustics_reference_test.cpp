// The reference's caustics, light-traced (reference/reference_caustics), on
// their own against closed forms, and the raster's caustics map measured
// against them through the frames both draw.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "cli/frame_samples.hpp"
#include "gpu_test.hpp"
#include "reference/reference_caustics.hpp"
#include "reference/reference_tracer.hpp"
#include "render/renderer.hpp"
#include "shading/frame_uniforms.hpp"
#include "shading/pool_model.hpp"
#include "shading/sky_model.hpp"
#include "shading/water_model.hpp"
#include "shared/objects.h"
#include "shared/shading.h"
#include "sim/water_scene.hpp"
#include "sim/water_state.hpp"

namespace tp::test {
namespace {

constexpr uint32_t kSize = 128;  // texels a side: 3.1 cm in the 4 m pool

struct Pool {
  scene::Mesh water;
  render::CausticReceivers receivers;  // the floor and the walls
  std::vector<glm::vec3> normals;
};

Pool poolOf(const scene::Scene& s, const sim::WaterState& water) {
  Pool p;
  for (auto& mesh : render::sceneMeshes(s, &water, 0.0f))
    if (mesh.name == "pool_floor" || mesh.name == "pool_walls") p.receivers.meshes.push_back(std::move(mesh));
  render::WaterToTheWalls toTheWalls = render::waterSurfaceToTheWalls(s, water);
  p.water = std::move(toTheWalls.mesh);
  p.normals = std::move(toTheWalls.normals);
  return p;
}

scene::Scene flatFloor(float sunElevation) {
  scene::Scene s = scene::defaultScene();
  s.terrain.amplitude = 0.0f;
  s.sky.sunElevationDegrees = sunElevation;
  return s;
}

}  // namespace

// Under flat water every photon lands on its own light line, on the floor or
// a wall: every texel receives exactly its share (ratio 1), with the sun
// overhead and low, to the walls.
TEST(ReferenceCaustics, FlatWaterLeavesEachLightLineItsOwnLight) {
  for (const float elevation : {90.0f, 30.0f}) {
    const scene::Scene s = flatFloor(elevation);
    const sim::WaterState flat = sim::flatState(s.water.grid);
    const Pool pool = poolOf(s, flat);
    const render::CausticsMap map = render::traceCaustics(s, pool.water, pool.normals, pool.receivers, kSize);
    size_t exact = 0, checked = 0;
    for (uint32_t z = 0; z < kSize; ++z) {
      for (uint32_t x = 0; x < kSize; ++x) {
        ++checked;
        exact += map.ratio[size_t(z) * kSize + x] == 1.0f;
      }
    }
    std::printf("sun at %.0f degrees: %zu of %zu texels exactly 1\n", elevation, exact, checked);
    EXPECT_EQ(exact, checked);
  }
}

// Under waves the light gathers and spreads; the water neither makes nor
// loses it: the mean over the light lines stays 1.
TEST(ReferenceCaustics, WavesGatherLightWithoutMakingOrLosingIt) {
  scene::Scene s = flatFloor(90.0f);
  const sim::WaterState water = sim::waterInitialState(s.water);  // the default scene's three drops
  const Pool pool = poolOf(s, water);
  const render::CausticsMap map = render::traceCaustics(s, pool.water, pool.normals, pool.receivers, kSize);
  double sum = 0.0;
  size_t n = 0;
  float lo = 1e30f, hi = 0.0f;
  for (uint32_t z = 0; z < kSize; ++z) {
    for (uint32_t x = 0; x < kSize; ++x) {
      const float r = map.ratio[size_t(z) * kSize + x];
      sum += r;
      ++n;
      lo = std::min(lo, r);
      hi = std::max(hi, r);
    }
  }
  std::printf("light-traced caustics under the drops: mean %.4f, min %.3f, max %.3f\n", sum / double(n), lo, hi);
  EXPECT_NEAR(sum / double(n), 1.0, 0.01);
  EXPECT_GT(hi, 1.3f);
  EXPECT_LT(lo, 0.8f);
}

class CausticsReferenceGpuTest : public GpuTest {};

// The default pool without AO or objects, lit by the sun alone.
scene::Scene sunlitPool() {
  scene::Scene s = scene::defaultScene();
  s.ao.enabled = false;
  s.spheres.clear();
  s.boxes.clear();
  s.sky.zenith = s.sky.horizon = s.sky.glow = glm::vec3(0.0f);
  return s;
}

// Each pixel's caustics ratio, by the raster or the reference at 16 samples,
// lit by the sun alone: the frame with caustics over the frame without, in
// green (the least absorbed), -1 where the frame without is dark. With
// `position`, the reference's first surfaces (its position AOV).
std::vector<float> causticsRatios(const gpu::Context& ctx, const scene::Scene& scene, const sim::WaterState& water,
                                  uint32_t frame, uint32_t width, uint32_t height, bool reference,
                                  std::vector<float>* position = nullptr) {
  scene::Scene on = scene, off = scene;
  on.render.caustics = true;
  off.render.caustics = false;
  std::vector<float> a, b;
  if (reference) {
    render::RenderedFrame withCaustics = render::renderReference(on, &water, frame, width, height, {.samples = 16});
    a = std::move(withCaustics.rgba);
    if (position) *position = std::move(withCaustics.position);
    b = render::renderReference(off, &water, frame, width, height, {.samples = 16}).rgba;
  } else {
    render::Renderer ra(ctx, on, width, height), rb(ctx, off, width, height);
    a = app::renderSamples(ra, {.frame = frame}, 16).rgba;
    b = app::renderSamples(rb, {.frame = frame}, 16).rgba;
  }
  std::vector<float> r(size_t(width) * height, -1.0f);
  for (size_t p = 0; p < r.size(); ++p)
    if (b[p * 4 + 1] > 1e-3f) r[p] = a[p * 4 + 1] / b[p * 4 + 1];
  return r;
}

// The raster's caustics map against the light-traced caustics, in frames
// lit by the sun alone: each renderer's frame with caustics over its frame
// without (the refraction and the absorption cancel) is the caustics ratio
// where the eye meets the pool through the water. Seen from straight above
// the floor, and from a corner: the floor, two walls, a box and a sphere.
TEST_F(CausticsReferenceGpuTest, RasterCausticsMatchTheLightTracedOnes) {
  constexpr uint32_t kWidth = 160, kHeight = 160, kFrame = 10;
  scene::Scene terrain = sunlitPool();
  terrain.sky.sunElevationDegrees = 65.0f;
  terrain.camera.position = {0.0f, 3.0f, 0.0f};
  terrain.camera.target = {0.0f, -1.0f, 0.0f};
  terrain.camera.up = {0.0f, 0.0f, -1.0f};
  terrain.camera.fovYDegrees = 40.0f;
  scene::Scene flat = terrain;
  flat.terrain.amplitude = 0.0f;
  // The sun from +x +z lights the walls at x = -2 and z = -2, which the corner sees.
  scene::Scene corner = terrain;
  corner.sky.sunElevationDegrees = 50.0f;
  corner.sky.sunAzimuthDegrees = 45.0f;
  corner.camera.position = {1.6f, 1.0f, 1.6f};
  corner.camera.target = {-1.5f, -0.9f, -1.5f};
  corner.camera.up = {0.0f, 1.0f, 0.0f};
  corner.camera.fovYDegrees = 60.0f;
  corner.boxes = {{.center = {-1.0f, -0.95f, -0.5f}, .size = {0.5f, 0.5f, 0.5f}}};
  corner.spheres = {{.center = {-0.4f, -0.85f, -1.3f}, .radius = 0.3f}};
  // From under the surface, as scenes/underwater.json: the floor, the walls,
  // a box and a sphere seen directly through the water.
  scene::Scene under = corner;
  under.camera.position = {-1.4f, -0.75f, 1.5f};
  under.camera.target = {0.9f, -0.2f, -0.7f};
  under.camera.fovYDegrees = 70.0f;
  under.spheres = {{.center = {0.6f, -0.8f, -0.6f}, .radius = 0.35f}};
  under.boxes = {{.center = {-0.6f, -0.9f, -1.0f}, .size = {0.6f, 0.6f, 0.6f}, .yawDegrees = 30.0f}};
  struct Case {
    const char* name;
    scene::Scene scene;
    double bound;
  };
  for (const Case& c : {Case{"from above, over the terrain", terrain, 0.04}, Case{"from above, flat floor", flat, 0.04},
                        Case{"from a corner: floor, walls, box, sphere", corner, 0.1},
                        Case{"from under the surface: floor, walls, box, sphere", under, 0.1}}) {
    const sim::WaterState water = sim::simulateWater(ctx(), c.scene, kFrame);
    // The pixels whose centre's ray meets the water's rest level inside the
    // pool, or all of them from under the surface.
    const bool cameraUnder = c.scene.camera.position.y < c.scene.water.level;
    const shader::FrameUniforms u = render::frameUniforms(c.scene, kWidth, kHeight);
    std::vector<bool> pool(size_t(kWidth) * kHeight);
    for (uint32_t y = 0; y < kHeight; ++y) {
      for (uint32_t x = 0; x < kWidth; ++x) {
        const glm::vec4 near =
            u.inverseViewProjection *
            glm::vec4(2.0f * (float(x) + 0.5f) / kWidth - 1.0f, 2.0f * (float(y) + 0.5f) / kHeight - 1.0f, 0.0f, 1.0f);
        const glm::vec3 o = glm::vec3(near) / near.w, d = glm::normalize(o - c.scene.camera.position);
        const glm::vec3 at = o + d * ((c.scene.water.level - o.y) / d.y);
        pool[size_t(y) * kWidth + x] =
            cameraUnder || (d.y < 0.0f && std::max(std::abs(at.x), std::abs(at.z)) < 0.5f * c.scene.water.extent);
      }
    }
    // The pixels whose first surface, seen directly, is the sphere or the box
    // (the reference's position AOV): from under the surface, what the
    // objects' own pass draws.
    std::vector<bool> object(size_t(kWidth) * kHeight);
    auto ratios = [&](bool reference) {
      std::vector<float> position;
      std::vector<float> r =
          causticsRatios(ctx(), c.scene, water, kFrame, kWidth, kHeight, reference, reference ? &position : nullptr);
      for (size_t p = 0; p < r.size(); ++p) {
        if (!pool[p]) r[p] = -1.0f;
        if (!reference) continue;
        const glm::vec3 at(position[p * 4], position[p * 4 + 1], position[p * 4 + 2]);
        for (const auto& s : c.scene.spheres) object[p] = object[p] || glm::distance(at, s.center) < s.radius + 1e-3f;
        for (const auto& box : c.scene.boxes) {
          const float yaw = glm::radians(box.yawDegrees);
          const glm::vec3 rel = at - box.center;
          const glm::vec3 local(glm::dot(rel, shader::boxAxisX(yaw)), rel.y, glm::dot(rel, shader::boxAxisZ(yaw)));
          object[p] = object[p] || glm::all(glm::lessThan(glm::abs(local), 0.5f * box.size + 1e-3f));
        }
      }
      return r;
    };
    const auto raster = ratios(false), reference = ratios(true);
    double diff = 0.0, meanRaster = 0.0, meanReference = 0.0;
    size_t n = 0;
    for (size_t p = 0; p < raster.size(); ++p) {
      if (raster[p] < 0.0f || reference[p] < 0.0f) continue;
      diff += (raster[p] - reference[p]) * (raster[p] - reference[p]);
      meanRaster += raster[p];
      meanReference += reference[p];
      ++n;
    }
    const double rmse = std::sqrt(diff / double(n));
    std::printf("caustics ratio %s, %zu pixels: raster mean %.4f, light-traced mean %.4f, RMSE %.4f\n", c.name, n,
                meanRaster / double(n), meanReference / double(n), rmse);
    if (cameraUnder) {
      double objectDiff = 0.0;
      size_t objectPixels = 0;
      for (size_t p = 0; p < raster.size(); ++p) {
        if (!object[p] || raster[p] < 0.0f || reference[p] < 0.0f) continue;
        objectDiff += (raster[p] - reference[p]) * (raster[p] - reference[p]);
        ++objectPixels;
      }
      const double objectRmse = std::sqrt(objectDiff / double(objectPixels));
      std::printf("  on the %zu pixels of the objects seen directly: RMSE %.4f\n", objectPixels, objectRmse);
      EXPECT_GT(objectPixels, size_t(kWidth * kHeight / 50));
      EXPECT_LT(objectRmse, c.bound);
    }
    EXPECT_GT(n, size_t(kWidth * kHeight / 4)) << c.name;
    EXPECT_NEAR(meanRaster / double(n), meanReference / double(n), 0.02) << c.name;
    EXPECT_LT(rmse, c.bound) << c.name;
  }
}

// Where the water stands below its rest level at a lit wall, the wall
// between the two is in the air, in the whole sun. The caustics' mesh once
// stopped half a cell short of the walls, and the lines there read as no
// light: a dark line across the wall at the rest level. A drop drawn down
// against the wall at x = -2, which the sun lights, seen from across the
// pool: on the pixels whose first surface is that wall below the rest level
// (the reference's position AOV), both renderers' ratio is 1. The raster's
// is exact there but within its bilinear read of the water's light: two
// texels of light lines from the waterline on the wall.
TEST_F(CausticsReferenceGpuTest, WallAboveATroughHasTheWholeSun) {
  constexpr uint32_t kWidth = 160, kHeight = 160, kFrame = 2;
  scene::Scene s = sunlitPool();
  s.sky.sunElevationDegrees = 50.0f;
  s.sky.sunAzimuthDegrees = 45.0f;
  s.water.drops = {{.x = -2.0f, .z = 0.0f, .radius = 0.6f, .amplitude = -0.2f}};
  s.camera.position = {1.2f, 0.9f, 0.6f};
  s.camera.target = {-2.0f, -0.3f, 0.0f};
  s.camera.fovYDegrees = 50.0f;
  const sim::WaterState water = sim::simulateWater(ctx(), s, kFrame);
  std::vector<float> position;
  const auto reference = causticsRatios(ctx(), s, water, kFrame, kWidth, kHeight, true, &position);
  const auto raster = causticsRatios(ctx(), s, water, kFrame, kWidth, kHeight, false);
  // The water's height on the wall at z: its edge cells' (the caustics'
  // mesh reaching the walls), between their centres.
  const float cell = s.water.extent / float(water.n), half = 0.5f * s.water.extent;
  auto waterAtWall = [&](float z) {
    const float g = std::clamp((z + half) / cell - 0.5f, 0.0f, float(water.n - 1));
    const uint32_t j = std::min(uint32_t(g), water.n - 2);
    return s.water.level + glm::mix(water.u[size_t(j) * water.n], water.u[size_t(j + 1) * water.n], g - float(j));
  };
  // Two texels of light lines, as a height on the wall: a light line moves
  // across the wall by the refracted sun's run in x over its fall.
  const glm::vec3 light = shader::causticsLight(render::poolParams(s), render::sunDirection(s.sky));
  const float margin = 2.0f * (s.water.extent / float(render::kCausticsSize)) * std::abs(light.y / light.x);
  auto onBand = [&](uint32_t x, uint32_t y) {
    const float* at = &position[(size_t(y) * kWidth + x) * 4];
    return std::abs(at[0] + half) < 1e-3f && at[1] < s.water.level;
  };
  size_t band = 0, clear = 0;
  double worstClear = 0.0, worstNear = 0.0, worstReference = 0.0;
  for (uint32_t y = 1; y + 1 < kHeight; ++y) {
    for (uint32_t x = 1; x + 1 < kWidth; ++x) {
      // Whole pixels: the band's four neighbours too, so no sample sees the water.
      if (!onBand(x, y) || !onBand(x - 1, y) || !onBand(x + 1, y) || !onBand(x, y - 1) || !onBand(x, y + 1)) continue;
      const size_t p = size_t(y) * kWidth + x;
      const double error = std::abs(double(raster[p]) - 1.0);
      ++band;
      worstReference = std::max(worstReference, std::abs(double(reference[p]) - 1.0));
      if (position[p * 4 + 1] > waterAtWall(position[p * 4 + 2]) + margin) {
        ++clear;
        worstClear = std::max(worstClear, error);
      } else {
        worstNear = std::max(worstNear, error);
      }
    }
  }
  std::printf(
      "the wall above the trough, %zu pixels: the reference's ratio within %.4f of 1; the raster's within %.4f on "
      "the %zu clear of the waterline by %.1f mm, %.4f on the others\n",
      band, worstReference, worstClear, clear, 1e3 * margin, worstNear);
  EXPECT_GT(clear, size_t(50));
  EXPECT_LT(worstReference, 1e-3);
  EXPECT_LT(worstClear, 1e-3);
}

}  // namespace tp::test
