#pragma once
// Image sizes as every command spells them: --size WxH (1280x720).
#include <CLI/CLI.hpp>
#include <cstdint>
#include <optional>
#include <string_view>

namespace tp::app {

struct FrameSize {
  uint32_t width = 0, height = 0;
};

// "WxH" with each side in [minSide, maxSide], or nothing.
std::optional<FrameSize> parseFrameSize(std::string_view text, uint32_t minSide, uint32_t maxSide);

// A check that an option's text is WxH with sides in [minSide, maxSide]
// ("--size: 1280by720 is not WxH with each side 1 to 16384, e.g. 1280x720").
CLI::Validator frameSizeCheck(uint32_t minSide, uint32_t maxSide);

}  // namespace tp::app
