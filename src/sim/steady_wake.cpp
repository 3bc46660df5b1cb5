#include "sim/steady_wake.hpp"

#include <cmath>
#include <complex>
#include <numbers>
#include <stdexcept>

namespace tp::sim {
namespace {

using Complex = std::complex<double>;

// The 2D discrete Fourier transform in place (inverse: conjugate twiddles
// and a 1 / n^2 scale), as the separable O(n^3) sum: a fraction of a second
// at n = 256, and no library for one use.
void fourier(std::vector<Complex>& a, uint32_t n, bool inverse) {
  std::vector<Complex> twiddle(n);
  for (uint32_t k = 0; k < n; ++k) {
    twiddle[k] = std::polar(1.0, (inverse ? 2.0 : -2.0) * std::numbers::pi * k / n);
  }
  std::vector<Complex> line(n);
  const auto transform = [&](size_t start, size_t stride) {
    for (uint32_t k = 0; k < n; ++k) {
      Complex sum = 0.0;
      for (uint32_t j = 0; j < n; ++j) sum += a[start + j * stride] * twiddle[(size_t(k) * j) % n];
      line[k] = sum;
    }
    for (uint32_t k = 0; k < n; ++k) a[start + k * stride] = inverse ? line[k] / double(n) : line[k];
  };
  for (uint32_t row = 0; row < n; ++row) transform(size_t(row) * n, 1);
  for (uint32_t column = 0; column < n; ++column) transform(column, n);
}

// A wavenumber index as the signed integer it stands for.
double signedIndex(uint32_t k, uint32_t n) { return k <= n / 2 ? double(k) : double(k) - double(n); }

}  // namespace

std::vector<double> steadyWake(const WaterParams& p, double dt, double speed, const std::vector<double>& bump) {
  if (p.boundary != Boundary::Wrap) throw std::invalid_argument("the steady wake needs the wrap boundary");
  const uint32_t n = p.n;
  if (bump.size() != size_t(n) * n) throw std::invalid_argument("the bump's size is not the grid's");
  const double h = p.h(), d = std::exp(-p.damping * dt), wave = dt * dt * p.waveSpeed * p.waveSpeed / (h * h);
  std::vector<Complex> u(bump.begin(), bump.end());
  fourier(u, n, false);
  // A mode whose bump moves with the body is b z^s at step s, z = e^(-i kx
  // speed dt). The step (forcing, then the velocity with damping d, wave
  // term and grid damping, then the height with the new velocity) keeps u
  // = w + b and v in that form; its two equations, with the Laplacian's
  // symbol -sigma / h^2, give the water's part w = u - b:
  //   w = -d wave sigma z^2 b / ((z - 1)(z - d + kappa dt sigma) + d wave sigma z).
  for (uint32_t q = 0; q < n; ++q) {
    for (uint32_t m = 0; m < n; ++m) {
      const double angleX = 2.0 * std::numbers::pi * signedIndex(m, n) / n;
      const double angleZ = 2.0 * std::numbers::pi * signedIndex(q, n) / n;
      const double sigma = 4.0 * std::pow(std::sin(angleX / 2.0), 2) + 4.0 * std::pow(std::sin(angleZ / 2.0), 2);
      Complex& mode = u[size_t(q) * n + m];
      if (m == 0 && q == 0) {
        mode = 0.0;  // the mean: the water's level, which the body's motion does not move
        continue;
      }
      const Complex z = std::polar(1.0, -angleX / h * speed * dt);
      const Complex w =
          -d * wave * sigma * z * z * mode / ((z - 1.0) * (z - d + p.gridDamping * dt * sigma) + d * wave * sigma * z);
      mode += w;
    }
  }
  fourier(u, n, true);
  std::vector<double> heights(u.size());
  for (size_t k = 0; k < u.size(); ++k) heights[k] = u[k].real();
  return heights;
}

}  // namespace tp::sim
