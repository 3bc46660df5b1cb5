// The renderer's live changes (the viewer's camera, a dragged sphere) against
// an independent answer: a renderer made for the changed scene, a stepper
// given the same displacement, and the volume the sphere occupies.
#include <gtest/gtest.h>

#include <algorithm>

#include "gpu_test.hpp"
#include "process.hpp"
#include "render/renderer.hpp"
#include "scene/scene_file.hpp"
#include "shading/water_model.hpp"
#include "sim/gpu_stepper.hpp"
#include "sim/wake_measures.hpp"
#include "sim/water_sleep.hpp"
#include "sim_support.hpp"

namespace tp::test {
namespace {

constexpr uint32_t kWidth = 96, kHeight = 64;

// Drops made live in the tests below (the viewer's click drop is 0.15 m, 0.03 m).
const scene::Drop kFirstDrop{0.4f, -0.3f, 0.2f, 0.05f};
const scene::Drop kPausedDrop{-0.5f, 0.6f, 0.25f, -0.04f};
const scene::Drop kLaterDrop{0.1f, 0.9f, 0.15f, 0.03f};
// Over kPausedDrop: where two drops overlap, the order they are added in shows in the bits.
const scene::Drop kOverlappingDrop{-0.4f, 0.5f, 0.3f, 0.02f};

scene::Drop onFrame(scene::Drop drop, unsigned frame) {
  drop.frame = frame;
  return drop;
}

bool sameWater(const sim::WaterState& a, const sim::WaterState& b) { return a.u == b.u && a.v == b.v; }

}  // namespace

using LiveRendererTest = GpuTest;

// A camera moved between frames draws what a renderer made with that camera
// draws (nothing skipped there), to the bit: away from the water, over it
// (the medium around the camera is computed), away again (the medium pass
// runs once more to write air, then no more), and into the water.
TEST_F(LiveRendererTest, MovedCameraDrawsWhatARendererMadeForItDraws) {
  const scene::Scene s = scene::defaultScene();
  scene::Camera over = s.camera, under = s.camera;
  over.position = {0.6f, 1.6f, 1.2f};
  over.target = {0.0f, -0.3f, -0.5f};
  under.position = {0.2f, -0.5f, 1.0f};  // below the surface, inside the pool
  under.target = {0.0f, -0.6f, -0.5f};
  struct Step {
    uint32_t frame;
    scene::Camera camera;
    bool medium;  // the skipping renderer records the camera medium pass
  };
  const Step steps[] = {{0, s.camera, false}, {1, over, true},  {2, over, true},    {3, s.camera, true},
                        {4, s.camera, false}, {5, under, true}, {6, s.camera, true}};
  render::Renderer live(ctx(), s, kWidth, kHeight);
  for (const Step& step : steps) {
    SCOPED_TRACE("frame " + std::to_string(step.frame));
    live.setCamera(step.camera);
    const auto a = live.render({.frame = step.frame});
    scene::Scene fixed = s;
    fixed.camera = step.camera;
    const auto b = render::Renderer(ctx(), fixed, kWidth, kHeight, {.skipping = false}).render({.frame = step.frame});
    EXPECT_TRUE(a.rgba == b.rgba);
    EXPECT_EQ(render::findPass(a.passes, render::passes::kCameraMedium) != nullptr, step.medium);
  }
  scene::Camera bad = s.camera;
  bad.target = bad.position;
  EXPECT_THROW(live.setCamera(bad), std::runtime_error);
  EXPECT_EQ(live.scene().camera, s.camera);
}

// A sphere dragged deeper into calm, sleeping water wakes it; the water after
// the next frame is, to the bit, a stepper's given the same displacement in
// equal pieces, one before each substep; and the surface rose by the volume
// the sphere newly occupies.
TEST_F(LiveRendererTest, DraggedSphereDisplacesTheWaterItPushesIn) {
  scene::Scene s = scene::defaultScene();
  s.water.drops.clear();
  const glm::vec3 from = s.spheres[0].center, to = from + glm::vec3(0.2f, -0.25f, 0.1f);
  render::Renderer renderer(ctx(), s, kWidth, kHeight);
  EXPECT_TRUE(renderer.render({.frame = 0}).waterAsleep);
  EXPECT_TRUE(renderer.render({.frame = 1}).waterAsleep);
  renderer.moveSphere(0, to);
  EXPECT_EQ(renderer.scene().spheres[0].center, to);
  EXPECT_FALSE(renderer.render({.frame = 2}).waterAsleep);
  const sim::WaterState water = renderer.waterState();

  const uint32_t substeps = sim::waterSubsteps(s.water);
  sim::GpuStepper stepper(ctx(), sim::waterParams(s), sim::waterInitialState(s.water), sim::StepKernel::OnePerDispatch);
  ASSERT_GT(substeps, 1u);
  const auto at = [&](uint32_t k) {
    return sim::worldToGrid(s.water, k == 0          ? from
                                     : k == substeps ? to
                                                     : glm::mix(from, to, float(double(k) / substeps)));
  };
  for (uint32_t k = 0; k < substeps; ++k) {
    stepper.moveSphere(at(k), at(k + 1), s.spheres[0].radius, s.water.level, sim::waterStep(s.water));
    stepper.step(1, sim::waterStep(s.water));
  }
  const sim::WaterState expected = stepper.download();
  EXPECT_TRUE(water.u == expected.u);
  EXPECT_TRUE(water.v == expected.v);

  const uint32_t n = s.water.grid;
  const double h = double(s.water.extent) / n;
  const double pushedIn = sim::sphereCapVolume(s.spheres[0].radius, to.y, s.water.level) -
                          sim::sphereCapVolume(s.spheres[0].radius, from.y, s.water.level);
  EXPECT_GT(pushedIn, 0.02);
  EXPECT_NEAR(volumeOf(water, h) - volumeOf(sim::waterInitialState(s.water), h), pushedIn, 1e-3 * pushedIn);

  EXPECT_THROW(renderer.moveSphere(1, to), std::out_of_range);
}

// New water dynamics go on from the water's state: after them the renderer's
// water is, to the bit, a stepper's that took the same steps under the old
// parameters and then the new (with the new substeps); going back restarts
// with the new parameters, as a renderer made with them.
TEST_F(LiveRendererTest, NewWaterDynamicsGoOnFromTheState) {
  const scene::Scene s = scene::defaultScene();
  scene::Water w = s.water;
  w.waveSpeed = 1.5f;  // more substeps per frame
  w.damping = 0.8f;
  w.boundary = "wrap";
  w.maxSlope = 0.2f;
  w.sphereForcing = "column";
  const uint32_t before = sim::waterSubsteps(s.water), after = sim::waterSubsteps(w);
  ASSERT_NE(before, after);

  render::Renderer renderer(ctx(), s, kWidth, kHeight);
  for (uint32_t frame = 0; frame <= 3; ++frame) renderer.render({.frame = frame});
  renderer.setWaterDynamics(w);
  EXPECT_EQ(renderer.scene().water, w);
  renderer.render({.frame = 4});
  renderer.render({.frame = 5});
  sim::GpuStepper stepper(ctx(), sim::waterParams(s), sim::waterInitialState(s.water), sim::StepKernel::OnePerDispatch);
  stepper.step(3 * before, sim::waterStep(s.water));
  scene::Scene withW = s;
  withW.water = w;
  stepper.setParams(sim::waterParams(withW));
  stepper.step(2 * after, sim::waterStep(w));
  const sim::WaterState expected = stepper.download(), water = renderer.waterState();
  EXPECT_TRUE(water.u == expected.u);
  EXPECT_TRUE(water.v == expected.v);

  scene::Scene changed = s;
  changed.water = w;
  render::Renderer fresh(ctx(), changed, kWidth, kHeight);
  const auto a = renderer.render({.frame = 1}), b = fresh.render({.frame = 1});
  EXPECT_TRUE(a.rgba == b.rgba);
  EXPECT_TRUE(renderer.waterState().u == fresh.waterState().u);

  scene::Water grid = w;
  grid.grid = 64;
  EXPECT_THROW(renderer.setWaterDynamics(grid), std::invalid_argument);
  scene::Water negative = w;
  negative.damping = -1.0f;
  EXPECT_ANY_THROW(renderer.setWaterDynamics(negative));
  EXPECT_EQ(renderer.scene().water, w);  // a refused change changes nothing
}

// A parameter change wakes sleeping water.
TEST_F(LiveRendererTest, NewWaterDynamicsWakeSleepingWater) {
  scene::Scene s = scene::defaultScene();
  s.water.drops.clear();
  render::Renderer renderer(ctx(), s, kWidth, kHeight);
  EXPECT_TRUE(renderer.render({.frame = 1}).waterAsleep);
  scene::Water w = s.water;
  w.damping = 0.1f;
  renderer.setWaterDynamics(w);
  EXPECT_FALSE(renderer.render({.frame = 2}).waterAsleep);
}

// Drops made live are recorded in the scene with the frame after the one the
// water has reached, and a new renderer of that scene, saved and loaded,
// renders the same frames to the bit: frame by frame, straight to the last,
// and sim::simulateWater() to the same water. The one exception, as documented: a
// drop made while paused at frame 3 shows in the live frame 3 at once, in the
// recorded scene from 4. It is listed before the scene's own drop on frame 4,
// which comes after it in the live run too.
TEST_F(LiveRendererTest, LiveDropsAreRecordedAndANewRendererOfTheSceneRendersTheSameFrames) {
  constexpr uint32_t kLast = 7, kPaused = 3, kLater = 5;
  scene::Scene s = scene::defaultScene();
  s.water.drops.push_back(onFrame(kOverlappingDrop, kPaused + 1));
  render::Renderer live(ctx(), s, kWidth, kHeight);
  std::vector<std::vector<float>> frames;
  frames.push_back(live.render({.frame = 0}).rgba);
  live.addDrop(kFirstDrop);  // before frame 1
  std::vector<float> pausedFrame;
  for (uint32_t frame = 1; frame <= kLast; ++frame) {
    if (frame == kLater) live.addDrop(kLaterDrop);
    frames.push_back(live.render({.frame = frame}).rgba);
    if (frame == kPaused) {
      live.addDrop(kPausedDrop);
      pausedFrame = live.render({.frame = frame}).rgba;  // the same frame again: shown at once
    }
  }
  std::vector<scene::Drop> drops = scene::defaultScene().water.drops;
  drops.push_back(onFrame(kPausedDrop, kPaused + 1));
  drops.push_back(onFrame(kOverlappingDrop, kPaused + 1));
  drops.push_back(onFrame(kFirstDrop, 1));
  drops.push_back(onFrame(kLaterDrop, kLater));
  EXPECT_EQ(live.scene().water.drops, drops);
  scene::Scene expected = s;
  expected.water.drops = drops;
  EXPECT_TRUE(live.scene() == expected);

  ScratchDir dir;
  scene::saveSceneFile(dir.file("saved.json"), live.scene());
  const scene::Scene saved = scene::loadSceneFile(dir.file("saved.json"));
  ASSERT_TRUE(saved == live.scene());
  render::Renderer replay(ctx(), saved, kWidth, kHeight);
  for (uint32_t frame = 0; frame <= kLast; ++frame) {
    SCOPED_TRACE("frame " + std::to_string(frame));
    const auto b = replay.render({.frame = frame});
    EXPECT_TRUE(frames[frame] == b.rgba);
    if (frame == kPaused) {
      EXPECT_FALSE(pausedFrame == b.rgba);
    }
  }
  render::Renderer jump(ctx(), saved, kWidth, kHeight);
  EXPECT_TRUE(jump.render({.frame = kLast}).rgba == frames[kLast]);
  EXPECT_TRUE(sameWater(sim::simulateWater(ctx(), saved, kLast), live.waterState()));
}

// Calm water sleeps from its first frame; a drop the scene schedules on a
// frame where it sleeps wakes it there. Its frames equal, to the bit, those of
// a renderer that skips nothing, and its water a stepper's given the drop
// after the steps of the frames before.
TEST_F(LiveRendererTest, AScheduledDropWakesSleepingWater) {
  constexpr uint32_t kDropFrame = 3, kLast = 5;
  scene::Scene s = scene::defaultScene();
  s.water.drops = {onFrame(kFirstDrop, kDropFrame)};
  render::Renderer skipping(ctx(), s, kWidth, kHeight), full(ctx(), s, kWidth, kHeight, {.skipping = false});
  for (uint32_t frame = 0; frame <= kLast; ++frame) {
    SCOPED_TRACE("frame " + std::to_string(frame));
    const auto a = skipping.render({.frame = frame}), b = full.render({.frame = frame});
    EXPECT_EQ(a.waterAsleep, frame < kDropFrame);
    EXPECT_TRUE(a.rgba == b.rgba);
    if (frame == kDropFrame) {
      const uint32_t substeps = sim::waterSubsteps(s.water);
      sim::GpuStepper stepper(ctx(), sim::waterParams(s), sim::waterInitialState(s.water),
                              sim::StepKernel::OnePerDispatch);
      stepper.step(uint64_t(kDropFrame - 1) * substeps, sim::waterStep(s.water));
      const glm::vec3 centre = sim::worldToGrid(s.water, {kFirstDrop.x, 0.0f, kFirstDrop.z});
      stepper.drop({centre.x, centre.z}, kFirstDrop.radius, kFirstDrop.amplitude);
      stepper.step(substeps, sim::waterStep(s.water));
      EXPECT_TRUE(sameWater(skipping.waterState(), stepper.download()));
    }
  }
}

// Going back restarts the water and replays the drops made live, each once on
// its frame: frame 2 and the last frame again are the bits they were. A drop
// still pending when the renderer goes back comes on its frame too.
TEST_F(LiveRendererTest, GoingBackReplaysTheLiveDrops) {
  constexpr uint32_t kBack = 2, kLast = 5;
  const scene::Scene s = scene::defaultScene();
  render::Renderer live(ctx(), s, kWidth, kHeight);
  std::vector<std::vector<float>> frames;
  for (uint32_t frame = 0; frame <= kLast; ++frame) {
    if (frame == 1 || frame == 4) live.addDrop(frame == 1 ? kFirstDrop : kLaterDrop);
    frames.push_back(live.render({.frame = frame}).rgba);
  }
  const std::vector<scene::Drop> drops = live.scene().water.drops;
  EXPECT_TRUE(live.render({.frame = kBack}).rgba == frames[kBack]);
  EXPECT_TRUE(live.render({.frame = kLast}).rgba == frames[kLast]);
  EXPECT_EQ(live.scene().water.drops, drops);  // replayed, not made again

  live.addDrop(kPausedDrop);  // on frame kLast + 1
  EXPECT_TRUE(live.render({.frame = kBack}).rgba == frames[kBack]);
  render::Renderer replay(ctx(), live.scene(), kWidth, kHeight);
  EXPECT_TRUE(live.render({.frame = kLast + 1}).rgba == replay.render({.frame = kLast + 1}).rgba);
}

// A renderer made from a running one for a changed scene (another refraction
// mode, no caustics, no AO, another ior) goes on with its water, the drops
// made live included (one applied, one pending): its frames equal, to the
// bit, a new renderer's of the changed scene. Changed water is refused.
TEST_F(LiveRendererTest, ARendererForAChangedSceneGoesOnWithTheWater) {
  constexpr uint32_t kMadeAt = 3, kLast = 5;
  const scene::Scene s = scene::defaultScene();
  render::Renderer live(ctx(), s, kWidth, kHeight);
  for (uint32_t frame = 0; frame <= kMadeAt; ++frame) {
    if (frame == 2) live.addDrop(kFirstDrop);
    live.render({.frame = frame});
  }
  live.addDrop(kLaterDrop);  // pending: on frame kMadeAt + 1
  scene::Scene changed = live.scene();
  changed.render.refraction = "apparent";
  changed.render.caustics = false;
  changed.ao.enabled = false;
  changed.water.ior = 1.5f;
  render::Renderer next(render::GoOnFrom{live}, changed);
  EXPECT_TRUE(next.scene() == changed);
  render::Renderer fresh(ctx(), changed, kWidth, kHeight);
  for (uint32_t frame = kMadeAt + 1; frame <= kLast; ++frame) {
    SCOPED_TRACE("frame " + std::to_string(frame));
    EXPECT_TRUE(next.render({.frame = frame}).rgba == fresh.render({.frame = frame}).rgba);
  }
  EXPECT_TRUE(sameWater(next.waterState(), fresh.waterState()));

  scene::Scene grid = changed;
  grid.water.grid = 64;
  EXPECT_THROW(render::Renderer(render::GoOnFrom{live}, grid), std::invalid_argument);
  scene::Scene moreDrops = changed;
  moreDrops.water.drops.push_back(kPausedDrop);
  EXPECT_THROW(render::Renderer(render::GoOnFrom{live}, moreDrops), std::invalid_argument);
}

}  // namespace tp::test
