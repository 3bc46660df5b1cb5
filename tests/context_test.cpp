#include <gtest/gtest.h>

#include "gpu_test.hpp"

namespace tp::test {

using ContextTest = GpuTest;

TEST_F(ContextTest, RunsOnLavapipeWithValidation) {
  EXPECT_NE(ctx().deviceName().find("llvmpipe"), std::string::npos) << ctx().deviceName();
  EXPECT_TRUE(ctx().validationEnabled());
  EXPECT_GE(ctx().properties().apiVersion, VK_API_VERSION_1_3);
  EXPECT_EQ(ctx().validationLog().total(), 0);
}

TEST(ContextSelection, UnknownDeviceNameNamesTheDevices) {
  try {
    gpu::Context c(gpu::ContextOptions{.validation = false, .deviceName = "no-such-gpu"});
    FAIL() << "a device named no-such-gpu was found";
  } catch (const std::runtime_error& e) {
    std::string m = e.what();
    EXPECT_NE(m.find("no-such-gpu"), std::string::npos) << m;
    EXPECT_NE(m.find("llvmpipe"), std::string::npos) << m;
  }
}

TEST(ContextSelection, PicksByNameSubstring) {
  gpu::Context c(gpu::ContextOptions{.validation = false, .deviceName = "llvmpipe"});
  EXPECT_NE(c.deviceName().find("llvmpipe"), std::string::npos);
}

}  // namespace tp::test
