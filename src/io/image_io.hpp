#pragma once
#include <cstdint>
#include <glm/glm.hpp>
#include <optional>
#include <string>
#include <vector>

#include "base/rational.hpp"

namespace tp::io {

enum class PixelType { Half, Float };

// Float channels, interleaved, rows top to bottom (EXR's order).
struct FloatImage {
  uint32_t width = 0;
  uint32_t height = 0;
  std::vector<std::string> channels;  // e.g. R G B A, or u v
  std::vector<float> pixels;          // width * height * channels.size()
};

// The compressions writeExr takes, as OpenEXR names them; the first is the default.
const std::vector<std::string>& exrCompressions();

struct ExrAttributes {
  bool hasCamera = false;
  glm::mat4 worldToCamera{1.0f};  // column-vector matrices, as GLM keeps them
  glm::mat4 worldToNDC{1.0f};
  bool linearRec709 = false;  // colour: chromaticities of Rec.709/sRGB primaries and a D65 white
  std::string software{};     // e.g. "tidepool 0.1"; none when empty
  std::optional<uint32_t> frame{};
  std::optional<base::Rational> framesPerSecond{};
  std::string compression = exrCompressions().front();
};

// Writes an OpenEXR file through a temporary file renamed into place, each
// channel as half or float (channelTypes, one per channel), with the
// attributes' compression (one of exrCompressions(), else it throws).
// The camera matrices become the standard m44f attributes worldToCamera and
// worldToNDC, in OpenEXR's row-vector convention; the others the standard
// chromaticities and framesPerSecond, and software (string) and frame (int).
void writeExr(const std::string& path, const FloatImage& image, const std::vector<PixelType>& channelTypes,
              const ExrAttributes& attributes = {});

// The largest image readImage takes: each side (the largest frame, sky
// texture and water grid have 16384), and all its channels as floats (a
// 16384 x 16384 water state of u and v).
constexpr int kMaxImageSide = 16384;
constexpr uint64_t kMaxImageBytes = uint64_t(16384) * 16384 * 2 * sizeof(float);

// Reads every channel of an image OpenImageIO can read (EXR, HDR) as float.
// Throws with the path and the reason on a missing, unreadable or truncated
// file, or one whose header declares more than the limits above.
FloatImage readImage(const std::string& path);

// Writes an 8-bit RGBA PNG (already sRGB encoded), through a temporary file.
void writePng(const std::string& path, uint32_t width, uint32_t height, const std::vector<std::uint8_t>& rgba);

}  // namespace tp::io
