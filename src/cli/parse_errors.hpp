#pragma once
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

namespace tp::app {

// One line for a command line the parser refused, naming the command or
// option that is not there and the nearest one a typist meant ("render:
// unknown option --widht; did you mean --width?"), else the parser's own
// message. `args` are the words after the program's name.
std::string explainParseError(CLI::App& app, const CLI::ParseError& error, const std::vector<std::string>& args);

}  // namespace tp::app
