#pragma once
#include <cstdint>
#include <glm/glm.hpp>
#include <memory>
#include <vector>

#include "gpu/context.hpp"
#include "graph/frame_graph.hpp"
#include "render/pass_kinds.hpp"  // what a frame's passes are found by
#include "scene/scene.hpp"
#include "sim/water_driver.hpp"
#include "sim/water_state.hpp"

namespace tp::render {

struct FrameRequest {
  uint32_t frame = 0;
  bool hdr = true;    // read back the linear RGBA image
  bool ldr = false;   // read back the tonemapped sRGB preview
  bool aovs = false;  // read back world normal, world position and view depth (needs RendererOptions::aovs)
  bool ao = false;    // read back the AO and the G-buffer it came from (needs a scene with AO on)
  // Submit each pass on its own and wait for it, timing it by wall clock
  // (RecordedPass::wallMilliseconds): lavapipe's timestamps miss the
  // rasterization it defers to the end of a render pass.
  bool passWallTimes = false;
  // Leave the tonemapped sRGB image on the GPU for the caller to show
  // (Renderer::presentable), with no readback.
  bool present = false;
  // Where each pixel samples the image, in pixels from its centre (x right,
  // y down): one jittered sample of an anti-aliased frame (cli/frame_samples).
  // The frame's matrices (RenderedFrame::worldToNDC...) stay the centre's.
  glm::vec2 pixelOffset{0.0f};
  // The width in pixels textures are filtered over: 1/sqrt(N) for one of N
  // jittered samples, each sample's share of the pixel.
  float filterWidth = 1.0f;
};

// The tonemapped image of the last frame rendered with FrameRequest::present,
// and the layout it is in. Whoever reads it does so on the context's queue,
// after that frame, puts it back in that layout, and makes its own reads and
// that transition finish before the compute and transfer work that follows.
struct PresentableImage {
  const gpu::Image* image = nullptr;
  vk::ImageLayout layout = vk::ImageLayout::eUndefined;
};

struct RendererOptions {
  bool aovs = false;  // make the targets and the pass for arbitrary output variables
  // Leave out what a frame does not need: the G-buffer without AO, the camera
  // medium with the camera away from the water, passes whose inputs have not
  // changed (sky, caustics, camera medium), the SSAO while the opaque
  // surfaces stand still (render/opaque_geometry.hpp), the simulation of
  // water that has come to rest (sim::WaterSleep), objects outside the view.
  // Off, every frame records all of it: the frame to compare against.
  bool skipping = true;
  // Draw the water's and the pool floor's grids coarser where a quad of
  // them would span a fraction of a pixel (shading/grid_detail.hpp); off,
  // always whole: the frame the coarser grids' error is measured against.
  bool coarseGrids = true;
};

struct RenderedFrame {
  uint32_t width = 0;
  uint32_t height = 0;
  std::vector<float> rgba;         // linear, scene-referred RGBA; rows top to bottom
  std::vector<std::uint8_t> srgb;  // RGBA8 sRGB preview, when requested
  std::vector<float> normal;       // xyz0 world normal per pixel, when AOVs are requested (0 where nothing is hit)
  std::vector<float> position;     // xyz world position and w view depth Z (infinite where nothing is hit)
  // With FrameRequest::ao: the AO (frame size, after blur and upsample), the
  // unblurred SSAO at the AO resolution (aoWidth x aoHeight), and the opaque
  // surfaces' G-buffer it was computed from: the depth buffer's values (1 where
  // no surface) and xyz0 view-space normals.
  std::vector<float> ao, aoRaw, gbufferDepth, gbufferNormal;
  uint32_t aoWidth = 0, aoHeight = 0;
  std::vector<RecordedPass> passes;
  gpu::CommandCounts counts;  // the whole frame's: the sum over `passes`
  bool waterAsleep = false;   // the water was drawn as it was, not simulated
  // The tiles the resolve pass worked on, of the frame's, where it works on
  // listed tiles (render/frame_resolve.hpp); 0 of 0 where it works on the
  // whole frame, or did not run.
  uint32_t resolvedTiles = 0, frameTiles = 0;
  double waterEnergy = 0.0;  // per unit area, after the last simulated frame (sim::WaterSleep's measure)
  glm::mat4 worldToCamera{1.0f};
  glm::mat4 worldToNDC{1.0f};
  glm::mat4 inverseProjection{1.0f};
  // With several samples and a transparent sky (cli/frame_samples): RGBA
  // premultiplied by the share of the pixel's samples that hit something, for
  // compositing over a plate; empty otherwise.
  std::vector<float> foreground;
};

// Renders a scene offscreen at a fixed size. The frame graph is declared once;
// each render() records only the passes its request needs.
//
// Frame N shows the water after N frames of simulation, the scene's later
// drops (scene::Drop::frame >= 1) each applied once on its frame, whatever was
// rendered before: going back to an earlier frame restarts the water and
// replays them. Drops made live (addDrop) are recorded in the scene, so a new
// renderer of scene() renders the same frames to the bit, with one exception:
// a drop made while paused at frame f (frame f rendered again) shows in the
// live frame f at once, but in the recorded scene from frame f+1.
class Renderer;

// Names the renderer a new one goes on from (Renderer(GoOnFrom, ...)).
struct GoOnFrom {
  const Renderer& previous;
};

class Renderer {
 public:
  Renderer(const gpu::Context& ctx, const scene::Scene& scene, uint32_t width, uint32_t height,
           const RendererOptions& options = {});
  // A renderer of `scene`, a changed scene (refraction, caustics, AO, sky,
  // ground, pool, terrain, objects, exposure, camera, the water's ior and
  // absorption...), that goes on where `from.previous` is, its pipelines made
  // from the code gpu::spirvModule now gives (shader hot reload): the same
  // size and options, and the water's state, clock, sleep, applied drops and
  // pending drops and sphere moves. The next frame draws what a renderer of
  // `scene` would draw having been where the previous one is. `scene.water`
  // must be the previous scene's water in every field but ior and absorption
  // (which only shade it); otherwise throws std::invalid_argument: other
  // water needs a new renderer (the water restarts).
  Renderer(GoOnFrom from, const scene::Scene& scene);
  // The same, with the scene as the previous renderer now has it.
  explicit Renderer(GoOnFrom from);
  // The same at another size (the viewer's dynamic resolution).
  Renderer(GoOnFrom from, uint32_t width, uint32_t height);
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;
  // Waits for the device: work on its queue (a viewer's blit of its image)
  // may still read its images.
  ~Renderer();
  RenderedFrame render(const FrameRequest& request);
  // A drop into the water (it wakes sleeping water), applied at the start of
  // the next render's simulation: at once when that render is of the same
  // frame (paused), else before its steps. It is recorded in the scene with
  // the frame after the one the water has reached (listed before the
  // scene's drops of that frame still to come, which come after it). Throws
  // on an impossible drop, or without water.
  void addDrop(const scene::Drop& drop);

  // The live part of the scene, for the viewer. The scene as it now stands,
  // with every drop made live.
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
  // New wave speed, damping, grid damping, boundary, max slope or sphere
  // forcing from the next frame on:
  // the water goes on from its state (waking if asleep), the substeps follow
  // the wave speed. Any other field of `water` must be the scene's (throws
  // std::invalid_argument: those need a new renderer). Going back to an
  // earlier frame restarts the water with the new parameters.
  void setWaterDynamics(const scene::Water& water);
  PresentableImage presentable() const;
  // The water's state now, downloaded. Throws without water.
  sim::WaterState waterState() const;
  // The checkpoint of the water as it stands. Throws without water, and
  // after setWaterDynamics (a scene file cannot say when the change came).
  sim::WaterCheckpoint checkpoint() const;
  // Puts the water where the checkpoint says, as if this renderer had
  // rendered up to its frame: the drops up to it count as applied, pending
  // drops and moves are dropped. The scene must be the one the checkpoint
  // was taken from (the caller's to check). Throws without water or on a
  // state of another grid size.
  void resume(const sim::WaterCheckpoint& checkpoint);

 private:
  struct Resources;
  // What the two public ways of going on from a renderer come to.
  Renderer(GoOnFrom from, const scene::Scene& scene, uint32_t width, uint32_t height);
  const gpu::Context& ctx_;
  scene::Scene scene_;
  uint32_t width_, height_;
  RendererOptions options_;
  std::unique_ptr<Resources> res_;
};

}  // namespace tp::render
