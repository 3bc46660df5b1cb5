#include "sim/water_driver.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "sim/water_scene.hpp"

namespace tp::sim {
namespace {

// Whether a sphere's path moves it at some time in (t0, t1].
bool bodyMoves(const scene::Scene& scene, double t0, double t1) {
  for (const auto& sphere : scene.spheres) {
    if (sphere.path.size() >= 2 && t1 > sphere.path.front().time && t0 < sphere.path.back().time) return true;
  }
  return false;
}

// The stats' energy per unit area of the water: WaterSleep's measure.
double energyOverArea(const scene::Scene& scene, const WaterStats& stats) {
  return stats.energy / (double(scene.water.extent) * scene.water.extent);
}

// The highest the water's surface can be to reach the objects: the rim,
// unless the stats saw a wave over it.
float highestWater(const scene::Scene& scene, const WaterStats& stats) {
  return std::max(scene.ground.height, scene.water.level + float(stats.maxAbsU));
}

const scene::Scene& checkedFits(const gpu::Context& ctx, const scene::Scene& scene) {
  checkGridFits(ctx, scene.water.grid);  // before the initial state is made on the CPU
  return scene;
}

}  // namespace

WaterDriver::WaterDriver(const gpu::Context& ctx, const scene::Scene& scene, bool skipping)
    : stepper_(ctx, waterParams(checkedFits(ctx, scene)), waterInitialState(scene.water), StepKernel::ActiveTiles),
      skipping_(skipping),
      sleep_(sleepRule(scene.water)) {
  if (!skipping) stepper_.setTileDispatch(TileDispatch::Full);
  clock_.substeps = waterSubsteps(scene.water);
  restart(scene, stepper_.stats(waterStep(scene.water)));
}

void WaterDriver::goOnFrom(const WaterDriver& previous) {
  // A new start from the previous water: every tile counts as changed once.
  stepper_.reset(previous.state());
  stepsDone_ = previous.stepsDone_;
  clock_ = previous.clock_;
  dropsApplied_ = previous.dropsApplied_;
  pendingDrops_ = previous.pendingDrops_;
  pendingMoves_ = previous.pendingMoves_;
  sleep_ = previous.sleep_;
  energyPerArea_ = previous.energyPerArea_;
  top_ = previous.top_;
  largestHeight_ = previous.largestHeight_;
}

bool WaterDriver::plan(const scene::Scene& scene, uint32_t frame) {
  simulating_ = false;
  bool uploaded = false;
  const double dt = waterStep(scene.water);
  if (frame < clock_.frameBase || clock_.stepsAt(frame) < stepsDone_) {
    // From the start, with the water's parameters as they now are; every
    // drop made live is in the scene, and comes again on its frame.
    stepper_.reset(waterInitialState(scene.water));
    uploaded = true;
    stepsDone_ = 0;
    clock_ = WaterClock{.substeps = clock_.substeps};  // from frame 0 at step 0
    dropsApplied_.assign(scene.water.drops.size(), false);
    pendingDrops_.clear();
    restart(scene, stepper_.stats(dt));
  }
  const uint64_t target = clock_.stepsAt(frame);
  dropsDue_ = dueDrops(scene.water, clock_, stepsDone_, target, dropsApplied_);
  const bool disturbed = !pendingDrops_.empty() || !pendingMoves_.empty() || !dropsDue_.empty();
  if (disturbed || bodyMoves(scene, clock_.timeAt(stepsDone_, scene.water), clock_.timeAt(target, scene.water))) {
    sleep_.wake();
  }
  if (skipping_ && sleep_.asleep()) {
    stepsDone_ = target;
    pendingSteps_ = 0;
  } else {
    pendingSteps_ = target - stepsDone_;
    simulating_ = pendingSteps_ > 0 || disturbed;
  }
  return uploaded;
}

void WaterDriver::record(const vk::raii::CommandBuffer& cmd, const scene::Scene& scene) {
  for (const scene::Drop& d : pendingDrops_) recordSceneDrop(cmd, stepper_, scene.water, d);
  recordWaterRun(cmd, stepper_, scene, clock_, stepsDone_, stepsDone_ + pendingSteps_, dropsDue_, pendingMoves_);
  stepper_.recordStats(cmd, waterStep(scene.water));
}

uint64_t WaterDriver::finish(const scene::Scene& scene) {
  const uint64_t listedTiles = stepper_.readTilesDispatched().listed;
  stepsDone_ += pendingSteps_;
  pendingSteps_ = 0;
  pendingDrops_.clear();
  pendingMoves_.clear();
  dropsApplied_.resize(scene.water.drops.size(), false);
  for (const size_t i : dropsDue_) dropsApplied_[i] = true;
  const WaterStats stats = stepper_.readStats();
  checkHealth(stats, stepsDone_, std::numeric_limits<double>::infinity());
  observe(scene, stats);
  return listedTiles;
}

void WaterDriver::addDrop(scene::Water& water, const scene::Drop& drop) {
  scene::Drop recorded = drop;
  recorded.frame = clock_.frameAt(stepsDone_) + 1;
  // Listed before the scene's drops of the same frame still to come: the
  // schedule applies those after this one, and a run of the scene applies
  // drops of one frame in the order listed.
  std::vector<scene::Drop>& drops = water.drops;
  dropsApplied_.resize(drops.size(), false);
  size_t at = 0;
  while (at < drops.size() && (drops[at].frame != recorded.frame || dropsApplied_[at])) ++at;
  drops.insert(drops.begin() + std::ptrdiff_t(at), recorded);
  dropsApplied_.insert(dropsApplied_.begin() + std::ptrdiff_t(at), true);  // by the next simulation, before its steps
  pendingDrops_.push_back(recorded);
}

void WaterDriver::moveSphere(glm::vec3 from, glm::vec3 to, float radius) {
  if (from != to) pendingMoves_.push_back({from, to, radius});
}

void WaterDriver::setDynamics(const scene::Water& water) {
  // Everything that can refuse the change, before any of it is made.
  WaterParams params = waterParams(water);
  params.spillHeight = stepper_.params().spillHeight;  // the rim stays where it is, and so do the boxes
  params.solid = stepper_.params().solid;
  validate(params);
  const uint32_t substeps = waterSubsteps(water);
  // Re-base the clock at the frame the water has reached (a whole number of
  // the old frames since the last base: frames are stepped whole).
  clock_ = WaterClock{clock_.frameAt(stepsDone_), stepsDone_, substeps};
  stepper_.setParams(params);
  sleep_ = WaterSleep(sleepRule(water));  // its threshold follows the wave speed
  sleep_.wake();
}

WaterCheckpoint WaterDriver::checkpoint() const {
  if (clock_.frameBase != 0 || clock_.stepBase != 0) {
    throw std::runtime_error("a water whose dynamics changed on the way cannot be checkpointed");
  }
  return WaterCheckpoint{clock_.frameAt(stepsDone_), state(), sleep_.quietFrames(), sleep_.asleep()};
}

void WaterDriver::resume(const WaterCheckpoint& checkpoint, const scene::Scene& scene) {
  if (checkpoint.state.n != scene.water.grid) {
    throw std::runtime_error("a checkpoint of a " + std::to_string(checkpoint.state.n) + "x" +
                             std::to_string(checkpoint.state.n) + " water for a scene whose water.grid is " +
                             std::to_string(scene.water.grid));
  }
  stepper_.reset(checkpoint.state);
  clock_ = WaterClock{.substeps = clock_.substeps};
  stepsDone_ = clock_.stepsAt(checkpoint.frame);
  pendingSteps_ = 0;
  pendingDrops_.clear();
  pendingMoves_.clear();
  const auto& drops = scene.water.drops;
  dropsApplied_.resize(drops.size());
  for (size_t i = 0; i < drops.size(); ++i) dropsApplied_[i] = drops[i].frame <= checkpoint.frame;
  const WaterStats stats = stepper_.stats(waterStep(scene.water));
  restart(scene, stats);
  sleep_.resume(checkpoint.quietFrames, checkpoint.asleep);
  energyPerArea_ = energyOverArea(scene, stats);
}

void WaterDriver::restart(const scene::Scene& scene, const WaterStats& stats) {
  sleep_.restart(stats);
  top_ = highestWater(scene, stats);
  largestHeight_ = float(stats.maxAbsU);
}

void WaterDriver::observe(const scene::Scene& scene, const WaterStats& stats) {
  energyPerArea_ = energyOverArea(scene, stats);
  sleep_.observe(energyPerArea_);
  top_ = highestWater(scene, stats);
  largestHeight_ = float(stats.maxAbsU);
}

}  // namespace tp::sim
