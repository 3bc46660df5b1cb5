#include "gpu/glsl_compiler.hpp"

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>

#include <algorithm>
#include <mutex>
#include <optional>

#include "base/text_file.hpp"

namespace tp::gpu {
namespace {

namespace fs = std::filesystem;

// `#include "x"`: the including file's folder first, then the include folder
// (glslangValidator's -I); `#include <x>`: the include folder.
class Includer : public glslang::TShader::Includer {
 public:
  explicit Includer(fs::path includeDir) : includeDir_(std::move(includeDir)) {}

  IncludeResult* includeLocal(const char* header, const char* includer, size_t) override {
    if (IncludeResult* r = tryFrom(fs::path(includer).parent_path() / header)) return r;
    return includeSystem(header, includer, 0);
  }
  IncludeResult* includeSystem(const char* header, const char*, size_t) override {
    return tryFrom(includeDir_ / header);
  }
  void releaseInclude(IncludeResult* result) override {
    if (!result) return;
    delete static_cast<std::string*>(result->userData);
    delete result;
  }

 private:
  IncludeResult* tryFrom(const fs::path& path) {
    std::optional<std::string> text = base::readTextFile(path);
    if (!text) return nullptr;
    auto* owned = new std::string(std::move(*text));
    return new IncludeResult(path.string(), owned->data(), owned->size(), owned);
  }
  fs::path includeDir_;
};

std::optional<EShLanguage> stageOf(const fs::path& source) {
  const std::string ext = source.extension().string();
  if (ext == ".comp") return EShLangCompute;
  if (ext == ".vert") return EShLangVertex;
  if (ext == ".frag") return EShLangFragment;
  return std::nullopt;
}

}  // namespace

GlslCompile compileGlsl(const fs::path& source, const fs::path& includeDir, const std::string& define) {
  static std::once_flag initialised;  // glslang's process state; never finalised, as the process ends
  std::call_once(initialised, [] { glslang::InitializeProcess(); });
  const std::optional<EShLanguage> stage = stageOf(source);
  if (!stage) return {{}, source.string() + ": not a .comp, .vert or .frag shader"};
  const std::optional<std::string> text = base::readTextFile(source);
  if (!text) return {{}, "cannot read " + source.string()};

  glslang::TShader shader(*stage);
  const char* strings[] = {text->c_str()};
  const std::string name = source.string();
  const char* names[] = {name.c_str()};
  shader.setStringsWithLengthsAndNames(strings, nullptr, names, 1);
  // `define` may name several macros, joined by '+' (cmake/shaders.cmake's variants).
  std::string preamble;
  for (size_t from = 0; from < define.size();) {
    const size_t plus = std::min(define.find('+', from), define.size());
    preamble += "#define " + define.substr(from, plus - from) + " 1\n";
    from = plus + 1;
  }
  shader.setPreamble(preamble.c_str());
  // Vulkan 1.3 and SPIR-V 1.6: glslangValidator's --target-env vulkan1.3.
  shader.setEnvInput(glslang::EShSourceGlsl, *stage, glslang::EShClientVulkan, 100);
  shader.setEnvClient(glslang::EShClientVulkan, glslang::EShTargetVulkan_1_3);
  shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_6);
  const auto messages = EShMessages(EShMsgSpvRules | EShMsgVulkanRules);
  Includer includer(includeDir);
  if (!shader.parse(GetDefaultResources(), 100, false, messages, includer)) {
    return {{}, shader.getInfoLog()};
  }
  glslang::TProgram program;
  program.addShader(&shader);
  if (!program.link(messages)) return {{}, program.getInfoLog()};
  GlslCompile out;
  glslang::SpvOptions options;
  spv::SpvBuildLogger logger;
  glslang::GlslangToSpv(*program.getIntermediate(*stage), out.spirv, &logger, &options);
  if (const std::string log = logger.getAllMessages(); log.find("error") != std::string::npos) {
    return {{}, name + ": " + log};
  }
  return out;
}

}  // namespace tp::gpu
