#include "app/bench_output.hpp"

#include <cstdio>

#include "io/atomic_file.hpp"

namespace tp::app {

void checkBenchOutputs(const std::string& csv, const std::string& plot) {
  io::requireExtension(csv, ".csv");
  io::checkWritable(csv);
  if (!plot.empty()) {
    io::requireExtension(plot, ".png");
    io::checkWritable(plot);
  }
}

std::string formatNumber(const char* format, double x) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, format, x);
  return buffer;
}

}  // namespace tp::app
