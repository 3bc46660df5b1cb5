#pragma once
#include <cstdint>
#include <glm/glm.hpp>
#include <memory>
#include <vector>

#include "gpu/context.hpp"
#include "render/frame_graph.hpp"
#include "scene/scene.hpp"
#include "sim/water_state.hpp"

namespace tp::render {

struct FrameRequest {
  uint32_t frame = 0;
  bool hdr = true;    // read back the linear RGBA image
  bool ldr = false;   // read back the tonemapped sRGB preview
  bool aovs = false;  // read back world normal, world position and view depth (needs RendererOptions::aovs)
  bool ao = false;    // read back the AO and the G-buffer it came from (needs a scene with AO on)
};

struct RendererOptions {
  bool aovs = false;  // make the targets and the pass for arbitrary output variables
  // Leave out what a frame does not need: the G-buffer without AO, the camera
  // medium with the camera away from the water, passes whose inputs have not
  // changed (sky, caustics, camera medium), the simulation of water that has
  // come to rest (WaterSleep), objects outside the view. Off, every frame
  // records all of it: the frame to compare against.
  bool skipping = true;
};

struct RenderedFrame {
  uint32_t width = 0;
  uint32_t height = 0;
  std::vector<float> rgba;        // linear, scene-referred RGBA; rows top to bottom
  std::vector<std::uint8_t> srgb; // RGBA8 sRGB preview, when requested
  std::vector<float> normal;      // xyz0 world normal per pixel, when AOVs are requested (0 where nothing is hit)
  std::vector<float> position;    // xyz world position and w view depth Z (infinite where nothing is hit)
  // With FrameRequest::ao: the AO (frame size, after blur and upsample), the
  // unblurred SSAO at the AO resolution (aoWidth x aoHeight), and the opaque
  // surfaces' G-buffer it was computed from: the depth buffer's values (1 where
  // no surface) and xyz0 view-space normals.
  std::vector<float> ao, aoRaw, gbufferDepth, gbufferNormal;
  uint32_t aoWidth = 0, aoHeight = 0;
  std::vector<RecordedPass> passes;
  gpu::CommandCounts counts;  // the whole frame's: the sum over `passes`
  bool waterAsleep = false;   // the water was drawn as it was, not simulated
  double waterEnergy = 0.0;   // per unit area, after the last simulated frame (WaterSleep's measure)
  glm::mat4 worldToCamera{1.0f};
  glm::mat4 worldToNDC{1.0f};
  glm::mat4 inverseProjection{1.0f};
};

// Renders a scene offscreen at a fixed size. The frame graph is declared once;
// each render() records only the passes its request needs.
class Renderer {
 public:
  Renderer(const gpu::Context& ctx, const scene::Scene& scene, uint32_t width, uint32_t height,
           const RendererOptions& options = {});
  // A renderer that goes on where `previous` is (shader hot reload: its
  // pipelines are made from the code gpu::spirvModule now gives): the same
  // size and options, the scene as it now stands, the water's state, clock,
  // sleep and pending drops and sphere moves. The next frame draws what
  // `previous` would have drawn, given the same shader code.
  explicit Renderer(const Renderer& previous);
  // A renderer for a changed scene that goes on with `previous`'s water as
  // Renderer(previous) does. The water must be the same but for its ior and
  // absorption (throws std::invalid_argument otherwise).
  Renderer(const Renderer& previous, const scene::Scene& scene);
  ~Renderer();
  RenderedFrame render(const FrameRequest& request);
  // A drop into the water before the next frame's simulation (it wakes sleeping water).
  void addDrop(const scene::Drop& drop);

  // The live part of the scene, for the viewer. The scene as it now stands.
  const scene::Scene& scene() const { return scene_; }
  const gpu::Context& context() const { return ctx_; }
  uint32_t width() const { return width_; }
  uint32_t height() const { return height_; }
  // Takes effect at the next render(); throws on an impossible camera.
  void setCamera(const scene::Camera& camera);
  // Moves sphere `index` to `center` before the next frame's simulation: its
  // path is dropped, it stays there, and the water it pushes in or out is
  // displaced (as a moving sphere's), waking sleeping water. Throws
  // std::out_of_range for a bad index.
  void moveSphere(size_t index, glm::vec3 center);
  // New wave speed, damping, boundary or max slope from the next frame on:
  // the water goes on from its state (waking if asleep), the substeps follow
  // the wave speed. Any other field of `water` must be the scene's (throws
  // std::invalid_argument: those need a new renderer). Going back to an
  // earlier frame restarts the water with the new parameters.
  void setWaterDynamics(const scene::Water& water);
  // The water's state now, downloaded. Throws without water.
  sim::WaterState waterState() const;

 private:
  struct Resources;
  const gpu::Context& ctx_;
  scene::Scene scene_;
  uint32_t width_, height_;
  RendererOptions options_;
  std::unique_ptr<Resources> res_;
};

}  // namespace tp::render
