#include "graph/frame_graph.hpp"

#include <stdexcept>

namespace tp::render {
namespace {

using S = vk::PipelineStageFlagBits2;
using A = vk::AccessFlagBits2;
using L = vk::ImageLayout;

struct UseInfo {
  gpu::Access access;
  L layout;
  bool reads;
  bool writes;
};

UseInfo info(Use use) {
  switch (use) {
    case Use::ComputeRead:
      return {{S::eComputeShader, A::eShaderStorageRead}, L::eGeneral, true, false};
    case Use::ComputeWrite:
      return {{S::eComputeShader, A::eShaderStorageWrite}, L::eGeneral, false, true};
    case Use::ComputeReadWrite:
      return {{S::eComputeShader, A::eShaderStorageRead | A::eShaderStorageWrite}, L::eGeneral, true, true};
    case Use::ComputeReadIndirect:
      return {{S::eComputeShader | S::eDrawIndirect, A::eShaderStorageRead | A::eIndirectCommandRead},
              L::eGeneral,
              true,
              false};
    case Use::FragmentStorageWrite:
      return {{S::eFragmentShader, A::eShaderStorageWrite}, L::eGeneral, false, true};
    case Use::FragmentSample:
      return {{S::eFragmentShader, A::eShaderSampledRead}, L::eShaderReadOnlyOptimal, true, false};
    case Use::ComputeSample:
      return {{S::eComputeShader, A::eShaderSampledRead}, L::eShaderReadOnlyOptimal, true, false};
    case Use::ColorWrite:
      return {{S::eColorAttachmentOutput, A::eColorAttachmentWrite}, L::eColorAttachmentOptimal, false, true};
    case Use::ColorReadWrite:
      return {{S::eColorAttachmentOutput, A::eColorAttachmentRead | A::eColorAttachmentWrite},
              L::eColorAttachmentOptimal,
              true,
              true};
    case Use::DepthWrite:
      return {{S::eEarlyFragmentTests | S::eLateFragmentTests,
               A::eDepthStencilAttachmentRead | A::eDepthStencilAttachmentWrite},
              L::eDepthAttachmentOptimal,
              false,
              true};
    case Use::DepthReadWrite:
      return {{S::eEarlyFragmentTests | S::eLateFragmentTests,
               A::eDepthStencilAttachmentRead | A::eDepthStencilAttachmentWrite},
              L::eDepthAttachmentOptimal,
              true,
              true};
    case Use::FragmentUniformRead:
      return {{S::eFragmentShader, A::eUniformRead}, L::eGeneral, true, false};
    case Use::ComputeUniformRead:
      return {{S::eComputeShader, A::eUniformRead}, L::eGeneral, true, false};
    case Use::VertexStorageRead:
      return {{S::eVertexShader, A::eShaderStorageRead}, L::eGeneral, true, false};
    case Use::FragmentStorageRead:
      return {{S::eFragmentShader, A::eShaderStorageRead}, L::eGeneral, true, false};
    case Use::TransferRead:
      return {{S::eCopy, A::eTransferRead}, L::eTransferSrcOptimal, true, false};
    case Use::TransferWrite:
      return {{S::eCopy, A::eTransferWrite}, L::eTransferDstOptimal, false, true};
    case Use::TransferWritePart:
      return {{S::eCopy, A::eTransferWrite}, L::eTransferDstOptimal, true, true};
    case Use::HostData:
      return {{S::eVertexShader | S::eFragmentShader | S::eComputeShader, A::eUniformRead}, L::eGeneral, true, false};
  }
  throw std::logic_error("unknown Use");
}

constexpr vk::AccessFlags2 kWriteAccess = A::eShaderStorageWrite | A::eColorAttachmentWrite |
                                          A::eDepthStencilAttachmentWrite | A::eTransferWrite | A::eHostWrite;

}  // namespace

GraphImage FrameGraph::image(std::string name, const gpu::Image& image, vk::ImageLayout layout) {
  Resource r;
  r.name = std::move(name);
  r.image = image.handle();
  r.aspect = image.aspect;
  r.layout = layout;
  resources_.push_back(std::move(r));
  return {{uint32_t(resources_.size() - 1)}, &image};
}

GraphBuffer FrameGraph::buffer(std::string name, const gpu::Buffer& buffer) {
  Resource r;
  r.name = std::move(name);
  r.buffer = buffer.handle();
  resources_.push_back(std::move(r));
  return {{uint32_t(resources_.size() - 1)}, &buffer};
}

FrameGraph::Resource& FrameGraph::at(ResourceRef ref) {
  if (ref.index >= resources_.size()) throw std::logic_error("FrameGraph: unknown resource");
  return resources_[ref.index];
}

void FrameGraph::pass(const PassKind& kind, const std::function<Recorder(PassBuilder&)>& declare, PassOptions options) {
  PassBuilder builder;
  Recorder record = declare(builder);
  const std::string name(kind.name);
  for (const auto& [ref, use] : builder.uses_) {
    const Resource& r = at(ref);
    // A buffer may be a copy's end; else only uses in the general layout fit it.
    const UseInfo u = info(use);
    if (!r.image && u.layout != L::eGeneral && u.access.stage != S::eCopy) {
      throw std::logic_error("FrameGraph: pass " + name + " uses buffer " + r.name + " as an image");
    }
  }
  passes_.push_back(
      {&kind, std::move(builder.uses_), std::move(builder.sets_), std::move(record), std::move(options), false, {}});
}

void FrameGraph::touch(ResourceRef ref) { ++at(ref).version; }

std::vector<bool> FrameGraph::needed(std::span<const ResourceRef> requested, const std::vector<bool>& absent) const {
  // Walk back from the requested resources: a pass is needed when it writes a
  // live resource, and then everything it reads is live too.
  std::vector<bool> live(resources_.size(), false);
  for (ResourceRef r : requested) live.at(r.index) = true;
  std::vector<bool> keep(passes_.size(), false);
  for (size_t p = passes_.size(); p-- > 0;) {
    if (absent[p]) continue;
    for (const auto& [ref, use] : passes_[p].uses) {
      if (info(use).writes && live[ref.index]) keep[p] = true;
    }
    if (!keep[p]) continue;
    for (const auto& [ref, use] : passes_[p].uses) {
      if (info(use).reads) live[ref.index] = true;
    }
  }
  return keep;
}

void FrameGraph::barriersFor(const Pass& pass, std::vector<vk::BufferMemoryBarrier2>& buffers,
                             std::vector<vk::ImageMemoryBarrier2>& images) {
  for (const auto& [ref, use] : pass.uses) {
    Resource& r = at(ref);
    const UseInfo u = info(use);
    const bool isImage = bool(r.image);
    const bool layoutChange = isImage && r.layout != u.layout;
    gpu::Access src = gpu::access::none;
    L oldLayout = r.layout;
    bool emit = false;
    if (u.writes || layoutChange) {
      // Write after write or read, or a layout transition: wait for the last
      // write (and make it available) and for every read since.
      src = {r.lastWrite.stage | r.readStages, r.lastWrite.access};
      emit = layoutChange || src.stage != S::eNone;
      if (u.writes && !u.reads) oldLayout = L::eUndefined;  // contents are replaced
      r.layout = u.layout;
      if (u.writes) {
        r.lastWrite = {u.access.stage, u.access.access & kWriteAccess};
      } else {
        r.lastWrite = {u.access.stage, A::eNone};  // the transition, finished before this stage
      }
      // A write in this pass is visible to no one yet, not even to a later
      // pass of the same stage; a transition alone makes the last write
      // visible to this use.
      r.visible = u.writes ? gpu::access::none : u.access;
      r.readStages = u.reads ? u.access.stage : S::eNone;
    } else {
      // Read after write: make the write visible to this stage and access once.
      const bool covered = (r.visible.stage & u.access.stage) == u.access.stage &&
                           (r.visible.access & u.access.access) == u.access.access;
      if (r.lastWrite.stage != S::eNone && !covered) {
        src = r.lastWrite;
        emit = true;
        r.visible = {r.visible.stage | u.access.stage, r.visible.access | u.access.access};
      }
      r.readStages |= u.access.stage;
    }
    if (!emit) continue;
    if (isImage) {
      images.push_back(gpu::imageBarrier(r.image, r.aspect, src, oldLayout, u.access, u.layout));
    } else {
      buffers.push_back(gpu::bufferBarrier(r.buffer, src, u.access));
    }
  }
}

std::vector<bool> FrameGraph::toRecord(std::span<const ResourceRef> requested) const {
  std::vector<bool> absent(passes_.size(), false);
  for (size_t p = 0; p < passes_.size(); ++p) absent[p] = passes_[p].options.runIf && !passes_[p].options.runIf();
  auto keep = needed(requested, absent);
  if (!caching_) return keep;
  // A cached pass is fresh when every resource it uses will be at the version
  // it saw, after the writes of the passes recorded before it this frame.
  // Leaving a fresh pass out can only leave more passes out (their outputs
  // then feed nothing, or do not change), so repeat until nothing changes.
  for (bool changed = true; changed;) {
    changed = false;
    std::vector<uint64_t> version(resources_.size());
    for (size_t r = 0; r < resources_.size(); ++r) version[r] = resources_[r].version;
    for (size_t p = 0; p < passes_.size(); ++p) {
      if (!keep[p]) continue;
      const Pass& pass = passes_[p];
      bool fresh = pass.options.cached && pass.ran;
      for (size_t u = 0; fresh && u < pass.uses.size(); ++u) fresh = version[pass.uses[u].first.index] == pass.seen[u];
      if (fresh) {
        absent[p] = true;
        changed = true;
        continue;
      }
      for (const auto& [ref, use] : pass.uses) {
        if (info(use).writes) ++version[ref.index];
      }
    }
    if (changed) keep = needed(requested, absent);
  }
  return keep;
}

namespace {

// Both constnesses of findPass.
template <typename Passes>
auto* findPassIn(Passes& passes, const PassKind& kind) {
  decltype(&passes.front()) found = nullptr;
  for (auto& p : passes) {
    if (p.kind == &kind) return &p;
  }
  return found;
}

}  // namespace

RecordedPass* findPass(std::vector<RecordedPass>& passes, const PassKind& kind) { return findPassIn(passes, kind); }

const RecordedPass* findPass(const std::vector<RecordedPass>& passes, const PassKind& kind) {
  return findPassIn(passes, kind);
}

std::vector<RecordedPass> FrameGraph::record(PassContext& context, std::span<const ResourceRef> requested,
                                             gpu::GpuTimer* timer, const AfterPass& afterPass) {
  const vk::raii::CommandBuffer& cmd = context.cmd;
  std::vector<RecordedPass> recorded;
  const auto keep = toRecord(requested);
  for (size_t p = 0; p < passes_.size(); ++p) {
    if (!keep[p]) continue;
    Pass& pass = passes_[p];
    std::vector<vk::BufferMemoryBarrier2> bufferBarriers;
    std::vector<vk::ImageMemoryBarrier2> imageBarriers;
    barriersFor(pass, bufferBarriers, imageBarriers);
    gpu::pipelineBarrier(cmd, bufferBarriers, imageBarriers);
    const std::string name(pass.kind->name);
    uint32_t scope = timer ? timer->begin(cmd, name) : 0;
    RecordedPass done;
    done.kind = pass.kind;
    done.name = name;
    for (const auto& [ref, use] : pass.uses) done.resources.push_back(at(ref).name);
    {
      gpu::CountScope counting(done.counts);
      pass.record(context);
    }
    if (timer) timer->end(cmd, scope);
    if (gpu::CommandCounts* frame = gpu::currentCounts()) *frame += done.counts;
    for (const auto& [ref, use] : pass.uses) {
      if (info(use).writes) ++at(ref).version;
    }
    pass.seen.clear();
    for (const auto& [ref, use] : pass.uses) pass.seen.push_back(at(ref).version);
    pass.ran = true;
    if (afterPass) afterPass(done);
    recorded.push_back(std::move(done));
  }
  std::vector<vk::BufferMemoryBarrier2> toHost;
  for (ResourceRef ref : requested) {
    Resource& r = at(ref);
    if (r.buffer && r.lastWrite.access != A::eNone) {
      toHost.push_back(gpu::bufferBarrier(r.buffer, r.lastWrite, gpu::access::hostRead));
      r.visible = gpu::access::hostRead;
    }
  }
  gpu::pipelineBarrier(cmd, toHost);
  return recorded;
}

}  // namespace tp::render
