#pragma once
// The screen-space ambient occlusion passes: SSAO from the opaque surfaces'
// depth and G-buffer, the separable blur, the depth-aware upsample (half
// resolution), and the AO put into the frame (shaders_glsl/ssao.comp,
// ao_blur.comp, ao_upsample.comp, ao_apply.comp).
#include "render/passes.hpp"
#include "scene/scene.hpp"

namespace tp::render {

// The AO images of a frame, at the AO resolution but for `full`.
struct AoImages {
  Target raw;              // the SSAO pass's output, unblurred
  Target blurX, blurred;   // the blur's two directions; no images with the blur off
  Target full;             // the AO upsampled to the frame; no image at full resolution
  // The AO at the AO resolution after the blur (or the raw AO without one).
  Target lowResult() const { return blurred.image ? blurred : raw; }
  // The frame-size AO the apply pass reads.
  Target result() const { return full.image ? full : lowResult(); }
};

struct SsaoPasses {
  explicit SsaoPasses(const gpu::Context& ctx);
  // `kernel`: the uniform buffer of render::ssaoKernel(ao). `depthSampler`:
  // nearest (the shaders fetch texels).
  void declare(FrameGraph& graph, const SurfaceTargets& surfaces, const AoImages& images,
               const gpu::Buffer& frameUniforms, const gpu::Buffer& kernel, vk::Sampler depthSampler,
               const scene::Ao& ao) const;
  gpu::Pipeline ssao, blur, upsample, apply;
};

}  // namespace tp::render
