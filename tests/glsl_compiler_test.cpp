// The run-time GLSL compiler (shader hot reload) against the build's own
// compiler: every embedded module, compiled again from its source by the
// library, is the same SPIR-V to the bit. Broken shaders give their errors.
#include <gtest/gtest.h>

#include "gpu/glsl_compiler.hpp"
#include "gpu/spirv_library.hpp"
#include "process.hpp"

namespace tp::test {
namespace {

const std::filesystem::path kShaders = std::filesystem::path(TIDEPOOL_SOURCE_DIR) / "shaders_glsl";

}  // namespace

TEST(GlslCompiler, EveryEmbeddedModuleRecompilesToTheBuildsBits) {
  size_t variants = 0;
  for (const gpu::EmbeddedSpirv& module : gpu::embeddedSpirvModules()) {
    SCOPED_TRACE(std::string(module.name));
    const gpu::GlslCompile c = gpu::compileGlsl(kShaders / module.source, kShaders, std::string(module.define));
    ASSERT_TRUE(c.ok()) << c.errors;
    EXPECT_TRUE(std::equal(c.spirv.begin(), c.spirv.end(), module.code.begin(), module.code.end()));
    variants += !module.define.empty();
  }
  EXPECT_GE(gpu::embeddedSpirvModules().size(), 30u);
  // cmake/shaders.cmake: five surfaces colour-only, without shadows and both;
  // four of them scattering, in those four ways; four water shaders (three
  // forward, one deferred) and the glass without shadows, scattering and
  // both; the water shaders with glass in those four ways; the glass's box
  // variant in those four ways; the deferred
  // water and the side from below clearing the ambient part, in the four
  // ways without glass; the resolve with AO, full and half resolution, and
  // the three over listed tiles; the AO's apply that upsamples; the floor's
  // depth and the sky's background colour-only.
  EXPECT_EQ(variants, 5u * 3u + 4u * 4u + 5u * 3u + 4u * 4u + 4u + 2u * 4u + 2u + 3u + 1u + 1u + 1u);
}

TEST(GlslCompiler, BrokenShadersReportWhereAndWhy) {
  ScratchDir dir;
  const std::string broken = dir.file("broken.comp");
  writeText(broken, "#version 450\nlayout(local_size_x = 1) in;\nvoid main() { undeclared = 1.0; }\n");
  gpu::GlslCompile c = gpu::compileGlsl(broken, kShaders);
  EXPECT_FALSE(c.ok());
  EXPECT_TRUE(c.spirv.empty());
  EXPECT_NE(c.errors.find(broken + ":3"), std::string::npos) << c.errors;
  EXPECT_NE(c.errors.find("undeclared"), std::string::npos) << c.errors;

  const std::string missing = dir.file("missing.frag");
  writeText(missing,
            "#version 450\n#extension GL_GOOGLE_include_directive : require\n#include \"lib/nothing.glsl\"\n"
            "void main() {}\n");
  c = gpu::compileGlsl(missing, kShaders);
  EXPECT_FALSE(c.ok());
  EXPECT_NE(c.errors.find("lib/nothing.glsl"), std::string::npos) << c.errors;

  c = gpu::compileGlsl(dir.file("absent.comp"), kShaders);
  EXPECT_EQ(c.errors, "cannot read " + dir.file("absent.comp"));
  c = gpu::compileGlsl(kShaders / "lib" / "gbuffer.glsl", kShaders);
  EXPECT_NE(c.errors.find("not a .comp, .vert or .frag shader"), std::string::npos);

  // Includes resolve from the including file's folder first, then the include folder.
  const std::string local = dir.file("local.comp");
  writeText(dir.file("here.glsl"), "const float kHere = 2.0;\n");
  writeText(local,
            "#version 450\n#extension GL_GOOGLE_include_directive : require\n#include \"here.glsl\"\n"
            "#include \"shared/water.h\"\nlayout(local_size_x = 1) in;\nvoid main() {}\n");
  c = gpu::compileGlsl(local, kShaders);
  EXPECT_TRUE(c.ok()) << c.errors;
  EXPECT_FALSE(c.spirv.empty());
}

}  // namespace tp::test
