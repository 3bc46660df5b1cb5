#pragma once
// Reading what tidepool prints for --help (CLI11's layout), for the tests
// that check the commands against the docs and against their exit codes.
#include <algorithm>
#include <cctype>
#include <sstream>
#include <string>
#include <vector>

namespace tp::test {

inline std::vector<std::string> splitLines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    lines.push_back(line);
  }
  return lines;
}

inline size_t leadingSpaces(const std::string& line) {
  const size_t first = line.find_first_not_of(' ');
  return first == std::string::npos ? line.size() : first;
}

// The subcommands `--help` lists, under its "Subcommands:" heading (CLI11:
// two spaces, the name, then the description).
inline std::vector<std::string> helpSubcommands(const std::string& help) {
  std::vector<std::string> names;
  bool inList = false;
  for (const std::string& line : splitLines(help)) {
    if (!inList) {
      std::string heading = line;
      std::transform(heading.begin(), heading.end(), heading.begin(),
                     [](char c) { return char(std::tolower(static_cast<unsigned char>(c))); });
      inList = heading == "subcommands:";
      continue;
    }
    if (line.empty() || line.front() != ' ') break;  // the end of the list
    if (leadingSpaces(line) != 2) continue;          // a description carried onto its own line
    std::istringstream words(line);
    std::string name;
    words >> name;
    names.push_back(name);
  }
  return names;
}

}  // namespace tp::test
