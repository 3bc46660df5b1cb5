#pragma once
#include <cstdint>
#include <iosfwd>
#include <string>
#include <vector>

#include "base/median.hpp"
#include "cli/frame_size.hpp"

namespace tp::base {
class AtomicFile;
}

namespace tp::app {

// Every benchmark writes a CSV and, unless `plot` is empty, a PNG: both are
// checked before any measuring starts, so a bad path costs nothing.
void checkBenchOutputs(const std::string& csv, const std::string& plot);

// Closes `csv`, written to file.tempPath(), renames it into place and says so;
// then plots it with tools/<plotScript> unless `plot` is empty.
void commitBenchCsv(base::AtomicFile& file, std::ofstream& csv, const std::string& plotScript, const std::string& plot);

// The sides a benchmark's image may have: --size WxH, each side within.
constexpr uint32_t kMinBenchSide = 8, kMaxBenchSide = 4096;

// An image size given as WxH, each side kMinBenchSide to kMaxBenchSide;
// `bench` names the benchmark in the error.
using Resolution = FrameSize;
Resolution parseResolution(const std::string& text, const std::string& bench);

// The median of timed repeats (base::median).
using base::median;

// One CSV or table cell: x printed with a printf format.
std::string formatNumber(const char* format, double x);

}  // namespace tp::app
