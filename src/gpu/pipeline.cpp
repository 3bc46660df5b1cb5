#include "gpu/pipeline.hpp"

#include <stdexcept>

#include "gpu/commands.hpp"
#include "gpu/spirv_library.hpp"

namespace tp::gpu {
namespace {

struct LoadedShader {
  vk::raii::ShaderModule module = nullptr;
  ShaderReflection reflection;
};

LoadedShader loadShader(const Context& ctx, const std::string& name) {
  auto code = spirvModule(name + ".spv");
  LoadedShader s;
  s.reflection = reflectSpirv(code);
  s.module = vk::raii::ShaderModule(ctx.device(),
                                    vk::ShaderModuleCreateInfo{.codeSize = code.size_bytes(), .pCode = code.data()});
  return s;
}

void mergeBindings(std::vector<PipelineBinding>& into, const ShaderReflection& r, const std::string& name) {
  for (const auto& b : r.bindings) {
    bool merged = false;
    for (auto& existing : into) {
      if (existing.binding != b.binding) continue;
      if (existing.type != b.type)
        throw std::runtime_error(name + ": binding " + std::to_string(b.binding) + " has two types");
      existing.stages |= r.stage;
      merged = true;
    }
    if (!merged) into.push_back({b.binding, b.type, r.stage});
  }
}

void createLayout(const Context& ctx, Pipeline& p) {
  std::vector<vk::DescriptorSetLayoutBinding> bindings;
  for (const auto& b : p.bindings) {
    bindings.push_back({.binding = b.binding, .descriptorType = b.type, .descriptorCount = 1, .stageFlags = b.stages});
  }
  p.setLayout = vk::raii::DescriptorSetLayout(
      ctx.device(),
      vk::DescriptorSetLayoutCreateInfo{.bindingCount = uint32_t(bindings.size()), .pBindings = bindings.data()});
  vk::PushConstantRange range{.stageFlags = p.pushStages, .offset = 0, .size = p.pushSize};
  vk::DescriptorSetLayout setLayout = *p.setLayout;
  p.layout = vk::raii::PipelineLayout(ctx.device(), vk::PipelineLayoutCreateInfo{
                                                        .setLayoutCount = 1,
                                                        .pSetLayouts = &setLayout,
                                                        .pushConstantRangeCount = p.pushSize ? 1u : 0u,
                                                        .pPushConstantRanges = &range,
                                                    });
}

void checkPush(const Context& ctx, const Pipeline& p, bool shaderHasPush) {
  if (shaderHasPush != (p.pushSize > 0)) {
    throw std::runtime_error(p.name + ": the shader " + (shaderHasPush ? "has" : "has no") +
                             " push constants but C++ declares " + std::to_string(p.pushSize) + " bytes");
  }
  if (p.pushSize > ctx.limits().maxPushConstantsSize) {
    throw std::runtime_error(p.name + ": " + std::to_string(p.pushSize) +
                             " bytes of push constants, the device allows " +
                             std::to_string(ctx.limits().maxPushConstantsSize));
  }
}

}  // namespace

Pipeline createComputePipeline(const Context& ctx, const std::string& shader, uint32_t pushSize,
                               const Specialization& specialization) {
  LoadedShader s = loadShader(ctx, shader);
  if (s.reflection.stage != vk::ShaderStageFlagBits::eCompute)
    throw std::runtime_error(shader + " is not a compute shader");
  Pipeline p;
  p.name = shader;
  p.bindPoint = vk::PipelineBindPoint::eCompute;
  p.pushSize = pushSize;
  p.pushStages = vk::ShaderStageFlagBits::eCompute;
  p.localSize = s.reflection.localSize;
  checkPush(ctx, p, s.reflection.pushConstants);
  mergeBindings(p.bindings, s.reflection, shader);
  createLayout(ctx, p);
  vk::SpecializationInfo spec = specialization.info();
  p.pipeline = vk::raii::Pipeline(ctx.device(), nullptr,
                                  vk::ComputePipelineCreateInfo{
                                      .stage = {.stage = vk::ShaderStageFlagBits::eCompute,
                                                .module = *s.module,
                                                .pName = "main",
                                                .pSpecializationInfo = specialization.empty() ? nullptr : &spec},
                                      .layout = *p.layout,
                                  });
  return p;
}

Pipeline createGraphicsPipeline(const Context& ctx, const GraphicsPipelineDesc& desc) {
  LoadedShader vs = loadShader(ctx, desc.vertexShader);
  LoadedShader fs = loadShader(ctx, desc.fragmentShader);
  Pipeline p;
  p.name = desc.vertexShader + "+" + desc.fragmentShader;
  p.bindPoint = vk::PipelineBindPoint::eGraphics;
  p.pushSize = desc.pushSize;
  if (vs.reflection.pushConstants) p.pushStages |= vk::ShaderStageFlagBits::eVertex;
  if (fs.reflection.pushConstants) p.pushStages |= vk::ShaderStageFlagBits::eFragment;
  checkPush(ctx, p, vs.reflection.pushConstants || fs.reflection.pushConstants);
  mergeBindings(p.bindings, vs.reflection, p.name);
  mergeBindings(p.bindings, fs.reflection, p.name);
  createLayout(ctx, p);

  const vk::SpecializationInfo spec = desc.fragmentSpecialization.info();
  vk::PipelineShaderStageCreateInfo stages[] = {
      {.stage = vk::ShaderStageFlagBits::eVertex, .module = *vs.module, .pName = "main"},
      {.stage = vk::ShaderStageFlagBits::eFragment,
       .module = *fs.module,
       .pName = "main",
       .pSpecializationInfo = desc.fragmentSpecialization.empty() ? nullptr : &spec},
  };
  vk::PipelineVertexInputStateCreateInfo vertexInput{};  // vertices are pulled from buffers or gl_VertexIndex
  // Strips are drawn row by row, the rows separated by the restart index.
  const bool strip = desc.topology == vk::PrimitiveTopology::eTriangleStrip;
  vk::PipelineInputAssemblyStateCreateInfo inputAssembly{.topology = desc.topology, .primitiveRestartEnable = strip};
  vk::PipelineViewportStateCreateInfo viewport{.viewportCount = 1, .scissorCount = 1};
  vk::PipelineRasterizationStateCreateInfo raster{.polygonMode = vk::PolygonMode::eFill,
                                                  .cullMode = desc.cullMode,
                                                  .frontFace = vk::FrontFace::eCounterClockwise,
                                                  .lineWidth = 1.0f};
  vk::PipelineMultisampleStateCreateInfo multisample{.rasterizationSamples = vk::SampleCountFlagBits::e1};
  vk::PipelineDepthStencilStateCreateInfo depth{.depthTestEnable = desc.depthTest,
                                                .depthWriteEnable = desc.depthWrite,
                                                .depthCompareOp = vk::CompareOp::eLessOrEqual};
  std::vector<vk::PipelineColorBlendAttachmentState> blends(
      desc.colorFormats.size(),
      vk::PipelineColorBlendAttachmentState{
          .blendEnable = desc.additive ? VK_TRUE : VK_FALSE,
          .srcColorBlendFactor = vk::BlendFactor::eOne,
          .dstColorBlendFactor = vk::BlendFactor::eOne,
          .colorBlendOp = vk::BlendOp::eAdd,
          .srcAlphaBlendFactor = vk::BlendFactor::eOne,
          .dstAlphaBlendFactor = vk::BlendFactor::eOne,
          .alphaBlendOp = vk::BlendOp::eAdd,
          .colorWriteMask = desc.colorWrites ? vk::ColorComponentFlagBits::eR | vk::ColorComponentFlagBits::eG |
                                                   vk::ColorComponentFlagBits::eB | vk::ColorComponentFlagBits::eA
                                             : vk::ColorComponentFlags{}});
  vk::PipelineColorBlendStateCreateInfo blend{.attachmentCount = uint32_t(blends.size()),
                                              .pAttachments = blends.data()};
  vk::DynamicState dynamicStates[] = {vk::DynamicState::eViewport, vk::DynamicState::eScissor};
  vk::PipelineDynamicStateCreateInfo dynamic{.dynamicStateCount = 2, .pDynamicStates = dynamicStates};

  vk::StructureChain<vk::GraphicsPipelineCreateInfo, vk::PipelineRenderingCreateInfo> chain{
      vk::GraphicsPipelineCreateInfo{
          .stageCount = 2,
          .pStages = stages,
          .pVertexInputState = &vertexInput,
          .pInputAssemblyState = &inputAssembly,
          .pViewportState = &viewport,
          .pRasterizationState = &raster,
          .pMultisampleState = &multisample,
          .pDepthStencilState = &depth,
          .pColorBlendState = &blend,
          .pDynamicState = &dynamic,
          .layout = *p.layout,
      },
      vk::PipelineRenderingCreateInfo{
          .colorAttachmentCount = uint32_t(desc.colorFormats.size()),
          .pColorAttachmentFormats = desc.colorFormats.data(),
          .depthAttachmentFormat = desc.depthFormat,
      },
  };
  p.pipeline = vk::raii::Pipeline(ctx.device(), nullptr, chain.get<vk::GraphicsPipelineCreateInfo>());
  return p;
}

void dispatchCovering(const vk::raii::CommandBuffer& cmd, const Pipeline& p, uint32_t x, uint32_t y, uint32_t z) {
  auto groups = [](uint32_t n, uint32_t local) { return (n + local - 1) / local; };
  dispatch(cmd, groups(x, p.localSize[0]), groups(y, p.localSize[1]), groups(z, p.localSize[2]));
}

}  // namespace tp::gpu
