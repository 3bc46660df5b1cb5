#pragma once
// Active tiles: a step computes only the tiles within reach of the last
// step's changes, with the result of a full-grid step to the bit.
//
// Why it is exact. The grid is cut into tiles of T x T cells (T =
// TP_WATER_TILE). S_n is the state after step n; step n+1 reads S_n and writes
// into the buffer that holds S_{n-1}. changedAt[t] is the last step index at
// which some cell of tile t changed bitwise (u or v). A cell's update reads
// only its 4 neighbours, so if no tile of t's 3x3 neighbourhood changed at step
// n, the inputs of every cell of t are the same in S_n as in S_{n-1}, hence
// S_{n+1} = S_n on t; and the destination already holds S_{n-1} = S_n there:
// skipping t writes exactly what computing it would. Anything that changes the
// state outside a step (a drop, a sphere, a reset) marks the tiles it changes
// at the current index, so the next step computes them. Step indices, not
// booleans, so that no flag is ever cleared (a uint that wraps after 2^32
// steps can only make a stale tile look changed: a wasted tile, never a wrong one).
#include <cstdint>

#include "gpu/context.hpp"
#include "gpu/descriptors.hpp"
#include "gpu/memory.hpp"
#include "gpu/pipeline.hpp"
#include "sim/water_params.hpp"

namespace tp::sim {

// Whether a step should dispatch the list of active tiles rather than every
// tile, given how many tiles the last step listed. Measured with `tidepool
// bench tiles` (docs/simulation.md, "Active tiles"): see water_tiles.cpp.
bool preferActiveList(uint32_t listedTiles, uint32_t allTiles);

// Tiles dispatched by steps, since the last read.
struct TileCounts {
  uint64_t listed = 0;  // by indirect dispatches over the active list: known only once read back
  uint64_t direct = 0;  // by full-grid dispatches: counted by gpu::dispatch when recorded
  uint64_t total() const { return listed + direct; }
};

// The per-tile flags, the active list and its indirect dispatch arguments.
class WaterTiles {
 public:
  WaterTiles(const gpu::Context& ctx, uint32_t n, Boundary boundary);

  uint32_t perSide() const { return perSide_; }
  uint32_t count() const { return perSide_ * perSide_; }
  const gpu::Buffer& changedAt() const { return changedAt_; }
  const gpu::Buffer& list() const { return list_; }

  // Marks every tile changed at `step` (a new state), and counts the whole
  // grid as the last listing, so that an automatic choice starts full.
  void markAll(uint32_t step);
  // The boundary the list's neighbourhoods follow (wrap reaches across edges).
  void setBoundary(Boundary boundary) { boundary_ = boundary; }

  // Lists the tiles with a tile changed at `changedStep` in their 3x3
  // neighbourhood; `accumulate` adds them to the running total (off when the
  // list only measures). The caller orders earlier compute writes before it
  // and the list's compute reads after it; this orders the indirect arguments.
  void recordList(const vk::raii::CommandBuffer& cmd, uint32_t changedStep, bool accumulate);
  // One workgroup per listed tile, for the pipeline bound by the caller.
  void recordListedDispatch(const vk::raii::CommandBuffer& cmd) const;
  // Makes the counters readable by the host once the submission has finished.
  void recordHostRead(const vk::raii::CommandBuffer& cmd) const;

  // Tiles listed by the last recordList of a finished submission. Read while
  // a submission runs, it may be older: the dispatch rule, the only user,
  // affects speed, never results.
  uint32_t lastListed() const;
  // The running total of accumulated listings, then zero.
  uint64_t takeListedTotal();

 private:
  const gpu::Context& ctx_;
  uint32_t perSide_;
  Boundary boundary_;
  gpu::Pipeline listPipeline_;
  gpu::Buffer changedAt_, list_, counters_;
  gpu::DescriptorArena descriptors_;
  vk::DescriptorSet listSet_;
};

}  // namespace tp::sim
