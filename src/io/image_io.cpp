#include "io/image_io.hpp"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <stdexcept>

#include "base/atomic_file.hpp"

namespace tp::io {
namespace {

std::string oiioError(const std::string& fallback) {
  std::string e = OIIO::geterror();
  return e.empty() ? fallback : e;
}

// Replaces newlines so that an OpenImageIO message stays on one line.
std::string oneLine(std::string s) {
  std::replace(s.begin(), s.end(), '\n', ' ');
  while (!s.empty() && s.back() == ' ') s.pop_back();
  return s;
}

void writeWithOiio(const std::string& path, const OIIO::ImageSpec& spec, OIIO::TypeDesc dataType, const void* data) {
  base::AtomicFile file(path);
  auto out = OIIO::ImageOutput::create(file.tempPath());
  if (!out) throw std::runtime_error("cannot write " + path + ": " + oneLine(oiioError("no writer for this format")));
  if (!out->open(file.tempPath(), spec) || !out->write_image(dataType, data) || !out->close()) {
    std::string e = out->geterror();
    throw std::runtime_error("cannot write " + path + ": " + oneLine(e.empty() ? "write failed" : e));
  }
  out.reset();
  file.commit();
}

// OpenEXR's chromaticities of linear Rec.709 (sRGB's primaries): red, green,
// blue and white (D65) as CIE xy.
constexpr float kRec709Chromaticities[8] = {0.64f, 0.33f, 0.30f, 0.60f, 0.15f, 0.06f, 0.3127f, 0.3290f};

}  // namespace

const std::vector<std::string>& exrCompressions() {
  static const std::vector<std::string> names{"zip", "piz", "dwaa", "none"};
  return names;
}

void writeExr(const std::string& path, const FloatImage& image, const std::vector<PixelType>& channelTypes,
              const ExrAttributes& attributes) {
  base::requireExtension(path, ".exr");
  const size_t channels = image.channels.size();
  if (image.pixels.size() != size_t(image.width) * image.height * channels || channelTypes.size() != channels) {
    throw std::logic_error("writeExr: pixel or channel-type count does not match");
  }
  auto typeOf = [](PixelType t) { return t == PixelType::Half ? OIIO::TypeDesc::HALF : OIIO::TypeDesc::FLOAT; };
  OIIO::ImageSpec spec(int(image.width), int(image.height), int(channels), typeOf(channelTypes[0]));
  spec.channelnames = image.channels;
  if (std::any_of(channelTypes.begin(), channelTypes.end(), [&](PixelType t) { return t != channelTypes[0]; })) {
    for (PixelType t : channelTypes) spec.channelformats.push_back(typeOf(t));
  }
  spec.alpha_channel = -1;
  for (size_t c = 0; c < channels; ++c) {
    if (image.channels[c] == "A") spec.alpha_channel = int(c);
  }
  const auto& compressions = exrCompressions();
  if (std::find(compressions.begin(), compressions.end(), attributes.compression) == compressions.end()) {
    std::string known;
    for (const std::string& name : compressions) known += (known.empty() ? "" : ", ") + name;
    throw std::invalid_argument("EXR compression " + attributes.compression + " is not one of " + known);
  }
  spec.attribute("compression", attributes.compression);
  if (attributes.linearRec709) {
    spec.attribute("chromaticities", OIIO::TypeDesc(OIIO::TypeDesc::FLOAT, 8), kRec709Chromaticities);
  }
  if (!attributes.software.empty()) spec.attribute("software", attributes.software);
  if (attributes.frame) spec.attribute("frame", int(*attributes.frame));
  if (attributes.framesPerSecond) {
    // OpenEXR's standard name; OpenImageIO's own FramesPerSecond would be
    // written with its capital F, which other readers do not know.
    const int fps[2] = {attributes.framesPerSecond->numerator, attributes.framesPerSecond->denominator};
    spec.attribute("framesPerSecond", OIIO::TypeRational, fps);
  }
  if (attributes.hasCamera) {
    // GLM's column-major storage of M is the row-major storage of M^T, which is
    // OpenEXR's row-vector form of the same transform.
    spec.attribute("worldToCamera", OIIO::TypeMatrix44, &attributes.worldToCamera[0][0]);
    spec.attribute("worldToNDC", OIIO::TypeMatrix44, &attributes.worldToNDC[0][0]);
  }
  writeWithOiio(path, spec, OIIO::TypeDesc::FLOAT, image.pixels.data());
}

FloatImage readImage(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) throw std::runtime_error("cannot read " + path + ": not a file");
  auto in = OIIO::ImageInput::open(path);
  if (!in) throw std::runtime_error("cannot read " + path + ": " + oneLine(oiioError("unknown format")));
  const OIIO::ImageSpec& spec = in->spec();
  if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0 || spec.depth != 1) {
    throw std::runtime_error("cannot read " + path + ": not a 2D image");
  }
  // A header may declare any size: refuse what no image of ours reaches
  // before memory is taken for it (OpenImageIO buffers many rows of a wide
  // image at once: a 3,211,272 x 8 file made it ask for 6.5 GB).
  if (spec.width > kMaxImageSide || spec.height > kMaxImageSide ||
      uint64_t(spec.width) * spec.height * spec.nchannels * sizeof(float) > kMaxImageBytes) {
    throw std::runtime_error("cannot read " + path + ": " + std::to_string(spec.width) + "x" +
                             std::to_string(spec.height) + " pixels of " + std::to_string(spec.nchannels) +
                             " channels is over the limit of " + std::to_string(kMaxImageSide) + " a side and " +
                             std::to_string(kMaxImageBytes >> 20) + " MiB of floats");
  }
  FloatImage image;
  image.width = uint32_t(spec.width);
  image.height = uint32_t(spec.height);
  image.channels = spec.channelnames;
  image.pixels.resize(size_t(spec.width) * spec.height * spec.nchannels);
  if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, image.pixels.data())) {
    std::string e = in->geterror();
    throw std::runtime_error("cannot read " + path + ": " + oneLine(e.empty() ? "read failed" : e));
  }
  return image;
}

void writePng(const std::string& path, uint32_t width, uint32_t height, const std::vector<std::uint8_t>& rgba) {
  base::requireExtension(path, ".png");
  if (rgba.size() != size_t(width) * height * 4)
    throw std::logic_error("writePng: pixel count does not match the size");
  OIIO::ImageSpec spec(int(width), int(height), 4, OIIO::TypeDesc::UINT8);
  spec.attribute("oiio:ColorSpace", "sRGB");
  writeWithOiio(path, spec, OIIO::TypeDesc::UINT8, rgba.data());
}

}  // namespace tp::io
