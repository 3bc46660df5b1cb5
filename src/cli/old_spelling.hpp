#pragma once
#include <CLI/CLI.hpp>
#include <string>

namespace tp::app {

// An option's name from before every command spelled sizes --size and grid
// sides --grids (--resolution, --resolutions, --sizes): still read, with the
// same check, but left out of --help; docs/command-line.md lists them.
// Given with the new name, the later one wins (a hidden option has no name
// for CLI11's "excludes" message).
template <typename T>
CLI::Option* addOldSpelling(CLI::App* cmd, const std::string& oldName, T& variable, CLI::Option* current,
                            const CLI::Validator& check) {
  return cmd->add_option(oldName, variable, "the old spelling of " + current->get_name())
      ->group("")
      ->delimiter(current->get_delimiter())
      ->check(check);
}

}  // namespace tp::app
