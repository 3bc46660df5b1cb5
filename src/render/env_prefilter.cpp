#include "render/env_prefilter.hpp"

#include <stdexcept>

#include "gpu/barriers.hpp"
#include "gpu/transfer.hpp"
#include "shared/env_sampling.h"

namespace tp::render {

namespace {

constexpr auto kStorage = vk::BufferUsageFlagBits::eStorageBuffer | vk::BufferUsageFlagBits::eTransferSrc;

void computeToCompute(const vk::raii::CommandBuffer& cmd, std::initializer_list<vk::Buffer> written) {
  std::vector<vk::BufferMemoryBarrier2> barriers;
  for (vk::Buffer b : written) {
    barriers.push_back(
        gpu::bufferBarrier(b,
                           {vk::PipelineStageFlagBits2::eComputeShader,
                            vk::AccessFlagBits2::eShaderStorageRead | vk::AccessFlagBits2::eShaderStorageWrite},
                           gpu::access::computeRead));
  }
  gpu::pipelineBarrier(cmd, barriers);
}

// Before a pass writes buffers again: after the last frame's compute reads and
// writes of them, and a readback's copy.
void beforeRewrite(const vk::raii::CommandBuffer& cmd, std::initializer_list<vk::Buffer> written) {
  std::vector<vk::BufferMemoryBarrier2> barriers;
  for (vk::Buffer b : written) {
    barriers.push_back(
        gpu::bufferBarrier(b,
                           {vk::PipelineStageFlagBits2::eComputeShader | vk::PipelineStageFlagBits2::eCopy,
                            vk::AccessFlagBits2::eShaderStorageRead | vk::AccessFlagBits2::eShaderStorageWrite |
                                vk::AccessFlagBits2::eTransferRead},
                           {vk::PipelineStageFlagBits2::eComputeShader,
                            vk::AccessFlagBits2::eShaderStorageRead | vk::AccessFlagBits2::eShaderStorageWrite}));
  }
  gpu::pipelineBarrier(cmd, barriers);
}

}  // namespace

EnvPrefilter::EnvPrefilter(const gpu::Context& ctx, uint32_t width, uint32_t height, uint32_t maxSamples)
    : ctx_(ctx),
      width_(width),
      height_(height),
      maxSamples_(maxSamples),
      rows_(gpu::createComputePipeline(ctx, "env_rows.comp", sizeof(shader::EnvParams))),
      marginalPass_(gpu::createComputePipeline(ctx, "env_marginal.comp", sizeof(shader::EnvParams))),
      shPass_(gpu::createComputePipeline(ctx, "env_sh.comp", sizeof(shader::EnvParams))),
      conditional_(gpu::createBuffer(ctx, vk::DeviceSize(height) * (width + 1) * 4, kStorage, gpu::MemoryUse::Device,
                                     "environment conditional CDFs")),
      rowWeights_(gpu::createBuffer(ctx, vk::DeviceSize(height) * 4, kStorage, gpu::MemoryUse::Device,
                                    "environment row weights")),
      marginal_(gpu::createBuffer(ctx, vk::DeviceSize(height + 2) * 4, kStorage, gpu::MemoryUse::Device,
                                  "environment marginal CDF")),
      partials_(gpu::createBuffer(
          ctx, vk::DeviceSize((maxSamples + shPass_.localSize[0] - 1) / shPass_.localSize[0]) * 9 * 16, kStorage,
          gpu::MemoryUse::Device, "environment SH partials")),
      descriptors_(ctx) {}

void EnvPrefilter::recordCdf(const vk::raii::CommandBuffer& cmd, const gpu::Image& environment, vk::Sampler sampler) {
  if (environment.extent != vk::Extent2D{width_, height_})
    throw std::invalid_argument("environment size differs from the prefilter's");
  const shader::EnvParams params{glm::uvec4(width_, height_, 0, 0), glm::vec4(0.0f)};
  beforeRewrite(cmd, {conditional_.handle(), rowWeights_.handle(), marginal_.handle()});
  gpu::bindPipeline(cmd, rows_, params);
  gpu::DescriptorWrites()
      .sampledImage(0, environment, sampler)
      .storageBuffer(1, conditional_)
      .storageBuffer(2, rowWeights_)
      .bind(cmd, rows_, descriptors_);
  gpu::dispatchCovering(cmd, rows_, height_);
  computeToCompute(cmd, {rowWeights_.handle()});
  gpu::bindPipeline(cmd, marginalPass_, params);
  gpu::DescriptorWrites()
      .storageBuffer(0, rowWeights_)
      .storageBuffer(1, marginal_)
      .bind(cmd, marginalPass_, descriptors_);
  gpu::dispatchCovering(cmd, marginalPass_, 1);
  computeToCompute(cmd, {conditional_.handle(), marginal_.handle()});
}

void EnvPrefilter::recordSh(const vk::raii::CommandBuffer& cmd, const gpu::Image& environment, vk::Sampler sampler,
                            uint32_t samples, glm::vec2 rotation, bool uniform) {
  if (samples == 0 || samples > maxSamples_) {
    throw std::invalid_argument("environment SH samples must be 1 to " + std::to_string(maxSamples_));
  }
  samples_ = samples;
  const shader::EnvParams params{glm::uvec4(width_, height_, samples, uniform ? 1u : 0u),
                                 glm::vec4(rotation, 0.0f, 0.0f)};
  beforeRewrite(cmd, {partials_.handle()});
  gpu::bindPipeline(cmd, shPass_, params);
  gpu::DescriptorWrites()
      .sampledImage(0, environment, sampler)
      .storageBuffer(1, conditional_)
      .storageBuffer(2, marginal_)
      .storageBuffer(3, partials_)
      .bind(cmd, shPass_, descriptors_);
  gpu::dispatchCovering(cmd, shPass_, samples);
}

shader::Sh9 EnvPrefilter::sh() const {
  const auto partials = gpu::readBufferAs<glm::vec4>(ctx_, partials_, gpu::access::computeWrite);
  const uint32_t groups = (samples_ + shPass_.localSize[0] - 1) / shPass_.localSize[0];
  glm::dvec3 sum[9] = {};
  for (uint32_t g = 0; g < groups; ++g) {
    for (uint32_t i = 0; i < 9; ++i) sum[i] += glm::dvec3(glm::vec3(partials[g * 9 + i]));
  }
  shader::Sh9 out{};
  for (uint32_t i = 0; i < 9; ++i) out.c[i] = glm::vec4(glm::vec3(sum[i] / double(samples_)), 0.0f);
  return out;
}

std::vector<float> EnvPrefilter::conditional() const {
  return gpu::readBufferAs<float>(ctx_, conditional_, gpu::access::computeWrite);
}

std::vector<float> EnvPrefilter::marginal() const {
  return gpu::readBufferAs<float>(ctx_, marginal_, gpu::access::computeWrite);
}

}  // namespace tp::render
