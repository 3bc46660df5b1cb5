#include "cli/profile_table.hpp"

#include <cmath>
#include <cstdio>

namespace tp::app {

void printProfile(const render::RenderedFrame& frame) {
  std::printf("%-20s %10s %10s %6s %11s\n", "pass", "GPU ms", "dispatches", "draws", "workgroups");
  double total = 0.0;
  auto row = [](const char* name, const char* ms, const gpu::CommandCounts& c) {
    std::printf("%-20s %10s %10llu %6llu %11llu\n", name, ms, static_cast<unsigned long long>(c.dispatches),
                static_cast<unsigned long long>(c.draws), static_cast<unsigned long long>(c.workgroups));
  };
  for (const auto& pass : frame.passes) {
    char ms[32] = "n/a";
    if (!std::isnan(pass.milliseconds)) {
      std::snprintf(ms, sizeof ms, "%.3f", pass.milliseconds);
      total += pass.milliseconds;
    }
    row(pass.name.c_str(), ms, pass.counts);
  }
  char ms[32];
  std::snprintf(ms, sizeof ms, "%.3f", total);
  char name[40];
  std::snprintf(name, sizeof name, "total (%zu passes)", frame.passes.size());
  row(name, ms, frame.counts);
}

}  // namespace tp::app
