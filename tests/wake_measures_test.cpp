// The wake's measures (sim/wake_measures.hpp) on fields whose answers are
// known: single cosine modes (all their variance at one wavenumber), a sum
// of two with known energies, a plane of known slope, and nested grids.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "sim/wake_measures.hpp"

namespace tp::test {
namespace {

sim::WaterState cosineField(uint32_t n, std::initializer_list<std::array<double, 3>> modes) {
  sim::WaterState s = sim::flatState(n);
  for (uint32_t j = 0; j < n; ++j) {
    for (uint32_t i = 0; i < n; ++i) {
      double u = 0.0;
      for (const auto& [m, q, amplitude] : modes) {
        u +=
            amplitude * std::cos(std::numbers::pi * m * (i + 0.5) / n) * std::cos(std::numbers::pi * q * (j + 0.5) / n);
      }
      s.u[size_t(j) * n + i] = float(u);
    }
  }
  return s;
}

}  // namespace

// A mode below half the Nyquist wavenumber has no high share, one above it
// all; two modes of amplitudes 3 and 1 (energies 9 : 1) give 1/10.
TEST(WakeMeasures, HighShareOfCosineModesIsTheirEnergyFraction) {
  const uint32_t n = 64;
  EXPECT_LT(sim::measureWake(cosineField(n, {{20.0, 20.0, 0.01}}), 1.0, 0.0, {}).highShare, 1e-9);  // |m| 28.3 < 32
  EXPECT_GT(sim::measureWake(cosineField(n, {{24.0, 24.0, 0.01}}), 1.0, 0.0, {}).highShare, 1.0 - 1e-6);  // 33.9
  EXPECT_NEAR(sim::measureWake(cosineField(n, {{3.0, 1.0, 0.03}, {40.0, 5.0, 0.01}}), 1.0, 0.0, {}).highShare, 0.1,
              1e-5);
}

// A plane of slope 0.25 along z: its slope, crest and trough, and the cells
// of a hidden disc left out of the crest.
TEST(WakeMeasures, SlopeCrestAndTroughOfAPlane) {
  const uint32_t n = 32;
  const double extent = 2.0, h = extent / n;
  sim::WaterState s = sim::flatState(n);
  for (uint32_t j = 0; j < n; ++j) {
    for (uint32_t i = 0; i < n; ++i) s.u[size_t(j) * n + i] = float(0.25 * ((j + 0.5) * h - 1.0));
  }
  const sim::WakeMeasures all = sim::measureWake(s, extent, 0.0, {});
  EXPECT_NEAR(all.maxSlope, 0.25, 1e-6);
  EXPECT_NEAR(all.crest, 0.25 * (1.0 - 0.5 * h), 1e-6);
  EXPECT_NEAR(all.trough, 0.25 * (1.0 - 0.5 * h), 1e-6);
  // Hiding the top rows' middle leaves the crest at the top row's ends.
  const sim::WakeMeasures hidden = sim::measureWake(s, extent, 0.0, {{1.0, 2.0, 0.5}});
  EXPECT_NEAR(hidden.crest, all.crest, 1e-6);
  const sim::WakeMeasures allTop = sim::measureWake(s, extent, 0.0, {{1.0, 2.0, 5.0}});
  EXPECT_EQ(allTop.crest, 0.0);
}

// A smooth field sampled at n and 2n: the block average of the fine one
// differs from the coarse one by the midpoint rule's error, O(h^2), so the
// difference falls about 4x when both grids double.
TEST(WakeMeasures, RmsDifferenceOfNestedGridsFallsWithTheGrid) {
  const auto field = [](uint32_t n) {
    sim::WaterState s = sim::flatState(n);
    for (uint32_t j = 0; j < n; ++j) {
      for (uint32_t i = 0; i < n; ++i) {
        const double x = (i + 0.5) / n, z = (j + 0.5) / n;
        s.u[size_t(j) * n + i] = float(0.1 * std::sin(3.0 * x) * std::cos(2.0 * z));
      }
    }
    return s;
  };
  const double coarse = sim::rmsDifference(field(32), field(64));
  const double fine = sim::rmsDifference(field(64), field(128));
  EXPECT_NEAR(coarse / fine, 4.0, 0.2);
  EXPECT_THROW(sim::rmsDifference(field(32), field(48)), std::invalid_argument);
}

}  // namespace tp::test
