#pragma once
#include <CLI/CLI.hpp>

#include "bench/bench_frame.hpp"
#include "bench/bench_glass.hpp"
#include "bench/bench_ibl.hpp"
#include "bench/bench_passes.hpp"
#include "bench/bench_sim.hpp"
#include "bench/bench_ssao.hpp"
#include "bench/bench_tiles.hpp"
#include "bench/bench_truth.hpp"
#include "bench/bench_wake.hpp"
#include "bench/bench_water.hpp"

namespace tp::app {

struct BenchOptions {
  BenchSimOptions sim;
  BenchWaterOptions water;
  BenchSsaoOptions ssao;
  BenchTilesOptions tiles;
  BenchFrameOptions frame;
  BenchPassesOptions passes;
  BenchIblOptions ibl;
  BenchGlassOptions glass;
  BenchTruthOptions truth;
  BenchWakeOptions wake;
};

// Adds `tidepool bench` with its subcommands (sim, tiles, wake, water, ssao, frame, passes, ibl, glass, truth).
CLI::App* addBenchCommand(CLI::App& app, BenchOptions& options);
int runBench(CLI::App* bench, const BenchOptions& options);

}  // namespace tp::app
