#pragma once
#include <CLI/CLI.hpp>

#include "app/bench_frame.hpp"
#include "app/bench_glass.hpp"
#include "app/bench_ibl.hpp"
#include "app/bench_sim.hpp"
#include "app/bench_ssao.hpp"
#include "app/bench_tiles.hpp"
#include "app/bench_water.hpp"

namespace tp::app {

struct BenchOptions {
  BenchSimOptions sim;
  BenchWaterOptions water;
  BenchSsaoOptions ssao;
  BenchTilesOptions tiles;
  BenchFrameOptions frame;
  BenchIblOptions ibl;
  BenchGlassOptions glass;
};

// Adds `tidepool bench` with its subcommands (sim, tiles, water, ssao, frame, ibl, glass).
CLI::App* addBenchCommand(CLI::App& app, BenchOptions& options);
int runBench(CLI::App* bench, const BenchOptions& options);

}  // namespace tp::app
