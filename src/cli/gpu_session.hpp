#pragma once
#include <CLI/CLI.hpp>
#include <string>

#include "gpu/context.hpp"

namespace tp::app {

// The --validate and --device options every command that uses the GPU takes.
void addGpuOptions(CLI::App* command, bool& validate, std::string& device);

// The Vulkan context of one command, with the CLI's reporting of validation
// messages: echoed as they come, counted at the end.
class GpuSession {
 public:
  GpuSession(bool validate, const std::string& device);
  // With the rest of the context's options too (a window's extensions).
  explicit GpuSession(const gpu::ContextOptions& options);
  gpu::Context& context() { return context_; }
  // Prints the validation count (when validating) and returns the exit code:
  // 0, or 3 when the validation layer said anything.
  int finish();

 private:
  gpu::Context context_;
};

}  // namespace tp::app
