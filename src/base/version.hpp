#pragma once

namespace tp::base {

// The program's version: `tidepool --version`, and the EXR's software attribute.
inline constexpr const char* kVersion = "0.1";

}  // namespace tp::base
