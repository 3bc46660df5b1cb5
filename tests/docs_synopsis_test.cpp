// The command synopses in README.md and docs/*.md against the program itself.
// A synopsis is a line in a fenced code block that starts with "tidepool ",
// with the lines under it indented by spaces (up to a blank line or the
// fence): e.g.
//
//   tidepool render [--scene PATH] [--width W] [--height H] ...
//                   [--device NAME] [--profile]
//
// For each command a synopsis names ("render", "bench water", ...), every
// --option it writes must be one that `tidepool <command> --help` lists, and
// every option the help lists must be written in at least one synopsis of that
// command; and every command the program has must have a synopsis.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "help_text.hpp"
#include "process.hpp"

namespace tp::test {
namespace {

namespace fs = std::filesystem;

struct Synopsis {
  std::string where;              // "docs/rendering.md:8", for messages
  std::string command;            // "render", "bench water"
  std::set<std::string> options;  // "--scene", "--width", ...
};

bool isBlank(const std::string& line) { return line.find_first_not_of(" \t") == std::string::npos; }

// A Markdown code fence, indented or not: ``` or ~~~, with or without an info string.
bool isFence(const std::string& line) {
  const std::string rest = line.substr(leadingSpaces(line));
  return rest.rfind("```", 0) == 0 || rest.rfind("~~~", 0) == 0;
}

// The line with up to `indent` leading spaces taken off (a fence inside a list
// item is indented, and so are the lines of its block).
std::string unindent(const std::string& line, size_t indent) {
  return line.substr(std::min(indent, leadingSpaces(line)));
}

bool isOptionChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '-'; }

// Every long option written in `text`: "--" at the start of a word (after a
// space, "[", "|", a quote, ...), followed by a letter or digit, up to the
// first character that is not a letter, a digit or "-".
std::set<std::string> longOptions(const std::string& text) {
  std::set<std::string> options;
  for (size_t i = 0; i + 2 < text.size(); ++i) {
    if (text[i] != '-' || text[i + 1] != '-') continue;
    if (i > 0 && (isOptionChar(text[i - 1]) || text[i - 1] == '_')) continue;
    if (std::isalnum(static_cast<unsigned char>(text[i + 2])) == 0) continue;
    size_t end = i + 2;
    while (end < text.size() && isOptionChar(text[end])) ++end;
    options.insert(text.substr(i, end - i));
    i = end - 1;
  }
  return options;
}

// The command a synopsis names: the words after "tidepool" up to the first that
// is not a plain lower-case word ("--frames", "[--scene", ...).
std::string commandOf(const std::string& text) {
  std::istringstream words(text);
  std::string word, command;
  words >> word;  // "tidepool"
  while (words >> word) {
    const bool plain = std::all_of(word.begin(), word.end(), [](char c) { return c >= 'a' && c <= 'z'; });
    if (!plain) break;
    command += (command.empty() ? "" : " ") + word;
  }
  return command;
}

// The synopses of one Markdown file.
std::vector<Synopsis> synopsesIn(const fs::path& file, const std::string& name) {
  std::vector<Synopsis> found;
  const std::vector<std::string> lines = splitLines(readText(file));
  bool inFence = false;
  size_t fenceIndent = 0;
  for (size_t i = 0; i < lines.size(); ++i) {
    if (isFence(lines[i])) {
      inFence = !inFence;
      fenceIndent = leadingSpaces(lines[i]);
      continue;
    }
    if (!inFence) continue;
    const std::string first = unindent(lines[i], fenceIndent);
    if (first.rfind("tidepool ", 0) != 0) continue;
    std::string text = first;
    size_t next = i + 1;
    for (; next < lines.size(); ++next) {
      if (isFence(lines[next]) || isBlank(lines[next])) break;
      const std::string more = unindent(lines[next], fenceIndent);
      if (more.empty() || more.front() != ' ') break;  // not a continuation: maybe the next synopsis
      text += " " + more;
    }
    found.push_back({name + ":" + std::to_string(i + 1), commandOf(text), longOptions(text)});
    i = next - 1;
  }
  return found;
}

// README.md and every docs/*.md, in a fixed order.
std::vector<Synopsis> allSynopses() {
  const fs::path source = TIDEPOOL_SOURCE_DIR;
  std::vector<std::pair<fs::path, std::string>> files{{source / "README.md", "README.md"}};
  std::vector<fs::path> docs;
  for (const auto& entry : fs::directory_iterator(source / "docs")) {
    if (entry.is_regular_file() && entry.path().extension() == ".md") docs.push_back(entry.path());
  }
  std::sort(docs.begin(), docs.end());
  for (const fs::path& doc : docs) files.emplace_back(doc, "docs/" + doc.filename().string());
  std::vector<Synopsis> all;
  for (const auto& [path, name] : files) {
    std::vector<Synopsis> some = synopsesIn(path, name);
    all.insert(all.end(), some.begin(), some.end());
  }
  return all;
}

// The long options `--help` lists (CLI11: an option's line starts with its
// names, "-h,--help" or "--width", then its type and requirements, then the
// description), --help itself left out.
std::set<std::string> helpOptions(const std::string& help) {
  std::set<std::string> options;
  for (const std::string& line : splitLines(help)) {
    const size_t indent = leadingSpaces(line);
    if (indent == line.size() || indent > 8 || line[indent] != '-') continue;  // not an option's first line
    std::istringstream words(line.substr(indent));
    for (std::string word; words >> word && word.front() == '-';) {
      std::istringstream names(word);
      for (std::string name; std::getline(names, name, ',');) {
        if (name.rfind("--", 0) != 0) continue;  // "-h", or the empty name after "-h,"
        size_t end = 2;
        while (end < name.size() && isOptionChar(name[end])) ++end;  // "--foo=3" is "--foo"
        if (end > 2) options.insert(name.substr(0, end));
      }
    }
  }
  for (const char* own : {"--help", "--help-all", "--version"}) options.erase(own);
  return options;
}

std::string join(const std::set<std::string>& words) {
  std::string text;
  for (const std::string& w : words) text += (text.empty() ? "" : " ") + w;
  return text;
}

TEST(DocsSynopsis, OptionsWrittenAreTheOptionsTheProgramTakes) {
  ScratchDir dir;
  const std::vector<Synopsis> synopses = allSynopses();
  ASSERT_FALSE(synopses.empty()) << "no synopsis found in README.md or docs/";

  std::map<std::string, std::set<std::string>> written;  // command -> options in any of its synopses
  std::map<std::string, std::set<std::string>> listed;   // command -> options its --help lists
  for (const Synopsis& s : synopses) {
    ASSERT_FALSE(s.command.empty()) << s.where << ": a synopsis that names no command";
    written[s.command].insert(s.options.begin(), s.options.end());
    if (listed.count(s.command) == 0) {
      const ProcessResult help = runTidepool(s.command + " --help", dir);
      EXPECT_EQ(help.exitCode, 0) << s.where << ": `tidepool " << s.command << " --help` failed:\n" << help.err;
      listed[s.command] = helpOptions(help.out);
      EXPECT_FALSE(listed[s.command].empty()) << "`tidepool " << s.command << " --help` lists no option:\n" << help.out;
    }
    for (const std::string& option : s.options) {
      EXPECT_EQ(listed[s.command].count(option), 1u)
          << s.where << ": `tidepool " << s.command << "` has no option " << option << " (its --help lists "
          << join(listed[s.command]) << ")";
    }
  }
  for (const auto& [command, options] : listed) {
    for (const std::string& option : options) {
      EXPECT_EQ(written[command].count(option), 1u)
          << "`tidepool " << command << " --help` lists " << option << ", which no synopsis of `tidepool " << command
          << "` in README.md or docs/ writes";
    }
  }
}

TEST(DocsSynopsis, EveryCommandHasASynopsis) {
  ScratchDir dir;
  std::set<std::string> documented;
  for (const Synopsis& s : allSynopses()) documented.insert(s.command);

  const ProcessResult top = runTidepool("--help", dir);
  ASSERT_EQ(top.exitCode, 0) << top.err;
  const std::vector<std::string> commands = helpSubcommands(top.out);
  ASSERT_NE(std::find(commands.begin(), commands.end(), "render"), commands.end())
      << "no subcommands read from `tidepool --help`:\n"
      << top.out;
  for (const std::string& command : commands) {
    const ProcessResult help = runTidepool(command + " --help", dir);
    ASSERT_EQ(help.exitCode, 0) << command << ": " << help.err;
    const std::vector<std::string> subcommands = helpSubcommands(help.out);
    std::vector<std::string> leaves;
    if (subcommands.empty()) leaves.push_back(command);
    for (const std::string& sub : subcommands) leaves.push_back(command + " " + sub);
    for (const std::string& leaf : leaves) {
      EXPECT_EQ(documented.count(leaf), 1u) << "`tidepool " << leaf << "` has no synopsis in README.md or docs/";
    }
  }
}

}  // namespace
}  // namespace tp::test
