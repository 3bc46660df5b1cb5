#include "gpu/spirv_library.hpp"

#include <algorithm>
#include <map>
#include <stdexcept>

#include "gpu/glsl_compiler.hpp"

namespace tp::gpu {
namespace {

// Reloaded code by module name; what spirvModule() prefers.
std::map<std::string, std::vector<std::uint32_t>, std::less<>>& reloaded() {
  static std::map<std::string, std::vector<std::uint32_t>, std::less<>> modules;
  return modules;
}

}  // namespace

std::span<const std::uint32_t> spirvModule(std::string_view name) {
  if (auto it = reloaded().find(name); it != reloaded().end()) return it->second;
  for (const auto& module : embeddedSpirvModules()) {
    if (module.name == name) return module.code;
  }
  throw std::runtime_error("no SPIR-V module named '" + std::string(name) + "' is embedded");
}

ShaderReload reloadShaders(const std::filesystem::path& shaderDir) {
  ShaderReload report;
  for (const EmbeddedSpirv& module : embeddedSpirvModules()) {
    const GlslCompile c = compileGlsl(shaderDir / module.source, shaderDir, std::string(module.define));
    if (!c.ok()) {
      report.errors.push_back(std::string(module.name) + ": " + c.errors);
      continue;
    }
    const std::span<const std::uint32_t> current = spirvModule(module.name);
    if (std::equal(c.spirv.begin(), c.spirv.end(), current.begin(), current.end())) continue;
    reloaded()[std::string(module.name)] = c.spirv;
    report.changed.emplace_back(module.name);
  }
  return report;
}

void forgetReloadedShaders() { reloaded().clear(); }

}  // namespace tp::gpu
