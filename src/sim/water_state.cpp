#include "sim/water_state.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "io/image_io.hpp"
#include "sim/grid_index.hpp"

namespace tp::sim {
namespace {

constexpr double kPi = 3.14159265358979323846;

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

WaterState flatState(uint32_t n, float level) {
  return WaterState{n, std::vector<float>(size_t(n) * n, level), std::vector<float>(size_t(n) * n, 0.0f)};
}

WaterState modeState(uint32_t n, double extent, int m, int nz, double amplitude, double level) {
  WaterState s = flatState(n);
  const double h = extent / n;
  for (uint32_t j = 0; j < n; ++j) {
    for (uint32_t i = 0; i < n; ++i) {
      const double x = (i + 0.5) * h, z = (j + 0.5) * h;
      s.u[size_t(j) * n + i] = float(level + amplitude * std::cos(m * kPi * x / extent) * std::cos(nz * kPi * z / extent));
    }
  }
  return s;
}

void addDrop(WaterState& s, double extent, double x, double z, double radius, double amplitude) {
  const double h = extent / s.n;
  for (uint32_t j = 0; j < s.n; ++j) {
    for (uint32_t i = 0; i < s.n; ++i) {
      const double r = std::hypot((i + 0.5) * h - x, (j + 0.5) * h - z);
      if (r < radius) s.u[size_t(j) * s.n + i] += float(amplitude * 0.5 * (1.0 + std::cos(kPi * r / radius)));
    }
  }
}

std::vector<shader::WaterCell> toCells(const WaterState& s, double extent) {
  const double h = extent / s.n;
  std::vector<shader::WaterCell> cells(size_t(s.n) * s.n);
  for (uint32_t j = 0; j < s.n; ++j) {
    for (uint32_t i = 0; i < s.n; ++i) {
      const size_t k = size_t(j) * s.n + i;
      cells[k] = {float((i + 0.5) * h), s.u[k], float((j + 0.5) * h), s.v[k]};
    }
  }
  return cells;
}

WaterState fromCells(std::span<const shader::WaterCell> cells, uint32_t n) {
  WaterState s = flatState(n);
  for (size_t k = 0; k < s.u.size(); ++k) {
    s.u[k] = cells[k].u;
    s.v[k] = cells[k].v;
  }
  return s;
}

void startAtRest(WaterState& s, const WaterParams& params, double dt) {
  const long n = s.n;
  const double factor = -0.5 * dt * params.waveSpeed * params.waveSpeed / (params.h() * params.h());
  auto at = [&](long i, long j) { return double(s.u[cellIndex(i, j, s.n, params.boundary)]); };
  for (long j = 0; j < n; ++j) {
    for (long i = 0; i < n; ++i) {
      const double laplacianH2 = at(i - 1, j) + at(i + 1, j) + at(i, j - 1) + at(i, j + 1) - 4.0 * at(i, j);
      s.v[size_t(j) * n + size_t(i)] = float(factor * laplacianH2);
    }
  }
}

WaterState initialState(const std::string& spec, const WaterParams& params, double dt) {
  const uint32_t n = params.n;
  if (spec.rfind("drop:", 0) == 0 || spec.rfind("mode:", 0) == 0) {
    if (n < 2) throw std::runtime_error("--init " + spec + " needs --grid N with N >= 2");
    WaterState s;
    if (spec[0] == 'd') {
      auto a = parseNumbers(spec, spec.substr(5), 4);
      if (a[2] <= 0.0) throw std::runtime_error("--init " + spec + ": the radius must be positive");
      s = flatState(n);
      addDrop(s, params.extent, a[0], a[1], a[2], a[3]);
    } else {
      auto a = parseNumbers(spec, spec.substr(5), 3);
      if (a[0] != std::floor(a[0]) || a[1] != std::floor(a[1]) || a[0] < 0 || a[1] < 0 || a[0] > 1e6 || a[1] > 1e6) {
        throw std::runtime_error("--init " + spec + ": M and N must be non-negative integers");
      }
      s = modeState(n, params.extent, int(a[0]), int(a[1]), a[2]);
    }
    startAtRest(s, params, dt);
    return s;
  }
  WaterState s = readStateExr(spec);
  if (n != 0 && s.n != n) {
    throw std::runtime_error("--init " + spec + ": the file holds a " + std::to_string(s.n) + "x" + std::to_string(s.n) +
                             " grid, but --grid asks for " + std::to_string(n));
  }
  return s;
}

void writeStateExr(const std::string& path, const WaterState& s) {
  io::FloatImage image{s.n, s.n, {"u", "v"}, std::vector<float>(size_t(s.n) * s.n * 2)};
  for (size_t k = 0; k < s.u.size(); ++k) {
    image.pixels[2 * k] = s.u[k];
    image.pixels[2 * k + 1] = s.v[k];
  }
  io::writeExr(path, image, {io::PixelType::Float, io::PixelType::Float});
}

WaterState readStateExr(const std::string& path) {
  io::FloatImage image = io::readImage(path);
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
  WaterState s = flatState(image.width);
  const size_t channels = image.channels.size();
  for (size_t k = 0; k < s.u.size(); ++k) {
    s.u[k] = image.pixels[k * channels + uc];
    s.v[k] = image.pixels[k * channels + vc];
    if (!std::isfinite(s.u[k]) || !std::isfinite(s.v[k])) {
      throw std::runtime_error(path + ": non-finite value at cell " + std::to_string(k % s.n) + "," + std::to_string(k / s.n));
    }
  }
  return s;
}

}  // namespace tp::sim
