#include "bench/bench_pass_times.hpp"

#include "bench/bench_output.hpp"

namespace tp::app {

PassTimes medianPassTimes(render::Renderer& renderer, const render::FrameRequest& request, uint32_t repeats,
                          const std::vector<PassGroup>& groups, render::RenderedFrame& last) {
  std::vector<std::vector<double>> groupMs(groups.size());
  std::vector<double> frameMs;
  last = renderer.render(request);
  for (uint32_t r = 0; r < repeats; ++r) {
    last = renderer.render(request);
    std::vector<double> sums(groups.size(), 0.0);
    double total = 0.0;
    for (const auto& pass : last.passes) {
      for (size_t g = 0; g < groups.size(); ++g) {
        if (groups[g](pass.kind)) sums[g] += pass.milliseconds;
      }
      total += pass.milliseconds;
    }
    for (size_t g = 0; g < groups.size(); ++g) groupMs[g].push_back(sums[g]);
    frameMs.push_back(total);
  }
  PassTimes times{.groups = {}, .frame = median(frameMs)};
  for (auto& ms : groupMs) times.groups.push_back(median(std::move(ms)));
  return times;
}

}  // namespace tp::app
