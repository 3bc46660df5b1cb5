#include "base/data_dir.hpp"

#include <system_error>

namespace tp::base {

std::filesystem::path dataDir(const std::string& name, const std::filesystem::path& checkout) {
  std::error_code error;
  const std::filesystem::path executable = std::filesystem::read_symlink("/proc/self/exe", error);
  if (!error) {
    const std::filesystem::path installed = executable.parent_path().parent_path() / "share" / "tidepool" / name;
    if (std::filesystem::is_directory(installed, error)) return installed;
  }
  return checkout;
}

}  // namespace tp::base
