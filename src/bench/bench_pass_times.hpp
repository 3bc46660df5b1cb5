#pragma once
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "render/renderer.hpp"

namespace tp::app {

// Which passes of a frame a benchmark times together, by kind (render/pass_kinds.hpp).
using PassGroup = std::function<bool(const render::PassKind* kind)>;

struct PassTimes {
  std::vector<double> groups;  // per group: the median of its passes' GPU ms summed in each frame
  double frame = 0.0;          // the median of the whole frame's GPU ms
};

// Renders `request` once to warm up (pipelines are compiled on first use,
// cached passes filled), then `repeats` times more, timing each with the
// renderer's GPU timestamps. `last` gets the last frame rendered.
PassTimes medianPassTimes(render::Renderer& renderer, const render::FrameRequest& request, uint32_t repeats,
                          const std::vector<PassGroup>& groups, render::RenderedFrame& last);

}  // namespace tp::app
