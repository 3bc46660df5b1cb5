#include "cli/gpu_session.hpp"

#include <cstdio>

namespace tp::app {

void addGpuOptions(CLI::App* command, bool& validate, std::string& device) {
  command->add_flag("--validate", validate,
                    "Enable the Khronos validation layer with synchronization validation; exit 3 on any message");
  command->add_option("--device", device, "Use the Vulkan device whose name contains NAME (also $TIDEPOOL_DEVICE)")
      ->type_name("NAME");
}

GpuSession::GpuSession(bool validate, const std::string& device)
    : GpuSession(gpu::ContextOptions{.validation = validate, .deviceName = device}) {}

GpuSession::GpuSession(const gpu::ContextOptions& options) : context_(options) {
  context_.validationLog().setEcho(true);
}

int GpuSession::finish() {
  context_.device().waitIdle();
  if (!context_.validationEnabled()) return 0;
  auto& log = context_.validationLog();
  std::fprintf(stderr, "validation: %d warnings, %d errors\n", log.warnings(), log.errors());
  return log.total() == 0 ? 0 : 3;
}

}  // namespace tp::app
