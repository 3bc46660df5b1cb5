#include "cli/command_help.hpp"

#include <cstdio>

#include "base/closest_word.hpp"
#include "cli/usage_error.hpp"

namespace tp::app {

CLI::App* addHelpCommand(CLI::App& app, HelpOptions& o) {
  CLI::App* cmd = app.add_subcommand(
      "help",
      "Show the help of tidepool or of a command, as --help does: tidepool help render, tidepool help bench water");
  cmd->add_option("command", o.topic, "The command (and its subcommand) to explain; none: tidepool itself")
      ->type_name("COMMAND");
  cmd->add_flag("--all", o.all, "Also every command under it, each with its options");
  return cmd;
}

std::vector<std::string> commandNames(CLI::App& app) {
  std::vector<std::string> names;
  for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) names.push_back(sub->get_name());
  return names;
}

CLI::App* findCommand(CLI::App& app, const std::string& name) {
  for (CLI::App* sub : app.get_subcommands([&](CLI::App* s) { return s->get_name() == name; })) return sub;
  return nullptr;
}

int runHelp(CLI::App& app, const HelpOptions& o) {
  CLI::App* command = &app;
  std::string parents;  // the usage line's words before the command's own name
  for (const std::string& word : o.topic) {
    CLI::App* sub = findCommand(*command, word);
    if (!sub) {
      const std::vector<std::string> names = commandNames(*command);
      const std::string where = command == &app ? "tidepool" : parents + " " + command->get_name();
      std::string message = "help " + word + ": " + where + " has no command " + word;
      if (names.empty()) throw UsageError(message);
      if (const auto guess = base::closestWord(word, names))
        throw UsageError(message + "; did you mean " + *guess + "?");
      throw UsageError(message + "; its commands are " + base::listWords(names));
    }
    parents = parents.empty() ? command->get_name() : parents + " " + command->get_name();
    command = sub;
  }
  // The formatter, not App::help, which would show the help command's own help.
  const std::string name = parents.empty() ? command->get_name() : parents + " " + command->get_name();
  std::fputs(command->get_formatter()
                 ->make_help(command, name, o.all ? CLI::AppFormatMode::All : CLI::AppFormatMode::Normal)
                 .c_str(),
             stdout);
  return 0;
}

}  // namespace tp::app
