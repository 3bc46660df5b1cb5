#include "viewer/resolution_governor.hpp"

#include "base/median.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace tp::app {

ResolutionGovernor::ResolutionGovernor(glm::uvec2 full, double targetFps, GovernorSettings settings)
    : full_(full), budget_(1.0 / targetFps), settings_(settings), size_(full), skip_(settings.settle) {
  if (!(targetFps > 0.0) || !std::isfinite(targetFps)) throw std::invalid_argument("the target fps must be positive");
}

glm::uvec2 ResolutionGovernor::sizeAt(double scale) const {
  // Sides rounded to the step, the aspect kept within a step.
  auto side = [&](uint32_t full) {
    const uint32_t steps = uint32_t(std::lround(full * scale / settings_.align));
    return std::clamp(steps * settings_.align, std::min(settings_.align, full), full);
  };
  return {side(full_.x), side(full_.y)};
}

bool ResolutionGovernor::frameShown(double seconds) {
  if (skip_ > 0) {
    --skip_;
    return false;
  }
  times_.push_back(seconds);
  if (times_.size() < settings_.window) return false;
  const double median = base::median(times_);
  times_.clear();
  const bool slow = median > settings_.shrink * budget_;
  const bool fast = median < settings_.grow * budget_ && scale_ < 1.0;
  if (!slow && !fast) return false;
  // The cost taken as proportional to the pixels: the scale of the sides
  // goes as the square root of the time.
  const double scale = std::clamp(scale_ * std::sqrt(settings_.aim * budget_ / median), settings_.minScale, 1.0);
  const glm::uvec2 next = sizeAt(scale);
  if (next == size_) return false;
  scale_ = scale;
  size_ = next;
  skip_ = settings_.settle;
  ++changes_;
  return true;
}

}  // namespace tp::app
