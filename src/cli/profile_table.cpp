#include "cli/profile_table.hpp"

#include <cmath>
#include <cstdio>

namespace tp::app {
namespace {

// A number of milliseconds, or n/a.
std::string milliseconds(double ms) {
  if (std::isnan(ms)) return "n/a";
  char text[32];
  std::snprintf(text, sizeof text, "%.3f", ms);
  return text;
}

// The sum of one of the passes' times over the passes that have it.
double knownTotal(const std::vector<render::RecordedPass>& passes, double render::RecordedPass::*ms) {
  double total = 0.0;
  for (const auto& pass : passes) {
    if (!std::isnan(pass.*ms)) total += pass.*ms;
  }
  return total;
}

}  // namespace

void printProfile(const render::RenderedFrame& frame) {
  std::printf("%-20s %10s %10s %10s %6s %11s\n", "pass", "wall ms", "GPU ms", "dispatches", "draws", "workgroups");
  auto row = [](const std::string& name, const std::string& wall, const std::string& gpu, const gpu::CommandCounts& c) {
    std::printf("%-20s %10s %10s %10llu %6llu %11llu\n", name.c_str(), wall.c_str(), gpu.c_str(),
                static_cast<unsigned long long>(c.dispatches), static_cast<unsigned long long>(c.draws),
                static_cast<unsigned long long>(c.workgroups));
  };
  for (const auto& pass : frame.passes) {
    row(pass.name, milliseconds(pass.wallMilliseconds), milliseconds(pass.milliseconds), pass.counts);
  }
  row("total (" + std::to_string(frame.passes.size()) + " passes)",
      milliseconds(knownTotal(frame.passes, &render::RecordedPass::wallMilliseconds)),
      milliseconds(knownTotal(frame.passes, &render::RecordedPass::milliseconds)), frame.counts);
}

}  // namespace tp::app
