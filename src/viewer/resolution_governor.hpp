#pragma once
// The viewer's dynamic resolution (view --target-fps): the size the renderer
// draws at, chosen from the measured time of recent frames so that the
// frames come at the target rate, the frame shown scaled to the window.
#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

namespace tp::app {

struct GovernorSettings {
  // Frames timed at a size before it is judged; the first frames at a new
  // size are not counted (lavapipe compiles the new renderer's shaders at
  // their first draw).
  uint32_t window = 8;
  uint32_t settle = 2;
  // Hysteresis: a size is kept while its median frame time is within
  // [grow, shrink] times the target's; outside, the next size aims at
  // `aim` times the target's, the cost taken as proportional to the pixels.
  double shrink = 1.05;
  double grow = 0.7;
  double aim = 0.9;
  // The smallest scale of the full size, and the step sides are rounded to.
  double minScale = 0.125;
  uint32_t align = 8;
};

class ResolutionGovernor {
 public:
  ResolutionGovernor(glm::uvec2 full, double targetFps, GovernorSettings settings = {});
  // The size the next frame renders at.
  glm::uvec2 size() const { return size_; }
  // After a frame rendered at size(): the seconds from the last frame shown
  // to this one. Returns true when size() changed.
  bool frameShown(double seconds);
  uint32_t changes() const { return changes_; }

 private:
  glm::uvec2 sizeAt(double scale) const;
  glm::uvec2 full_;
  double budget_;  // seconds per frame
  GovernorSettings settings_;
  double scale_ = 1.0;
  glm::uvec2 size_;
  uint32_t skip_;
  std::vector<double> times_;
  uint32_t changes_ = 0;
};

}  // namespace tp::app
