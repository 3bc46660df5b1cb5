// The golden images: `tidepool render` of the default scene and the example
// scene files against PNGs committed under tests/golden/ (tools/update-golden.sh
// writes them; each was looked at before it was committed). They guard
// against any change to what a frame shows that no other test describes; the
// reference tests say whether the images are right.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "io/image_io.hpp"
#include "process.hpp"

namespace tp::test {
namespace {

struct GoldenCase {
  std::string name, scene;
  unsigned frame = 0;
};

std::vector<GoldenCase> goldenCases() {
  std::ifstream in(std::string(TIDEPOOL_SOURCE_DIR) + "/tests/golden/cases.txt");
  std::vector<GoldenCase> cases;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    GoldenCase c;
    if (fields >> c.name >> c.scene >> c.frame) cases.push_back(c);
  }
  return cases;
}

}  // namespace

// lavapipe compiles shaders for the CPU it runs on, so another machine may
// round differently: a few pixels at edges and the march's bisection may
// move by a step. A change to shading, geometry or the camera moves far more.
TEST(GoldenImage, ScenesMatchTheirGoldenImages) {
  const auto cases = goldenCases();
  ASSERT_GE(cases.size(), 4u) << "tests/golden/cases.txt";
  ScratchDir dir;
  for (const GoldenCase& c : cases) {
    const std::string out = dir.file(c.name + ".png");
    std::string args = "render --validate --width 160 --height 90 --frame " + std::to_string(c.frame) + " --out " +
                       dir.file(c.name + ".exr") + " --png " + out;
    if (c.scene != "-") args += " --scene " + std::string(TIDEPOOL_SOURCE_DIR) + "/" + c.scene;
    const ProcessResult r = runTidepool(args, dir);
    ASSERT_EQ(r.exitCode, 0) << c.name << ": " << r.err;
    const io::FloatImage golden = io::readImage(std::string(TIDEPOOL_SOURCE_DIR) + "/tests/golden/" + c.name + ".png");
    const io::FloatImage image = io::readImage(out);
    ASSERT_EQ(image.width, golden.width) << c.name;
    ASSERT_EQ(image.height, golden.height) << c.name;
    ASSERT_EQ(image.channels, golden.channels) << c.name;
    const size_t channels = golden.channels.size(), pixels = size_t(golden.width) * golden.height;
    ASSERT_GE(channels, 3u) << c.name;
    double sumSquares = 0.0;
    size_t off = 0;
    for (size_t p = 0; p < pixels; ++p) {
      int worst = 0;
      for (size_t k = 0; k < 3; ++k) {  // R, G, B: the alpha is always 1
        const int a = int(std::lround(image.pixels[p * channels + k] * 255.0f));
        const int b = int(std::lround(golden.pixels[p * channels + k] * 255.0f));
        worst = std::max(worst, std::abs(a - b));
        sumSquares += double(a - b) * (a - b);
      }
      off += worst > 8;
    }
    const double rmse = std::sqrt(sumSquares / double(pixels * 3));
    std::printf("%s: RMSE %.3f of 255, %zu of %zu pixels off by more than 8\n", c.name.c_str(), rmse, off, pixels);
    EXPECT_LT(rmse, 1.0) << c.name << ": tools/update-golden.sh rewrites the goldens when the change is meant";
    EXPECT_LE(off, pixels / 200) << c.name;
  }
}

}  // namespace tp::test
