#pragma once
#include <string>

namespace tp::app {

// Every benchmark writes a CSV and, unless `plot` is empty, a PNG: both are
// checked before any measuring starts, so a bad path costs nothing.
void checkBenchOutputs(const std::string& csv, const std::string& plot);

// One CSV or table cell: x printed with a printf format.
std::string formatNumber(const char* format, double x);

}  // namespace tp::app
