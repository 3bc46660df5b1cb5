#pragma once
#include <functional>
#include <limits>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "gpu/barriers.hpp"
#include "gpu/commands.hpp"
#include "gpu/descriptors.hpp"
#include "gpu/memory.hpp"
#include "gpu/timer.hpp"
#include "graph/pass_builder.hpp"
#include "graph/pass_kind.hpp"
#include "graph/resource_use.hpp"

namespace tp::render {

// What a pass records with: the command buffer and the descriptor sets of this submission.
struct PassContext {
  const vk::raii::CommandBuffer& cmd;
  gpu::DescriptorArena& descriptors;
};

struct RecordedPass {
  const PassKind* kind = nullptr;
  std::string name;
  double milliseconds = 0.0;  // NaN where the device has no timestamps
  // By wall clock, from the pass's own submission to its end (NaN unless the
  // frame was submitted a pass at a time: FrameRequest::passWallTimes).
  double wallMilliseconds = std::numeric_limits<double>::quiet_NaN();
  gpu::CommandCounts counts;           // what the pass recorded
  std::vector<std::string> resources;  // the names of the images and buffers it uses
};

// The pass of that kind among those a frame recorded; null when it was left out.
RecordedPass* findPass(std::vector<RecordedPass>& passes, const PassKind& kind);
const RecordedPass* findPass(const std::vector<RecordedPass>& passes, const PassKind& kind);

struct PassOptions {
  // The pass's outputs keep their contents from frame to frame and depend on
  // nothing but the resources it declares: it is recorded again only when one
  // of them changed (written by a pass, or touched by the host) since it last ran.
  bool cached = false;
  // Asked every frame: false leaves the pass out, and its outputs as they are.
  std::function<bool()> runIf;
};

// A frame declared as passes with their reads and writes. record() keeps only
// the passes that something requested depends on, less those whose runIf says
// no and the cached passes whose inputs have not changed, in declaration
// order, and puts before each the barriers its uses imply. Resource state
// persists from one record() to the next, so a graph declared once can record
// every frame.
class FrameGraph {
 public:
  // `layout`: the layout the image is in when the first recorded frame begins
  // (an image filled before, by an upload whose own barrier made it visible).
  GraphImage image(std::string name, const gpu::Image& image, vk::ImageLayout layout = vk::ImageLayout::eUndefined);
  GraphBuffer buffer(std::string name, const gpu::Buffer& buffer);

  using Recorder = std::function<void(PassContext&)>;
  // A pass of `kind`: `declare` binds what it uses (PassBuilder) and returns
  // what records it. Passes record in the order declared.
  void pass(const PassKind& kind, const std::function<Recorder(PassBuilder&)>& declare, PassOptions options = {});

  size_t passCount() const { return passes_.size(); }

  // The host changed the resource's contents: cached passes reading it run again.
  void touch(ResourceRef ref);
  // A number that changes whenever the resource is written or touched: asked
  // as a pass records, it counts the writes of the passes recorded before it.
  uint64_t versionOf(ResourceRef ref) const { return resources_.at(ref.index).version; }
  // The layout an image is in after the frames recorded so far.
  vk::ImageLayout layoutOf(ResourceRef ref) const { return resources_.at(ref.index).layout; }
  // Off: cached passes run every frame (a frame with nothing skipped, to compare against).
  void setCaching(bool on) { caching_ = on; }

  // Returns the passes recorded, in order, with what each recorded (times are
  // the caller's to fill in from `timer`). Requested buffers end with a
  // barrier that makes them readable on the host. `afterPass`, if given, is
  // called after each pass is recorded (to submit it on its own).
  using AfterPass = std::function<void(RecordedPass&)>;
  std::vector<RecordedPass> record(PassContext& context, std::span<const ResourceRef> requested,
                                   gpu::GpuTimer* timer = nullptr, const AfterPass& afterPass = {});

 private:
  struct Resource {
    std::string name;
    vk::Image image = nullptr;
    vk::ImageAspectFlags aspect;
    vk::Buffer buffer = nullptr;
    vk::ImageLayout layout = vk::ImageLayout::eUndefined;
    gpu::Access lastWrite = gpu::access::none;
    vk::PipelineStageFlags2 readStages;       // stages that read since the last write
    gpu::Access visible = gpu::access::none;  // where the last write has been made visible
    uint64_t version = 0;                     // bumped by every write and touch
  };
  struct Pass {
    const PassKind* kind;
    std::vector<std::pair<ResourceRef, Use>> uses;
    std::vector<std::shared_ptr<Bindings>> sets;  // what `record` binds
    Recorder record;
    PassOptions options;
    bool ran = false;
    std::vector<uint64_t> seen;  // versions of its resources when it last ran, in the order of `uses`
  };

  // Passes that something requested depends on, `absent` ones not counted.
  std::vector<bool> needed(std::span<const ResourceRef> requested, const std::vector<bool>& absent) const;
  std::vector<bool> toRecord(std::span<const ResourceRef> requested) const;
  void barriersFor(const Pass& pass, std::vector<vk::BufferMemoryBarrier2>& buffers,
                   std::vector<vk::ImageMemoryBarrier2>& images);
  Resource& at(ResourceRef ref);

  std::vector<Resource> resources_;
  std::vector<Pass> passes_;
  bool caching_ = true;
};

}  // namespace tp::render
