#pragma once
// The water's state in files: float EXR with channels u and v, and the
// initial states the sim command's --init names.
#include <string>

#include "sim/water_params.hpp"
#include "sim/water_state.hpp"

namespace tp::io {

// Builds the initial state from a --init specification: "drop:X,Z,RADIUS,AMP" or
// "mode:M,N,AMP" (at rest, started with startAtRest for time step dt), or the
// path of an EXR with channels u and v (N x N float), taken as it is so that a
// run resumes exactly where another stopped. params.n is the grid size asked
// for (0: take it from the EXR). Throws a one-line error naming the
// specification and the problem.
sim::WaterState initialState(const std::string& spec, const sim::WaterParams& params, double dt);

// The EXR form of a state: float32 channels u and v, pixel (i, j) = cell (i, j).
void writeStateExr(const std::string& path, const sim::WaterState& s);
sim::WaterState readStateExr(const std::string& path);

}  // namespace tp::io
