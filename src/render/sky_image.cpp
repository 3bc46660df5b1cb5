#include "render/sky_image.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/packing.hpp>
#include <stdexcept>

#include "gpu/barriers.hpp"
#include "gpu/submit.hpp"
#include "io/image_io.hpp"
#include "shared/shading.h"
#include "shared/sky.h"

namespace tp::render {

SkyImage loadSkyImage(const std::string& path) {
  io::FloatImage image = io::readImage(path);
  const size_t channels = image.channels.size();
  if (channels < 3) throw std::runtime_error("sky image " + path + " needs R, G and B channels");
  SkyImage sky{image.width, image.height, std::vector<glm::vec4>(size_t(image.width) * image.height)};
  for (size_t k = 0; k < sky.texels.size(); ++k) {
    const float* p = &image.pixels[k * channels];
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2])) {
      throw std::runtime_error("sky image " + path + ": non-finite texel at " + std::to_string(k % sky.width) + "," +
                               std::to_string(k / sky.width));
    }
    sky.texels[k] = glm::vec4(p[0], p[1], p[2], 1.0f);
  }
  return sky;
}

SkyImage loadSkyImage(const scene::Sky& sky) {
  return placeSkyImage(loadSkyImage(sky.image), sky.rotationDegrees, sky.intensity);
}

SkyImage placeSkyImage(const SkyImage& image, float degrees, float intensity) {
  SkyImage placed{image.width, image.height, std::vector<glm::vec4>(image.texels.size())};
  // Texel i of the placed image shows what texel i - shift showed (u = azimuth / 2 pi + 1/2).
  const double shift = double(degrees) / 360.0 * image.width;
  const double whole = std::floor(shift);
  const float fraction = float(shift - whole);
  const int64_t w = image.width;
  for (uint32_t j = 0; j < image.height; ++j) {
    const glm::vec4* row = &image.texels[size_t(j) * w];
    for (int64_t i = 0; i < w; ++i) {
      const int64_t from = (((i - int64_t(whole)) % w) + w) % w;
      const glm::vec4 texel = glm::mix(row[from], row[(from - 1 + w) % w], fraction);
      placed.texels[size_t(j) * w + i] = glm::vec4(glm::vec3(texel) * intensity, 1.0f);
    }
  }
  return placed;
}

glm::vec3 skyRadianceWithout(const shader::SkyParams& procedural, const SkyImage* image, glm::vec3 d) {
  return image ? skyImageRadiance(*image, d) : shader::skyRadiance(procedural, d, 0.0f);
}

glm::vec3 skyImageRadiance(const SkyImage& image, glm::vec3 d) {
  const glm::vec2 uv = shader::directionToEquirect(d);
  const float x = uv.x * float(image.width) - 0.5f, y = uv.y * float(image.height) - 0.5f;
  const float x0 = std::floor(x), y0 = std::floor(y);
  const float fx = x - x0, fy = y - y0;
  auto texel = [&](int64_t i, int64_t j) {
    const int64_t w = image.width, h = image.height;
    i = ((i % w) + w) % w;
    j = std::clamp<int64_t>(j, 0, h - 1);
    return glm::vec3(image.texels[size_t(j * w + i)]);
  };
  const int64_t i = int64_t(x0), j = int64_t(y0);
  return glm::mix(glm::mix(texel(i, j), texel(i + 1, j), fx), glm::mix(texel(i, j + 1), texel(i + 1, j + 1), fx), fy);
}

SkyImage proceduralSkyImage(const scene::Sky& sky, uint32_t width) {
  const uint32_t height = width / 2;
  const shader::SkyParams params = skyParams(sky);
  SkyImage image{width, height, std::vector<glm::vec4>(size_t(width) * height)};
  for (uint32_t j = 0; j < height; ++j) {
    for (uint32_t i = 0; i < width; ++i) {
      const glm::vec3 d = shader::equirectToDirection({(i + 0.5f) / width, (j + 0.5f) / height});
      const glm::vec3 l = glm::min(shader::skyRadiance(params, d, 1.0f), glm::vec3(65504.0f));
      image.texels[size_t(j) * width + i] = glm::vec4(glm::unpackHalf4x16(glm::packHalf4x16(glm::vec4(l, 1.0f))));
    }
  }
  return image;
}

gpu::Image uploadSkyImage(const gpu::Context& ctx, const SkyImage& image, const char* name, uint32_t mipLevels) {
  // Half floats: linear filtering of them is required of every device.
  std::vector<uint16_t> halves(image.texels.size() * 4);
  for (size_t k = 0; k < image.texels.size(); ++k) {
    for (int c = 0; c < 4; ++c) halves[4 * k + c] = glm::packHalf1x16(std::min(image.texels[k][c], 65504.0f));
  }
  // Its other levels are written by a compute shader (render/sky_mips).
  const vk::ImageUsageFlags usage = vk::ImageUsageFlagBits::eSampled | vk::ImageUsageFlagBits::eTransferDst |
                                    (mipLevels > 1 ? vk::ImageUsageFlagBits::eStorage : vk::ImageUsageFlags{});
  gpu::Image texture =
      gpu::createImage2D(ctx, {image.width, image.height}, vk::Format::eR16G16B16A16Sfloat, usage, name, mipLevels);
  gpu::Buffer staging = gpu::createBuffer(ctx, halves.size() * sizeof(uint16_t), vk::BufferUsageFlagBits::eTransferSrc,
                                          gpu::MemoryUse::Upload, "sky image staging");
  std::memcpy(staging.mapped, halves.data(), halves.size() * sizeof(uint16_t));
  gpu::submitAndWait(
      ctx,
      [&](const vk::raii::CommandBuffer& cmd) {
        auto toTransfer =
            gpu::imageBarrier(texture.handle(), texture.aspect, gpu::access::none, vk::ImageLayout::eUndefined,
                              gpu::access::transferWrite, vk::ImageLayout::eTransferDstOptimal);
        gpu::pipelineBarrier(cmd, {}, std::span(&toTransfer, 1));
        cmd.copyBufferToImage(staging.handle(), texture.handle(), vk::ImageLayout::eTransferDstOptimal,
                              vk::BufferImageCopy{.imageSubresource = {texture.aspect, 0, 0, 1},
                                                  .imageExtent = {image.width, image.height, 1}});
        // Later submissions come later in submission order: this covers their reads.
        auto toShader = gpu::imageBarrier(
            texture.handle(), texture.aspect, gpu::access::transferWrite, vk::ImageLayout::eTransferDstOptimal,
            {vk::PipelineStageFlagBits2::eFragmentShader, vk::AccessFlagBits2::eShaderSampledRead},
            vk::ImageLayout::eShaderReadOnlyOptimal);
        gpu::pipelineBarrier(cmd, {}, std::span(&toShader, 1));
      },
      "sky image upload");
  return texture;
}

}  // namespace tp::render
