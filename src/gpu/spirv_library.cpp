#include "gpu/spirv_library.hpp"

#include <stdexcept>
#include <string>

namespace tp::gpu {

std::span<const std::uint32_t> spirvModule(std::string_view name) {
  for (const auto& module : embeddedSpirvModules()) {
    if (module.name == name) return module.code;
  }
  throw std::runtime_error("no SPIR-V module named '" + std::string(name) + "' is embedded");
}

}  // namespace tp::gpu
