// The EXR that `render` writes, read as a compositor reads it: the AOVs in
// layers (LAYER.COMPONENT, upper-case components), no infinity anywhere,
// alpha 0 on the sky only when asked, the colour, software and frame
// attributes, and each compression asked for.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <set>
#include <string>
#include <vector>

#include "base/rational.hpp"
#include "io/image_io.hpp"
#include "process.hpp"
#include "scene/scene.hpp"

namespace tp::test {
namespace {

const std::string kSmall = " --validate --width 48 --height 32";

// The layer of a channel as Nuke and Blender split its name: before the last
// dot; the base layer's channels (R G B A Z) have none.
std::string layerOf(const std::string& name) {
  const size_t dot = name.rfind('.');
  return dot == std::string::npos ? "" : name.substr(0, dot);
}

// One channel of an image, a value per pixel.
std::vector<float> channel(const io::FloatImage& image, const std::string& name) {
  const auto at = std::find(image.channels.begin(), image.channels.end(), name);
  EXPECT_NE(at, image.channels.end()) << name;
  if (at == image.channels.end()) return {};
  const size_t c = size_t(at - image.channels.begin()), n = image.channels.size();
  std::vector<float> values;
  for (size_t p = c; p < image.pixels.size(); p += n) values.push_back(image.pixels[p]);
  return values;
}

const float kFar = scene::defaultScene().camera.farPlane;

// Renders with `args` into `dir` and reads the EXR back.
io::FloatImage render(const ScratchDir& dir, const std::string& name, const std::string& args) {
  const std::string exr = dir.file(name);
  const ProcessResult r = runTidepool("render" + kSmall + " " + args + " --out " + exr, dir);
  EXPECT_EQ(r.exitCode, 0) << args << "\n" << r.err;
  return io::readImage(exr);
}

TEST(ExrConventions, AovsAreLayersWithUpperCaseComponentsAndNoInfinity) {
  ScratchDir dir;
  const io::FloatImage image = render(dir, "aov.exr", "--aov Z,N,P,ao,ao_raw");
  const std::set<std::string> names(image.channels.begin(), image.channels.end());
  EXPECT_EQ(names, (std::set<std::string>{"R", "G", "B", "A", "Z", "N.X", "N.Y", "N.Z", "P.X", "P.Y", "P.Z", "AO.Y",
                                          "AO_raw.Y"}));
  std::vector<std::string> layers;  // in the order met: each once if grouped
  for (const std::string& name : image.channels) {
    const std::string layer = layerOf(name);
    if (layer.empty()) {
      EXPECT_TRUE(name == "R" || name == "G" || name == "B" || name == "A" || name == "Z") << name;
    } else {
      const std::string component = name.substr(layer.size() + 1);
      EXPECT_TRUE(component.size() == 1 && std::isupper(static_cast<unsigned char>(component[0])) != 0) << name;
    }
    if (layers.empty() || layers.back() != layer) layers.push_back(layer);
  }
  EXPECT_EQ(std::set<std::string>(layers.begin(), layers.end()).size(), layers.size()) << "a layer split apart";
  // OpenImageIO finds the depth and alpha channels by their bare names.
  auto in = OIIO::ImageInput::open(dir.file("aov.exr"));
  ASSERT_TRUE(in);
  EXPECT_GE(in->spec().z_channel, 0);
  EXPECT_EQ(in->spec().z_channel, in->spec().channelindex("Z"));
  EXPECT_EQ(in->spec().alpha_channel, in->spec().channelindex("A"));

  for (size_t i = 0; i < image.pixels.size(); ++i) {
    ASSERT_TRUE(std::isfinite(image.pixels[i]))
        << image.channels[i % image.channels.size()] << " at pixel " << i / image.channels.size();
  }
  // Where nothing is hit, Z is the far plane and P is on it: its view depth is Z.
  const std::vector<float> z = channel(image, "Z"), px = channel(image, "P.X"), py = channel(image, "P.Y"),
                           pz = channel(image, "P.Z");
  const glm::mat4 view = scene::defaultScene().camera.view();
  size_t sky = 0;
  for (size_t p = 0; p < z.size(); ++p) {
    if (z[p] != kFar) continue;
    ++sky;
    const float depth = -(view * glm::vec4(px[p], py[p], pz[p], 1.0f)).z;
    EXPECT_NEAR(depth, kFar, 1e-3f * kFar) << "pixel " << p;
  }
  EXPECT_GT(sky, 0u) << "the default view shows no sky";
  EXPECT_LT(sky, z.size());
}

// Alpha 0 (and RGB 0) exactly where nothing is hit with --transparent-sky, 1
// everywhere without it; the rest of the frame unchanged.
TEST(ExrConventions, TransparentSkyIsAnOptionAndTheReferenceAgrees) {
  ScratchDir dir;
  const io::FloatImage opaque = render(dir, "opaque.exr", "--aov Z");
  const io::FloatImage clear = render(dir, "clear.exr", "--aov Z --transparent-sky");
  for (float a : channel(opaque, "A")) ASSERT_EQ(a, 1.0f);
  const std::vector<float> z = channel(clear, "Z"), a = channel(clear, "A");
  size_t sky = 0;
  for (size_t p = 0; p < z.size(); ++p) {
    const bool nothingHit = z[p] == kFar;
    sky += nothingHit;
    ASSERT_EQ(a[p], nothingHit ? 0.0f : 1.0f) << "pixel " << p;
    for (size_t c = 0; c < 3; ++c) {
      const float before = opaque.pixels[p * 5 + c], after = clear.pixels[p * 5 + c];
      ASSERT_EQ(after, nothingHit ? 0.0f : before) << "pixel " << p << " channel " << c;
    }
  }
  EXPECT_GT(sky, 0u);

  // The CPU reference goes through the same channels: alpha 0 where its rays miss.
  const io::FloatImage reference = render(dir, "reference.exr", "--reference --samples 1 --aov Z --transparent-sky");
  const std::vector<float> rz = channel(reference, "Z"), ra = channel(reference, "A");
  size_t referenceSky = 0;
  for (size_t p = 0; p < rz.size(); ++p) {
    ASSERT_TRUE(std::isfinite(rz[p]));
    referenceSky += rz[p] == kFar;
    ASSERT_EQ(ra[p], rz[p] == kFar ? 0.0f : 1.0f) << "pixel " << p;
  }
  // The two differ only where an edge crosses a pixel centre.
  EXPECT_NEAR(double(referenceSky), double(sky), 0.05 * double(z.size()));
}

TEST(ExrConventions, SequenceFramesCarryColourSoftwareFrameAndRate) {
  ScratchDir dir;
  writeText(dir.file("scene.json"), R"({"water": {"frame_time": 0.04}})");
  const ProcessResult r = runTidepool(
      "render" + kSmall + " --scene " + dir.file("scene.json") + " --frames 2-3 --out " + dir.file("f.####.exr"), dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const ProcessResult version = runTidepool("--version", dir);
  ASSERT_EQ(version.exitCode, 0);
  for (int frame : {2, 3}) {
    auto in = OIIO::ImageInput::open(dir.file("f.000" + std::to_string(frame) + ".exr"));
    ASSERT_TRUE(in);
    const OIIO::ImageSpec& spec = in->spec();
    // By exact name: OpenEXR's readers match attribute names case-sensitively.
    auto attribute = [&](const char* name, OIIO::TypeDesc type) { return spec.find_attribute(name, type, true); };
    const OIIO::ParamValue* chromaticities = attribute("chromaticities", OIIO::TypeDesc(OIIO::TypeDesc::FLOAT, 8));
    ASSERT_TRUE(chromaticities);
    const float* xy = static_cast<const float*>(chromaticities->data());
    const float rec709[8] = {0.64f, 0.33f, 0.30f, 0.60f, 0.15f, 0.06f, 0.3127f, 0.3290f};
    for (int i = 0; i < 8; ++i) EXPECT_FLOAT_EQ(xy[i], rec709[i]) << i;
    const OIIO::ParamValue* software = attribute("software", OIIO::TypeString);
    ASSERT_TRUE(software);
    EXPECT_EQ(software->get_string() + "\n", version.out);
    const OIIO::ParamValue* number = attribute("frame", OIIO::TypeInt);
    ASSERT_TRUE(number);
    EXPECT_EQ(number->get_int(), frame);
    const OIIO::ParamValue* fps = attribute("framesPerSecond", OIIO::TypeRational);
    ASSERT_TRUE(fps) << "no framesPerSecond";
    const int* rate = static_cast<const int*>(fps->data());
    EXPECT_EQ(rate[0], 25);  // 1 / water.frame_time
    EXPECT_EQ(rate[1], 1);
  }
}

TEST(ExrConventions, EachCompressionIsWrittenAndABadOneRefused) {
  ScratchDir dir;
  for (const std::string compression : {"", "zip", "piz", "dwaa", "none"}) {
    const std::string exr = dir.file("c" + compression + ".exr");
    const std::string option = compression.empty() ? "" : " --compression " + compression;
    const ProcessResult r = runTidepool("render" + kSmall + option + " --out " + exr, dir);
    ASSERT_EQ(r.exitCode, 0) << compression << "\n" << r.err;
    auto in = OIIO::ImageInput::open(exr);
    ASSERT_TRUE(in);
    EXPECT_EQ(in->spec().get_string_attribute("compression"), compression.empty() ? "zip" : compression);
  }
  ScratchDir bad;
  const ProcessResult r = runTidepool("render --compression lzma --out " + bad.file("x.exr"), bad);
  EXPECT_EQ(r.exitCode, 2) << r.err;  // a bad command line
  EXPECT_EQ(lineCount(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("lzma"), std::string::npos) << r.err;
  EXPECT_TRUE(bad.entries().empty());
}

TEST(ExrConventions, FrameRatesAreTheNearestVideoRationals) {
  EXPECT_EQ(base::nearestRational(1.0 / double(1.0f / 30.0f), 1001), (base::Rational{30, 1}));
  EXPECT_EQ(base::nearestRational(1.0 / double(0.04f), 1001), (base::Rational{25, 1}));
  EXPECT_EQ(base::nearestRational(30000.0 / 1001.0, 1001), (base::Rational{30000, 1001}));
  EXPECT_EQ(base::nearestRational(24000.0 / 1001.0, 1001), (base::Rational{24000, 1001}));
  EXPECT_EQ(base::nearestRational(62.5, 1001), (base::Rational{125, 2}));
  EXPECT_EQ(base::nearestRational(0.5, 1001), (base::Rational{1, 2}));
  for (double bad : {0.0, -1.0, double(INFINITY), double(NAN)})
    EXPECT_THROW(base::nearestRational(bad, 1001), std::invalid_argument);
}

}  // namespace
}  // namespace tp::test
