#pragma once
#include <CLI/CLI.hpp>
#include <string>

namespace tp::app {

struct SimOptions {
  uint32_t grid = 256;
  double extent = 2.0;
  uint64_t steps = 100;
  double dt = 0.0;
  double frameTime = 1.0 / 60.0;
  double waveSpeed = 0.5;
  double damping = 0.0;
  double gridDamping = 0.0;
  std::string boundary = "clamp";
  double maxSlope = 0.0;
  std::string scheme = "symplectic";
  std::string init = "drop:1,1,0.2,0.05";
  std::string out;
  std::string kernel = "one";
  uint32_t halo = 4;
  uint64_t healthEvery = 1000;
  bool validate = false;
  std::string device;
};

// Adds `tidepool sim` and its options to the command line.
CLI::App* addSimCommand(CLI::App& app, SimOptions& options);

// Returns the process exit code; throws std::exception on failure.
int runSim(const CLI::App& command, const SimOptions& options);

}  // namespace tp::app
