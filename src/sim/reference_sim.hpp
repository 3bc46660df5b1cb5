#pragma once
#include <vector>

#include "sim/water_params.hpp"
#include "sim/water_state.hpp"
#include "sim/water_stats.hpp"

namespace tp::sim {

// The water step in double precision, plain C++, written apart from the
// shaders: the answer the GPU is checked against in tests and benchmarks.
class ReferenceSim {
 public:
  ReferenceSim(const WaterParams& params, const WaterState& initial);

  void step(double dt);
  void steps(uint64_t count, double dt);
  WaterStats stats(double dt) const;
  WaterState state() const;  // rounded to float

  const std::vector<double>& u() const { return u_; }
  const std::vector<double>& v() const { return v_; }

 private:
  size_t seen(size_t self, long i, long j) const;
  double heightAt(size_t self, long i, long j) const;
  double velocityAt(size_t self, long i, long j) const;

  WaterParams p_;
  std::vector<uint32_t> depths_;  // solidDepths(p_)
  std::vector<double> u_, v_, nextU_, nextV_;
};

}  // namespace tp::sim
