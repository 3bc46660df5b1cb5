#pragma once
#include <glm/glm.hpp>
#include <memory>
#include <optional>

#include "gpu/context.hpp"
#include "gpu/descriptors.hpp"
#include "gpu/memory.hpp"
#include "gpu/pipeline.hpp"
#include "sim/water_params.hpp"
#include "sim/water_state.hpp"
#include "sim/water_stats.hpp"
#include "sim/water_tiles.hpp"

namespace tp::sim {

enum class StepKernel {
  OnePerDispatch,  // water_step.comp: one step per dispatch
  Tiled,           // water_step_tiled.comp: up to `halo` steps per dispatch in shared memory
  ActiveTiles,     // water_step_active.comp: one step per dispatch over the tiles within reach of
                   // motion (sim/water_tiles.hpp), or over all tiles, whichever is measured faster
};

// How an ActiveTiles stepper dispatches its steps: Auto chooses per
// recordSteps() call by preferActiveList() from the last finished count;
// Full and Active force one way (tests, benchmarks). Both give the same bits.
enum class TileDispatch { Auto, Full, Active };

// The water on the GPU: two state buffers (ping-pong) and the compute passes
// that step, disturb and measure it. record*() add commands with the exact
// compute-to-compute barriers between them; the plain methods submit and wait.
// The largest grid side whose state fits one storage buffer on the device.
uint32_t maxGrid(const gpu::Context& ctx);
// Throws one line naming the grid, the bytes it needs and the device's limit
// when an n x n state does not fit one storage buffer.
void checkGridFits(const gpu::Context& ctx, uint32_t n);

class GpuStepper {
 public:
  static constexpr uint32_t kMaxHalo = 15;  // the tiled shader's 32-cell tile keeps an inner tile of 2

  GpuStepper(const gpu::Context& ctx, const WaterParams& params, const WaterState& initial,
             StepKernel kernel = StepKernel::Tiled, uint32_t halo = 4);

  void recordSteps(const vk::raii::CommandBuffer& cmd, uint64_t steps, double dt);
  void recordDrop(const vk::raii::CommandBuffer& cmd, glm::vec2 center, float radius, float amplitude);
  // Moves a sphere of `radius` from `from` to `to` over `seconds` (0: at
  // once), displacing water below `restLevel`. The spread forcing's bump
  // follows the move's speed across the water (wakeWidening near the wave
  // speed, fastBodyWeight above it).
  void recordSphereMove(const vk::raii::CommandBuffer& cmd, glm::vec3 from, glm::vec3 to, float radius, float restLevel,
                        double seconds);
  // Computes the per-workgroup statistics; readStats() after the submission finished.
  void recordStats(const vk::raii::CommandBuffer& cmd, double dt);
  WaterStats readStats() const;

  // Starts again from `state` (same grid size), as if newly made.
  void reset(const WaterState& state);
  // New parameters (same grid size) from the next step on, the state kept.
  // Every tile counts as changed: the step itself changed.
  void setParams(const WaterParams& params);
  void step(uint64_t steps, double dt);
  void drop(glm::vec2 center, float radius, float amplitude);
  void moveSphere(glm::vec3 from, glm::vec3 to, float radius, float restLevel, double seconds);
  WaterStats stats(double dt);
  WaterState download() const;

  const gpu::Buffer& current() const { return buffers_[current_]; }
  const gpu::Buffer& buffer(int k) const { return buffers_[k]; }
  const WaterParams& params() const { return params_; }
  StepKernel kernel() const { return kernel_; }
  uint32_t halo() const { return halo_; }

  // ActiveTiles only. Takes effect from the next recordSteps().
  void setTileDispatch(TileDispatch mode) { tileDispatch_ = mode; }
  // Whether the last recordSteps() dispatched all tiles (true) or the active list.
  bool lastStepsFull() const { return lastStepsFull_; }
  // Tiles dispatched by steps since the last call. Call it when none of the
  // stepper's submissions is running: it zeroes a device counter they add to.
  // Inside a gpu::CountScope, add `listed` with gpu::addWorkgroups: the
  // indirect dispatches could not count their workgroups when recorded.
  TileCounts readTilesDispatched();
  const WaterTiles& tiles() const { return tiles_; }

 private:
  void beforeCompute(const vk::raii::CommandBuffer& cmd);
  void recordActiveSteps(const vk::raii::CommandBuffer& cmd, uint64_t steps, double dt);
  void uploadSolid();

  const gpu::Context& ctx_;
  WaterParams params_;
  StepKernel kernel_;
  uint32_t halo_;
  // The step and statistics pipelines, for open water alone and with solid
  // cells (TP_SPEC_WATER_SOLIDS; made when a mask first comes). The
  // descriptor sets, made with the first's layouts, serve both.
  struct StepPipelines {
    gpu::Pipeline one, tiled, active, stats;
  };
  StepPipelines makeStepPipelines(bool solids) const;
  const StepPipelines& stepPipelines() const;
  StepPipelines openWater_;
  std::optional<StepPipelines> withSolids_;
  gpu::Pipeline dropPipeline_;
  // A sphere's forcing, each way (SphereForcing): setParams may change it.
  gpu::Pipeline sphereColumn_, sphereSpread_;
  gpu::Buffer buffers_[2];
  // Every kernel keeps the tile flags: drops and spheres mark them whatever steps.
  WaterTiles tiles_;
  gpu::Buffer partials_;
  gpu::Buffer solidDepths_;  // solidDepths(params_): all zero, and unread, where no cell is solid
  // Descriptor sets made once: stepSets_[k] reads buffers_[k] and writes the
  // other (for the kernel in use), inPlaceSets_[k] for the drop and sphere
  // passes on buffers_[k], statsSets_[k] for the statistics of buffers_[k].
  gpu::DescriptorArena descriptors_;
  vk::DescriptorSet stepSets_[2], plainSets_[2], dropSets_[2], sphereSets_[2], statsSets_[2];
  uint32_t current_ = 0;
  uint64_t stepIndex_ = 0;     // steps since the last reset: the index of the state in buffers_[current_]
  bool pendingWrite_ = false;  // a compute write that later compute work must wait for
  TileDispatch tileDispatch_ = TileDispatch::Auto;
  bool lastStepsFull_ = true;
  uint64_t directTiles_ = 0;  // tiles of full-grid active-kernel steps recorded since the last read
};

}  // namespace tp::sim
