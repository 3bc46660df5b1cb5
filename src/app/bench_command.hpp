#pragma once
#include <CLI/CLI.hpp>

#include "app/bench_sim.hpp"
#include "app/bench_water.hpp"

namespace tp::app {

struct BenchOptions {
  BenchSimOptions sim;
  BenchWaterOptions water;
};

// Adds `tidepool bench` with its subcommands (sim, water).
CLI::App* addBenchCommand(CLI::App& app, BenchOptions& options);
int runBench(CLI::App* bench, const BenchOptions& options);

}  // namespace tp::app
