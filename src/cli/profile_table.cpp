#include "cli/profile_table.hpp"

#include <cmath>
#include <cstdio>

namespace tp::app {
namespace {

// A number of milliseconds, or n/a; adds it to `total`.
std::string milliseconds(double ms, double& total) {
  if (std::isnan(ms)) return "n/a";
  total += ms;
  char text[32];
  std::snprintf(text, sizeof text, "%.3f", ms);
  return text;
}

}  // namespace

void printProfile(const render::RenderedFrame& frame) {
  std::printf("%-20s %10s %10s %10s %6s %11s\n", "pass", "wall ms", "GPU ms", "dispatches", "draws", "workgroups");
  double wallTotal = 0.0, gpuTotal = 0.0;
  auto row = [](const std::string& name, const std::string& wall, const std::string& gpu, const gpu::CommandCounts& c) {
    std::printf("%-20s %10s %10s %10llu %6llu %11llu\n", name.c_str(), wall.c_str(), gpu.c_str(),
                static_cast<unsigned long long>(c.dispatches), static_cast<unsigned long long>(c.draws),
                static_cast<unsigned long long>(c.workgroups));
  };
  for (const auto& pass : frame.passes) {
    const std::string wall = milliseconds(pass.wallMilliseconds, wallTotal);
    row(pass.name, wall, milliseconds(pass.milliseconds, gpuTotal), pass.counts);
  }
  double unused = 0.0;
  row("total (" + std::to_string(frame.passes.size()) + " passes)", milliseconds(wallTotal, unused),
      milliseconds(gpuTotal, unused), frame.counts);
}

}  // namespace tp::app
