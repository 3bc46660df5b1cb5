#pragma once
// The committed pictures the tests render again: the golden images
// (tests/golden/cases.txt) and the gallery (docs/images/gallery.txt). Each
// list names a picture, its scene file and its frame; both are compared the
// same way, in 8-bit sRGB as a viewer sees them.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "io/image_io.hpp"
#include "process.hpp"

namespace tp::test {

struct PictureCase {
  std::string name;
  std::string scene;  // relative to the repository; - for the built-in scene
  unsigned frame = 0;
};

// The cases of a list file (relative to the repository): a line each of name,
// scene and frame; blank lines and lines starting with # left out.
inline std::vector<PictureCase> pictureCases(const std::string& list) {
  std::ifstream in(std::string(TIDEPOOL_SOURCE_DIR) + "/" + list);
  std::vector<PictureCase> cases;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    PictureCase c;
    if (fields >> c.name >> c.scene >> c.frame) cases.push_back(c);
  }
  return cases;
}

// The `tidepool render` arguments that pick a case's scene and frame.
inline std::string pictureSceneArgs(const PictureCase& c) {
  std::string args = " --frame " + std::to_string(c.frame);
  if (c.scene != "-") args += " --scene " + std::string(TIDEPOOL_SOURCE_DIR) + "/" + c.scene;
  return args;
}

// A pixel is off where a channel differs by more than this many 8-bit levels.
constexpr int kPictureLevelsOff = 8;

struct PictureDifference {
  double rmse = 0.0;  // of the R, G and B levels, 0 to 255
  size_t off = 0;     // pixels with a channel off by more than kPictureLevelsOff levels
  size_t pixels = 0;
};

// Two pictures of one size (values 0 to 1, sRGB encoded) in 8-bit levels;
// the alpha (always 1) left out.
inline PictureDifference pictureDifference(const io::FloatImage& a, const io::FloatImage& b) {
  PictureDifference d;
  EXPECT_EQ(a.width, b.width);
  EXPECT_EQ(a.height, b.height);
  EXPECT_EQ(a.channels, b.channels);
  if (a.width != b.width || a.height != b.height || a.channels != b.channels || a.channels.size() < 3) return d;
  const size_t channels = a.channels.size();
  d.pixels = size_t(a.width) * a.height;
  double sumSquares = 0.0;
  for (size_t p = 0; p < d.pixels; ++p) {
    int worst = 0;
    for (size_t k = 0; k < 3; ++k) {
      const int x = int(std::lround(a.pixels[p * channels + k] * 255.0f));
      const int y = int(std::lround(b.pixels[p * channels + k] * 255.0f));
      worst = std::max(worst, std::abs(x - y));
      sumSquares += double(x - y) * (x - y);
    }
    d.off += worst > kPictureLevelsOff;
  }
  d.rmse = std::sqrt(sumSquares / double(d.pixels * 3));
  return d;
}

// A picture rendered again by the build that made it: lavapipe compiles
// shaders for the CPU it runs on, so another machine may round differently
// (a few pixels at edges; the march's bisection may move by a step). A
// change to shading, geometry or the camera moves far more (docs/testing.md
// has the figures). `remedy`: how to make the pictures again when it is meant.
inline void expectRenderedAgain(const PictureDifference& d, const std::string& name, const std::string& remedy) {
  std::printf("%s: RMSE %.3f of 255, %zu of %zu pixels off by more than %d\n", name.c_str(), d.rmse, d.off, d.pixels,
              kPictureLevelsOff);
  EXPECT_LT(d.rmse, 1.0) << name << ": " << remedy;
  EXPECT_LE(d.off, d.pixels / 200) << name;
}

// Renders each case of `list` with `renderArgs` (`tidepool render` options:
// the size, the samples) to a PNG and expects the PNG `folder`/NAME.png
// (both relative to the repository) rendered again.
inline void expectPicturesRenderedAgain(const std::string& list, const std::string& folder,
                                        const std::string& renderArgs, const std::string& remedy) {
  const auto cases = pictureCases(list);
  ASSERT_GE(cases.size(), 4u) << list;
  ScratchDir dir;
  for (const PictureCase& c : cases) {
    const std::string out = dir.file(c.name + ".png");
    const ProcessResult r = runTidepool("render --validate " + renderArgs + pictureSceneArgs(c) + " --out " + out, dir);
    ASSERT_EQ(r.exitCode, 0) << c.name << ": " << r.err;
    const io::FloatImage committed =
        io::readImage(std::string(TIDEPOOL_SOURCE_DIR) + "/" + folder + "/" + c.name + ".png");
    expectRenderedAgain(pictureDifference(io::readImage(out), committed), c.name, remedy);
  }
}

}  // namespace tp::test
