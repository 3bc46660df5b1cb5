#include "base/heap_settings.hpp"

#include <malloc.h>

namespace tp::base {
namespace {

// Free memory at the top of a heap is trimmed only beyond this.
constexpr int kTrimThresholdBytes = 1 << 30;
// Blocks below this come from the heap, not from their own mapping; glibc
// takes at most 32 MiB here on 64-bit systems.
constexpr int kMmapThresholdBytes = 32 << 20;

}  // namespace

void keepFreedHeapMemory() {
  // Either call may fail on a C library that lacks the setting: the program
  // then runs as before, only slower.
  (void)mallopt(M_TRIM_THRESHOLD, kTrimThresholdBytes);
  (void)mallopt(M_MMAP_THRESHOLD, kMmapThresholdBytes);
}

}  // namespace tp::base
