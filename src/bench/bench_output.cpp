#include "bench/bench_output.hpp"

#include <cstdio>
#include <fstream>
#include <stdexcept>

#include "base/atomic_file.hpp"
#include "bench/plot.hpp"
#include "cli/usage_error.hpp"

namespace tp::app {

void checkBenchOutputs(const std::string& csv, const std::string& plot) {
  base::requireExtension(csv, ".csv");
  base::checkWritable(csv);
  if (!plot.empty()) {
    base::requireExtension(plot, ".png");
    base::checkWritable(plot);
  }
}

void commitBenchCsv(base::AtomicFile& file, std::ofstream& csv, const std::string& plotScript,
                    const std::string& plot) {
  csv.close();
  if (!csv) throw std::runtime_error("cannot write " + file.target());
  file.commit();
  std::printf("wrote %s\n", file.target().c_str());
  if (!plot.empty()) plotCsv(plotScript, file.target(), plot);
}

Resolution parseResolution(const std::string& text, const std::string& bench) {
  const auto size = parseFrameSize(text, kMinBenchSide, kMaxBenchSide);
  if (!size) throw UsageError(bench + ": --size " + text + " is not WxH with sides 8 to 4096");
  return *size;
}

std::string formatNumber(const char* format, double x) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, format, x);
  return buffer;
}

}  // namespace tp::app
