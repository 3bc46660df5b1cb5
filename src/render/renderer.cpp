#include "render/renderer.hpp"

#include <cstring>
#include <optional>

#include "gpu/submit.hpp"
#include "gpu/timer.hpp"
#include "render/frame_uniforms.hpp"
#include "render/passes.hpp"
#include "render/sky_model.hpp"
#include "render/objects_model.hpp"
#include "render/pool_model.hpp"
#include "render/sky_image.hpp"
#include "render/water_model.hpp"
#include "gpu/transfer.hpp"
#include "sim/gpu_stepper.hpp"

namespace tp::render {

struct Renderer::Resources {
  Resources(const gpu::Context& ctx, const scene::Scene& scene, uint32_t w, uint32_t h, const RendererOptions& options)
      : skyPass(ctx),
        backgroundPass(ctx),
        groundPass(ctx),
        tonemapPass(ctx),
        sampler(ctx.device(), vk::SamplerCreateInfo{.magFilter = vk::Filter::eLinear,
                                                    .minFilter = vk::Filter::eLinear,
                                                    .addressModeU = vk::SamplerAddressMode::eRepeat,
                                                    .addressModeV = vk::SamplerAddressMode::eClampToEdge,
                                                    .addressModeW = vk::SamplerAddressMode::eClampToEdge}),
        nearestSampler(ctx.device(), vk::SamplerCreateInfo{.magFilter = vk::Filter::eNearest,
                                                           .minFilter = vk::Filter::eNearest,
                                                           .addressModeU = vk::SamplerAddressMode::eClampToEdge,
                                                           .addressModeV = vk::SamplerAddressMode::eClampToEdge,
                                                           .addressModeW = vk::SamplerAddressMode::eClampToEdge}),
        clampSampler(ctx.device(), vk::SamplerCreateInfo{.magFilter = vk::Filter::eLinear,
                                                         .minFilter = vk::Filter::eLinear,
                                                         .addressModeU = vk::SamplerAddressMode::eClampToEdge,
                                                         .addressModeV = vk::SamplerAddressMode::eClampToEdge,
                                                         .addressModeW = vk::SamplerAddressMode::eClampToEdge}),
        color(gpu::createImage2D(ctx, {w, h}, kHdrFormat,
                                 vk::ImageUsageFlagBits::eColorAttachment | vk::ImageUsageFlagBits::eStorage |
                                     vk::ImageUsageFlagBits::eTransferSrc,
                                 "HDR color target")),
        depth(gpu::createImage2D(ctx, {w, h}, kDepthFormat, vk::ImageUsageFlagBits::eDepthStencilAttachment,
                                 "depth target")),
        ldr(gpu::createImage2D(ctx, {w, h}, kLdrFormat,
                               vk::ImageUsageFlagBits::eStorage | vk::ImageUsageFlagBits::eTransferSrc, "LDR preview")),
        uniforms(gpu::createBuffer(ctx, sizeof(shader::FrameUniforms), vk::BufferUsageFlagBits::eUniformBuffer,
                                   gpu::MemoryUse::Upload, "frame uniforms")),
        colorReadback(gpu::createBuffer(ctx, vk::DeviceSize(w) * h * 16, vk::BufferUsageFlagBits::eTransferDst,
                                        gpu::MemoryUse::Readback, "HDR readback")),
        ldrReadback(gpu::createBuffer(ctx, vk::DeviceSize(w) * h * 4, vk::BufferUsageFlagBits::eTransferDst,
                                      gpu::MemoryUse::Readback, "LDR readback")),
        descriptors(ctx) {
    if (scene.water.enabled) {
      water.emplace(ctx, render::waterParams(scene.water), waterInitialState(scene.water),
                    sim::StepKernel::OnePerDispatch);
      const auto gridIndices = waterGridIndices(scene.water.grid);
      indexCount = uint32_t(gridIndices.size());
      indices = gpu::createFilledBuffer(ctx, gridIndices, vk::BufferUsageFlagBits::eIndexBuffer, gpu::MemoryUse::Device,
                                        "water grid indices");
      substeps = render::waterSubsteps(scene.water);
    }
    // The sky: the procedural one, filled by the sky pass, or an image, uploaded
    // once (and then no sky pass at all), which alone lights the scene.
    ResourceRef skyRef;
    const bool skyFromImage = !scene.sky.image.empty();
    if (skyFromImage) {
      const SkyImage image = loadSkyImage(scene.sky.image);
      sky = uploadSkyImage(ctx, image);
      light = skyImageLight(image);
      skyRef = graph.image("sky", sky, vk::ImageLayout::eShaderReadOnlyOptimal);
    } else {
      sky = gpu::createImage2D(ctx, {scene.sky.textureWidth, scene.sky.textureWidth / 2}, kSkyFormat,
                               vk::ImageUsageFlagBits::eStorage | vk::ImageUsageFlagBits::eSampled, "sky texture");
      light = proceduralSkyLight(scene.sky);
      skyRef = graph.image("sky", sky);
    }
    colorRef = graph.image("color", color);
    auto depthRef = graph.image("depth", depth);
    auto ldrRef = graph.image("ldr", ldr);
    colorReadbackRef = graph.buffer("color readback", colorReadback);
    ldrReadbackRef = graph.buffer("ldr readback", ldrReadback);

    const shader::GroundParams ground = groundParams(scene);
    std::optional<WaterDraw> waterDraw;
    if (water) {
      waterDraw = WaterDraw{{graph.buffer("water state 0", water->buffer(0)), graph.buffer("water state 1", water->buffer(1))},
                            [this]() -> const gpu::Buffer& { return water->current(); },
                            &indices,
                            indexCount,
                            waterSurfaceParams(scene)};
      graph.pass("simulate",
                 {{waterDraw->stateRefs[0], Use::ComputeReadWrite}, {waterDraw->stateRefs[1], Use::ComputeReadWrite}},
                 [this, scene](PassContext& pc) { recordWaterSteps(pc.cmd, *water, scene, stepsDone, pendingSteps); });
    }
    // The medium around the camera: decided after the simulation where there
    // is water, air (zeros, uploaded once) where there is none.
    if (water) {
      medium = gpu::createBuffer(ctx, sizeof(shader::CameraMedium),
                                 vk::BufferUsageFlagBits::eStorageBuffer | vk::BufferUsageFlagBits::eUniformBuffer,
                                 gpu::MemoryUse::Device, "camera medium");
    } else {
      const shader::CameraMedium air{glm::vec4(0.0f)};
      medium = gpu::createFilledBuffer(ctx, &air, sizeof(air), vk::BufferUsageFlagBits::eUniformBuffer,
                                       gpu::MemoryUse::Upload, "camera medium");
    }
    const MediumDraw mediumDraw{graph.buffer("camera medium", medium), &medium};
    if (water) {
      cameraMediumPass.emplace(ctx);
      cameraMediumPass->declare(graph, *waterDraw, uniforms, mediumDraw);
    }
    std::optional<PoolDraw> poolDraw;
    if (hasPool(scene)) {
      const shader::PoolParams pool = poolParams(scene);
      poolUniforms = gpu::createFilledBuffer(ctx, &pool, sizeof(pool), vk::BufferUsageFlagBits::eUniformBuffer,
                                             gpu::MemoryUse::Upload, "pool uniforms");
      const auto floorGridIndices = waterGridIndices(kPoolFloorGrid);
      floorIndices = gpu::createFilledBuffer(ctx, floorGridIndices, vk::BufferUsageFlagBits::eIndexBuffer,
                                             gpu::MemoryUse::Device, "pool floor indices");
      // Filled by render(): the spheres may move from frame to frame.
      objectUniforms = gpu::createBuffer(ctx, sizeof(shader::SceneObjects), vk::BufferUsageFlagBits::eUniformBuffer,
                                         gpu::MemoryUse::Upload, "scene objects");
      poolDraw = PoolDraw{&poolUniforms, &objectUniforms, &floorIndices, uint32_t(floorGridIndices.size()), kPoolFloorGrid,
                          {}, &causticsImage, *clampSampler};
      if (scene.render.caustics) {
        causticsImage = gpu::createImage2D(ctx, {kCausticsSize, kCausticsSize}, kCausticsFormat,
                                           vk::ImageUsageFlagBits::eColorAttachment | vk::ImageUsageFlagBits::eSampled,
                                           "caustics");
        poolDraw->causticsRef = graph.image("caustics", causticsImage);
        causticsPass.emplace(ctx);
        causticsPass->declare(graph, *waterDraw, *poolDraw, uniforms);
      } else {
        // The floor lit as through flat water: one texel of 1, uploaded once.
        causticsImage = uploadSkyImage(ctx, SkyImage{1, 1, {glm::vec4(1.0f)}}, "no caustics");
        poolDraw->causticsRef = graph.image("caustics", causticsImage, vk::ImageLayout::eShaderReadOnlyOptimal);
      }
    }
    if (!skyFromImage) skyPass.declare(graph, skyRef, sky, skyParams(scene.sky));
    backgroundPass.declare(graph, colorRef, color, skyRef, sky, *sampler, uniforms);
    groundPass.declare(graph, colorRef, color, depthRef, depth, uniforms, ground);
    if (poolDraw) {
      poolPass.emplace(ctx);
      poolPass->declare(graph, colorRef, color, depthRef, depth, uniforms, *poolDraw, mediumDraw);
    }
    for (const auto& sphere : scene.spheres) spheres.push_back(sphereParams(sphere));
    for (const auto& box : scene.boxes) boxes.push_back(boxParams(box));
    if (!spheres.empty() || !boxes.empty()) {
      objectPass.emplace(ctx);
      objectPass->declare(graph, colorRef, color, depthRef, depth, uniforms, mediumDraw, &spheres, &boxes);
    }
    if (water) {
      std::optional<Underwater> underwater;
      if (scene.render.refraction == "apparent") {
        underwaterImage = gpu::createImage2D(ctx, {w, h}, kHdrFormat,
                                             vk::ImageUsageFlagBits::eSampled | vk::ImageUsageFlagBits::eTransferDst,
                                             "underwater image");
        underwater = Underwater{graph.image("underwater", underwaterImage), &underwaterImage, *nearestSampler};
        declareImageCopy(graph, "underwater", colorRef, color, underwater->ref, underwaterImage);
      }
      waterPass.emplace(ctx, underwater.has_value());
      waterPass->declare(graph, colorRef, color, depthRef, depth, *waterDraw, *poolDraw, skyRef, sky, *sampler, uniforms,
                         underwater);
    }
    if (options.aovs) {
      const vk::Extent2D extent{w, h};
      const auto usage = vk::ImageUsageFlagBits::eColorAttachment | vk::ImageUsageFlagBits::eTransferSrc;
      aovNormal = gpu::createImage2D(ctx, extent, kAovFormat, usage, "normal AOV target");
      aovPosition = gpu::createImage2D(ctx, extent, kAovFormat, usage, "position AOV target");
      aovDepth = gpu::createImage2D(ctx, extent, kDepthFormat, vk::ImageUsageFlagBits::eDepthStencilAttachment,
                                    "AOV depth target");
      normalReadback = gpu::createBuffer(ctx, vk::DeviceSize(w) * h * 16, vk::BufferUsageFlagBits::eTransferDst,
                                         gpu::MemoryUse::Readback, "normal AOV readback");
      positionReadback = gpu::createBuffer(ctx, vk::DeviceSize(w) * h * 16, vk::BufferUsageFlagBits::eTransferDst,
                                           gpu::MemoryUse::Readback, "position AOV readback");
      auto normalRef = graph.image("normal", aovNormal), positionRef = graph.image("position", aovPosition);
      normalReadbackRef = graph.buffer("normal readback", normalReadback);
      positionReadbackRef = graph.buffer("position readback", positionReadback);
      aovPass.emplace(ctx, poolDraw.has_value());
      aovPass->declare(graph, normalRef, aovNormal, positionRef, aovPosition, graph.image("aov depth", aovDepth),
                       aovDepth, uniforms, ground, poolDraw ? &*poolDraw : nullptr, waterDraw ? &*waterDraw : nullptr,
                       &spheres, &boxes);
      declareReadback(graph, "readback normal", normalRef, aovNormal, normalReadbackRef, normalReadback);
      declareReadback(graph, "readback position", positionRef, aovPosition, positionReadbackRef, positionReadback);
    }
    tonemapPass.declare(graph, colorRef, color, ldrRef, ldr, scene.render.exposure);
    declareReadback(graph, "readback hdr", colorRef, color, colorReadbackRef, colorReadback);
    declareReadback(graph, "readback ldr", ldrRef, ldr, ldrReadbackRef, ldrReadback);
  }

  SkyPass skyPass;
  BackgroundPass backgroundPass;
  GroundPass groundPass;
  TonemapPass tonemapPass;
  vk::raii::Sampler sampler, nearestSampler, clampSampler;
  gpu::Image sky, color, depth, ldr;
  gpu::Buffer uniforms, colorReadback, ldrReadback;
  gpu::DescriptorArena descriptors;
  SkyLight light;
  // The water, when the scene has it: the stepper, the grid's index buffer,
  // and the steps the next frame takes to reach its frame number.
  std::optional<sim::GpuStepper> water;
  std::optional<WaterSurfacePass> waterPass;
  gpu::Image underwaterImage;  // the apparent-depth mode's copy of the pool under the water
  // The pool, when there is water to hold.
  std::optional<PoolPass> poolPass;
  gpu::Buffer poolUniforms, objectUniforms, floorIndices;
  std::optional<CausticsPass> causticsPass;
  gpu::Image causticsImage;  // the caustics pass's target, or one texel of 1 without caustics
  std::optional<ObjectPass> objectPass;
  std::vector<shader::SphereParams> spheres;  // where the spheres are in the frame being recorded
  std::vector<shader::BoxParams> boxes;
  std::optional<CameraMediumPass> cameraMediumPass;
  gpu::Buffer medium;
  // Arbitrary output variables, when the renderer was made with them.
  std::optional<AovPass> aovPass;
  gpu::Image aovNormal, aovPosition, aovDepth;
  gpu::Buffer normalReadback, positionReadback;
  ResourceRef normalReadbackRef, positionReadbackRef;
  gpu::Buffer indices;
  uint32_t indexCount = 0;
  uint32_t substeps = 1;
  uint64_t stepsDone = 0;
  uint64_t pendingSteps = 0;
  FrameGraph graph;
  ResourceRef colorRef, colorReadbackRef, ldrReadbackRef;
};

Renderer::Renderer(const gpu::Context& ctx, const scene::Scene& scene, uint32_t width, uint32_t height,
                   const RendererOptions& options)
    : ctx_(ctx), scene_(scene), width_(width), height_(height),
      res_(std::make_unique<Resources>(ctx, scene, width, height, options)) {}

Renderer::~Renderer() = default;

RenderedFrame Renderer::render(const FrameRequest& request) {
  RenderedFrame out;
  out.width = width_;
  out.height = height_;
  const shader::FrameUniforms uniforms = frameUniforms(scene_, res_->light, width_, height_);
  std::memcpy(res_->uniforms.mapped, &uniforms, sizeof(uniforms));
  out.worldToCamera = uniforms.view;
  out.worldToNDC = uniforms.viewProjection;

  if (res_->water) {
    // Frame N shows the water after N frames of simulation from the scene's
    // start, whatever was rendered before: going back restarts it.
    const uint64_t target = uint64_t(request.frame) * res_->substeps;
    if (target < res_->stepsDone) {
      res_->water->reset(waterInitialState(scene_.water));
      res_->stepsDone = 0;
    }
    res_->pendingSteps = target - res_->stepsDone;
  }
  // Spheres with a path are where the path puts them at this frame's time.
  const float time = float(request.frame) * scene_.water.frameTime;
  const scene::Scene placed = scene::sceneAt(scene_, time);
  for (size_t i = 0; i < placed.spheres.size(); ++i) res_->spheres[i] = sphereParams(placed.spheres[i]);
  if (res_->objectUniforms.mapped) {
    const shader::SceneObjects objects = sceneObjects(placed);
    std::memcpy(res_->objectUniforms.mapped, &objects, sizeof(objects));
  }
  std::vector<ResourceRef> requested;
  if (request.hdr) requested.push_back(res_->colorReadbackRef);
  if (request.ldr) requested.push_back(res_->ldrReadbackRef);
  if (request.aovs) {
    if (!res_->aovPass) throw std::logic_error("AOVs requested from a renderer made without them");
    requested.push_back(res_->normalReadbackRef);
    requested.push_back(res_->positionReadbackRef);
  }

  gpu::GpuTimer timer(ctx_, 16);
  res_->descriptors.reset();  // the previous frame has finished: render() waits for it
  gpu::submitAndWait(ctx_, [&](const vk::raii::CommandBuffer& cmd) {
    timer.reset(cmd);
    PassContext context{cmd, res_->descriptors};
    res_->graph.record(context, requested, &timer);
  }, "frame rendering");
  for (const auto& scope : timer.read()) out.passes.push_back({scope.name, scope.milliseconds});
  res_->stepsDone += res_->pendingSteps;
  res_->pendingSteps = 0;

  const size_t pixels = size_t(width_) * height_;
  if (request.hdr) {
    out.rgba.resize(pixels * 4);
    std::memcpy(out.rgba.data(), res_->colorReadback.mapped, pixels * 16);
  }
  if (request.ldr) {
    out.srgb.resize(pixels * 4);
    std::memcpy(out.srgb.data(), res_->ldrReadback.mapped, pixels * 4);
  }
  if (request.aovs) {
    out.normal.resize(pixels * 4);
    out.position.resize(pixels * 4);
    std::memcpy(out.normal.data(), res_->normalReadback.mapped, pixels * 16);
    std::memcpy(out.position.data(), res_->positionReadback.mapped, pixels * 16);
  }
  return out;
}

}  // namespace tp::render
