#pragma once
// The fixture of every GPU test: a Vulkan context on lavapipe (ctest forces
// the ICD) with the validation layer and synchronization validation on. A test
// fails on any warning or error the layer reports.
#include <gtest/gtest.h>

#include <memory>

#include "gpu/context.hpp"

namespace tp::test {

class GpuTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { context_ = std::make_unique<gpu::Context>(gpu::ContextOptions{.validation = true}); }
  static void TearDownTestSuite() { context_.reset(); }
  void SetUp() override { ctx().validationLog().clear(); }
  void TearDown() override {
    ctx().device().waitIdle();
    auto& log = ctx().validationLog();
    EXPECT_EQ(log.total(), 0) << "validation messages:\n" << joined(log.messages());
  }
  static gpu::Context& ctx() { return *context_; }

  static std::string joined(const std::vector<std::string>& lines) {
    std::string s;
    for (const auto& l : lines) s += l + "\n";
    return s;
  }

 private:
  static inline std::unique_ptr<gpu::Context> context_;
};

}  // namespace tp::test
