#include "render/water_surface.hpp"

#include <stdexcept>

#include "gpu/commands.hpp"
#include "gpu/transfer.hpp"
#include "render/pass_kinds.hpp"
#include "shading/frame_uniforms.hpp"
#include "shading/water_model.hpp"

namespace tp::render {
namespace {

// One side of the water mesh, the other side culled; the fragment shader's
// variant and specialization as `needs` says.
gpu::GraphicsPipelineDesc waterSide(const std::string& fragmentShader, vk::CullModeFlags cull, FragmentNeeds needs) {
  return {.vertexShader = "water_surface.vert",
          .fragmentShader = fragmentVariant(fragmentShader, needs),
          .pushSize = sizeof(shader::WaterSurfaceParams),
          .colorFormats = needs.clearAmbient ? std::vector{kHdrFormat, kGbufferFormat} : std::vector{kHdrFormat},
          .depthFormat = kDepthFormat,
          .depthTest = true,
          .depthWrite = true,
          .topology = vk::PrimitiveTopology::eTriangleStrip,
          .cullMode = cull,
          .fragmentSpecialization = fragmentSpecialization(needs)};
}

// The water's shaders have no G-buffer outputs and no colour-only variant;
// their rays may meet glass. The deferred shading and the side seen from
// below may clear the ambient image.
FragmentNeeds waterNeeds(const scene::Scene& scene, FragmentNeeds surfaces, bool clearAmbient) {
  FragmentNeeds needs = surfaces;
  needs.gbuffer = true;
  needs.glass = scene::hasGlass(scene);
  needs.clearAmbient = clearAmbient;
  return needs;
}

}  // namespace

WaterSurface::WaterSurface(const gpu::Context& ctx, FrameGraph& graph, const scene::Scene& scene,
                           FragmentNeeds surfaces, sim::GpuStepper& stepper, vk::Extent2D frame, bool deferred,
                           bool clearAmbient)
    : below_(gpu::createGraphicsPipeline(ctx, waterSide("water_surface_below.frag", vk::CullModeFlagBits::eFront,
                                                        waterNeeds(scene, surfaces, clearAmbient)))),
      clearAmbient_(clearAmbient),
      mesh_(ctx, scene.water.grid, true, "water grid") {
  if (clearAmbient && (!deferred || apparentRefraction(scene))) {
    throw std::logic_error("only the deferred water clears the ambient image");
  }
  const ResourceRef state0 = graph.buffer("water state 0", stepper.buffer(0)).ref;
  const ResourceRef state1 = graph.buffer("water state 1", stepper.buffer(1)).ref;
  draw_ = WaterDraw{{{state0, state1}, [&stepper]() -> const gpu::Buffer& { return stepper.current(); }},
                    &mesh_,
                    waterSurfaceParams(scene)};
  if (apparentRefraction(scene)) {
    underwater_ =
        gpu::createImage2D(ctx, frame, kHdrFormat,
                           vk::ImageUsageFlagBits::eSampled | vk::ImageUsageFlagBits::eTransferDst, "underwater image");
    underwaterRef_ = graph.image("underwater", underwater_);
  } else if (deferred) {
    deferred_.emplace(ctx, graph, frame, waterNeeds(scene, surfaces, clearAmbient));
  }
  if (!deferred_) {
    above_.emplace(gpu::createGraphicsPipeline(
        ctx, waterSide(apparentRefraction(scene) ? "water_surface_apparent.frag" : "water_surface.frag",
                       vk::CullModeFlagBits::eBack, waterNeeds(scene, surfaces, false))));
  }
}

void WaterSurface::declareUnderwater(FrameGraph& graph, const GraphImage& color) const {
  if (!underwaterRef_) return;
  graph.pass(passes::kUnderwater, [this, color](PassBuilder& pass) {
    const gpu::Image& from = pass.attach(color, Use::TransferRead);
    const gpu::Image& to = pass.attach(*underwaterRef_, Use::TransferWrite);
    return [&from, &to](PassContext& pc) { gpu::recordImageCopy(pc.cmd, from, to); };
  });
}

void WaterSurface::declare(FrameGraph& graph, const SurfaceTargets& targets, const PoolDraw& pool,
                           const FrameInputs& in) const {
  // Deferred, the side seen from above is shaded before the side seen from
  // below is drawn, which the depth test then keeps where it is nearer.
  if (deferred_) deferred_->declare(graph, targets, draw_, pool, in);
  graph.pass(deferred_ ? passes::kWaterBelow : passes::kWater, [this, targets, pool, in](PassBuilder& pass) {
    const gpu::Image& color = pass.attach(targets.color, Use::ColorReadWrite);
    const gpu::Image& depth = pass.attach(targets.depth, Use::DepthReadWrite);
    const gpu::Image* ambient = clearAmbient_ ? &pass.attach(targets.ambient, Use::ColorReadWrite) : nullptr;
    Bindings& set = pass.bindings()
                        .uniformBuffer(0, in.uniforms, Use::HostData)
                        .storageBuffer(TP_GLASS_TABLES_BINDING, in.glassTables, Use::HostData)
                        .sampledImage(1, in.sky, in.equirect, Use::FragmentSample)
                        .storageBuffer(2, draw_.state, Use::VertexStorageRead)
                        .constantBuffer(3, *pool.uniforms)
                        .constantBuffer(4, *pool.objects);
    if (underwaterRef_) set.sampledImage(5, *underwaterRef_, in.nearest, Use::FragmentSample);
    // The floor the refracted (or, from below, reflected) rays meet, and the
    // glossy walls and spheres they meet.
    set.sampledImage(6, pool.caustics, in.clamp, Use::FragmentSample)
        .sampledImage(7, in.glossy, in.equirect, Use::FragmentSample)
        .constantStorageBuffer(8, *pool.floorVertices);
    return [this, &color, &depth, ambient, &set](PassContext& pc) {
      drawOver(
          pc.cmd, color, depth,
          [&] {
            const std::vector<const gpu::Pipeline*> sides =
                above_ ? std::vector{&*above_, &below_} : std::vector{&below_};
            for (const gpu::Pipeline* side : sides) {
              gpu::bindPipeline(pc.cmd, *side, draw_.params);
              set.bind(pc.cmd, *side, pc.descriptors);
              drawWater(pc.cmd, draw_);
            }
          },
          ambient);
    };
  });
}

}  // namespace tp::render
