#include "render/renderer.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <limits>
#include <optional>
#include <stdexcept>

#include "gpu/submit.hpp"
#include "gpu/timer.hpp"
#include "graph/readback.hpp"
#include "render/ambient_occlusion.hpp"
#include "render/aovs.hpp"
#include "render/camera_medium.hpp"
#include "render/frame_resolve.hpp"
#include "render/frame_targets.hpp"
#include "render/glass.hpp"
#include "render/glossy_environment.hpp"
#include "render/glossy_probes.hpp"
#include "render/ground.hpp"
#include "render/morphological_aa.hpp"
#include "render/objects.hpp"
#include "render/opaque_geometry.hpp"
#include "render/pass_kinds.hpp"
#include "render/pool.hpp"
#include "render/sky.hpp"
#include "render/water_surface.hpp"
#include "shading/frame_uniforms.hpp"
#include "shading/frustum.hpp"
#include "shading/glass_caustic.hpp"
#include "shading/grid_detail.hpp"
#include "shading/objects_model.hpp"
#include "shading/pool_model.hpp"
#include "shading/screen_rect.hpp"
#include "shading/shadow_reach.hpp"
#include "shading/water_model.hpp"
#include "sim/water_driver.hpp"

namespace tp::render {
namespace {

// Whether the resolve pass takes the AO, after the water, rather than a pass
// of its own before it: one pass less over the frame. Only with the water
// shaded deferred (or none), which then clears the ambient part where it is
// seen; not in the apparent-depth mode, whose copy of the pool has the AO,
// nor with glass, drawn forward after the AO; and not with nothing skipped,
// whose frame, AO applied before the water, the tests compare with.
bool aoAfterWater(const scene::Scene& scene, bool skipping) {
  return scene.ao.enabled && skipping && !apparentRefraction(scene) && !scene::hasGlass(scene);
}

}  // namespace

// The renderer's features, each with its images and pipelines, in the order
// their passes record. `live` is the renderer's own scene, which setCamera()
// and moveSphere() change between frames: the passes that read those parts
// read it when recorded.
struct Renderer::Resources {
  Resources(const gpu::Context& ctx, const scene::Scene& scene, vk::Extent2D frame, const RendererOptions& options)
      : live(scene),
        skipping(options.skipping),
        coarseGrids(options.coarseGrids),
        descriptors(ctx),
        samplers(ctx),
        uniforms(gpu::createBuffer(ctx, sizeof(shader::FrameUniforms), vk::BufferUsageFlagBits::eUniformBuffer,
                                   gpu::MemoryUse::Upload, "frame uniforms")),
        uniformsRef(graph.buffer("frame uniforms", uniforms)),
        glassTables(gpu::createBuffer(ctx, sizeof(shader::GlassTables), vk::BufferUsageFlagBits::eStorageBuffer,
                                      gpu::MemoryUse::Upload, "glass sun tables")),
        glassTablesRef(graph.buffer("glass sun tables", glassTables)),
        // Filled before each frame: the spheres may move.
        objectUniforms(gpu::createBuffer(ctx, sizeof(shader::SceneObjects), vk::BufferUsageFlagBits::eUniformBuffer,
                                         gpu::MemoryUse::Upload, "scene objects")),
        // The G-buffer: AO reads it (or nothing is skipped).
        targets(ctx, graph, frame, scene.ao.enabled || !options.skipping,
                scene.ao.enabled || scene.render.antialiasing == "morphological" || scene.sky.hazeDistance > 0.0f),
        needs(surfaceNeeds(scene, targets.surfaces().gbuffer(), options.skipping)),
        sky(ctx, graph, scene, targets.surfaces().gbuffer()),
        glossy(ctx, graph, scene, *sky.image().image),
        glossyProbes(ctx, graph, scene),
        medium(ctx, graph, scene.water.enabled),
        ground(ctx, graph, scene, needs, frame, targets.surfaces().gbuffer()) {
    graph.setCaching(skipping);
    const FrameInputs in{uniformsRef,     glassTablesRef,     sky.image(),       glossy.image(),
                         medium.buffer(), *samplers.equirect, *samplers.nearest, *samplers.clamp};
    const SurfaceTargets& surfaces = targets.surfaces();
    if (scene.water.enabled) declareWater(ctx, scene, frame, in);
    stillInPart = stillFramesInPart(scene);
    sky.declareSky(graph);
    glossy.declare(graph, sky.image(), *samplers.equirect);
    ground.declare(
        graph, surfaces, in,
        [this] {
          const auto& u = *static_cast<const shader::FrameUniforms*>(uniforms.mapped);
          return skipping && groundOutOfObjectShadows(u.shadows, glm::vec3(u.sunDirection), ground.params().plane.y,
                                                      ground.params().plane.w);
        },
        [this, in](PassBuilder& pass) { return sky.background(pass, in); },
        stillInPart ? std::function<std::optional<PixelRect>()>([this] { return groundCopy; }) : nullptr);
    if (!pool && (!scene.spheres.empty() || !scene.boxes.empty()))
      noPool.emplace(ctx, graph, objectUniforms, ground.params());
    const PoolDraw* poolDraw = pool ? &pool->draw() : noPool ? &noPool->draw() : nullptr;
    // The glossy spheres' and walls' probes, before what reflects them.
    if (poolDraw) glossyProbes.declare(graph, in, *poolDraw);
    if (pool) {
      pool->declare(
          graph, surfaces, in,
          [this] {
            if (!skipping || !floorSeenOnlyThroughWater(live, water->largestHeight(), pool->floorTop()))
              return Pool::Drawn{Pool::Floor::Lit, std::nullopt, std::nullopt};
            // Nothing but the SSAO reads the depth and normals the water draws over.
            const float below = seenOnlyThroughWaterBelow(live, water->largestHeight());
            if (aoMakesItsInputs()) return Pool::Drawn{Pool::Floor::DepthAndNormal, std::nullopt, below};
            return Pool::Drawn{Pool::Floor::None, below, std::nullopt};
          },
          glossyProbes.poolMap());
    }
    if (!scene.spheres.empty() || !scene.boxes.empty()) {
      objects.emplace(ctx, needs, *poolDraw);
      objects->declare(graph, surfaces, in, opaqueInView, glossyProbes.maps());
    }
    // AO of the opaque surfaces, before the water: the apparent-depth mode's
    // copy of the pool then has it too. Applied here, or by the resolve.
    if (scene.ao.enabled) {
      ao.emplace(ctx, graph, scene.ao, frame, aoAfterWater(scene, skipping));
      ao->declare(graph, surfaces, in, [this] { return opaqueSurfacesMayHaveChanged(); });
    }
    if (waterSurface) waterSurface->declareUnderwater(graph, surfaces.color);
    // Glass after AO (it neither occludes nor is occluded) and after the
    // apparent-depth mode's copy (the water's rays cast against glass
    // instead), before the water, which draws over what of it is under the
    // surface.
    if (scene::hasGlass(scene)) {
      glass.emplace(ctx, graph, frame, needs, *poolDraw, scene);
      glass->declare(graph, surfaces, in, glassInView, glassBoxesInView);
    }
    if (waterSurface) waterSurface->declare(graph, surfaces, pool->draw(), in);
    // The AO when it is taken after the water, the air between the camera
    // and every surface (the water's too), the tonemap.
    const std::optional<AoForResolve> aoInResolve = ao ? std::optional(ao->forResolve(surfaces)) : std::nullopt;
    resolve.emplace(ctx, graph, scene, frame, aoInResolve, resolveTiles(aoInResolve));
    if (options.aovs) {
      aovs.emplace(ctx, graph, frame, pool.has_value());
      aovs->declare(graph, in, ground.params(), pool ? &pool->draw() : nullptr,
                    waterSurface ? &waterSurface->draw() : nullptr, aovInView);
    }
    // The morphological anti-aliasing filters the tonemapped frame into the
    // LDR target, which the viewer shows and the PNG is read from.
    if (scene.render.antialiasing == "morphological") {
      antialiasing.emplace(ctx, graph, frame);
      resolve->declare(graph, surfaces, in, antialiasing->input());
      antialiasing->declare(graph, targets.ldr(), surfaces.depth, *samplers.clamp, *samplers.nearest);
    } else {
      resolve->declare(graph, surfaces, in, targets.ldr());
    }
    targets.declareReadbacks(graph);
  }

  // Whether a frame whose inputs outside what the pool, the objects and the
  // water draw did not change since the last frame may copy the ground and
  // resolve the frame in part. Not with nothing skipped, nor where a pass
  // that is not followed draws over the frame: the AO applied before the
  // water, glass, the apparent-depth mode's copy. Asked once the water is
  // declared.
  bool stillFramesInPart(const scene::Scene& scene) const {
    return skipping && waterSurface && waterSurface->deferred() && !scene::hasGlass(scene) &&
           !apparentRefraction(scene) && (!scene.ao.enabled || aoAfterWater(scene, skipping));
  }

  // What lets the resolve work on the changed tiles alone: the water's
  // tiles, and the inputs that change the pixels of the ground's copy.
  std::optional<ResolveTiles> resolveTiles(const std::optional<AoForResolve>& aoIn) const {
    if (!stillInPart) return std::nullopt;
    ResolveTiles tiles{.water = waterSurface->deferred(),
                       .unchanged = {uniformsRef.ref, sky.image().ref, medium.buffer().ref}};
    const SurfaceTargets& g = ground.drawn();
    for (const GraphImage& image : {g.color, g.depth, g.normal, g.ambient}) {
      if (image) tiles.unchanged.push_back(image.ref);
    }
    if (aoIn) {
      tiles.unchanged.push_back(aoIn->ao.ref);
      if (aoIn->upsample) tiles.unchanged.push_back(aoIn->lowViewDepth.ref);
    }
    return tiles;
  }

  // The pixels frame `number` copies of the ground: those the last frame drew
  // over it, when that was the frame before and left the rest as the ground's
  // copy (it did not store its HDR colour, which the resolve changes in
  // place); none for all. The water the last frame drew is under the highest
  // wave its statistics saw.
  std::optional<PixelRect> groundToCopy(uint64_t number, const glm::mat4& viewProjection, glm::uvec2 size) const {
    if (!stillInPart || !lastFrame || lastFrame->number + 1 != number || lastFrame->storedHdr) return std::nullopt;
    const glm::vec3 lo = poolBox.first, hi = poolBox.second;
    const PixelRect water =
        pixelsCovering(viewProjection, size, {lo.x, hi.y, lo.z}, {hi.x, std::max(hi.y, lastFrame->waterTop), hi.z});
    return united(lastFrame->drawn, water);
  }

  // The pixels the pool and the objects in view may draw this frame.
  PixelRect drawnOverTheGround(const shader::FrameUniforms& frame, glm::uvec2 size) const {
    const glm::mat4& viewProjection = frame.viewProjection;
    PixelRect drawn;
    if (pool) {
      // Over the ground, the pool is seen only through its opening: the
      // ground, drawn first, hides the rest of it.
      std::pair<glm::vec3, glm::vec3> box = poolBox;
      if (frame.cameraPosition.y > box.second.y) box.first.y = box.second.y;
      drawn = pixelsCovering(viewProjection, size, box.first, box.second);
    }
    for (const auto& sphere : opaqueInView.spheres) {
      const glm::vec3 c(sphere.sphere), r(sphere.sphere.w);
      drawn = united(drawn, pixelsCovering(viewProjection, size, c - r, c + r));
    }
    for (const auto& box : opaqueInView.boxes) {
      const glm::vec3 c(box.center), r(glm::length(glm::vec3(box.halfSize)));  // any yaw
      drawn = united(drawn, pixelsCovering(viewProjection, size, c - r, c + r));
    }
    return drawn;
  }

  // The water and what follows it: the simulation (its driver), the surface,
  // the camera's medium, the pool and its caustics.
  void declareWater(const gpu::Context& ctx, const scene::Scene& scene, vk::Extent2D frame, const FrameInputs& in) {
    water.emplace(ctx, scene, skipping);
    waterSurface.emplace(ctx, graph, scene, needs, water->stepper(), frame, skipping, aoAfterWater(scene, skipping));
    const WaterDraw& draw = waterSurface->draw();
    // The live drops and moves, the steps to this frame with the scene's
    // drops due on the way, and the stats that say whether the water is
    // healthy and whether it may sleep; left out while it sleeps.
    graph.pass(passes::kSimulate,
               [this, &draw](PassBuilder& pass) {
                 pass.use(draw.state, Use::ComputeReadWrite);
                 return [this](PassContext& pc) { water->record(pc.cmd, live); };
               },
               {.cached = false, .runIf = [this] { return water->simulating(); }});
    medium.declare(graph, draw, in, [this] { return !skipping || cameraOverWater(live) || mediumMayNotBeAir; });
    pool.emplace(ctx, graph, scene, sky, needs, objectUniforms, draw.state);
    const shader::PoolParams p = poolParams(scene);
    poolBox = {{-p.box.x, shader::poolBottom(p), -p.box.x}, {p.box.x, p.box.y, p.box.x}};
    pool->declareCaustics(graph, draw, in);
  }

  // The objects where they are at `time`, those in view for the passes that
  // draw them (all of them stay in the objects the water's rays meet: a
  // reflection shows what the frame does not), and the glossy probes' eyes
  // and light (`frame`'s).
  void placeObjects(const scene::Scene& scene, float time, const shader::FrameUniforms& frame, unsigned glassSteps) {
    const scene::Scene placed = scene::sceneAt(scene, time);
    glossyProbes.update(graph, frame, placed);
    const Frustum frustum(frame.viewProjection);
    opaqueInView = {};
    aovInView = {};
    glassInView.clear();
    glassBoxesInView.clear();
    // Objects wholly over the water are left out of the casts under it.
    const shader::SceneObjects casts =
        sceneObjects(placed, skipping && water ? water->top() : std::numeric_limits<float>::infinity());
    std::memcpy(objectUniforms.mapped, &casts, sizeof(casts));
    for (size_t k = 0; k < placed.spheres.size(); ++k) {
      const scene::Sphere& sphere = placed.spheres[k];
      if (skipping && !frustum.mayShow(sphere.center, sphere.radius)) continue;
      if (scene::isGlass(sphere)) {
        glassInView.push_back(glassSphereParams(sphere, glassSteps, sphereSlot(casts, sphere)));
      } else {
        opaqueInView.spheres.push_back(sphereParams(sphere));
        opaqueInView.sphereProbes.push_back(glossyProbes.probeOf(k));
      }
      aovInView.spheres.push_back(sphereParams(sphere));
    }
    for (const auto& box : placed.boxes) {
      if (skipping && !frustum.mayShow(box.center, 0.5f * glm::length(box.size))) continue;
      if (scene::isGlass(box)) {
        glassBoxesInView.push_back(glassBoxParams(box));
      } else {
        opaqueInView.boxes.push_back(boxParams(box));
      }
      aovInView.boxes.push_back(boxParams(box));
    }
  }

  // The water's and the floor's grids as finely as this frame shows them
  // (the camera may have moved). The cached caustics draw the water's grid
  // reaching the walls at the same step: a new step draws them again.
  void setGridSteps(const scene::Scene& scene, const glm::mat4& viewProjection, glm::vec2 pixels) {
    if (!waterSurface) return;
    auto step = [&](float y, uint32_t vertices) {
      return coarseGrids ? gridStep(viewProjection, pixels, {0.0f, y, 0.0f}, scene.water.extent, vertices) : 1u;
    };
    const uint32_t waterStep = step(scene.water.level, scene.water.grid);
    if (waterSurface->setGridStep(waterStep) | pool->setCausticsStep(waterStep)) {
      for (ResourceRef state : waterSurface->draw().state.refs) graph.touch(state);
    }
    pool->setFloorStep(step(scene.ground.height - scene.pool.depth, kPoolFloorGrid));
  }

  // Whether the opaque surfaces' depth and normals may differ from those the
  // SSAO last ran on (or nothing is skipped): the SSAO runs again.
  bool opaqueSurfacesMayHaveChanged() const { return !skipping || aoGeometry != geometry; }

  // Whether this frame's opaque surfaces must give the SSAO its depth and
  // normals: it runs, or the frame reads them back.
  bool aoMakesItsInputs() const { return ao && (opaqueSurfacesMayHaveChanged() || aoReadback); }

  // The readbacks a request asks for: their passes, and those they depend on, record.
  std::vector<ResourceRef> requestedOutputs(const FrameRequest& request) const {
    std::vector<ResourceRef> requested;
    if (request.hdr) requested.push_back(targets.hdrReadback().ref.ref);
    if (request.ldr) requested.push_back(targets.ldrReadback().ref.ref);
    if (request.present) requested.push_back(targets.ldr().ref);
    if (request.aovs) {
      if (!aovs) throw std::logic_error("AOVs requested from a renderer made without them");
      for (ResourceRef r : aovs->readbackRefs()) requested.push_back(r);
    }
    if (request.ao) {
      if (!ao) throw std::logic_error("AO requested from a renderer of a scene without it");
      for (ResourceRef r : ao->readbackRefs()) requested.push_back(r);
    }
    return requested;
  }

  // The frame's pixels, as the request asked for them.
  void readBack(const FrameRequest& request, RenderedFrame& out) const {
    const size_t pixels = size_t(out.width) * out.height;
    if (request.hdr) out.rgba = readFloats(targets.hdrReadback().buffer, pixels * 4);
    if (request.ldr) out.srgb = readBytes(targets.ldrReadback().buffer, pixels * 4);
    if (request.aovs) {
      out.normal = aovs->normals();
      out.position = aovs->positions();
    }
    if (request.ao) {
      out.aoWidth = ao->lowExtent().width;
      out.aoHeight = ao->lowExtent().height;
      AmbientOcclusion::Readings r = ao->read();
      out.ao = std::move(r.ao);
      out.aoRaw = std::move(r.raw);
      out.gbufferDepth = std::move(r.depth);
      out.gbufferNormal = std::move(r.viewNormal);
    }
  }

  const scene::Scene& live;
  bool skipping;     // RendererOptions::skipping
  bool coarseGrids;  // RendererOptions::coarseGrids
  FrameGraph graph;
  gpu::DescriptorArena descriptors;
  Samplers samplers;
  gpu::Buffer uniforms;
  GraphBuffer uniformsRef;
  gpu::Buffer glassTables;  // shader::GlassTables, filled from glassTableCache
  GraphBuffer glassTablesRef;
  GlassTableCache glassTableCache;
  gpu::Buffer objectUniforms;  // the objects the rays cast in shaders meet (shader::SceneObjects)
  FrameTargets targets;
  FragmentNeeds needs;  // what the surfaces' shaders need of the scene
  Sky sky;
  GlossyEnvironment glossy;
  GlossyProbes glossyProbes;  // none without glossy spheres or walls
  CameraMedium medium;
  Ground ground;
  // With water: the simulation, the surface, the pool.
  std::optional<sim::WaterDriver> water;
  std::optional<WaterSurface> waterSurface;
  std::optional<Pool> pool;
  std::optional<NoPool> noPool;  // without water, for the objects and the glass
  std::optional<Objects> objects;
  std::optional<AmbientOcclusion> ao;
  std::optional<Glass> glass;
  std::optional<FrameResolve> resolve;
  std::optional<Aovs> aovs;  // when the renderer was made with them
  std::optional<MorphologicalAntialiasing> antialiasing;
  // The pool's inside, floor to rim: the corners of the box the pool pass draws in.
  std::pair<glm::vec3, glm::vec3> poolBox;
  uint64_t frames = 0;       // rendered so far
  bool stillInPart = false;  // stillFramesInPart
  // The last frame rendered, when it copied the ground: what groundToCopy needs of it.
  struct LastFrame {
    uint64_t number;
    PixelRect drawn;  // drawnOverTheGround
    float waterTop;   // sim::WaterDriver::top
    bool storedHdr;   // its resolve stored the HDR colour
  };
  std::optional<LastFrame> lastFrame;
  std::optional<PixelRect> groundCopy;  // the frame being recorded's groundToCopy
  // Filled by render() for the frame being recorded.
  ObjectsInView opaqueInView;  // the opaque spheres and the boxes in view
  ObjectsInView aovInView;     // every sphere in view, glass too, and the boxes
  std::vector<shader::GlassSphereParams> glassInView;
  std::vector<shader::GlassBoxParams> glassBoxesInView;
  bool mediumMayNotBeAir = false;            // the camera medium pass last ran with the camera over the water
  OpaqueGeometry geometry;                   // the frame being recorded's
  std::optional<OpaqueGeometry> aoGeometry;  // the frame's where the SSAO last ran
  bool aoReadback = false;                   // the frame being recorded reads back the AO and its G-buffer
};

Renderer::Renderer(const gpu::Context& ctx, const scene::Scene& scene, uint32_t width, uint32_t height,
                   const RendererOptions& options)
    : ctx_(ctx),
      scene_(scene),
      width_(width),
      height_(height),
      options_(options),
      res_(std::make_unique<Resources>(ctx, scene_, vk::Extent2D{width, height}, options)) {}

namespace {

// `scene`, when its water is `previous`'s but for what only shades it.
const scene::Scene& sameWater(const scene::Scene& previous, const scene::Scene& scene) {
  if (!sim::sameWaterMotion(scene.water, previous.water)) {
    throw std::invalid_argument(
        "a renderer that goes on with the water needs the same water but for ior, absorption and scattering: "
        "other water settings need a new renderer (the water restarts)");
  }
  return scene;
}

}  // namespace

Renderer::Renderer(GoOnFrom from) : Renderer(from, from.previous.scene_) {}

Renderer::Renderer(GoOnFrom from, uint32_t width, uint32_t height)
    : Renderer(from, from.previous.scene_, width, height) {}

Renderer::Renderer(GoOnFrom from, const scene::Scene& scene)
    : Renderer(from, scene, from.previous.width_, from.previous.height_) {}

Renderer::Renderer(GoOnFrom from, const scene::Scene& scene, uint32_t width, uint32_t height)
    : Renderer(from.previous.ctx_, sameWater(from.previous.scene_, scene), width, height, from.previous.options_) {
  if (res_->water) res_->water->goOnFrom(*from.previous.res_->water);
}

Renderer::~Renderer() {
  try {
    ctx_.device().waitIdle();
  } catch (const vk::SystemError&) {
    // A lost device: nothing runs any more.
  }
}

PresentableImage Renderer::presentable() const {
  return {res_->targets.ldr().image, res_->graph.layoutOf(res_->targets.ldr().ref)};
}

void Renderer::addDrop(const scene::Drop& drop) {
  if (!res_->water) throw std::runtime_error("a drop needs a scene with water");
  scene::validateDrop(drop);
  res_->water->addDrop(scene_.water, drop);
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
  const float now = res_->water ? float(res_->water->time(scene_.water)) : 0.0f;
  const glm::vec3 from = scene::sphereCenterAt(sphere, now);
  sphere.path.clear();
  sphere.center = center;
  if (res_->water) res_->water->moveSphere(from, center, sphere.radius);
}

void Renderer::setWaterDynamics(const scene::Water& water) {
  if (!res_->water) throw std::runtime_error("the scene has no water");
  if (sim::withDynamicsOf(water, scene_.water) != scene_.water) {
    throw std::invalid_argument(
        "only the wave speed, damping, grid damping, boundary, max slope and sphere forcing change on a live renderer");
  }
  res_->water->setDynamics(water);  // validates before it changes anything
  scene_.water = water;
}

sim::WaterState Renderer::waterState() const {
  if (!res_->water) throw std::runtime_error("the scene has no water");
  return res_->water->state();
}

sim::WaterCheckpoint Renderer::checkpoint() const {
  if (!res_->water) throw std::runtime_error("the scene has no water");
  return res_->water->checkpoint();
}

void Renderer::resume(const sim::WaterCheckpoint& checkpoint) {
  if (!res_->water) throw std::runtime_error("the scene has no water");
  res_->water->resume(checkpoint, scene_);
  for (ResourceRef state : res_->waterSurface->draw().state.refs)
    res_->graph.touch(state);  // uploaded outside the graph
}

RenderedFrame Renderer::render(const FrameRequest& request) {
  RenderedFrame out;
  out.width = width_;
  out.height = height_;
  const float time = float(request.frame) * scene_.water.frameTime;
  shader::FrameUniforms uniforms =
      frameUniforms(scene_, res_->sky.light(), width_, height_, request.pixelOffset, request.filterWidth);
  uniforms.shadows = shadowCasters(scene_, time);
  if (std::memcmp(res_->uniforms.mapped, &uniforms, sizeof(uniforms)) != 0) {
    std::memcpy(res_->uniforms.mapped, &uniforms, sizeof(uniforms));
    res_->graph.touch(res_->uniformsRef.ref);
  }
  if (res_->glassTableCache.fill(scene_, time, *static_cast<shader::GlassTables*>(res_->glassTables.mapped)))
    res_->graph.touch(res_->glassTablesRef.ref);
  // The camera's matrices, without the sample's jitter.
  const shader::FrameUniforms centred = frameUniforms(scene_, res_->sky.light(), width_, height_);
  out.worldToCamera = centred.view;
  out.worldToNDC = centred.viewProjection;
  out.inverseProjection = centred.inverseProjection;
  res_->setGridSteps(scene_, centred.viewProjection, glm::vec2(float(width_), float(height_)));
  if (res_->water && res_->water->plan(scene_, request.frame)) {
    for (ResourceRef state : res_->waterSurface->draw().state.refs)
      res_->graph.touch(state);  // uploaded outside the graph
  }
  // Spheres with a path are where the path puts them at this frame's time.
  res_->placeObjects(scene_, time, uniforms, scene_.render.glassSearchSteps);
  res_->geometry = opaqueGeometry(uniforms, res_->opaqueInView, res_->pool ? res_->pool->floorStep() : 1u);
  res_->aoReadback = request.ao;
  const std::vector<ResourceRef> requested = res_->requestedOutputs(request);
  res_->resolve->setWanted(request.hdr, request.ldr || request.present);
  const uint64_t number = res_->frames++;
  const PixelRect drawn = res_->drawnOverTheGround(uniforms, {width_, height_});
  res_->resolve->setFrame(number, drawn);
  res_->groundCopy = res_->groundToCopy(number, uniforms.viewProjection, {width_, height_});

  gpu::GpuTimer timer(ctx_, uint32_t(res_->graph.passCount()));  // a scope per pass at most
  res_->descriptors.reset();  // the previous frame has finished: render() waits for it
  gpu::Submission submission(ctx_, "frame rendering");
  timer.reset(submission.cmd());
  FrameGraph::AfterPass submitPass;
  if (request.passWallTimes) {
    submission.flush();  // the timer's reset, before the first pass's clock starts
    submitPass = [&submission](RecordedPass& pass) {
      const auto start = std::chrono::steady_clock::now();
      submission.flush();
      pass.wallMilliseconds =
          std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    };
  }
  {
    PassContext context{submission.cmd(), res_->descriptors};
    gpu::CountScope counting(out.counts);
    out.passes = res_->graph.record(context, requested, &timer, submitPass);
  }
  submission.finish();
  const auto times = timer.read();
  for (size_t p = 0; p < out.passes.size(); ++p) out.passes[p].milliseconds = times.at(p).milliseconds;
  RecordedPass* simulate = findPass(out.passes, passes::kSimulate);
  if (simulate) {
    // The tiles the steps' indirect dispatches launched, known only now.
    const uint64_t listedTiles = res_->water->finish(scene_);
    out.counts.workgroups += listedTiles;
    simulate->counts.workgroups += listedTiles;
  }
  if (findPass(out.passes, passes::kCameraMedium)) res_->mediumMayNotBeAir = cameraOverWater(scene_);
  if (findPass(out.passes, passes::kSsao)) res_->aoGeometry = res_->geometry;
  out.waterAsleep = res_->water && !simulate;
  res_->lastFrame.reset();
  if (findPass(out.passes, passes::kGroundCopy)) {
    res_->lastFrame =
        Resources::LastFrame{.number = number,
                             .drawn = drawn,
                             .waterTop = res_->water ? res_->water->top() : 0.0f,
                             .storedHdr = findPass(out.passes, passes::kResolve) && res_->resolve->storesHdr()};
  }
  if (findPass(out.passes, passes::kResolveTiles)) {
    const FrameResolve::Resolved r = res_->resolve->lastResolved();
    out.resolvedTiles = r.tiles;
    out.frameTiles = r.of;
  }
  out.waterEnergy = res_->water ? res_->water->energyPerArea() : 0.0;
  res_->readBack(request, out);
  return out;
}

}  // namespace tp::render
