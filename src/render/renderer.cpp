#include "render/renderer.hpp"

#include <algorithm>
#include <cstring>
#include <glm/gtc/packing.hpp>
#include <optional>

#include "gpu/submit.hpp"
#include "gpu/timer.hpp"
#include "render/frame_uniforms.hpp"
#include "render/frustum.hpp"
#include "render/glass_passes.hpp"
#include "render/glossy_model.hpp"
#include "render/glossy_prefilter.hpp"
#include "render/water_sleep.hpp"
#include "render/passes.hpp"
#include "render/sky_model.hpp"
#include "render/objects_model.hpp"
#include "render/pool_model.hpp"
#include "render/sky_image.hpp"
#include "render/ssao_model.hpp"
#include "render/ssao_passes.hpp"
#include "render/water_model.hpp"
#include "render/water_timeline.hpp"
#include "gpu/transfer.hpp"
#include "sim/gpu_stepper.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace tp::render {

struct Renderer::Resources {
  // `scene` is the renderer's own, which setCamera() and moveSphere() change
  // between frames: the passes that read those parts read it when recorded.
  Resources(const gpu::Context& ctx, const scene::Scene& scene, uint32_t w, uint32_t h, const RendererOptions& options)
      : live(scene),
        skipping(options.skipping),
        gbuffer(scene.ao.enabled || !options.skipping),
        skyPass(ctx),
        backgroundPass(ctx),
        groundPass(ctx, gbuffer),
        tonemapPass(ctx),
        // The equirectangular maps': around in u, clamped at the poles, and
        // through every mip level (the glossy environment's; the sky has one).
        sampler(ctx.device(), vk::SamplerCreateInfo{.magFilter = vk::Filter::eLinear,
                                                    .minFilter = vk::Filter::eLinear,
                                                    .mipmapMode = vk::SamplerMipmapMode::eLinear,
                                                    .addressModeU = vk::SamplerAddressMode::eRepeat,
                                                    .addressModeV = vk::SamplerAddressMode::eClampToEdge,
                                                    .addressModeW = vk::SamplerAddressMode::eClampToEdge,
                                                    .maxLod = VK_LOD_CLAMP_NONE}),
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
        // With AO, SSAO samples the depth target and a frame may read it back.
        depth(gpu::createImage2D(ctx, {w, h}, kDepthFormat,
                                 scene.ao.enabled ? vk::ImageUsageFlagBits::eDepthStencilAttachment |
                                                        vk::ImageUsageFlagBits::eSampled |
                                                        vk::ImageUsageFlagBits::eTransferSrc
                                                  : vk::ImageUsageFlagBits::eDepthStencilAttachment,
                                 "depth target")),
        ldr(gpu::createImage2D(ctx, {w, h}, kLdrFormat,
                               vk::ImageUsageFlagBits::eStorage | vk::ImageUsageFlagBits::eTransferSrc, "LDR preview")),
        uniforms(gpu::createBuffer(ctx, sizeof(shader::FrameUniforms), vk::BufferUsageFlagBits::eUniformBuffer,
                                   gpu::MemoryUse::Upload, "frame uniforms")),
        colorReadback(gpu::createBuffer(ctx, vk::DeviceSize(w) * h * 16, vk::BufferUsageFlagBits::eTransferDst,
                                        gpu::MemoryUse::Readback, "HDR readback")),
        ldrReadback(gpu::createBuffer(ctx, vk::DeviceSize(w) * h * 4, vk::BufferUsageFlagBits::eTransferDst,
                                      gpu::MemoryUse::Readback, "LDR readback")),
        descriptors(ctx),
        sleep(sleepRule(scene.water)) {
    graph.setCaching(skipping);
    uniformsRef = graph.buffer("frame uniforms", uniforms);
    if (scene.water.enabled) {
      sim::checkGridFits(ctx, scene.water.grid);  // before the initial state is made on the CPU
      // Steps only the tiles within reach of motion (sim/water_tiles.hpp), the
      // same bits as the whole grid; with skipping off, every tile.
      water.emplace(ctx, render::waterParams(scene.water), waterInitialState(scene.water), sim::StepKernel::ActiveTiles);
      if (!skipping) water->setTileDispatch(sim::TileDispatch::Full);
      const auto gridIndices = waterGridStrips(scene.water.grid);
      indexCount = uint32_t(gridIndices.size());
      indices = gpu::createFilledBuffer(ctx, gridIndices, vk::BufferUsageFlagBits::eIndexBuffer, gpu::MemoryUse::Device,
                                        "water grid indices");
      clock.substeps = render::waterSubsteps(scene.water);
      restartWater(scene, water->stats(waterStep(scene.water)));
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
    // The glossy surfaces' environment, prefiltered from the sky by a cached
    // pass (on the first frame, and again only if the sky changes); without
    // glossy surfaces no pass, and one black texel for the shaders to bind.
    if (hasGlossySurface(scene)) {
      glossyPrefilter.emplace(ctx, sky.extent.width, sky.extent.height);
      glossy = {graph.image("glossy environment", glossyPrefilter->map()), &glossyPrefilter->map(), *sampler};
    } else {
      noGlossy = uploadSkyImage(ctx, SkyImage{1, 1, {glm::vec4(0.0f)}}, "no glossy environment");
      glossy = {graph.image("glossy environment", noGlossy, vk::ImageLayout::eShaderReadOnlyOptimal), &noGlossy,
                *sampler};
    }
    colorRef = graph.image("color", color);
    auto depthRef = graph.image("depth", depth);
    SurfaceTargets surfaces{{colorRef, &color}, {depthRef, &depth}, {}, {}};
    if (gbuffer) declareGbuffer(ctx, w, h, surfaces);
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
      waterStateRefs = waterDraw->stateRefs;
      // The live drops and moves, the steps to this frame with the scene's
      // drops due on the way, and the stats that say whether the water is
      // healthy and whether it may sleep; left out while it sleeps.
      graph.pass("simulate",
                 {{waterDraw->stateRefs[0], Use::ComputeReadWrite}, {waterDraw->stateRefs[1], Use::ComputeReadWrite}},
                 [this](PassContext& pc) {
                   for (const scene::Drop& d : pendingDrops) recordSceneDrop(pc.cmd, *water, live.water, d);
                   for (const SphereMove& m : pendingMoves) {
                     water->recordSphereMove(pc.cmd, worldToGrid(live.water, m.from), worldToGrid(live.water, m.to),
                                             m.radius, live.water.level);
                   }
                   recordWaterRun(pc.cmd, *water, live, clock, stepsDone, stepsDone + pendingSteps, dropsDue);
                   water->recordStats(pc.cmd, waterStep(live.water));
                 },
                 {.cached = false, .runIf = [this] { return simulating; }});
    }
    // The medium around the camera: air (zeros, uploaded first) while the
    // camera is away from the water's square, where it cannot be under the
    // surface; decided after the simulation while it is over it, and once
    // more when it leaves (setCamera), to write air again.
    const shader::CameraMedium air{glm::vec4(0.0f)};
    medium = gpu::createFilledBuffer(ctx, &air, sizeof(air),
                                     vk::BufferUsageFlagBits::eStorageBuffer | vk::BufferUsageFlagBits::eUniformBuffer,
                                     gpu::MemoryUse::Device, "camera medium");
    const MediumDraw mediumDraw{graph.buffer("camera medium", medium), &medium};
    if (water) {
      cameraMediumPass.emplace(ctx);
      cameraMediumPass->declare(graph, *waterDraw, uniforms, uniformsRef, mediumDraw,
                                [this] { return !skipping || cameraOverWater(live) || mediumMayNotBeAir; });
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
                          {}, &causticsImage, *clampSampler, glossy};
      if (scene.render.caustics) {
        causticsImage = gpu::createImage2D(ctx, {kCausticsSize, kCausticsSize}, kCausticsFormat,
                                           vk::ImageUsageFlagBits::eColorAttachment | vk::ImageUsageFlagBits::eSampled,
                                           "caustics");
        poolDraw->causticsRef = graph.image("caustics", causticsImage);
        causticsPass.emplace(ctx);
        causticsPass->declare(graph, *waterDraw, *poolDraw, uniforms, uniformsRef);
      } else {
        // The floor lit as through flat water: one texel of 1, uploaded once.
        causticsImage = uploadSkyImage(ctx, SkyImage{1, 1, {glm::vec4(1.0f)}}, "no caustics");
        poolDraw->causticsRef = graph.image("caustics", causticsImage, vk::ImageLayout::eShaderReadOnlyOptimal);
      }
    }
    if (!skyFromImage) skyPass.declare(graph, skyRef, sky, skyParams(scene.sky));
    if (glossyPrefilter) glossyPrefilter->declare(graph, skyRef, sky, *sampler, glossy.ref);
    backgroundPass.declare(graph, colorRef, color, skyRef, sky, *sampler, uniforms);
    groundPass.declare(graph, surfaces, uniforms, ground);
    if (poolDraw) {
      poolPass.emplace(ctx, gbuffer);
      poolPass->declare(graph, surfaces, uniforms, *poolDraw, mediumDraw);
    }
    // `spheres` and `boxes`: those in view, filled by render().
    if (!scene.spheres.empty() || !scene.boxes.empty()) {
      objectPass.emplace(ctx, gbuffer);
      objectPass->declare(graph, surfaces, uniforms, mediumDraw, glossy, &spheres, &boxes);
    }
    // AO of the opaque surfaces, before the water: the apparent-depth mode's
    // copy of the pool then has it too.
    if (scene.ao.enabled) declareAo(ctx, scene.ao, surfaces);
    std::optional<Underwater> underwater;
    if (water && scene.render.refraction == "apparent") {
      underwaterImage = gpu::createImage2D(ctx, {w, h}, kHdrFormat,
                                           vk::ImageUsageFlagBits::eSampled | vk::ImageUsageFlagBits::eTransferDst,
                                           "underwater image");
      underwater = Underwater{graph.image("underwater", underwaterImage), &underwaterImage, *nearestSampler};
      declareImageCopy(graph, "underwater", colorRef, color, underwater->ref, underwaterImage);
    }
    // Glass after AO (it neither occludes nor is occluded) and after the
    // apparent-depth mode's copy (the water's rays do not meet glass), before
    // the water, which draws over what of it is under the surface.
    if (std::any_of(scene.spheres.begin(), scene.spheres.end(), scene::isGlass)) {
      declareGlass(ctx, w, h, surfaces, mediumDraw, skyRef);
    }
    if (water) {
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
                       &aovSpheres, &boxes);
      declareReadback(graph, "readback normal", normalRef, aovNormal, normalReadbackRef, normalReadback);
      declareReadback(graph, "readback position", positionRef, aovPosition, positionReadbackRef, positionReadback);
    }
    tonemapPass.declare(graph, colorRef, color, ldrRef, ldr, scene.render.exposure);
    declareReadback(graph, "readback hdr", colorRef, color, colorReadbackRef, colorReadback);
    declareReadback(graph, "readback ldr", ldrRef, ldr, ldrReadbackRef, ldrReadback);
  }

  // The water's statistics after a start: whether it is at rest, and how high it reaches.
  void restartWater(const scene::Scene& scene, const sim::WaterStats& stats) {
    sleep.restart(stats);
    waterTop = highestWater(scene, stats);
  }

  // The stats' energy per unit area of the water: WaterSleep's measure.
  static double energyPerArea(const scene::Scene& scene, const sim::WaterStats& stats) {
    return stats.energy / (double(scene.water.extent) * scene.water.extent);
  }

  // The highest the water's surface can be to reach the objects: the rim,
  // unless the last stats saw a wave over it.
  static float highestWater(const scene::Scene& scene, const sim::WaterStats& stats) {
    return std::max(scene.ground.height, scene.water.level + float(stats.maxAbsU));
  }

  // The G-buffer targets beside colour and depth, with their readbacks.
  void declareGbuffer(const gpu::Context& ctx, uint32_t w, uint32_t h, SurfaceTargets& surfaces) {
    const auto usage = vk::ImageUsageFlagBits::eColorAttachment | vk::ImageUsageFlagBits::eStorage;
    gbufferNormal = gpu::createImage2D(ctx, {w, h}, kGbufferFormat, usage | vk::ImageUsageFlagBits::eTransferSrc,
                                       "G-buffer view normal");
    gbufferAmbient = gpu::createImage2D(ctx, {w, h}, kGbufferFormat, usage, "G-buffer ambient radiance");
    surfaces.normal = {graph.image("view normal", gbufferNormal), &gbufferNormal};
    surfaces.ambient = {graph.image("ambient", gbufferAmbient), &gbufferAmbient};
  }

  // The glass spheres' passes and the back faces' targets (glass_passes.hpp).
  void declareGlass(const gpu::Context& ctx, uint32_t w, uint32_t h, const SurfaceTargets& surfaces,
                    const MediumDraw& mediumDraw, ResourceRef skyRef) {
    glassBackFaces = gpu::createImage2D(ctx, {w, h}, kGlassBackFormat,
                                        vk::ImageUsageFlagBits::eColorAttachment | vk::ImageUsageFlagBits::eSampled,
                                        "glass back faces");
    glassDepth = gpu::createImage2D(ctx, {w, h}, kDepthFormat, vk::ImageUsageFlagBits::eDepthStencilAttachment,
                                    "glass back-face depth");
    const GlassTargets targets{{graph.image("glass back faces", glassBackFaces), &glassBackFaces},
                               {graph.image("glass depth", glassDepth), &glassDepth}};
    glassPasses.emplace(ctx);
    glassPasses->declare(graph, targets, surfaces, mediumDraw, skyRef, sky, *sampler, *nearestSampler, uniforms,
                         &glassSpheres);
  }

  // The SSAO passes and their images, and the readbacks a frame asking for
  // its AO uses (declared here, so the depth read back is the opaque
  // surfaces', before the water draws over it).
  void declareAo(const gpu::Context& ctx, const scene::Ao& ao, const SurfaceTargets& surfaces) {
    const vk::Extent2D frame = surfaces.color.image->extent, low = aoExtent(ao, frame.width, frame.height);
    const auto usage = vk::ImageUsageFlagBits::eStorage | vk::ImageUsageFlagBits::eTransferSrc;
    auto makeImage = [&](gpu::Image& image, vk::Extent2D extent, const char* name) -> Target {
      image = gpu::createImage2D(ctx, extent, kAoFormat, usage, name);
      return {graph.image(name, image), &image};
    };
    AoImages images;
    images.raw = makeImage(aoRaw, low, "AO raw");
    if (ao.blur != "off") {
      images.blurX = makeImage(aoBlurX, low, "AO blurred in x");
      images.blurred = makeImage(aoBlurred, low, "AO blurred");
    }
    if (low != frame) images.full = makeImage(aoFull, frame, "AO upsampled");
    const shader::SsaoKernel kernel = ssaoKernel(ao);
    ssaoKernelBuffer = gpu::createFilledBuffer(ctx, &kernel, sizeof(kernel), vk::BufferUsageFlagBits::eUniformBuffer,
                                               gpu::MemoryUse::Upload, "SSAO kernel");
    ssaoPasses.emplace(ctx);
    ssaoPasses->declare(graph, surfaces, images, uniforms, ssaoKernelBuffer, *nearestSampler, ao);

    aoExtentLow = low;
    const auto readbackUsage = vk::BufferUsageFlagBits::eTransferDst;
    const vk::DeviceSize pixels = vk::DeviceSize(frame.width) * frame.height;
    aoReadback = gpu::createBuffer(ctx, pixels * 4, readbackUsage, gpu::MemoryUse::Readback, "AO readback");
    aoRawReadback = gpu::createBuffer(ctx, vk::DeviceSize(low.width) * low.height * 4, readbackUsage,
                                      gpu::MemoryUse::Readback, "raw AO readback");
    depthReadback = gpu::createBuffer(ctx, pixels * 4, readbackUsage, gpu::MemoryUse::Readback, "G-buffer depth readback");
    viewNormalReadback = gpu::createBuffer(ctx, pixels * 8, readbackUsage, gpu::MemoryUse::Readback,
                                           "G-buffer normal readback");
    aoReadbackRefs = {graph.buffer("AO readback", aoReadback), graph.buffer("raw AO readback", aoRawReadback),
                      graph.buffer("G-buffer depth readback", depthReadback),
                      graph.buffer("G-buffer normal readback", viewNormalReadback)};
    const Target result = images.result();
    declareReadback(graph, "readback ao", result.ref, *result.image, aoReadbackRefs[0], aoReadback);
    declareReadback(graph, "readback ao raw", images.raw.ref, aoRaw, aoReadbackRefs[1], aoRawReadback);
    declareReadback(graph, "readback depth", surfaces.depth.ref, depth, aoReadbackRefs[2], depthReadback);
    declareReadback(graph, "readback view normal", surfaces.normal.ref, gbufferNormal, aoReadbackRefs[3],
                    viewNormalReadback);
  }

  const scene::Scene& live;  // the renderer's scene (see the constructor)
  bool skipping;  // RendererOptions::skipping
  bool gbuffer;   // the surfaces draw the G-buffer: AO reads it (or nothing is skipped)
  SkyPass skyPass;
  BackgroundPass backgroundPass;
  GroundPass groundPass;
  TonemapPass tonemapPass;
  vk::raii::Sampler sampler, nearestSampler, clampSampler;
  gpu::Image sky, color, depth, ldr;
  gpu::Buffer uniforms, colorReadback, ldrReadback;
  gpu::DescriptorArena descriptors;
  SkyLight light;
  std::optional<GlossyPrefilter> glossyPrefilter;  // when the scene has a glossy surface
  gpu::Image noGlossy;                             // else one black texel
  GlossyDraw glossy;
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
  std::vector<shader::SphereParams> aovSpheres;  // every sphere in view, glass too, for the AOV pass
  // Glass spheres, when the scene has them: those in view, filled by render().
  std::optional<GlassPasses> glassPasses;
  gpu::Image glassBackFaces, glassDepth;
  std::vector<shader::GlassSphereParams> glassSpheres;
  std::optional<CameraMediumPass> cameraMediumPass;
  gpu::Buffer medium;
  // Ambient occlusion, when the scene has it on.
  gpu::Image gbufferNormal, gbufferAmbient, aoRaw, aoBlurX, aoBlurred, aoFull;
  gpu::Buffer ssaoKernelBuffer, aoReadback, aoRawReadback, depthReadback, viewNormalReadback;
  std::vector<ResourceRef> aoReadbackRefs;  // AO, raw AO, depth, view normal
  vk::Extent2D aoExtentLow;
  std::optional<SsaoPasses> ssaoPasses;
  // Arbitrary output variables, when the renderer was made with them.
  std::optional<AovPass> aovPass;
  gpu::Image aovNormal, aovPosition, aovDepth;
  gpu::Buffer normalReadback, positionReadback;
  ResourceRef normalReadbackRef, positionReadbackRef;
  gpu::Buffer indices;
  uint32_t indexCount = 0;
  uint64_t stepsDone = 0;
  WaterClock clock;  // setWaterDynamics re-bases it, a restart starts it again
  // Scene time after `steps` steps, for the paths of the spheres.
  double waterTime(uint64_t steps) const { return clock.timeAt(steps, live.water); }
  uint64_t pendingSteps = 0;
  std::vector<ResourceRef> waterStateRefs;
  std::vector<scene::Drop> pendingDrops;  // addDrop()'s, for the next frame
  // Per drop of the scene: applied in this run of the water (addDrop's at
  // once; the schedule's when the simulation that applies them was recorded).
  std::vector<bool> dropsApplied;
  std::vector<size_t> dropsDue;  // the scheduled drops within this frame's steps (dueDrops())
  struct SphereMove {
    glm::vec3 from, to;
    float radius;
  };
  std::vector<SphereMove> pendingMoves;   // moveSphere()'s, for the next frame
  bool mediumMayNotBeAir = false;         // the camera medium pass last ran with the camera over the water
  bool simulating = false;                 // this frame records the simulation
  WaterSleep sleep;
  double waterEnergy = 0.0;
  float waterTop = std::numeric_limits<float>::infinity();  // highestWater() after the last stats
  FrameGraph graph;
  ResourceRef colorRef, colorReadbackRef, ldrReadbackRef, uniformsRef;
};

Renderer::Renderer(const gpu::Context& ctx, const scene::Scene& scene, uint32_t width, uint32_t height,
                   const RendererOptions& options)
    : ctx_(ctx), scene_(scene), width_(width), height_(height), options_(options),
      res_(std::make_unique<Resources>(ctx, scene_, width, height, options)) {}

namespace {

// Whether a sphere's path moves it at some time in (t0, t1].
bool bodyMoves(const scene::Scene& scene, double t0, double t1) {
  for (const auto& sphere : scene.spheres) {
    if (sphere.path.size() >= 2 && t1 > sphere.path.front().time && t0 < sphere.path.back().time) return true;
  }
  return false;
}

// `scene`, when its water is `previous`'s but for what only shades it.
const scene::Scene& sameWater(const scene::Scene& previous, const scene::Scene& scene) {
  if (!sameWaterMotion(scene.water, previous.water)) {
    throw std::invalid_argument(
        "a renderer that goes on with the water needs the same water but for ior and absorption: "
        "other water settings need a new renderer (the water restarts)");
  }
  return scene;
}

}  // namespace

Renderer::Renderer(const Renderer& previous) : Renderer(previous, previous.scene_) {}

Renderer::Renderer(const Renderer& previous, const scene::Scene& scene)
    : Renderer(previous.ctx_, sameWater(previous.scene_, scene), previous.width_, previous.height_, previous.options_) {
  const Resources& from = *previous.res_;
  if (!res_->water) return;
  // A new start from the previous water: every tile counts as changed once.
  res_->water->reset(previous.waterState());
  res_->stepsDone = from.stepsDone;
  res_->clock = from.clock;
  res_->dropsApplied = from.dropsApplied;
  res_->pendingDrops = from.pendingDrops;
  res_->pendingMoves = from.pendingMoves;
  res_->sleep = from.sleep;
  res_->waterEnergy = from.waterEnergy;
  res_->waterTop = from.waterTop;
}

Renderer::~Renderer() = default;

void Renderer::addDrop(const scene::Drop& drop) {
  if (!res_->water) throw std::runtime_error("a drop needs a scene with water");
  scene::validateDrop(drop);
  scene::Drop recorded = drop;
  recorded.frame = res_->clock.frameAt(res_->stepsDone) + 1;
  // Listed before the scene's drops of the same frame still to come: the
  // schedule applies those after this one, and a run of the scene applies
  // drops of one frame in the order listed.
  std::vector<scene::Drop>& drops = scene_.water.drops;
  std::vector<bool>& applied = res_->dropsApplied;
  applied.resize(drops.size(), false);
  size_t at = 0;
  while (at < drops.size() && (drops[at].frame != recorded.frame || applied[at])) ++at;
  drops.insert(drops.begin() + std::ptrdiff_t(at), recorded);
  applied.insert(applied.begin() + std::ptrdiff_t(at), true);  // by the next simulation, before its steps
  res_->pendingDrops.push_back(recorded);
}

void Renderer::setCamera(const scene::Camera& camera) {
  scene::validateCamera(camera);
  scene_.camera = camera;
}

void Renderer::moveSphere(size_t index, glm::vec3 center) {
  if (index >= scene_.spheres.size()) {
    throw std::out_of_range("sphere " + std::to_string(index) + " of a scene with " +
                            std::to_string(scene_.spheres.size()));
  }
  if (!std::isfinite(center.x) || !std::isfinite(center.y) || !std::isfinite(center.z)) {
    throw std::runtime_error("a sphere's centre must be finite");
  }
  scene::Sphere& sphere = scene_.spheres[index];
  // Where it is now: on its path, at the time the water has reached.
  const float now = res_->water ? float(res_->waterTime(res_->stepsDone)) : 0.0f;
  const glm::vec3 from = scene::sphereCenterAt(sphere, now);
  sphere.path.clear();
  sphere.center = center;
  if (res_->water && from != center) res_->pendingMoves.push_back({from, center, sphere.radius});
}

void Renderer::setWaterDynamics(const scene::Water& water) {
  if (!res_->water) throw std::runtime_error("the scene has no water");
  if (withDynamicsOf(water, scene_.water) != scene_.water) {
    throw std::invalid_argument("only the wave speed, damping, boundary and max slope change on a live renderer");
  }
  // Everything that can refuse the change, before any of it is made.
  const sim::WaterParams params = waterParams(water);
  sim::validate(params);
  const uint32_t substeps = waterSubsteps(water);
  // Re-base the clock at the frame the water has reached (a whole number of
  // the old frames since the last base: render() steps whole frames).
  res_->clock = WaterClock{res_->clock.frameAt(res_->stepsDone), res_->stepsDone, substeps};
  scene_.water = water;
  res_->water->setParams(params);
  res_->sleep = WaterSleep(sleepRule(water));  // its threshold follows the wave speed
  res_->sleep.wake();
}

sim::WaterState Renderer::waterState() const {
  if (!res_->water) throw std::runtime_error("the scene has no water");
  return res_->water->download();
}

WaterCheckpoint Renderer::checkpoint() const {
  if (!res_->water) throw std::runtime_error("the scene has no water");
  if (res_->clock.frameBase != 0 || res_->clock.stepBase != 0) {
    throw std::runtime_error("a water whose dynamics changed on the way cannot be checkpointed");
  }
  return WaterCheckpoint{res_->clock.frameAt(res_->stepsDone), waterState(), res_->sleep.quietFrames(),
                         res_->sleep.asleep()};
}

void Renderer::resume(const WaterCheckpoint& checkpoint) {
  if (!res_->water) throw std::runtime_error("the scene has no water");
  if (checkpoint.state.n != scene_.water.grid) {
    throw std::runtime_error("a checkpoint of a " + std::to_string(checkpoint.state.n) + "x" +
                             std::to_string(checkpoint.state.n) + " water for a scene whose water.grid is " +
                             std::to_string(scene_.water.grid));
  }
  res_->water->reset(checkpoint.state);
  for (ResourceRef state : res_->waterStateRefs) res_->graph.touch(state);  // uploaded outside the graph
  res_->clock = WaterClock{.substeps = res_->clock.substeps};
  res_->stepsDone = res_->clock.stepsAt(checkpoint.frame);
  res_->pendingSteps = 0;
  res_->pendingDrops.clear();
  res_->pendingMoves.clear();
  const auto& drops = scene_.water.drops;
  res_->dropsApplied.resize(drops.size());
  for (size_t i = 0; i < drops.size(); ++i) res_->dropsApplied[i] = drops[i].frame <= checkpoint.frame;
  const sim::WaterStats stats = res_->water->stats(waterStep(scene_.water));
  res_->restartWater(scene_, stats);
  res_->sleep.resume(checkpoint.quietFrames, checkpoint.asleep);
  res_->waterEnergy = Resources::energyPerArea(scene_, stats);
}

RenderedFrame Renderer::render(const FrameRequest& request) {
  RenderedFrame out;
  out.width = width_;
  out.height = height_;
  const shader::FrameUniforms uniforms = frameUniforms(scene_, res_->light, width_, height_);
  if (std::memcmp(res_->uniforms.mapped, &uniforms, sizeof(uniforms)) != 0) {
    std::memcpy(res_->uniforms.mapped, &uniforms, sizeof(uniforms));
    res_->graph.touch(res_->uniformsRef);
  }
  out.worldToCamera = uniforms.view;
  out.worldToNDC = uniforms.viewProjection;
  out.inverseProjection = uniforms.inverseProjection;

  res_->simulating = false;
  if (res_->water) {
    // Frame N shows the water after N frames of simulation from the scene's
    // start, whatever was rendered before: going back restarts it. Sleeping
    // water skips ahead without a step. The scene's later drops come on their
    // frames (water_timeline.hpp).
    const double dt = waterStep(scene_.water);
    WaterClock& clock = res_->clock;
    if (request.frame < clock.frameBase || clock.stepsAt(request.frame) < res_->stepsDone) {
      // From the start, with the water's parameters as they now are; every
      // drop made live is in the scene, and comes again on its frame.
      res_->water->reset(waterInitialState(scene_.water));
      for (ResourceRef state : res_->waterStateRefs) res_->graph.touch(state);  // uploaded outside the graph
      res_->stepsDone = 0;
      clock = WaterClock{.substeps = clock.substeps};  // from frame 0 at step 0
      res_->dropsApplied.assign(scene_.water.drops.size(), false);
      res_->pendingDrops.clear();
      res_->restartWater(scene_, res_->water->stats(dt));
    }
    const uint64_t target = clock.stepsAt(request.frame);
    res_->dropsDue = dueDrops(scene_.water, clock, res_->stepsDone, target, res_->dropsApplied);
    const bool disturbed = !res_->pendingDrops.empty() || !res_->pendingMoves.empty() || !res_->dropsDue.empty();
    if (disturbed || bodyMoves(scene_, res_->waterTime(res_->stepsDone), res_->waterTime(target))) {
      res_->sleep.wake();
    }
    if (res_->skipping && res_->sleep.asleep()) {
      res_->stepsDone = target;
      res_->pendingSteps = 0;
    } else {
      res_->pendingSteps = target - res_->stepsDone;
      res_->simulating = res_->pendingSteps > 0 || disturbed;
    }
  }
  // Spheres with a path are where the path puts them at this frame's time;
  // only those in view are drawn (all of them stay in the objects the water's
  // rays meet: a reflection shows what the frame does not).
  const float time = float(request.frame) * scene_.water.frameTime;
  const scene::Scene placed = scene::sceneAt(scene_, time);
  const Frustum frustum(uniforms.viewProjection);
  res_->spheres.clear();
  res_->glassSpheres.clear();
  res_->aovSpheres.clear();
  for (const auto& sphere : placed.spheres) {
    if (res_->skipping && !frustum.mayShow(sphere.center, sphere.radius)) continue;
    if (scene::isGlass(sphere)) {
      res_->glassSpheres.push_back(glassSphereParams(sphere, scene_.render.glassSearchSteps));
    } else {
      res_->spheres.push_back(sphereParams(sphere));
    }
    res_->aovSpheres.push_back(sphereParams(sphere));
  }
  res_->boxes.clear();
  for (const auto& box : placed.boxes) {
    if (!res_->skipping || frustum.mayShow(box.center, 0.5f * glm::length(box.size))) res_->boxes.push_back(boxParams(box));
  }
  if (res_->objectUniforms.mapped) {
    // Objects wholly over the water are left out of the casts under it.
    const shader::SceneObjects objects =
        sceneObjects(placed, res_->skipping ? res_->waterTop : std::numeric_limits<float>::infinity());
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
  if (request.ao) {
    if (!res_->ssaoPasses) throw std::logic_error("AO requested from a renderer of a scene without it");
    requested.insert(requested.end(), res_->aoReadbackRefs.begin(), res_->aoReadbackRefs.end());
  }

  gpu::GpuTimer timer(ctx_, uint32_t(res_->graph.passCount()));  // a scope per pass at most
  res_->descriptors.reset();  // the previous frame has finished: render() waits for it
  gpu::submitAndWait(ctx_, [&](const vk::raii::CommandBuffer& cmd) {
    timer.reset(cmd);
    PassContext context{cmd, res_->descriptors};
    gpu::CountScope counting(out.counts);
    out.passes = res_->graph.record(context, requested, &timer);
  }, "frame rendering");
  const auto times = timer.read();
  for (size_t p = 0; p < out.passes.size(); ++p) out.passes[p].milliseconds = times.at(p).milliseconds;
  RecordedPass* simulate = findPass(out.passes, "simulate");
  const bool simulated = simulate != nullptr;
  if (simulated) {
    // The tiles the steps' indirect dispatches launched, known only now.
    const uint64_t listedTiles = res_->water->readTilesDispatched().listed;
    out.counts.workgroups += listedTiles;
    simulate->counts.workgroups += listedTiles;
    res_->stepsDone += res_->pendingSteps;
    res_->pendingSteps = 0;
    res_->pendingDrops.clear();
    res_->pendingMoves.clear();
    res_->dropsApplied.resize(scene_.water.drops.size(), false);
    for (const size_t i : res_->dropsDue) res_->dropsApplied[i] = true;
    const sim::WaterStats stats = res_->water->readStats();
    sim::checkHealth(stats, res_->stepsDone, std::numeric_limits<double>::infinity());
    res_->waterEnergy = Resources::energyPerArea(scene_, stats);
    res_->sleep.observe(res_->waterEnergy);
    res_->waterTop = Resources::highestWater(scene_, stats);
  }
  if (findPass(out.passes, "camera medium")) {
    res_->mediumMayNotBeAir = cameraOverWater(scene_);
  }
  out.waterAsleep = res_->water && !simulated;
  out.waterEnergy = res_->waterEnergy;

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
  if (request.ao) {
    const vk::Extent2D low = res_->aoExtentLow;
    out.aoWidth = low.width;
    out.aoHeight = low.height;
    auto copyFloats = [](std::vector<float>& to, const gpu::Buffer& from, size_t count) {
      to.resize(count);
      std::memcpy(to.data(), from.mapped, count * sizeof(float));
    };
    copyFloats(out.ao, res_->aoReadback, pixels);
    copyFloats(out.aoRaw, res_->aoRawReadback, size_t(low.width) * low.height);
    copyFloats(out.gbufferDepth, res_->depthReadback, pixels);
    out.gbufferNormal.resize(pixels * 4);
    const auto* halves = static_cast<const glm::uint64*>(res_->viewNormalReadback.mapped);
    for (size_t p = 0; p < pixels; ++p) {
      const glm::vec4 n = glm::unpackHalf4x16(halves[p]);
      for (int c = 0; c < 4; ++c) out.gbufferNormal[p * 4 + c] = n[c];
    }
  }
  return out;
}

}  // namespace tp::render
