#include "sim/water_tiles.hpp"

#include <cstring>
#include <vector>

#include "gpu/barriers.hpp"
#include "gpu/commands.hpp"
#include "gpu/transfer.hpp"
#include "shared/water.h"

namespace tp::sim {
namespace {

// The dispatch rule, from `tidepool bench tiles` (docs/simulation.md, "Active tiles"; 2
// cores, lavapipe, grids 256, 512, 1024, each ratio the median over 7 runs
// interleaved under the same load): the list took 0.01-0.02 of the full
// grid's time on calm water, 0.09-0.26 with 5-17% of the tiles active,
// 0.78-0.97 with 59-73%, 1.3-1.5 with all: about 1.3-1.5 times the fraction
// plus the list build (one workgroup), since a full run steps all but its
// last step with the plain kernel. It crossed the full grid at 72-75% active
// on every grid size, so the rule has no size bound. 0.7, just below the
// crossings: the count it sees is the last finished step's, and the active
// region widens by a ring of tiles per step after it.
constexpr double kActiveListMaxFraction = 0.7;

shader::WaterTileCounters* countersOf(const gpu::Buffer& b) {
  return static_cast<shader::WaterTileCounters*>(b.mapped);
}

}  // namespace

bool preferActiveList(uint32_t listedTiles, uint32_t allTiles) {
  return double(listedTiles) < kActiveListMaxFraction * double(allTiles);
}

WaterTiles::WaterTiles(const gpu::Context& ctx, uint32_t n, Boundary boundary)
    : ctx_(ctx), perSide_((n + TP_WATER_TILE - 1) / TP_WATER_TILE), boundary_(boundary), descriptors_(ctx, 1) {
  const vk::DeviceSize bytes = vk::DeviceSize(count()) * sizeof(uint32_t);
  listPipeline_ = gpu::createComputePipeline(ctx, "water_tile_list.comp", sizeof(shader::WaterTileListParams));
  changedAt_ =
      gpu::createBuffer(ctx, bytes, vk::BufferUsageFlagBits::eStorageBuffer | vk::BufferUsageFlagBits::eTransferDst,
                        gpu::MemoryUse::Device, "water tile change steps");
  list_ = gpu::createBuffer(ctx, bytes, vk::BufferUsageFlagBits::eStorageBuffer, gpu::MemoryUse::Device,
                            "active water tiles");
  // Host-visible: the host reads the count to choose the next dispatch.
  counters_ = gpu::createBuffer(ctx, sizeof(shader::WaterTileCounters),
                                vk::BufferUsageFlagBits::eStorageBuffer | vk::BufferUsageFlagBits::eIndirectBuffer,
                                gpu::MemoryUse::Readback, "active water tile counters");
  *countersOf(counters_) = shader::WaterTileCounters{};
  listSet_ = gpu::DescriptorWrites()
                 .storageBuffer(0, changedAt_)
                 .storageBuffer(1, list_)
                 .storageBuffer(2, counters_)
                 .allocate(listPipeline_, descriptors_);
}

void WaterTiles::markAll(uint32_t step) {
  const std::vector<uint32_t> steps(count(), step);
  gpu::uploadToBuffer(ctx_, changedAt_, steps.data(), steps.size() * sizeof(uint32_t));
  countersOf(counters_)->groupsX = count();
}

void WaterTiles::recordList(const vk::raii::CommandBuffer& cmd, uint32_t changedStep, bool accumulate) {
  // The last indirect dispatch read the arguments this overwrites.
  auto afterRead = gpu::bufferBarrier(counters_.handle(), gpu::access::indirectRead, gpu::access::computeWrite);
  gpu::pipelineBarrier(cmd, std::span(&afterRead, 1));
  shader::WaterTileListParams p{
      .tilesPerSide = perSide_,
      .boundary = boundary_ == Boundary::Wrap ? TP_WATER_BOUNDARY_WRAP : TP_WATER_BOUNDARY_CLAMP,
      .changedStep = changedStep,
      .accumulate = accumulate ? 1u : 0u};
  gpu::bindPipeline(cmd, listPipeline_, p);
  gpu::bindSet(cmd, listPipeline_, listSet_);
  gpu::dispatch(cmd, 1);
  auto toIndirect = gpu::bufferBarrier(counters_.handle(), gpu::access::computeWrite, gpu::access::indirectRead);
  gpu::pipelineBarrier(cmd, std::span(&toIndirect, 1));
}

void WaterTiles::recordListedDispatch(const vk::raii::CommandBuffer& cmd) const {
  gpu::dispatchIndirect(cmd, counters_.handle(), offsetof(shader::WaterTileCounters, groupsX));
}

void WaterTiles::recordHostRead(const vk::raii::CommandBuffer& cmd) const {
  auto toHost = gpu::bufferBarrier(counters_.handle(), gpu::access::computeWrite, gpu::access::hostRead);
  gpu::pipelineBarrier(cmd, std::span(&toHost, 1));
}

uint32_t WaterTiles::lastListed() const { return countersOf(counters_)->groupsX; }

uint64_t WaterTiles::takeListedTotal() {
  auto* c = countersOf(counters_);
  const uint64_t total = (uint64_t(c->totalHigh) << 32) | c->totalLow;
  c->totalLow = c->totalHigh = 0;
  return total;
}

}  // namespace tp::sim
