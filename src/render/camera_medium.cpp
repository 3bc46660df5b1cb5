#include "render/camera_medium.hpp"

#include "gpu/commands.hpp"
#include "gpu/transfer.hpp"
#include "render/pass_kinds.hpp"
#include "shading/water_model.hpp"
#include "shared/water_surface.h"

namespace tp::render {

CameraMedium::CameraMedium(const gpu::Context& ctx, FrameGraph& graph, bool water) {
  const shader::CameraMedium air = cameraInAir();
  medium_ = gpu::createFilledBuffer(ctx, &air, sizeof(air),
                                    vk::BufferUsageFlagBits::eStorageBuffer | vk::BufferUsageFlagBits::eUniformBuffer,
                                    gpu::MemoryUse::Device, "camera medium");
  ref_ = graph.buffer("camera medium", medium_);
  if (water) pipeline_ = gpu::createComputePipeline(ctx, "camera_medium.comp", sizeof(shader::WaterSurfaceParams));
}

void CameraMedium::declare(FrameGraph& graph, const WaterDraw& water, const FrameInputs& in,
                           std::function<bool()> runIf) const {
  graph.pass(passes::kCameraMedium,
             [this, water, in](PassBuilder& pass) {
               Bindings& set = pass.bindings()
                                   .uniformBuffer(0, in.uniforms, Use::HostData)
                                   .storageBuffer(1, ref_, Use::ComputeWrite)
                                   .storageBuffer(2, water.state, Use::ComputeRead);
               return [this, water, &set](PassContext& pc) {
                 gpu::bindPipeline(pc.cmd, *pipeline_, water.params);
                 set.bind(pc.cmd, *pipeline_, pc.descriptors);
                 gpu::dispatch(pc.cmd, 1);
               };
             },
             {.cached = true, .runIf = std::move(runIf)});
}

}  // namespace tp::render
