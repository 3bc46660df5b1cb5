#include "sim/gpu_stepper.hpp"

#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <utility>

#include "gpu/barriers.hpp"
#include "gpu/commands.hpp"
#include "gpu/submit.hpp"
#include "gpu/transfer.hpp"

namespace tp::sim {
namespace {

constexpr uint32_t kTile = 32;   // water_step_tiled.comp's local size
constexpr uint32_t kGroup = 16;  // the 16x16 local size of the other water shaders

shader::WaterStepParams stepParams(const WaterParams& p, double dt, uint32_t steps) {
  const double h = p.h();
  return shader::WaterStepParams{
      .n = p.n,
      .boundary = p.boundary == Boundary::Wrap ? TP_WATER_BOUNDARY_WRAP : TP_WATER_BOUNDARY_CLAMP,
      .scheme = p.scheme == Scheme::Explicit ? TP_WATER_SCHEME_EXPLICIT : TP_WATER_SCHEME_SYMPLECTIC,
      .steps = steps,
      .dt = float(dt),
      .waveFactor = float(dt * p.waveSpeed * p.waveSpeed / (h * h)),
      .damping = float(std::exp(-p.damping * dt)),
      .maxDifference = float(p.maxSlope * h),
      .gridDamping = float(p.gridDamping * dt),
      .spillHeight = float(p.spillHeight),
      .slopeShare = float(slopeShare(p)),
      .pad = 0,
  };
}

gpu::Buffer stateBuffer(const gpu::Context& ctx, uint32_t n, const char* what) {
  return gpu::createBuffer(ctx, vk::DeviceSize(n) * n * sizeof(shader::WaterCell),
                           vk::BufferUsageFlagBits::eStorageBuffer | vk::BufferUsageFlagBits::eVertexBuffer |
                               vk::BufferUsageFlagBits::eTransferSrc | vk::BufferUsageFlagBits::eTransferDst,
                           gpu::MemoryUse::Device, what);
}

uint32_t groupsPerSide(uint32_t n) { return (n + kGroup - 1) / kGroup; }

WaterParams withGrid(WaterParams p, uint32_t n) {
  p.n = n;
  validate(p);
  return p;
}

}  // namespace

uint32_t maxGrid(const gpu::Context& ctx) {
  return uint32_t(std::sqrt(double(ctx.limits().maxStorageBufferRange) / sizeof(shader::WaterCell)));
}

void checkGridFits(const gpu::Context& ctx, uint32_t n) {
  if (n <= maxGrid(ctx)) return;
  const uint64_t bytes = uint64_t(n) * n * sizeof(shader::WaterCell);
  throw std::runtime_error("grid " + std::to_string(n) + " needs " + std::to_string(bytes) +
                           " bytes of state, over the storage buffer limit of " +
                           std::to_string(ctx.limits().maxStorageBufferRange) + " bytes on " + ctx.deviceName() +
                           " (at most " + std::to_string(maxGrid(ctx)) + ")");
}

GpuStepper::GpuStepper(const gpu::Context& ctx, const WaterParams& params, const WaterState& initial, StepKernel kernel,
                       uint32_t halo)
    : ctx_(ctx),
      params_(withGrid(params, initial.n)),
      kernel_(kernel),
      halo_(halo),
      tiles_(ctx, initial.n, params.boundary),
      descriptors_(ctx, 16) {
  if (halo < 1 || halo > kMaxHalo) {
    throw std::runtime_error("tiled water halo " + std::to_string(halo) + " is outside 1.." + std::to_string(kMaxHalo));
  }
  checkGridFits(ctx, initial.n);
  const uint32_t n = params_.n;
  openWater_ = makeStepPipelines(false);
  if (!params_.solid.empty()) withSolids_ = makeStepPipelines(true);
  dropPipeline_ = gpu::createComputePipeline(ctx, "water_drop.comp", sizeof(shader::WaterDropParams));
  sphereColumn_ = gpu::createComputePipeline(ctx, "water_sphere.comp", sizeof(shader::WaterSphereParams));
  sphereSpread_ = gpu::createComputePipeline(ctx, "water_sphere.comp", sizeof(shader::WaterSphereParams),
                                             gpu::Specialization().set(0, vk::Bool32(true)));
  const std::string grid = std::to_string(n) + "x" + std::to_string(n) + " water state";
  buffers_[0] = stateBuffer(ctx, n, grid.c_str());
  buffers_[1] = stateBuffer(ctx, n, grid.c_str());
  partials_ =
      gpu::createBuffer(ctx, vk::DeviceSize(groupsPerSide(n)) * groupsPerSide(n) * sizeof(shader::WaterStatsPartial),
                        vk::BufferUsageFlagBits::eStorageBuffer, gpu::MemoryUse::Readback, "water statistics");
  solidDepths_ = gpu::createBuffer(ctx, vk::DeviceSize(solidDepthWords(n)) * sizeof(uint32_t),
                                   vk::BufferUsageFlagBits::eStorageBuffer | vk::BufferUsageFlagBits::eTransferDst,
                                   gpu::MemoryUse::Device, "water solid cells");
  uploadSolid();
  reset(initial);
  for (int k = 0; k < 2; ++k) {
    gpu::DescriptorWrites step;
    step.storageBuffer(0, buffers_[k]).storageBuffer(1, buffers_[1 - k]).storageBuffer(4, solidDepths_);
    if (kernel_ == StepKernel::ActiveTiles) {
      // Full-grid runs step with the plain kernel but for their last step (see recordActiveSteps).
      plainSets_[k] = gpu::DescriptorWrites()
                          .storageBuffer(0, buffers_[k])
                          .storageBuffer(1, buffers_[1 - k])
                          .storageBuffer(4, solidDepths_)
                          .allocate(openWater_.one, descriptors_);
      stepSets_[k] = step.storageBuffer(2, tiles_.changedAt())
                         .storageBuffer(3, tiles_.list())
                         .allocate(openWater_.active, descriptors_);
    } else {
      stepSets_[k] = step.allocate(kernel_ == StepKernel::Tiled ? openWater_.tiled : openWater_.one, descriptors_);
    }
    dropSets_[k] = gpu::DescriptorWrites()
                       .storageBuffer(0, buffers_[k])
                       .storageBuffer(1, tiles_.changedAt())
                       .allocate(dropPipeline_, descriptors_);
    sphereSets_[k] = gpu::DescriptorWrites()
                         .storageBuffer(0, buffers_[k])
                         .storageBuffer(1, tiles_.changedAt())
                         .allocate(sphereColumn_, descriptors_);  // the same layout as sphereSpread_'s
    statsSets_[k] = gpu::DescriptorWrites()
                        .storageBuffer(0, buffers_[k])
                        .storageBuffer(1, partials_)
                        .storageBuffer(4, solidDepths_)
                        .allocate(openWater_.stats, descriptors_);
  }
}

void GpuStepper::reset(const WaterState& state) {
  if (state.n != params_.n) throw std::logic_error("GpuStepper::reset: another grid size");
  auto cells = toCells(state, params_.extent);
  gpu::uploadToBuffer(ctx_, buffers_[0], cells.data(), cells.size() * sizeof(cells[0]));
  // The second buffer's x and z never change; give it the same contents so
  // that it is never read uninitialised, whichever kernel runs.
  gpu::uploadToBuffer(ctx_, buffers_[1], cells.data(), cells.size() * sizeof(cells[0]));
  current_ = 0;
  stepIndex_ = 0;
  tiles_.markAll(0);
}

GpuStepper::StepPipelines GpuStepper::makeStepPipelines(bool solids) const {
  const auto spec = [&] { return gpu::Specialization().set(TP_SPEC_WATER_SOLIDS, vk::Bool32(solids)); };
  return StepPipelines{
      .one = gpu::createComputePipeline(ctx_, "water_step.comp", sizeof(shader::WaterStepParams), spec()),
      .tiled = gpu::createComputePipeline(ctx_, "water_step_tiled.comp", sizeof(shader::WaterStepParams),
                                          spec().set(0, int32_t(halo_))),
      .active = gpu::createComputePipeline(ctx_, "water_step_active.comp", sizeof(shader::WaterTileStepParams), spec()),
      .stats = gpu::createComputePipeline(ctx_, "water_stats.comp", sizeof(shader::WaterStatsParams), spec())};
}

const GpuStepper::StepPipelines& GpuStepper::stepPipelines() const {
  return params_.solid.empty() ? openWater_ : *withSolids_;
}

void GpuStepper::uploadSolid() {
  const std::vector<uint32_t> depths = solidDepths(params_);
  gpu::uploadToBuffer(ctx_, solidDepths_, depths.data(), depths.size() * sizeof(uint32_t));
}

void GpuStepper::setParams(const WaterParams& params) {
  if (params.n != params_.n) throw std::logic_error("GpuStepper::setParams: another grid size");
  validate(params);
  const bool solidChanged = params.solid != params_.solid;
  params_ = params;
  if (solidChanged) uploadSolid();
  if (!params_.solid.empty() && !withSolids_) withSolids_ = makeStepPipelines(true);
  tiles_.setBoundary(params.boundary);
  tiles_.markAll(uint32_t(stepIndex_));
}

void GpuStepper::beforeCompute(const vk::raii::CommandBuffer& cmd) {
  // Ping-pong: the next pass reads what the last wrote and overwrites what it
  // read. One global barrier from compute writes to compute reads and writes is
  // the smallest that covers both.
  if (pendingWrite_) {
    gpu::stageBarrier(cmd, gpu::access::computeWrite,
                      {vk::PipelineStageFlagBits2::eComputeShader,
                       vk::AccessFlagBits2::eShaderStorageRead | vk::AccessFlagBits2::eShaderStorageWrite});
  }
  pendingWrite_ = true;
}

void GpuStepper::recordSteps(const vk::raii::CommandBuffer& cmd, uint64_t steps, double dt) {
  checkStable(params_, dt);
  if (kernel_ == StepKernel::ActiveTiles) {
    recordActiveSteps(cmd, steps, dt);
    return;
  }
  const uint32_t n = params_.n;
  const uint32_t inner = kTile - 2 * halo_;
  for (uint64_t done = 0; done < steps;) {
    const uint32_t k = kernel_ == StepKernel::Tiled ? uint32_t(std::min<uint64_t>(halo_, steps - done)) : 1u;
    const gpu::Pipeline& pipeline = kernel_ == StepKernel::Tiled ? stepPipelines().tiled : stepPipelines().one;
    beforeCompute(cmd);
    gpu::bindPipeline(cmd, pipeline, stepParams(params_, dt, k));
    gpu::bindSet(cmd, pipeline, stepSets_[current_]);
    if (kernel_ == StepKernel::Tiled) {
      const uint32_t groups = (n + inner - 1) / inner;
      gpu::dispatch(cmd, groups, groups);
    } else {
      gpu::dispatchCovering(cmd, pipeline, n, n);
    }
    current_ = 1 - current_;
    stepIndex_ += k;
    done += k;
  }
}

void GpuStepper::recordActiveSteps(const vk::raii::CommandBuffer& cmd, uint64_t steps, double dt) {
  if (steps == 0) return;
  const bool full = tileDispatch_ == TileDispatch::Full ||
                    (tileDispatch_ == TileDispatch::Auto && !preferActiveList(tiles_.lastListed(), tiles_.count()));
  lastStepsFull_ = full;
  for (uint64_t s = 0; s < steps; ++s) {
    // A full run steps with the plain kernel, which keeps no tile flags and
    // runs 1.2-1.3x faster than the tracking one over all tiles (bench tiles),
    // but for its last step: a listed step needs only the flags of the step
    // just before it (sim/water_tiles.hpp), and flags left older by the plain
    // steps say "unchanged since", which is all the list reads.
    if (full && s + 1 < steps) {
      beforeCompute(cmd);
      const gpu::Pipeline& one = stepPipelines().one;
      gpu::bindPipeline(cmd, one, stepParams(params_, dt, 1));
      gpu::bindSet(cmd, one, plainSets_[current_]);
      gpu::dispatchCovering(cmd, one, params_.n, params_.n);
      directTiles_ += tiles_.count();
      current_ = 1 - current_;
      ++stepIndex_;
      continue;
    }
    if (!full) {
      beforeCompute(cmd);
      tiles_.recordList(cmd, uint32_t(stepIndex_), true);
    }
    beforeCompute(cmd);
    const shader::WaterTileStepParams p{.step = stepParams(params_, dt, 1),
                                        .stepIndex = uint32_t(stepIndex_ + 1),
                                        .tilesPerSide = tiles_.perSide(),
                                        .fromList = full ? 0u : 1u,
                                        .pad = 0};
    const gpu::Pipeline& active = stepPipelines().active;
    gpu::bindPipeline(cmd, active, p);
    gpu::bindSet(cmd, active, stepSets_[current_]);
    if (full) {
      gpu::dispatch(cmd, tiles_.perSide(), tiles_.perSide());
      directTiles_ += tiles_.count();
    } else {
      tiles_.recordListedDispatch(cmd);
    }
    current_ = 1 - current_;
    ++stepIndex_;
  }
  if (full) {
    // Full steps need no list; one after them counts what the next step would
    // dispatch, for the rule that chooses the next submission's way.
    beforeCompute(cmd);
    tiles_.recordList(cmd, uint32_t(stepIndex_), false);
  }
  tiles_.recordHostRead(cmd);
}

TileCounts GpuStepper::readTilesDispatched() {
  return TileCounts{.listed = tiles_.takeListedTotal(), .direct = std::exchange(directTiles_, 0)};
}

void GpuStepper::recordDrop(const vk::raii::CommandBuffer& cmd, glm::vec2 center, float radius, float amplitude) {
  if (!(radius > 0.0f) || !std::isfinite(amplitude))
    throw std::runtime_error("a drop needs a positive radius and a finite amplitude");
  beforeCompute(cmd);
  shader::WaterDropParams p{.n = params_.n,
                            .h = float(params_.h()),
                            .radius = radius,
                            .amplitude = amplitude,
                            .center = center,
                            .markStep = uint32_t(stepIndex_),
                            .pad = 0};
  gpu::bindPipeline(cmd, dropPipeline_, p);
  gpu::bindSet(cmd, dropPipeline_, dropSets_[current_]);
  gpu::dispatchCovering(cmd, dropPipeline_, params_.n, params_.n);
}

void GpuStepper::recordSphereMove(const vk::raii::CommandBuffer& cmd, glm::vec3 from, glm::vec3 to, float radius,
                                  float restLevel, double seconds) {
  beforeCompute(cmd);
  // A move across the water at once is faster than any wave. Round a grid
  // that wraps, the move across an edge is the short way round.
  glm::dvec2 move(to.x - from.x, to.z - from.z);
  if (params_.boundary == Boundary::Wrap) move -= params_.extent * glm::round(move / params_.extent);
  const double across = glm::length(move);
  const double froude = across == 0.0   ? 0.0
                        : seconds > 0.0 ? across / (seconds * params_.waveSpeed)
                                        : std::numeric_limits<double>::infinity();
  shader::WaterSphereParams p{.oldCenter = glm::vec4(from, radius),
                              .newCenter = glm::vec4(to, restLevel),
                              .n = params_.n,
                              .h = float(params_.h()),
                              .markStep = uint32_t(stepIndex_),
                              .wrap = params_.boundary == Boundary::Wrap ? 1u : 0u,
                              .spreadDepth = float(params_.spreadDepthFactor),
                              .fast = float(fastBodyWeight(froude)),
                              .topShare = float(kSpreadTopShare),
                              .widening = float(params_.widenNearWaveSpeed ? wakeWidening(froude) : 1.0)};
  const gpu::Pipeline& pipeline = params_.sphereForcing == SphereForcing::Spread ? sphereSpread_ : sphereColumn_;
  gpu::bindPipeline(cmd, pipeline, p);
  gpu::bindSet(cmd, pipeline, sphereSets_[current_]);
  gpu::dispatchCovering(cmd, pipeline, params_.n, params_.n);
}

void GpuStepper::recordStats(const vk::raii::CommandBuffer& cmd, double dt) {
  beforeCompute(cmd);
  shader::WaterStatsParams p{
      .n = params_.n,
      .boundary = params_.boundary == Boundary::Wrap ? TP_WATER_BOUNDARY_WRAP : TP_WATER_BOUNDARY_CLAMP,
      .c2 = float(params_.waveSpeed * params_.waveSpeed),
      .h = float(params_.h()),
      .dt = float(dt),
      .pad0 = 0.0f,
      .pad1 = {}};
  const gpu::Pipeline& stats = stepPipelines().stats;
  gpu::bindPipeline(cmd, stats, p);
  gpu::bindSet(cmd, stats, statsSets_[current_]);
  gpu::dispatchCovering(cmd, stats, params_.n, params_.n);
  auto toHost = gpu::bufferBarrier(partials_.handle(), gpu::access::computeWrite, gpu::access::hostRead);
  gpu::pipelineBarrier(cmd, std::span(&toHost, 1));
}

WaterStats GpuStepper::readStats() const {
  const size_t groups = size_t(groupsPerSide(params_.n)) * groupsPerSide(params_.n);
  std::vector<shader::WaterStatsPartial> partials(groups);
  std::memcpy(partials.data(), partials_.mapped, groups * sizeof(shader::WaterStatsPartial));
  WaterStats s;
  const double area = params_.h() * params_.h();
  for (const auto& p : partials) {
    s.maxAbsU = std::max(s.maxAbsU, double(p.maxAbsU));
    s.maxAbsV = std::max(s.maxAbsV, double(p.maxAbsV));
    s.volume += double(p.sumU) * area;
    s.energy += double(p.energy) * area;
    s.nonFinite += p.nonFinite;
  }
  return s;
}

void GpuStepper::step(uint64_t steps, double dt) {
  // Bounded command buffers: a long run is split so that no single submission
  // holds an unbounded number of dispatches.
  constexpr uint64_t kDispatchesPerSubmit = 2048;
  const uint64_t stepsPerSubmit = kernel_ == StepKernel::Tiled         ? kDispatchesPerSubmit * halo_
                                  : kernel_ == StepKernel::ActiveTiles ? kDispatchesPerSubmit / 2  // list + step
                                                                       : kDispatchesPerSubmit;
  for (uint64_t done = 0; done < steps;) {
    const uint64_t k = std::min(stepsPerSubmit, steps - done);
    gpu::submitAndWait(
        ctx_, [&](const vk::raii::CommandBuffer& cmd) { recordSteps(cmd, k, dt); }, "water simulation");
    done += k;
  }
}

void GpuStepper::drop(glm::vec2 center, float radius, float amplitude) {
  gpu::submitAndWait(
      ctx_, [&](const vk::raii::CommandBuffer& cmd) { recordDrop(cmd, center, radius, amplitude); }, "water drop");
}

void GpuStepper::moveSphere(glm::vec3 from, glm::vec3 to, float radius, float restLevel, double seconds) {
  gpu::submitAndWait(
      ctx_, [&](const vk::raii::CommandBuffer& cmd) { recordSphereMove(cmd, from, to, radius, restLevel, seconds); },
      "sphere displacement");
}

WaterStats GpuStepper::stats(double dt) {
  gpu::submitAndWait(
      ctx_, [&](const vk::raii::CommandBuffer& cmd) { recordStats(cmd, dt); }, "water statistics");
  return readStats();
}

WaterState GpuStepper::download() const {
  auto cells = gpu::readBufferAs<shader::WaterCell>(ctx_, current(), gpu::access::computeWrite);
  return fromCells(cells, params_.n);
}

}  // namespace tp::sim
