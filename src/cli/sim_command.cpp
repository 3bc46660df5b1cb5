#include "cli/sim_command.hpp"
#include "cli/number_checks.hpp"
#include "cli/usage_error.hpp"
#include "io/water_state_file.hpp"

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>

#include "base/atomic_file.hpp"
#include "cli/gpu_session.hpp"
#include "gpu/submit.hpp"
#include "sim/gpu_stepper.hpp"

namespace tp::app {

CLI::App* addSimCommand(CLI::App& app, SimOptions& o) {
  CLI::App* cmd =
      app.add_subcommand("sim", "Run the water simulation headless and write its state as EXR (channels u, v)");
  cmd->add_option("--grid", o.grid, "Cells per side (default 256, or the --init EXR's size)")
      ->check(inRange(2u, 16384u));
  cmd->add_option("--extent", o.extent, "Side of the square domain in metres; h = extent / grid")
      ->capture_default_str();
  cmd->add_option("--steps", o.steps, "Steps of --dt, or frames of --frame-time")->capture_default_str();
  auto* dt = cmd->add_option("--dt", o.dt, "Time step in seconds; refused when c*dt/h > 1/sqrt(2)");
  auto* frame = cmd->add_option("--frame-time", o.frameTime,
                                "Seconds per frame, split into the fewest substeps with c*dt/h <= 0.9/sqrt(2)")
                    ->capture_default_str();
  dt->excludes(frame);
  cmd->add_option("--wave-speed", o.waveSpeed, "Wave speed c in m/s")->capture_default_str();
  cmd->add_option("--damping", o.damping, "Damping rate gamma in 1/s")->capture_default_str();
  cmd->add_option("--grid-damping", o.gridDamping, "Damping kappa of the shortest waves in 1/s")->capture_default_str();
  cmd->add_option("--boundary", o.boundary, "clamp (reflective walls) or wrap (periodic)")
      ->capture_default_str()
      ->check(CLI::IsMember({"clamp", "wrap"}));
  cmd->add_option(
         "--max-slope", o.maxSlope,
         "Slope limiter: neighbours more than S*h apart pass an eighth of the excess across their edge each step, "
         "keeping the volume; needs lambda <= 1/2 (0: off)")
      ->capture_default_str();
  cmd->add_option("--scheme", o.scheme, "symplectic (stable up to the bound) or explicit (forward Euler, unstable)")
      ->capture_default_str()
      ->check(CLI::IsMember({"symplectic", "explicit"}));
  cmd->add_option("--init", o.init,
                  "PATH.exr (channels u, v; resumes exactly), drop:X,Z,RADIUS,AMP or mode:M,N,AMP (at rest)")
      ->capture_default_str();
  cmd->add_option("--out", o.out, "Output EXR (float32 channels u, v; pixel (i, j) = cell (i, j))")
      ->type_name("PATH")
      ->required();
  cmd->add_option(
         "--kernel", o.kernel,
         "one (one step per dispatch), tiled (several steps per dispatch) or active (only the tiles in motion)")
      ->capture_default_str()
      ->check(CLI::IsMember({"one", "tiled", "active"}));
  cmd->add_option("--halo", o.halo, "Steps per dispatch of the tiled kernel")
      ->capture_default_str()
      ->check(inRange(1u, sim::GpuStepper::kMaxHalo));
  cmd->add_option("--health-every", o.healthEvery, "Steps between health checks (max |u|, volume, energy, NaN)")
      ->capture_default_str()
      ->check(inRange(uint64_t(1), uint64_t(1) << 40));
  addGpuOptions(cmd, o.validate, o.device);
  return cmd;
}

int runSim(const CLI::App& command, const SimOptions& o) {
  asUsageError([&] { base::requireExtension(o.out, ".exr"); });
  base::checkWritable(o.out);
  sim::WaterParams params{.n = o.grid,
                          .extent = o.extent,
                          .waveSpeed = o.waveSpeed,
                          .damping = o.damping,
                          .boundary = sim::parseBoundary(o.boundary),
                          .maxSlope = o.maxSlope,
                          .scheme = sim::parseScheme(o.scheme),
                          .gridDamping = o.gridDamping};
  const bool fromFile = o.init.rfind("drop:", 0) != 0 && o.init.rfind("mode:", 0) != 0;
  // A file named on the command line that is not there is a bad command line,
  // as --scene's is; one there but not a state fails later, with exit code 1.
  if (fromFile) {
    std::string path = o.init;
    if (const std::string why = CLI::ExistingFile(path); !why.empty()) throw UsageError("--init: " + why);
  }
  if (fromFile && command.count("--grid") == 0) params.n = 0;  // take the file's size
  if (params.n != 0) asUsageError([&] { sim::validate(params); });

  GpuSession session(o.validate, o.device);
  const gpu::Context& ctx = session.context();
  if (params.n != 0) sim::checkGridFits(ctx, params.n);

  sim::WaterState initial;
  if (fromFile) {
    initial = io::initialState(o.init, params, 0.0);  // taken as it is: the step size does not enter
    params.n = initial.n;
    sim::validate(params);
    sim::checkGridFits(ctx, params.n);
  }
  // The time step: given, or the fewest substeps of a frame within the margin.
  const bool givenStep = command.count("--dt") > 0;
  uint32_t substeps = 1;
  asUsageError([&] {
    if (!givenStep) substeps = sim::substepsFor(params, o.frameTime);
    sim::checkStable(params, givenStep ? o.dt : o.frameTime / substeps);
  });
  const double dt = givenStep ? o.dt : o.frameTime / substeps;
  // drop:... and mode:... are values of the command line: a malformed one exits 2.
  if (!fromFile) asUsageError([&] { initial = io::initialState(o.init, params, dt); });
  const uint64_t totalSteps = o.steps * substeps;

  double maxHeight = 0.0;
  for (float u : initial.u) maxHeight = std::max(maxHeight, double(std::abs(u)));
  maxHeight = 1e3 * (maxHeight + params.extent);  // far beyond any sane wave: only a blow-up gets there

  const sim::StepKernel kernel = o.kernel == "tiled"    ? sim::StepKernel::Tiled
                                 : o.kernel == "active" ? sim::StepKernel::ActiveTiles
                                                        : sim::StepKernel::OnePerDispatch;
  sim::GpuStepper stepper(ctx, params, initial, kernel, o.halo);
  const bool progress = isatty(STDERR_FILENO);
  const auto start = std::chrono::steady_clock::now();
  sim::WaterStats stats = stepper.stats(dt);
  const double volume0 = stats.volume;
  for (uint64_t done = 0; done < totalSteps;) {
    const uint64_t chunk = std::min(o.healthEvery, totalSteps - done);
    stepper.step(chunk, dt);
    done += chunk;
    stats = stepper.stats(dt);
    sim::checkHealth(stats, done, maxHeight);
    if (progress) {
      const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      std::fprintf(stderr, "\rstep %llu/%llu  %.1f s  %s", static_cast<unsigned long long>(done),
                   static_cast<unsigned long long>(totalSteps), elapsed, sim::describe(stats).c_str());
    }
  }
  if (progress) std::fputc('\n', stderr);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  io::writeStateExr(o.out, stepper.download());
  std::printf("wrote %s (%ux%u cells, float32 u v)\n", o.out.c_str(), params.n, params.n);
  std::printf("grid %u  h %.6g m  dt %.6g s  lambda %.4f  substeps %u  steps %llu  kernel %s on %s\n", params.n,
              params.h(), dt, params.lambda(dt), substeps, static_cast<unsigned long long>(totalSteps),
              o.kernel.c_str(), ctx.deviceName().c_str());
  std::printf("%s  volume change %.3g relative\n", sim::describe(stats).c_str(),
              volume0 != 0.0 ? (stats.volume - volume0) / std::abs(volume0) : stats.volume);
  std::printf("%.3f s, %.1f Mcells/s (wall clock, with health checks)\n", seconds,
              double(totalSteps) * params.n * params.n / seconds / 1e6);
  return session.finish();
}

}  // namespace tp::app
