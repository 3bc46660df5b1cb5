// The reference's caustics, light-traced (reference/reference_caustics), on
// their own against closed forms, and the raster's caustics map measured
// against them through the frames both draw.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <glm/gtc/type_ptr.hpp>

#include "cli/frame_samples.hpp"
#include "exact_fresnel.hpp"
#include "gpu_test.hpp"
#include "reference/reference_caustics.hpp"
#include "reference/reference_tracer.hpp"
#include "render/renderer.hpp"
#include "shading/frame_uniforms.hpp"
#include "shading/sky_model.hpp"
#include "shading/water_model.hpp"
#include "shared/objects.h"
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

// The sun's image in the water on the walls above it: flat water leaves
// each mirror point its own light (ratio 1); water whose every normal is
// tilted by the same angle sends the sun's image off as a parallel beam,
// which lands on the wall facing the sun stretched along x by the factor k
// worked out here from the reflected direction (the mirror point moves k
// times as far as the photon's lattice point), each photon weighted by its
// Fresnel reflectance over the flat water's: the ratio over the texels the
// wall's band takes is that weight over k.
TEST(ReferenceCaustics, ATiltedMirrorStretchesTheSunsImageOnTheWall) {
  scene::Scene s = flatFloor(30.0f);
  s.sky.sunAzimuthDegrees = 0.0f;  // towards +x: the image lands on the wall at x = -extent/2
  s.water.level = -0.6f;
  const sim::WaterState flat = sim::flatState(s.water.grid);
  Pool pool = poolOf(s, flat);
  const glm::vec3 toSun = render::sunDirection(s.sky);
  const float wall = -0.5f * s.water.extent, band = s.ground.height - s.water.level;
  const float reach = band * toSun.y > 0.0f ? band * std::sqrt(1.0f - toSun.y * toSun.y) / toSun.y : 0.0f;
  for (const float tilt : {0.0f, 0.06f}) {
    const glm::vec3 n(std::sin(tilt), std::cos(tilt), 0.0f);
    std::fill(pool.normals.begin(), pool.normals.end(), n);
    const render::CausticsMap map = render::traceReflectedCaustics(s, pool.water, pool.normals, pool.receivers, kSize);
    const glm::vec3 r = glm::reflect(-toSun, n);
    const double k = double(r.y) * toSun.x / (double(toSun.y) * -r.x);
    const double weight = fresnelFromAir(glm::dot(toSun, n), s.water.ior) / fresnelFromAir(toSun.y, s.water.ior);
    // The texels whose mirror points the band takes, 0.15 m clear of its ends and the side walls.
    const float texel = s.water.extent / float(kSize);
    double sum = 0.0;
    size_t count = 0;
    for (uint32_t z = 0; z < kSize; ++z) {
      for (uint32_t x = 0; x < kSize; ++x) {
        const float qx = wall + (float(x) + 0.5f) * texel, qz = wall + (float(z) + 0.5f) * texel;
        if (qx < wall + 0.15f || qx > wall + reach - 0.15f || std::abs(qz) > -wall - 0.15f) continue;
        const float ratio = map.ratio[size_t(z) * kSize + x];
        if (tilt == 0.0f) EXPECT_EQ(ratio, 1.0f) << x << "," << z;
        sum += ratio;
        ++count;
      }
    }
    const double expected = weight / k;
    std::printf("tilt %.2f: %zu texels, mean ratio %.4f, exact %.4f (k %.4f, Fresnel's weight %.4f)\n", tilt, count,
                sum / double(count), expected, k, weight);
    EXPECT_GT(count, 1000u);
    EXPECT_NEAR(sum / double(count) / expected, 1.0, 0.01);
  }
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
          const glm::vec3 local = shader::toBoxFrame(at - box.center, glm::radians(box.yawDegrees));
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

// What each renderer's caustics ratio does about a surface (`on`) in a
// trough, frame 2 of `s` at 160x160. On the whole pixels (their four
// neighbours too, so no sample sees the water) whose first surface, by the
// reference's position AOV, lies on it below the water's rest level, in the
// air: how far each strays from 1. On the pixels that see it through the
// water within 0.1 m of it (`near`): the raster's RMS difference from the
// reference.
struct AboutTheTrough {
  size_t inTheAir = 0, throughTheWater = 0;
  double raster = 0.0, reference = 0.0, rmsThroughTheWater = 0.0;
};

AboutTheTrough ratiosAboutTheTrough(const gpu::Context& ctx, const scene::Scene& s,
                                    const std::function<bool(glm::vec3)>& on,
                                    const std::function<bool(glm::vec3)>& near) {
  constexpr uint32_t kWidth = 160, kHeight = 160, kFrame = 2;
  const sim::WaterState water = sim::simulateWater(ctx, s, kFrame);
  std::vector<float> position;
  const auto reference = causticsRatios(ctx, s, water, kFrame, kWidth, kHeight, true, &position);
  const auto raster = causticsRatios(ctx, s, water, kFrame, kWidth, kHeight, false);
  auto at = [&](uint32_t x, uint32_t y) { return glm::make_vec3(&position[(size_t(y) * kWidth + x) * 4]); };
  auto inTheAir = [&](uint32_t x, uint32_t y) { return at(x, y).y < s.water.level && on(at(x, y)); };
  const float half = 0.5f * s.water.extent;
  AboutTheTrough about;
  double squares = 0.0;
  for (uint32_t y = 1; y + 1 < kHeight; ++y) {
    for (uint32_t x = 1; x + 1 < kWidth; ++x) {
      const size_t p = size_t(y) * kWidth + x;
      // The water's surface: in the pool, off the floor, and not on the surface.
      const glm::vec3 q = at(x, y);
      const bool water = std::abs(q.y - s.water.level) < 0.3f && std::max(std::abs(q.x), std::abs(q.z)) < half;
      if (water && !on(q) && near(q) && raster[p] >= 0.0f && reference[p] >= 0.0f) {
        ++about.throughTheWater;
        squares += (raster[p] - reference[p]) * (raster[p] - reference[p]);
      }
      if (!inTheAir(x, y) || !inTheAir(x - 1, y) || !inTheAir(x + 1, y) || !inTheAir(x, y - 1) || !inTheAir(x, y + 1))
        continue;
      ++about.inTheAir;
      about.raster = std::max(about.raster, std::abs(double(raster[p]) - 1.0));
      about.reference = std::max(about.reference, std::abs(double(reference[p]) - 1.0));
    }
  }
  about.rmsThroughTheWater = std::sqrt(squares / double(std::max<size_t>(about.throughTheWater, 1)));
  std::printf(
      "  in the air, %zu pixels: the raster's ratio within %.4f of 1, the reference's %.4f; through the water, %zu "
      "pixels: the raster's RMS difference from the reference %.4f\n",
      about.inTheAir, about.raster, about.reference, about.throughTheWater, about.rmsThroughTheWater);
  return about;
}

// The pool lit from +x +z (the walls at x = -2 and z = -2), a drop drawn
// down at `at` (0.2 m deep), seen from `camera`.
scene::Scene troughAt(glm::vec2 at, float radius, glm::vec3 camera, glm::vec3 target, float fov) {
  scene::Scene s = sunlitPool();
  s.sky.sunElevationDegrees = 50.0f;
  s.sky.sunAzimuthDegrees = 45.0f;
  s.water.drops = {{.x = at.x, .z = at.y, .radius = radius, .amplitude = -0.2f}};
  s.camera.position = camera;
  s.camera.target = target;
  s.camera.fovYDegrees = fov;
  return s;
}

// Where a wave draws the water below its rest level at a lit wall, the wall
// between the two is in the air, in the whole sun. Read as under the water,
// the caustics' mesh once stopping half a cell short of the walls, it drew
// a dark line across the wall at the rest level. A drop against the wall at
// x = -2, seen from across the pool: on the pixels of that wall below the
// rest level seen directly (so in the air), both renderers' ratio is 1;
// through the water the raster follows the reference.
TEST_F(CausticsReferenceGpuTest, WallAboveATroughHasTheWholeSun) {
  const scene::Scene s = troughAt({-2.0f, 0.0f}, 0.6f, {1.2f, 0.9f, 0.6f}, {-2.0f, -0.3f, 0.0f}, 50.0f);
  const float wall = -0.5f * s.water.extent;
  std::printf("the wall at x = %.1f:\n", wall);
  const AboutTheTrough about = ratiosAboutTheTrough(
      ctx(), s, [&](glm::vec3 p) { return std::abs(p.x - wall) < 1e-3f; },
      [&](glm::vec3 p) { return p.x - wall < 0.1f; });
  EXPECT_GT(about.inTheAir, size_t(100));
  EXPECT_GT(about.throughTheWater, size_t(100));
  EXPECT_LT(about.reference, 1e-3);
  EXPECT_LT(about.raster, 1e-3);
  EXPECT_LT(about.rmsThroughTheWater, 1.0);
}

// The same for a sphere half in the water, the water drawn down around it.
TEST_F(CausticsReferenceGpuTest, SphereAboveItsTroughHasTheWholeSun) {
  scene::Scene s = troughAt({0.0f, 0.0f}, 0.9f, {1.6f, 0.6f, 1.6f}, {0.0f, -0.15f, 0.0f}, 30.0f);
  const scene::Sphere sphere{.center = {0.0f, s.water.level, 0.0f}, .radius = 0.4f};
  s.spheres = {sphere};
  std::printf("the sphere:\n");
  const AboutTheTrough about = ratiosAboutTheTrough(
      ctx(), s, [&](glm::vec3 p) { return std::abs(glm::distance(p, sphere.center) - sphere.radius) < 1e-3f; },
      [&](glm::vec3 p) { return glm::distance(p, sphere.center) - sphere.radius < 0.1f; });
  EXPECT_GT(about.inTheAir, size_t(100));
  EXPECT_GT(about.throughTheWater, size_t(100));
  EXPECT_LT(about.reference, 1e-3);
  EXPECT_LT(about.raster, 1e-3);
  EXPECT_LT(about.rmsThroughTheWater, 1.0);
}

}  // namespace tp::test
