#include "base/atomic_file.hpp"

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <stdexcept>

namespace tp::base {
namespace fs = std::filesystem;

void checkWritable(const std::string& path) {
  if (path.empty()) throw std::runtime_error("empty output path");
  fs::path target(path);
  fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
  std::error_code ec;
  if (!fs::is_directory(dir, ec))
    throw std::runtime_error("cannot write " + path + ": directory " + dir.string() + " does not exist");
  if (fs::is_directory(target, ec)) throw std::runtime_error("cannot write " + path + ": it is a directory");
  if (access(dir.c_str(), W_OK | X_OK) != 0) {
    throw std::runtime_error("cannot write " + path + ": " + std::strerror(errno));
  }
}

bool hasExtension(const std::string& path, const std::string& extension) {
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext == extension;
}

void requireExtension(const std::string& path, const std::string& extension) {
  if (!hasExtension(path, extension)) throw std::runtime_error("output " + path + " must end in " + extension);
}

AtomicFile::AtomicFile(std::string target) : target_(std::move(target)) {
  checkWritable(target_);
  fs::path t(target_);
  // Appended piecewise: GCC 12 warns falsely (-Wrestrict) on "." + std::string.
  std::string name(".");
  name += t.stem().string();
  name += ".tmp";
  name += std::to_string(getpid());
  name += t.extension().string();
  temp_ = (t.parent_path() / name).string();
}

AtomicFile::~AtomicFile() {
  if (!committed_) {
    std::error_code ec;
    fs::remove(temp_, ec);
  }
}

void AtomicFile::commit() {
  std::error_code ec;
  fs::rename(temp_, target_, ec);
  if (ec) throw std::runtime_error("cannot write " + target_ + ": " + ec.message());
  committed_ = true;
}

}  // namespace tp::base
