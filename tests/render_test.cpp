// The rendered frame against answers computed independently on the CPU: the
// ground's Lambertian shading under a sky whose irradiance is known in closed
// form, the sky's radiance along each pixel's view ray, and the passes that a
// request needs.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/gtc/constants.hpp>
#include <optional>

#include "exact_fresnel.hpp"
#include "gpu_test.hpp"
#include "io/image_io.hpp"
#include "process.hpp"
#include "render/pass_kinds.hpp"
#include "render/renderer.hpp"
#include "shading/frame_uniforms.hpp"
#include "shading/pool_light.hpp"
#include "shading/pool_model.hpp"
#include "shading/sky_model.hpp"
#include "shared/pool_light.h"
#include "shared/shading.h"
#include "test_scenes.hpp"

namespace tp::test {
namespace {

constexpr uint32_t kWidth = 320, kHeight = 180;

// A sky of constant radiance c (no glow, zenith = horizon) has irradiance
// pi * c on an up-facing surface, exactly.
scene::Scene uniformSkyScene() {
  scene::Scene s = checkerScene();
  // The default camera sees the far ground at grazing angles, where the
  // depth buffer's steps read as a little occlusion (ambient-occlusion.md).
  s.ao.enabled = false;
  s.water.enabled = false;
  s.spheres.clear();
  s.sky.zenith = s.sky.horizon = glm::vec3(0.4f, 0.5f, 0.7f);
  s.sky.glow = glm::vec3(0.0f);
  return s;
}

// World-space ray through the centre of pixel (x, y), rows top to bottom.
glm::vec3 pixelRay(const shader::FrameUniforms& u, uint32_t x, uint32_t y) {
  glm::vec2 ndc((x + 0.5f) / kWidth * 2.0f - 1.0f, (y + 0.5f) / kHeight * 2.0f - 1.0f);
  glm::vec4 far = u.inverseViewProjection * glm::vec4(ndc, 1.0f, 1.0f);
  return glm::normalize(glm::vec3(far) / far.w - glm::vec3(u.cameraPosition));
}

glm::vec3 pixel(const render::RenderedFrame& f, uint32_t x, uint32_t y) {
  const float* p = &f.rgba[(size_t(y) * f.width + x) * 4];
  return {p[0], p[1], p[2]};
}

}  // namespace

using RenderTest = GpuTest;

TEST_F(RenderTest, GroundIsLambertianUnderSunAndUniformSky) {
  const scene::Scene s = uniformSkyScene();
  render::Renderer renderer(ctx(), s, kWidth, kHeight);
  auto frame = renderer.render({.hdr = true});
  const auto u = render::frameUniforms(s, kWidth, kHeight);

  const glm::vec3 l = render::sunDirection(s.sky);
  const float sunSolidAngle = glm::two_pi<float>() * (1.0f - std::cos(glm::radians(s.sky.sunAngularRadiusDegrees)));
  const glm::vec3 irradiance = s.sky.sunRadiance * sunSolidAngle * l.y + glm::pi<float>() * s.sky.zenith;
  int checked = 0;
  for (uint32_t y = 0; y < kHeight; ++y) {
    for (uint32_t x = 0; x < kWidth; ++x) {
      glm::vec3 d = pixelRay(u, x, y);
      if (d.y >= -1e-3f) continue;
      float t = (s.ground.height - u.cameraPosition.y) / d.y;
      if (t > 8.0f) continue;  // near enough that the checker filter sees one square
      glm::vec3 hit = glm::vec3(u.cameraPosition) + t * d;
      glm::vec2 q = glm::vec2(hit.x, hit.z) / s.ground.checkerSize;
      glm::vec2 f = q - glm::floor(q);
      if (f.x < 0.2f || f.x > 0.8f || f.y < 0.2f || f.y > 0.8f) continue;  // away from square edges
      bool even = (int(std::floor(q.x)) + int(std::floor(q.y))) % 2 == 0;
      glm::vec3 albedo = even ? s.ground.albedoA : s.ground.albedoB;
      glm::vec3 expected = albedo / glm::pi<float>() * irradiance;
      glm::vec3 got = pixel(frame, x, y);
      for (int c = 0; c < 3; ++c)
        ASSERT_NEAR(got[c], expected[c], 1e-4f * expected[c]) << x << "," << y << " channel " << c;
      ++checked;
    }
  }
  EXPECT_GT(checked, 1000);
}

// The least and largest radiance among the sky texels the sampler may blend
// for direction d: those around d's equirectangular point (u repeats, v
// clamps), each the CPU's skyRadiance at its centre, within eps texels of
// error in the GPU's own mapping. Any bilinear sample there lies between them.
struct SkyRange {
  glm::vec3 lo{1e30f}, hi{-1e30f};
};
static SkyRange sampledSkyRange(const shader::SkyParams& params, glm::vec3 d, float eps) {
  const int w = int(params.counts.x), h = w / 2;
  const glm::vec2 t = shader::directionToEquirect(d) * glm::vec2(w, h) - 0.5f;
  SkyRange r;
  for (int j = int(std::floor(t.y - eps)); j <= int(std::floor(t.y + eps)) + 1; ++j) {
    for (int i = int(std::floor(t.x - eps)); i <= int(std::floor(t.x + eps)) + 1; ++i) {
      const int wrapped = ((i % w) + w) % w, clamped = std::clamp(j, 0, h - 1);
      const glm::vec3 dir = shader::equirectToDirection({(wrapped + 0.5f) / w, (clamped + 0.5f) / h});
      const glm::vec3 v = shader::skyRadiance(params, dir, 1.0f);
      r.lo = glm::min(r.lo, v);
      r.hi = glm::max(r.hi, v);
    }
  }
  return r;
}

// Clear, and with clouds: each sky pixel shows the sky the CPU evaluates with
// the same shared function. Clear, the sky is smooth: the pixel is the
// radiance along its view ray. Clouds vary from texel to texel (up to the
// texture's Nyquist limit), and the GPU's atan and acos, which place the
// sample, may err by 4096 ulp (the Vulkan spec's bound: 2^-10 rad near pi,
// 2^-10 w / 2 pi texels): the pixel lies within the texels it may blend.
TEST_F(RenderTest, SkyPixelsShowTheSkyAlongTheirViewRay) {
  for (const float coverage : {0.0f, 0.5f}) {
    scene::Scene s = scene::defaultScene();
    s.camera.position = {0.0f, 2.0f, 8.0f};  // a view with much sky
    s.camera.target = {0.0f, 0.5f, 0.0f};
    s.sky.clouds.coverage = coverage;
    render::Renderer renderer(ctx(), s, kWidth, kHeight);
    auto frame = renderer.render({.hdr = true});
    const auto u = render::frameUniforms(s, kWidth, kHeight);
    const auto params = render::skyParams(s.sky);
    const glm::vec3 sun = render::sunDirection(s.sky);
    const float eps = std::ldexp(1.0f, -10) * float(s.sky.textureWidth) / glm::two_pi<float>();
    const float halfFloat = 2e-3f;  // half-float texels (2^-11 relative) and the sampler's weights
    int checked = 0, cloudy = 0, outside = 0;
    double worst = 0.0;
    for (uint32_t y = 0; y < kHeight; ++y) {
      for (uint32_t x = 0; x < kWidth; ++x) {
        glm::vec3 d = pixelRay(u, x, y);
        if (d.y < 0.05f || glm::dot(d, sun) > std::cos(glm::radians(5.0f))) continue;  // clear of horizon and sun disk
        const glm::vec3 got = pixel(frame, x, y);
        const SkyRange range = sampledSkyRange(params, d, eps);
        for (int c = 0; c < 3; ++c) {
          if (got[c] < range.lo[c] * (1.0f - halfFloat) || got[c] > range.hi[c] * (1.0f + halfFloat)) ++outside;
        }
        if (coverage == 0.0f) {
          const glm::vec3 expected = shader::skyRadiance(params, d, 1.0f);
          for (int c = 0; c < 3; ++c) worst = std::max(worst, double(std::abs(got[c] - expected[c]) / expected[c]));
        }
        ++checked;
        if (coverage > 0.0f && shader::cloudAmount(params, d) > 0.5f) ++cloudy;
      }
    }
    EXPECT_GT(checked, 10000);
    EXPECT_EQ(outside, 0) << "pixel channels outside the texels they may blend, coverage " << coverage;
    if (coverage == 0.0f) {
      // Half-float texels and bilinear interpolation of a smooth sky.
      EXPECT_LT(worst, 2e-3) << "worst relative error of a clear sky pixel";
    } else {
      EXPECT_GT(cloudy, checked / 10) << "the clouds show";
    }
    std::printf("coverage %.1f: %d sky pixels (%d cloudy), %d channels outside; clear: worst relative error %.2e\n",
                coverage, checked, cloudy, outside, worst);
  }
}

TEST_F(RenderTest, OnlyThePassesARequestNeedsAreRecorded) {
  render::Renderer renderer(ctx(), scene::defaultScene(), 64, 48);
  auto names = [](const render::RenderedFrame& f) {
    std::vector<std::string> n;
    for (const auto& p : f.passes) n.push_back(p.name);
    return n;
  };
  // Frame 0 again and again: no steps to take, and the cached passes (sky,
  // caustics, the ground) ran on the first; the camera is away from the water
  // (no camera medium). Each frame begins with the ground's copy; the sky
  // behind everything is drawn in the ground's pass. The AO made on the
  // first frame only: nothing opaque moves. The water deferred: its
  // G-buffer, tiles, shading and the side seen from below. The AO, the haze
  // and the tonemap in the resolve, which runs for either image, over the
  // tiles its list names.
  const std::vector<std::string> opaque{"ground copy", "pool",        "objects",       "water g-buffer", "water tiles",
                                        "water",       "water below", "resolve tiles", "resolve"};
  auto with = [&](std::vector<std::string> tail) {
    std::vector<std::string> all = opaque;
    all.insert(all.end(), tail.begin(), tail.end());
    return all;
  };
  auto hdrOnly = renderer.render({.hdr = true, .ldr = false});
  const std::vector<std::string> first{"caustics",    "sky",   "ground",      "ground copy",   "pool",
                                       "objects",     "ssao",  "ao blur x",   "ao blur y",     "water g-buffer",
                                       "water tiles", "water", "water below", "resolve tiles", "resolve",
                                       "readback hdr"};
  EXPECT_EQ(names(hdrOnly), first);
  EXPECT_TRUE(hdrOnly.srgb.empty());
  auto both = renderer.render({.hdr = true, .ldr = true});
  EXPECT_EQ(names(both), with({"readback hdr", "readback ldr"}));
  auto ldrOnly = renderer.render({.hdr = false, .ldr = true});
  EXPECT_EQ(names(ldrOnly), with({"readback ldr"}));
  EXPECT_EQ(both.srgb, ldrOnly.srgb);
  EXPECT_EQ(both.rgba, hdrOnly.rgba);
  for (const auto& p : both.passes) EXPECT_GE(p.milliseconds, 0.0) << p.name;

  // A scene without water pays for none: no simulation, no water pass; one
  // without AO, for no SSAO passes; AO at half resolution without a blur:
  // SSAO, then the resolve, which upsamples as it applies (the upsampled
  // image only for a request of the AO).
  scene::Scene dry = scene::defaultScene();
  dry.water.enabled = false;
  dry.ao.enabled = false;
  render::Renderer dryRenderer(ctx(), dry, 64, 48);
  EXPECT_EQ(names(dryRenderer.render({.hdr = true})),
            (std::vector<std::string>{"sky", "ground", "ground copy", "objects", "resolve", "readback hdr"}));
  dry.ao = scene::Ao{};
  dry.ao.resolution = "half";
  dry.ao.blur = "off";
  render::Renderer halfRenderer(ctx(), dry, 64, 48);
  EXPECT_EQ(names(halfRenderer.render({.hdr = true})),
            (std::vector<std::string>{"sky", "ground", "ground copy", "objects", "ssao", "resolve", "readback hdr"}));
  const auto withAo = halfRenderer.render({.hdr = true, .ao = true});
  EXPECT_NE(render::findPass(withAo.passes, render::passes::kAoUpsample), nullptr);
}

TEST_F(RenderTest, TonemapMatchesTheCpuCurve) {
  render::Renderer renderer(ctx(), scene::defaultScene(), 64, 48);
  auto f = renderer.render({.hdr = true, .ldr = true});
  const float exposure = scene::defaultScene().render.exposure;
  auto curve = [&](float x) {
    x *= exposure;
    float t = std::clamp((x * (2.51f * x + 0.03f)) / (x * (2.43f * x + 0.59f) + 0.14f), 0.0f, 1.0f);
    return t <= 0.0031308f ? 12.92f * t : 1.055f * std::pow(t, 1.0f / 2.4f) - 0.055f;
  };
  for (size_t i = 0; i < f.rgba.size(); i += 4) {
    for (int c = 0; c < 3; ++c) {
      float expected = curve(f.rgba[i + c]) * 255.0f;
      ASSERT_NEAR(float(f.srgb[i + c]), expected, 0.51f + 1e-3f * expected) << "pixel " << i / 4;
    }
    ASSERT_EQ(f.srgb[i + 3], 255);
  }
}

namespace {

glm::vec3 refractGlsl(glm::vec3 i, glm::vec3 n, float eta) {
  const float k = 1.0f - eta * eta * (1.0f - glm::dot(n, i) * glm::dot(n, i));
  if (k < 0.0f) return glm::vec3(0.0f);
  return eta * i - (eta * glm::dot(n, i) + std::sqrt(k)) * n;
}

// Flat water (no drops) over a flat pool floor (no terrain), seen straight down.
scene::Scene flatWaterFromAbove() {
  scene::Scene s = checkerScene();
  s.camera.position = {0.3f, 2.0f, 0.2f};
  s.camera.target = {0.3f, 0.0f, 0.2f};
  s.camera.up = {0.0f, 0.0f, -1.0f};
  s.camera.fovYDegrees = 60.0f;
  s.water.drops.clear();
  s.terrain.amplitude = 0.0f;
  s.spheres.clear();
  // The CPU's answer lights the floor as through flat water everywhere; the
  // caustics pass also shades the strip the walls shadow (tested on its own),
  // as do the sun's shadows (tests/sun_shadow_test.cpp and its GPU peer).
  s.render.caustics = false;
  s.render.shadows = false;
  return s;
}

}  // namespace

using WaterRenderTest = GpuTest;

// Through flat water seen from above, each pixel shows the floor where Snell's
// law puts it: the CPU traces the pixel's ray (reflection of the sky, Schlick's
// Fresnel, refraction to the floor, absorption along the path) and the frame
// must agree. Pixels where the straight, unrefracted ray would land on the
// other checker colour prove that the refraction is what is checked.
TEST_F(WaterRenderTest, FlatWaterShowsTheFloorWhereSnellsLawPutsIt) {
  const scene::Scene s = flatWaterFromAbove();
  render::Renderer renderer(ctx(), s, kWidth, kHeight);
  const auto frame = renderer.render({.frame = 0, .hdr = true});
  const auto u = render::frameUniforms(s, kWidth, kHeight);
  const auto sky = render::skyParams(s.sky);
  const float ior = s.water.ior;
  const float f0 = ((ior - 1.0f) / (ior + 1.0f)) * ((ior - 1.0f) / (ior + 1.0f));
  const float half = 0.5f * s.water.extent;
  const float floorY = s.ground.height - s.pool.depth;
  // The floor's irradiance: the sun refracted down through the flat water
  // (Fresnel's transmission, the horizontal flux cos(air), absorbed over
  // the slant path), and the pool's baked light (the raster's model of the
  // rest, checked against closed forms in tests/pool_light_test.cpp).
  const double sinSun = std::max(u.sunDirection.y, 0.0f);
  const double cosSunInWater = std::sqrt(1.0 - (1.0 - sinSun * sinSun) / (double(ior) * ior));
  const glm::vec3 sunDown = glm::vec3(u.sunIrradiance) * float(sinSun * (1.0 - fresnelFromAir(sinSun, ior))) *
                            glm::exp(-s.water.absorption * float((s.water.level - floorY) / cosSunInWater));
  const render::PoolModel pool = render::poolModel(s);
  const render::PoolLight baked = render::bakePoolLight(
      pool.params, pool.floorVertices, [&](glm::vec3 dir) { return shader::skyRadiance(sky, dir, 0.0f); },
      {glm::vec3(u.sunDirection), glm::vec3(u.sunIrradiance)}, {});
  auto parityAt = [&](glm::vec2 xz, bool& nearEdge) {
    const glm::vec2 q = xz / s.pool.tileSize;
    const glm::vec2 f = q - glm::floor(q);
    nearEdge = f.x < 0.15f || f.x > 0.85f || f.y < 0.15f || f.y > 0.85f;
    return (int(std::floor(q.x)) + int(std::floor(q.y))) % 2 == 0;
  };
  int checked = 0, refractionDecides = 0;
  for (uint32_t y = 0; y < kHeight; ++y) {
    for (uint32_t x = 0; x < kWidth; ++x) {
      const glm::vec3 d = pixelRay(u, x, y);
      const float t = (s.water.level - u.cameraPosition.y) / d.y;
      const glm::vec3 p = glm::vec3(u.cameraPosition) + t * d;
      if (std::abs(p.x) > half - 0.05f || std::abs(p.z) > half - 0.05f) continue;  // on the water, off its rim
      const glm::vec3 n(0.0f, 1.0f, 0.0f);
      const glm::vec3 refracted = refractGlsl(d, n, 1.0f / ior);
      const float s2 = (floorY - p.y) / refracted.y;
      const glm::vec3 hit = p + s2 * refracted;
      if (std::abs(hit.x) > half - 0.05f || std::abs(hit.z) > half - 0.05f) continue;  // a wall, not the floor
      bool nearEdge = false, straightNearEdge = false;
      const bool even = parityAt({hit.x, hit.z}, nearEdge);
      const glm::vec3 straight = p + ((floorY - p.y) / d.y) * d;
      const bool straightEven = parityAt({straight.x, straight.z}, straightNearEdge);
      if (nearEdge) continue;
      const glm::vec3 albedo = even ? s.pool.tileAlbedoA : s.pool.tileAlbedoB;
      // Seen from the air: 1 / n^2 of the radiance under the surface.
      const glm::vec3 irradiance =
          sunDown + shader::poolLightAt(pool.params, hit, glm::vec3(0.0f, 1.0f, 0.0f), baked.floorAndLight.data());
      const glm::vec3 transmitted =
          albedo / glm::pi<float>() * irradiance * glm::exp(-s.water.absorption * s2) / (ior * ior);
      const float cosIn = std::clamp(-glm::dot(d, n), 0.0f, 1.0f);
      const float fresnel = f0 + (1.0f - f0) * std::pow(1.0f - cosIn, 5.0f);
      const glm::vec3 reflected = shader::skyRadiance(sky, glm::reflect(d, n), 1.0f);
      const glm::vec3 expected = glm::mix(transmitted, reflected, fresnel);
      const glm::vec3 got = pixel(frame, x, y);
      for (int c = 0; c < 3; ++c) {
        // The reflected sky comes from a half-float texture: 2e-3 of it, plus float shading.
        ASSERT_NEAR(got[c], expected[c], 2e-3f * fresnel * reflected[c] + 1e-4f * expected[c] + 1e-6f)
            << x << "," << y << " channel " << c;
      }
      ++checked;
      if (!straightNearEdge && straightEven != even) ++refractionDecides;
    }
  }
  EXPECT_GT(checked, 5000);
  EXPECT_GT(refractionDecides, 500);
}

// Frame N is the water after N frames from the scene's start, whichever frames
// the renderer drew before; water at rest and in motion differ.
TEST_F(WaterRenderTest, FramesAreDeterministicAndTheWaterMoves) {
  const scene::Scene s = scene::defaultScene();
  render::Renderer a(ctx(), s, 96, 64), b(ctx(), s, 96, 64);
  const auto a0 = a.render({.frame = 0});
  const auto a12 = a.render({.frame = 12});
  (void)b.render({.frame = 5});
  const auto b12 = b.render({.frame = 12});
  const auto b0 = b.render({.frame = 0});  // backwards: restarts the simulation
  EXPECT_EQ(a12.rgba, b12.rgba);
  EXPECT_EQ(a0.rgba, b0.rgba);
  EXPECT_NE(a0.rgba, a12.rgba);

  scene::Scene calm = s;
  calm.water.drops.clear();
  render::Renderer c(ctx(), calm, 96, 64);
  EXPECT_EQ(c.render({.frame = 0}).rgba, c.render({.frame = 12}).rgba);  // nothing disturbs flat water
}

using AovTest = GpuTest;

// World position, normal and view depth against each pixel's ray cast on the
// CPU against the flat water square and the ground plane.
TEST_F(AovTest, PositionNormalAndDepthMatchTheRayCast) {
  scene::Scene s = scene::defaultScene();
  s.water.drops.clear();
  render::Renderer renderer(ctx(), s, kWidth, kHeight, {.aovs = true});
  const auto frame = renderer.render({.frame = 3, .hdr = false, .aovs = true});
  ASSERT_EQ(frame.position.size(), size_t(kWidth) * kHeight * 4);
  const auto u = render::frameUniforms(s, kWidth, kHeight);
  const glm::vec3 eye(u.cameraPosition);
  const float half = 0.5f * s.water.extent;
  int water = 0, ground = 0, sky = 0, spherePixels = 0;
  for (uint32_t y = 0; y < kHeight; ++y) {
    for (uint32_t x = 0; x < kWidth; ++x) {
      const glm::vec3 d = pixelRay(u, x, y);
      const size_t k = (size_t(y) * kWidth + x) * 4;
      const glm::vec3 p(frame.position[k], frame.position[k + 1], frame.position[k + 2]);
      const glm::vec3 n(frame.normal[k], frame.normal[k + 1], frame.normal[k + 2]);
      const float z = frame.position[k + 3];
      // The ground outside the pool's hole, else (through the hole) the water,
      // else a wall of the pool, which this test leaves out.
      std::optional<glm::vec3> hit;
      bool onWater = false;
      if (d.y < 0.0f) {
        const glm::vec3 g = eye + ((s.ground.height - eye.y) / d.y) * d;
        const glm::vec3 w = eye + ((s.water.level - eye.y) / d.y) * d;
        auto inside = [&](glm::vec3 q, float margin) {
          return std::abs(q.x) < half - margin && std::abs(q.z) < half - margin;
        };
        auto outside = [&](glm::vec3 q, float margin) {
          return std::abs(q.x) > half + margin || std::abs(q.z) > half + margin;
        };
        if (outside(g, 0.05f)) {
          if (std::abs(g.x) < s.ground.halfExtent && std::abs(g.z) < s.ground.halfExtent) hit = g;
        } else if (inside(g, 0.05f) && inside(w, 0.05f)) {
          hit = w;
          onWater = true;
        } else {
          continue;  // the rim, or a wall
        }
      }
      // The sphere, where it is in front; its silhouette is left out.
      bool onSphere = false;
      for (const auto& sphere : s.spheres) {
        const glm::vec3 oc = eye - sphere.center;
        const float b = glm::dot(oc, d), disc = b * b - (glm::dot(oc, oc) - sphere.radius * sphere.radius);
        if (std::abs(disc) < 0.02f * sphere.radius * sphere.radius) {
          hit.reset();
          onWater = false;
          break;
        }
        const float ts = -b - std::sqrt(std::max(disc, 0.0f));
        if (disc > 0.0f && ts > 0.0f && (!hit || ts < glm::length(*hit - eye))) {
          hit = eye + ts * d;
          onWater = false;
          onSphere = true;
          const glm::vec3 expectedNormal = glm::normalize(*hit - sphere.center);
          const glm::vec3 gotNormal(frame.normal[k], frame.normal[k + 1], frame.normal[k + 2]);
          ASSERT_LT(glm::length(gotNormal - expectedNormal), 0.05f) << x << "," << y;  // a tessellated sphere
        }
      }
      if (!hit && std::isinf(z)) {
        if (d.y > 0.01f) ++sky;
        continue;
      }
      if (!hit) {
        if (d.y > 0.01f && !onSphere) {  // clearly sky
          EXPECT_TRUE(std::isinf(z) && std::isinf(p.x)) << x << "," << y;
          EXPECT_EQ(n, glm::vec3(0.0f)) << x << "," << y;
          ++sky;
        }
        continue;
      }
      const float distance = glm::length(*hit - eye);
      if (distance > 30.0f) continue;  // far grazing pixels: one pixel spans metres
      // A tessellated sphere is within (1 - cos(pi/64)) of the true one: 0.1% of its radius.
      const float tolerance = onSphere ? 2e-3f * (1.0f + distance) : 1e-3f * (1.0f + distance);
      ASSERT_LT(glm::length(p - *hit), tolerance) << x << "," << y;
      if (!onSphere) {
        ASSERT_LT(glm::length(n - glm::vec3(0.0f, 1.0f, 0.0f)), 1e-5f) << x << "," << y;
      }
      ASSERT_NEAR(z, -(u.view * glm::vec4(*hit, 1.0f)).z, tolerance) << x << "," << y;
      (onSphere ? spherePixels : onWater ? water : ground)++;
    }
  }
  EXPECT_GT(water, 2000);
  EXPECT_GT(ground, 2000);
  EXPECT_GT(sky, 500);
  EXPECT_GT(spherePixels, 200);

  // A frame that does not ask for them does not pay for them.
  const auto plain = renderer.render({.frame = 3, .hdr = true});
  for (const auto& pass : plain.passes) EXPECT_NE(pass.name, "aov");
  EXPECT_TRUE(plain.position.empty());
}

namespace {

// Distance to the sphere along a unit ray, or -1; `margin` reports how close
// the ray passes to the silhouette (relative to r^2), for leaving those out.
float rayToSphere(glm::vec3 o, glm::vec3 d, const scene::Sphere& s, float& margin) {
  const glm::vec3 oc = o - s.center;
  const float b = glm::dot(oc, d), disc = b * b - (glm::dot(oc, oc) - s.radius * s.radius);
  margin = std::abs(disc) / (s.radius * s.radius);
  if (disc < 0.0f) return -1.0f;
  const float t = -b - std::sqrt(disc);
  return t > 0.0f ? t : -1.0f;
}

}  // namespace

// The water reflects the sphere where, and only where, the reflected ray meets
// it: the frame with the sphere and the frame without differ exactly at the
// pixels where a CPU ray cast says the reflected ray hits it (leaving out
// pixels that see the sphere directly or through the water).
TEST_F(WaterRenderTest, WaterReflectsTheSphereWhereTheReflectedRayMeetsIt) {
  scene::Scene with = scene::defaultScene();
  with.water.drops.clear();
  // A sphere hovering over the water, seen from low over the pool: its
  // reflection is clear of its direct image and of anything refracted.
  with.spheres = {{{0.9f, 0.4f, -0.7f}, 0.45f, {0.8f, 0.32f, 0.2f}}};
  with.camera.position = {-1.6f, 0.15f, -0.6f};
  with.camera.target = {0.9f, 0.0f, -0.7f};
  with.camera.fovYDegrees = 50.0f;
  with.render.shadows = false;  // the answer is the reflection alone, not the sphere's shadow
  scene::Scene without = with;
  without.spheres.clear();
  render::Renderer a(ctx(), with, kWidth, kHeight), b(ctx(), without, kWidth, kHeight);
  const auto fa = a.render({.hdr = true}), fb = b.render({.hdr = true});
  const auto u = render::frameUniforms(with, kWidth, kHeight);
  const glm::vec3 eye(u.cameraPosition);
  const scene::Sphere& sphere = with.spheres.front();
  const float half = 0.5f * with.water.extent;
  int reflecting = 0, notReflecting = 0;
  for (uint32_t y = 0; y < kHeight; ++y) {
    for (uint32_t x = 0; x < kWidth; ++x) {
      const glm::vec3 d = pixelRay(u, x, y);
      if (d.y >= 0.0f) continue;
      const glm::vec3 g = eye + ((with.ground.height - eye.y) / d.y) * d;
      const glm::vec3 p = eye + ((with.water.level - eye.y) / d.y) * d;
      if (std::max(std::abs(g.x), std::abs(g.z)) > half - 0.05f ||
          std::max(std::abs(p.x), std::abs(p.z)) > half - 0.05f) {
        continue;  // not through the hole onto the water
      }
      float m1 = 0, m2 = 0, m3 = 0;
      const float direct = rayToSphere(eye, d, sphere, m1);
      const glm::vec3 n(0.0f, 1.0f, 0.0f);
      const glm::vec3 t = refractGlsl(d, n, 1.0f / with.water.ior);
      const float refracted = rayToSphere(p, glm::normalize(t), sphere, m2);
      const float reflected = rayToSphere(p, glm::reflect(d, n), sphere, m3);
      if (direct > 0.0f || refracted > 0.0f || std::min({m1, m2, m3}) < 0.05f) continue;
      const glm::vec3 ca = pixel(fa, x, y), cb = pixel(fb, x, y);
      if (reflected > 0.0f) {
        EXPECT_GT(glm::length(ca - cb), 1e-3f * glm::length(cb)) << x << "," << y;
        ++reflecting;
      } else {
        EXPECT_LE(glm::length(ca - cb), 1e-6f * glm::length(cb)) << x << "," << y;
        ++notReflecting;
      }
    }
  }
  EXPECT_GT(reflecting, 200);
  EXPECT_GT(notReflecting, 2000);
}

using SkyImageTest = GpuTest;

// A sky image of constant radiance L lights an up-facing Lambertian surface
// with E = pi L, so the ground shows albedo * L; the sky shows L; and with a
// sky image the procedural sky pass is never recorded.
TEST_F(SkyImageTest, ConstantSkyImageLightsTheGroundExactly) {
  ScratchDir dir;
  const glm::vec3 radiance(0.3f, 0.45f, 0.6f);
  io::FloatImage sky{256, 128, {"R", "G", "B"}, {}};
  for (int k = 0; k < 256 * 128; ++k) sky.pixels.insert(sky.pixels.end(), {radiance.r, radiance.g, radiance.b});
  io::writeExr(dir.file("sky.exr"), sky, std::vector<io::PixelType>(3, io::PixelType::Float));

  scene::Scene s = checkerScene();
  s.water.enabled = false;
  s.spheres.clear();
  s.ground.albedoA = s.ground.albedoB = glm::vec3(0.5f, 0.4f, 0.3f);  // no checker edges to avoid
  s.sky.image = dir.file("sky.exr");
  render::Renderer renderer(ctx(), s, kWidth, kHeight);
  const auto frame = renderer.render({.hdr = true});
  for (const auto& pass : frame.passes) EXPECT_NE(pass.name, "sky");

  const auto u = render::frameUniforms(s, kWidth, kHeight);  // camera only: the light here is the image's
  int ground = 0, skyPixels = 0;
  for (uint32_t y = 0; y < kHeight; ++y) {
    for (uint32_t x = 0; x < kWidth; ++x) {
      const glm::vec3 d = pixelRay(u, x, y);
      const glm::vec3 got = pixel(frame, x, y);
      if (d.y < -0.05f) {
        // The irradiance is fitted from the sky's bins (sceneLight), whose
        // sum of the clamped cosine is a quadrature: measured 1.4e-4 of
        // pi L here and in SkyIrradiance.UniformSkyOverUniformGroundIsExact
        // (the exact texel-by-texel SH9 it replaced gave float round-off,
        // 1e-5, and SH9's bias under a peaked sky).
        for (int c = 0; c < 3; ++c) {
          ASSERT_NEAR(got[c], s.ground.albedoA[c] * radiance[c], 3e-4f * radiance[c]) << x << "," << y;
        }
        ++ground;
      } else if (d.y > 0.05f) {
        for (int c = 0; c < 3; ++c)
          ASSERT_NEAR(got[c], radiance[c], 1e-3f * radiance[c]) << x << "," << y;  // half texels
        ++skyPixels;
      }
    }
  }
  EXPECT_GT(ground, 10000);
  EXPECT_GT(skyPixels, 1000);
}

TEST(SkyImageCli, MissingOrUnfitSkyImagesFailCleanly) {
  ScratchDir dir;
  io::FloatImage gray{8, 4, {"Y"}, std::vector<float>(32, 0.5f)};
  io::writeExr(dir.file("gray.exr"), gray, {io::PixelType::Float});
  writeText(dir.file("missing.json"), "{\"sky\": {\"image\": \"nowhere.exr\"}}");
  writeText(dir.file("gray.json"), "{\"sky\": {\"image\": \"gray.exr\"}}");
  const std::vector<std::string> files{"gray.exr", "missing.json", "gray.json"};
  EXPECT_NE(expectCleanFailure("render --scene " + dir.file("missing.json") + " --out " + dir.file("x.exr"), dir, files)
                .find("nowhere.exr"),
            std::string::npos);
  EXPECT_NE(expectCleanFailure("render --scene " + dir.file("gray.json") + " --out " + dir.file("x.exr"), dir, files)
                .find("R, G and B"),
            std::string::npos);
}

// The apparent-depth mode is exact where its assumption holds (flat water over
// a flat floor at the mean depth: the refracted ray's mean-depth point is its
// true hit), and only an approximation where it does not (waves, terrain).
// The bound was 1e-3 while the floor's light was the same everywhere. The
// pool's baked light changes over the floor, by texels of a quarter metre
// and most within one of the walls, and the apparent mode reads it from the
// frame's image of the floor, bilinearly between its pixels: measured worst
// 3.7e-3 over 13108 pixels.
TEST_F(WaterRenderTest, ApparentDepthAgreesWhereItsAssumptionHolds) {
  constexpr float kApparentBound = 5e-3f;
  scene::Scene accurate = flatWaterFromAbove();
  // The accurate mode traces the floor itself and sees no SSAO, the apparent
  // mode reads the frame's own image of it, AO included: compare without.
  accurate.ao.enabled = false;
  scene::Scene apparent = accurate;
  apparent.render.refraction = "apparent";
  render::Renderer ra(ctx(), accurate, kWidth, kHeight), rb(ctx(), apparent, kWidth, kHeight);
  const auto fa = ra.render({.hdr = true}), fb = rb.render({.hdr = true});
  const auto u = render::frameUniforms(accurate, kWidth, kHeight);
  const float half = 0.5f * accurate.water.extent, floorY = accurate.ground.height - accurate.pool.depth;
  int compared = 0;
  for (uint32_t y = 1; y + 1 < kHeight; ++y) {
    for (uint32_t x = 1; x + 1 < kWidth; ++x) {
      const glm::vec3 d = pixelRay(u, x, y);
      const glm::vec3 p = glm::vec3(u.cameraPosition) + ((accurate.water.level - u.cameraPosition.y) / d.y) * d;
      const glm::vec3 t = refractGlsl(d, {0.0f, 1.0f, 0.0f}, 1.0f / accurate.water.ior);
      const glm::vec3 hit = p + ((floorY - p.y) / t.y) * t;
      if (std::max(std::abs(hit.x), std::abs(hit.z)) > half - 0.1f) continue;
      const glm::vec2 q = glm::vec2(hit.x, hit.z) / accurate.pool.tileSize, f = q - glm::floor(q);
      if (f.x < 0.2f || f.x > 0.8f || f.y < 0.2f || f.y > 0.8f) continue;  // texel quantisation at tile edges
      const glm::vec3 a = pixel(fa, x, y), b = pixel(fb, x, y);
      ASSERT_LT(glm::length(a - b), kApparentBound * glm::length(a)) << x << "," << y;
      ++compared;
    }
  }
  EXPECT_GT(compared, 3000);

  // Waves and terrain break the assumption: the modes then differ.
  scene::Scene wavy = scene::defaultScene(), wavyApparent = wavy;
  wavyApparent.render.refraction = "apparent";
  render::Renderer wa(ctx(), wavy, kWidth, kHeight), wb(ctx(), wavyApparent, kWidth, kHeight);
  const auto ga = wa.render({.frame = 12, .hdr = true}), gb = wb.render({.frame = 12, .hdr = true});
  double difference = 0.0;
  for (size_t k = 0; k < ga.rgba.size(); ++k) difference += std::abs(ga.rgba[k] - gb.rgba[k]);
  EXPECT_GT(difference / double(ga.rgba.size()), 1e-3);
  EXPECT_TRUE(render::findPass(gb.passes, render::passes::kUnderwater));
  EXPECT_FALSE(render::findPass(ga.passes, render::passes::kUnderwater));
}

// A sphere on a path stirs calm water; the same sphere held still does not.
TEST_F(WaterRenderTest, MovingSphereStirsCalmWater) {
  scene::Scene still = scene::defaultScene();
  still.water.drops.clear();
  scene::Scene moving = still;
  moving.spheres[0].path = {{0.0f, {0.9f, 0.4f, -0.7f}}, {0.4f, {0.9f, -0.3f, -0.7f}}};
  render::Renderer a(ctx(), still, 96, 64), b(ctx(), moving, 96, 64);
  EXPECT_EQ(a.render({.frame = 0}).rgba, a.render({.frame = 12}).rgba);
  const auto b0 = b.render({.frame = 0}), b12 = b.render({.frame = 12});
  EXPECT_NE(b0.rgba, b12.rgba);
  render::Renderer again(ctx(), moving, 96, 64);
  EXPECT_EQ(again.render({.frame = 12}).rgba, b12.rgba);  // deterministic, with the moves between steps
}

// Caustics: under flat water with the sun overhead every patch of the surface
// sends the sun to a patch of the same area, so the floor is lit exactly as
// without caustics; under waves the light gathers and spreads, and the water
// neither makes nor loses light on average (the ratios' mean stays near 1).
TEST_F(WaterRenderTest, CausticsAreUniformUnderFlatWaterAndConserveLightUnderWaves) {
  scene::Scene s = flatWaterFromAbove();
  s.sky.sunElevationDegrees = 90.0f;
  s.sky.zenith = s.sky.horizon = s.sky.glow = glm::vec3(0.0f);  // the floor lit by the sun alone
  auto ratios = [&](const scene::Scene& scene, uint32_t frame) {
    scene::Scene on = scene, off = scene;
    on.render.caustics = true;
    off.render.caustics = false;
    render::Renderer ra(ctx(), on, kWidth, kHeight), rb(ctx(), off, kWidth, kHeight);
    const auto a = ra.render({.frame = frame, .hdr = true}), b = rb.render({.frame = frame, .hdr = true});
    std::vector<float> r;
    // The middle of the image: the floor through the water, clear of the walls.
    for (uint32_t y = kHeight / 4; y < 3 * kHeight / 4; ++y) {
      for (uint32_t x = kWidth / 4; x < 3 * kWidth / 4; ++x) r.push_back(pixel(a, x, y).g / pixel(b, x, y).g);
    }
    return r;
  };
  for (float r : ratios(s, 0)) ASSERT_NEAR(r, 1.0f, 1e-3f);

  scene::Scene waves = s;
  waves.water.drops = scene::defaultScene().water.drops;
  for (auto& d : waves.water.drops) {
    d.x = 0.3f + 0.5f * d.x;  // under the camera
    d.z = 0.2f + 0.5f * d.z;
  }
  const auto r = ratios(waves, 10);
  double mean = 0.0;
  for (float v : r) mean += v;
  mean /= double(r.size());
  const auto [lo, hi] = std::minmax_element(r.begin(), r.end());
  std::printf("caustic ratio under waves: mean %.4f, min %.3f, max %.3f\n", mean, *lo, *hi);
  EXPECT_GT(*hi, 1.3f);
  EXPECT_LT(*lo, 0.8f);
  EXPECT_NEAR(mean, 1.0, 0.02);  // measured 0.9994 on lavapipe
}

}  // namespace tp::test
