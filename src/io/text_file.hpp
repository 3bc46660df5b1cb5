#pragma once
#include <cstdio>
#include <functional>

#include "base/atomic_file.hpp"

namespace tp::io {

// Writes `body` into `file`'s temporary, leaving the commit to the caller:
// throws, naming the target, when it cannot be opened or the disk refuses a write.
void writeTemporary(const base::AtomicFile& file, const std::function<void(std::FILE*)>& body);

}  // namespace tp::io
