#pragma once
#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

#include "gpu/descriptors.hpp"
#include "gpu/memory.hpp"
#include "gpu/pipeline.hpp"
#include "shared/sh9.h"

namespace tp::render {

// The environment sampler on the GPU: the CDFs built in compute from the
// sky texture's luminance (env_rows.comp, env_marginal.comp), and SH9
// coefficients estimated from them (env_sh.comp), for one environment size.
// The CPU counterparts (render/env_sampler, render/env_sh) are its reference.
class EnvPrefilter {
 public:
  EnvPrefilter(const gpu::Context& ctx, uint32_t width, uint32_t height, uint32_t maxSamples);

  // The CDFs of `environment` (width x height, in the shader-read layout),
  // ready for the compute shader stage when recorded.
  void recordCdf(const vk::raii::CommandBuffer& cmd, const gpu::Image& environment, vk::Sampler sampler);
  // The SH9 estimate from `samples` points of the Hammersley set rotated by
  // `rotation`, drawn by luminance (after recordCdf) or uniformly; sh() reads it.
  void recordSh(const vk::raii::CommandBuffer& cmd, const gpu::Image& environment, vk::Sampler sampler,
                uint32_t samples, glm::vec2 rotation, bool uniform);
  // After the submission: the coefficients (the partials added in double).
  shader::Sh9 sh() const;
  // The CDFs: per row, width + 1 entries; the marginal, height + 1, then the
  // luminance's integral.
  std::vector<float> conditional() const;
  std::vector<float> marginal() const;
  // The CDF buffers themselves, for passes that draw from them (glossy_prefilter.comp).
  const gpu::Buffer& conditionalBuffer() const { return conditional_; }
  const gpu::Buffer& marginalBuffer() const { return marginal_; }

 private:
  const gpu::Context& ctx_;
  uint32_t width_, height_, maxSamples_, samples_ = 0;
  gpu::Pipeline rows_, marginalPass_, shPass_;
  gpu::Buffer conditional_, rowWeights_, marginal_, partials_;
  gpu::DescriptorArena descriptors_;
};

}  // namespace tp::render
