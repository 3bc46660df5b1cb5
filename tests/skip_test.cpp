// What a frame skips, proved by its counters and checked against the frame
// rendered with nothing skipped (RendererOptions::skipping off): the same bits
// where the skipped work cannot change a pixel, and within the stated bound
// where it can (sleeping water, render/water_sleep.hpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

#include "gpu/submit.hpp"
#include "gpu_test.hpp"
#include "graph/frame_graph.hpp"
#include "io/image_io.hpp"
#include "process.hpp"
#include "render/pass_kinds.hpp"
#include "render/renderer.hpp"
#include "shading/objects_model.hpp"
#include "shading/pool_model.hpp"
#include "shading/water_model.hpp"
#include "sim/water_sleep.hpp"

namespace tp::test {
namespace {

constexpr uint32_t kWidth = 96, kHeight = 64;

bool recorded(const render::RenderedFrame& f, const render::PassKind& pass) { return render::findPass(f.passes, pass); }

const render::RecordedPass* find(const render::RenderedFrame& f, const render::PassKind& pass) {
  return render::findPass(f.passes, pass);
}

bool anyPassUses(const render::RenderedFrame& f, const std::string& resource) {
  for (const auto& p : f.passes) {
    if (std::find(p.resources.begin(), p.resources.end(), resource) != p.resources.end()) return true;
  }
  return false;
}

// The frame's passes and what they recorded, less the water surface's:
// skipping shades it deferred (render/water_deferred.hpp), in four passes
// where the frame with nothing skipped draws it forward in one.
struct OutsideWater {
  size_t passes = 0;
  gpu::CommandCounts counts;
};

OutsideWater outsideWater(const render::RenderedFrame& f) {
  OutsideWater o;
  for (const auto& p : f.passes) {
    if (render::passes::isWater(p.kind)) continue;
    ++o.passes;
    o.counts += p.counts;
  }
  return o;
}

// The pool pass's draws: where the walls' bands under the water give their
// depth and normal alone, they take a draw of their own (render/pool.cpp),
// one more than the frame with nothing skipped, with far less to shade.
uint64_t poolDraws(const render::RenderedFrame& f) {
  uint64_t draws = 0;
  for (const auto& p : f.passes)
    if (p.kind == &render::passes::kPool) draws += p.counts.draws;
  return draws;
}

// Pixels whose RGBA differs in any bit.
size_t differingPixels(const render::RenderedFrame& a, const render::RenderedFrame& b) {
  size_t n = 0;
  for (size_t p = 0; p < a.rgba.size(); p += 4) {
    if (!std::equal(a.rgba.begin() + p, a.rgba.begin() + p + 4, b.rgba.begin() + p)) ++n;
  }
  return n;
}

// A terrain as high as the pool allows under water lowered to meet it: the
// floor comes through the water's surface.
void raiseTheFloorThroughTheWater(scene::Scene& s) {
  s.terrain.amplitude = 2.0f * s.pool.depth;
  s.water.level = -0.6f;
}

struct Variant {
  std::string name;
  std::function<void(scene::Scene&, const std::string& dir)> change;
  // What the skipping renderer must never record, on any frame.
  std::vector<const render::PassKind*> neverPasses;
  std::vector<std::string> neverResources;
};

}  // namespace

using SkipTest = GpuTest;

// For each scene variant, frames 0, 1, 2 and 0 again with skipping on and
// off: what the variant does not need is never recorded, and the images are
// the same bits.
TEST_F(SkipTest, EachVariantSkipsWhatItDoesNotNeedAndDrawsTheSameBits) {
  ScratchDir dir;
  const std::vector<Variant> variants{
      {"everything on",
       [](scene::Scene&, const std::string&) {},
       {&render::passes::kCameraMedium, &render::passes::kAoApply},
       {}},
      {"no water",
       [](scene::Scene& s, const std::string&) { s.water.enabled = false; },
       {&render::passes::kSimulate, &render::passes::kWater, &render::passes::kCaustics, &render::passes::kCameraMedium,
        &render::passes::kUnderwater},
       {}},
      {"calm water",
       [](scene::Scene& s, const std::string&) { s.water.drops.clear(); },
       {&render::passes::kSimulate, &render::passes::kCameraMedium},
       {}},
      {"AO off",
       [](scene::Scene& s, const std::string&) { s.ao.enabled = false; },
       {&render::passes::kSsao, &render::passes::kAoBlurX, &render::passes::kAoBlurY, &render::passes::kAoUpsample,
        &render::passes::kAoApply},
       {"view normal", "ambient"}},
      {"sky image",
       [](scene::Scene& s, const std::string& d) {
         io::FloatImage sky{64, 32, {"R", "G", "B"}, {}};
         for (int k = 0; k < 64 * 32; ++k)
           sky.pixels.insert(sky.pixels.end(), {0.3f, 0.4f + 0.001f * float(k % 64), 0.6f});
         io::writeExr(d + "/sky.exr", sky, std::vector<io::PixelType>(3, io::PixelType::Float));
         s.sky.image = d + "/sky.exr";
       },
       {&render::passes::kSky},
       {}},
      {"objects out of view",
       [](scene::Scene& s, const std::string&) {
         s.spheres[0].center = {8.0f, 0.5f, 12.0f};  // behind the camera
         s.boxes.push_back({.center = {-30.0f, 0.5f, 0.0f}});
       },
       {&render::passes::kObjects, &render::passes::kCameraMedium},
       {}},
      {"sphere above the water",
       [](scene::Scene& s, const std::string&) {
         s.spheres[0].center = {0.3f, 0.9f, -0.2f};  // bottom 0.45 m over the rim: left out of the casts below
         s.boxes.push_back({.center = {-0.8f, 0.2f, 0.6f}, .size = {0.3f, 0.6f, 0.3f}});  // reaches into the pool
       },
       {&render::passes::kCameraMedium},
       {}},
      {"a sphere's shadow on the ground",
       [](scene::Scene& s, const std::string&) {
         s.spheres[0].center = {-2.6f, 0.4f, -1.0f};  // resting on the ground past the far wall
       },
       {},
       {}},
      {"water that scatters, the camera under it",
       [](scene::Scene& s, const std::string&) {
         s.water.scattering = {0.08f, 0.12f, 0.14f};
         s.camera.position = {-1.4f, -0.75f, 1.5f};
         s.camera.target = {0.9f, -0.2f, -0.7f};
       },
       {},
       {}},
      {"glass in the water and out of view",
       [](scene::Scene& s, const std::string&) {
         // The water's rays meet it (its shaders' glass variants); the other is behind the camera.
         s.spheres.push_back({.center = {0.8f, s.water.level, 0.5f}, .radius = 0.3f, .material = "glass"});
         s.spheres.push_back({.center = {8.0f, 0.5f, 12.0f}, .radius = 0.3f, .material = "glass", .ior = 1.33f});
       },
       {&render::passes::kCameraMedium},
       {}},
      // In the variants above the camera sees the floor only through the
      // water, and the floor gives its depth and normal alone; in the next
      // three its own light shows: the apparent-depth mode reads the frame
      // drawn under the water, a floor that rises above the water's level
      // comes through it, and a camera over a wall's plane looks down the
      // slot between the water's mesh and that wall.
      {"apparent refraction", [](scene::Scene& s, const std::string&) { s.render.refraction = "apparent"; }, {}, {}},
      {"a floor that comes through the water",
       [](scene::Scene& s, const std::string&) { raiseTheFloorThroughTheWater(s); },
       {},
       {}},
      {"camera over a wall's plane",
       [](scene::Scene& s, const std::string&) {
         s.camera.position = {0.5f * s.water.extent + 0.005f, 1.0f, 1.2f};
         s.camera.target = {0.5f * s.water.extent - 0.4f, -1.0f, -1.0f};
       },
       {},
       {}},
      {"camera over the water",
       [](scene::Scene& s, const std::string&) {
         s.camera.position = {0.6f, 1.6f, 1.2f};
         s.camera.target = {0.0f, -0.3f, -0.5f};
       },
       {},
       {}},
      // Skipping takes the AO after the water, which clears the ambient part
      // where it is seen, from below too; with nothing skipped the AO is
      // applied before the water.
      {"camera under the water",
       [](scene::Scene& s, const std::string&) {
         s.camera.position = {-1.4f, -0.75f, 1.5f};
         s.camera.target = {0.9f, -0.2f, -0.7f};
       },
       {&render::passes::kAoApply},
       {}},
  };
  for (const Variant& v : variants) {
    SCOPED_TRACE(v.name);
    scene::Scene s = scene::defaultScene();
    v.change(s, dir.path().string());
    render::Renderer skipping(ctx(), s, kWidth, kHeight);
    render::Renderer everything(ctx(), s, kWidth, kHeight, {.skipping = false});
    const uint32_t sequence[] = {0, 1, 2, 0};  // the last goes back: the water restarts
    for (size_t i = 0; i < std::size(sequence); ++i) {
      const uint32_t frame = sequence[i];
      SCOPED_TRACE("frame " + std::to_string(frame) + " (" + std::to_string(i) + ")");
      const auto a = skipping.render({.frame = frame, .ldr = true});
      const auto b = everything.render({.frame = frame, .ldr = true});
      EXPECT_EQ(differingPixels(a, b), 0u);
      EXPECT_TRUE(a.srgb == b.srgb);
      for (const auto* pass : v.neverPasses) EXPECT_FALSE(recorded(a, *pass)) << pass->name;
      for (const auto& resource : v.neverResources) EXPECT_FALSE(anyPassUses(a, resource)) << resource;
      const OutsideWater oa = outsideWater(a), ob = outsideWater(b);
      EXPECT_LE(oa.passes, ob.passes);
      EXPECT_LE(oa.counts.dispatches, ob.counts.dispatches);
      EXPECT_LE(oa.counts.draws - poolDraws(a), ob.counts.draws - poolDraws(b));
      EXPECT_LE(poolDraws(a), poolDraws(b) + 1);
      EXPECT_LE(oa.counts.workgroups, ob.counts.workgroups);
      // The water's too: its mesh drawn no more often.
      EXPECT_LE(a.counts.draws - poolDraws(a), b.counts.draws - poolDraws(b));
      // Passes whose inputs do not change run on the first frame only.
      if (s.sky.image.empty()) {
        EXPECT_EQ(recorded(a, render::passes::kSky), i == 0);
      }
      if (s.water.enabled && s.render.caustics) {
        EXPECT_EQ(recorded(a, render::passes::kCaustics), i == 0 || i == 3 || recorded(a, render::passes::kSimulate));
        EXPECT_TRUE(recorded(b, render::passes::kCaustics));
      }
      // Still camera and objects: the opaque surfaces' depth and normals do
      // not change, so the AO made on the first frame stands.
      // Still frame uniforms: the ground drawn on the first frame stands.
      EXPECT_EQ(recorded(a, render::passes::kGround), i == 0);
      EXPECT_TRUE(recorded(a, render::passes::kGroundCopy));
      if (s.ao.enabled) {
        EXPECT_EQ(recorded(a, render::passes::kSsao), i == 0);
        EXPECT_EQ(recorded(a, render::passes::kAoBlurY), i == 0);
        EXPECT_TRUE(recorded(b, render::passes::kSsao));
      }
      // With nothing skipped, the scene's every pass is there.
      if (s.water.enabled && frame > 0) {
        EXPECT_TRUE(recorded(b, render::passes::kSimulate));
        EXPECT_TRUE(recorded(b, render::passes::kCameraMedium));
      }
      EXPECT_TRUE(recorded(b, render::passes::kObjects));
      EXPECT_TRUE(anyPassUses(b, "view normal"));
    }
  }
}

// The SSAO and its blur run again when what the opaque surfaces' depth and
// normals follow from changes (render/opaque_geometry.hpp): the camera, a
// sample's jitter, a sphere dragged or on its path. Each frame is the frame
// of a renderer that records everything, given the same calls, to the bit.
TEST_F(SkipTest, TheAoIsMadeAgainOnlyWhenTheOpaqueSurfacesMayHaveChanged) {
  scene::Scene s = scene::defaultScene();
  s.spheres.push_back({.center = {-2.6f, 0.4f, -1.0f}, .radius = 0.4f});  // on the ground past the far wall
  scene::Camera turned = s.camera;
  turned.position = {3.0f, 1.6f, 4.6f};
  struct Step {
    std::string what;
    std::function<void(render::Renderer&)> change;
    render::FrameRequest request;
    bool ssao;  // the skipping renderer makes the AO again
  };
  const std::vector<Step> steps{
      {"first frame", [](render::Renderer&) {}, {.frame = 0}, true},
      {"nothing moved", [](render::Renderer&) {}, {.frame = 1}, false},
      {"the camera moved", [&](render::Renderer& r) { r.setCamera(turned); }, {.frame = 2}, true},
      {"still again", [](render::Renderer&) {}, {.frame = 3}, false},
      {"a sphere dragged on the ground",
       [](render::Renderer& r) {
         r.moveSphere(1, {-2.2f, 0.4f, -1.3f});
       },
       {.frame = 4},
       true},
      {"still again", [](render::Renderer&) {}, {.frame = 5}, false},
      {"a jittered sample", [](render::Renderer&) {}, {.frame = 6, .pixelOffset = {0.25f, -0.25f}}, true},
      {"the same sample", [](render::Renderer&) {}, {.frame = 7, .pixelOffset = {0.25f, -0.25f}}, false},
      {"the camera back", [&](render::Renderer& r) { r.setCamera(s.camera); }, {.frame = 8}, true},
  };
  render::Renderer skipping(ctx(), s, kWidth, kHeight);
  render::Renderer everything(ctx(), s, kWidth, kHeight, {.skipping = false});
  for (const Step& step : steps) {
    SCOPED_TRACE(step.what + ", frame " + std::to_string(step.request.frame));
    step.change(skipping);
    step.change(everything);
    render::FrameRequest request = step.request;
    request.ldr = true;
    const auto a = skipping.render(request);
    const auto b = everything.render(request);
    EXPECT_EQ(differingPixels(a, b), 0u);
    EXPECT_TRUE(a.srgb == b.srgb);
    EXPECT_EQ(recorded(a, render::passes::kSsao), step.ssao);
    EXPECT_EQ(recorded(a, render::passes::kAoBlurX), step.ssao);
    // The same changes change the frame's uniforms (the camera, the shadows'
    // casters): the ground is drawn again.
    EXPECT_EQ(recorded(a, render::passes::kGround), step.ssao);
  }

  // A sphere on a path moves every frame: the AO is made every frame.
  s.spheres[1].path = {{0.0f, {-2.6f, 0.4f, -1.0f}}, {1.0f, {-2.0f, 0.4f, -1.6f}}};
  render::Renderer moving(ctx(), s, kWidth, kHeight);
  render::Renderer movingEverything(ctx(), s, kWidth, kHeight, {.skipping = false});
  for (uint32_t frame = 0; frame < 3; ++frame) {
    SCOPED_TRACE("a sphere on a path, frame " + std::to_string(frame));
    const auto a = moving.render({.frame = frame});
    EXPECT_TRUE(a.rgba == movingEverything.render({.frame = frame}).rgba);
    EXPECT_TRUE(recorded(a, render::passes::kSsao));
  }
}

// The resolve of a frame shown alone works on the tiles whose pixels may
// differ from the last frame's (render/frame_resolve.hpp), and leaves the rest
// of the 8-bit image as the last frame left it: each frame's 8-bit image is
// the renderer's with nothing skipped, to the bit.
namespace {

struct StillStep {
  std::string what;
  std::function<void(render::Renderer&)> change = {};
  bool hdr = false;
  bool partly = true;  // the skipping renderer resolves some tiles, not all
};

void expectTheSameBits(const gpu::Context& ctx, const scene::Scene& s, const std::vector<StillStep>& steps) {
  render::Renderer skipping(ctx, s, kWidth, kHeight);
  render::Renderer everything(ctx, s, kWidth, kHeight, {.skipping = false});
  for (uint32_t frame = 0; frame < steps.size(); ++frame) {
    const StillStep& step = steps[frame];
    SCOPED_TRACE(step.what + ", frame " + std::to_string(frame));
    if (step.change) {
      step.change(skipping);
      step.change(everything);
    }
    const render::FrameRequest request{.frame = frame, .hdr = step.hdr, .ldr = true};
    const auto a = skipping.render(request);
    const auto b = everything.render(request);
    EXPECT_TRUE(a.srgb == b.srgb);
    ASSERT_GT(a.frameTiles, 0u);
    EXPECT_EQ(b.frameTiles, 0u);
    if (step.partly) {
      EXPECT_LT(a.resolvedTiles, a.frameTiles);
    } else {
      EXPECT_EQ(a.resolvedTiles, a.frameTiles);
    }
  }
}

scene::Scene withoutAoOrShadows() {
  scene::Scene s = scene::defaultScene();
  s.ao.enabled = false;
  s.render.shadows = false;
  return s;
}

}  // namespace

// From a camera low over the ground a crest over the rim stands against the
// far ground, outside the pool's opening, and moves: where it was in the
// last frame is resolved again.
TEST_F(SkipTest, TheResolveOfAStillFrameTakesTheWaterWhereItWasAndIs) {
  scene::Scene s = withoutAoOrShadows();
  s.spheres.clear();
  s.water.level = -0.02f;
  s.water.drops = {{.x = 0.0f, .z = -0.6f, .radius = 0.35f, .amplitude = 0.5f, .frame = 0}};
  s.camera.position = {0.0f, 0.25f, 4.0f};
  s.camera.target = {0.0f, 0.25f, 0.0f};
  std::vector<StillStep> steps{{.what = "first frame", .partly = false}};
  for (int k = 0; k < 24; ++k) steps.push_back({.what = "the crest over the rim, falling"});
  expectTheSameBits(ctx(), s, steps);
  // The crest did stand over the rim.
  render::Renderer r(ctx(), s, kWidth, kHeight);
  r.render({.frame = 1, .hdr = false});
  const std::vector<float> u = r.waterState().u;
  EXPECT_GT(s.water.level + *std::max_element(u.begin(), u.end()), s.ground.height + 0.1f);
}

// A sphere dragged on the ground, with neither AO nor shadows to change the
// rest of the frame, the pool out of view: where it was and where it is are
// resolved again. A frame that stores its HDR colour, or whose camera moved,
// resolves every tile.
TEST_F(SkipTest, TheResolveOfAStillFrameTakesTheObjectsWhereTheyWereAndAre) {
  scene::Scene s = withoutAoOrShadows();
  s.camera.position = {0.0f, 1.2f, 5.0f};
  s.camera.target = {0.0f, 0.3f, 10.0f};  // away from the pool
  s.spheres.push_back({.center = {-1.0f, 0.3f, 9.0f}, .radius = 0.3f});
  scene::Camera turned = s.camera;
  turned.target = {0.3f, 0.3f, 10.0f};
  const auto drag = [](glm::vec3 to) { return [to](render::Renderer& r) { r.moveSphere(1, to); }; };
  expectTheSameBits(
      ctx(), s,
      {{.what = "first frame", .partly = false},
       {.what = "still"},
       {.what = "the sphere dragged right", .change = drag({1.0f, 0.3f, 9.0f})},
       {.what = "still"},
       {.what = "the HDR image read back", .hdr = true, .partly = false},
       {.what = "after it"},
       {.what = "the camera turned", .change = [&](render::Renderer& r) { r.setCamera(turned); }, .partly = false},
       {.what = "still again"},
       {.what = "the sphere dragged back", .change = drag({-1.0f, 0.3f, 9.0f})}});
}

// When the floor gives its depth and normal alone (render/pool.cpp).
TEST(SkipFloor, TheFloorIsSeenOnlyThroughWaterOverItFromTheAirAwayFromTheWalls) {
  const scene::Scene s = scene::defaultScene();
  const float top = render::poolParams(s).terrain.w;
  const float calm = 0.05f;              // metres over and under the rest level
  ASSERT_LT(top, s.water.level - 0.5f);  // the default floor: deep under the water
  EXPECT_TRUE(render::floorSeenOnlyThroughWater(s, calm, top));
  EXPECT_FALSE(render::floorSeenOnlyThroughWater(s, s.water.level - top + 0.01f, top));      // a trough to the floor
  EXPECT_FALSE(render::floorSeenOnlyThroughWater(s, s.ground.height - s.water.level, top));  // a crest at the rim
  EXPECT_FALSE(render::floorSeenOnlyThroughWater(s, std::numeric_limits<float>::infinity(), top));  // no stats yet
  scene::Scene apparent = s;
  apparent.render.refraction = "apparent";
  EXPECT_FALSE(render::floorSeenOnlyThroughWater(apparent, calm, top));
  scene::Scene over = s;
  over.camera.position = {0.6f, 1.6f, 1.2f};
  EXPECT_FALSE(render::floorSeenOnlyThroughWater(over, calm, top));
  // Near a wall's plane, a line steep enough across the wall finds the slot
  // between the water's mesh and the wall; further out, higher is steeper.
  const float half = 0.5f * s.water.extent;
  scene::Scene beside = s;
  beside.camera.position = {half + 0.01f, 1.3f, 2.8f};
  EXPECT_FALSE(render::floorSeenOnlyThroughWater(beside, calm, top));
  beside.camera.position = {half + 0.5f, 1.3f, 2.8f};
  EXPECT_TRUE(render::floorSeenOnlyThroughWater(beside, calm, top));
  beside.camera.position = {half + 0.5f, 40.0f, 2.8f};
  EXPECT_FALSE(render::floorSeenOnlyThroughWater(beside, calm, top));
  beside.camera.position = {half + 0.5f, s.ground.height - 0.01f, 2.8f};  // under the ground
  EXPECT_FALSE(render::floorSeenOnlyThroughWater(beside, calm, top));
  // SkipTest's variant whose floor comes through the water reaches above its level.
  scene::Scene high = s;
  raiseTheFloorThroughTheWater(high);
  EXPECT_GT(render::poolParams(high).terrain.w, high.water.level);
}

// What the rays under the water can meet: the objects reaching below the
// water's top come first and are counted in count.zw; the rest only in count.xy.
TEST(SkipObjects, ObjectsWhollyOverTheWaterAreLeftOutOfTheCastsBelowIt) {
  scene::Scene s = scene::defaultScene();
  s.spheres = {{{0.0f, 1.0f, 0.0f}, 0.5f}, {{1.0f, 0.2f, 0.0f}, 0.3f}, {{-1.0f, 0.49f, 0.0f}, 0.5f}};
  s.boxes = {{.center = {0.0f, 0.5f, 1.0f}, .size = {1.0f, 0.8f, 1.0f}},
             {.center = {0.0f, 0.3f, -1.0f}, .size = {1.0f, 0.8f, 1.0f}}};
  const shader::SceneObjects objects = render::sceneObjects(s, 0.0f);
  EXPECT_EQ(objects.count, glm::uvec4(3, 2, 2, 1));
  // Below first, each group in the scene's order.
  EXPECT_EQ(glm::vec3(objects.spheres[0]), glm::vec3(1.0f, 0.2f, 0.0f));
  EXPECT_EQ(glm::vec3(objects.spheres[1]), glm::vec3(-1.0f, 0.49f, 0.0f));
  EXPECT_EQ(glm::vec3(objects.spheres[2]), glm::vec3(0.0f, 1.0f, 0.0f));
  EXPECT_EQ(glm::vec3(objects.boxCenter[0]), glm::vec3(0.0f, 0.3f, -1.0f));
  EXPECT_EQ(render::sceneObjects(s).count, glm::uvec4(3, 2, 3, 2));  // no water top: every object
}

// The counters count what is recorded. The default scene's frame 1 steps
// its water `substeps` times over every tile, as it must after a (re)start:
// the plain kernel (64x1 groups over 128^2) but for the last step, which keeps
// the tile flags (16x16 groups), then one workgroup lists the tiles the next
// step would need, and the statistics measure the water (16x16 groups). Its
// surfaces draw once per mesh.
// The deferred water's G-buffer keeps what earlier frames stored where this
// frame's surface is not: a camera that comes close to the water and then
// backs away must shade none of it again. Each frame is the forward
// shader's bits.
TEST_F(SkipTest, DeferredWaterShadesOnlyWhatThisFrameCovers) {
  const scene::Scene s = scene::defaultScene();
  render::Renderer deferred(ctx(), s, kWidth, kHeight);
  render::Renderer forward(ctx(), s, kWidth, kHeight, {.skipping = false});
  scene::Camera close = s.camera;
  close.position = {0.8f, 0.6f, 0.9f};  // the water fills the frame
  close.target = {0.0f, -0.2f, 0.0f};
  for (const scene::Camera& camera : {close, s.camera}) {
    deferred.setCamera(camera);
    forward.setCamera(camera);
    const auto a = deferred.render({.frame = 0});
    const auto b = forward.render({.frame = 0});
    ASSERT_TRUE(recorded(a, render::passes::kWaterGbuffer));
    EXPECT_EQ(differingPixels(a, b), 0u);
  }
}

TEST_F(SkipTest, CountersMatchWhatThePassesRecord) {
  const scene::Scene s = scene::defaultScene();
  render::Renderer renderer(ctx(), s, kWidth, kHeight);
  const auto first = renderer.render({.frame = 0});
  const auto f = renderer.render({.frame = 1});
  const uint32_t substeps = sim::waterSubsteps(s.water);
  const uint32_t n = s.water.grid;
  const uint64_t tiles = (n / 16) * (n / 16);
  const render::RecordedPass* simulate = find(f, render::passes::kSimulate);
  ASSERT_NE(simulate, nullptr);
  EXPECT_EQ(simulate->counts.dispatches, substeps + 2);
  EXPECT_EQ(simulate->counts.workgroups, uint64_t(substeps - 1) * (n / 64) * n + tiles + 1 + tiles);
  EXPECT_EQ(simulate->counts.draws, 0u);
  // The ground and the sky drawn on the first frame; on the next their copy alone.
  EXPECT_EQ(find(first, render::passes::kGround)->counts.draws, 2u);  // the ground, the sky behind it
  EXPECT_EQ(find(f, render::passes::kGround), nullptr);
  EXPECT_EQ(find(f, render::passes::kGroundCopy)->counts.draws, 0u);
  // The floor, seen only through the water, gives the SSAO its depth and
  // normal on the first frame, and so do the walls' bands under the water;
  // on the next the AO stands and the floor is not drawn, and the cover
  // under the water leaves out the walls below it.
  EXPECT_EQ(find(first, render::passes::kPool)->counts.draws, 3u);  // walls lit, walls under, floor
  EXPECT_EQ(find(f, render::passes::kPool)->counts.draws, 2u);      // cover, walls
  EXPECT_EQ(find(f, render::passes::kObjects)->counts.draws, 1u);   // the sphere
  // The water deferred: the mesh seen from above into the G-buffer, its tiles
  // listed, its pixels shaded; then the mesh seen from below, forward.
  EXPECT_EQ(find(f, render::passes::kWaterGbuffer)->counts.draws, 1u);
  EXPECT_EQ(find(f, render::passes::kWaterTiles)->counts.dispatches, 1u);
  EXPECT_EQ(find(f, render::passes::kWater)->counts.dispatches, 1u);
  EXPECT_EQ(find(f, render::passes::kWater)->counts.draws, 0u);
  EXPECT_EQ(find(f, render::passes::kWaterBelow)->counts.draws, 1u);
  gpu::CommandCounts sum;
  for (const auto& p : f.passes) sum += p.counts;
  EXPECT_EQ(sum, f.counts);
}

// A drop on calm water: the frame after the one that dropped it steps only
// the tiles within reach of the ripple, and counts the tiles its indirect
// dispatches launched. Each step is a one-workgroup list and a dispatch of
// the listed tiles; step k after the drop can have changed only the cells
// within k of its footprint, so it lists at most the tiles over that square
// plus a ring of one tile, and at least the one under the drop's centre.
TEST_F(SkipTest, ActiveTilesAreCountedWhenTheyAreLaunched) {
  scene::Scene s = scene::defaultScene();
  s.water.drops.clear();
  render::Renderer renderer(ctx(), s, kWidth, kHeight);
  renderer.render({.frame = 0});
  const scene::Drop drop{0.5f, 0.5f, 0.15f, 0.05f};
  renderer.addDrop(drop);
  renderer.render({.frame = 1});  // after a start every tile is stepped once
  const auto f = renderer.render({.frame = 2});
  const uint32_t substeps = sim::waterSubsteps(s.water);
  const uint32_t n = s.water.grid, perSide = n / 16;
  const render::RecordedPass* simulate = find(f, render::passes::kSimulate);
  ASSERT_NE(simulate, nullptr);
  EXPECT_EQ(simulate->counts.dispatches, 2 * substeps + 1);
  const uint64_t stats = uint64_t(perSide) * perSide;
  ASSERT_GT(simulate->counts.workgroups, substeps + stats);
  const uint64_t listed = simulate->counts.workgroups - substeps - stats;

  const double h = double(s.water.extent) / n;
  const glm::vec3 c = sim::worldToGrid(s.water, {drop.x, 0.0f, drop.z});
  const int lo = int(std::floor((c.x - drop.radius) / h)), hi = int(std::ceil((c.x + drop.radius) / h));
  uint64_t bound = 0;
  for (uint32_t k = substeps + 1; k <= 2 * substeps; ++k) {
    // The footprint is square (the drop is at x = z): the same range on both axes.
    const int t0 = std::max(0, (lo - int(k - 1)) / 16 - 1);
    const int t1 = std::min(int(perSide) - 1, (hi + int(k - 1)) / 16 + 1);
    bound += uint64_t(t1 - t0 + 1) * (t1 - t0 + 1);
  }
  EXPECT_GE(listed, substeps);
  EXPECT_LE(listed, bound);
  EXPECT_LT(bound, uint64_t(substeps) * perSide * perSide);  // the bound itself leaves tiles out
  gpu::CommandCounts sum;
  for (const auto& p : f.passes) sum += p.counts;
  EXPECT_EQ(sum, f.counts);
}

// The graph's caching on its own: a cached pass runs again only when a
// resource it uses changes, by a pass's write or the host's touch.
TEST_F(SkipTest, CachedPassRunsOnlyWhenAnInputChanged) {
  auto make = [&](const char* name) {
    return gpu::createBuffer(ctx(), 256,
                             vk::BufferUsageFlagBits::eStorageBuffer | vk::BufferUsageFlagBits::eTransferDst |
                                 vk::BufferUsageFlagBits::eTransferSrc,
                             gpu::MemoryUse::Device, name);
  };
  gpu::Buffer input = make("input"), cachedOut = make("cached output"), result = make("result");
  render::FrameGraph graph;
  const render::GraphBuffer in = graph.buffer("input", input), out = graph.buffer("cached output", cachedOut),
                            res = graph.buffer("result", result);
  bool writeInput = true;
  int cachedRuns = 0;
  static constexpr render::PassKind kWriteInput{"write input"}, kCached{"cached"}, kUse{"use"};
  graph.pass(kWriteInput,
             [&](render::PassBuilder& pass) {
               const gpu::Buffer& b = pass.attach(in, render::Use::TransferWrite);
               return [&b](render::PassContext& pc) { pc.cmd.fillBuffer(b.handle(), 0, 256, 7u); };
             },
             {.cached = false, .runIf = [&] { return writeInput; }});
  graph.pass(kCached,
             [&](render::PassBuilder& pass) {
               const gpu::Buffer& from = pass.attach(in, render::Use::TransferRead);
               const gpu::Buffer& to = pass.attach(out, render::Use::TransferWrite);
               return [&](render::PassContext& pc) {
                 ++cachedRuns;
                 pc.cmd.copyBuffer(from.handle(), to.handle(), vk::BufferCopy{0, 0, 256});
               };
             },
             {.cached = true, .runIf = {}});
  graph.pass(kUse, [&](render::PassBuilder& pass) {
    const gpu::Buffer& from = pass.attach(out, render::Use::TransferRead);
    const gpu::Buffer& to = pass.attach(res, render::Use::TransferWrite);
    return [&from, &to](render::PassContext& pc) {
      pc.cmd.copyBuffer(from.handle(), to.handle(), vk::BufferCopy{0, 0, 256});
    };
  });
  gpu::DescriptorArena arena(ctx());
  auto frame = [&] {
    std::vector<std::string> names;
    gpu::submitAndWait(
        ctx(),
        [&](const vk::raii::CommandBuffer& cmd) {
          render::PassContext pc{cmd, arena};
          for (const auto& p : graph.record(pc, std::vector{res.ref})) names.push_back(p.name);
        },
        "graph test");
    return names;
  };
  using Names = std::vector<std::string>;
  EXPECT_EQ(frame(), (Names{"write input", "cached", "use"}));
  writeInput = false;
  EXPECT_EQ(frame(), (Names{"use"}));  // the input unchanged: the cached output stands
  EXPECT_EQ(frame(), (Names{"use"}));
  graph.touch(in.ref);  // the host changed the input
  EXPECT_EQ(frame(), (Names{"cached", "use"}));
  writeInput = true;
  EXPECT_EQ(frame(), (Names{"write input", "cached", "use"}));
  graph.setCaching(false);
  writeInput = false;
  EXPECT_EQ(frame(), (Names{"cached", "use"}));
  EXPECT_EQ(cachedRuns, 4);
}

// Water that has come to rest sleeps: no simulation is recorded, and what it
// draws differs from the simulated frame by no more than the rule's bound
// allows; a drop wakes it within one frame.
TEST_F(SkipTest, RestingWaterSleepsWithinTheBoundAndADropWakesIt) {
  scene::Scene s = scene::defaultScene();
  // Comes to rest in under a hundred frames: small drops, long frames, and
  // damping near the critical rate of the pool's longest wave (2 c pi / L):
  // more would overdamp it, and it would creep back to rest slower.
  s.water.grid = 48;
  s.water.frameTime = 0.1f;
  s.water.damping = 1.0f;
  for (auto& drop : s.water.drops) drop.amplitude *= 0.1f;
  render::Renderer skipping(ctx(), s, kWidth, kHeight);
  uint32_t asleepAt = 0;
  double energyAtSleep = 0.0;
  for (uint32_t frame = 1; frame <= 200 && !asleepAt; ++frame) {
    const auto f = skipping.render({.frame = frame});
    if (f.waterAsleep) {
      asleepAt = frame;
      energyAtSleep = f.waterEnergy;
    }
  }
  ASSERT_GT(asleepAt, 0u) << "the water never slept";
  EXPECT_LE(energyAtSleep, sim::sleepRule(s.water).energyPerArea);
  // The stated error: the rule bounds the RMS difference of the normals by
  // 2 sim::kSleepSlope = 1e-4 rad. A pixel's radiance moves with its normal by its
  // gradient in angle: a smooth sky or floor (relative gradient of order 1 per
  // radian) moves by ~1e-4, so the mean relative difference stays under 1e-4;
  // a pixel on an edge (tile, caustic) may move more, but no channel by 1%.
  // Measured: mean 2e-5, worst 3.3e-3 (docs/frame-skipping.md).
  render::Renderer everything(ctx(), s, kWidth, kHeight, {.skipping = false});
  for (uint32_t later : {asleepAt + 5, asleepAt + 60}) {
    SCOPED_TRACE("frame " + std::to_string(later));
    const auto a = skipping.render({.frame = later});
    const auto b = everything.render({.frame = later});
    EXPECT_TRUE(a.waterAsleep);
    EXPECT_FALSE(recorded(a, render::passes::kSimulate));
    EXPECT_FALSE(recorded(a, render::passes::kCaustics));
    EXPECT_FALSE(b.waterAsleep);
    double sum = 0.0, worst = 0.0;
    size_t off = 0;
    for (size_t k = 0; k < a.rgba.size(); ++k) {
      if (k % 4 == 3) continue;
      const double d = std::abs(double(a.rgba[k]) - b.rgba[k]) / std::max(1e-3, double(std::abs(b.rgba[k])));
      sum += d;
      worst = std::max(worst, d);
      off += d > 1e-3;
    }
    const double mean = sum / (double(a.rgba.size()) * 3 / 4);
    std::printf(
        "sleeping vs simulated at frame %u (asleep at %u, energy %.3g): mean relative %.3g, worst %.3g, %zu "
        "channels over 1e-3\n",
        later, asleepAt, energyAtSleep, mean, worst, off);
    EXPECT_LT(mean, 1e-4);
    EXPECT_LT(worst, 1e-2);
  }
  // A drop wakes it: the next frame simulates and shows it.
  const auto before = skipping.render({.frame = asleepAt + 60});
  skipping.addDrop({0.0f, 0.0f, 0.4f, 0.05f});
  const auto after = skipping.render({.frame = asleepAt + 61});
  EXPECT_FALSE(after.waterAsleep);
  EXPECT_TRUE(recorded(after, render::passes::kSimulate));
  EXPECT_TRUE(recorded(after, render::passes::kCaustics));
  EXPECT_GT(differingPixels(before, after), size_t(kWidth) * kHeight / 20);
}

}  // namespace tp::test
