#pragma once
// The frame's targets, and what the graphics passes share: the viewport, an
// attachment stored after the pass, the opaque surfaces' framing and
// pipelines, and what every pass may read (FrameInputs).
#include <functional>
#include <span>
#include <string>

#include "gpu/context.hpp"
#include "gpu/pipeline.hpp"
#include "graph/frame_graph.hpp"
#include "scene/scene.hpp"
#include "shared/shadow_casters.h"

namespace tp::render {

constexpr vk::Format kHdrFormat = vk::Format::eR32G32B32A32Sfloat;
constexpr vk::Format kLdrFormat = vk::Format::eR8G8B8A8Unorm;
constexpr vk::Format kDepthFormat = vk::Format::eD32Sfloat;
constexpr vk::Format kSkyFormat = vk::Format::eR16G16B16A16Sfloat;
constexpr vk::Format kAovFormat = vk::Format::eR32G32B32A32Sfloat;
constexpr vk::Format kGbufferFormat = vk::Format::eR16G16B16A16Sfloat;  // view normal, ambient radiance
constexpr vk::Format kAoFormat = vk::Format::eR32Sfloat;

// What the opaque surfaces (ground, pool, objects) draw into: colour and
// depth, and, when something reads it (SSAO), the G-buffer beside them: the
// view-space normal and the ambient part of the colour. Without it the
// surfaces draw with their shaders' colour-only variants.
struct SurfaceTargets {
  GraphImage color, depth, normal, ambient;
  bool gbuffer() const { return bool(normal); }
};

// What the passes of every feature may read, made before any of them.
struct FrameInputs {
  GraphBuffer uniforms;     // the frame's uniforms, filled by the host before each frame
  GraphBuffer glassTables;  // the glass spheres' sun tables (shared/shadow_casters.h), filled the same way
  GraphImage sky;           // the equirectangular sky
  GraphImage glossy;        // the glossy environment (shared/glossy.h), or one black texel
  GraphBuffer medium;       // the medium around the camera (camera_medium.comp), or air
  vk::Sampler equirect;     // around in u, clamped at the poles, through every mip level
  vk::Sampler nearest;      // texel fetches
  vk::Sampler clamp;        // linear, clamped
};

// The frame's samplers (FrameInputs'), made once.
struct Samplers {
  explicit Samplers(const gpu::Context& ctx);
  vk::raii::Sampler equirect, nearest, clamp;
};

void setViewport(const vk::raii::CommandBuffer& cmd, vk::Extent2D extent);
vk::RenderingAttachmentInfo attachment(const gpu::Image& image, vk::ImageLayout layout, vk::AttachmentLoadOp load,
                                       vk::ClearValue clear = {});

// Renders into `colors` (and `depth`, when given) over `extent`: begins
// rendering, sets the viewport and scissor, draws, ends.
void renderTo(const vk::raii::CommandBuffer& cmd, std::span<const vk::RenderingAttachmentInfo> colors,
              const vk::RenderingAttachmentInfo* depth, vk::Extent2D extent, const std::function<void()>& draw);

// A surface pass's attachments, declared: colour, depth and the G-buffer
// cleared by the first surface pass (`first`) and drawn over by the rest.
// The sky's background comes after the surfaces, where none was drawn.
void attachSurfaces(PassBuilder& pass, const SurfaceTargets& targets, bool first);
// Renders over the surface targets (as attachSurfaces declared them; zero
// ambient where the first pass clears: AO takes nothing from pixels no
// surface covers).
void drawSurfaces(const vk::raii::CommandBuffer& cmd, const SurfaceTargets& targets, bool first,
                  const std::function<void()>& draw);
// Renders over what colour and depth already hold (both loaded and stored),
// and over a second colour target (the G-buffer's ambient image) when given.
void drawOver(const vk::raii::CommandBuffer& cmd, const gpu::Image& color, const gpu::Image& depth,
              const std::function<void()>& draw, const gpu::Image* second = nullptr);

// What a scene needs of a fragment shader, which picks its variant
// (cmake/shaders.cmake): the G-buffer outputs, the sun shadows' code
// (shading/frame_uniforms.hpp's castsShadows), the light scattered in the
// water (shading/water_model.hpp's hasWaterScattering), glass the water's
// rays meet (scene::hasGlass); and, as specialization constants
// (fragmentSpecialization), which casters' code the shadows hold, whether
// the glossy lookups are there, and which patterns' code.
struct FragmentNeeds {
  bool gbuffer = true;
  bool shadows = true;
  bool scattering = false;
  bool glass = false;
  bool sphereShadows = true;
  bool boxShadows = true;
  bool glassShadows = true;
  bool glossy = true;
  bool brickWalls = true;
  bool tiles = true;
  // The water's shaders: write zero into the G-buffer's ambient image where
  // the water is seen, so that the resolve pass takes AO from the opaque
  // surfaces alone (render/frame_resolve.hpp).
  bool clearAmbient = false;
};

// What the scene's opaque surfaces need (glass is the water's alone). With
// `skipping` off, all of the code (every kind of caster, the glossy lookups,
// every pattern): the frame drawn by the general shaders, which tests
// compare the specialized ones with.
FragmentNeeds surfaceNeeds(const scene::Scene& scene, bool gbuffer, bool skipping);

// The fragment shader's specialization constants (shared/specialization.h).
gpu::Specialization fragmentSpecialization(FragmentNeeds needs);

// The variant of a fragment shader NAME.frag (or of the compute shader
// that shades the water deferred, NAME.comp): NAME, then .color_only
// without the G-buffer, .no_shadows without shadows, .scattering with
// scattering, .glass with glass, then .frag (.comp).
std::string fragmentVariant(const std::string& fragmentShader, FragmentNeeds needs);

// A pipeline of an opaque surface: colour, the two G-buffer targets (or,
// without them, the fragment shader's colour-only variant), depth; the
// fragment shader's variant as fragmentVariant gives it.
gpu::GraphicsPipelineDesc opaquePipeline(const std::string& vertexShader, const std::string& fragmentShader,
                                         uint32_t pushSize, FragmentNeeds needs);

}  // namespace tp::render
