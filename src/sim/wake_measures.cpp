#include "sim/wake_measures.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace tp::sim {
namespace {

// The orthonormal cosine transform (DCT-II) along both axes, in double: the
// separable O(n^3) sum, a fraction of a second at n = 512.
std::vector<double> cosineTransform(const std::vector<double>& f, uint32_t n) {
  std::vector<double> basis(size_t(n) * n);
  for (uint32_t m = 0; m < n; ++m) {
    const double norm = std::sqrt((m == 0 ? 1.0 : 2.0) / n);
    for (uint32_t i = 0; i < n; ++i) basis[size_t(m) * n + i] = norm * std::cos(std::numbers::pi * m * (i + 0.5) / n);
  }
  std::vector<double> rows(size_t(n) * n), out(size_t(n) * n);
  for (uint32_t j = 0; j < n; ++j) {
    for (uint32_t m = 0; m < n; ++m) {
      double sum = 0.0;
      for (uint32_t i = 0; i < n; ++i) sum += basis[size_t(m) * n + i] * f[size_t(j) * n + i];
      rows[size_t(m) * n + j] = sum;  // transposed: row m holds the column of coefficient m
    }
  }
  for (uint32_t m = 0; m < n; ++m) {
    for (uint32_t q = 0; q < n; ++q) {
      double sum = 0.0;
      for (uint32_t j = 0; j < n; ++j) sum += basis[size_t(q) * n + j] * rows[size_t(m) * n + j];
      out[size_t(q) * n + m] = sum;
    }
  }
  return out;
}

}  // namespace

WakeMeasures measureWake(const WaterState& s, double extent, double level, const std::vector<WaterlineDisc>& hidden) {
  const uint32_t n = s.n;
  const double h = extent / n;
  double mean = 0.0;
  for (float u : s.u) mean += u;
  mean /= double(s.u.size());
  std::vector<double> f(s.u.size());
  for (size_t k = 0; k < f.size(); ++k) f[k] = double(s.u[k]) - mean;
  const std::vector<double> c = cosineTransform(f, n);
  double all = 0.0, high = 0.0;
  for (uint32_t q = 0; q < n; ++q) {
    for (uint32_t m = 0; m < n; ++m) {
      const double e = c[size_t(q) * n + m] * c[size_t(q) * n + m];
      all += e;
      if (4.0 * (double(m) * m + double(q) * q) > double(n) * n) high += e;  // |k| > (pi / h) / 2
    }
  }
  WakeMeasures w;
  w.highShare = all > 0.0 ? high / all : 0.0;
  const auto seen = [&](uint32_t i, uint32_t j) {
    const double x = (i + 0.5) * h, z = (j + 0.5) * h;
    for (const WaterlineDisc& d : hidden) {
      if ((x - d.x) * (x - d.x) + (z - d.z) * (z - d.z) < d.radius * d.radius) return false;
    }
    return true;
  };
  for (uint32_t j = 0; j < n; ++j) {
    for (uint32_t i = 0; i < n; ++i) {
      if (!seen(i, j)) continue;
      const double u = s.u[size_t(j) * n + i];
      w.crest = std::max(w.crest, u - level);
      w.trough = std::max(w.trough, level - u);
      if (i + 1 < n && seen(i + 1, j)) w.maxSlope = std::max(w.maxSlope, std::abs(s.u[size_t(j) * n + i + 1] - u) / h);
      if (j + 1 < n && seen(i, j + 1)) w.maxSlope = std::max(w.maxSlope, std::abs(s.u[size_t(j + 1) * n + i] - u) / h);
    }
  }
  return w;
}

double sphereCapVolume(double radius, double centerY, double level) {
  const double d = std::clamp(level - (centerY - radius), 0.0, 2.0 * radius);
  return std::numbers::pi * d * d * (3.0 * radius - d) / 3.0;
}

double rmsDifference(const WaterState& coarse, const WaterState& fine) {
  if (coarse.n == 0 || fine.n % coarse.n != 0) throw std::invalid_argument("grids do not nest");
  const uint32_t b = fine.n / coarse.n;
  double sum = 0.0;
  for (uint32_t j = 0; j < coarse.n; ++j) {
    for (uint32_t i = 0; i < coarse.n; ++i) {
      double block = 0.0;
      for (uint32_t y = 0; y < b; ++y) {
        for (uint32_t x = 0; x < b; ++x) block += fine.u[size_t(j * b + y) * fine.n + i * b + x];
      }
      const double d = block / (double(b) * b) - coarse.u[size_t(j) * coarse.n + i];
      sum += d * d;
    }
  }
  return std::sqrt(sum / (double(coarse.n) * coarse.n));
}

}  // namespace tp::sim
