#pragma once
// The scene's water through the frames of a renderer: its stepper, its clock,
// the drops and sphere moves still to apply, sleep, checkpoints and resume.
#include <cstdint>
#include <limits>
#include <vector>

#include "gpu/context.hpp"
#include "scene/scene.hpp"
#include "sim/gpu_stepper.hpp"
#include "sim/water_sleep.hpp"
#include "sim/water_state.hpp"
#include "sim/water_timeline.hpp"

namespace tp::sim {

// What a renderer's next frames depend on besides its scene: the water as it
// stands after the last frame rendered, and the sleep rule's count. A
// renderer of the same scene that resumes from it renders the frames after
// `frame` to the bit, as the one it came from would have (render --frames
// A-B --checkpoint-every K: a range can start on another machine).
struct WaterCheckpoint {
  uint32_t frame = 0;  // the frame the water has reached
  WaterState state;
  uint32_t quietFrames = 0;
  bool asleep = false;
};

// Frame N shows the water after N frames of simulation from the scene's
// start, whatever was rendered before: going back restarts it. The scene's
// later drops come on their frames (water_timeline.hpp); sleeping water
// skips ahead without a step.
class WaterDriver {
 public:
  // `skipping` (RendererOptions::skipping): sleeping water takes no step and
  // only the tiles within reach of motion are stepped (the same bits as the
  // whole grid); off, every frame steps every tile.
  WaterDriver(const gpu::Context& ctx, const scene::Scene& scene, bool skipping);

  // Takes over `previous`'s water: its state, clock, sleep, applied and
  // pending drops and moves (a renderer going on from another).
  void goOnFrom(const WaterDriver& previous);

  // Before frame `frame` of `scene` is recorded: the steps it takes, the
  // drops due on the way, and whether it simulates at all. Returns true when
  // the state was uploaded from the host (a restart from frame 0), which the
  // frame graph must be told of.
  bool plan(const scene::Scene& scene, uint32_t frame);
  bool simulating() const { return simulating_; }
  // The simulation pass's commands: the live drops and moves, the steps with
  // the scene's drops due on the way, and the stats.
  void record(const vk::raii::CommandBuffer& cmd, const scene::Scene& scene);
  // After a submitted frame that simulated: the steps count as done, the
  // stats are read and checked, sleep observes them. Returns the tiles the
  // steps' indirect dispatches launched, known only now.
  uint64_t finish(const scene::Scene& scene);

  // A live drop, recorded into `water.drops` with the frame after the one
  // the water has reached (before the scene's drops of that frame still to
  // come), applied at the start of the next simulation.
  void addDrop(scene::Water& water, const scene::Drop& drop);
  // A sphere moved by hand from `from` to `to`: its displacement of the water
  // is divided over the next frame's steps (recordWaterRun).
  void moveSphere(glm::vec3 from, glm::vec3 to, float radius);
  // Scene time (seconds) the water has reached.
  double time(const scene::Water& water) const { return clock_.timeAt(stepsDone_, water); }
  // New dynamics (`water`, validated by the caller's scene rules) from the
  // next frame on: the clock re-based at the frame reached, the water woken.
  void setDynamics(const scene::Water& water);

  WaterState state() const { return stepper_.download(); }
  // Throws after setDynamics (a scene file cannot say when the change came).
  WaterCheckpoint checkpoint() const;
  // Puts the water where the checkpoint says, as if it had been run up to its
  // frame. Throws on a state of another grid size.
  void resume(const WaterCheckpoint& checkpoint, const scene::Scene& scene);

  GpuStepper& stepper() { return stepper_; }
  bool asleep() const { return sleep_.asleep(); }
  // Per unit area, after the last simulated frame (WaterSleep's measure).
  double energyPerArea() const { return energyPerArea_; }
  // The highest the water's surface can be: the rim, unless the last stats
  // saw a wave over it.
  float top() const { return top_; }
  // The largest height over or under the rest level the last stats saw
  // (infinite before any).
  float largestHeight() const { return largestHeight_; }

 private:
  void restart(const scene::Scene& scene, const WaterStats& stats);
  void observe(const scene::Scene& scene, const WaterStats& stats);

  GpuStepper stepper_;
  bool skipping_;
  WaterClock clock_;  // setDynamics re-bases it, a restart starts it again
  uint64_t stepsDone_ = 0;
  uint64_t pendingSteps_ = 0;
  // Per drop of the scene: applied in this run of the water (addDrop's at
  // once; the schedule's when the simulation that applies them was recorded).
  std::vector<bool> dropsApplied_;
  std::vector<size_t> dropsDue_;           // the scheduled drops within this frame's steps (dueDrops())
  std::vector<scene::Drop> pendingDrops_;  // addDrop()'s, for the next frame
  std::vector<SphereMove> pendingMoves_;   // moveSphere()'s, for the next frame
  bool simulating_ = false;                // this frame records the simulation
  WaterSleep sleep_;
  double energyPerArea_ = 0.0;
  float top_ = std::numeric_limits<float>::infinity();
  float largestHeight_ = std::numeric_limits<float>::infinity();
};

}  // namespace tp::sim
