// `export --frames A-B` stopped and resumed as `render --frames` is
// (sequence_test.cpp): a signal ends the run after the frame being written,
// with a line that says so and exit code 128 + the signal, leaving only whole
// files; --resume then writes the rest as one go would have.
#include <gtest/gtest.h>

#include <csignal>
#include <filesystem>
#include <string>

#include "process.hpp"

namespace tp::test {
namespace {

constexpr const char* kExport = "export --set water.grid=32 ";

std::string frameName(uint32_t frame, const char* extension) {
  char name[32];
  std::snprintf(name, sizeof name, "p.%04u.%s", frame, extension);
  return name;
}

}  // namespace

TEST(ExportSequence, SignalsStopAfterAWholeFrame) {
  // SIGTERM first: a run that does not catch the signals dies by it there and
  // fails the test at once (a shell's background job ignores SIGINT).
  for (const int signal : {SIGTERM, SIGINT}) {
    const std::string name = signal == SIGINT ? "SIGINT" : "SIGTERM";
    SCOPED_TRACE(name);
    ScratchDir dir;
    for (const char* folder : {"f", "g"}) std::filesystem::create_directory(dir.file(folder));
    const std::string pattern = dir.file("f/p.####.obj");
    const ProcessResult stopped = runUntilSignalled(std::string(kExport) + "--frames 0-5000 --out " + pattern, dir,
                                                    dir.file("f/" + frameName(1, "obj")), signal);
    EXPECT_EQ(stopped.exitCode, 128 + signal);
    ASSERT_NE(stopped.err.find("export: stopped by " + name + " after "), std::string::npos) << stopped.err;
    EXPECT_NE(stopped.err.find("run again with --resume to export the rest"), std::string::npos) << stopped.err;
    uint32_t objs = 0, mtls = 0;
    for (const auto& e : std::filesystem::directory_iterator(dir.file("f"))) {
      const std::string file = e.path().filename().string();
      EXPECT_EQ(file.size(), frameName(0, "obj").size()) << "a temporary file was left: " << file;
      (file.ends_with(".obj") ? objs : mtls) += 1;
    }
    EXPECT_GE(objs, 2u);
    EXPECT_LT(objs, 5001u);
    EXPECT_EQ(mtls, objs) << "each OBJ with its .mtl";
    // The rest, resumed: the frames there are left as they are, and the new
    // ones equal a run straight to them.
    const std::string last = std::to_string(objs + 1);
    const ProcessResult rest =
        runTidepool(std::string(kExport) + "--frames 0-" + last + " --resume --out " + pattern, dir);
    ASSERT_EQ(rest.exitCode, 0) << rest.err;
    EXPECT_NE(rest.out.find("frames 0-" + last + ": " + std::to_string(objs) + " already written, 2 to export"),
              std::string::npos)
        << rest.out;
    const ProcessResult straight = runTidepool(
        std::string(kExport) + "--frames " + std::to_string(objs) + "-" + last + " --out " + dir.file("g/p.####.obj"),
        dir);
    ASSERT_EQ(straight.exitCode, 0) << straight.err;
    for (uint32_t f = objs; f <= objs + 1; ++f) {
      for (const char* extension : {"obj", "mtl"}) {
        // Compared whole but not printed: gtest's diff of two long texts would not end.
        EXPECT_TRUE(readText(dir.file("f/" + frameName(f, extension))) ==
                    readText(dir.file("g/" + frameName(f, extension))))
            << frameName(f, extension);
      }
    }
    const ProcessResult again =
        runTidepool(std::string(kExport) + "--frames 0-" + last + " --resume --out " + pattern, dir);
    EXPECT_NE(again.out.find("all " + std::to_string(objs + 2) + " already written"), std::string::npos) << again.out;
  }
}

}  // namespace tp::test
