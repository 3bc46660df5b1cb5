#pragma once
#include <filesystem>
#include <optional>
#include <string>

namespace tp::base {

// The whole of a regular file's bytes; none when it is not a regular file or
// cannot be read. Callers word their own error.
std::optional<std::string> readTextFile(const std::filesystem::path& path);

}  // namespace tp::base
