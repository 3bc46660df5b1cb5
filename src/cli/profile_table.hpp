#pragma once
#include "render/renderer.hpp"

namespace tp::app {

// A frame's passes as a table on stdout: wall ms (n/a unless each pass was
// submitted on its own), GPU ms (n/a without timestamps), dispatches, draws
// and workgroups per pass, then the totals (render --profile, view --profile).
void printProfile(const render::RenderedFrame& frame);

}  // namespace tp::app
