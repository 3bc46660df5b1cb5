// tidepool: a Vulkan renderer of an interactive water scene.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>
#include <string>

#include "base/version.hpp"
#include "bench/bench_command.hpp"
#include "cli/export_command.hpp"
#include "cli/render_command.hpp"
#include "cli/sim_command.hpp"
#include "gpu/vulkan.hpp"
#include "viewer/view_command.hpp"

int main(int argc, char** argv) {
  CLI::App app{"tidepool: a Vulkan renderer of an interactive water scene", "tidepool"};
  const std::string version = std::string("tidepool ") + tp::base::kVersion;
  app.set_version_flag("--version", version);
  app.require_subcommand(1);
  tp::app::RenderOptions renderOptions;
  CLI::App* render = tp::app::addRenderCommand(app, renderOptions);
  tp::app::SimOptions simOptions;
  CLI::App* sim = tp::app::addSimCommand(app, simOptions);
  tp::app::ExportOptions exportOptions;
  CLI::App* exporter = tp::app::addExportCommand(app, exportOptions);
  tp::app::BenchOptions benchOptions;
  CLI::App* bench = tp::app::addBenchCommand(app, benchOptions);
  tp::app::ViewOptions viewOptions;
  CLI::App* view = tp::app::addViewCommand(app, viewOptions);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp&) {
    std::fputs(app.help().c_str(), stdout);
    return 0;
  } catch (const CLI::CallForAllHelp&) {
    std::fputs(app.help("", CLI::AppFormatMode::All).c_str(), stdout);
    return 0;
  } catch (const CLI::CallForVersion&) {
    std::puts(version.c_str());
    return 0;
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "tidepool: error: %s (see tidepool --help)\n", e.what());
    return 2;
  }
  try {
    if (render->parsed()) return tp::app::runRender(renderOptions);
    if (sim->parsed()) return tp::app::runSim(*sim, simOptions);
    if (exporter->parsed()) return tp::app::runExport(exportOptions);
    if (bench->parsed()) return tp::app::runBench(bench, benchOptions);
    if (view->parsed()) return tp::app::runView(viewOptions);
  } catch (const vk::DeviceLostError& e) {
    // Lost outside a wait that says what it was doing (a present, a read of timestamps).
    std::fprintf(stderr, "tidepool: error: the GPU device was lost (VK_ERROR_DEVICE_LOST) in %s\n", e.what());
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "tidepool: error: %s\n", e.what());
    return 1;
  }
  return 0;
}
