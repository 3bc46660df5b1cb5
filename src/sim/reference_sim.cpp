#include "sim/reference_sim.hpp"

#include <algorithm>
#include <cmath>

#include "sim/grid_index.hpp"

namespace tp::sim {

ReferenceSim::ReferenceSim(const WaterParams& params, const WaterState& initial)
    : p_(params),
      u_(initial.u.begin(), initial.u.end()),
      v_(initial.v.begin(), initial.v.end()),
      nextU_(u_.size()),
      nextV_(v_.size()) {
  p_.n = initial.n;
  depths_ = solidDepths(p_);
}

// A solid cell (WaterParams::solid) holds no water: an open cell `self`
// sees its own state in its place.
size_t ReferenceSim::seen(size_t self, long i, long j) const {
  const size_t k = cellIndex(i, j, p_.n, p_.boundary);
  return isSolid(p_.solid, k) ? self : k;
}
double ReferenceSim::heightAt(size_t self, long i, long j) const { return u_[seen(self, i, j)]; }
double ReferenceSim::velocityAt(size_t self, long i, long j) const { return v_[seen(self, i, j)]; }

void ReferenceSim::step(double dt) {
  const long n = p_.n;
  const double h = p_.h();
  const double decay = std::exp(-p_.damping * dt);
  const double c2 = p_.waveSpeed * p_.waveSpeed;
  const double maxDifference = p_.maxSlope * h, share = slopeShare(p_);
  // The slope limiter: what an edge steeper than maxSlope passes down in a step.
  const auto excess = [&](double difference) {
    return share * (difference - std::clamp(difference, -maxDifference, maxDifference));
  };
  for (long j = 0; j < n; ++j) {
    for (long i = 0; i < n; ++i) {
      const size_t k = size_t(j) * n + size_t(i);
      if (const uint32_t depth = solidDepthAt(depths_, k); depth != 0) {
        // No water: a ghost, the mean of the neighbours one cell nearer the water.
        double sum = 0.0;
        int nearer = 0;
        for (const size_t other : {cellIndex(i - 1, j, p_.n, p_.boundary), cellIndex(i + 1, j, p_.n, p_.boundary),
                                   cellIndex(i, j - 1, p_.n, p_.boundary), cellIndex(i, j + 1, p_.n, p_.boundary)}) {
          if (solidDepthAt(depths_, other) + 1 != depth) continue;
          sum += u_[other];
          ++nearer;
        }
        nextU_[k] = nearer > 0 ? sum / nearer : u_[k];
        nextV_[k] = v_[k];
        continue;
      }
      const double average =
          0.25 * (heightAt(k, i - 1, j) + heightAt(k, i + 1, j) + heightAt(k, i, j - 1) + heightAt(k, i, j + 1));
      const double laplacian = 4.0 * (average - u_[k]) / (h * h);
      const double velocityLaplacianH2 = velocityAt(k, i - 1, j) + velocityAt(k, i + 1, j) + velocityAt(k, i, j - 1) +
                                         velocityAt(k, i, j + 1) - 4.0 * v_[k];
      const double v = decay * (v_[k] + dt * c2 * laplacian) + p_.gridDamping * dt * velocityLaplacianH2;
      double u = u_[k] + dt * (p_.scheme == Scheme::Explicit ? v_[k] : v);
      if (maxDifference > 0.0) {
        const double own = u_[k];
        u -= excess(own - heightAt(k, i - 1, j)) + excess(own - heightAt(k, i + 1, j)) +
             excess(own - heightAt(k, i, j - 1)) + excess(own - heightAt(k, i, j + 1));
      }
      const bool atWall = i == 0 || j == 0 || i == n - 1 || j == n - 1;
      double vKept = v;
      if (atWall && p_.boundary == Boundary::Clamp && u > p_.spillHeight) {  // over the rim: spills
        u = p_.spillHeight;
        vKept = std::min(v, 0.0);
      }
      nextU_[k] = u;
      nextV_[k] = vKept;
    }
  }
  std::swap(u_, nextU_);
  std::swap(v_, nextV_);
}

void ReferenceSim::steps(uint64_t count, double dt) {
  for (uint64_t s = 0; s < count; ++s) step(dt);
}

WaterStats ReferenceSim::stats(double dt) const {
  WaterStats s;
  const long n = p_.n;
  const double h = p_.h(), c2 = p_.waveSpeed * p_.waveSpeed;
  for (long j = 0; j < n; ++j) {
    for (long i = 0; i < n; ++i) {
      const size_t k = size_t(j) * n + size_t(i);
      if (isSolid(p_.solid, k)) continue;  // holds no water
      const double u = u_[k], v = v_[k];
      if (!std::isfinite(u) || !std::isfinite(v)) {
        ++s.nonFinite;
        continue;
      }
      s.maxAbsU = std::max(s.maxAbsU, std::abs(u));
      s.maxAbsV = std::max(s.maxAbsV, std::abs(v));
      s.volume += u * h * h;
      const double dE = u - heightAt(k, i + 1, j), dN = u - heightAt(k, i, j + 1);
      const double laplacian =
          (heightAt(k, i - 1, j) + heightAt(k, i + 1, j) + heightAt(k, i, j - 1) + heightAt(k, i, j + 1) - 4.0 * u) /
          (h * h);
      s.energy += (0.5 * v * v + 0.5 * c2 * (dE * dE + dN * dN) / (h * h) + 0.5 * dt * c2 * v * laplacian) * h * h;
    }
  }
  return s;
}

WaterState ReferenceSim::state() const {
  WaterState s = flatState(p_.n);
  for (size_t k = 0; k < u_.size(); ++k) {
    s.u[k] = float(u_[k]);
    s.v[k] = float(v_[k]);
  }
  return s;
}

}  // namespace tp::sim
