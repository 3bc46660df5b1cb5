#include "render/frame_targets.hpp"

#include "render/pass_kinds.hpp"

namespace tp::render {

FrameTargets::FrameTargets(const gpu::Context& ctx, FrameGraph& graph, vk::Extent2D extent, bool gbuffer,
                           bool sampledDepth)
    : color_(gpu::createImage2D(ctx, extent, kHdrFormat,
                                vk::ImageUsageFlagBits::eColorAttachment | vk::ImageUsageFlagBits::eStorage |
                                    vk::ImageUsageFlagBits::eTransferSrc | vk::ImageUsageFlagBits::eTransferDst,
                                "HDR color target")),
      // Every target is a transfer destination: each frame begins with the ground's copy (render/ground.hpp).
      depth_(gpu::createImage2D(
          ctx, extent, kDepthFormat,
          sampledDepth ? vk::ImageUsageFlagBits::eDepthStencilAttachment | vk::ImageUsageFlagBits::eSampled |
                             vk::ImageUsageFlagBits::eTransferSrc | vk::ImageUsageFlagBits::eTransferDst
                       : vk::ImageUsageFlagBits::eDepthStencilAttachment | vk::ImageUsageFlagBits::eTransferDst,
          "depth target")),
      ldr_(gpu::createImage2D(ctx, extent, kLdrFormat,
                              vk::ImageUsageFlagBits::eStorage | vk::ImageUsageFlagBits::eTransferSrc, "LDR preview")),
      hdrReadback_(ctx, graph, "color readback", vk::DeviceSize(extent.width) * extent.height * 16),
      ldrReadback_(ctx, graph, "ldr readback", vk::DeviceSize(extent.width) * extent.height * 4) {
  surfaces_.color = graph.image("color", color_);
  surfaces_.depth = graph.image("depth", depth_);
  if (gbuffer) {
    const auto usage = vk::ImageUsageFlagBits::eColorAttachment | vk::ImageUsageFlagBits::eStorage |
                       vk::ImageUsageFlagBits::eTransferDst;
    normal_ = gpu::createImage2D(ctx, extent, kGbufferFormat, usage | vk::ImageUsageFlagBits::eTransferSrc,
                                 "G-buffer view normal");
    ambient_ = gpu::createImage2D(ctx, extent, kGbufferFormat, usage, "G-buffer ambient radiance");
    surfaces_.normal = graph.image("view normal", normal_);
    surfaces_.ambient = graph.image("ambient", ambient_);
  }
  ldrRef_ = graph.image("ldr", ldr_);
}

void FrameTargets::declareReadbacks(FrameGraph& graph) const {
  declareReadback(graph, passes::kReadbackHdr, surfaces_.color, hdrReadback_);
  declareReadback(graph, passes::kReadbackLdr, ldrRef_, ldrReadback_);
}

}  // namespace tp::render
