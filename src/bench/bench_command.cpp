#include "bench/bench_command.hpp"

#include <filesystem>

#include "base/number_text.hpp"
#include "bench/bench_output.hpp"
#include "cli/frame_size.hpp"
#include "cli/gpu_session.hpp"
#include "cli/number_checks.hpp"
#include "cli/old_spelling.hpp"
#include "scene/scene.hpp"

namespace tp::app {

namespace {

// The CSV and plot outputs every benchmark writes.
void addOutputOptions(CLI::App* cmd, std::string& csv, std::string& plot) {
  cmd->add_option("--csv", csv, "CSV output")->type_name("PATH")->capture_default_str();
  cmd->add_option("--plot", plot, "PNG plot output (empty: none)")->type_name("PATH")->capture_default_str();
}

// The image size a benchmark renders at, WxH.
void addSizeOption(CLI::App* cmd, std::string& size) {
  const CLI::Validator check = frameSizeCheck(kMinBenchSide, kMaxBenchSide);
  auto* option = cmd->add_option("--size", size, "Image size WxH, each side 8 to 4096")
                     ->type_name("WxH")
                     ->capture_default_str()
                     ->check(check);
  addOldSpelling(cmd, "--resolution", size, option, check);
}

// The image sizes a benchmark renders at, WxH,WxH,...
void addSizesOption(CLI::App* cmd, std::vector<std::string>& sizes) {
  const CLI::Validator check = frameSizeCheck(kMinBenchSide, kMaxBenchSide);
  auto* option = cmd->add_option("--size", sizes, "Image sizes WxH, comma-separated, each side 8 to 4096")
                     ->type_name("WxH,...")
                     ->delimiter(',')
                     ->capture_default_str()
                     ->check(check);
  addOldSpelling(cmd, "--resolutions", sizes, option, check);
}

// The grid sides a simulation benchmark measures.
template <typename T>
void addGridsOption(CLI::App* cmd, std::vector<T>& grids, T maxSide) {
  const CLI::Validator check = inRange(T(16), maxSide);
  auto* option =
      cmd->add_option("--grids", grids, "Grid sides to measure")->delimiter(',')->capture_default_str()->check(check);
  addOldSpelling(cmd, "--sizes", grids, option, check);
}

// A comma-separated list option with its default shown and each value checked.
template <typename T, typename Check>
CLI::Option* addListOption(CLI::App* cmd, const std::string& name, std::vector<T>& values, const std::string& help,
                           Check check) {
  return cmd->add_option(name, values, help)->delimiter(',')->capture_default_str()->check(check);
}

void addSimBench(CLI::App* bench, BenchSimOptions& o) {
  CLI::App* sim = bench->add_subcommand(
      "sim", "Water stepper: GPU (one step per dispatch, tiled) against an OpenMP C++ loop, cells/s and error");
  addGridsOption(sim, o.sizes, 8192u);
  addOutputOptions(sim, o.csv, o.plot);
  sim->add_option("--min-time", o.minTime, "Seconds measured per case")
      ->capture_default_str()
      ->check(inRange(0.01, 60.0));
  addGpuOptions(sim, o.validate, o.device);
}

void addTilesBench(CLI::App* bench, BenchTilesOptions& o) {
  CLI::App* tiles = bench->add_subcommand("tiles",
                                          "Water stepper on active tiles: ms per step over all tiles, over the active "
                                          "list and with the one-step kernel, against the fraction of tiles active");
  addGridsOption(tiles, o.sizes, 8192u);
  addListOption(tiles, "--radii", o.radii, "Drop radii as fractions of the side (0: calm water)", inRange(0.0, 2.0));
  tiles->add_option("--steps", o.steps, "Steps per timed submission, right after the drop")
      ->capture_default_str()
      ->check(inRange(1u, 1000u));
  tiles->add_option("--repeats", o.repeats, "Timed submissions per case; the median is reported")
      ->capture_default_str()
      ->check(inRange(1u, 1000u));
  addOutputOptions(tiles, o.csv, o.plot);
  addGpuOptions(tiles, o.validate, o.device);
}

void addWakeBench(CLI::App* bench, BenchWakeOptions& o) {
  CLI::App* wake = bench->add_subcommand(
      "wake",
      "A sphere crossing the pool: high-wavenumber share, steepest slope and crest of its wake against ms per step");
  addGridsOption(wake, o.sizes, 2048u);
  addListOption(wake, "--speeds", o.speeds, "Sphere speeds as fractions of the wave speed", inRange(0.05, 2.0));
  addListOption(wake, "--grid-dampings", o.gridDampings, "Grid damping kappa values in 1/s to compare",
                inRange(0.0, 1e4));
  addListOption(wake, "--forcings", o.forcings, "Sphere forcings to compare (water.sphere_forcing)",
                CLI::IsMember(scene::choices::kSphereForcing));
  addListOption(wake, "--spread-depth-factors", o.spreadDepthFactors,
                "The spread forcing's widening per metre of the body's depth, to compare (the free surface's: 0.65)",
                inRange(0.0, 100.0));
  addListOption(wake, "--near-speed-widening", o.nearSpeedWidening,
                "The spread forcing's bump widened near the wave speed, to compare (on: the scenes')",
                CLI::IsMember({"on", "off"}));
  addListOption(wake, "--max-slopes", o.maxSlopes,
                "Slope limits (water.max_slope) to compare; 0: the limiter off, the scenes' default",
                inRange(0.0, 1e4));
  wake->add_option("--wave-speed", o.waveSpeed,
                   "The water's wave speed c in m/s; the sphere's speeds are fractions of it")
      ->default_str(base::numberText(float(o.waveSpeed)))  // the scene's float, as written there
      ->check(inRange(0.05, 10.0));
  addOutputOptions(wake, o.csv, o.plot);
  addGpuOptions(wake, o.validate, o.device);
}

void addWaterBench(CLI::App* bench, BenchWaterOptions& o) {
  CLI::App* water = bench->add_subcommand("water",
                                          "Water refraction modes (accurate, apparent) on fixed views: GPU ms against "
                                          "error from the raster's model traced on the CPU");
  addSceneSourceOptions(water, o.scene, "Scene file (JSON); default: the built-in scene");
  addSizesOption(water, o.resolutions);
  water->add_option("--frame", o.frame, "Frame of the water to render")->capture_default_str()->check(frameNumber());
  water->add_option("--samples", o.samples, "Samples per pixel of the model traced")
      ->capture_default_str()
      ->check(inRange(1u, 4096u));
  water->add_option("--repeats", o.repeats, "Timed frames per case; the median is reported")
      ->capture_default_str()
      ->check(inRange(1u, 1000u));
  addOutputOptions(water, o.csv, o.plot);
  addGpuOptions(water, o.validate, o.device);
}

void addSsaoBench(CLI::App* bench, BenchSsaoOptions& o) {
  CLI::App* ssao = bench->add_subcommand(
      "ssao", "SSAO settings and presets on one frame: GPU ms of the AO passes against error from ray-traced AO");
  addSceneSourceOptions(ssao, o.scene, "Scene file (JSON); default: the built-in scene");
  addSizeOption(ssao, o.resolution);
  ssao->add_option("--frame", o.frame, "Frame of the water to render")->capture_default_str()->check(frameNumber());
  ssao->add_option("--repeats", o.repeats, "Timed frames per case; the median is reported")
      ->capture_default_str()
      ->check(inRange(1u, 1000u));
  addOutputOptions(ssao, o.csv, o.plot);
  addGpuOptions(ssao, o.validate, o.device);
}

void addFrameBench(CLI::App* bench, BenchFrameOptions& o) {
  CLI::App* frame = bench->add_subcommand(
      "frame",
      "Scene variants as frame sequences with skipping on and off: GPU ms per frame and the passes, "
      "dispatches, draws and workgroups recorded");
  addSceneSourceOptions(frame, o.scene, "Scene file (JSON) the variants start from; default: the built-in scene");
  addSizeOption(frame, o.resolution);
  frame->add_option("--frames", o.frames, "Timed frames of each sequence (frames 1..N, after frame 0)")
      ->capture_default_str()
      ->check(inRange(1u, 100000u));
  addOutputOptions(frame, o.csv, o.plot);
  addGpuOptions(frame, o.validate, o.device);
}

void addPassesBench(CLI::App* bench, BenchPassesOptions& o) {
  CLI::App* passes = bench->add_subcommand(
      "passes",
      "Where a frame's time goes: each pass's wall ms (submitted on its own) and the frame's fps, per resolution; "
      "the camera moves as the scene's path or turntable says (camera.turntable=20: a moving camera's frame)");
  addSceneSourceOptions(passes, o.scene, "Scene file (JSON); default: the built-in scene");
  addSizesOption(passes, o.resolutions);
  passes->add_option("--frames", o.frames, "Timed frames of each kind (whole, pass by pass) per resolution")
      ->capture_default_str()
      ->check(inRange(1u, 100000u));
  passes->add_flag("--shown", o.shown,
                   "Time the frame the viewer shows rather than the one render writes: no HDR readback, and the "
                   "resolve stores no HDR colour");
  addOutputOptions(passes, o.csv, o.plot);
  addGpuOptions(passes, o.validate, o.device);
}

void addIblBench(CLI::App* bench, BenchIblOptions& o) {
  CLI::App* ibl = bench->add_subcommand(
      "ibl",
      "Sky irradiance (SH9) by importance and by uniform sampling, and the glossy prefilter by environment, lobe and "
      "MIS sampling: samples against error against GPU ms");
  addSceneSourceOptions(ibl, o.scene, "Scene file (JSON) whose procedural sky to use; default: the built-in scene");
  ibl->add_option("--width", o.width, "Environment texels across (even; height is half)")
      ->capture_default_str()
      ->check(inRange(16u, 8192u));
  addListOption(ibl, "--samples", o.samples, "Sample counts to measure", inRange(1u, 1u << 22));
  ibl->add_option("--rotations", o.rotations, "Independent sample sets per case (errors: RMS over them)")
      ->capture_default_str()
      ->check(inRange(1u, 1000u));
  ibl->add_option("--repeats", o.repeats, "Timed CDF builds; the median is reported")
      ->capture_default_str()
      ->check(inRange(1u, 1000u));
  addOutputOptions(ibl, o.csv, o.plot);
  ibl->add_option("--glossy-samples", o.glossySamples,
                  "Glossy prefilter samples per texel to measure (MIS: half from the environment, half from the lobe)")
      ->delimiter(',')
      ->capture_default_str()
      ->check(inRange(2u, 65536u));
  ibl->add_option("--glossy-csv", o.glossyCsv, "CSV output of the glossy prefilter")
      ->type_name("PATH")
      ->capture_default_str();
  ibl->add_option("--glossy-plot", o.glossyPlot, "PNG plot of the glossy prefilter (empty: none)")
      ->type_name("PATH")
      ->capture_default_str();
  addGpuOptions(ibl, o.validate, o.device);
}

void addGlassBench(CLI::App* bench, BenchGlassOptions& o) {
  CLI::App* glass = bench->add_subcommand("glass",
                                          "Glass spheres' image-space refraction: binary-search steps against GPU ms "
                                          "and error from the raster's model traced on the CPU");
  addSceneSourceOptions(glass, o.scene,
                        "Scene file (JSON) with a glass sphere; default: a glass sphere over the ground");
  addSizeOption(glass, o.resolution);
  addListOption(glass, "--steps", o.steps, "Binary-search steps to measure, each 1 to 64", inRange(1u, 64u));
  glass->add_option("--samples", o.samples, "Samples per pixel of the model traced")
      ->capture_default_str()
      ->check(inRange(1u, 4096u));
  glass->add_option("--repeats", o.repeats, "Timed frames per case; the median is reported")
      ->capture_default_str()
      ->check(inRange(1u, 1000u));
  addOutputOptions(glass, o.csv, o.plot);
  addGpuOptions(glass, o.validate, o.device);
}

void addTruthBench(CLI::App* bench, BenchTruthOptions& o) {
  CLI::App* truth = bench->add_subcommand(
      "truth", "The raster against the path-traced truth: error per scene and region beside each one's wall time");
  // `default` names the built-in scene among files (docs/accuracy.md's command).
  addListOption(truth, "--scenes", o.scenes,
                "Scene files to measure, comma-separated, `default` the built-in scene; default: the built-in scene",
                CLI::Validator(
                    [](std::string& name) {
                      return name == "default" || std::filesystem::is_regular_file(name)
                                 ? std::string()
                                 : "File does not exist: " + name;
                    },
                    "FILE or default"))
      ->type_name("PATH,...");
  addSizeOption(truth, o.resolution);
  truth->add_option("--frame", o.frame, "Frame number of each scene")->capture_default_str()->check(frameNumber());
  truth->add_option("--samples", o.samples, "Paths per pixel of the truth")
      ->capture_default_str()
      ->check(inRange(1u, 65536u));
  truth->add_option("--raster-samples", o.rasterSamples, "Jittered frames the raster averages, as render --samples")
      ->capture_default_str()
      ->check(inRange(1u, 4096u));
  addOutputOptions(truth, o.csv, o.plot);
  addGpuOptions(truth, o.validate, o.device);
}

}  // namespace

CLI::App* addBenchCommand(CLI::App& app, BenchOptions& o) {
  CLI::App* bench = app.add_subcommand("bench", "Benchmarks: run time against error, as a table, CSV and a plot");
  bench->require_subcommand(1);
  addSimBench(bench, o.sim);
  addTilesBench(bench, o.tiles);
  addWakeBench(bench, o.wake);
  addWaterBench(bench, o.water);
  addSsaoBench(bench, o.ssao);
  addFrameBench(bench, o.frame);
  addPassesBench(bench, o.passes);
  addIblBench(bench, o.ibl);
  addGlassBench(bench, o.glass);
  addTruthBench(bench, o.truth);
  return bench;
}

int runBench(CLI::App* bench, const BenchOptions& o) {
  if (bench->get_subcommand("sim")->parsed()) return runBenchSim(o.sim);
  if (bench->get_subcommand("tiles")->parsed()) return runBenchTiles(o.tiles);
  if (bench->get_subcommand("wake")->parsed()) return runBenchWake(o.wake);
  if (bench->get_subcommand("water")->parsed()) return runBenchWater(o.water);
  if (bench->get_subcommand("ssao")->parsed()) return runBenchSsao(o.ssao);
  if (bench->get_subcommand("frame")->parsed()) return runBenchFrame(o.frame);
  if (bench->get_subcommand("passes")->parsed()) return runBenchPasses(o.passes);
  if (bench->get_subcommand("ibl")->parsed()) return runBenchIbl(o.ibl);
  if (bench->get_subcommand("glass")->parsed()) return runBenchGlass(o.glass);
  if (bench->get_subcommand("truth")->parsed()) return runBenchTruth(o.truth);
  return 2;
}

}  // namespace tp::app
