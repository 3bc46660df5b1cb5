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

namespace {

// The folder an output goes in, "." for a bare name.
fs::path folderOf(const fs::path& target) { return target.has_parent_path() ? target.parent_path() : fs::path("."); }

// The nearest of `dir` and the folders above it that is there: where the
// folders an output needs are made from.
fs::path nearestThere(fs::path dir) {
  std::error_code ec;
  while (!fs::exists(dir, ec) && dir.has_relative_path()) dir = dir.parent_path();
  return dir.empty() ? fs::path(".") : dir;
}

}  // namespace

void checkWritable(const std::string& path) {
  if (path.empty()) throw std::runtime_error("empty output path");
  const fs::path target(path);
  // A folder that is not there is made when the file is written (AtomicFile);
  // the check is of the nearest one that is.
  const fs::path there = nearestThere(folderOf(target));
  std::error_code ec;
  if (!fs::is_directory(there, ec)) {
    throw std::runtime_error("cannot write " + path + ": " + there.string() + " is not a folder");
  }
  if (fs::is_directory(target, ec)) throw std::runtime_error("cannot write " + path + ": it is a directory");
  if (access(there.c_str(), W_OK | X_OK) != 0) {
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
  std::error_code ec;
  fs::create_directories(folderOf(t), ec);
  if (ec) throw std::runtime_error("cannot write " + target_ + ": cannot make its folder: " + ec.message());
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
