// The tidepool executable as a user runs it: what it writes, and how it
// refuses bad input (one line on stderr, a non-zero exit, no file left).
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <cmath>
#include <fstream>

#include "io/image_io.hpp"
#include "process.hpp"
#include "scene/scene.hpp"

namespace tp::test {
TEST(Cli, RenderWritesExrPngAndProfile) {
  ScratchDir dir;
  const std::string exr = dir.file("frame.exr"), png = dir.file("frame.png");
  ProcessResult r =
      runTidepool("render --width 96 --height 64 --out " + exr + " --png " + png + " --validate --profile", dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.err.find("validation: 0 warnings, 0 errors"), std::string::npos) << r.err;
  // The profile is of a frame after a first one (cached passes such as the
  // sky's do not run again), every pass timed by wall clock and by timestamps.
  for (const char* pass : {"pass", "wall ms", "GPU ms", "ground", "water", "resolve", "total"}) {
    EXPECT_NE(r.out.find(pass), std::string::npos) << pass << " missing from:\n" << r.out;
  }
  EXPECT_EQ(r.out.find("n/a"), std::string::npos) << r.out;

  auto in = OIIO::ImageInput::open(exr);
  ASSERT_TRUE(in);
  const OIIO::ImageSpec& spec = in->spec();
  EXPECT_EQ(spec.width, 96);
  EXPECT_EQ(spec.height, 64);
  EXPECT_EQ(spec.channelnames, (std::vector<std::string>{"R", "G", "B", "A"}));
  EXPECT_EQ(spec.format, OIIO::TypeDesc::HALF);
  const OIIO::ParamValue* w2c = spec.find_attribute("worldToCamera", OIIO::TypeMatrix44);
  const OIIO::ParamValue* w2ndc = spec.find_attribute("worldToNDC", OIIO::TypeMatrix44);
  ASSERT_TRUE(w2c);
  ASSERT_TRUE(w2ndc);
  // OpenEXR's row-vector matrix is the transpose of the column-vector view matrix.
  const float* m = static_cast<const float*>(w2c->data());
  const glm::mat4 view = scene::defaultScene().camera.view();
  for (int row = 0; row < 4; ++row) {
    for (int col = 0; col < 4; ++col) EXPECT_FLOAT_EQ(m[row * 4 + col], view[row][col]) << row << "," << col;
  }
  in->close();

  io::FloatImage image = io::readImage(exr);
  for (float v : image.pixels) ASSERT_TRUE(std::isfinite(v));
  float maxValue = *std::max_element(image.pixels.begin(), image.pixels.end());
  EXPECT_GT(maxValue, 0.1f);  // not a black frame

  io::FloatImage preview = io::readImage(png);
  EXPECT_EQ(preview.width, 96u);
  EXPECT_EQ(preview.height, 64u);
  EXPECT_EQ(preview.channels.size(), 4u);
}

TEST(Cli, AovsAreFloatChannelsAfterRgba) {
  ScratchDir dir;
  const std::string exr = dir.file("aov.exr");
  ProcessResult r = runTidepool("render --validate --width 64 --height 40 --aov P,Z,N --out " + exr, dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  auto in = OIIO::ImageInput::open(exr);
  ASSERT_TRUE(in);
  const OIIO::ImageSpec& spec = in->spec();
  EXPECT_EQ(spec.channelnames,
            (std::vector<std::string>{"R", "G", "B", "A", "Z", "N.X", "N.Y", "N.Z", "P.X", "P.Y", "P.Z"}));
  ASSERT_EQ(spec.channelformats.size(), 11u);
  EXPECT_EQ(spec.channelformats[0], OIIO::TypeDesc::HALF);
  EXPECT_EQ(spec.channelformats[4], OIIO::TypeDesc::FLOAT);
  EXPECT_EQ(spec.channelformats[10], OIIO::TypeDesc::FLOAT);
  ScratchDir again;
  EXPECT_NE(expectCleanFailure("render --aov Z,Q --out " + again.file("x.exr"), again, {}).find("Q"),
            std::string::npos);
}

TEST(Cli, ReferenceWritesTheRasterLayoutAndReportsProgress) {
  ScratchDir dir;
  const std::string exr = dir.file("ref.exr"), png = dir.file("ref.png");
  ProcessResult r =
      runTidepool("render --reference --samples 4 --frame 3 --validate --width 48 --height 32 --aov Z,N --out " + exr +
                      " --png " + png,
                  dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.err.find("reference: 100%"), std::string::npos) << r.err;
  EXPECT_TRUE(std::filesystem::is_regular_file(png));
  auto in = OIIO::ImageInput::open(exr);
  ASSERT_TRUE(in);
  EXPECT_EQ(in->spec().channelnames, (std::vector<std::string>{"R", "G", "B", "A", "Z", "N.X", "N.Y", "N.Z"}));
  ScratchDir bad;
  const std::string out = " --out " + bad.file("x.exr");
  expectCleanFailure("render --reference --samples 0" + out, bad, {});
  expectCleanFailure("render --reference --profile" + out, bad, {});
  expectUsageError("render --seed 3" + out, bad);                           // the path tracer's alone
  expectUsageError("render --reference-model --time-budget 5" + out, bad);  // likewise
  expectUsageError("render --reference --time-budget -1" + out, bad);
  expectUsageError("render --reference --time-budget soon" + out, bad);
  expectUsageError("render --reference --reference-model" + out, bad);
}

TEST(Cli, ReferenceSeedsGiveTheSameBitsOrIndependentNoise) {
  ScratchDir dir;
  const std::string base = "render --reference --samples 2 --size 32x18 --set sky.clouds.coverage=0 --out ";
  auto pixels = [&](const std::string& name, const std::string& extra) {
    const ProcessResult r = runTidepool(base + dir.file(name) + extra, dir);
    EXPECT_EQ(r.exitCode, 0) << r.err;
    return io::readImage(dir.file(name)).pixels;
  };
  const std::vector<float> a = pixels("a.exr", ""), again = pixels("again.exr", " --seed 0"),
                           other = pixels("other.exr", " --seed 7");
  EXPECT_EQ(a, again);
  EXPECT_NE(a, other);
  // A budget far under one pass's time still renders that pass, and says so.
  const ProcessResult r =
      runTidepool("render --reference --samples 64 --size 32x18 --time-budget 0.001 --out " + dir.file("b.exr"), dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.err.find("time budget of 0.001 s ran out at 2 samples of 64"), std::string::npos) << r.err;
}

TEST(Cli, SameFrameTwiceGivesIdenticalPixels) {
  ScratchDir dir;
  const std::string a = dir.file("a.exr"), b = dir.file("b.exr");
  // --validate: exit 3 on any validation message.
  ASSERT_EQ(runTidepool("render --validate --width 80 --height 48 --float --frame 3 --out " + a, dir).exitCode, 0);
  ASSERT_EQ(runTidepool("render --validate --width 80 --height 48 --float --frame 3 --out " + b, dir).exitCode, 0);
  io::FloatImage ia = io::readImage(a), ib = io::readImage(b);
  ASSERT_EQ(ia.pixels.size(), size_t(80) * 48 * 4);
  EXPECT_EQ(0, std::memcmp(ia.pixels.data(), ib.pixels.data(), ia.pixels.size() * sizeof(float)));
  auto in = OIIO::ImageInput::open(a);
  EXPECT_EQ(in->spec().format, OIIO::TypeDesc::FLOAT);
}

TEST(Cli, HelpAndVersion) {
  ScratchDir dir;
  ProcessResult help = runTidepool("render --help", dir);
  EXPECT_EQ(help.exitCode, 0);
  for (const char* option : {"--scene", "--set", "--size", "--frame", "--out", "--png", "--half", "--float",
                             "--validate", "--device", "--profile"}) {
    EXPECT_NE(help.out.find(option), std::string::npos) << option;
  }
  EXPECT_EQ(runTidepool("--version", dir).exitCode, 0);
}

TEST(Cli, BadCommandLinesFailCleanly) {
  ScratchDir dir;
  const std::string out = " --out " + dir.file("x.exr");
  std::vector<std::string> none;
  expectCleanFailure("", dir, none);
  expectCleanFailure("paint", dir, none);
  expectCleanFailure("render --bogus" + out, dir, none);
  expectCleanFailure("render --width 0" + out, dir, none);
  expectCleanFailure("render --height -3" + out, dir, none);
  expectCleanFailure("render --width 100000" + out, dir, none);
  expectCleanFailure("render --width abc" + out, dir, none);
  expectCleanFailure("render --frame -1" + out, dir, none);
  expectCleanFailure("render --half --float" + out, dir, none);
  EXPECT_NE(expectCleanFailure("render --width 16384 --height 16384" + out, dir, none).find("over the limit"),
            std::string::npos);
  EXPECT_NE(expectCleanFailure("render --device no-such-gpu" + out, dir, none).find("no-such-gpu"), std::string::npos);
}

TEST(Cli, UnwritableOutputsFailCleanly) {
  ScratchDir dir;
  std::vector<std::string> none;
  EXPECT_NE(expectCleanFailure("render --out /dev/null/x.exr", dir, none).find("/dev/null is not a folder"),
            std::string::npos);
  EXPECT_NE(expectUsageError("render --out " + dir.file("x.tiff"), dir, none).find("must be .exr or .png"),
            std::string::npos);
  EXPECT_NE(expectUsageError("render --out " + dir.file("x.exr") + " --png " + dir.file("x.jpg"), dir, none)
                .find("must end in .png"),
            std::string::npos);
  std::filesystem::create_directory(dir.file("taken.exr"));
  EXPECT_NE(expectCleanFailure("render --out " + dir.file("taken.exr"), dir, {"taken.exr"}).find("is a directory"),
            std::string::npos);
  // Creating a file fails only when the writer opens it (root may write anywhere
  // that is not special): the error is still one line and nothing is left.
  expectCleanFailure("render --width 8 --height 8 --out /proc/tidepool-test.exr", dir, {"taken.exr"});
  EXPECT_FALSE(std::filesystem::exists("/proc/tidepool-test.exr"));
}

// An output's folder that is not there is made, with those above it: for
// --out, for the files of a sequence and for --checkpoint-dir; --help says so.
TEST(Cli, OutputFoldersAreMadeWhenNotThere) {
  ScratchDir dir;
  ProcessResult r = runTidepool("render --size 8x8 --out " + dir.file("nodir/deeper/a.png"), dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_TRUE(std::filesystem::is_regular_file(dir.file("nodir/deeper/a.png")));
  r = runTidepool("render --size 8x8 --frames 0-1 --checkpoint-every 1 --checkpoint-dir " + dir.file("int/ck") +
                      " --out " + dir.file("seq/f.#.png"),
                  dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_TRUE(std::filesystem::is_regular_file(dir.file("seq/f.1.png")));
  EXPECT_TRUE(std::filesystem::is_regular_file(dir.file("int/ck/water.000001.json")));
  const ProcessResult help = runTidepool("render --help", dir);
  EXPECT_NE(help.out.find("its folder made if it is not there"), std::string::npos) << help.out;
  EXPECT_NE(help.out.find("machine; made if it is not there"), std::string::npos) << help.out;
}

TEST(Cli, BadSceneFilesFailCleanly) {
  ScratchDir dir;
  const std::string out = " --out " + dir.file("x.exr");
  writeText(dir.file("broken.json"), "{\"camera\": {\"fov\": ");
  writeText(dir.file("unknown.json"), "{\"camera\": {\"fvo\": 40}}");
  writeText(dir.file("type.json"), "{\"ground\": {\"albedo_a\": \"grey\"}}");
  writeText(dir.file("impossible.json"), "{\"camera\": {\"fov\": 0}}");
  std::vector<std::string> files{"broken.json", "unknown.json", "type.json", "impossible.json"};
  expectCleanFailure("render --scene " + dir.file("missing.json") + out, dir, files);
  EXPECT_NE(expectCleanFailure("render --scene " + dir.file("broken.json") + out, dir, files).find("not valid JSON"),
            std::string::npos);
  EXPECT_NE(expectCleanFailure("render --scene " + dir.file("unknown.json") + out, dir, files).find("camera.fvo"),
            std::string::npos);
  EXPECT_NE(expectCleanFailure("render --scene " + dir.file("type.json") + out, dir, files).find("ground.albedo_a"),
            std::string::npos);
  EXPECT_NE(expectCleanFailure("render --scene " + dir.file("impossible.json") + out, dir, files).find("fov"),
            std::string::npos);
}

TEST(Cli, SceneFileRendersTheSameAsTheBuiltInScene) {
  ScratchDir dir;
  const std::string a = dir.file("a.exr"), b = dir.file("b.exr");
  ASSERT_EQ(runTidepool("render --validate --width 64 --height 40 --out " + a, dir).exitCode, 0);
  ASSERT_EQ(runTidepool("render --validate --width 64 --height 40 --scene " + std::string(TIDEPOOL_SOURCE_DIR) +
                            "/scenes/default.json --out " + b,
                        dir)
                .exitCode,
            0);
  EXPECT_EQ(io::readImage(a).pixels, io::readImage(b).pixels);
}

}  // namespace tp::test
