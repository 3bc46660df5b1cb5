// The renderer's live changes (the viewer's camera, a dragged sphere) against
// an independent answer: a renderer made for the changed scene, a stepper
// given the same displacement, and the volume the sphere occupies.
#include <gtest/gtest.h>

#include <algorithm>

#include "gpu_test.hpp"
#include "render/renderer.hpp"
#include "render/water_model.hpp"
#include "render/water_sleep.hpp"
#include "sim/gpu_stepper.hpp"
#include "sim_support.hpp"

namespace tp::test {
namespace {

constexpr uint32_t kWidth = 96, kHeight = 64;


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
  const Step steps[] = {{0, s.camera, false}, {1, over, true}, {2, over, true},   {3, s.camera, true},
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
    EXPECT_EQ(render::findPass(a.passes, "camera medium") != nullptr, step.medium);
  }
  scene::Camera bad = s.camera;
  bad.target = bad.position;
  EXPECT_THROW(live.setCamera(bad), std::runtime_error);
  EXPECT_EQ(live.scene().camera, s.camera);
}

// A sphere dragged deeper into calm, sleeping water wakes it; the water after
// the next frame is, to the bit, a stepper's given the same displacement and
// steps; and the water's volume fell by the volume the sphere newly occupies.
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

  const uint32_t substeps = render::waterSubsteps(s.water);
  sim::GpuStepper stepper(ctx(), render::waterParams(s.water), render::waterInitialState(s.water),
                          sim::StepKernel::OnePerDispatch);
  stepper.moveSphere(render::worldToGrid(s.water, from), render::worldToGrid(s.water, to), s.spheres[0].radius,
                     s.water.level);
  stepper.step(substeps, render::waterStep(s.water));
  const sim::WaterState expected = stepper.download();
  EXPECT_TRUE(water.u == expected.u);
  EXPECT_TRUE(water.v == expected.v);

  const uint32_t n = s.water.grid;
  const double h = double(s.water.extent) / n;
  const double pushedIn = submergedVolume(n, s.water.extent, s.water.level, to, s.spheres[0].radius) -
                          submergedVolume(n, s.water.extent, s.water.level, from, s.spheres[0].radius);
  EXPECT_GT(pushedIn, 0.02);
  EXPECT_NEAR(volumeOf(water, h) - volumeOf(render::waterInitialState(s.water), h), -pushedIn, 1e-3 * pushedIn);

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
  const uint32_t before = render::waterSubsteps(s.water), after = render::waterSubsteps(w);
  ASSERT_NE(before, after);

  render::Renderer renderer(ctx(), s, kWidth, kHeight);
  for (uint32_t frame = 0; frame <= 3; ++frame) renderer.render({.frame = frame});
  renderer.setWaterDynamics(w);
  EXPECT_EQ(renderer.scene().water, w);
  renderer.render({.frame = 4});
  renderer.render({.frame = 5});
  sim::GpuStepper stepper(ctx(), render::waterParams(s.water), render::waterInitialState(s.water),
                          sim::StepKernel::OnePerDispatch);
  stepper.step(3 * before, render::waterStep(s.water));
  stepper.setParams(render::waterParams(w));
  stepper.step(2 * after, render::waterStep(w));
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

}  // namespace tp::test
