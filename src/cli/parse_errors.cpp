#include "cli/parse_errors.hpp"

#include <cctype>
#include <optional>

#include "base/closest_word.hpp"
#include "cli/command_help.hpp"

namespace tp::app {
namespace {

// Every spelling of every option of `command`, with its dashes.
std::vector<std::string> optionNames(CLI::App& command) {
  std::vector<std::string> names;
  for (const CLI::Option* option : command.get_options()) {
    for (const std::string& name : option->get_lnames()) names.push_back("--" + name);
    for (const std::string& name : option->get_snames()) names.push_back("-" + name);
  }
  return names;
}

// Where to read more: " (see tidepool help render)".
std::string seeHelp(const std::string& path) { return " (see tidepool help" + (path.empty() ? "" : " " + path) + ")"; }

bool isOptionWord(const std::string& word) {
  // "-3" is a value (a negative number), not an option.
  return word.size() > 1 && word[0] == '-' && !std::isdigit(static_cast<unsigned char>(word[1])) && word[1] != '.';
}

// The first word of `args` that names no command or option where it stands,
// explained; nothing when every word is known.
std::optional<std::string> unknownWord(CLI::App& app, const std::vector<std::string>& args) {
  CLI::App* command = &app;
  std::string path;  // the commands named so far: "", "render", "bench water"
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& word = args[i];
    if (word == "--") break;
    if (isOptionWord(word)) {
      const std::string name = word.substr(0, word.find('='));
      const CLI::Option* option = command->get_option_no_throw(name);
      if (!option) {
        std::string message = (path.empty() ? "" : path + ": ") + "unknown option " + name;
        if (const auto guess = base::closestWord(name, optionNames(*command))) {
          message += "; did you mean " + *guess + "?";
          // An old spelling out of --help says what it is now.
          const CLI::Option* meant = command->get_option_no_throw(*guess);
          if (meant->get_group().empty()) message += " (" + meant->get_description() + ")";
          return message;
        }
        return message + seeHelp(path);
      }
      // The option's values follow it, unless written with "=".
      if (word.find('=') == std::string::npos && option->get_type_size_max() > 0) {
        const bool many = option->get_items_expected_max() > 1;
        while (i + 1 < args.size() && !isOptionWord(args[i + 1]) && args[i + 1] != "--") {
          ++i;
          if (!many) break;
        }
      }
      continue;
    }
    if (CLI::App* sub = findCommand(*command, word)) {
      command = sub;
      path += (path.empty() ? "" : " ") + word;
      continue;
    }
    if (!command->get_options([](const CLI::Option* o) { return o->get_positional(); }).empty()) continue;
    const std::vector<std::string> names = commandNames(*command);
    if (names.empty()) return path + ": unexpected argument " + word + seeHelp(path);
    std::string message = (path.empty() ? "" : path + ": ") + "unknown command " + word;
    if (const auto guess = base::closestWord(word, names)) return message + "; did you mean " + *guess + "?";
    return message + "; the commands are " + base::listWords(names);
  }
  return std::nullopt;
}

// The option written before `value` in `args` ("--width abc", "--width=abc").
std::string optionGiven(const std::vector<std::string>& args, const std::string& value) {
  for (size_t i = 0; i < args.size(); ++i) {
    const size_t equals = args[i].find('=');
    if (isOptionWord(args[i]) && equals != std::string::npos && args[i].substr(equals + 1) == value) {
      return args[i].substr(0, equals);
    }
    if (isOptionWord(args[i]) && i + 1 < args.size() && args[i + 1] == value) return args[i];
  }
  return "";
}

// The deepest command the words name.
CLI::App* namedCommand(CLI::App& app, const std::vector<std::string>& args) {
  CLI::App* command = &app;
  for (const std::string& word : args) {
    if (CLI::App* sub = findCommand(*command, word)) command = sub;
  }
  return command;
}

}  // namespace

std::string explainParseError(CLI::App& app, const CLI::ParseError& error, const std::vector<std::string>& args) {
  if (const auto message = unknownWord(app, args)) return *message;
  if (dynamic_cast<const CLI::RequiredError*>(&error) != nullptr) {
    CLI::App* command = namedCommand(app, args);
    const std::vector<std::string> names = commandNames(*command);
    if (!names.empty() && command->get_require_subcommand_min() > 0 && command->get_subcommands().empty()) {
      return (command == &app ? "" : command->get_name() + ": ") + "a command is needed: " + base::listWords(names);
    }
  }
  // A value the option's check refused says all there is to say, but for
  // an old spelling out of --help, which CLI11 leaves unnamed.
  if (dynamic_cast<const CLI::ValidationError*>(&error) != nullptr) {
    const std::string message = error.what();
    if (message.rfind(": ", 0) == 0) return optionGiven(args, message.substr(2, message.find(' ', 2) - 2)) + message;
    return message;
  }
  std::string path;
  for (CLI::App* c = namedCommand(app, args); c != &app; c = c->get_parent()) {
    path = c->get_name() + (path.empty() ? "" : " " + path);
  }
  return std::string(error.what()) + seeHelp(path);
}

}  // namespace tp::app
