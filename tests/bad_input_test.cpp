// Bad input that the other suites leave out: a huge scene file,
// NaN and infinity on the command line, broken sky images, a full disk (a
// file size limit: the write fails part way), and water larger than
// the device holds. Each gets one line naming the problem, a non-zero exit
// and no file left behind.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "io/image_io.hpp"
#include "process.hpp"

namespace tp::test {
namespace {

// A shell prefix that limits the size of any file the command writes to
// `kib` KiB and makes a write past it fail (EFBIG) rather than kill the
// process: a disk that fills up part way through a file.
std::string fileSizeLimit(int kib) { return "ulimit -f " + std::to_string(kib * 2) + " && trap '' XFSZ &&"; }

}  // namespace

// A huge scene file through the command line (the parser's own handling of
// huge and deeply nested JSON: SceneFile.HugeAndDeeplyNestedJson): one line.
TEST(BadInput, HugeSceneFile) {
  std::string huge = "{\"water\": {\"wave_speed\": 0.5}, \"junk\": [";
  for (int i = 0; i < 2'000'000; ++i) huge += "1234567.8,";
  huge += "0]}";
  ScratchDir dir;
  writeText(dir.file("huge.json"), huge);
  const std::string line =
      expectCleanFailure("render --out " + dir.file("x.exr") + " --scene " + dir.file("huge.json"), dir, {"huge.json"});
  EXPECT_NE(line.find("junk: is not a known key"), std::string::npos) << line;
}

// Numbers that are not numbers, on the command line.
TEST(BadInput, NanAndInfinityOnTheCommandLine) {
  ScratchDir dir;
  const std::string out = " --out " + dir.file("x.exr");
  for (const char* args : {"--width nan", "--width inf", "--height -1", "--frame nan", "--frame inf", "--frame -1",
                           "--frames nan-3", "--frames 0-inf", "--samples 1e999 --reference"}) {
    expectCleanFailure(std::string("render ") + args + out, dir, {});
  }
  for (const char* args : {"--grid 64 --extent nan", "--grid 64 --dt inf", "--grid 64 --max-slope nan",
                           "--grid 64 --init drop:nan,0,0.1,0.1", "--grid 64 --init mode:1,1,inf"}) {
    expectCleanFailure(std::string("sim ") + args + out, dir, {});
  }
}

// A sky image cut short, and text named like an image: one line naming the file.
TEST(BadInput, BrokenSkyImages) {
  ScratchDir dir;
  io::FloatImage sky{64, 32, {"R", "G", "B"}, std::vector<float>(64 * 32 * 3, 1.0f)};
  io::writeExr(dir.file("whole.exr"), sky, std::vector<io::PixelType>(3, io::PixelType::Float));
  const std::string bytes = readText(dir.file("whole.exr"));
  std::ofstream(dir.file("cut.exr"), std::ios::binary) << bytes.substr(0, bytes.size() / 2);
  std::filesystem::remove(dir.file("whole.exr"));
  writeText(dir.file("text.hdr"), "#?RADIANCE\nthis is not a picture\n");
  writeText(dir.file("cut.json"), "{\"sky\": {\"image\": \"cut.exr\"}}");
  writeText(dir.file("text.json"), "{\"sky\": {\"image\": \"text.hdr\"}}");
  const std::vector<std::string> files{"cut.exr", "text.hdr", "cut.json", "text.json"};
  for (const char* scene : {"cut", "text"}) {
    const std::string line = expectCleanFailure(
        "render --out " + dir.file("x.exr") + " --scene " + dir.file(std::string(scene) + ".json"), dir, files);
    EXPECT_NE(line.find(scene == std::string("cut") ? "cut.exr" : "text.hdr"), std::string::npos) << line;
  }
}

// The disk fills up while an image is written: one line, and neither the
// image nor its temporary file is left.
TEST(BadInput, FullDiskLeavesNoFile) {
  ScratchDir dir;
  const std::string limit = fileSizeLimit(16);  // the frames and meshes below take 70 KB and more
  for (const std::string& args :
       {"render --width 256 --height 144 --out " + dir.file("x.exr"),
        "render --width 256 --height 144 --frames 0-2 --out " + dir.file("f.####.exr"),
        "sim --grid 256 --steps 2 --out " + dir.file("s.exr"), "export --out " + dir.file("m.obj"),
        "export --out " + dir.file("m.ply"), "export --frames 0-1 --out " + dir.file("m.####.glb")}) {
    const std::string line = expectCleanFailure(args, dir, {}, limit);
    EXPECT_NE(line.find("cannot write"), std::string::npos) << args << "\n" << line;
  }
}

// Water larger than one storage buffer of the device holds is refused before
// anything is made (lavapipe: 2896 cells a side at most).
TEST(BadInput, WaterLargerThanTheDeviceHolds) {
  ScratchDir dir;
  writeText(dir.file("big.json"), "{\"water\": {\"grid\": 8192}}");
  const std::string line =
      expectCleanFailure("render --out " + dir.file("x.exr") + " --scene " + dir.file("big.json"), dir, {"big.json"});
  EXPECT_NE(line.find("grid 8192 needs"), std::string::npos) << line;
  EXPECT_NE(line.find("storage buffer limit"), std::string::npos) << line;
}

// A glass sphere of an impossible index, from the command line: one line naming the key.
TEST(BadInput, GlassOfAnImpossibleIndex) {
  ScratchDir dir;
  writeText(dir.file("glass.json"), "{\"spheres\": [{\"material\": \"glass\", \"ior\": 0.9}]}");
  const std::string line = expectCleanFailure(
      "render --out " + dir.file("x.exr") + " --scene " + dir.file("glass.json"), dir, {"glass.json"});
  EXPECT_NE(line.find("spheres[].ior = 0.9 is outside (1, 3]"), std::string::npos) << line;
}

// The same for a glass box.
TEST(BadInput, GlassBoxOfAnImpossibleIndex) {
  ScratchDir dir;
  writeText(dir.file("box.json"), "{\"boxes\": [{\"material\": \"glass\", \"ior\": 4}]}");
  const std::string line =
      expectCleanFailure("render --out " + dir.file("x.exr") + " --scene " + dir.file("box.json"), dir, {"box.json"});
  EXPECT_NE(line.find("boxes[].ior = 4 is outside (1, 3]"), std::string::npos) << line;
}

}  // namespace tp::test
