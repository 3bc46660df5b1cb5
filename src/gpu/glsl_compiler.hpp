#pragma once
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace tp::gpu {

struct GlslCompile {
  std::vector<std::uint32_t> spirv;  // empty when it failed
  std::string errors;                // glslang's log when it failed, one line or more naming file and line
  bool ok() const { return errors.empty(); }
};

// Compiles a GLSL file at run time as the build compiles it (cmake/shaders.cmake:
// glslangValidator --target-env vulkan1.3 -I<includeDir> [-D<define>]): the
// stage from the extension (.comp, .vert, .frag), includes from the including
// file's folder then `includeDir`, `define` (if any; several joined by '+')
// each defined as 1. The same
// source gives the build's SPIR-V to the bit. For shader hot reload.
GlslCompile compileGlsl(const std::filesystem::path& source, const std::filesystem::path& includeDir,
                        const std::string& define = {});

}  // namespace tp::gpu
