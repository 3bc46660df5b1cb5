#pragma once
#include <CLI/CLI.hpp>

#include "app/bench_sim.hpp"

namespace tp::app {

struct BenchOptions {
  BenchSimOptions sim;
};

// Adds `tidepool bench` with its subcommands (sim).
CLI::App* addBenchCommand(CLI::App& app, BenchOptions& options);
int runBench(CLI::App* bench, const BenchOptions& options);

}  // namespace tp::app
