#pragma once
#include <string>

namespace tp::app {

// Runs tools/<script> (matplotlib) on a benchmark CSV to make a PNG, through a
// temporary file renamed into place. A machine without python3-matplotlib gets
// one warning line and no plot: the CSV is the benchmark's result.
void plotCsv(const std::string& script, const std::string& csv, const std::string& png);

}  // namespace tp::app
