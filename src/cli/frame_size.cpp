#include "cli/frame_size.hpp"

#include <string>

#include "cli/whole_number.hpp"

namespace tp::app {

std::optional<FrameSize> parseFrameSize(std::string_view text, uint32_t minSide, uint32_t maxSide) {
  const size_t x = text.find('x');
  if (x == std::string_view::npos) return std::nullopt;
  const auto w = wholeNumber<uint32_t>(text.substr(0, x)), h = wholeNumber<uint32_t>(text.substr(x + 1));
  const auto fits = [&](const std::optional<uint32_t>& side) { return side && *side >= minSide && *side <= maxSide; };
  if (!fits(w) || !fits(h)) return std::nullopt;
  return FrameSize{*w, *h};
}

CLI::Validator frameSizeCheck(uint32_t minSide, uint32_t maxSide) {
  const std::string form =
      "WxH with each side " + std::to_string(minSide) + " to " + std::to_string(maxSide) + ", e.g. 1280x720";
  return CLI::Validator(
      [minSide, maxSide, form](std::string& input) -> std::string {
        return parseFrameSize(input, minSide, maxSide) ? std::string() : input + " is not " + form;
      },
      "");
}

}  // namespace tp::app
