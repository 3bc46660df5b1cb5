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
#include "shading/sky_model.hpp"
#include "shading/water_model.hpp"
#include "sim/water_scene.hpp"
#include "sim/water_state.hpp"

namespace tp::test {
namespace {

constexpr uint32_t kSize = 128;  // texels a side: 3.1 cm in the 4 m pool

struct Pool {
  scene::Mesh water, floor;
  std::vector<glm::vec3> normals;
};

Pool poolOf(const scene::Scene& s, const sim::WaterState& water) {
  Pool p;
  for (auto& mesh : render::sceneMeshes(s, &water, 0.0f)) {
    if (mesh.name == "water") p.water = std::move(mesh);
    if (mesh.name == "pool_floor") p.floor = std::move(mesh);
  }
  p.normals = render::waterVertexNormals(water, s.water.extent);
  return p;
}

scene::Scene flatFloor(float sunElevation) {
  scene::Scene s = scene::defaultScene();
  s.terrain.amplitude = 0.0f;
  s.sky.sunElevationDegrees = sunElevation;
  return s;
}

}  // namespace

// Under flat water every texel of the lit floor receives exactly its share
// (ratio 1): the photon lattice shifted by one refraction. The strip along
// the sunward wall gets none: its width is the depth under the level times
// the tangent of the refracted sun's angle (Snell), within a texel.
TEST(ReferenceCaustics, FlatWaterLightsTheFloorExactlyButTheWallsStrip) {
  for (const float elevation : {90.0f, 50.0f}) {
    const scene::Scene s = flatFloor(elevation);
    const sim::WaterState flat = sim::flatState(s.water.grid);
    const Pool pool = poolOf(s, flat);
    const render::CausticsMap map = render::traceCaustics(s, pool.water, pool.normals, pool.floor, kSize);
    const glm::vec3 toSun = render::sunDirection(s.sky);
    const float sinWater = std::sqrt(1.0f - toSun.y * toSun.y) / s.water.ior;
    const float depth = s.water.level - (s.ground.height - s.pool.depth);
    const float strip = depth * sinWater / std::sqrt(1.0f - sinWater * sinWater);
    const float texel = 2.0f * map.halfExtent / kSize;
    // The sun's azimuth in xz: the strip lies along the walls it shines past.
    const glm::vec2 away = glm::length(glm::vec2(toSun.x, toSun.z)) > 0.0f
                               ? glm::normalize(glm::vec2(-toSun.x, -toSun.z)) * strip
                               : glm::vec2(0.0f);
    // The water mesh spans the grid's cell centres: half a cell's rim has no water.
    const float rim = 0.5f * s.water.extent / float(s.water.grid);
    size_t exact = 0, dark = 0, checked = 0;
    for (uint32_t z = 0; z < kSize; ++z) {
      for (uint32_t x = 0; x < kSize; ++x) {
        const glm::vec2 lo(-map.halfExtent + float(x) * texel, -map.halfExtent + float(z) * texel);
        // The floor lit through the water's mesh: [-h + rim, h - rim]^2 moved by the refraction.
        const glm::vec2 litLo = glm::vec2(-map.halfExtent + rim) + away, litHi = glm::vec2(map.halfExtent - rim) + away;
        const float r = map.ratio[size_t(z) * kSize + x];
        if (glm::all(glm::greaterThanEqual(lo, litLo + texel)) &&
            glm::all(glm::lessThanEqual(lo + texel, litHi - texel))) {
          ++checked;
          exact += r == 1.0f;
        } else if (glm::any(glm::lessThan(lo + texel, litLo - texel)) ||
                   glm::any(glm::greaterThan(lo, litHi + texel))) {
          EXPECT_EQ(r, 0.0f) << "texel " << x << ", " << z;
          ++dark;
        }
      }
    }
    std::printf("sun at %.0f degrees: %zu of %zu lit texels exactly 1, %zu in the walls' strip dark (strip %.3f m)\n",
                elevation, exact, checked, dark, strip);
    EXPECT_EQ(exact, checked);
    EXPECT_GT(checked, size_t(kSize * kSize / 2));
    if (elevation < 90.0f) EXPECT_GT(dark, size_t(kSize));
  }
}

// Under waves the light gathers and spreads; the water neither makes nor
// loses it: the mean over the floor stays 1 but for what the waves send
// into the walls (the photons that land outside the floor's square).
TEST(ReferenceCaustics, WavesGatherLightWithoutMakingOrLosingIt) {
  scene::Scene s = flatFloor(90.0f);
  const sim::WaterState water = sim::waterInitialState(s.water);  // the default scene's three drops
  const Pool pool = poolOf(s, water);
  const render::CausticsMap map = render::traceCaustics(s, pool.water, pool.normals, pool.floor, kSize);
  // The interior, clear of the border half cell the mesh lacks.
  double sum = 0.0;
  size_t n = 0;
  float lo = 1e30f, hi = 0.0f;
  for (uint32_t z = 2; z + 2 < kSize; ++z) {
    for (uint32_t x = 2; x + 2 < kSize; ++x) {
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

// The raster's caustics map against the light-traced caustics, seen from
// straight above the pool lit by the sun alone: each renderer's frame with
// caustics over its frame without (the refraction and the absorption cancel)
// is the floor's caustics ratio where the eye meets it.
TEST_F(CausticsReferenceGpuTest, RasterCausticsMatchTheLightTracedOnes) {
  constexpr uint32_t kWidth = 160, kHeight = 160, kFrame = 10;
  scene::Scene terrain = scene::defaultScene();
  terrain.ao.enabled = false;
  terrain.spheres.clear();
  terrain.boxes.clear();
  terrain.sky.zenith = terrain.sky.horizon = terrain.sky.glow = glm::vec3(0.0f);
  terrain.sky.sunElevationDegrees = 65.0f;
  terrain.camera.position = {0.0f, 3.0f, 0.0f};
  terrain.camera.target = {0.0f, -1.0f, 0.0f};
  terrain.camera.up = {0.0f, 0.0f, -1.0f};
  terrain.camera.fovYDegrees = 40.0f;
  scene::Scene flat = terrain;
  flat.terrain.amplitude = 0.0f;
  struct Case {
    const char* name;
    scene::Scene scene;
    double bound;
  };
  // The raster lands its light on a level plane at the floor's height near
  // the landing: over the terrain's relief (0.35 m peak to peak) its slope is
  // left out; over a flat floor only the map's own approximations are left.
  // On the mean floor's plane, as it was, the terrain's RMSE was 0.0616.
  for (const Case& c : {Case{"over the terrain", terrain, 0.06}, Case{"over a flat floor", flat, 0.035}}) {
    const sim::WaterState water = sim::simulateWater(ctx(), c.scene, kFrame);
    auto ratios = [&](bool reference) {
      scene::Scene on = c.scene, off = c.scene;
      on.render.caustics = true;
      off.render.caustics = false;
      std::vector<float> a, b;
      if (reference) {
        a = render::renderReference(on, &water, kFrame, kWidth, kHeight, {.samples = 16}).rgba;
        b = render::renderReference(off, &water, kFrame, kWidth, kHeight, {.samples = 16}).rgba;
      } else {
        render::Renderer ra(ctx(), on, kWidth, kHeight), rb(ctx(), off, kWidth, kHeight);
        a = app::renderSamples(ra, {.frame = kFrame}, 16).rgba;
        b = app::renderSamples(rb, {.frame = kFrame}, 16).rgba;
      }
      std::vector<float> r(size_t(kWidth) * kHeight, -1.0f);
      for (size_t p = 0; p < r.size(); ++p)
        if (b[p * 4 + 1] > 1e-3f) r[p] = a[p * 4 + 1] / b[p * 4 + 1];  // green: the least absorbed
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
    std::printf("caustics ratio seen from above %s, %zu pixels: raster mean %.4f, light-traced mean %.4f, RMSE %.4f\n",
                c.name, n, meanRaster / double(n), meanReference / double(n), rmse);
    EXPECT_GT(n, size_t(kWidth * kHeight / 2)) << c.name;
    EXPECT_NEAR(meanRaster / double(n), meanReference / double(n), 0.02) << c.name;
    EXPECT_LT(rmse, c.bound) << c.name;
  }
}

}  // namespace tp::test
