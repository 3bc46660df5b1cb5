#include "sim/water_params.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "sim/grid_index.hpp"

namespace tp::sim {
namespace {

std::string fmt(double x) {
  std::ostringstream s;
  s.precision(6);
  s << x;
  return s.str();
}

void require(bool ok, const std::string& message) {
  if (!ok) throw std::runtime_error(message);
}

}  // namespace

void validate(const WaterParams& p) {
  require(p.n >= 2, "grid size " + std::to_string(p.n) + " is below the minimum of 2");
  require(std::isfinite(p.extent) && p.extent > 0.0, "extent must be positive and finite, got " + fmt(p.extent));
  require(std::isfinite(p.waveSpeed) && p.waveSpeed > 0.0,
          "wave speed must be positive and finite, got " + fmt(p.waveSpeed));
  require(std::isfinite(p.damping) && p.damping >= 0.0, "damping must be >= 0 and finite, got " + fmt(p.damping));
  require(std::isfinite(p.maxSlope) && p.maxSlope >= 0.0, "max slope must be >= 0 and finite, got " + fmt(p.maxSlope));
  require(std::isfinite(p.gridDamping) && p.gridDamping >= 0.0,
          "grid damping must be >= 0 and finite, got " + fmt(p.gridDamping));
  require(std::isfinite(p.spreadDepthFactor) && p.spreadDepthFactor >= 0.0,
          "spread depth factor must be >= 0 and finite, got " + fmt(p.spreadDepthFactor));
  require(p.solid.empty() || p.solid.size() == solidWords(p.n),
          "the solid-cell mask has " + std::to_string(p.solid.size()) + " words, where a grid of " +
              std::to_string(p.n) + " needs " + std::to_string(solidWords(p.n)));
  require(p.spillHeight > 0.0, "spill height (the rim over the rest level) must be > 0, got " + fmt(p.spillHeight));
}

std::vector<uint32_t> solidDepths(const WaterParams& p) {
  const size_t cells = size_t(p.n) * p.n;
  std::vector<uint32_t> words(solidDepthWords(p.n), 0u);
  if (p.solid.empty()) return words;
  // Breadth first from the open cells, a ring of solid cells at a time.
  std::vector<uint32_t> depth(cells, 0u);
  std::vector<size_t> ring;
  for (size_t k = 0; k < cells; ++k) {
    if (isSolid(p.solid, k)) {
      depth[k] = 255u;
    } else {
      ring.push_back(k);
    }
  }
  for (uint32_t d = 1; d < 255 && !ring.empty(); ++d) {
    std::vector<size_t> next;
    for (const size_t k : ring) {
      const long i = long(k % p.n), j = long(k / p.n);
      for (const size_t other : {cellIndex(i - 1, j, p.n, p.boundary), cellIndex(i + 1, j, p.n, p.boundary),
                                 cellIndex(i, j - 1, p.n, p.boundary), cellIndex(i, j + 1, p.n, p.boundary)}) {
        if (depth[other] != 255u) continue;
        depth[other] = d;
        next.push_back(other);
      }
    }
    ring = std::move(next);
  }
  for (size_t k = 0; k < cells; ++k) words[k / 4] |= depth[k] << (k % 4 * 8);
  return words;
}

double slopeShare(const WaterParams& p) { return p.maxSlope > 0.0 ? kSlopeShare : 0.0; }

double lambdaBound(const WaterParams& p) { return kStabilityBound * std::sqrt(1.0 - 4.0 * slopeShare(p)); }

double gridDampingBound(const WaterParams& p, double dt) {
  const double d = std::exp(-p.damping * dt), lambda = p.lambda(dt), s = slopeShare(p);
  return ((2.0 + 2.0 * d) * (1.0 - 4.0 * s) - 8.0 * d * lambda * lambda) / (16.0 - 64.0 * s);
}

void checkStable(const WaterParams& p, double dt) {
  require(std::isfinite(dt) && dt > 0.0, "time step must be positive and finite, got " + fmt(dt));
  const double lambda = p.lambda(dt);
  const std::string bound =
      p.maxSlope > 0.0 ? "the bound with the slope limiter on, " : "the 2D stability bound 1/sqrt(2) = ";
  require(lambda <= lambdaBound(p), "lambda = c*dt/h = " + fmt(lambda) + " exceeds " + bound + fmt(lambdaBound(p)) +
                                        " (dt = " + fmt(dt) + " s, h = " + fmt(p.h()) + " m, c = " + fmt(p.waveSpeed) +
                                        " m/s)");
  require(p.gridDamping * dt <= gridDampingBound(p, dt),
          "grid damping * dt = " + fmt(p.gridDamping * dt) + " exceeds its stability bound " +
              fmt(gridDampingBound(p, dt)) + " at dt = " + fmt(dt) + " s (lambda = " + fmt(lambda) + ")");
}

uint32_t substepsFor(const WaterParams& p, double frameTime, double safety) {
  require(std::isfinite(frameTime) && frameTime > 0.0, "frame time must be positive and finite, got " + fmt(frameTime));
  require(safety > 0.0 && safety <= 1.0, "substep safety factor must be in (0, 1]");
  double needed = std::max(1.0, std::ceil(p.lambda(frameTime) / (safety * lambdaBound(p))));
  require(needed <= 1e6,
          "frame time " + fmt(frameTime) + " s needs " + fmt(needed) + " substeps, over the limit of 1e6");
  // The grid damping's bound grows as dt shrinks (towards 1/4 at dt -> 0):
  // more substeps until kappa dt is within it.
  while (p.gridDamping * frameTime / needed > safety * gridDampingBound(p, frameTime / needed)) {
    needed += 1.0;
    require(needed <= 1e6,
            "grid damping " + fmt(p.gridDamping) + "/s at frame time " + fmt(frameTime) + " s needs over 1e6 substeps");
  }
  return uint32_t(needed);
}

std::string toString(Boundary b) { return b == Boundary::Clamp ? "clamp" : "wrap"; }
std::string toString(Scheme s) { return s == Scheme::Symplectic ? "symplectic" : "explicit"; }

Boundary parseBoundary(const std::string& s) {
  if (s == "clamp") return Boundary::Clamp;
  if (s == "wrap") return Boundary::Wrap;
  throw std::runtime_error("boundary must be clamp or wrap, got '" + s + "'");
}

Scheme parseScheme(const std::string& s) {
  if (s == "symplectic") return Scheme::Symplectic;
  if (s == "explicit") return Scheme::Explicit;
  throw std::runtime_error("scheme must be symplectic or explicit, got '" + s + "'");
}

std::string toString(SphereForcing f) { return f == SphereForcing::Column ? "column" : "spread"; }

SphereForcing parseSphereForcing(const std::string& s) {
  if (s == "column") return SphereForcing::Column;
  if (s == "spread") return SphereForcing::Spread;
  throw std::runtime_error("sphere forcing must be column or spread, got '" + s + "'");
}

}  // namespace tp::sim
