#include "render/objects.hpp"

#include "gpu/commands.hpp"
#include "render/pass_kinds.hpp"
#include "shading/frame_uniforms.hpp"
#include "shading/objects_model.hpp"

namespace tp::render {

Objects::Objects(const gpu::Context& ctx, FragmentNeeds needs, const PoolDraw& pool)
    : spheres_(gpu::createGraphicsPipeline(
          ctx, opaquePipeline("sphere.vert", "sphere.frag", sizeof(shader::SphereParams), needs))),
      boxes_(
          gpu::createGraphicsPipeline(ctx, opaquePipeline("box.vert", "box.frag", sizeof(shader::BoxParams), needs))),
      poolUniforms_(pool.uniforms),
      floorVertices_(pool.floorVertices),
      caustics_(pool.caustics),
      waterCells_(pool.waterCells) {}

void Objects::declare(FrameGraph& graph, const SurfaceTargets& targets, const FrameInputs& in,
                      const ObjectsInView& inView, std::vector<GraphImage> probeMaps) const {
  graph.pass(passes::kObjects,
             [this, targets, in, &inView, probeMaps](PassBuilder& pass) {
               attachSurfaces(pass, targets, false);
               // One set with the sky's glossy map, one with each probe.
               auto withGlossy = [&](const GraphImage& glossy) -> Bindings& {
                 return pass.bindings()
                     .uniformBuffer(0, in.uniforms, Use::HostData)
                     .storageBuffer(TP_GLASS_TABLES_BINDING, in.glassTables, Use::HostData)
                     .uniformBuffer(1, in.medium, Use::FragmentUniformRead)
                     .sampledImage(2, glossy, in.equirect, Use::FragmentSample)
                     .constantBuffer(3, *poolUniforms_)
                     .sampledImage(4, caustics_, in.clamp, Use::FragmentSample)
                     .storageBuffer(5, waterCells_, Use::FragmentStorageRead)
                     .constantStorageBuffer(6, *floorVertices_);
               };
               Bindings& set = withGlossy(in.glossy);
               std::vector<const Bindings*> probeSets;
               for (const GraphImage& map : probeMaps) probeSets.push_back(&withGlossy(map));
               return [this, targets, &set, probeSets, &inView](PassContext& pc) {
                 drawSurfaces(pc.cmd, targets, false,
                              [&] { drawObjects(pc.cmd, pc.descriptors, spheres_, boxes_, set, inView, probeSets); });
               };
             },
             {.cached = false, .runIf = [&inView] { return !inView.empty(); }});
}

void drawObjects(const vk::raii::CommandBuffer& cmd, gpu::DescriptorArena& arena, const gpu::Pipeline& spheres,
                 const gpu::Pipeline& boxes, const Bindings& set, const ObjectsInView& inView,
                 std::span<const Bindings* const> probeSets) {
  if (!inView.spheres.empty()) {
    cmd.bindPipeline(spheres.bindPoint, *spheres.pipeline);
    const Bindings* bound = nullptr;
    for (size_t k = 0; k < inView.spheres.size(); ++k) {
      const uint32_t probe = k < inView.sphereProbes.size() ? inView.sphereProbes[k] : kNoGlossyProbe;
      const Bindings* wanted = probe < probeSets.size() ? probeSets[probe] : &set;
      if (wanted != bound) wanted->bind(cmd, spheres, arena);
      bound = wanted;
      gpu::bindPipeline(cmd, spheres, inView.spheres[k]);
      gpu::draw(cmd, sphereVertexCount(inView.spheres[k].tessellation));
    }
  }
  if (!inView.boxes.empty()) {
    cmd.bindPipeline(boxes.bindPoint, *boxes.pipeline);
    set.bind(cmd, boxes, arena);
    for (const auto& box : inView.boxes) {
      gpu::bindPipeline(cmd, boxes, box);
      gpu::draw(cmd, kBoxVertices);
    }
  }
}

}  // namespace tp::render
