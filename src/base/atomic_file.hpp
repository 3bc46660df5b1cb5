#pragma once
#include <string>

namespace tp::base {

// Output files are written under a temporary name in the target's directory
// and renamed into place by commit(): a crash or an error never leaves a
// half-written file under the real name. The destructor removes an
// uncommitted temporary.
class AtomicFile {
 public:
  // Makes the target's folder (and those above it) when they are not there.
  // Throws when that folder cannot be made or written, or when the target
  // exists and is a directory.
  explicit AtomicFile(std::string target);
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  // Keeps the target's extension so writers that pick a format by name still can.
  const std::string& tempPath() const { return temp_; }
  const std::string& target() const { return target_; }
  void commit();

 private:
  std::string target_;
  std::string temp_;
  bool committed_ = false;
};

// Throws when a file could not be created at `path` (checked before long work
// starts): a folder not there yet passes when the nearest one above it that is
// there is a folder we may write in (AtomicFile makes the rest).
void checkWritable(const std::string& path);

// Whether `path` ends in `extension` (".exr", ".png"), case-insensitive.
bool hasExtension(const std::string& path, const std::string& extension);

// Throws unless `path` ends in `extension` (".exr", ".png"), case-insensitive.
void requireExtension(const std::string& path, const std::string& extension);

}  // namespace tp::base
