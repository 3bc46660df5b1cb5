#include "app/gpu_session.hpp"

#include <cstdio>

namespace tp::app {

GpuSession::GpuSession(bool validate, const std::string& device)
    : context_(gpu::ContextOptions{.validation = validate, .deviceName = device}) {
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
