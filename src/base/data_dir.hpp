#pragma once
#include <filesystem>
#include <string>

namespace tp::base {

// The folder of the program's data called `name` (shaders_glsl, tools). An
// installed tidepool, PREFIX/bin/tidepool, finds it in
// PREFIX/share/tidepool/NAME; a tidepool run from its build tree finds none
// there and takes `checkout`, the folder of the source tree it was built from.
std::filesystem::path dataDir(const std::string& name, const std::filesystem::path& checkout);

}  // namespace tp::base
