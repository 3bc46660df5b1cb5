// The command line every command shares (docs/command-line.md): exit code 2
// and one line naming the nearest word for a bad command line, numbers as
// written, help, --version with its commit, --set, --size and outputs named
// by their extension.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <cstdio>
#include <cstring>
#include <regex>

#include "io/image_io.hpp"
#include "process.hpp"

namespace tp::test {
namespace {

// The words a refusal must hold, for each bad command line.
struct Refusal {
  std::string args;
  std::string says;
};

void expectRefusals(const std::vector<Refusal>& refusals) {
  ScratchDir dir;
  for (const auto& [args, says] : refusals) {
    const std::string err = expectUsageError(args, dir);
    EXPECT_NE(err.find(says), std::string::npos) << "tidepool " << args << "\nsaid: " << err << "expected: " << says;
  }
}

// The first line of a command's standard output.
std::string commandOutput(const std::string& command) {
  std::string text;
  if (FILE* pipe = popen(command.c_str(), "r")) {
    char buffer[256];
    while (std::fgets(buffer, sizeof buffer, pipe)) text += buffer;
    pclose(pipe);
  }
  return text.substr(0, text.find('\n'));
}

}  // namespace

TEST(CommandLine, MisspelledCommandsAndOptionsNameTheNearest) {
  expectRefusals({
      {"", "a command is needed: render, sim, export, bench, view or help"},
      {"rendr", "unknown command rendr; did you mean render?"},
      {"--verison", "unknown option --verison; did you mean --version?"},
      {"bench foo", "bench: unknown command foo; the commands are sim, tiles, wake"},
      {"bench", "bench: a command is needed: sim, tiles"},
      {"bench watr", "did you mean water?"},
      {"render --sizee 64x40", "render: unknown option --sizee; did you mean --size?"},
      {"render --widht 100", "did you mean --width? (the old spelling of --size, one side)"},
      {"render --bogus", "render: unknown option --bogus (see tidepool help render)"},
      {"render extra", "render: unexpected argument extra"},
      {"help rendr", "help rendr: tidepool has no command rendr; did you mean render?"},
      {"help bench wter", "tidepool bench has no command wter; did you mean water?"},
  });
}

TEST(CommandLine, BadValuesExitTwoInTheUsersWords) {
  expectRefusals({
      {"render --width abc", "--width: abc is not a whole number"},
      {"render --width 0", "--width: 0 is outside 1 to 16384"},
      {"render --height -3", "--height: -3 is outside 1 to 16384"},
      {"render --frame -1", "--frame: -1: a frame number is 0 or more"},
      {"export --frame -1 --out x.obj", "--frame: -1: a frame number is 0 or more"},
      {"bench water --frame -1", "--frame: -1: a frame number is 0 or more"},
      {"render --size 12x", "--size: 12x is not WxH with each side 1 to 16384"},
      {"render --size 10x10 --width 5", "--size 10x10: not with --width or --height"},
      {"render --profile --samples 4", "--profile times the passes of one frame: not with --samples 4"},
      {"render --samples 0", "--samples: 0 is outside 1 to 65536"},
      {"render --size 16384x16384", "over the limit"},
      {"render --frames 5-2", "--frames 5-2: expected A-B"},
      {"render --frames 0-1 --out x.exr", "--frames 0-1: the output x.exr needs ####"},
      {"render --frames 0-1 --out 'x.$F4.####.exr'", "the output x.$F4.####.exr has two places for the frame"},
      {"export --frames 0-1 --out 'x.%04d.%d.obj'", "the output x.%04d.%d.obj has two places for the frame"},
      {"render --checkpoint-every 2 --frames 0-1 --out x.####.exr", "--checkpoint-every needs --checkpoint-dir"},
      {"bench tiles --radii 3", "--radii: 3 is outside 0 to 2"},
      {"bench wake --speeds 0.01", "--speeds: 0.01 is outside 0.05 to 2"},
      {"bench sim --grids 8", "--grids: 8 is outside 16 to 8192"},
      {"bench water --size 4x4", "--size: 4x4 is not WxH with each side 8 to 4096"},
      {"view --size abc", "--size: abc is not WxH"},
      {"view --target-fps 0.5", "--target-fps: 0.5 is outside 1 to 1000"},
      {"sim --dt 10 --out x.exr", "exceeds the 2D stability bound"},
      {"sim --extent -1 --out x.exr", "extent must be positive and finite, got -1"},
  });
}

TEST(CommandLine, OutputsTakeTheirFormatFromTheExtension) {
  expectRefusals({
      {"render --out foo.tif", "--out foo.tif: the format comes from the extension, which must be .exr or .png"},
      {"render --out a.exr --out b.exr", "--out b.exr: a second output of its format"},
      {"render --out a.png --out b.png", "--out b.png: a second output of its format"},
      {"render --out a.png --aov Z", "--aov: the AOVs are EXR channels"},
      {"render --png a.jpg", "--png a.jpg: the path must end in .png"},
      {"export --out mesh.stl",
       "--out mesh.stl: the format comes from the extension, which must be .obj, .ply, .glb or .exr"},
  });

  // Run in the scratch folder, where the default render.exr goes.
  ScratchDir dir;
  const std::string here = "cd " + dir.path().string() + " &&";
  // A PNG alone: no EXR beside it.
  ProcessResult r = runTidepool("render --size 48x32 --out only.png --validate", dir, here);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"only.png"});
  auto in = OIIO::ImageInput::open(dir.file("only.png"));
  ASSERT_TRUE(in);
  EXPECT_EQ(in->format_name(), std::string("png"));
  EXPECT_EQ(in->spec().width, 48);
  EXPECT_EQ(in->spec().height, 32);
  in->close();

  // Both, in either order; and the old --png beside the default EXR.
  r = runTidepool("render --size 48x32 --out both.png --out both.exr --validate", dir, here);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(io::readImage(dir.file("both.exr")).width, 48u);
  EXPECT_EQ(io::readImage(dir.file("both.png")).width, 48u);
  r = runTidepool("render --size 48x32 --png old.png --validate", dir, here);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_TRUE(std::filesystem::exists(dir.file("render.exr")));
  EXPECT_TRUE(std::filesystem::exists(dir.file("old.png")));

  // A sequence of PNGs alone, its pattern in printf's way, and the EXRs beside them in Houdini's.
  ScratchDir frames;
  r = runTidepool("render --size 48x32 --frames 0-1 --out " + frames.file("f.%04d.png") + " --out '" +
                      frames.file("f.$F2.exr") + "' --validate",
                  frames);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  std::vector<std::string> written = frames.entries();
  std::sort(written.begin(), written.end());
  EXPECT_EQ(written, (std::vector<std::string>{"f.00.exr", "f.0000.png", "f.0001.png", "f.01.exr"}));
}

// --set changes the scene exactly as the scene file's key does.
TEST(CommandLine, SetRendersAsTheSceneFileWithTheKeyChanged) {
  ScratchDir dir;
  writeText(dir.file("narrow.json"), R"({"camera": {"fov": 30}, "water": {"wave_speed": 0.8}})");
  const std::string size = "render --size 64x40 --frame 3 --validate";
  ASSERT_EQ(runTidepool(size + " --scene " + dir.file("narrow.json") + " --out " + dir.file("file.exr"), dir).exitCode,
            0);
  ProcessResult r =
      runTidepool(size + " --set camera.fov=30 --set water.wave_speed=0.8 --out " + dir.file("set.exr"), dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  ASSERT_EQ(runTidepool(size + " --out " + dir.file("default.exr"), dir).exitCode, 0);
  const io::FloatImage file = io::readImage(dir.file("file.exr")), set = io::readImage(dir.file("set.exr")),
                       plain = io::readImage(dir.file("default.exr"));
  ASSERT_EQ(file.pixels.size(), set.pixels.size());
  EXPECT_EQ(0, std::memcmp(file.pixels.data(), set.pixels.data(), file.pixels.size() * sizeof(float)));
  EXPECT_NE(0, std::memcmp(plain.pixels.data(), set.pixels.data(), plain.pixels.size() * sizeof(float)));

  expectRefusals({
      {"render --set water.grdi=3", "--set water.grdi=3: water.grdi: not a key of the scene; did you mean water.grid?"},
      {"render --set wter.grid=3", "did you mean water.grid?"},
      {"render --set spheres.0.radus=1", "did you mean spheres.0.radius?"},
      {"render --set spheres.1.radius=1",
       "spheres has 1 element (0); to add one, set it whole: --set 'spheres.1={...}'"},
      {"render --set camera.fov=0", "--set camera.fov=0: camera fov 0 degrees is outside (0, 180)"},
      {"render --set water.level=0.3", "water.level 0.3 must be below the pool's rim, the ground at 0"},
      {"render --set novalue", "--set novalue: expected KEY=VALUE"},
      {"export --set camera.fvo=40 --out m.obj", "did you mean camera.fov?"},
      {"bench ssao --set ao.radus=1", "did you mean ao.radius?"},
  });
}

TEST(CommandLine, HelpCommandPrintsWhatHelpOptionsPrint) {
  ScratchDir dir;
  const ProcessResult top = runTidepool("help", dir);
  ASSERT_EQ(top.exitCode, 0) << top.err;
  EXPECT_EQ(top.out, runTidepool("--help", dir).out);
  EXPECT_NE(top.out.find("Usage: tidepool [OPTIONS] SUBCOMMAND"), std::string::npos) << top.out;
  const ProcessResult all = runTidepool("help --all", dir);
  ASSERT_EQ(all.exitCode, 0) << all.err;
  for (const char* option : {"--target-fps", "--checkpoint-dir", "--grid-damping"}) {
    EXPECT_NE(all.out.find(option), std::string::npos) << option << " missing from:\n" << all.out;
  }
  for (const char* command : {"render", "view", "export", "bench water", "bench sim"}) {
    const ProcessResult help = runTidepool(std::string("help ") + command, dir);
    EXPECT_EQ(help.exitCode, 0) << command << ": " << help.err;
    EXPECT_EQ(help.out, runTidepool(std::string(command) + " --help", dir).out) << command;
    EXPECT_NE(help.out.find(std::string("Usage: tidepool ") + command), std::string::npos) << help.out;
  }
}

// `tidepool help` lists what export writes, the heightfield EXRs included.
TEST(CommandLine, HelpSaysExportWritesHeightfieldSequences) {
  ScratchDir dir;
  const ProcessResult help = runTidepool("help", dir);
  ASSERT_EQ(help.exitCode, 0) << help.err;
  EXPECT_NE(help.out.find("water's heightfield as EXR (an EXR sequence with --frames)"), std::string::npos) << help.out;
}

TEST(CommandLine, VersionNamesTheCommitBuiltFrom) {
  ScratchDir dir;
  const ProcessResult r = runTidepool("--version", dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  std::smatch match;
  ASSERT_TRUE(
      std::regex_match(r.out, match, std::regex("tidepool 0\\.1 \\(commit ([0-9a-f]{12}(-dirty)?|unknown)\\)\n")))
      << r.out;
  // A commit of this repository (a build older than the last commit names an
  // earlier one, so HEAD itself is not required).
  const std::string git = "git -C " + std::string(TIDEPOOL_SOURCE_DIR);
  if (commandOutput(git + " rev-parse --is-inside-work-tree 2>/dev/null") == "true") {
    ASSERT_NE(match[1], "unknown") << "built in a git checkout, yet no commit named";
    EXPECT_EQ(commandOutput(git + " cat-file -t " + match[1].str().substr(0, 12) + " 2>&1"), "commit") << r.out;
  }
}

}  // namespace tp::test
