#include <gtest/gtest.h>

#include "gpu/spirv_library.hpp"
#include "gpu/spirv_reflect.hpp"

namespace tp::test {

TEST(SpirvReflect, ComputeBindingsPushConstantsAndLocalSize) {
  auto r = gpu::reflectSpirv(gpu::spirvModule("test_saxpy.comp.spv"));
  EXPECT_EQ(r.stage, vk::ShaderStageFlagBits::eCompute);
  ASSERT_EQ(r.bindings.size(), 2u);
  EXPECT_EQ(r.bindings[0].binding, 0u);
  EXPECT_EQ(r.bindings[0].type, vk::DescriptorType::eStorageBuffer);
  EXPECT_EQ(r.bindings[1].binding, 1u);
  EXPECT_TRUE(r.pushConstants);
  EXPECT_EQ(r.localSize[0], 64u);
  EXPECT_EQ(r.localSize[1], 1u);
}

TEST(SpirvReflect, ImagesSamplersAndUniforms) {
  auto resolve = gpu::reflectSpirv(gpu::spirvModule("resolve.comp.spv"));
  ASSERT_EQ(resolve.bindings.size(), 6u);
  EXPECT_EQ(resolve.bindings[0].type, vk::DescriptorType::eStorageImage);
  EXPECT_EQ(resolve.bindings[1].type, vk::DescriptorType::eStorageImage);
  EXPECT_EQ(resolve.bindings[2].type, vk::DescriptorType::eUniformBuffer);
  EXPECT_EQ(resolve.bindings[3].type, vk::DescriptorType::eCombinedImageSampler);
  EXPECT_EQ(resolve.bindings[4].type, vk::DescriptorType::eCombinedImageSampler);
  EXPECT_EQ(resolve.bindings[5].type, vk::DescriptorType::eUniformBuffer);
  EXPECT_TRUE(resolve.pushConstants);
  EXPECT_EQ(resolve.localSize[0], 8u);
  EXPECT_EQ(resolve.localSize[1], 8u);

  auto background = gpu::reflectSpirv(gpu::spirvModule("sky_background.frag.spv"));
  EXPECT_EQ(background.stage, vk::ShaderStageFlagBits::eFragment);
  ASSERT_EQ(background.bindings.size(), 2u);
  EXPECT_EQ(background.bindings[0].type, vk::DescriptorType::eUniformBuffer);
  EXPECT_EQ(background.bindings[1].type, vk::DescriptorType::eCombinedImageSampler);
  EXPECT_FALSE(background.pushConstants);
}

TEST(SpirvReflect, RejectsWhatIsNotSpirv) {
  std::vector<uint32_t> junk{1, 2, 3, 4, 5, 6};
  EXPECT_THROW(gpu::reflectSpirv(junk), std::runtime_error);
  auto code = gpu::spirvModule("resolve.comp.spv");
  std::vector<uint32_t> truncated(code.begin(), code.end());
  truncated.push_back(0xffff0000u | 71u);  // a last instruction claiming more words than remain
  EXPECT_THROW(gpu::reflectSpirv(truncated), std::runtime_error);
  std::vector<uint32_t> headerOnly(code.begin(), code.begin() + 5);
  EXPECT_THROW(gpu::reflectSpirv(headerOnly), std::runtime_error);  // no entry point
  EXPECT_THROW(gpu::spirvModule("no_such.comp.spv"), std::runtime_error);
}

}  // namespace tp::test
