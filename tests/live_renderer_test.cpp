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

bool recorded(const render::RenderedFrame& f, const std::string& pass) {
  return std::any_of(f.passes.begin(), f.passes.end(), [&](const auto& p) { return p.name == pass; });
}

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
    EXPECT_EQ(recorded(a, "camera medium"), step.medium);
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

}  // namespace tp::test
