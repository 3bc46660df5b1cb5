// Stale SPIR-V never ships: every module committed under spirv/ must equal,
// byte for byte, a fresh glslang compile of shaders_glsl/ (the build's
// spirv/ directory), and every shader must have its committed module.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>

namespace fs = std::filesystem;

namespace {

std::set<std::string> spvNames(const fs::path& dir) {
  std::set<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) {
    if (e.path().extension() == ".spv") names.insert(e.path().filename().string());
  }
  return names;
}

std::string bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

}  // namespace

TEST(SpirvFresh, CommittedModulesMatchAFreshCompile) {
  const fs::path fresh = TIDEPOOL_FRESH_SPIRV_DIR, committed = TIDEPOOL_COMMITTED_SPIRV_DIR;
  auto freshNames = spvNames(fresh);
  auto committedNames = spvNames(committed);
  ASSERT_FALSE(freshNames.empty());
  for (const auto& name : freshNames) {
    EXPECT_TRUE(committedNames.count(name))
        << "spirv/" << name << " is missing; run: cmake --build build --target update_spirv";
    if (committedNames.count(name)) {
      EXPECT_EQ(bytes(fresh / name), bytes(committed / name))
          << "spirv/" << name << " is stale; run: cmake --build build --target update_spirv";
    }
  }
  for (const auto& name : committedNames) {
    EXPECT_TRUE(freshNames.count(name)) << "spirv/" << name << " has no source in shaders_glsl/; remove it";
  }
}

TEST(SpirvFresh, EveryShaderSourceIsCompiled) {
  const fs::path sources = fs::path(TIDEPOOL_SOURCE_DIR) / "shaders_glsl";
  auto freshNames = spvNames(TIDEPOOL_FRESH_SPIRV_DIR);
  int shaders = 0;
  for (const auto& e : fs::directory_iterator(sources)) {
    auto ext = e.path().extension();
    if (ext != ".comp" && ext != ".vert" && ext != ".frag") continue;
    ++shaders;
    EXPECT_TRUE(freshNames.count(e.path().filename().string() + ".spv")) << e.path();
  }
  EXPECT_GT(shaders, 0);
}
