#include "io/water_state_file.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "io/image_io.hpp"

namespace tp::io {
namespace {

std::vector<double> parseNumbers(const std::string& spec, const std::string& body, size_t count) {
  std::vector<double> values;
  std::stringstream in(body);
  std::string item;
  while (std::getline(in, item, ',')) {
    size_t used = 0;
    double value = 0.0;
    try {
      value = std::stod(item, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || used != item.size() || !std::isfinite(value)) {
      throw std::runtime_error("--init " + spec + ": '" + item + "' is not a finite number");
    }
    values.push_back(value);
  }
  if (values.size() != count) {
    throw std::runtime_error("--init " + spec + ": expected " + std::to_string(count) + " comma-separated numbers");
  }
  return values;
}

}  // namespace

sim::WaterState initialState(const std::string& spec, const sim::WaterParams& params, double dt) {
  const uint32_t n = params.n;
  if (spec.rfind("drop:", 0) == 0 || spec.rfind("mode:", 0) == 0) {
    if (n < 2) throw std::runtime_error("--init " + spec + " needs --grid N with N >= 2");
    sim::WaterState s;
    if (spec[0] == 'd') {
      auto a = parseNumbers(spec, spec.substr(5), 4);
      if (a[2] <= 0.0) throw std::runtime_error("--init " + spec + ": the radius must be positive");
      s = sim::flatState(n);
      sim::addDrop(s, params.extent, a[0], a[1], a[2], a[3]);
    } else {
      auto a = parseNumbers(spec, spec.substr(5), 3);
      if (a[0] != std::floor(a[0]) || a[1] != std::floor(a[1]) || a[0] < 0 || a[1] < 0 || a[0] > 1e6 || a[1] > 1e6) {
        throw std::runtime_error("--init " + spec + ": M and N must be non-negative integers");
      }
      s = sim::modeState(n, params.extent, int(a[0]), int(a[1]), a[2]);
    }
    sim::startAtRest(s, params, dt);
    return s;
  }
  sim::WaterState s = readStateExr(spec);
  if (n != 0 && s.n != n) {
    throw std::runtime_error("--init " + spec + ": the file holds a " + std::to_string(s.n) + "x" +
                             std::to_string(s.n) + " grid, but --grid asks for " + std::to_string(n));
  }
  return s;
}

void writeStateExr(const std::string& path, const sim::WaterState& s) {
  FloatImage image{s.n, s.n, {"u", "v"}, std::vector<float>(size_t(s.n) * s.n * 2)};
  for (size_t k = 0; k < s.u.size(); ++k) {
    image.pixels[2 * k] = s.u[k];
    image.pixels[2 * k + 1] = s.v[k];
  }
  writeExr(path, image, {PixelType::Float, PixelType::Float});
}

sim::WaterState readStateExr(const std::string& path) {
  FloatImage image = readImage(path);
  int uc = -1, vc = -1;
  for (size_t c = 0; c < image.channels.size(); ++c) {
    if (image.channels[c] == "u") uc = int(c);
    if (image.channels[c] == "v") vc = int(c);
  }
  if (uc < 0 || vc < 0) throw std::runtime_error(path + ": a water state needs channels u and v");
  if (image.width != image.height) {
    throw std::runtime_error(path + ": a water state is square, this image is " + std::to_string(image.width) + "x" +
                             std::to_string(image.height));
  }
  if (image.width < 2) throw std::runtime_error(path + ": a water state needs at least 2x2 cells");
  sim::WaterState s = sim::flatState(image.width);
  const size_t channels = image.channels.size();
  for (size_t k = 0; k < s.u.size(); ++k) {
    s.u[k] = image.pixels[k * channels + uc];
    s.v[k] = image.pixels[k * channels + vc];
    if (!std::isfinite(s.u[k]) || !std::isfinite(s.v[k])) {
      throw std::runtime_error(path + ": non-finite value at cell " + std::to_string(k % s.n) + "," +
                               std::to_string(k / s.n));
    }
  }
  return s;
}

}  // namespace tp::io
