#pragma once
// The passes of the frame. Each owns its pipeline and declares itself into a
// FrameGraph with the resources it reads and writes; the graph orders them and
// places the barriers.
#include <functional>
#include <optional>

#include "gpu/context.hpp"
#include "gpu/pipeline.hpp"
#include "render/frame_graph.hpp"
#include "shared/ground.h"
#include "shared/objects.h"
#include "shared/sky.h"
#include "shared/tonemap.h"
#include "shared/water_surface.h"

namespace tp::render {

constexpr vk::Format kHdrFormat = vk::Format::eR32G32B32A32Sfloat;
constexpr vk::Format kLdrFormat = vk::Format::eR8G8B8A8Unorm;
constexpr vk::Format kDepthFormat = vk::Format::eD32Sfloat;
constexpr vk::Format kSkyFormat = vk::Format::eR16G16B16A16Sfloat;
constexpr vk::Format kAovFormat = vk::Format::eR32G32B32A32Sfloat;
constexpr vk::Format kCausticsFormat = vk::Format::eR16G16B16A16Sfloat;  // the sky's format: blendable, sampled
constexpr uint32_t kCausticsSize = 512;  // texels per side of the caustics texture over the pool
constexpr vk::Format kGbufferFormat = vk::Format::eR16G16B16A16Sfloat;  // view normal, ambient radiance
constexpr vk::Format kAoFormat = vk::Format::eR32Sfloat;

// An image and its name in the frame graph.
struct Target {
  ResourceRef ref;
  const gpu::Image* image = nullptr;
};

// What the opaque surfaces (ground, pool, objects) draw into: colour and
// depth, and, when something reads it (SSAO), the G-buffer beside them: the
// view-space normal and the ambient part of the colour. Without it the
// surfaces draw with their shaders' colour-only variants.
struct SurfaceTargets {
  Target color, depth, normal, ambient;
  bool gbuffer() const { return normal.image != nullptr; }
};

// Compute: the procedural sky into an equirectangular HDR texture. Cached:
// its parameters are fixed, so it runs on the first frame only.
struct SkyPass {
  explicit SkyPass(const gpu::Context& ctx);
  void declare(FrameGraph& graph, ResourceRef skyRef, const gpu::Image& sky, const shader::SkyParams& params) const;
  gpu::Pipeline pipeline;
};

// Graphics: the sky texture behind everything, seen through each pixel's view ray.
struct BackgroundPass {
  explicit BackgroundPass(const gpu::Context& ctx);
  void declare(FrameGraph& graph, ResourceRef colorRef, const gpu::Image& color, ResourceRef skyRef,
               const gpu::Image& sky, vk::Sampler sampler, const gpu::Buffer& frameUniforms) const;
  gpu::Pipeline pipeline;
};

// Graphics: the checkered ground plane, depth tested; the first surface, so it
// clears depth and the G-buffer.
struct GroundPass {
  GroundPass(const gpu::Context& ctx, bool gbuffer);
  void declare(FrameGraph& graph, const SurfaceTargets& targets, const gpu::Buffer& frameUniforms,
               const shader::GroundParams& params) const;
  gpu::Pipeline pipeline;
};

// The medium around the camera (camera_medium.comp's output, or air where
// the scene has no water), read by the passes that draw what the camera sees
// directly.
struct MediumDraw {
  ResourceRef ref;
  const gpu::Buffer* buffer = nullptr;
};

// The glossy environment the glossy surfaces reflect (shared/glossy.h): the
// prefilter's map, or one black texel where the scene has no glossy surface.
struct GlossyDraw {
  ResourceRef ref;
  const gpu::Image* image = nullptr;
  vk::Sampler sampler;  // trilinear: textureLod blends two levels
};

// What a pass needs to draw the pool: its uniform buffer and the floor grid's indices.
struct PoolDraw {
  const gpu::Buffer* uniforms = nullptr;
  const gpu::Buffer* objects = nullptr;  // the spheres the refracted rays can meet
  const gpu::Buffer* floorIndices = nullptr;
  uint32_t floorIndexCount = 0;
  uint32_t floorGrid = 0;  // vertices per side
  // The sun through the waves on the floor (the caustics pass's target, or
  // one texel of 1 when the scene has caustics off), sampled linearly.
  ResourceRef causticsRef;
  const gpu::Image* caustics = nullptr;
  vk::Sampler causticsSampler;
  GlossyDraw glossy;  // for the walls and the spheres the water's rays meet
};

// Graphics: the pool's inner walls and its terrain floor.
struct PoolPass {
  PoolPass(const gpu::Context& ctx, bool gbuffer);
  void declare(FrameGraph& graph, const SurfaceTargets& targets, const gpu::Buffer& frameUniforms, const PoolDraw& pool,
               const MediumDraw& medium) const;
  gpu::Pipeline walls, floor;
};

// Graphics: the scene's spheres and boxes, one draw each, where `spheres` and
// `boxes` say they are when the frame records (spheres may move from frame to
// frame); left out of a frame where both are empty (all out of view).
struct ObjectPass {
  ObjectPass(const gpu::Context& ctx, bool gbuffer);
  void declare(FrameGraph& graph, const SurfaceTargets& targets, const gpu::Buffer& frameUniforms, const MediumDraw& medium,
               const GlossyDraw& glossy, const std::vector<shader::SphereParams>* spheres,
               const std::vector<shader::BoxParams>* boxes) const;
  gpu::Pipeline spherePipeline, boxPipeline;
};

// What a pass needs to draw the water grid: the state buffers (read in the
// vertex stage; `state` names the current one at record time) and the indices.
struct WaterDraw {
  std::vector<ResourceRef> stateRefs;
  std::function<const gpu::Buffer&()> state;
  const gpu::Buffer* indices = nullptr;
  uint32_t indexCount = 0;
  shader::WaterSurfaceParams params;
};

// Graphics: the simulated water surface over the ground, reflecting the sky
// and refracting the floor.
// The apparent-depth mode reads `underwater`, the frame's image of the pool
// copied before the water is drawn (accurate mode: none).
struct Underwater {
  ResourceRef ref;
  const gpu::Image* image = nullptr;
  vk::Sampler sampler;
};

struct WaterSurfacePass {
  WaterSurfacePass(const gpu::Context& ctx, bool apparentDepth);
  void declare(FrameGraph& graph, ResourceRef colorRef, const gpu::Image& color, ResourceRef depthRef,
               const gpu::Image& depth, const WaterDraw& water, const PoolDraw& pool, ResourceRef skyRef,
               const gpu::Image& sky, vk::Sampler sampler, const gpu::Buffer& frameUniforms,
               std::optional<Underwater> underwater) const;
  gpu::Pipeline above, below;  // two draws of the mesh: its front faces, then its back faces
};

// Graphics: the caustics texture, accumulated from the water grid refracting
// the sun onto the floor's mean plane (shaders_glsl/caustics.vert).
struct CausticsPass {
  explicit CausticsPass(const gpu::Context& ctx);
  // Cached: recorded again only when the water or the frame uniforms (`uniformsRef`: the sun) changed.
  void declare(FrameGraph& graph, const WaterDraw& water, const PoolDraw& pool, const gpu::Buffer& frameUniforms,
               ResourceRef uniformsRef) const;
  gpu::Pipeline pipeline;
};

// Compute: whether the camera is under the simulated surface, into `medium`
// (one invocation after the simulation). Cached: recorded again only when the
// water or the frame uniforms (the camera) changed.
struct CameraMediumPass {
  explicit CameraMediumPass(const gpu::Context& ctx);
  // `runIf`: whether the medium may differ from what the buffer holds.
  void declare(FrameGraph& graph, const WaterDraw& water, const gpu::Buffer& frameUniforms, ResourceRef uniformsRef,
               const MediumDraw& medium, std::function<bool()> runIf) const;
  gpu::Pipeline pipeline;
};

// Transfer: the colour target copied into another image of the same size.
void declareImageCopy(FrameGraph& graph, const std::string& name, ResourceRef fromRef, const gpu::Image& from,
                      ResourceRef toRef, const gpu::Image& to);

// Graphics: world normal, world position and view depth of every surface
// (arbitrary output variables for the EXR), into their own targets. Recorded
// only when a frame asks for them.
struct AovPass {
  AovPass(const gpu::Context& ctx, bool withPoolAndWater);
  void declare(FrameGraph& graph, ResourceRef normalRef, const gpu::Image& normal, ResourceRef positionRef,
               const gpu::Image& position, ResourceRef depthRef, const gpu::Image& depth,
               const gpu::Buffer& frameUniforms, const shader::GroundParams& ground, const PoolDraw* pool,
               const WaterDraw* water, const std::vector<shader::SphereParams>* spheres,
               const std::vector<shader::BoxParams>* boxes) const;
  gpu::Pipeline groundPipeline, spherePipeline, boxPipeline;
  std::optional<gpu::Pipeline> wallsPipeline, floorPipeline, waterPipeline;
};

// Compute: linear HDR to the 8-bit sRGB preview.
struct TonemapPass {
  explicit TonemapPass(const gpu::Context& ctx);
  void declare(FrameGraph& graph, ResourceRef hdrRef, const gpu::Image& hdr, ResourceRef ldrRef, const gpu::Image& ldr,
               float exposure) const;
  gpu::Pipeline pipeline;
};

// Helpers of the graphics passes, for those declared in files of their own
// (glass_passes.cpp): the viewport and scissor of a target, an attachment
// stored after the pass, and a draw over what colour and depth already hold.
void setViewport(const vk::raii::CommandBuffer& cmd, vk::Extent2D extent);
vk::RenderingAttachmentInfo attachment(const gpu::Image& image, vk::ImageLayout layout, vk::AttachmentLoadOp load,
                                       vk::ClearValue clear = {});
void drawOver(const vk::raii::CommandBuffer& cmd, const gpu::Image& color, const gpu::Image& depth,
              const std::function<void()>& draw);

// Transfer: an image copied into a buffer for the host to read.
void declareReadback(FrameGraph& graph, const std::string& name, ResourceRef imageRef, const gpu::Image& image,
                     ResourceRef bufferRef, const gpu::Buffer& buffer);

}  // namespace tp::render
