#pragma once
// `tidepool help [COMMAND...]`: the --help of the program or of a command.
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

namespace tp::app {

struct HelpOptions {
  std::vector<std::string> topic;  // the command's words: none, {"render"}, {"bench", "water"}
  bool all = false;                // --all: every command under it too, with its options
};

// Adds `help`, whose words name the command: `help`, `help render`, `help bench water`.
CLI::App* addHelpCommand(CLI::App& app, HelpOptions& options);

// Prints the help the options name and returns 0; throws UsageError naming
// the first word that is not a command there, and the nearest one.
int runHelp(CLI::App& app, const HelpOptions& options);

// The commands under `app`, by name.
std::vector<std::string> commandNames(CLI::App& app);

// `app`'s command named `name`, or null.
CLI::App* findCommand(CLI::App& app, const std::string& name);

}  // namespace tp::app
