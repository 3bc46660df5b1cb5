// The exit codes of bad input for every command `tidepool --help` lists, as
// docs/command-line.md states them once: 2 for a bad command line (an
// unknown option, a value malformed or out of range, a file named on it that
// does not exist), 1 for what fails after it was read (a file there but not
// valid, an output that cannot be written); each with one line and no file
// left behind.
#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

#include "help_text.hpp"
#include "process.hpp"

namespace tp::test {

TEST(ExitCodes, BadInputOfEveryCommand) {
  ScratchDir dir;
  writeText(dir.file("broken.json"), "{\"camera\": {\"fov\": ");
  writeText(dir.file("text.exr"), "not an image\n");
  writeText(dir.file("file"), "");
  const std::vector<std::string> files{"broken.json", "text.exr", "file"};
  const std::string missingScene = "--scene " + dir.file("missing.json"),
                    brokenScene = "--scene " + dir.file("broken.json");
  const std::string underAFile = dir.file("file/x");  // no folder can be made there
  const std::string exr = " --out " + dir.file("x.exr"), obj = " --out " + dir.file("x.obj");
  struct Case {
    std::string command, args;
    int exitCode;
  };
  const std::vector<Case> cases{
      {"render", "--no-such-option", 2},
      {"render", missingScene, 2},
      {"render", "--size 0x0", 2},
      {"render", "--frames 5-2 --out " + dir.file("f.####.exr"), 2},
      {"render", brokenScene, 1},
      {"render", "--size 8x8 --out " + underAFile + ".png", 1},
      {"export", "--no-such-option" + obj, 2},
      {"export", missingScene + obj, 2},
      {"export", "--frames 5-2 --out " + dir.file("x.####.obj"), 2},
      {"export", brokenScene + obj, 1},
      {"export", "--out " + underAFile + ".obj", 1},
      {"sim", "--no-such-option" + exr, 2},
      {"sim", "--grid 16 --init drop:1,1" + exr, 2},
      {"sim", "--grid 16 --init mode:1.5,1,0.1" + exr, 2},
      {"sim", "--init " + dir.file("missing.exr") + exr, 2},
      {"sim", "--init " + dir.file("text.exr") + exr, 1},
      {"sim", "--grid 16 --steps 1 --out " + underAFile + ".exr", 1},
      {"view", "--no-such-option", 2},
      {"view", missingScene, 2},
      {"view", "--size abc", 2},
      {"help", "nosuch", 2},
      {"help", "--no-such-option", 2},
      {"bench sim", "--grids 8", 2},
      {"bench tiles", "--radii 3", 2},
      {"bench wake", "--speeds 0.01", 2},
      {"bench water", missingScene, 2},
      {"bench ssao", missingScene, 2},
      {"bench frame", missingScene, 2},
      {"bench passes", missingScene, 2},
      {"bench ibl", missingScene, 2},
      {"bench glass", missingScene, 2},
      {"bench truth", "--scenes " + dir.file("missing.json"), 2},
  };
  std::set<std::string> covered;
  for (const Case& c : cases) {
    const std::string args = c.command + " " + c.args;
    EXPECT_EQ(cleanFailure(args, dir, files).exitCode, c.exitCode) << "tidepool " << args;
    covered.insert(c.command);
  }
  // Every command, and every subcommand, has its rows.
  const ProcessResult top = runTidepool("--help", dir);
  ASSERT_EQ(top.exitCode, 0) << top.err;
  const std::vector<std::string> commands = helpSubcommands(top.out);
  ASSERT_GE(commands.size(), 6u) << top.out;
  for (const std::string& command : commands) {
    const std::vector<std::string> subcommands = helpSubcommands(runTidepool(command + " --help", dir).out);
    if (subcommands.empty()) {
      EXPECT_TRUE(covered.contains(command)) << "no bad input of tidepool " << command;
    }
    for (const std::string& sub : subcommands) {
      EXPECT_TRUE(covered.contains(command + " " + sub)) << "no bad input of tidepool " << command << " " << sub;
    }
  }
}

}  // namespace tp::test
