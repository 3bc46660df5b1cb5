// Shader hot reload: a renderer made again from a running one goes on to the
// bit; reloaded shader code reaches its pipelines (checked against the same
// change made through the scene instead); a broken shader keeps the old code.
#include <gtest/gtest.h>

#include <filesystem>

#include "gpu/spirv_library.hpp"
#include "gpu_test.hpp"
#include "process.hpp"
#include "render/renderer.hpp"

namespace tp::test {
namespace {

constexpr uint32_t kWidth = 96, kHeight = 64;

// Leaves the process with the embedded shaders, whatever the test did.
struct ReloadGuard {
  ~ReloadGuard() { gpu::forgetReloadedShaders(); }
};

}  // namespace

using ShaderReloadTest = GpuTest;

TEST_F(ShaderReloadTest, RendererMadeAgainGoesOnWhereThePreviousWas) {
  scene::Scene s = scene::defaultScene();
  s.spheres[0].path = {{0.0f, {0.9f, 0.3f, -0.7f}}, {1.0f, {0.9f, -0.4f, -0.7f}}};
  render::Renderer first(ctx(), s, kWidth, kHeight);
  for (uint32_t frame = 0; frame <= 3; ++frame) first.render({.frame = frame});
  scene::Camera camera = s.camera;
  camera.position.x += 0.5f;
  first.setCamera(camera);
  first.addDrop({0.3f, -0.4f, 0.2f, 0.05f});
  render::Renderer again(render::GoOnFrom{first});
  for (uint32_t frame = 4; frame <= 6; ++frame) {
    SCOPED_TRACE("frame " + std::to_string(frame));
    const auto a = first.render({.frame = frame, .ldr = true});
    const auto b = again.render({.frame = frame, .ldr = true});
    EXPECT_TRUE(a.rgba == b.rgba);
    EXPECT_TRUE(a.srgb == b.srgb);
  }
  EXPECT_TRUE(first.waterState().u == again.waterState().u);
}

TEST_F(ShaderReloadTest, ReloadedShaderReachesThePipelinesAndABrokenOneKeepsTheOld) {
  ReloadGuard guard;
  ScratchDir dir;
  const std::filesystem::path shaders = dir.path() / "shaders_glsl";
  std::filesystem::copy(std::filesystem::path(TIDEPOOL_SOURCE_DIR) / "shaders_glsl", shaders,
                        std::filesystem::copy_options::recursive);
  const scene::Scene s = scene::defaultScene();
  render::Renderer renderer(ctx(), s, kWidth, kHeight);
  renderer.render({.frame = 1});
  // Made before the reload: its pipelines keep the built code.
  scene::Scene halfExposure = s;
  halfExposure.render.exposure *= 0.5f;
  render::Renderer halfExposureRenderer(ctx(), halfExposure, kWidth, kHeight);

  EXPECT_TRUE(gpu::reloadShaders(shaders).changed.empty()) << "the sources as built";

  // Half the exposure in the shader, against half the exposure in the scene.
  // The resolve pass's source builds six modules (cmake/shaders.cmake).
  const std::vector<std::string> modules{"resolve.ao.comp.spv",
                                         "resolve.ao.listed.comp.spv",
                                         "resolve.ao_upsample.comp.spv",
                                         "resolve.ao_upsample.listed.comp.spv",
                                         "resolve.comp.spv",
                                         "resolve.listed.comp.spv"};
  std::string resolve = readText((shaders / "resolve.comp").string());
  const std::string exposure = "params.look.y)";
  ASSERT_NE(resolve.find(exposure), std::string::npos);
  resolve.replace(resolve.find(exposure), exposure.size(), "0.5 * params.look.y)");
  writeText((shaders / "resolve.comp").string(), resolve);
  gpu::ShaderReload reload = gpu::reloadShaders(shaders);
  EXPECT_EQ(reload.changed, modules);
  EXPECT_TRUE(reload.errors.empty());
  render::Renderer reloaded(render::GoOnFrom{renderer});
  const auto darker = reloaded.render({.frame = 2, .ldr = true});
  const auto expected = halfExposureRenderer.render({.frame = 2, .ldr = true});
  EXPECT_TRUE(darker.srgb == expected.srgb);
  EXPECT_FALSE(darker.srgb == renderer.render({.frame = 2, .ldr = true}).srgb);

  // A broken shader: its errors, and the code it had (the halved exposure) stays.
  writeText((shaders / "resolve.comp").string(), "#version 450\nvoid main() { broken }\n");
  reload = gpu::reloadShaders(shaders);
  EXPECT_TRUE(reload.changed.empty());
  ASSERT_EQ(reload.errors.size(), modules.size());
  for (size_t k = 0; k < modules.size(); ++k) {
    EXPECT_EQ(reload.errors[k].rfind(modules[k] + ": ", 0), 0u) << reload.errors[k];
    EXPECT_NE(reload.errors[k].find("resolve.comp:2"), std::string::npos) << reload.errors[k];
  }
  render::Renderer kept(render::GoOnFrom{reloaded});
  EXPECT_TRUE(kept.render({.frame = 2, .ldr = true}).srgb == darker.srgb);
}

}  // namespace tp::test
