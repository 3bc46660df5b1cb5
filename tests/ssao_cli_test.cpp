// `tidepool render` with ambient occlusion from the command line: the AO
// channels in the EXR, presets, --no-ao, and every bad input failing cleanly.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "io/image_io.hpp"
#include "process.hpp"

namespace tp::test {
namespace {

TEST(SsaoCli, AoChannelsFollowRgba) {
  ScratchDir dir;
  for (const char* preset : {"balanced", "fast"}) {  // full and half resolution
    const std::string exr = dir.file(std::string(preset) + ".exr");
    ProcessResult r = runTidepool("render --validate --width 64 --height 40 --preset " + std::string(preset) +
                                      " --aov ao,ao_raw,ao_ref --out " + exr,
                                  dir);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const io::FloatImage image = io::readImage(exr);
    ASSERT_EQ(image.channels, (std::vector<std::string>{"R", "G", "B", "A", "AO.Y", "AO_raw.Y", "AO_ref.Y"}));
    float lowest[3] = {1.0f, 1.0f, 1.0f};
    for (size_t p = 0; p < size_t(image.width) * image.height; ++p) {
      for (int c = 0; c < 3; ++c) {
        const float v = image.pixels[p * 7 + 4 + c];
        ASSERT_TRUE(v >= 0.0f && v <= 1.0f) << image.channels[4 + c] << " = " << v;
        lowest[c] = std::min(lowest[c], v);
      }
    }
    for (int c = 0; c < 3; ++c)
      EXPECT_LT(lowest[c], 0.9f) << preset << " " << image.channels[4 + c] << ": no crease darkened";
  }
}

TEST(SsaoCli, NoAoLeavesTheAmbientAlone) {
  ScratchDir dir;
  const std::string with = dir.file("with.exr"), without = dir.file("without.exr");
  ASSERT_EQ(runTidepool("render --validate --width 64 --height 40 --float --out " + with, dir).exitCode, 0);
  ASSERT_EQ(runTidepool("render --validate --width 64 --height 40 --float --no-ao --out " + without, dir).exitCode, 0);
  const io::FloatImage a = io::readImage(with), b = io::readImage(without);
  int darker = 0, brighter = 0;
  for (size_t k = 0; k < a.pixels.size(); ++k) {
    darker += a.pixels[k] < b.pixels[k] - 1e-6f;
    brighter += a.pixels[k] > b.pixels[k] + 1e-6f;
  }
  EXPECT_GT(darker, 20);   // AO takes light from the creases...
  EXPECT_EQ(brighter, 0);  // ...and adds none anywhere
}

TEST(SsaoCli, BadAoInputFailsCleanly) {
  ScratchDir dir;
  const std::string out = " --width 32 --height 20 --out " + dir.file("x.exr");
  expectCleanFailure("render --no-ao --aov ao" + out, dir, {});
  expectCleanFailure("render --reference --aov ao_ref" + out, dir, {});
  expectCleanFailure("render --preset nope" + out, dir, {});
  expectCleanFailure("render --preset fast --no-ao" + out, dir, {});
  const std::vector<std::pair<std::string, std::string>> scenes{
      {R"({"ao": {"preset": "nope"}})", "ao.preset"},
      {R"({"ao": {"blur": "gauss"}})", "ao.blur"},
      {R"({"ao": {"kernel_size": 65}})", "ao.kernel_size"},
      {R"({"ao": {"kernel_size": 0}})", "ao.kernel_size"},
      {R"({"ao": {"resolution": "quarter"}})", "ao.resolution"},
      {R"({"ao": {"radius": -1}})", "ao.radius"},
      {R"({"ao": {"noise_size": 9}})", "ao.noise_size"},
      {R"({"ao": {"depth_lookup": "cubic"}})", "ao.depth_lookup"},
      {R"({"ao": {"sample_count": 8}})", "sample_count"},
  };
  for (const auto& [text, key] : scenes) {
    const std::string scene = dir.file("bad.json");
    writeText(scene, text);
    const std::string line = expectCleanFailure("render --scene " + scene + out, dir, {"bad.json"});
    EXPECT_NE(line.find(key), std::string::npos) << text << " -> " << line;
  }
  expectCleanFailure("bench ssao --resolution 4x4 --csv " + dir.file("b.csv") + " --plot " + dir.file("b.png"), dir,
                     {"bad.json"});
}

}  // namespace
}  // namespace tp::test
