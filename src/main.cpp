// tidepool: a Vulkan renderer of an interactive water scene.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "base/heap_settings.hpp"
#include "bench/bench_command.hpp"
#include "cli/build_version.hpp"
#include "cli/command_help.hpp"
#include "cli/export_command.hpp"
#include "cli/parse_errors.hpp"
#include "cli/render_command.hpp"
#include "cli/sim_command.hpp"
#include "cli/usage_error.hpp"
#include "gpu/vulkan.hpp"
#include "viewer/view_command.hpp"

int main(int argc, char** argv) {
  tp::base::keepFreedHeapMemory();
  CLI::App app{"tidepool: a Vulkan renderer of an interactive water scene", "tidepool"};
  app.set_version_flag("--version", tp::app::versionText(), "Print the version and the git commit built from");
  app.require_subcommand(1);
  app.footer(
      "tidepool help COMMAND, or tidepool COMMAND --help, tells more of each; exit codes: 0 done, 1 failed, "
      "2 a bad command line, 130 or 143 stopped by SIGINT or SIGTERM");
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
  tp::app::HelpOptions helpOptions;
  CLI::App* help = tp::app::addHelpCommand(app, helpOptions);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp&) {
    std::fputs(app.help().c_str(), stdout);
    return 0;
  } catch (const CLI::CallForAllHelp&) {
    std::fputs(app.help("", CLI::AppFormatMode::All).c_str(), stdout);
    return 0;
  } catch (const CLI::CallForVersion&) {
    std::puts(tp::app::versionText());
    return 0;
  } catch (const CLI::ParseError& e) {
    const std::string message = tp::app::explainParseError(app, e, std::vector<std::string>(argv + 1, argv + argc));
    std::fprintf(stderr, "tidepool: error: %s\n", message.c_str());
    return 2;
  }
  try {
    if (help->parsed()) return tp::app::runHelp(app, helpOptions);
    if (render->parsed()) return tp::app::runRender(renderOptions);
    if (sim->parsed()) return tp::app::runSim(*sim, simOptions);
    if (exporter->parsed()) return tp::app::runExport(exportOptions);
    if (bench->parsed()) return tp::app::runBench(bench, benchOptions);
    if (view->parsed()) return tp::app::runView(viewOptions);
  } catch (const tp::app::UsageError& e) {
    std::fprintf(stderr, "tidepool: error: %s\n", e.what());
    return 2;
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
